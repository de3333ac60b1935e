"""Where each cable runs: its length and the point where its straight part begins (the exit
point, or the tangent point of a swivelling pulley), and whether these exist at a pose.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §2.1.1, Eq. 2.1. (docs/references.bib: rushton2022)
.. [2] A. Pott, "Cable-Driven Parallel Robots: Theory and Application", Springer Tracts in
   Advanced Robotics 120, Springer, 2018, pulley kinematics. (docs/references.bib: pott2018)
"""

from __future__ import annotations

import numpy as np

from taut.errors import PoseError
from taut.kinematics._swivel import swivel_parameters, swivel_paths
from taut.model import Robot

#: A cable shorter than this [m] has no direction: the pose is rejected.
MIN_LENGTH = 1e-12

#: ``ik_status`` codes of a cable at a pose: its quantities exist, or why they do not.
CABLE_OK, ZERO_LENGTH, ON_SWIVEL_AXIS, ON_PULLEY = 0, 1, 2, 3

STATUS_REASONS = {
    ZERO_LENGTH: "has zero length (its anchor is at its exit point)",
    ON_SWIVEL_AXIS: "has its anchor on the axis of its swivelling pulley (the pulley's swivel angle is undefined)",
    ON_PULLEY: "has its anchor on or inside the circle of its swivelling pulley (no tangent to leave it by)",
}


def cable_paths(robot: Robot, anchors: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Cable lengths ``(N, n)``, the points where their straight parts begin ``(N, n, d)``
    (exit points, or tangent points of swivelling pulleys) and their status ``(N, n)`` (see
    :func:`ik_status`) for the platform anchors ``(N, n, d)`` in the fixed frame."""
    if not isinstance(anchors, np.ndarray) or anchors.shape[1:] != robot.exits.shape or anchors.ndim != 3:
        raise PoseError(
            f"{robot.name}: expected anchors of shape (N, {robot.n_cables}, {robot.dimension}), got {np.shape(anchors)}"
        )
    exits = np.broadcast_to(robot.exits[None], anchors.shape)
    v = exits - anchors
    lengths = np.sqrt(np.einsum("nki,nki->nk", v, v))
    status = np.where(lengths < MIN_LENGTH, ZERO_LENGTH, CABLE_OK)
    if robot.swivel_cables:
        idx, axes, radii = swivel_parameters(robot)
        paths = swivel_paths(robot.exits[idx], axes, radii, anchors[:, idx])
        exits = exits.copy()
        lengths[:, idx] = paths.lengths
        exits[:, idx] = paths.tangent_points
        status[:, idx] = np.select([paths.on_axis, paths.on_pulley], [ON_SWIVEL_AXIS, ON_PULLEY], CABLE_OK)
    return lengths, exits, status
