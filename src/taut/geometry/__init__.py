"""Pure geometry, no robot: rotations and pose conventions, intersections and distances, and the
rigid alignment of point sets."""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports

if TYPE_CHECKING:
    from taut.geometry._alignment import rigid_alignment
    from taut.geometry._frames import axis_frames
    from taut.geometry._intersections import (
        circles_overlap,
        point_in_polygon,
        segment_enters_polygon,
        segment_meets_circle,
        segments_intersect,
    )
    from taut.geometry._rates import angular_acceleration, angular_velocity, rate_matrix, rate_matrix_derivative
    from taut.geometry._rotation import CONVENTIONS, angles_from_matrix, planar_rotation, rotation_matrix
    from taut.geometry._rotation_kernels import matrix_angles, rotate_about_axis, rotation_into
    from taut.geometry._segments import segment_distance, segment_distance_scalar
    from taut.geometry._tangents import directed_tangent
    from taut.geometry._vectors import cross

#: Every name is imported on first use (PEP 562), so that importing the package loads nothing heavy.
_LAZY = {
    "rigid_alignment": "taut.geometry._alignment",
    "axis_frames": "taut.geometry._frames",
    "circles_overlap": "taut.geometry._intersections",
    "point_in_polygon": "taut.geometry._intersections",
    "segment_enters_polygon": "taut.geometry._intersections",
    "segment_meets_circle": "taut.geometry._intersections",
    "segments_intersect": "taut.geometry._intersections",
    "angular_acceleration": "taut.geometry._rates",
    "angular_velocity": "taut.geometry._rates",
    "rate_matrix": "taut.geometry._rates",
    "rate_matrix_derivative": "taut.geometry._rates",
    "CONVENTIONS": "taut.geometry._rotation",
    "angles_from_matrix": "taut.geometry._rotation",
    "planar_rotation": "taut.geometry._rotation",
    "rotation_matrix": "taut.geometry._rotation",
    "matrix_angles": "taut.geometry._rotation_kernels",
    "rotate_about_axis": "taut.geometry._rotation_kernels",
    "rotation_into": "taut.geometry._rotation_kernels",
    "segment_distance": "taut.geometry._segments",
    "segment_distance_scalar": "taut.geometry._segments",
    "directed_tangent": "taut.geometry._tangents",
    "cross": "taut.geometry._vectors",
}

__all__ = [
    "CONVENTIONS",
    "angles_from_matrix",
    "angular_acceleration",
    "angular_velocity",
    "axis_frames",
    "circles_overlap",
    "cross",
    "directed_tangent",
    "matrix_angles",
    "planar_rotation",
    "point_in_polygon",
    "rate_matrix",
    "rate_matrix_derivative",
    "rigid_alignment",
    "rotate_about_axis",
    "rotation_into",
    "rotation_matrix",
    "segment_distance",
    "segment_distance_scalar",
    "segment_enters_polygon",
    "segment_meets_circle",
    "segments_intersect",
]

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
