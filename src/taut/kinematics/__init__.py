"""Kinematics: poses and frames, inverse kinematics and structure matrix, elastic cables,
forward kinematics of fully-constrained robots."""

from taut.kinematics.elastic import robot_stiffness, tension_from_stretch, unstretched_length
from taut.kinematics.forward import FKResult, forward_kinematics
from taut.kinematics.inverse import (
    MIN_LENGTH,
    IKResult,
    anchor_points,
    cable_lengths,
    inverse_kinematics,
    structure_matrix,
)
from taut.kinematics.pose import as_poses, body_frames, platform_frame

__all__ = [
    "MIN_LENGTH",
    "FKResult",
    "IKResult",
    "anchor_points",
    "as_poses",
    "body_frames",
    "cable_lengths",
    "forward_kinematics",
    "inverse_kinematics",
    "platform_frame",
    "robot_stiffness",
    "structure_matrix",
    "tension_from_stretch",
    "unstretched_length",
]
