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
import numpy.typing as npt

from taut.errors import PoseError, UnsupportedRobotError, WrappedCableError
from taut.geometry import segment_enters_polygon, segment_meets_circle
from taut.kinematics._pose import anchors_at, as_poses
from taut.kinematics._routing import routed_segments
from taut.kinematics._swivel import swivel_parameters, swivel_paths
from taut.model import Robot

#: A cable shorter than this [m] has no direction: the pose is rejected.
MIN_LENGTH = 1e-12

#: Round-off allowance [m] of a cable meeting a spherical obstacle (that of the planar tests,
#: :func:`taut.geometry.segment_meets_circle`).
TOL = 1e-9

#: The status codes of a cable at a pose (:func:`~taut.kinematics.ik_status`,
#: :func:`cable_paths`): ``CABLE_OK`` (0) its direction and structure-matrix column exist;
#: ``ZERO_LENGTH`` (1) its anchor is at its exit point; ``ON_SWIVEL_AXIS`` (2) its anchor is on
#: the axis of its swivelling pulley; ``ON_PULLEY`` (3) its anchor is on or inside the pulley's
#: circle; ``WRAPPED`` (4) the straight cable meets an obstacle of a variable-structure robot
#: (:func:`obstacles_met`).  Only ``CABLE_OK`` is exported: test ``status == CABLE_OK``.
CABLE_OK, ZERO_LENGTH, ON_SWIVEL_AXIS, ON_PULLEY, WRAPPED = 0, 1, 2, 3, 4

STATUS_REASONS = {
    ZERO_LENGTH: "has zero length (its anchor is at its exit point)",
    ON_SWIVEL_AXIS: "has its anchor on the axis of its swivelling pulley (the pulley's swivel angle is undefined)",
    ON_PULLEY: "has its anchor on or inside the circle of its swivelling pulley (no tangent to leave it by)",
    WRAPPED: "meets an obstacle",
}


def first_obstacle(robot: Robot, starts: np.ndarray, anchors: np.ndarray) -> np.ndarray:
    """The 0-based index of the first obstacle each straight segment ``starts → anchors``
    meets, ``-1`` where it meets none: ``(N, n)`` int.

    A segment meets a circle when it enters the open disc, and a polygon when it enters its
    interior (:func:`~taut.geometry.segment_meets_circle`,
    :func:`~taut.geometry.segment_enters_polygon`, within their round-off tolerance): the
    test by which :mod:`taut.wrapping` decides that a straight cable is no longer taut.  A
    cable that only touches an obstacle has its straight length and direction.  In space a
    circle obstacle is a ball (:func:`~taut.geometry.segment_distance` from its centre).

    Raises
    ------
    UnsupportedRobotError
        A polygon obstacle of a spatial robot.
    """
    met = np.full(anchors.shape[:2], -1, dtype=np.int64)
    for k in range(len(robot.obstacles) - 1, -1, -1):  # the lowest index wins
        o = robot.obstacles[k]
        if o.kind == "polygon" and robot.dimension == 3:
            raise UnsupportedRobotError(
                f"{robot.name}: obstacle {k + 1} is a polygon in space; straight cables are tested against "
                "spheres in space (circle obstacles) and polygons in the plane"
            )
        if o.kind == "polygon":
            hit = segment_enters_polygon(starts, anchors, np.asarray(o.vertices, float))
        elif robot.dimension == 2:
            hit = segment_meets_circle(starts, anchors, np.asarray(o.center, float), o.radius)
        else:  # a sphere: the distance from its centre, as a zero-length segment, to the cable
            from taut.geometry import segment_distance  # Numba: spatial obstacles only

            c = np.asarray(o.center, float)
            hit = segment_distance(starts, anchors, c, c) < o.radius - TOL
        met[hit] = k
    return met


