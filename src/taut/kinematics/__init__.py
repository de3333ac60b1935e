"""Kinematics: poses and frames, inverse kinematics and structure matrix, elastic cables,
forward kinematics of fully-constrained robots."""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports

if TYPE_CHECKING:
    from taut.kinematics._elastic import robot_stiffness, tension_from_stretch, unstretched_length
    from taut.kinematics._forward import FKResult, default_guess, forward_kinematics
    from taut.kinematics._inverse import (
        IKResult,
        batch_structure_matrices,
        cable_lengths,
        ik_status,
        inverse_kinematics,
        lengths_at,
        structure_matrix,
    )
    from taut.kinematics._jointed import actuator_jacobian, joint_forces, jointed_structure_matrix
    from taut.kinematics._paths import CABLE_OK, MIN_LENGTH, cable_paths, obstacles_met, refuse_routed, refuse_wrapped
    from taut.kinematics._pose import anchor_points, anchors_at, as_poses, body_frames, platform_frame
    from taut.kinematics._routing import via_points_at
    from taut.kinematics._swivel import (
        SwivelPaths,
        refuse_near_swivel_axis,
        refuse_swivels,
        swivel_angles,
        swivel_parameters,
        swivel_paths,
    )

#: Every name is imported on first use (PEP 562), so that importing the package loads nothing heavy.
_LAZY = {
    "robot_stiffness": "taut.kinematics._elastic",
    "tension_from_stretch": "taut.kinematics._elastic",
    "unstretched_length": "taut.kinematics._elastic",
    "FKResult": "taut.kinematics._forward",
    "default_guess": "taut.kinematics._forward",
    "forward_kinematics": "taut.kinematics._forward",
    "IKResult": "taut.kinematics._inverse",
    "batch_structure_matrices": "taut.kinematics._inverse",
    "cable_lengths": "taut.kinematics._inverse",
    "ik_status": "taut.kinematics._inverse",
    "inverse_kinematics": "taut.kinematics._inverse",
    "lengths_at": "taut.kinematics._inverse",
    "structure_matrix": "taut.kinematics._inverse",
    "actuator_jacobian": "taut.kinematics._jointed",
    "joint_forces": "taut.kinematics._jointed",
    "jointed_structure_matrix": "taut.kinematics._jointed",
    "CABLE_OK": "taut.kinematics._paths",
    "MIN_LENGTH": "taut.kinematics._paths",
    "cable_paths": "taut.kinematics._paths",
    "obstacles_met": "taut.kinematics._paths",
    "refuse_routed": "taut.kinematics._paths",
    "refuse_wrapped": "taut.kinematics._paths",
    "anchor_points": "taut.kinematics._pose",
    "anchors_at": "taut.kinematics._pose",
    "as_poses": "taut.kinematics._pose",
    "body_frames": "taut.kinematics._pose",
    "platform_frame": "taut.kinematics._pose",
    "via_points_at": "taut.kinematics._routing",
    "SwivelPaths": "taut.kinematics._swivel",
    "refuse_near_swivel_axis": "taut.kinematics._swivel",
    "refuse_swivels": "taut.kinematics._swivel",
    "swivel_angles": "taut.kinematics._swivel",
    "swivel_parameters": "taut.kinematics._swivel",
    "swivel_paths": "taut.kinematics._swivel",
}

__all__ = [
    "CABLE_OK",
    "FKResult",
    "IKResult",
    "MIN_LENGTH",
    "SwivelPaths",
    "actuator_jacobian",
    "anchor_points",
    "anchors_at",
    "as_poses",
    "batch_structure_matrices",
    "body_frames",
    "cable_lengths",
    "cable_paths",
    "default_guess",
    "forward_kinematics",
    "ik_status",
    "inverse_kinematics",
    "joint_forces",
    "jointed_structure_matrix",
    "lengths_at",
    "obstacles_met",
    "platform_frame",
    "refuse_near_swivel_axis",
    "refuse_swivels",
    "refuse_routed",
    "refuse_wrapped",
    "robot_stiffness",
    "structure_matrix",
    "swivel_angles",
    "swivel_parameters",
    "swivel_paths",
    "tension_from_stretch",
    "unstretched_length",
    "via_points_at",
]

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
