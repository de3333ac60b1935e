"""Swivelling exit pulleys: the cable length with the arc wound on the pulley, and the
tangent point where the straight part of the cable begins.

The cable comes from its winch along the swivel axis (unit vector ``k``) and runs onto the
pulley at the fixed point ``D`` on that axis.  The pulley turns about the axis until its
plane contains the platform anchor ``b``: with ``w`` the part of ``b − D`` normal to the axis,
``d = ‖w‖`` the anchor's distance from the axis and ``e = w/d``, the pulley centre is
``M = D + r e``.  In the pulley plane, with coordinates along ``e`` and ``k`` about ``M``, the
cable runs onto the circle at ``(−r, 0)`` heading along ``k`` and wraps around it through the
angle ``β`` to the tangent point ``C = M + r(−cos β e + sin β k)``, where its direction
``sin β e + cos β k`` points at the anchor.  With the anchor at ``(x, y) = (d − r, k·(b − D))``,
``ρ = ‖(x, y)‖`` and the free length ``l_f = √(ρ² − r²)``, tangency gives
``β = atan2(x, y) + atan2(r, l_f)`` taken in ``[0, 2π)``, and the cable length is
``l = r β + l_f`` (Pott 2018; WireX's ``doInverseKinematicsPulleyEx``).  The two-``arccos``
form of the wrap angle found in the literature is this one for ``d ≥ r``; the ``atan2`` form
also holds for anchors closer to the axis than the pulley centre and for wraps beyond a
half turn.

Because ``C`` is the point of tangency, ``∂l/∂b = (b − C)/l_f``: the structure matrix uses
``u = (C − b)/l_f`` in place of the direction to the fixed exit point.

The geometry does not exist when the anchor is on the swivel axis (``d = 0``: the pulley's
swivel angle is undefined) or on or inside the pulley circle (``ρ ≤ r``: no tangent).

**Swivel angle.**  :func:`swivel_angles` gives the angle ``γ`` the pulley has turned about its
axis, as WireX measures it (``doInverseKinematicsPulleyEx``: ``γ = atan2(b_y, b_x)`` of the
anchor in the winch frame): from the x axis of the winch frame
(:func:`taut.geometry.axis_frames`) whose z axis is the unit swivel axis (the frame taut
writes into WireX files; the identity for the axis ``(0, 0, 1)``).

**Planar robots.**  On a planar robot the swivel axis lies in the robot's plane, and so do
the exit point and every anchor: ``w``, ``e`` and the pulley plane spanned by ``e`` and ``k``
are the robot's plane, and the spatial model above is a planar one exactly.  The cable comes
along the fixed in-plane direction ``k``, wraps the pulley whose centre ``D + r e`` lies on
the anchor's side of the axis line, and leaves tangentially towards the anchor; when the
anchor crosses the axis line the pulley turns half a turn and faces it from the other side
(``γ`` jumps between 0 and π).  The length is continuous there, its direction is not
(``d = 0`` is singular, as in space).  This is not the planar winch pulley ``cables[].pulley``
of the wrapping model, whose centre is the fixed exit point and whose arc is counted from a
calibration angle.

References
----------
.. [1] A. Pott, "Cable-Driven Parallel Robots: Theory and Application", Springer Tracts in
   Advanced Robotics 120, Springer, 2018, pulley kinematics. (docs/references.bib: pott2018)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from taut._results import Result
from taut.errors import InfeasiblePoseError, TautError, UnsupportedRobotError
from taut.geometry import axis_frames
from taut.kinematics._pose import anchors_at, as_poses
from taut.model import Robot

#: Relative tolerance of the singular configurations: an anchor nearer the swivel axis, or
#: a free length shorter, than this times ``r + ‖b − D‖`` has no swivel angle or no tangent.
SINGULAR_TOL = 1e-9


@dataclass(frozen=True)
class SwivelPaths(Result):
    """The cables through swivelling pulleys at ``N`` poses, ``s`` such cables
    (:func:`swivel_paths`).

    Attributes
    ----------
    lengths : ndarray, shape (N, s)
        Cable lengths ``r β + l_f`` [m]: the arc wound on the pulley and the free length.
    tangent_points : ndarray, shape (N, s, d)
        Points ``C`` where the cables leave the pulleys [m].
    wrap : ndarray, shape (N, s)
        Wrap angles ``β`` [rad], in ``[0, 2π)``.
    on_axis : ndarray of bool, shape (N, s)
        Anchors on a swivel axis (no swivel angle).
    on_pulley : ndarray of bool, shape (N, s)
        Anchors on or inside the pulley circle (no tangent).

    References
    ----------
    .. [1] A. Pott, "Cable-Driven Parallel Robots: Theory and Application", Springer Tracts in
       Advanced Robotics 120, Springer, 2018, pulley kinematics. (docs/references.bib: pott2018)

    Examples
    --------
    >>> from taut.kinematics import swivel_paths
    >>> paths = swivel_paths([[0, 0, 0]], [[0, 0, 1]], [0.1], [[[1.0, 0, 0]]])
    >>> sorted(paths.as_dict())
    ['lengths', 'on_axis', 'on_pulley', 'tangent_points', 'wrap']
    """

    lengths: np.ndarray  #: ``(N, s)`` cable lengths ``r β + l_f``
    tangent_points: np.ndarray  #: ``(N, s, 3)`` points ``C`` where the cables leave the pulleys
    wrap: np.ndarray  #: ``(N, s)`` wrap angles ``β`` [rad]
    on_axis: np.ndarray  #: ``(N, s)`` anchors on a swivel axis (no swivel angle)
    on_pulley: np.ndarray  #: ``(N, s)`` anchors on or inside the pulley circle (no tangent)


def swivel_parameters(robot: Robot) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The swivelling pulleys of a robot: which cables, their unit axes and radii.

    Parameters
    ----------
    robot : Robot

    Returns
    -------
    indices : ndarray of int, shape (s,)
        The 0-based cables that leave through a swivelling pulley (``robot.swivel_cables``).
    axes : ndarray, shape (s, d)
        Their unit swivel axes.
    radii : ndarray, shape (s,)
        Their pulley radii [m].

    Examples
    --------
    >>> from taut.model import example
    >>> robot = example("spatial-8cable")
    >>> pulleys = {"swivel": {"axis": (0, 0, 1), "radius": 0.05}}
    >>> robot = robot.model_copy(update={"cables": tuple(c.model_copy(update=pulleys) for c in robot.cables)})
    >>> from taut.kinematics import swivel_parameters
    >>> indices, axes, radii = swivel_parameters(robot)
    >>> indices, axes[0], float(radii[0])
    (array([0, 1, 2, 3, 4, 5, 6, 7]), array([0., 0., 1.]), 0.05)
    """
    idx = np.array(robot.swivel_cables, dtype=int)
    swivels = [robot.cables[i].swivel for i in robot.swivel_cables]
    axes = np.array([s.axis for s in swivels if s is not None], dtype=float).reshape(-1, robot.dimension)
    axes /= np.linalg.norm(axes, axis=1, keepdims=True)
    radii = np.array([s.radius for s in swivels if s is not None], dtype=float)
    return idx, axes, radii


