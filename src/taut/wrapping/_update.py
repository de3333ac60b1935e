"""Cable-state update along a motion of the platform end (§4.2.2, Alg. 4.4 of Rushton 2022).

Between two samples the platform anchor moves on a straight line ``b(τ) = b₀ + τ (b₁ − b₀)``,
``τ ∈ [0, 1]``.  Alg. 4.4 compares the angle swept by the active segment with the angles of
the children of the tracked node, and the segment magnitudes; here the same tests are
evaluated at the instant they change, which makes them exact for straight moves, so no
step is too large to jump over a collision:

* **separation** (lines 5–11): the wrap angle about the tracked node's object turns
  negative when ``b`` crosses the forward extension of the node's segment,
  ``h(τ) = d · (u × (b(τ) − e)) < 0`` with ``(b − e)·u ≥ 0`` (``e`` the entry point,
  ``u`` the segment direction, ``d`` the wrap direction); the node moves to its parent;
* **collision** (lines 12–33): a child segment of the tracked node is reached when ``b``
  crosses the child's line beyond its end point (``θ_i`` between the old and new active
  angle and ``m < m_t2``), ``h_child(τ) ≥ 0``; the wrap direction is the one that the
  sweep direction gives (``dir`` of Eq. 4.6).  Of several children, the earliest crossing
  wins; at equal crossing (the same angle, Fig. 4.5) the child with the largest magnitude.

``h`` is linear in ``τ``, so each event time is one division.  Events are handled in time
order and the search restarts from each (several transitions in one step); separations are
strict (``h < 0``) and collisions inclusive (``h ≥ 0``), the same function for a node and
the child it came from, so a wrap and its unwrap can never fire at the same instant.

A zero-radius object (a polygon corner, or a point) has one line for both wrap directions,
so the sibling of an unwrapped node on the same point — and any other point on that line —
has ``h_sibling = −h = 0`` at the unwrap instant and rising: the inclusive collision test
alone would re-wrap the point the other way at the same instant (which one of the two
happened was decided by round-off).  Physically the cable has just straightened over the
point and moves off it; a collision needs the straight cable to have been on the other
side of the point *in this state*, which it never was.  So right after an unwrap, zero-radius
children whose line the cable lies on (``h_child = 0`` within round-off) do not collide at
that instant (and, ``h_child`` rising, not later in the step either).  A circle of positive
radius that touches the straightened cable does collide: the cable swings into it.  The
kernel (Numba) stops when it reaches a node that the lazily expanded tree has not expanded
yet; :func:`track_cable_state` expands it and resumes.

A rigid platform's anchor moves on a curve when the platform turns: callers sample it
finely enough (``taut.wrapping._ik``) that the chord is the motion.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §4.2.2, Alg. 4.4. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
from numba import njit

from taut._checks import as_array, as_index
from taut._results import Result
from taut.errors import TautError
from taut.wrapping._tree import CableStateTree

_DONE, _EXPAND, _FULL, _INSIDE, _LOOP = 0, 1, 2, 3, 4
#: Two event instants closer than this (in step fractions) are the same instant.
TIE = 1e-12
#: Most transitions of one cable within one step before the update gives up.
MAX_EVENTS_PER_STEP = 1000


@njit(cache=True)
def _length(
    F: np.ndarray, I: np.ndarray, circles: np.ndarray, node: int, bx: float, by: float
) -> tuple[float, float, float]:
    k = I[node, 1]
    cx, cy, r = circles[k, 0], circles[k, 1], circles[k, 2]
    d = F[node, 9]
    Dx, Dy = bx - cx, by - cy
    L2 = Dx * Dx + Dy * Dy - r * r
    if L2 < 0.0:
        return -1.0, 0.0, 0.0
    L = math.sqrt(L2)
    phi = math.atan2(Dy, Dx) - math.atan2(-d * r, L)
    ux, uy = math.cos(phi), math.sin(phi)
    theta = math.atan2(-d * ux, d * uy)
    low = -math.pi if I[node, 0] < 0 else -0.5 * math.pi
    w = d * (theta - F[node, 7]) - low
    w = w - 2.0 * math.pi * math.floor(w / (2.0 * math.pi)) + low
    return F[node, 8] + r * w + L, ux, uy


@njit(cache=True)
def _track(
    F: np.ndarray,
    I: np.ndarray,
    circles: np.ndarray,
    P: np.ndarray,
    node: int,
    j0: int,
    t0: float,
    nodes: np.ndarray,
    lengths: np.ndarray,
    dirs: np.ndarray,
    ev_j: np.ndarray,
    ev_t: np.ndarray,
    ev_kind: np.ndarray,
    ev_node: np.ndarray,
    n_ev: int,
) -> tuple[int, int, float, int, int]:
    T = P.shape[0]
    for j in range(j0, T):
        if j > 0:
            ax, ay, bx, by = P[j - 1, 0], P[j - 1, 1], P[j, 0], P[j, 1]
            t = t0 if j == j0 else 0.0
            count = 0
            while True:
                if I[node, 3] < 0:
                    return _EXPAND, j, t, node, n_ev
                best, kind, target, bestm = 2.0, 0, -1, -1.0
                p = I[node, 0]
                if p >= 0:  # separation from the tracked node's object
                    d, ux, uy, ex, ey = F[node, 9], F[node, 4], F[node, 5], F[node, 2], F[node, 3]
                    fa = d * (ux * (ay - ey) - uy * (ax - ex))
                    fb = d * (ux * (by - ey) - uy * (bx - ex))
                    if fb < 0.0 and fa + t * (fb - fa) >= 0.0:
                        tau = max(t, fa / (fa - fb))
                        qx, qy = ax + tau * (bx - ax) - ex, ay + tau * (by - ay) - ey
                        if qx * ux + qy * uy >= 0.0:
                            best, kind, target = tau, 2, p
                # entered at this very instant by an unwrap: the cable has just straightened
                # over the object it left and now only moves off the line it lies on
                fresh = n_ev > 0 and ev_kind[n_ev - 1] == 2 and ev_j[n_ev - 1] == j and ev_t[n_ev - 1] == t
                f0, nc = I[node, 2], I[node, 3]
                for c in range(f0, f0 + nc):  # collisions with the children
                    d, ux, uy, ex, ey = F[c, 9], F[c, 4], F[c, 5], F[c, 2], F[c, 3]
                    ga = d * (ux * (ay - ey) - uy * (ax - ex))
                    gb = d * (ux * (by - ey) - uy * (bx - ex))
                    gt = ga + t * (gb - ga)
                    if fresh and circles[I[c, 1], 2] == 0.0 and gt >= -TIE * (abs(ga) + abs(gb)):
                        continue  # a point on the straightened cable: no collision (see above)
                    if gb >= 0.0 and gt <= 0.0 and gb != ga:
                        tau = max(t, ga / (ga - gb))
                        if tau > 1.0:
                            tau = 1.0
                        qx, qy = ax + tau * (bx - ax) - ex, ay + tau * (by - ay) - ey
                        if qx * ux + qy * uy >= 0.0:
                            m = F[c, 6]
                            if tau < best - TIE or (kind == 1 and abs(tau - best) <= TIE and m > bestm):
                                best, kind, target, bestm = tau, 1, c, m
                if kind == 0:
                    break
                if n_ev >= ev_j.shape[0]:
                    return _FULL, j, t, node, n_ev
                count += 1
                if count > 1000:
                    return _LOOP, j, t, node, n_ev
                ev_j[n_ev], ev_t[n_ev], ev_kind[n_ev] = j, best, kind
                ev_node[n_ev] = node if kind == 2 else target
                n_ev += 1
                node, t = target, best
        length, ux, uy = _length(F, I, circles, node, P[j, 0], P[j, 1])
        if length < 0.0:
            return _INSIDE, j, 0.0, node, n_ev
        nodes[j], lengths[j], dirs[j, 0], dirs[j, 1] = node, length, ux, uy
    return _DONE, T, 0.0, node, n_ev


@dataclass(frozen=True)
class Tracking(Result):
    """A cable followed along ``T`` positions of its platform end (:func:`track_cable_state`).

    Attributes
    ----------
    nodes : ndarray of int, shape (T,)
        The tracked node of the cable-state tree at each sample.
    lengths : ndarray, shape (T,)
        Cable length [m] (Eq. 4.9).
    directions : ndarray, shape (T, 2)
        Unit direction of the active segment, towards the platform end.
    events : ndarray, shape (E, 4)
        Rows ``(sample j, fraction τ of the step j−1 → j, kind, node)``: kind 1 wraps onto
        ``node``'s object, kind 2 unwraps from it.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §4.2.2, Alg. 4.4. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.wrapping import CableStateTree, track_cable_state, update_state
    >>> tree = CableStateTree([[0.0, 1.0, 0.2], [0.0, 0.0, 0.0]])  # one disc, then a point winch
    >>> tr = track_cable_state(tree, [[1.0, 2.0], [-1.0, 2.0]])
    >>> tr.nodes.tolist(), np.round(tr.lengths, 4), tr.events[:, [0, 2, 3]].tolist()
    ([0, 1], array([2.2361, 2.6055]), [[1.0, 1.0, 1.0]])
    """

    nodes: np.ndarray  #: ``(T,)`` tracked CST node at each sample
    lengths: np.ndarray  #: ``(T,)`` cable length (Eq. 4.9)
    directions: np.ndarray  #: ``(T, 2)`` direction of the active segment (towards ``b``)
    events: np.ndarray  #: ``(E, 4)`` rows ``(sample j, fraction τ of step j−1→j, kind, node)``;
    #: kind 1 = wrap onto ``node``'s object, 2 = unwrap from ``node``'s object


def track_cable_state(tree: CableStateTree, points: npt.ArrayLike, *, node: int = 0) -> Tracking:
    """The states of a cable whose platform end moves along a polyline (Alg. 4.4 per step,
    exact for straight moves: module docstring).

    Parameters
    ----------
    tree : CableStateTree
    points : array_like, shape (T, 2)
        The platform end's positions [m], joined by straight moves.
    node : int, optional
        The tree node of the cable's state at ``points[0]`` (default the straight cable).

    Returns
    -------
    Tracking

    Raises
    ------
    TautError
        Points that are not rows of two finite numbers, a node not in the tree, the
        platform end inside an object, or a state that does not settle.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §4.2.2, Alg. 4.4. (docs/references.bib: rushton2022)

    Examples
    --------
    The platform end moves from ``(1, 2)`` to ``(−1, 2)``: the cable wraps the disc
    counter-clockwise on the way.

    >>> import numpy as np
    >>> from taut.wrapping import CableStateTree, track_cable_state, update_state
    >>> tree = CableStateTree([[0.0, 1.0, 0.2], [0.0, 0.0, 0.0]])  # one disc, then a point winch
    >>> tr = track_cable_state(tree, [[1.0, 2.0], [-1.0, 2.0]])
    >>> tree.contacts(int(tr.nodes[-1]))
    ((0, 1),)
    """
    P = np.ascontiguousarray(as_array(points, "points", shape=(None, 2)))
    node = as_index(node, "node", tree.size)
    T = len(P)
    nodes = np.zeros(T, dtype=np.int64)
    lengths = np.zeros(T)
    dirs = np.zeros((T, 2))
    cap = 64
    ev_j, ev_t, ev_kind, ev_node = (
        np.zeros(cap, np.int64),
        np.zeros(cap),
        np.zeros(cap, np.int64),
        np.zeros(cap, np.int64),
    )
    j, t, n_ev = 0, 0.0, 0
    tree.expand(node)
    while True:
        status, j, t, node, n_ev = _track(
            tree.F, tree.I, tree.circles, P, node, j, t, nodes, lengths, dirs, ev_j, ev_t, ev_kind, ev_node, n_ev
        )
        if status == _DONE:
            break
        if status == _EXPAND:
            tree.expand(node)
        elif status == _FULL:
            cap *= 2
            ev_j, ev_t, ev_kind, ev_node = (
                np.concatenate([a, np.zeros_like(a)]) for a in (ev_j, ev_t, ev_kind, ev_node)
            )
        elif status == _INSIDE:
            raise TautError(
                f"the platform anchor {[round(float(x), 6) for x in P[j]]} is inside object {int(tree.I[node, 1]) + 1}"
            )
        else:
            raise TautError(
                f"the cable state does not settle at sample {j} (more than {MAX_EVENTS_PER_STEP} transitions in one step)"
            )
    events = np.column_stack([ev_j[:n_ev], ev_t[:n_ev], ev_kind[:n_ev], ev_node[:n_ev]])
    return Tracking(nodes, lengths, dirs, events)


def update_state(tree: CableStateTree, node: int, b0: npt.ArrayLike, b1: npt.ArrayLike) -> int:
    """One state update (Alg. 4.4): the tracked node after a straight move of the platform end.

    Parameters
    ----------
    tree : CableStateTree
    node : int
        The tree node of the cable's state at ``b0``.
    b0, b1 : array_like, shape (2,)
        The platform end before and after the move [m].

    Returns
    -------
    int
        The tree node at ``b1``.

    Raises
    ------
    TautError
        As :func:`track_cable_state`.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §4.2.2, Alg. 4.4. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.wrapping import CableStateTree, track_cable_state, update_state
    >>> tree = CableStateTree([[0.0, 1.0, 0.2], [0.0, 0.0, 0.0]])  # one disc, then a point winch
    >>> node = update_state(tree, 0, [1.0, 2.0], [-1.0, 2.0])
    >>> tree.contacts(node)
    ((0, 1),)
    """
    ends = [as_array(b, "the platform end", shape=(2,)) for b in (b0, b1)]
    return int(track_cable_state(tree, np.array(ends), node=node).nodes[-1])
