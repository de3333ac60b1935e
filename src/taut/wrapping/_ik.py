"""Inverse kinematics of planar variable-structure CDPRs (VSCRs) along a path (§4.3 of Rushton 2022).

Two stages per sample (§4.3): update every cable's state for the new platform pose with
Alg. 4.4 (:func:`taut.wrapping.track_cable_state`), then turn states into lengths with
Eq. (4.9).  The platform anchor of cable *i* is ``b_i = p + R(θ) r_i`` (Eq. 4.8; a point
mass has ``r_i = 0``).  Each cable's *active segment* plays the role of the straight cable
of a standard CDPR: ``u_i`` points from ``b_i`` to the last point where the cable touches
an object (or leaves its winch), and the structure matrix of the current structure is
``W = [u_i ; (R r_i) × u_i]`` (Eq. 2.8 with the effective exit points).

The robot's collidable objects are its circle obstacles; a polygon obstacle is, as §4.1
suggests, a zero-radius object at each vertex and a disallowed region inside.  Each cable
starts in the state given by ``initial`` (its wrapped objects and directions) or, by
default, in the shortest taut admissible state at the first pose
(:meth:`CableStateTree.shortest_taut_state`).  Its winch-pulley arc is counted from the
exit angle at that first pose (the calibration pose of §6.1.2).

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §4.3, Eqs. 4.8–4.9, Alg. 4.4. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from taut._results import Result, jsonable
from taut.errors import CableSetError, PoseError, TautError
from taut.geometry import circles_overlap, point_in_polygon
from taut.kinematics import anchor_points, as_poses, refuse_swivels
from taut.model import Circle, Robot
from taut.wrapping._state import CablePath, contact_angle, rebuild_path
from taut.wrapping._tree import DIR, OBJ, CableStateTree
from taut.wrapping._update import track_cable_state


def collidable_objects(robot: Robot) -> tuple[np.ndarray, list[np.ndarray]]:
    """The objects a planar robot's cables can wrap, and the regions they must not enter.

    Parameters
    ----------
    robot : Robot
        A planar robot.

    Returns
    -------
    circles : ndarray, shape (K, 3)
        ``(x, y, r)`` [m]: the circle obstacles, then every vertex of each polygon obstacle
        as a zero-radius object (§4.1).
    disallowed : list of ndarray, shape (V, 2)
        The robot's disallowed regions, then the interior of each polygon obstacle.

    Raises
    ------
    TautError
        A spatial robot, two objects that overlap, or an object overlapping a winch pulley.
    UnsupportedRobotError
        A swivelling pulley.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §4.1. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.wrapping import collidable_objects
    >>> circles, disallowed = collidable_objects(example("vscr-single-cable"))
    >>> circles.shape, len(disallowed)
    ((3, 3), 0)
    """
    refuse_swivels(robot, "cable wrapping")
    if robot.dimension != 2:
        raise TautError(f"{robot.name}: cable wrapping is implemented for planar robots (dimension 2)")
    circles: list[list[float]] | np.ndarray
    circles, polys = [], [np.asarray(p, float) for p in robot.disallowed]
    for o in robot.obstacles:
        if isinstance(o, Circle):
            circles.append([*o.center, o.radius])
        else:
            circles.extend([*v, 0.0] for v in o.vertices)
            polys.append(np.asarray(o.vertices, float))
    circles = np.asarray(circles, float).reshape(-1, 3)
    names = [f"object {k + 1}" for k in range(len(circles))]
    winches = np.array([[*c.exit, c.pulley.radius if c.pulley else 0.0] for c in robot.cables])
    for i in range(len(circles)):
        for j in range(i + 1, len(circles)):
            if circles_overlap(circles[i, :2], circles[i, 2], circles[j, :2], circles[j, 2]):
                raise TautError(f"{robot.name}: {names[i]} and {names[j]} overlap; collidable objects must be disjoint")
        for i2, w in enumerate(winches):
            if circles_overlap(circles[i, :2], circles[i, 2], w[:2], w[2]):
                raise TautError(f"{robot.name}: {names[i]} overlaps the winch of cable {i2 + 1}")
    return circles, polys


def _check_inside(robot: Robot, circles: np.ndarray, polys: list, anchors: np.ndarray, what: str) -> None:
    b = anchors.reshape(-1, 2)
    if len(circles):
        d = np.hypot(b[:, None, 0] - circles[None, :, 0], b[:, None, 1] - circles[None, :, 1])
        bad = d < circles[None, :, 2]
        if bad.any():
            s, k = np.argwhere(bad)[0]
            raise PoseError(
                f"{what}: the platform anchor {[round(float(x), 6) for x in b[s]]} is inside object {k + 1}"
            )
    n_obst = sum(1 for o in robot.obstacles if not isinstance(o, Circle))
    for poly in polys[len(polys) - n_obst :] if n_obst else []:
        inside = point_in_polygon(b, poly)
        if inside.any():
            raise PoseError(
                f"{what}: the platform anchor {[round(float(x), 6) for x in b[np.argmax(inside)]]} is inside a polygon obstacle"
            )


@dataclass(frozen=True)
class WrappedIK(Result):
    """VSCR inverse kinematics over ``T`` poses of a robot with ``n`` cables
    (:func:`wrapped_inverse_kinematics`).

    Attributes
    ----------
    poses : ndarray, shape (T, pose_size)
    anchors : ndarray, shape (T, n, 2)
        Platform anchors ``b_i`` [m].
    lengths : ndarray, shape (T, n)
        Cable lengths [m] (Eq. 4.9).
    nodes : ndarray of int, shape (T, n)
        The tracked node of each cable's state tree.
    directions : ndarray, shape (T, n, 2)
        Unit vectors ``u_i`` from the anchor to the last contact.
    exit_points : ndarray, shape (T, n, 2)
        Where each active segment leaves its last object.
    structure_matrix : ndarray, shape (T, m, n)
    events : tuple of ndarray, shape (E, 4)
        Per cable, rows ``(sample, fraction, kind, node)`` (:class:`Tracking`).
    trees : tuple of CableStateTree
        Each cable's state tree.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §4.3, Eqs. 4.8–4.9. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.wrapping import wrapped_inverse_kinematics
    >>> robot = example("vscr-single-cable")
    >>> ik = wrapped_inverse_kinematics(robot, [[0.0, 2.0], [4.0, 0.5]])
    >>> np.round(ik.lengths[:, 0], 4), ik.contacts(1, 0)
    (array([2.    , 4.8683]), ((0, -1),))
    """

    poses: np.ndarray  #: ``(T, pose_size)``
    anchors: np.ndarray  #: ``(T, n, 2)`` platform anchors ``b_i``
    lengths: np.ndarray  #: ``(T, n)`` cable lengths (Eq. 4.9)
    nodes: np.ndarray  #: ``(T, n)`` tracked CST node of each cable
    directions: np.ndarray  #: ``(T, n, 2)`` unit vectors ``u_i`` (platform → last contact)
    exit_points: np.ndarray  #: ``(T, n, 2)`` where each active segment leaves its object
    structure_matrix: np.ndarray  #: ``(T, m, n)``
    events: tuple[np.ndarray, ...]  #: per cable, ``(E, 4)`` rows ``(sample, fraction, kind, node)``
    trees: tuple[CableStateTree, ...] = field(repr=False)  #: the cable-state tree of each cable

    def contacts(self, sample: int, cable: int) -> tuple[tuple[int, int], ...]:
        """Objects wrapped by ``cable`` at ``sample`` (0-based), with directions."""
        return self.trees[cable].contacts(int(self.nodes[sample, cable]))

    def path(self, sample: int, cable: int) -> CablePath:
        """The full path (segments and arcs) of ``cable`` at ``sample``."""
        tree = self.trees[cable]
        return rebuild_path(
            tree.circles, tree.winch_direction, tree.state(int(self.nodes[sample, cable])), self.anchors[sample, cable]
        )

    def transitions(self, times: npt.ArrayLike | None = None) -> list[dict]:
        """Wraps and unwraps in time order: ``{"time", "sample", "cable", "kind", "object"}``
        with 0-based cable and object indices (``time`` interpolated within the step)."""
        t = np.arange(len(self.poses), dtype=float) if times is None else np.asarray(times, float)
        out = []
        for i, ev in enumerate(self.events):
            for j, tau, kind, node in ev:
                j, node = int(j), int(node)
                out.append(
                    {
                        "time": float(t[j - 1] + tau * (t[j] - t[j - 1])),
                        "sample": j,
                        "cable": i,
                        "kind": "wrap" if kind == 1 else "unwrap",
                        "object": int(self.trees[i].I[node, OBJ]),
                    }
                )
        return sorted(out, key=lambda e: (e["time"], e["cable"]))

    def as_dict(self) -> dict:
        """The inverse kinematics in plain JSON types, without the trees: ``poses``,
        ``anchors``, ``lengths``, ``directions``, ``exit_points``, ``structure_matrix``,
        ``states`` (per sample and cable, the wrapped ``[object, direction]`` pairs, 0-based
        objects) and ``transitions`` (:meth:`transitions`, sample numbers as times)."""
        n = len(self.trees)
        return {
            "poses": jsonable(self.poses),
            "anchors": jsonable(self.anchors),
            "lengths": jsonable(self.lengths),
            "directions": jsonable(self.directions),
            "exit_points": jsonable(self.exit_points),
            "structure_matrix": jsonable(self.structure_matrix),
            "states": [[jsonable(self.contacts(s, i)) for i in range(n)] for s in range(len(self.poses))],
            "transitions": self.transitions(),
        }


def _reference_angle(tree: CableStateTree, node: int, b: npt.ArrayLike) -> float:
    path = tree.path(node)
    if len(path) > 1:
        u = tree.F[path[1], [4, 5]]
    else:
        _, u, _, _ = tree.active_segment(0, b)
    return float(contact_angle(u, tree.winch_direction))


def wrapped_inverse_kinematics(
    robot: Robot, poses: npt.ArrayLike, *, initial: Mapping[int, Sequence[tuple[int, int]]] | None = None
) -> WrappedIK:
    """Inverse kinematics of a planar variable-structure robot along a path: every cable's
    state tracked, its length and the structure matrix (§4.3).

    Parameters
    ----------
    robot : Robot
        A planar robot.
    poses : array_like, shape (T, pose_size)
        Consecutive poses, joined by straight moves of the anchors.
    initial : mapping of int to sequence of (int, int), optional
        0-based cable index → its starting state ``[(object index, ±1), ...]``; by default
        the shortest taut state at the first pose.

    Returns
    -------
    WrappedIK

    Raises
    ------
    PoseError
        Bad poses, or an anchor inside an object.
    CableSetError
        ``initial`` of cables the robot does not have.
    TautError
        A start state that is not taut or not a state of the cable, or overlapping objects.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §4.3, Alg. 4.4, Eq. 4.9. (docs/references.bib: rushton2022)

    Examples
    --------
    The single-cable robot of §4.4 moving straight from ``(0, 2)`` to ``(4, 0.5)``: its
    cable wraps the first disc clockwise.

    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.wrapping import wrapped_inverse_kinematics
    >>> robot = example("vscr-single-cable")
    >>> ik = wrapped_inverse_kinematics(robot, [[0.0, 2.0], [4.0, 0.5]])
    >>> ik.contacts(0, 0), ik.contacts(1, 0), ik.structure_matrix.shape
    ((), ((0, -1),), (2, 2, 1))
    """
    arr, _ = as_poses(robot, poses)
    initial = initial or {}
    if not isinstance(initial, Mapping) or any(
        isinstance(i, bool) or not isinstance(i, (int, np.integer)) or not 0 <= i < robot.n_cables for i in initial
    ):
        raise CableSetError(
            f"initial: expected a mapping of cable indices 0..{robot.n_cables - 1} to states, got {initial!r}"
        )
    circles, polys = collidable_objects(robot)
    b = np.asarray(anchor_points(robot, arr), float)
    _check_inside(robot, circles, polys, b, robot.name)
    T, n = b.shape[:2]
    lengths, nodes = np.zeros((T, n)), np.zeros((T, n), dtype=np.int64)
    act, exits = np.zeros((T, n, 2)), np.zeros((T, n, 2))
    events, trees = [], []
    for i, cable in enumerate(robot.cables):
        r0 = cable.pulley.radius if cable.pulley else 0.0
        d0 = -1 if cable.pulley and cable.pulley.direction == "cw" else 1
        cc = np.vstack([circles, [[*cable.exit, r0]]])
        probe = CableStateTree(cc, d0, disallowed=polys)
        start = _start_node(probe, b[0, i], initial.get(i), i)
        tree = CableStateTree(cc, d0, disallowed=polys, reference_angle=_reference_angle(probe, start, b[0, i]))
        start = tree.find(probe.contacts(start))
        tr = track_cable_state(tree, b[:, i], node=start)
        lengths[:, i], nodes[:, i], act[:, i] = tr.lengths, tr.nodes, tr.directions
        events.append(tr.events)
        trees.append(tree)
    for i, tree in enumerate(trees):
        obj = tree.I[nodes[:, i], OBJ]
        d = tree.F[nodes[:, i], DIR]
        c, r = tree.circles[obj, :2], tree.circles[obj, 2]
        nrm = np.column_stack([-act[:, i, 1], act[:, i, 0]])
        exits[:, i] = c - (d * r)[:, None] * nrm
    u = -act
    W = np.swapaxes(u, 1, 2)
    if not robot.is_point_mass:
        p = arr[:, None, :2]
        rb = b - p
        mom = rb[..., 0] * u[..., 1] - rb[..., 1] * u[..., 0]
        W = np.concatenate([W, mom[:, None, :]], axis=1)
    return WrappedIK(arr, b, lengths, nodes, u, exits, W, tuple(events), tuple(trees))


def _start_node(tree: CableStateTree, b: np.ndarray, contacts: Sequence[tuple[int, int]] | None, i: int) -> int:
    if contacts is None:
        return tree.shortest_taut_state(b)
    node = tree.find(contacts)
    if not tree.is_taut(node, b):
        raise TautError(
            f"cable {i + 1}: the start state {list(contacts)} is not taut at {[round(float(x), 6) for x in b]} "
            "(its last segment wraps backwards, meets an object or enters a disallowed region)"
        )
    return node