def in_space(x: np.ndarray) -> np.ndarray:
    """Points or vectors ``(..., 2)`` of a robot's plane as ``(..., 3)`` with z = 0; ``(..., 3)`` as given."""
    if x.shape[-1] == 3:
        return x
    return np.concatenate([x, np.zeros((*x.shape[:-1], 1))], axis=-1)


def swivel_paths(
    points: npt.ArrayLike, axes: npt.ArrayLike, radii: npt.ArrayLike, anchors: npt.ArrayLike
) -> SwivelPaths:
    """Lengths and tangent points of cables that leave through swivelling pulleys.

    The wrap angle is ``β = atan2(x, h) + atan2(r, l_f)`` in ``[0, 2π)`` and the length
    ``r β + l_f`` (the module's docstring derives them).  Every output is finite; poses flagged
    ``on_axis`` or ``on_pulley`` have a length (at ``d = 0`` it does not depend on the pulley
    plane) but no meaningful tangent point.

    Parameters
    ----------
    points : array_like, shape (s, d)
        Where each cable runs onto its pulley (the exit points) [m]; ``d`` is 3, or 2 for a
        planar robot (axes in its plane).
    axes : array_like, shape (s, d)
        Unit swivel axes, along which the cables come from their winches.
    radii : array_like, shape (s,)
        Pulley radii [m].
    anchors : array_like, shape (N, s, d)
        Platform anchors in the fixed frame [m].

    Returns
    -------
    SwivelPaths

    Raises
    ------
    TautError
        Arguments that are not numbers or not of matching shapes.

    References
    ----------
    .. [1] A. Pott, "Cable-Driven Parallel Robots: Theory and Application", Springer Tracts in
       Advanced Robotics 120, Springer, 2018, pulley kinematics. (docs/references.bib: pott2018)

    Examples
    --------
    An anchor 1 m from a pulley of radius 0.1 m, level with it: the cable wraps
    ``β = π/2 + atan2(0.1, √0.8)`` and its length is ``0.1 β + √0.8``:

    >>> from taut.kinematics import swivel_paths
    >>> paths = swivel_paths([[0, 0, 0]], [[0, 0, 1]], [0.1], [[[1.0, 0, 0]]])
    >>> paths.wrap.round(4), paths.lengths.round(4)
    (array([[1.6821]]), array([[1.0626]]))
    """
    points, axes, radii, anchors = _swivel_arrays(points, axes, radii, anchors)
    d = points.shape[-1]
    if d == 2:
        # an anchor on the axis line: the pulley plane is still the robot's plane
        fallback = np.column_stack([-axes[:, 1], axes[:, 0], np.zeros(len(axes))])
        points, axes, anchors = in_space(points), in_space(axes), in_space(anchors)
    else:
        fallback = axis_frames(axes)[:, :, 1]
    v = anchors - points[None]
    h = np.einsum("nsi,si->ns", v, axes)
    w = v - h[..., None] * axes[None]
    dist = np.linalg.norm(w, axis=-1)
    scale = radii[None] + np.linalg.norm(v, axis=-1)
    on_axis = dist <= SINGULAR_TOL * scale
    e = np.where(on_axis[..., None], fallback[None], w / np.where(on_axis, 1.0, dist)[..., None])
    x = dist - radii[None]
    rho2 = x * x + h * h
    free = np.sqrt(np.maximum(rho2 - radii[None] ** 2, 0.0))
    on_pulley = free <= SINGULAR_TOL * scale
    wrap = np.arctan2(x, h) + np.arctan2(radii[None], free)
    # atan2(x, h) lies in (−π, π]: a negative sum is a wrap of more than half a turn
    wrap = np.where(wrap < 0.0, wrap + 2.0 * np.pi, wrap)
    centre = points[None] + radii[None, :, None] * e
    tangent = centre + radii[None, :, None] * (-np.cos(wrap)[..., None] * e + np.sin(wrap)[..., None] * axes[None])
    return SwivelPaths(radii[None] * wrap + free, tangent[..., :d], wrap, on_axis, on_pulley)


