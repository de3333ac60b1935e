"""Cable-state tree (CST) of a collidable cable (§4.2.1, Algs. 4.2–4.3 of Rushton 2022).

Each node is one possible *static* segment of the cable: the common tangent leaving the
object of its parent (the root is the winch pulley) and arriving on object ``obj`` with
wrap direction ``dir`` (Alg. 4.2).  The children of a node are the segments directly
reachable from its object: for every object not yet on the path and each wrap direction,
the wrap-direction consistent tangent (Appendix A), kept only if it

* meets no object (touching one tangentially is allowed: the tie of Fig. 4.5),
* crosses no earlier segment of the cable,
* enters no disallowed polygon, and
* leaves the parent's object with a non-negative wrap angle (a taut cable).

Alg. 4.3 builds the whole tree recursively (:meth:`CableStateTree.build`); with many
objects "a functional subtree can be built online with nodes only being expanded as
needed" — :meth:`CableStateTree.children` expands a node the first time it is asked for.
An object is wrapped at most once along a path, which keeps the tree finite.

Nodes live in two growing arrays so that the state-update kernel
(:mod:`taut.wrapping._update`) reads them without Python objects: ``F[n]`` holds the segment
start and end points, its unit direction, its length, the entry angle about ``obj``, the
cable length from the winch reference up to the entry point and the wrap direction;
``I[n]`` holds the parent, the object, the first child and the number of children (``−1``
while unexpanded).  The children of a node are contiguous.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §4.2.1, Algs. 4.2–4.3. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

import heapq
from collections.abc import Iterable, Sequence

import numpy as np
import numpy.typing as npt

from taut._checks import as_array, as_count, as_index
from taut.errors import TautError
from taut.geometry import directed_tangent, segment_enters_polygon, segment_meets_circle, segments_intersect
from taut.wrapping._state import WINCH_LOW, WRAP_LOW, CableState, contact_angle, wrap_angle

# columns of F
SX, SY, EX, EY, UX, UY, M, THETA_IN, L_STATIC, DIR = range(10)
# columns of I
PARENT, OBJ, FIRST, COUNT = range(4)

#: The node budget of :meth:`CableStateTree.shortest_taut_state` when none is given: the
#: tree of ``K`` objects has up to ``2^K K!`` nodes, so the search is bounded.
MAX_TREE_NODES = 20_000

#: Wrap angle [rad] below which a segment is not taut (round-off allowance).
TAUT_TOL = 1e-12
#: Distance [m] by which a segment must enter an object or a region to meet it.
MEET_TOL = 1e-9


def checked_contacts(contacts: object, n_objects: int) -> list[tuple[int, int]]:
    """A cable state's contacts as ``[(object, direction), ...]`` with objects
    ``0..n_objects − 1`` and directions ``±1``; :class:`TautError` otherwise."""
    try:
        pairs = [(k, d) for k, d in contacts]  # type: ignore[attr-defined]
    except (TypeError, ValueError):
        raise TautError(f"cable state: expected [(object, direction ±1), ...], got {contacts!r}") from None
    for k, d in pairs:
        as_index(k, "cable state: object", n_objects)
        if isinstance(d, bool) or d not in (1, -1):
            raise TautError(f"cable state: the direction about object {k + 1} must be +1 or -1, got {d!r}")
    return [(int(k), int(d)) for k, d in pairs]


class CableStateTree:
    """The cable-state tree of one cable (module docstring), expanded as needed.

    Parameters
    ----------
    circles : array_like, shape (K + 1, 3)
        ``(x, y, r)`` [m] of the ``K`` collidable objects followed by the winch pulley
        (radius 0 for a point exit).
    winch_direction : int, optional
        +1 (counter-clockwise) or −1.
    disallowed : iterable of array_like, shape (V, 2), optional
        Polygons the cable must not enter.
    reference_angle : float, optional
        Winch-pulley angle [rad] from which the pulley arc is counted
        (:mod:`taut.wrapping._state`).

    Raises
    ------
    TautError
        Circles that are not rows ``(x, y, r ≥ 0)``, or a bad direction or polygon.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §4.2.1, Algs. 4.2–4.3. (docs/references.bib: rushton2022)

    Examples
    --------
    The root (node 0) has two children, the disc wrapped either way; the cable to ``(0, 2)``
    must wrap it:

    >>> from taut.wrapping import CableStateTree
    >>> tree = CableStateTree([[0.0, 1.0, 0.2], [0.0, 0.0, 0.0]])  # one disc, then a point winch
    >>> [tree.contacts(int(c)) for c in tree.children(0)]
    [((0, 1),), ((0, -1),)]
    >>> node = tree.shortest_taut_state([0.0, 2.0])
    >>> tree.contacts(node), round(tree.length(node, [0.0, 2.0]), 4)
    (((0, 1),), 2.0401)
    """

    def __init__(
        self,
        circles: npt.ArrayLike,
        winch_direction: int = 1,
        *,
        disallowed: Iterable[npt.ArrayLike] = (),
        reference_angle: float = 0.0,
    ) -> None:
        self.circles = np.ascontiguousarray(as_array(circles, "circles", shape=(None, 3)))
        if not len(self.circles) or np.any(self.circles[:, 2] < 0):
            raise TautError("circles: expected rows (x, y, r >= 0) of the objects and the winch pulley last")
        self.n_objects = len(self.circles) - 1
        if winch_direction not in (1, -1):
            raise TautError(f"winch_direction: expected +1 or -1, got {winch_direction!r}")
        self.winch_direction = int(winch_direction)
        self.disallowed = [as_array(p, "a disallowed polygon", shape=(None, 2)) for p in disallowed]
        self.reference_angle = float(as_array(reference_angle, "reference_angle", shape=()))
        self.F = np.zeros((64, 10))
        self.I = np.full((64, 4), -1, dtype=np.int64)
        c = self.circles[-1]
        self.F[0] = [c[0], c[1], c[0], c[1], 1.0, 0.0, 0.0, self.reference_angle, 0.0, self.winch_direction]
        self.I[0] = [-1, self.n_objects, -1, -1]
        self.size = 1

    # ---- structure -------------------------------------------------------------------
    def _grow(self, extra: int) -> None:
        need = self.size + extra
        if need > len(self.F):
            cap = max(need, 2 * len(self.F))
            F = np.zeros((cap, 10))
            I = np.full((cap, 4), -1, dtype=np.int64)
            F[: self.size] = self.F[: self.size]
            I[: self.size] = self.I[: self.size]
            self.F, self.I = F, I

    def parent(self, node: int) -> int:
        """The node this one wraps from (−1 for the root)."""
        return int(self.I[node, PARENT])

    def obstacle(self, node: int) -> int:
        """The obstacle (0-based; ``n_objects`` for the winch) the cable last wraps at ``node``."""
        return int(self.I[node, OBJ])

    def direction(self, node: int) -> int:
        """The wrapping direction at ``node``: +1 counter-clockwise, −1 clockwise."""
        return int(self.F[node, DIR])

    def theta_in(self, node: int) -> float:
        """The contact angle [rad] at which the cable arrives on its last obstacle."""
        return float(self.F[node, THETA_IN])

    def static_length(self, node: int) -> float:
        """The length [m] of the cable from the winch up to its arrival on the last obstacle."""
        return float(self.F[node, L_STATIC])

    def ray(self, node: int) -> tuple[np.ndarray, np.ndarray]:
        """``(point (2,), unit direction (2,))``: where the free part of the cable leaves its
        last contact at ``node``, and the direction it leaves in."""
        return self.F[node, [EX, EY]].copy(), self.F[node, [UX, UY]].copy()

    def path(self, node: int) -> list[int]:
        """Nodes from the root to ``node``."""
        out = []
        while node >= 0:
            out.append(node)
            node = int(self.I[node, PARENT])
        return out[::-1]

    def contacts(self, node: int) -> tuple[tuple[int, int], ...]:
        """The objects wrapped up to ``node`` with their directions (the cable state)."""
        return tuple((int(self.I[n, OBJ]), int(self.F[n, DIR])) for n in self.path(node)[1:])

    def state(self, node: int) -> CableState:
        """The cable state of ``node``."""
        return CableState(self.contacts(node), self.reference_angle)

    def static_segments(self, node: int) -> np.ndarray:
        """Static segments ``(m, 2, 2)`` of the cable whose tracked node is ``node``."""
        p = self.path(node)[1:]
        return self.F[p][:, [SX, SY, EX, EY]].reshape(-1, 2, 2)

    def children(self, node: int) -> np.ndarray:
        """Indices of the children of ``node`` (expanding it if needed)."""
        if self.I[node, COUNT] < 0:
            self.expand(node)
        f, k = self.I[node, FIRST], self.I[node, COUNT]
        return np.arange(f, f + k)

    def find(self, contacts: Sequence[tuple[int, int]]) -> int:
        """The node of a cable state given as ``[(object, direction), ...]``; raises
        :class:`TautError` if that sequence of wraps is not reachable."""
        contacts = checked_contacts(contacts, self.n_objects)
        node = 0
        for j, (k, d) in enumerate(contacts):
            kids = self.children(node)
            hit = [c for c in kids if self.I[c, OBJ] == k and self.F[c, DIR] == d]
            if not hit:
                raise TautError(
                    f"cable state {list(contacts)}: the segment onto object {k + 1} "
                    f"({'ccw' if d > 0 else 'cw'}) after {list(contacts)[:j]} is not reachable "
                    "(blocked, crossing the cable, in a disallowed region, or not taut)"
                )
            node = int(hit[0])
        return node

    # ---- Alg. 4.3 --------------------------------------------------------------------
    def expand(self, node: int) -> None:
        """Add the children of ``node`` (the inner loop of Alg. 4.3)."""
        if self.I[node, COUNT] >= 0:
            return
        K = self.n_objects
        path = self.path(node)
        on_path = {int(self.I[n, OBJ]) for n in path}
        cand = np.array([k for k in range(K) if k not in on_path], dtype=np.int64)
        obj, d = int(self.I[node, OBJ]), self.F[node, DIR]
        if cand.size:
            ks = np.repeat(cand, 2)
            ds = np.tile([1.0, -1.0], cand.size)
            c1, r1 = self.circles[obj, :2], self.circles[obj, 2]
            x1, x2, u, L, ok = directed_tangent(c1, r1, d, self.circles[ks, :2], self.circles[ks, 2], ds)
            keep = ok.copy()
            if node != 0:
                phi = wrap_angle(self.F[node, THETA_IN], contact_angle(u, d), d, WRAP_LOW)
                keep &= phi >= -TAUT_TOL
            x1s, x2s = np.where(keep[:, None], x1, 0.0), np.where(keep[:, None], x2, 0.0)
            meets = segment_meets_circle(
                x1s[:, None], x2s[:, None], self.circles[None, :, :2], self.circles[None, :, 2], tol=MEET_TOL
            )
            keep &= ~meets.any(axis=1)
            earlier = self.static_segments(node)[:-1] if node != 0 else np.zeros((0, 2, 2))
            if len(earlier):
                cross = segments_intersect(
                    x1s[:, None], x2s[:, None], earlier[None, :, 0], earlier[None, :, 1], tol=MEET_TOL
                )
                keep &= ~cross.any(axis=1)
            for poly in self.disallowed:
                keep &= ~segment_enters_polygon(x1s, x2s, poly, tol=MEET_TOL)
            sel = np.flatnonzero(keep)
        else:
            sel = np.zeros(0, dtype=np.int64)
        n = len(sel)
        self._grow(n)
        first = self.size
        if n:
            r1 = self.circles[obj, 2]
            theta_out = contact_angle(u[sel], d)
            low = WINCH_LOW if node == 0 else WRAP_LOW
            arc = r1 * wrap_angle(self.F[node, THETA_IN], theta_out, d, low)
            rows = slice(first, first + n)
            self.F[rows, SX], self.F[rows, SY] = x1[sel, 0], x1[sel, 1]
            self.F[rows, EX], self.F[rows, EY] = x2[sel, 0], x2[sel, 1]
            self.F[rows, UX], self.F[rows, UY] = u[sel, 0], u[sel, 1]
            self.F[rows, M] = L[sel]
            self.F[rows, THETA_IN] = contact_angle(u[sel], ds[sel])
            self.F[rows, L_STATIC] = self.F[node, L_STATIC] + arc + L[sel]
            self.F[rows, DIR] = ds[sel]
            self.I[rows, PARENT] = node
            self.I[rows, OBJ] = ks[sel]
            self.I[rows, FIRST] = -1
            self.I[rows, COUNT] = -1
        self.I[node, FIRST] = first
        self.I[node, COUNT] = n
        self.size += n

    def build(self, *, max_depth: int | None = None) -> int:
        """Expand the whole tree (Alg. 4.3), down to ``max_depth`` wraps; returns its size."""
        stack = [(0, 0)]
        while stack:
            node, depth = stack.pop()
            if max_depth is not None and depth >= max_depth:
                continue
            for c in self.children(node):
                stack.append((int(c), depth + 1))
        return self.size

    # ---- the active segment ------------------------------------------------------------
    def active_segment(self, node: int, b: npt.ArrayLike) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """``(x, u, L, exists)``: the tangent from the object of ``node`` to the point ``b``."""
        k = int(self.I[node, OBJ])
        x1, _, u, L, ok = directed_tangent(self.circles[k, :2], self.circles[k, 2], self.F[node, DIR], b, 0.0, 1.0)
        return x1, u, L, ok

    def length(self, node: int, b: np.ndarray | Sequence[float]) -> float:
        """Cable length (Eq. 4.9) in state ``node`` with the platform end at ``b``."""
        x, u, L, ok = self.active_segment(node, b)
        if not ok:
            raise TautError(
                f"the platform anchor {[round(float(x), 6) for x in b]} is inside object {int(self.I[node, OBJ]) + 1}"
            )
        d = self.F[node, DIR]
        low = WINCH_LOW if node == 0 else WRAP_LOW
        phi = wrap_angle(self.F[node, THETA_IN], contact_angle(u, d), d, low)
        return float(self.F[node, L_STATIC] + self.circles[int(self.I[node, OBJ]), 2] * phi + L)

    def is_taut(self, node: int, b: npt.ArrayLike) -> bool:
        """Whether the cable in state ``node`` ending at ``b`` is a taut, admissible path:
        the active segment exists, leaves the last object with a wrap angle ``≥ 0``, meets
        no object, crosses no static segment and enters no disallowed region."""
        x, u, L, ok = self.active_segment(node, b)
        if not ok:
            return False
        b = np.asarray(b, float)
        if node != 0:
            d = self.F[node, DIR]
            if wrap_angle(self.F[node, THETA_IN], contact_angle(u, d), d, WRAP_LOW) < -TAUT_TOL:
                return False
        if segment_meets_circle(x, b, self.circles[:, :2], self.circles[:, 2], tol=MEET_TOL).any():
            return False
        earlier = self.static_segments(node)[:-1] if node != 0 else np.zeros((0, 2, 2))
        if len(earlier) and segments_intersect(x, b, earlier[:, 0], earlier[:, 1], tol=MEET_TOL).any():
            return False
        return not any(bool(segment_enters_polygon(x, b, poly, tol=MEET_TOL)) for poly in self.disallowed)

    def shortest_taut_state(self, b: npt.ArrayLike, *, max_nodes: int = MAX_TREE_NODES) -> int:
        """The taut admissible state of least length with the platform end at ``b``: a
        best-first (A*) search over the lazily expanded tree, each node bounded below by
        its static length plus the distance from its entry point to ``b``.  The default
        initial state of a cable, and the naive from-scratch state computation."""
        b = as_array(b, "the platform end b", shape=(2,))
        max_nodes = as_count(max_nodes, "max_nodes")
        heap = [(0.0, 0)]
        best, best_node, popped = np.inf, -1, 0
        while heap and heap[0][0] < best:
            _, node = heapq.heappop(heap)
            popped += 1
            if popped > max_nodes:
                break
            if self.is_taut(node, b):
                length = self.length(node, b)
                if length < best:
                    best, best_node = length, node
            for c in self.children(node):
                bound = self.F[c, L_STATIC] + np.hypot(*(b - self.F[c, [EX, EY]]))
                if bound < best:
                    heapq.heappush(heap, (float(bound), int(c)))
        if best_node < 0:
            raise TautError(
                f"no taut cable path reaches {[round(float(x), 6) for x in b]} (every routing is blocked or enters a disallowed region)"
            )
        return best_node
