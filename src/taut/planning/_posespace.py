"""Planning in a robot's own pose space, where its wrench-feasible poses fill an open set:
redundant robots (more cables than wrench components), fully constrained ones, point masses
and planar platforms, in any orientation convention.

A pose is valid when the test of :func:`taut.planning.verify_path` holds there
(:func:`~taut.planning._verify.pose_validity`: wrench feasibility of an ellipsoid around the
external wrench within the tension bounds, cable lengths inside their bounds, and on request
no interference, no cable in an obstacle, lengths inside given bounds).  A straight segment
between two poses (each angle of the orientation along its shortest difference: angles are
2π-periodic, as on the manifold of :mod:`taut.planning._manifold`) is valid when its poses
every ``resolution`` (in pose coordinates, m and rad) are; they are checked in batches.

**Margin.**  Checks at discrete poses cannot see an invalid region thinner than their
spacing, and near singular poses the invalid set can be such a sheet (0.0003–0.0008 wide on
CoGiRo and the 8-cable robot, where the tensions that hold the platform spike).  So the
planners plan with a stricter test (:func:`with_margin`): the wrench ellipsoid's axes
:data:`WRENCH_MARGIN` times longer and every upper tension bound capped at
:data:`TENSION_MARGIN` times the least cap (to a factor 2) that holds the start and the goal.
Both widen such sheets (the tensions diverge on their sides: on CoGiRo, whose tensions are
unbounded, a cap of 1000 N for a 1 N load turns a 0.0008 sheet into a 0.08 one) and keep
paths off the boundary of the valid set.  A path found is checked again every
``resolution / 10`` (ten poses at least per segment) with half that margin (axes √ times,
twice the cap), so that a path grazing the planners' boundary between its checked poses
passes; a segment that fails is replaced by a detour that RRT-Connect finds at that
resolution with the margin, else the unshortened path is tried, else the answer is "not
found"; when the margin leaves no path, the planners run again with the nominal test.  The
returned path is valid at every checked pose, not certified between them.

* ``rrtconnect`` — RRT-Connect (Kuffner & LaValle 2000): two trees, from the start and from
  the goal, each extended one ``step`` toward a random pose of the box and the other then
  connected greedily toward the new node; then the path shortened as OMPL's
  ``PathSimplifier::simplify`` does (:func:`simplify`: vertices dropped, random shortcuts
  between points of the path, partial shortcuts that straighten one coordinate along a
  stretch of it (Geraerts & Overmars 2007), corner cutting, repeated while it gains).  A
  shortcut does not take a path into another class of paths (around an invalid region the
  other way, or turning the platform the other way round: on the 8-cable robot, a turn by
  2.5 rad about z is 2.5 or at least 2π − 2.5 long, and the first path found may take
  either way), so up to :data:`CANDIDATES` paths are searched for, each shortened a
  little, and the shortest of them is shortened further: the best of several solutions, as
  Luna et al. (2013) start from.  Randomised, deterministic for a ``seed`` (unless
  ``time_limit`` stops it); a search that runs out of ``max_nodes`` or time proves nothing.
* ``grid`` — A* over a lattice of the pose box (positions at ``spacing``; each angle at the
  step nearest ``spacing`` that divides 2π, periodic), two lattice points joined when they are
  neighbours (differing by at most one step in each coordinate) and the segment between them
  is valid; the start and the goal join the corners of the lattice cell they lie in (and each
  other) the same way.  When the start's component of this graph is exhausted without reaching
  the goal, **what is proven** is exactly: no chain of valid lattice points, each a neighbour of
  the next with a valid segment between them, joins the start to the goal within the box.  It
  is a proof at the lattice's resolution only: a passage narrower than ``spacing``, or poses
  between the checked points of a segment, may hold a path the lattice misses.

References
----------
.. [1] J. J. Kuffner, S. M. LaValle, "RRT-Connect: an efficient approach to single-query path
   planning", IEEE International Conference on Robotics and Automation, 2000.
   (docs/references.bib: kuffner2000)
.. [2] R. Geraerts, M. H. Overmars, "Creating high-quality paths for motion planning",
   International Journal of Robotics Research 26(8), 2007, §3 (random and partial shortcuts).
   (docs/references.bib: geraerts2007)
.. [3] I. A. Şucan, M. Moll, L. E. Kavraki, "The Open Motion Planning Library", IEEE Robotics &
   Automation Magazine 19(4), 2012 (``PathSimplifier``). (docs/references.bib: sucan2012)
.. [4] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of Cable-Driven
   Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots, Mechanisms and
   Machine Science 12, Springer, 2013, §5. (docs/references.bib: bohigas2013)
.. [5] R. Luna, I. A. Şucan, M. Moll, L. E. Kavraki, "Anytime solution optimization for
   sampling-based motion planning", IEEE International Conference on Robotics and
   Automation, 2013 (several planners' solutions shortened, the best kept and combined).
   (docs/references.bib: luna2013)
"""

from __future__ import annotations

import heapq
import itertools
import time
from collections.abc import Callable
from dataclasses import dataclass, replace
from functools import partial

import numpy as np
import numpy.typing as npt

from taut._checks import as_array
from taut.errors import InfeasiblePoseError, TautError
from taut.model import Robot
from taut.planning._search import PathResult
from taut.planning._verify import angle_columns, pose_validity, refuse_unplannable, short_way, wrench_ellipsoid

__all__ = [
    "POSE_METHODS",
    "SHORTCUTS",
    "PoseSpace",
    "grid_search",
    "pose_space",
    "rrt_connect",
    "simplify",
    "with_margin",
]