def wrapped_error(robot: Robot, where: str, cable: int, obstacle: int) -> WrappedCableError:
    """The one-line error of a straight cable meeting an obstacle (0-based ``cable`` and
    ``obstacle``, named 1-based as in the robot file; ``where`` e.g. ``"at pose 3"``)."""
    o = robot.obstacles[obstacle]
    name = f" ({o.name})" if o.name else ""
    return WrappedCableError(
        f"{robot.name}: {where} cable {cable + 1} meets obstacle {obstacle + 1}{name} as a straight line: "
        "its wrapped length depends on the motion; taut trajectory models the wrapping"
    )


def obstacles_met(robot: Robot, poses: npt.ArrayLike) -> np.ndarray:
    """The obstacle each cable of a variable-structure robot meets when taken as a straight
    line from its exit to its anchor.

    Where it meets one, the cable wraps around it: its length and direction depend on the
    motion that led to the pose (:mod:`taut.wrapping`), and the straight-cable analyses
    (:func:`~taut.kinematics.inverse_kinematics`, the tensions, workspaces, checks and
    simulations) do not hold.  A cable that only touches an obstacle tangentially keeps its
    straight length and direction (the test of :mod:`taut.wrapping`).

    Parameters
    ----------
    robot : Robot
    poses : array_like, shape (N, pose_size) or (pose_size,)

    Returns
    -------
    ndarray of int, shape (N, n) or (n,) for one pose
        The 0-based index of the first obstacle (in ``robot.obstacles``) each cable meets, or
        ``-1``; all ``-1`` for a robot without obstacles.

    Raises
    ------
    PoseError
        Poses that :func:`~taut.kinematics.as_poses` refuses.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §4.2.1, Appendix A.2. (docs/references.bib: rushton2022)

    Examples
    --------
    At the start pose of ``vscr-four-cable`` every straight cable clears the obstacles; at
    ``(0, -0.7)`` cables 1 and 2 run through objects 2 and 3, centred at ``(∓0.75, 0.5)``:

    >>> from taut.model import example
    >>> from taut.kinematics import obstacles_met
    >>> robot = example("vscr-four-cable")
    >>> obstacles_met(robot, [[0.75, -0.5], [0, -0.7]])
    array([[-1, -1, -1, -1],
           [ 1,  2, -1, -1]])
    """
    arr, single = as_poses(robot, poses)
    b = anchors_at(robot, arr)
    met = first_obstacle(robot, cable_paths(robot, b)[1], b) if robot.obstacles else np.full(b.shape[:2], -1)
    return met[0] if single else met