def _swivel_arrays(
    points: npt.ArrayLike, axes: npt.ArrayLike, radii: npt.ArrayLike, anchors: npt.ArrayLike
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The arguments of :func:`swivel_paths` as float arrays of matching shapes."""
    try:
        arrays = [np.asarray(x, dtype=float) for x in (points, axes, radii, anchors)]
    except (TypeError, ValueError):
        raise TautError("swivel_paths takes arrays of numbers") from None
    p, k, r, b = arrays
    s = r.shape[0] if r.ndim == 1 else -1
    if p.ndim != 2 or p.shape[1] not in (2, 3) or p.shape != k.shape or s != p.shape[0] or b.shape[1:] != p.shape:
        raise TautError(
            "swivel_paths takes points (s, d), axes (s, d), radii (s,) and anchors (N, s, d) with d = 2 or 3, got "
            f"shapes {p.shape}, {k.shape}, {r.shape}, {b.shape}"
        )
    return p, k, r, b


def swivel_angles(robot: Robot, poses: npt.ArrayLike) -> np.ndarray:
    """The swivel angle ``γ`` of each swivelling pulley at each pose.

    ``γ = atan2(w·y, w·x)`` in ``[−π, π]``, where ``w`` is the anchor's offset from the exit
    point ``b − D`` and ``x``, ``y`` the first two axes of the winch frame
    :func:`taut.geometry.axis_frames` of the unit swivel axis: the rotation of the pulley
    about its axis as WireX measures it (``CKinematics::doInverseKinematicsPulleyEx``,
    ``γ = atan2(b_y, b_x)`` in the winch frame), for a file whose winch frames are those
    taut writes.  On a planar robot ``γ`` is 0 or π: the side of the axis line the pulley
    faces.

    Parameters
    ----------
    robot : Robot
    poses : array_like, shape (N, pose_size) or (pose_size,)

    Returns
    -------
    ndarray, shape (N, s) or (s,) for one pose
        The angles [rad], a column per cable of ``robot.swivel_cables`` in that order.

    Raises
    ------
    UnsupportedRobotError
        The robot has no swivelling pulleys.
    InfeasiblePoseError
        An anchor on a swivel axis (the pulley's angle is undefined there).

    References
    ----------
    .. [1] A. Pott, WireX, 2006–2019, ``WireLib/Kinematics.cpp``
       (``CKinematics::doInverseKinematicsPulleyEx``). (docs/references.bib: wirex)
    .. [2] A. Pott, "Cable-Driven Parallel Robots: Theory and Application", Springer Tracts in
       Advanced Robotics 120, Springer, 2018, pulley kinematics. (docs/references.bib: pott2018)

    Examples
    --------
    Cable 1 leaves ``(−1.5, −1, −1)`` for its anchor at ``(0.15, −0.1, 0.05)``: the pulley
    turns to ``atan2(0.9, 1.65)``:

    >>> from taut.model import example
    >>> robot = example("spatial-8cable")
    >>> pulleys = {"swivel": {"axis": (0, 0, 1), "radius": 0.05}}
    >>> robot = robot.model_copy(update={"cables": tuple(c.model_copy(update=pulleys) for c in robot.cables)})
    >>> from taut.kinematics import swivel_angles
    >>> swivel_angles(robot, [0, 0, 0, 0, 0, 0])[:2].round(3)
    array([0.499, 2.642])
    """
    if not robot.swivel_cables:
        raise UnsupportedRobotError(f"{robot.name}: no cable leaves through a swivelling pulley (cables[].swivel)")
    arr, single = as_poses(robot, poses)
    idx, axes, radii = swivel_parameters(robot)
    anchors = anchors_at(robot, arr)[:, idx]
    on_axis = swivel_paths(robot.exits[idx], axes, radii, anchors).on_axis
    if on_axis.any():
        k, j = np.argwhere(on_axis)[0]
        raise InfeasiblePoseError(
            f"{robot.name}: at pose {k + 1} cable {idx[j] + 1} has its anchor on the axis of its swivelling "
            "pulley (the pulley's swivel angle is undefined)"
        )
    frames = axis_frames(in_space(axes))
    w = in_space(anchors - robot.exits[idx][None])
    local = np.einsum("sji,nsj->nsi", frames, w)
    gamma = np.arctan2(local[..., 1], local[..., 0])
    return gamma[0] if single else gamma


def refuse_swivels(robot: Robot, analysis: str) -> None:
    """Refuse a robot with swivelling pulleys for an analysis that takes exits as fixed points.

    Parameters
    ----------
    robot : Robot
    analysis : str
        The analysis' name, for the message (e.g. ``"the geometrico-static problem"``).

    Raises
    ------
    UnsupportedRobotError
        ``robot`` has cables through swivelling pulleys.

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.kinematics import refuse_swivels
    >>> refuse_swivels(example("spatial-8cable"), "this analysis") is None
    True
    """
    if robot.swivel_cables:
        numbers = ", ".join(str(i + 1) for i in robot.swivel_cables)
        raise UnsupportedRobotError(
            f"{robot.name}: {analysis} models cable exits as fixed points; cable(s) {numbers} leave "
            "through swivelling pulleys (cables[].swivel), which it does not handle yet"
        )


def refuse_near_swivel_axis(
    robot: Robot, poses: npt.ArrayLike, *, times: npt.ArrayLike | None = None, what: str = ""
) -> None:
    """Refuse poses where a cable's anchor comes nearer the axis of its swivelling pulley than
    the pulley's radius: analyses along a motion (``taut simulate``) call it on the motion's poses.

    The pulley turns about its axis to face the anchor, its centre a radius ``r`` off the
    axis.  An anchor at ``d < r`` from the axis lies between the axis and the circle the
    centre sweeps: there the swivel angle's rate, the anchor's speed across the pulley plane
    over ``d``, exceeds that speed over ``r`` and grows without bound towards the axis, and
    the pulley models of CASPR (wraps of at most half a turn) and of the MuJoCo export
    (``taut.model._mjcf``, whose wrapping takes the other way round for some such anchors)
    part from taut's arc model.  A motion that takes an anchor there is refused rather than
    simulated.

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
    InfeasiblePoseError
        At the first such pose: the cable (1-based), the anchor's distance from the axis and
        the pulley's radius, the pose.
    PoseError
        Poses that :func:`~taut.kinematics.as_poses` refuses.

    References
    ----------
    .. [1] A. Pott, "Cable-Driven Parallel Robots: Theory and Application", Springer Tracts in
       Advanced Robotics 120, Springer, 2018, pulley kinematics. (docs/references.bib: pott2018)

    Examples
    --------
    The cables of ``suspended-3pulley`` come down along z onto 0.1 m pulleys; cable 1's anchor
    is 0.817 m from the platform's reference point, so that a platform at ``x = −0.75`` brings
    it within 0.067 m of its pulley's axis:

    >>> from taut.model import example
    >>> from taut.kinematics import refuse_near_swivel_axis
    >>> robot = example("suspended-3pulley")
    >>> refuse_near_swivel_axis(robot, [[2.75, 3.98, 5.5, 0, 0, 0], [-0.75, 0, 5.5, 0, 0, 0]], times=[0, 1])
    Traceback (most recent call last):
    ...
    taut.errors.InfeasiblePoseError: suspended 3-pulley robot: at t = 1 s cable 1's anchor is 0.067 m from the axis of its swivelling pulley, within the pulley's radius 0.1 m (pose [-0.75, 0.0, 5.5, 0.0, 0.0, 0.0]); taut's swivelling pulleys keep their anchors beyond their radius from the axis
    """
    if not robot.swivel_cables:
        return
    arr, _ = as_poses(robot, poses)
    idx, axes, radii = swivel_parameters(robot)
    v = anchors_at(robot, arr)[:, idx] - robot.exits[idx][None]
    h = np.einsum("nsi,si->ns", v, axes)
    dist = np.linalg.norm(v - h[..., None] * axes[None], axis=-1)
    near = np.argwhere(dist < radii[None])
    if near.size:
        k, j = (int(x) for x in near[0])
        where = f"at pose {k + 1}" if times is None else f"at t = {float(np.asarray(times, float)[k]):g} s"
        raise InfeasiblePoseError(
            f"{robot.name}: {where}{' ' + what if what else ''} cable {idx[j] + 1}'s anchor is {dist[k, j]:.3g} m from "
            f"the axis of its swivelling pulley, within the pulley's radius {radii[j]:g} m (pose "
            f"{np.round(arr[k], 6).tolist()}); taut's swivelling pulleys keep their anchors beyond their radius from "
            "the axis"
        )
