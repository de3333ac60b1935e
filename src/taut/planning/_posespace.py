"""Planning in a robot's own pose space, where its wrench-feasible poses fill an open set:
redundant robots (more cables than wrench components), fully constrained ones, point masses
and planar platforms, in any orientation convention.

A pose is valid when the test of :func:`taut.planning.verify_path` holds there
(:func:`~taut.planning._verify.pose_validity`: wrench feasibility of an ellipsoid around the
external wrench within the tension bounds, cable lengths inside their bounds, and on request
no interference, no cable in an obstacle, lengths inside given bounds).  A straight segment
between two poses (each angle of the orientation along its shortest difference: angles are
2π-periodic, as on the manifold of :mod:`taut.planning._manifold`) is valid when its poses
every ``resolution`` (in pose coordinates, m and rad) are; they are checked in batches.  A
path found is checked again every ``resolution / 10``, ten poses at least per segment; a
segment that fails is replaced by a detour that RRT-Connect finds at that resolution, else the
unshortened path is tried, else the answer is "not found".  Checks at discrete poses cannot
see an invalid region thinner than their spacing (near singular poses the invalid set can be a
thin sheet): the returned path is valid at every checked pose, not certified between them.

* ``rrtconnect`` — RRT-Connect (Kuffner & LaValle 2000): two trees, from the start and from
  the goal, each extended one ``step`` toward a random pose of the box and the other then
  connected greedily toward the new node; then random shortcuts (Geraerts & Overmars 2007)
  between points of the path.  Randomised, deterministic for a ``seed`` (unless
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
   International Journal of Robotics Research 26(8), 2007, §3 (random shortcuts).
   (docs/references.bib: geraerts2007)
.. [3] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of Cable-Driven
   Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots, Mechanisms and
   Machine Science 12, Springer, 2013, §5. (docs/references.bib: bohigas2013)
"""

from __future__ import annotations

import heapq
import itertools
import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from taut._checks import as_array
from taut.errors import InfeasiblePoseError, TautError
from taut.model import Robot
from taut.planning._search import PathResult
from taut.planning._verify import angle_columns, pose_validity, refuse_unplannable, short_way

__all__ = ["POSE_METHODS", "SHORTCUTS", "PoseSpace", "grid_search", "pose_space", "rrt_connect"]

#: The planners of :func:`taut.planning.plan_path` that search a robot's pose space.
POSE_METHODS = ("rrtconnect", "grid")
#: Random shortcuts tried on a path when it is shortened.
SHORTCUTS = 200
#: Most poses checked in one batch while a tree is connected greedily.
CONNECT_BATCH = 64
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
        t = np.arange(0 if closed else 1, n + 1)[:, None] / n
        return bool(self.valid(a + t * d).all())

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
    check = pose_validity(robot, E=E, interference=interference, obstacles=obstacles, lengths=lengths)
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
    space = PoseSpace(robot, lower, upper, angles, check)
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


def _step_end(space: PoseSpace, tree: _Tree, target: np.ndarray, step: float) -> tuple[int, np.ndarray]:
    """The node of ``tree`` nearest ``target`` and the pose one ``step`` from it toward
    ``target`` (``target`` itself when nearer)."""
    i = tree.nearest(space, target)
    d = space.diff(tree.nodes[i], target)
    L = float(np.linalg.norm(d))
    return i, tree.nodes[i] + (d if L <= step else (step / L) * d)


def _extend(space: PoseSpace, tree: _Tree, i: int, end: np.ndarray, resolution: float) -> int:
    """Add ``end`` (a valid pose) to ``tree`` as a child of node ``i`` if the segment between
    them is valid; the new node, or −1."""
    a = tree.nodes[i]
    if not space.segment_ok(a, end - a, resolution):
        return -1
    return tree.add(end, i)


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


def _length(path: np.ndarray) -> float:
    return float(np.linalg.norm(np.diff(path, axis=0), axis=1).sum())