#: The planners of :func:`taut.planning.plan_path` that search a robot's pose space.
POSE_METHODS = ("rrtconnect", "grid")
#: Random shortcuts tried on a path when it is shortened, at most.
SHORTCUTS = 2000
#: Shortcuts tried in a row without a shorter path that end a round of them.
PATIENCE = 100
#: Paths RRT-Connect searches for before shortening the one that shortens best (:func:`_shortest`).
CANDIDATES = 3
#: A further path is searched for with at most this many times the tree nodes of the first.
CANDIDATE_NODES = 4
#: Shortcuts tried on each path before the shortest is chosen.
QUICK = 200
#: A shortcut that would shorten the path by less than this fraction of its length is not tried.
MIN_GAIN = 1e-4
#: Shortcuts drawn and checked in one batch.
SHORTCUT_BATCH = 16
#: A shortcut joins a point of the path to another at most ``RANGE`` of its length away along it.
RANGE = 0.33
#: A shortcut's end this near a vertex (a fraction of the path's length) is moved onto it.
SNAP = 0.005
#: Corner-cutting passes per round of shortening.
SMOOTHING = 3
#: Rounds of shortening go on while one shortens the path by more than this fraction.
GAIN = 1e-3
#: The planners' wrench ellipsoid, in multiples of the axes of the one asked for.
WRENCH_MARGIN = 4.0
#: The planners' tension cap, in multiples of the least cap (a power of 2 times 2⁻³⁰ N, or of
#: the largest lower bound) at which the start and the goal are valid.
TENSION_MARGIN = 20
#: A segment longer than twice this many checked poses is first checked at this many, spread.
COARSE = 16
#: Most poses checked in one batch while a tree is connected greedily.
CONNECT_BATCH = 64
#: Most floats held at once by the differences between samples and a tree's nodes.
NEAREST_FLOATS = 1 << 20
#: Random samples whose extensions' ends are checked in one batch.
SAMPLE_BATCH = 64
#: A found path is checked again every ``resolution / FINE``: a segment that crosses a thin
#: invalid region between its checked poses is replaced by a detour.
FINE = 10
#: The detour's tree-node budget is ``max_nodes / REPAIR_SHARE``.
REPAIR_SHARE = 10
#: Steps of the box's diagonal per RRT-Connect step when none is given.
STEPS_PER_DIAGONAL = 20
#: Checked poses per RRT-Connect step (and per lattice spacing) when no resolution is given.
CHECKS_PER_STEP = 8
#: The largest gap between checked poses of a segment when no resolution is given, in pose
#: coordinates (m and rad): the fine step at which paths are verified.
RESOLUTION = 0.01


