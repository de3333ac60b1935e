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

#: The status codes of a cable at a pose (:func:`~taut.kinematics.ik_status`,
#: :func:`cable_paths`): ``CABLE_OK`` (0) its direction and structure-matrix column exist;
#: ``ZERO_LENGTH`` (1) its anchor is at its exit point; ``ON_SWIVEL_AXIS`` (2) its anchor is on
#: the axis of its swivelling pulley; ``ON_PULLEY`` (3) its anchor is on or inside the pulley's
#: circle.  Only ``CABLE_OK`` is exported: test ``status == CABLE_OK``.
CABLE_OK, ZERO_LENGTH, ON_SWIVEL_AXIS, ON_PULLEY = 0, 1, 2, 3

STATUS_REASONS = {
    ZERO_LENGTH: "has zero length (its anchor is at its exit point)",
    ON_SWIVEL_AXIS: "has its anchor on the axis of its swivelling pulley (the pulley's swivel angle is undefined)",
    ON_PULLEY: "has its anchor on or inside the circle of its swivelling pulley (no tangent to leave it by)",
}


def cable_paths(robot: Robot, anchors: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Where each cable runs, given its platform anchor: its length, the start of its straight
    part and whether its direction exists.

    Parameters
    ----------
    robot : Robot
    anchors : ndarray, shape (N, n, d)
        Platform anchors in the fixed frame [m] (:func:`~taut.kinematics.anchors_at`).

    Returns
    -------
    lengths : ndarray, shape (N, n)
        Cable lengths [m], the arc on a swivelling pulley included.
    starts : ndarray, shape (N, n, d)
        Where the straight part of each cable begins [m]: its exit point, or the tangent
        point of its swivelling pulley.
    status : ndarray of int, shape (N, n)
        :data:`CABLE_OK` or why the cable has no direction (see :func:`ik_status`).

    Raises
    ------
    PoseError
        ``anchors`` is not an ``(N, n, d)`` array.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §2.1.1, Eq. 2.1. (docs/references.bib: rushton2022)
    .. [2] A. Pott, "Cable-Driven Parallel Robots: Theory and Application", Springer Tracts in
       Advanced Robotics 120, Springer, 2018, pulley kinematics. (docs/references.bib: pott2018)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.kinematics import anchors_at, cable_paths
    >>> robot = example("planar-4cable")
    >>> lengths, starts, status = cable_paths(robot, anchors_at(robot, np.zeros((1, 3))))
    >>> lengths.round(4), starts[0, 0], status
    (array([[1.3086, 1.3086, 1.3086, 1.3086]]), array([-1., -1.]), array([[0, 0, 0, 0]]))
    """
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