def cable_paths(
    robot: Robot, anchors: np.ndarray, *, via: np.ndarray | None = None
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Where each cable runs, given its platform anchor: its length, the start of its straight
    part and whether its direction exists.

    Parameters
    ----------
    robot : Robot
    anchors : ndarray, shape (N, n, d)
        Platform anchors in the fixed frame [m] (:func:`~taut.kinematics.anchors_at`).
    via : ndarray, shape (N, V, d), optional
        The via points of the routed cables (``cables[].via``) in the fixed frame, in cable
        order then path order; needed, and only allowed, when the robot has routed cables.

    Returns
    -------
    lengths : ndarray, shape (N, n)
        Cable lengths [m], the arc on a swivelling pulley and the segments through via points
        included.
    starts : ndarray, shape (N, n, d)
        Where the straight part of each cable that ends at its anchor begins [m]: its exit
        point, the tangent point of its swivelling pulley, or its last via point.
    status : ndarray of int, shape (N, n)
        :data:`CABLE_OK` or why the cable has no direction (see :func:`ik_status`; a routed
        cable with a segment of zero length has none), or why its straight line is not the
        cable (it meets an obstacle, :func:`obstacles_met`).

    Raises
    ------
    PoseError
        ``anchors`` is not an ``(N, n, d)`` array.
    UnsupportedRobotError
        A robot with routed cables without ``via`` (an analysis that takes each cable as one
        straight segment), or with obstacles.

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
    chain = None
    if robot.routed_cables:
        refuse_routed(robot, "" if via is None else None)
        if robot.obstacles:
            raise UnsupportedRobotError(
                f"{robot.name}: cables run through via points (cables[].via) on a robot with obstacles, "
                "whose cables taut wraps as single straight segments"
            )
        chain, exits, shortest, _ = routed_segments(robot, anchors, np.asarray(via))
    v = exits - anchors
    lengths = np.sqrt(np.einsum("nki,nki->nk", v, v))
    status = np.where(lengths < MIN_LENGTH, ZERO_LENGTH, CABLE_OK)
    if chain is not None:
        lengths = lengths + chain
        status = np.where(shortest < MIN_LENGTH, ZERO_LENGTH, status)
    if robot.swivel_cables:
        idx, axes, radii = swivel_parameters(robot)
        paths = swivel_paths(robot.exits[idx], axes, radii, anchors[:, idx])
        exits = exits.copy()
        lengths[:, idx] = paths.lengths
        exits[:, idx] = paths.tangent_points
        status[:, idx] = np.select([paths.on_axis, paths.on_pulley], [ON_SWIVEL_AXIS, ON_PULLEY], CABLE_OK)
    if robot.obstacles:
        status = np.where((status == CABLE_OK) & (first_obstacle(robot, exits, anchors) >= 0), WRAPPED, status)
    return lengths, exits, status


def refuse_routed(robot: Robot, what: str | None) -> None:
    """Refuse a robot with routed cables (``cables[].via``) in an analysis ``what`` that takes
    each cable as one straight segment from its exit point to its anchor (``""``: an unnamed
    one; ``None``: the analysis handles them).

    Parameters
    ----------
    robot : Robot
    what : str or None
        The analysis, for the message.

    Raises
    ------
    UnsupportedRobotError
        The robot has routed cables and ``what`` is not None.

    Examples
    --------
    >>> from taut.model import example
    >>> refuse_routed(example("planar-4cable"), "the DGP")
    """
    if robot.routed_cables and what is not None:
        cables = ", ".join(str(i + 1) for i in robot.routed_cables)
        raise UnsupportedRobotError(
            f"{robot.name}: cables {cables} run through via points (cables[].via), and "
            f"{what or 'this analysis'} takes each cable as one straight segment from its exit point to its anchor"
        )


def refuse_wrapped(robot: Robot, poses: npt.ArrayLike, *, times: npt.ArrayLike | None = None, what: str = "") -> None:
    """Refuse poses where a cable of a variable-structure robot, taken as a straight line,
    meets one of its obstacles (:func:`obstacles_met`): analyses of straight cables along a
    motion (``taut simulate``) call it on the motion's poses.

    Parameters
    ----------
    robot : Robot
    poses : array_like, shape (N, pose_size) or (pose_size,)
    times : array_like, shape (N,), optional
        The poses' times [s], to name the first such pose by its time instead of its number.
    what : str, optional
        What the poses are (e.g. ``"of the reference"``), after its time or number.

    Raises
    ------
    WrappedCableError
        At the first such pose, naming the cable and the obstacle (1-based).
    PoseError
        Poses that :func:`~taut.kinematics.as_poses` refuses.

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.kinematics import refuse_wrapped
    >>> refuse_wrapped(example("vscr-four-cable"), [[0.75, -0.5], [0, -0.7]], times=[0, 0.5])
    Traceback (most recent call last):
    ...
    taut.errors.WrappedCableError: VSCR four cables: at t = 0.5 s cable 1 meets obstacle 2 (object 2) as a straight line: its wrapped length depends on the motion; taut trajectory models the wrapping
    """
    if not robot.obstacles:
        return
    met = np.atleast_2d(obstacles_met(robot, poses))
    hit = np.argwhere(met >= 0)
    if hit.size:
        k, i = (int(x) for x in hit[0])
        where = f"at pose {k + 1}" if times is None else f"at t = {float(np.asarray(times, float)[k]):g} s"
        raise wrapped_error(robot, f"{where}{' ' + what if what else ''}", i, int(met[k, i]))