@dataclass(frozen=True)
class PoseSpace:
    """A robot's pose space for planning: the box of the positions, the periodic angles and
    the validity test of a batch of poses (module docstring)."""

    robot: Robot
    lower: np.ndarray  #: ``(k,)`` box of the poses (angles: −π)
    upper: np.ndarray  #: ``(k,)`` (angles: π)
    angles: np.ndarray  #: indices of the 2π-periodic coordinates
    check: Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]]
    #: :func:`~taut.planning._verify.pose_validity` with the query's options but ``E`` and ``tension_bounds``
    validity: Callable[..., Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]]]
    E: np.ndarray  #: the query's wrench ellipsoid
    #: the space of the test that paths are checked with at last, when this one is stricter
    nominal: PoseSpace | None = None

    @property
    def verified(self) -> PoseSpace:
        """The space of the test that a path is checked with at last (:func:`_finish`)."""
        return self if self.nominal is None else self.nominal

    def valid(self, poses: np.ndarray) -> np.ndarray:
        """``(N,)`` bool: the validity of poses ``(N, k)``."""
        return self.check(np.atleast_2d(poses))[0]

    def diff(self, a: np.ndarray, b: np.ndarray) -> np.ndarray:
        """``b − a`` with the angles the short way."""
        return short_way(b - a, self.angles)

    def segment_ok(
        self, a: np.ndarray, d: np.ndarray, resolution: float, *, closed: bool = False, points: int = 1
    ) -> bool:
        """The segment ``a → a + d`` is valid at every ``resolution`` and at ``points`` evenly
        spaced poses at least, its end included (its start too when ``closed``, else assumed
        valid)."""
        n = max(points, int(np.ceil(np.linalg.norm(d) / resolution)))
        t = np.arange(0 if closed else 1, n + 1) / n
        if len(t) > 2 * COARSE:  # an invalid segment mostly fails at one of a few spread poses
            coarse = np.zeros(len(t), bool)
            coarse[:: len(t) // COARSE] = True
            if not self.valid(a + t[coarse, None] * d).all():
                return False
            t = t[~coarse]
        return bool(self.valid(a + t[:, None] * d).all())

    def segments_ok(
        self,
        a: np.ndarray,
        b: np.ndarray,
        resolution: float,
        *,
        closed: bool = False,
        groups: np.ndarray | None = None,
    ) -> np.ndarray:
        """``(m,)`` bool: the segments ``a[i] → b[i]`` valid at every ``resolution``, their ends
        ``b`` included (``a`` too when ``closed``), checked in two batches: a few spread poses
        of each (as :meth:`segment_ok`), then the other poses of those that pass.  With
        ``groups`` (``(m,)`` non-decreasing, from 0): whether every segment of each group is
        valid, the spread poses spread over the group's and a group failing at one of them
        not checked further."""
        d = b - a
        n = np.maximum(1, np.ceil(np.linalg.norm(d, axis=1) / resolution).astype(int))
        k = n + 1 if closed else n  # poses checked on each
        seg = np.repeat(np.arange(len(a)), k)
        idx = np.arange(len(seg)) - (np.cumsum(k) - k)[seg]  # each pose's rank on its segment
        t = (idx + (0 if closed else 1)) / n[seg]
        group = seg if groups is None else np.asarray(groups)[seg]
        size = np.bincount(group)
        rank = np.arange(len(seg)) - (np.cumsum(size) - size)[group]  # on its group
        coarse = rank % np.maximum(1, size // COARSE)[group] == 0
        bad = np.zeros(len(size), bool)
        for part in (coarse, ~coarse):
            part = part & ~bad[group]
            if part.any():
                ok = self.valid(a[seg[part]] + t[part, None] * d[seg[part]])
                bad[group[part][~ok]] = True
        return ~bad

    def straight(self, d: np.ndarray) -> bool:
        """The step ``d`` turns every angle by less than π: the path's straight segment is the
        one :func:`~taut.planning.verify_path` checks (each angle the short way)."""
        return bool(np.all(np.abs(d[..., self.angles]) < np.pi))

    def unwrap(self, nodes: np.ndarray) -> np.ndarray:
        """The path through ``nodes`` made continuous: each angle the short way from the
        previous pose, the first pose kept as it is."""
        steps = self.diff(nodes[:-1], nodes[1:])
        return np.vstack([nodes[:1], nodes[0] + np.cumsum(steps, axis=0)])


def pose_space(
    robot: Robot,
    start: np.ndarray,
    goal: np.ndarray,
    *,
    bounds: tuple[npt.ArrayLike, npt.ArrayLike] | None = None,
    E: npt.ArrayLike | None = None,
    interference: bool = False,
    obstacles: bool = False,
    lengths: tuple[npt.ArrayLike, npt.ArrayLike] | None = None,
) -> PoseSpace:
    """The :class:`PoseSpace` of a query: positions in ``bounds`` (default: the bounding box
    of the exits, the start and the goal, widened on every axis to its largest side, about
    its centre), angles over the full circle; start and goal checked valid."""
    refuse_unplannable(robot, "pose-space planning")
    ellipsoid = wrench_ellipsoid(robot, E)
    validity = partial(pose_validity, robot, interference=interference, obstacles=obstacles, lengths=lengths)
    check = validity(E=ellipsoid)
    d, k = robot.dimension, robot.pose_size
    if bounds is None:
        pts = np.vstack([robot.exits, start[None, :d], goal[None, :d]])
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        half = 0.5 * (hi - lo).max()
        centre = 0.5 * (lo + hi)
        lo, hi = np.minimum(lo, centre - half), np.maximum(hi, centre + half)
    else:
        if not isinstance(bounds, tuple | list) or len(bounds) != 2:
            raise TautError(f"bounds: expected (lower, upper) of the {d} position coordinates, got {bounds!r}")
        lo = as_array(bounds[0], "bounds (lower)", shape=(d,))
        hi = as_array(bounds[1], "bounds (upper)", shape=(d,))
        if np.any(lo >= hi):
            raise TautError(f"bounds: every lower bound must be below its upper bound, got {bounds!r}")
        for what, q in (("start", start), ("goal", goal)):
            if np.any(q[:d] < lo) or np.any(q[:d] > hi):
                raise TautError(f"the {what} {q.tolist()} lies outside the bounds {bounds!r}")
    angles = angle_columns(robot)
    lower, upper = np.full(k, -np.pi), np.full(k, np.pi)
    lower[:d], upper[:d] = lo, hi
    space = PoseSpace(robot, lower, upper, angles, check, validity, ellipsoid)
    for what, q in (("start", start), ("goal", goal)):
        if not space.valid(q)[0]:
            raise InfeasiblePoseError(
                f"{robot.name}: the {what} {np.round(q, 6).tolist()} is not valid (wrench-feasible with tensions "
                "and lengths inside their bounds, and the checks asked for)"
            )
    return space


class _Tree:
    """Nodes (grown in a preallocated array) and their parents."""

    def __init__(self, root: np.ndarray, capacity: int) -> None:
        self.nodes = np.empty((capacity, root.size))
        self.nodes[0] = root
        self.parent = [-1]

    def __len__(self) -> int:
        return len(self.parent)

    def add(self, q: np.ndarray, parent: int) -> int:
        self.nodes[len(self.parent)] = q
        self.parent.append(parent)
        return len(self.parent) - 1

    def nearest(self, space: PoseSpace, q: np.ndarray) -> int:
        d = space.diff(self.nodes[: len(self)], q)
        return int(np.einsum("ij,ij->i", d, d).argmin())

    def branch(self, i: int) -> list[np.ndarray]:
        out = []
        while i >= 0:
            out.append(self.nodes[i])
            i = self.parent[i]
        return out


def _step_ends(space: PoseSpace, tree: _Tree, targets: np.ndarray, step: float) -> tuple[np.ndarray, np.ndarray]:
    """The nodes of ``tree`` nearest ``targets`` ``(m, k)`` and the poses one ``step`` from
    them toward the targets (a target itself when nearer), a few targets at a time so that
    their differences to every node take at most :data:`NEAREST_FLOATS` floats."""
    nodes = tree.nodes[: len(tree)]
    idx = np.empty(len(targets), int)
    for lo in range(0, len(targets), max(1, NEAREST_FLOATS // nodes.size)):
        d = space.diff(nodes[None], targets[lo : lo + max(1, NEAREST_FLOATS // nodes.size), None])
        idx[lo : lo + len(d)] = np.einsum("mij,mij->mi", d, d).argmin(axis=1)
    d = space.diff(nodes[idx], targets)
    L = np.linalg.norm(d, axis=1)
    return idx, nodes[idx] + np.where(L <= step, 1.0, step / np.maximum(L, step))[:, None] * d


def _connect(
    space: PoseSpace, tree: _Tree, target: np.ndarray, step: float, resolution: float, room: int
) -> tuple[int, bool]:
    """Grow ``tree`` from its node nearest ``target`` straight toward it as far as the segment
    stays valid, a node every ``step`` and at most ``room``, checking in batches of
    :data:`CONNECT_BATCH` poses.  Returns the last node added (−1 if none) and whether it is
    ``target``."""
    i = tree.nearest(space, target)
    a = tree.nodes[i]
    d = space.diff(a, target)
    L = float(np.linalg.norm(d))
    if L == 0.0:
        return i, True
    n = max(1, int(np.ceil(L / resolution)))
    s = np.arange(1, n + 1) * (L / n)  # arc lengths of the checked poses
    good = n
    for lo in range(0, n, CONNECT_BATCH):
        ok = space.valid(a + (s[lo : lo + CONNECT_BATCH] / L)[:, None] * d)
        if not ok.all():
            good = lo + int(np.argmin(ok))
            break
    valid_len = s[good - 1] if good > 0 else 0.0
    reached = good == n
    marks = list(np.arange(step, valid_len, step))
    if reached:
        marks.append(L)
    last, parent = -1, i
    for m in marks[:room]:
        parent = last = tree.add(a + (m / L) * d, parent)
    if reached and len(marks) <= room:
        tree.nodes[last] = target
        return last, True
    return last, False


def with_margin(space: PoseSpace, start: np.ndarray, goal: np.ndarray) -> PoseSpace:
    """``space`` with the planners' stricter test (module docstring): the wrench ellipsoid's
    axes :data:`WRENCH_MARGIN` times longer (less where the start or the goal would not be
    valid) and every upper tension bound capped at :data:`TENSION_MARGIN` times the least
    cap, to a factor 2, at which the start and the goal are valid."""
    tmin, tmax = space.robot.tension_bounds
    ends = np.array([start, goal])
    grow = WRENCH_MARGIN
    while grow > 1.0 and not space.validity(E=space.E / grow**2, tension_bounds=(tmin, tmax))(ends)[0].all():
        grow = 1.0 + (grow - 1.0) / 2 if grow > 1.01 else 1.0
    E = space.E / grow**2
    cap = max(float(tmin.max()), 2.0**-30)
    while not space.validity(E=E, tension_bounds=(tmin, np.minimum(tmax, cap)))(ends)[0].all():
        cap *= 2.0
    bounds = np.minimum(tmax, TENSION_MARGIN * cap)
    if grow == 1.0 and np.array_equal(bounds, tmax):
        return space
    # paths are checked at last with half the margin: a path that grazes the planners' boundary
    # between its checked poses stays inside it
    half = space.validity(E=space.E / grow, tension_bounds=(tmin, np.minimum(tmax, 2 * bounds)))
    return replace(space, check=space.validity(E=E, tension_bounds=(tmin, bounds)), nominal=replace(space, check=half))


def _length(path: np.ndarray) -> float:
    return float(np.linalg.norm(np.diff(path, axis=0), axis=1).sum())


def simplify(
    space: PoseSpace,
    path: np.ndarray,
    resolution: float,
    rng: np.random.Generator,
    deadline: float,
    *,
    tries: int = SHORTCUTS,
) -> np.ndarray:
    """A continuous valid path ``(N, k)`` shortened as OMPL's ``PathSimplifier::simplify``
    does (Şucan, Moll & Kavraki 2012): vertices dropped (:func:`_reduce_vertices`), then
    rounds of random shortcuts between points of the path, vertices or not, then of partial
    shortcuts, which straighten one coordinate along a stretch of the path (Geraerts &
    Overmars 2007, §3; :func:`_shortcuts`), corner cutting (:func:`_smooth`) and vertices
    dropped again, while a round shortens the path by more than :data:`GAIN`, within
    ``tries`` shortcuts and the ``deadline``.  Every change replaces a stretch of the path by
    segments valid at ``resolution`` and shorter than it, each turning every angle by less
    than π (so that the path is the one :func:`~taut.planning.verify_path` checks), and keeps
    the ends of the stretch as they were: the path never gets longer, and starts and ends
    where it did."""
    path = _reduce_vertices(space, np.array(path, float), resolution, deadline)
    while tries > 0 and len(path) > 2 and time.perf_counter() <= deadline:
        before = _length(path)
        for one_coordinate in (False, True):
            path, used = _shortcuts(space, path, resolution, rng, deadline, tries, partial=one_coordinate)
            tries -= used
        path = _reduce_vertices(space, _smooth(space, path, resolution, deadline), resolution, deadline)
        if _length(path) > (1.0 - GAIN) * before:
            break
    return path


def _reduce_vertices(space: PoseSpace, path: np.ndarray, resolution: float, deadline: float) -> np.ndarray:
    """From the start, each kept vertex joined straight to a far later vertex it sees: the
    farthest of those found by doubling the reach from the next vertex, then halving the gap
    to the first that it does not see."""

    def sees(i: int, j: int) -> bool:
        d = path[j] - path[i]
        return space.straight(d) and space.segment_ok(path[i], d, resolution)

    n = len(path)
    kept, i = [0], 0
    while i < n - 1:
        if time.perf_counter() > deadline:
            kept.extend(range(i + 1, n))
            break
        seen, unseen, reach = i + 1, n, 1  # path[i] sees path[i + 1]: a segment of the path
        while seen < n - 1:
            j = min(i + 1 + reach, n - 1)
            if not sees(i, j):
                unseen = j
                break
            seen, reach = j, 2 * reach
        while unseen - seen > 1:
            j = (seen + unseen) // 2
            seen, unseen = (j, unseen) if sees(i, j) else (seen, j)
        kept.append(seen)
        i = seen
    return path[kept]


def _on_path(path: np.ndarray, cum: np.ndarray, s: float, snap: float) -> tuple[int, int, np.ndarray]:
    """The point at arc length ``s``: the vertices before and after it (both its own index
    when it is within ``snap`` of a vertex, and moved onto it) and its pose."""
    i = int(np.clip(np.searchsorted(cum, s, side="right") - 1, 0, len(path) - 2))
    if s - cum[i] < snap:
        return i, i, path[i]
    if cum[i + 1] - s < snap:
        return i + 1, i + 1, path[i + 1]
    u = (s - cum[i]) / (cum[i + 1] - cum[i])
    return i, i + 1, path[i] + u * (path[i + 1] - path[i])


def _shortcuts(
    space: PoseSpace,
    path: np.ndarray,
    resolution: float,
    rng: np.random.Generator,
    deadline: float,
    budget: int,
    *,
    partial: bool,
) -> tuple[np.ndarray, int]:
    """Random shortcuts between a point anywhere on the path and another within :data:`RANGE`
    of its length along it, as OMPL's ``shortcutPath``: the stretch between them replaced by
    the straight segment or, when ``partial``, only one coordinate (drawn at random) made to
    change linearly with the arc length along the stretch, the others kept as they were: the
    partial shortcut of Geraerts & Overmars (2007, §3), which straightens a path whose full
    shortcuts all leave the valid set.  A try is checked when it would shorten the path by
    more than :data:`MIN_GAIN` of its length, and applied when every segment of its new
    stretch is valid, until :data:`PATIENCE` tries in a row are not or ``budget`` are made.
    Tries are drawn :data:`SHORTCUT_BATCH` at a time and checked in one batch; the valid ones
    are applied, the largest gain first, as long as their stretches do not overlap.  Returns
    the path and the tries made."""
    used = idle = 0
    k = path.shape[1]
    while used < budget and idle < PATIENCE and len(path) > 2 and time.perf_counter() <= deadline:
        m = min(SHORTCUT_BATCH, budget - used)
        used += m
        cum = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(path, axis=0), axis=1))])
        L = float(cum[-1])
        s0 = rng.uniform(0.0, L, m)
        s1 = rng.uniform(np.maximum(0.0, s0 - RANGE * L), np.minimum(L, s0 + RANGE * L))
        coords = rng.integers(0, k, m) if partial else np.zeros(m, int)
        tries = []
        for a, b, c in zip(np.minimum(s0, s1), np.maximum(s0, s1), coords):
            i0, j0, p0 = _on_path(path, cum, a, SNAP * L)
            i1, j1, p1 = _on_path(path, cum, b, SNAP * L)
            # the arc lengths of the two points along the path
            t0, t1 = cum[i0] + float(np.linalg.norm(p0 - path[i0])), cum[i1] + float(np.linalg.norm(p1 - path[i1]))
            if j1 - i0 < 2 or t1 - t0 <= MIN_GAIN * L:  # no vertex strictly between, or nothing to gain
                continue
            if partial:
                inner = slice(j0 + (i0 == j0), i1 + (i1 != j1))  # the vertices strictly between
                new = np.vstack([p0, path[inner], p1])
                new[1:-1, c] = p0[c] + (cum[inner] - t0) / (t1 - t0) * (p1[c] - p0[c])  # its ends kept exactly
            else:
                new = np.vstack([p0, p1])
            steps = np.diff(new, axis=0)
            gain = t1 - t0 - float(np.linalg.norm(steps, axis=1).sum())
            if gain > MIN_GAIN * L and space.straight(steps):
                tries.append((gain, i0, j1, new))
        if not tries:
            idle += m
            continue
        ok = space.segments_ok(
            np.vstack([t[3][:-1] for t in tries]),
            np.vstack([t[3][1:] for t in tries]),
            resolution,
            closed=True,
            groups=np.repeat(np.arange(len(tries)), [len(t[3]) - 1 for t in tries]),
        )
        chosen: list[tuple[float, int, int, np.ndarray]] = []
        for t in sorted((t for t, v in zip(tries, ok) if v), key=lambda t: -t[0]):
            if all(t[2] <= c[1] or t[1] >= c[2] for c in chosen):  # stretches apart (a shared vertex kept)
                chosen.append(t)
        if not chosen:
            idle += m
            continue
        idle = 0
        for _, i0, j1, new in sorted(chosen, key=lambda t: -t[1]):  # from the end: indices stay right
            path = np.vstack([path[: i0 + 1], new, path[j1:]])
        path = path[np.r_[True, np.linalg.norm(np.diff(path, axis=0), axis=1) > 0.0]]  # vertices met twice
    return path, used


def _smooth(space: PoseSpace, path: np.ndarray, resolution: float, deadline: float) -> np.ndarray:
    """Corner cutting, as OMPL's ``smoothBSpline``: each segment halved and each inner vertex
    moved to the mean of its two neighbouring midpoints and itself (weights ¼, ¼, ½) where the
    two segments to those midpoints are valid; :data:`SMOOTHING` passes, fewer when one would
    move no vertex by more than 1 % of the path's length."""
    for _ in range(SMOOTHING):
        if len(path) < 3 or time.perf_counter() > deadline:
            break
        mid = 0.5 * (path[:-1] + path[1:])
        corner = 0.25 * mid[:-1] + 0.5 * path[1:-1] + 0.25 * mid[1:]
        moved = np.linalg.norm(corner - path[1:-1], axis=1) > 0.01 * _length(path)
        if not moved.any():
            break
        mid_ok = space.valid(mid)  # a midpoint need not be one of the poses its segment was checked at
        moved &= mid_ok[:-1] & mid_ok[1:]
        idx = np.flatnonzero(moved)
        ok = space.segments_ok(np.vstack([mid[idx], corner[idx]]), np.vstack([corner[idx], mid[idx + 1]]), resolution)
        moved[idx] = ok[: len(idx)] & ok[len(idx) :]
        inner = np.where(moved[:, None], corner, path[1:-1])
        out = np.empty((2 * len(path) - 1, path.shape[1]))
        out[0::2] = np.vstack([path[:1], inner, path[-1:]])
        out[1::2] = mid
        keep = np.ones(len(out), bool)
        keep[1::2] = mid_ok
        path = out[keep]
    return path


def _finish(
    space: PoseSpace,
    path: np.ndarray,
    goal: np.ndarray,
    resolution: float,
    rng: np.random.Generator,
    max_nodes: int,
    deadline: float,
) -> np.ndarray | None:
    """The continuous path checked again every ``resolution / FINE`` with the test of
    ``space.verified`` and ending at ``goal`` as written (the same rotation as its last pose,
    possibly written with other multiples of 2π); ``None`` when a segment fails that check
    and no detour around the thin invalid region it crosses is found by RRT-Connect at the
    fine resolution with the test of ``space`` (then checked as the path)."""
    fine = resolution / FINE
    check = space.verified
    out = [path[0]]
    for p, q in zip(path[:-1], path[1:]):
        # FINE poses at least on every segment, however short: a detour's short segments must not
        # step over a thin invalid sheet (near singular poses) that their ends straddle
        if check.segment_ok(p, q - p, fine, points=FINE):
            out.append(q)
            continue
        if time.perf_counter() > deadline:
            return None
        sub = _rrt(
            space,
            p,
            q,
            step=None,
            resolution=fine,
            rng=rng,
            max_nodes=max_nodes,
            time_limit=max(deadline - time.perf_counter(), 1e-3) if np.isfinite(deadline) else None,
            shorten=True,
            progress=None,
            final=False,
        )
        detour = space.unwrap(np.vstack([p, sub.path[1:]])) if sub.found else None
        if detour is None or not all(
            check.segment_ok(u, v - u, fine, points=FINE) for u, v in zip(detour[:-1], detour[1:])
        ):
            return None
        out.extend(detour[1:])
    result = np.array(out)
    result[-1] = goal
    return result


def _with_fallback(
    space: PoseSpace,
    start: np.ndarray,
    goal: np.ndarray,
    time_limit: float | None,
    run: Callable[[PoseSpace, float | None], PathResult],
) -> PathResult:
    """``run`` on ``space`` with the planners' margin (:func:`with_margin`), then, when that
    finds no path in time, on ``space`` itself with the time left; the work of both counted."""
    t0 = time.perf_counter()
    strict = with_margin(space, start, goal)
    res = run(strict, time_limit)
    left = None if time_limit is None else time_limit - (time.perf_counter() - t0)
    if not res.found and strict is not space and (left is None or left > 0):
        first = res
        res = run(space, left)
        res = replace(res, nodes=res.nodes + first.nodes, expanded=res.expanded + first.expanded)
    return replace(res, elapsed_s=time.perf_counter() - t0)


def rrt_connect(
    space: PoseSpace,
    start: np.ndarray,
    goal: np.ndarray,
    *,
    step: float | None,
    resolution: float | None,
    rng: np.random.Generator,
    max_nodes: int,
    time_limit: float | None,
    shorten: bool,
    progress: Callable[[int, int | None], None] | None,
) -> PathResult:
    """RRT-Connect then shortening (module docstring) from ``start`` to ``goal``, the path
    checked again at a finer resolution (:func:`_finish`): with the planners' margin, then
    without it when that finds no path (``max_nodes`` each)."""

    def run(sp: PoseSpace, limit: float | None) -> PathResult:
        return _rrt(
            sp,
            start,
            goal,
            step=step,
            resolution=resolution,
            rng=rng,
            max_nodes=max_nodes,
            time_limit=limit,
            shorten=shorten,
            progress=progress,
            candidates=CANDIDATES,
        )

    return _with_fallback(space, start, goal, time_limit, run)


def _rrt(
    space: PoseSpace,
    start: np.ndarray,
    goal: np.ndarray,
    *,
    step: float | None,
    resolution: float | None,
    rng: np.random.Generator,
    max_nodes: int,
    time_limit: float | None,
    shorten: bool,
    progress: Callable[[int, int | None], None] | None,
    final: bool = True,
    candidates: int = 1,
) -> PathResult:
    """RRT-Connect then shortening (:func:`simplify`) from ``start`` to ``goal`` with the
    validity test of ``space``; with ``final``, the path checked again at a finer resolution
    (:func:`_finish`).  With ``shorten``, up to ``candidates`` paths are searched for (the
    first with ``max_nodes``, each further one with the nodes left, at most
    :data:`CANDIDATE_NODES` times those of the first) and the one shortest after a first
    :data:`QUICK` shortcuts is shortened further (:func:`_shortest`)."""
    t0 = time.perf_counter()
    deadline = np.inf if time_limit is None else t0 + time_limit
    diag = float(np.linalg.norm(space.upper - space.lower))
    step = diag / STEPS_PER_DIAGONAL if step is None else step
    resolution = min(step / CHECKS_PER_STEP, RESOLUTION) if resolution is None else resolution
    nodes = 0
    raws: list[np.ndarray] = []
    for _ in range(candidates if shorten else 1):
        budget = max_nodes - nodes if not raws else min(max_nodes - nodes, CANDIDATE_NODES * nodes)
        if budget < 2 or time.perf_counter() >= deadline:
            break
        found, used = _connect_trees(space, start, goal, step, resolution, rng, budget, deadline, progress, nodes)
        nodes += used
        if found is None:
            break
        raws.append(space.unwrap(np.array(found)))
    path = np.zeros((0, start.size))
    if raws:
        raw = path = raws[0]
        if shorten:
            raw, path = _shortest(space, raws, resolution, rng, deadline)
            path = simplify(space, path, resolution, rng, deadline)
        if final:
            budget = max(2, max_nodes // REPAIR_SHARE)
            checked = _finish(space, path, goal, resolution, rng, budget, deadline)
            if checked is None and shorten:  # the tree's own path, farther from the boundary
                checked = _finish(space, raw, goal, resolution, rng, budget, deadline)
            path = np.zeros((0, start.size)) if checked is None else checked
        else:
            path[-1] = goal
    if progress is not None:
        progress(nodes, nodes)
    return _result(space, len(path) > 0, path, "rrtconnect", nodes=nodes, t0=t0)


def _connect_trees(
    space: PoseSpace,
    start: np.ndarray,
    goal: np.ndarray,
    step: float,
    resolution: float,
    rng: np.random.Generator,
    max_nodes: int,
    deadline: float,
    progress: Callable[[int, int | None], None] | None,
    done: int,
) -> tuple[list[np.ndarray] | None, int]:
    """RRT-Connect's two trees grown from ``start`` and ``goal`` until they meet, within
    ``max_nodes`` and the ``deadline``: the poses of the path through them (``None`` when
    they do not meet) and the nodes grown; ``progress`` is told ``done`` more."""
    trees = (_Tree(start, max_nodes), _Tree(goal, max_nodes))
    span = space.upper - space.lower
    a, b = 0, 1
    pending: list[tuple[int, np.ndarray, bool]] = []
    while len(trees[0]) + len(trees[1]) < max_nodes and time.perf_counter() < deadline:
        if not pending:
            # The ends of the next SAMPLE_BATCH extensions (alternately of the two trees, from
            # their nearest nodes now) are checked in one batch, most fall outside the valid set;
            # then the segments to the valid ones, in another: they do not change as the trees grow.
            samples = space.lower + span * rng.random((SAMPLE_BATCH, span.size))
            idx, ends, froms = np.empty(SAMPLE_BATCH, int), np.empty_like(samples), np.empty_like(samples)
            for j in (0, 1):
                idx[j::2], ends[j::2] = _step_ends(space, trees[(a + j) % 2], samples[j::2], step)
                froms[j::2] = trees[(a + j) % 2].nodes[idx[j::2]]
            ok = space.valid(ends)
            ok[ok] = space.segments_ok(froms[ok], ends[ok], resolution)
            pending = [(int(i), e, bool(v)) for i, e, v in zip(idx, ends, ok)][::-1]
        i, end, extends = pending.pop()
        new = trees[a].add(end, i) if extends else -1
        if new >= 0:
            room = max_nodes - len(trees[0]) - len(trees[1])
            last, reached = _connect(space, trees[b], trees[a].nodes[new], step, resolution, room)
            if reached:
                tips = {a: new, b: last}
                found = trees[0].branch(tips[0])[::-1] + trees[1].branch(tips[1])[1:]
                return found, len(trees[0]) + len(trees[1])
        if progress is not None:
            progress(done + len(trees[0]) + len(trees[1]), None)
        a, b = b, a
    return None, len(trees[0]) + len(trees[1])


def _shortest(
    space: PoseSpace, paths: list[np.ndarray], resolution: float, rng: np.random.Generator, deadline: float
) -> tuple[np.ndarray, np.ndarray]:
    """Of ``paths``, the one shortest after :func:`simplify` with :data:`QUICK` shortcuts
    tried: that path and its shortened one."""
    if len(paths) == 1:
        return paths[0], paths[0]
    quick = [simplify(space, p, resolution, rng, deadline, tries=QUICK) for p in paths]
    best = int(np.argmin([_length(q) for q in quick]))
    return paths[best], quick[best]


def _result(
    space: PoseSpace,
    found: bool,
    path: np.ndarray,
    method: str,
    *,
    nodes: int = 0,
    expanded: int = 0,
    proof: bool = False,
    t0: float,
) -> PathResult:
    length = float(np.linalg.norm(space.diff(path[:-1], path[1:]), axis=1).sum()) if found else float("nan")
    return PathResult(
        found=found,
        path=path,
        charts=0,
        expanded=expanded,
        no_path=proof,
        length=length,
        elapsed_s=time.perf_counter() - t0,
        atlas=None,
        method=method,
        nodes=nodes,
    )


def lattice(space: PoseSpace, spacing: float) -> tuple[list[np.ndarray], np.ndarray]:
    """The lattice of ``space`` at ``spacing``: its coordinates on each axis and which axes
    are periodic."""
    axes, periodic = [], np.zeros(space.lower.size, bool)
    for c in range(space.lower.size):
        if c in space.angles:
            n = max(3, int(round(2 * np.pi / spacing)))
            axes.append(-np.pi + 2 * np.pi * np.arange(n) / n)
            periodic[c] = True
        else:
            n = int(np.floor((space.upper[c] - space.lower[c]) / spacing)) + 1
            axes.append(space.lower[c] + spacing * np.arange(max(n, 2)))
    return axes, periodic


def grid_search(
    space: PoseSpace,
    start: np.ndarray,
    goal: np.ndarray,
    *,
    spacing: float | None,
    resolution: float | None,
    max_nodes: int,
    shorten: bool,
    rng: np.random.Generator,
    time_limit: float | None,
    progress: Callable[[int, int | None], None] | None,
) -> PathResult:
    """A* over the lattice of ``space`` (module docstring) with the planners' margin, then
    without it when that finds no path; ``no_path`` (a proof at the lattice's resolution, with
    the validity test of ``space``) when the start's component holds no path to the goal."""

    def run(sp: PoseSpace, limit: float | None) -> PathResult:
        return _grid(
            sp,
            start,
            goal,
            spacing=spacing,
            resolution=resolution,
            max_nodes=max_nodes,
            shorten=shorten,
            rng=rng,
            time_limit=limit,
            progress=progress,
        )

    return _with_fallback(space, start, goal, time_limit, run)


def _grid(
    space: PoseSpace,
    start: np.ndarray,
    goal: np.ndarray,
    *,
    spacing: float | None,
    resolution: float | None,
    max_nodes: int,
    shorten: bool,
    rng: np.random.Generator,
    time_limit: float | None,
    progress: Callable[[int, int | None], None] | None,
) -> PathResult:
    """A* over the lattice of ``space`` with its validity test (:func:`grid_search`)."""
    t0 = time.perf_counter()
    k = space.lower.size
    if spacing is None:  # as fine as the node budget allows
        volume = float(np.prod(np.where(np.isin(np.arange(k), space.angles), 2 * np.pi, space.upper - space.lower)))
        spacing = (volume / max_nodes) ** (1.0 / k)
        while np.prod([len(a) for a in lattice(space, spacing)[0]], dtype=float) > max_nodes:
            spacing *= 1.05
    axes, periodic = lattice(space, spacing)
    shape = tuple(len(a) for a in axes)
    total = int(np.prod(shape, dtype=float))
    if total > max_nodes:
        raise TautError(
            f"a lattice at spacing {spacing:.4g} has {total:,} points, more than max_nodes ({max_nodes:,}): "
            "give a larger spacing or max_nodes"
        )
    steps = np.array([a[1] - a[0] for a in axes])
    resolution = min(float(steps.min()) / CHECKS_PER_STEP, RESOLUTION) if resolution is None else resolution
    grid = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, k)
    free = np.zeros(total, bool)
    chunk = 4096
    for s in range(0, total, chunk):
        free[s : s + chunk] = space.valid(grid[s : s + chunk])
        if progress is not None:
            progress(min(s + chunk, total), None)
    S, G = total, total + 1  # the start and the goal as two more nodes
    point = lambda i: start if i == S else goal if i == G else grid[i]  # noqa: E731
    offsets = np.array([o for o in itertools.product((-1, 0, 1), repeat=k) if any(o)])
    dims = np.array(shape)

    def corners(q: np.ndarray) -> list[int]:
        base = []
        for c in range(k):
            x = (q[c] - axes[c][0]) / steps[c]
            i0 = int(np.floor(x)) if not periodic[c] else int(np.floor(np.mod(x, shape[c])))
            i0 = min(max(i0, 0), shape[c] - 2) if not periodic[c] else i0
            base.append((i0, (i0 + 1) % shape[c] if periodic[c] else i0 + 1))
        return [int(np.ravel_multi_index(idx, shape)) for idx in itertools.product(*base)]

    near_goal = {i for i in corners(goal) if free[i]}

    def neighbours(i: int) -> list[int]:
        if i == S:
            cand = [j for j in corners(start) if free[j]] + [G]
        else:
            idx = np.array(np.unravel_index(i, shape))[None, :] + offsets
            idx[:, periodic] %= dims[periodic]
            inside = np.all((idx >= 0) & (idx < dims), axis=1)
            flat = np.ravel_multi_index(idx[inside].T, shape)
            cand = [int(j) for j in flat if free[j]]
            if i in near_goal:
                cand.append(G)
        return cand

    def edges_ok(i: int, js: list[int]) -> np.ndarray:
        a = point(i)
        ds = np.array([space.diff(a, point(j)) for j in js])
        n = np.maximum(1, np.ceil(np.linalg.norm(ds, axis=1) / resolution).astype(int))
        t = [np.arange(1, m) / m for m in n]  # interior points: the ends are checked already
        pts = np.vstack([a + tj[:, None] * dj for tj, dj in zip(t, ds)] + [np.zeros((0, k))])
        ok = space.valid(pts) if len(pts) else np.zeros(0, bool)
        out, pos = np.ones(len(js), bool), 0
        for e, m in enumerate(n):
            out[e] = ok[pos : pos + m - 1].all()
            pos += m - 1
        return out

    deadline = np.inf if time_limit is None else t0 + time_limit
    g = {S: 0.0}
    parent = {S: -1}
    closed: set[int] = set()
    heap = [(float(np.linalg.norm(space.diff(start, goal))), 0.0, S)]
    expanded = 0
    reached = False
    stopped = False
    while heap:
        if time.perf_counter() > deadline:
            stopped = True
            break
        _, gi, i = heapq.heappop(heap)
        if i in closed:
            continue
        if i == G:
            reached = True
            break
        closed.add(i)
        expanded += 1
        js = [j for j in neighbours(i) if j not in closed]
        if not js:
            continue
        for j, ok in zip(js, edges_ok(i, js)):
            if not ok:
                continue
            gj = gi + float(np.linalg.norm(space.diff(point(i), point(j))))
            if gj < g.get(j, np.inf):
                g[j], parent[j] = gj, i
                heapq.heappush(heap, (gj + float(np.linalg.norm(space.diff(point(j), goal))), gj, j))
        if progress is not None and expanded % 256 == 0:
            progress(expanded, None)
    path = np.zeros((0, k))
    proof = not reached and not stopped  # the start's component closed without the goal
    if reached:
        chain, i = [], G
        while i >= 0:
            chain.append(point(i))
            i = parent[i]
        raw = path = space.unwrap(np.array(chain[::-1]))
        if shorten:
            path = simplify(space, path, resolution, rng, deadline)
        budget = max(2, max_nodes // REPAIR_SHARE)
        checked = _finish(space, path, goal, resolution, rng, budget, deadline)
        if checked is None and shorten:
            checked = _finish(space, raw, goal, resolution, rng, budget, deadline)
        reached = checked is not None
        path = np.zeros((0, k)) if checked is None else checked
    if progress is not None:
        progress(expanded, expanded)
    return _result(space, reached, path, "grid", expanded=expanded, proof=proof, t0=t0)