def shortcut(
    space: PoseSpace, path: np.ndarray, resolution: float, rng: np.random.Generator, attempts: int, deadline: float
) -> np.ndarray:
    """A continuous path ``(N, k)`` shortened: each vertex joined to the farthest later vertex
    it sees by a valid segment, then random shortcuts (Geraerts & Overmars 2007, §3), two
    random points of it joined straight where that segment is valid and shorter."""
    path = np.array(path, float)
    kept, i = [0], 0  # first each vertex joined to the farthest later one it sees
    while i < len(path) - 1 and time.perf_counter() <= deadline:
        j = next(
            (j for j in range(len(path) - 1, i + 1, -1) if space.segment_ok(path[i], path[j] - path[i], resolution)),
            i + 1,
        )
        kept.append(j)
        i = j
    path = path[kept] if kept[-1] == len(path) - 1 else path
    for _ in range(attempts):
        if len(path) < 3 or time.perf_counter() > deadline:
            break
        seg = np.linalg.norm(np.diff(path, axis=0), axis=1)
        cum = np.concatenate([[0.0], np.cumsum(seg)])
        s0, s1 = np.sort(rng.uniform(0.0, cum[-1], 2))
        i, j = np.searchsorted(cum, [s0, s1], side="right") - 1
        j = min(j, len(path) - 2)
        if i == j:
            continue
        p0 = path[i] + (s0 - cum[i]) / max(seg[i], 1e-300) * (path[i + 1] - path[i])
        p1 = path[j] + (s1 - cum[j]) / max(seg[j], 1e-300) * (path[j + 1] - path[j])
        if np.linalg.norm(p1 - p0) >= s1 - s0 - 1e-12 or not space.segment_ok(p0, p1 - p0, resolution, closed=True):
            continue
        path = np.vstack([path[: i + 1], p0[None], p1[None], path[j + 1 :]])
        keep = np.r_[True, np.linalg.norm(np.diff(path, axis=0), axis=1) > 1e-12]
        path = path[keep]
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
    """The continuous path checked again every ``resolution / FINE`` and ending at ``goal`` as
    written (the same rotation as its last pose, possibly written with other multiples of
    2π); ``None`` when a segment fails that check and no detour around the thin invalid
    region it crosses is found by RRT-Connect at the fine resolution."""
    fine = resolution / FINE
    out = [path[0]]
    for p, q in zip(path[:-1], path[1:]):
        # FINE poses at least on every segment, however short: a detour's short segments must not
        # step over a thin invalid sheet (near singular poses) that their ends straddle
        if space.segment_ok(p, q - p, fine, points=FINE):
            out.append(q)
            continue
        if time.perf_counter() > deadline:
            return None
        sub = rrt_connect(
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
            space.segment_ok(u, v - u, fine, points=FINE) for u, v in zip(detour[:-1], detour[1:])
        ):
            return None
        out.extend(detour[1:])
    result = np.array(out)
    result[-1] = goal
    return result


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
    final: bool = True,
) -> PathResult:
    """RRT-Connect then random shortcuts (module docstring) from ``start`` to ``goal``; with
    ``final``, the path checked again at a finer resolution (:func:`_finish`)."""
    t0 = time.perf_counter()
    deadline = np.inf if time_limit is None else t0 + time_limit
    diag = float(np.linalg.norm(space.upper - space.lower))
    step = diag / STEPS_PER_DIAGONAL if step is None else step
    resolution = min(step / CHECKS_PER_STEP, RESOLUTION) if resolution is None else resolution
    trees = (_Tree(start, max_nodes), _Tree(goal, max_nodes))
    found = None
    span = space.upper - space.lower
    a, b = 0, 1
    pending: list[tuple[np.ndarray, int, np.ndarray, bool]] = []
    while found is None and len(trees[0]) + len(trees[1]) < max_nodes and time.perf_counter() < deadline:
        if not pending:
            # The ends of the next SAMPLE_BATCH extensions (alternately of the two trees, from
            # their nearest nodes now) are checked in one batch: most fall outside the valid set.
            samples = space.lower + span * rng.random((SAMPLE_BATCH, span.size))
            steps = [_step_end(space, trees[(a + j) % 2], q, step) for j, q in enumerate(samples)]
            ok = space.valid(np.array([e for _, e in steps]))
            pending = [(q, i, e, bool(v)) for q, (i, e), v in zip(samples, steps, ok)][::-1]
        _, i, end, end_ok = pending.pop()
        new = _extend(space, trees[a], i, end, resolution) if end_ok else -1
        if new >= 0:
            room = max_nodes - len(trees[0]) - len(trees[1])
            last, reached = _connect(space, trees[b], trees[a].nodes[new], step, resolution, room)
            if reached:
                ends = {a: new, b: last}
                found = trees[0].branch(ends[0])[::-1] + trees[1].branch(ends[1])[1:]
        if progress is not None:
            progress(len(trees[0]) + len(trees[1]), None)
        a, b = b, a
    nodes = len(trees[0]) + len(trees[1])
    path = np.zeros((0, start.size))
    if found is not None:
        raw = path = space.unwrap(np.array(found))
        if shorten:
            path = shortcut(space, path, resolution, rng, SHORTCUTS, deadline)
        if final:
            budget = max(2, max_nodes // REPAIR_SHARE)
            checked = _finish(space, path, goal, resolution, rng, budget, deadline)
            if checked is None and shorten:  # the tree's own path, farther from the boundary
                checked = _finish(space, raw, goal, resolution, rng, budget, deadline)
            found = None if checked is None else found
            path = np.zeros((0, start.size)) if checked is None else checked
        else:
            path[-1] = goal
    if progress is not None:
        progress(nodes, nodes)
    return _result(space, found is not None, path, "rrtconnect", nodes=nodes, t0=t0)


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
    """A* over the lattice of ``space`` (module docstring); ``no_path`` (a proof at the
    lattice's resolution) when the start's component holds no path to the goal."""
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
            path = shortcut(space, path, resolution, rng, SHORTCUTS, deadline)
        budget = max(2, max_nodes // REPAIR_SHARE)
        checked = _finish(space, path, goal, resolution, rng, budget, deadline)
        if checked is None and shorten:
            checked = _finish(space, raw, goal, resolution, rng, budget, deadline)
        reached = checked is not None
        path = np.zeros((0, k)) if checked is None else checked
    if progress is not None:
        progress(expanded, expanded)
    return _result(space, reached, path, "grid", expanded=expanded, proof=proof, t0=t0)
