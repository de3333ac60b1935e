"""Trajectories in pose space (joint space included for jointed platforms): point-to-point and
multi-waypoint, with cubic, quintic, trapezoidal or linear time laws, sampled at any rate with
velocity, acceleration and angular rates (``docs/architecture.md`` §1, layer 2)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports

if TYPE_CHECKING:
    from taut.motion._caspr import CasprTrajectories, CasprTrajectory, read_caspr_trajectories
    from taut.motion._laws import LAWS
    from taut.motion._named import RobotTrajectory, robot_trajectory
    from taut.motion._trajectory import (
        ROTATIONS,
        Motion,
        MotionSamples,
        trajectory_from_robot,
        trajectory_from_waypoints,
    )
    from taut.motion._vias import VIAS
    from taut.motion._waypoints import angle_columns, complete_waypoints, unwrap_angles

#: Every name is imported on first use (PEP 562), so that importing the package loads nothing heavy.
_LAZY = {
    "CasprTrajectories": "taut.motion._caspr",
    "CasprTrajectory": "taut.motion._caspr",
    "read_caspr_trajectories": "taut.motion._caspr",
    "LAWS": "taut.motion._laws",
    "RobotTrajectory": "taut.motion._named",
    "robot_trajectory": "taut.motion._named",
    "Motion": "taut.motion._trajectory",
    "MotionSamples": "taut.motion._trajectory",
    "ROTATIONS": "taut.motion._trajectory",
    "trajectory_from_robot": "taut.motion._trajectory",
    "trajectory_from_waypoints": "taut.motion._trajectory",
    "VIAS": "taut.motion._vias",
    "angle_columns": "taut.motion._waypoints",
    "complete_waypoints": "taut.motion._waypoints",
    "unwrap_angles": "taut.motion._waypoints",
}

__all__ = [
    "CasprTrajectories",
    "CasprTrajectory",
    "LAWS",
    "Motion",
    "MotionSamples",
    "ROTATIONS",
    "RobotTrajectory",
    "VIAS",
    "angle_columns",
    "complete_waypoints",
    "read_caspr_trajectories",
    "robot_trajectory",
    "trajectory_from_robot",
    "trajectory_from_waypoints",
    "unwrap_angles",
]

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
