"""Pure geometry, no robot: rotations and pose conventions."""

from taut.geometry._rotation import (
    CONVENTIONS,
    angles_from_matrix,
    planar_rotation,
    rotation_matrix,
)

__all__ = ["CONVENTIONS", "angles_from_matrix", "planar_rotation", "rotation_matrix"]
