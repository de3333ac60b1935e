"""Wrench closure, wrench feasibility and static equilibrium over arrays of poses.

The tests decide, for each structure matrix ``W`` of a batch ``(N, m, n)`` and tension
bounds ``τ_min ≤ τ ≤ τ_max``, the workspace conditions of Rushton (2022)
§2.1.4:

* **wrench closure** (WCW): the columns of ``W`` positively span ``R^m``, so that the
  cables balance any wrench with positive tensions;
* **wrench feasibility** (WFW): for every wrench ``w`` of a required set there are tensions
  within the bounds with ``W τ + w = 0`` (Eq. 2.11);
* **static equilibrium**: the same for one wrench (the special case named in §2.1.4).

Method: *hyperplane shifting* (Gouttefarde & Gosselin 2006; Bouchard, Gosselin & Moore
2010).  The available wrench set is the zonotope ``Z = {W τ : τ_min ≤ τ ≤ τ_max}`` (a
Minkowski sum of segments, or of rays where ``τ_max = ∞``).  Every facet of ``Z`` is
parallel to ``m − 1`` linearly independent columns of ``W``, so its normal ``n`` is the
null vector of those columns (a generalised cross product), and the support function of
``Z`` is ``h_Z(n) = Σ_j max(n·w_j τ_min,j, n·w_j τ_max,j)``.  A closed convex set ``A`` lies
in the full-dimensional polyhedron ``Z`` iff ``h_A(±n) ≤ h_Z(±n)`` for all facet normals.
Here ``A = −(o + S)`` for the required set ``S`` shifted by ``o`` (the external wrench),
so ``h_A(n) = h_S(−n) − n·o``.  The normals are computed inside a Numba kernel by
Gaussian elimination with partial pivoting, shared between the combinations of columns
with a common prefix (a depth-first walk, see the kernel's comment).  The kernel also
evaluates the support function of the built-in wrench sets (point, box, ellipsoid,
polytope — or any Minkowski sum of them); other :class:`~taut.statics.WrenchSet`
subclasses get the normals back and are evaluated through their own vectorised
``support``.

Closure uses the same normals: ``0`` is interior to ``W·[0, 1]^n`` iff ``rank W = m`` and
every facet normal has columns strictly on both of its sides.

Any direction gives a valid *necessary* condition ``h_A(n) ≤ h_Z(n)``, so a spurious
normal from a nearly dependent set of columns can never turn an infeasible pose into a
feasible one.  When ``rank W < m`` (``Z`` is flat — always for under-constrained robots
with fewer cables than degrees of freedom) the facet test does not apply: a single
wrench, a box or a polytope is then decided exactly, one point of the set (vertex) after
the other — where the columns of ``W`` are independent (condition number below
``FLAT_COND``) the tensions balancing a point are unique, ``τ = W⁺ r``, and are checked in
one batched closed form (residual and bounds within the slack below); elsewhere by linear
programs (``highspy``); a full-dimensional set cannot fit in a flat ``Z`` and is
infeasible; an ellipsoid that is flat but not a point, or a set known only by its support
function, is treated conservatively as infeasible there (such poses have measure zero for
robots with ``n ≥ m`` cables).

Many cables: the facet test enumerates ``C(n, m − 1)`` normals per pose (2 million for
2000 cables and ``m = 3``); above ``FACET_WORK`` (normals times cables) linear programs
decide every pose instead, warm started: the closure by ``rank W = m`` and some
``τ ≥ 1`` with ``W τ = 0``, feasibility by one LP per vertex of the set (a set known
only by its support function, such as an ellipsoid, is then refused).
Cables with ``τ_min = τ_max`` carry a known tension: their wrench is moved into ``o`` and
their columns dropped, so that the remaining generators all have positive length.

Tolerances: a column whose projection on the complement of the columns already chosen
is below ``1e-12 ‖w_j‖`` (times the pivot growth bound ``2^d``) is dependent;
``|n·w_j| ≤ 1e-12 ‖w_j‖`` (unit ``n``) counts as zero, so that ``0·∞`` never arises from
round-off; support inequalities are tested with a slack of ``1e-9`` of the sum of the
magnitudes of their terms, plus ``1e-12`` of the norms of the offset and of the set (an
entry of ``n`` that should vanish is ~1e-17, so ``n·x`` is known to ``1e-12 ‖x‖`` only, as
the ``n·w_j`` are); for feasibility ``rank W = m`` needs some ``|n·w_j| > 1e-8 ‖w_j‖``
(``FULL_TOL``), else the pose is decided as a flat one; closure needs ``n·w_j`` beyond
``±1e-10 ‖w_j‖``.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §2.1.4, Eq. 2.11. (docs/references.bib: rushton2022)
.. [2] M. Gouttefarde, C. M. Gosselin, "Analysis of the wrench-closure workspace of planar
   parallel cable-driven mechanisms", IEEE Transactions on Robotics 22(3), 2006.
   (docs/references.bib: gouttefarde2006)
.. [3] S. Bouchard, C. Gosselin, B. Moore, "On the ability of a cable-driven robot to generate a
   prescribed set of wrenches", Journal of Mechanisms and Robotics 2(1), 2010.
   (docs/references.bib: bouchard2010)
"""

from __future__ import annotations

import math
import threading
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt
from numba import njit

from taut.errors import TautError
from taut.statics._wrench import (
    BoxWrenchSet,
    EllipsoidWrenchSet,
    PolytopeWrenchSet,
    SingleWrench,
    WrenchSet,
    as_floats,
    bounds_pair,
)

if TYPE_CHECKING:
    import highspy

__all__ = ["facet_normals", "static_equilibrium", "wrench_closure", "wrench_feasible"]

#: Relative pivot size below which a column depends on the columns already chosen.
RANK_TOL = 1e-12
#: ``|n·w_j| ≤ ZERO_TOL ‖w_j‖`` (unit ``n``) counts as ``n·w_j = 0``.
ZERO_TOL = 1e-12
#: Feasibility: a facet normal with some ``|n·w_j| > FULL_TOL ‖w_j‖`` proves ``rank W = m``;
#: where no normal has one, ``W`` is of rank ``< m`` to within round-off (a rank-5 ``W`` of
#: 6 rows showed ``|n·w_j| = 2e-12 ‖w_j‖``) and the pose is decided as a flat one, exactly.
FULL_TOL = 1e-8
#: Relative slack of the support inequalities ``h_A(n) ≤ h_Z(n)``.
SLACK = 1e-9
#: Relative margin for "a column strictly on each side" in the closure test.
CLOSURE_TOL = 1e-10
#: Facet normals times cables per pose (``C(n, m − 1) n``, the work of the facet test)
#: above which linear programs decide instead: one per pose for the closure, one per
#: vertex of the wrench set for feasibility, warm started.  An LP costs about a
#: millisecond, as much as the facets of 60 cables for m = 3 or 16 for m = 6 (1.1e5 and
#: 7e4); 2000 cables would need 2e6 (m = 3) or 2.6e14 (m = 6) normals per pose.
FACET_WORK = 2**17
#: Largest condition number of the columns of a flat ``W`` decided in closed form
#: (``τ = W⁺ r``); a worse conditioned one is decided by a linear program.
FLAT_COND = 1e8

# status codes of the kernels
_OUT, _IN, _FLAT = 0, 1, 2


# ---- Numba kernel -----------------------------------------------------------------
#
# The facet normals are enumerated by a depth-first walk over the combinations of
# m − 1 columns in lexicographic order, sharing the elimination of common prefixes:
# at depth d the walk holds a basis B_d (rows, m − d of them) of the orthogonal
# complement of the d chosen columns and the projections A_d = B_d W of all columns.
# Choosing column c with coefficients a = A_d[:, c] and pivot q = argmax |a_i|, the
# vectors b_i − (a_i/a_q) b_q (i ≠ q) span the complement of the d + 1 columns — one
# step of Gaussian elimination with partial pivoting; each b_i keeps a unit entry, so
# ‖b_i‖ ≥ 1 and |a| small means "c depends on the chosen columns" (the whole subtree is
# then skipped).  At depth m − 1 the single row of B is the normal n and the single row
# of A holds the n·w_j.

MODE_CLOSURE, MODE_FEASIBLE, MODE_NORMALS = 0, 1, 2
#: A built-in wrench set as the kernel takes it: ``(center, half, shape, has_shape, verts)``.
SetArrays = tuple[np.ndarray, np.ndarray, np.ndarray, bool, np.ndarray]


@njit(cache=True, nogil=True)
def _binom(a: int, b: int) -> int:
    if b < 0 or b > a:
        return 0
    r = 1
    for i in range(b):
        r = r * (a - i) // (i + 1)
    return r


@njit(cache=True, nogil=True)
def _facet_kernel(
    W: np.ndarray,
    tmin: np.ndarray,
    tmax: np.ndarray,
    mode: int,
    offset: np.ndarray,
    center: np.ndarray,
    half: np.ndarray,
    shape: np.ndarray,
    has_shape: bool,
    verts: np.ndarray,
    status: np.ndarray,
    normals: np.ndarray,
    hz: np.ndarray,
    valid: np.ndarray,
) -> None:
    """Hyperplane shifting over a batch ``W (N, m, n)``.

    ``mode`` 0: wrench closure; 1: feasibility of ``offset[k] + center + box(half) +
    ellipsoid(shape) + conv(verts)`` (``offset`` has 1 or N rows); 2: store the unit facet
    normals ``normals (N, C, m)``, ``h_Z(±n)`` in ``hz (N, C, 2)`` and the rank mask
    ``valid (N, C)`` (combinations in lexicographic order).  ``status[k]`` receives
    ``_OUT`` / ``_IN`` / ``_FLAT`` (rank W < m, nothing violated)."""
    N, m, n = W.shape
    p = m - 1
    nvert = verts.shape[0]
    n_off = offset.shape[0]
    A = np.empty((m, m, n))  # A[d, :m-d, :]
    B = np.empty((m, m, m))  # B[d, :m-d, :]
    nxt = np.empty(m, np.int64)
    chosen = np.empty(m, np.int64)
    colnorm = np.empty(n)
    d_ = np.empty(n)
    nv = np.empty(m)
    oc = np.empty(m)
    finite = np.empty(n, np.bool_)
    for j in range(n):
        finite[j] = np.isfinite(tmax[j])
    # Lipschitz constants in n of the set's support terms (|n·x| is known to ZERO_TOL ‖x‖):
    # Σ|n_i| half_i, sqrt(nᵀ S n) = ‖S^½ n‖ (‖S^½‖² ≤ trace S) and the vertices' n·v
    known_set = np.sqrt(np.sum(half * half))
    if has_shape:
        known_set += np.sqrt(max(np.trace(shape), 0.0))
    vnorm = 0.0
    for v in range(nvert):
        vnorm = max(vnorm, np.sqrt(np.sum(verts[v] * verts[v])))
    known_set += vnorm
    for k in range(N):
        Wk = W[k]
        for j in range(n):
            acc = 0.0
            for i in range(m):
                acc += Wk[i, j] * Wk[i, j]
            colnorm[j] = np.sqrt(acc)
        if mode == MODE_FEASIBLE:
            ko = k if n_off > 1 else 0
            for i in range(m):
                oc[i] = offset[ko, i] + center[i]
        for i in range(m):
            for j in range(n):
                A[0, i, j] = Wk[i, j]
            for j in range(m):
                B[0, i, j] = 1.0 if i == j else 0.0
        ok = True
        full = False
        leaf = 0
        depth = 0
        nxt[0] = 0
        while ok:
            c = nxt[depth]
            if c > n - p + depth:  # too few columns left to complete a combination
                if depth == 0:
                    break
                depth -= 1
                continue
            nxt[depth] = c + 1
            r = m - depth
            q = 0
            amax = -1.0
            for i in range(r):
                a = abs(A[depth, i, c])
                if a > amax:
                    amax = a
                    q = i
            if amax <= RANK_TOL * colnorm[c] * (2.0**depth):
                if mode == MODE_NORMALS:  # skip the subtree: its combinations have rank < m − 1
                    cnt = _binom(n - 1 - c, p - 1 - depth)
                    for s in range(leaf, leaf + cnt):
                        valid[k, s] = False
                    leaf += cnt
                continue
            aq = A[depth, q, c]
            ii = 0
            for i in range(r):
                if i == q:
                    continue
                f = A[depth, i, c] / aq
                for j in range(n):
                    A[depth + 1, ii, j] = A[depth, i, j] - f * A[depth, q, j]
                A[depth + 1, ii, c] = 0.0
                for j in range(m):
                    B[depth + 1, ii, j] = B[depth, i, j] - f * B[depth, q, j]
                ii += 1
            chosen[depth] = c
            if depth + 1 < p:
                depth += 1
                nxt[depth] = c + 1
                continue
            # ---- leaf: one facet normal ------------------------------------------
            bn = 0.0
            for j in range(m):
                bn += B[p, 0, j] * B[p, 0, j]
            bn = np.sqrt(bn)
            for j in range(m):
                nv[j] = B[p, 0, j] / bn
            off = False
            solid = False
            for j in range(n):
                dj = A[p, 0, j] / bn
                if abs(dj) <= ZERO_TOL * colnorm[j]:
                    dj = 0.0
                else:
                    off = True
                    solid = solid or abs(dj) > FULL_TOL * colnorm[j]
                d_[j] = dj
            for i in range(p):
                d_[chosen[i]] = 0.0
            if solid if mode == MODE_FEASIBLE else off:
                full = True
            if mode == MODE_CLOSURE:
                pos = False
                neg = False
                for j in range(n):
                    if d_[j] > CLOSURE_TOL * colnorm[j]:
                        pos = True
                    elif d_[j] < -CLOSURE_TOL * colnorm[j]:
                        neg = True
                if not (pos and neg):
                    ok = False
                continue
            # support of Z in +n and -n (0·∞ never occurs: zero d_j contribute nothing)
            hp = 0.0
            hm = 0.0
            sz = 0.0
            inf_p = False
            inf_m = False
            for j in range(n):
                dj = d_[j]
                if dj > 0.0:
                    if finite[j]:
                        hp += dj * tmax[j]
                        sz += abs(dj * tmax[j])
                    else:
                        inf_p = True
                    hm -= dj * tmin[j]
                    sz += abs(dj * tmin[j])
                elif dj < 0.0:
                    hp += dj * tmin[j]
                    sz += abs(dj * tmin[j])
                    if finite[j]:
                        hm -= dj * tmax[j]
                        sz += abs(dj * tmax[j])
                    else:
                        inf_m = True
            if mode == MODE_NORMALS:
                for j in range(m):
                    normals[k, leaf, j] = nv[j]
                hz[k, leaf, 0] = np.inf if inf_p else hp
                hz[k, leaf, 1] = np.inf if inf_m else hm
                valid[k, leaf] = True
                leaf += 1
                continue
            # support of the required set -(o + S):  h(n) = h_S(-n) - n.o,  h(-n) = h_S(n) + n.o
            lin = 0.0
            labs = 0.0
            spread = 0.0
            for i in range(m):
                lin += nv[i] * oc[i]
                labs += abs(nv[i] * oc[i])
                spread += abs(nv[i]) * half[i]
            if has_shape:
                qf = 0.0
                for i in range(m):
                    acc = 0.0
                    for j in range(m):
                        acc += shape[i, j] * nv[j]
                    qf += nv[i] * acc
                if qf > 0.0:
                    spread += np.sqrt(qf)
            vmax = 0.0
            vmin = 0.0
            vabs = 0.0
            if nvert > 0:
                vmax = -np.inf
                vmin = np.inf
                for v in range(nvert):
                    acc = 0.0
                    aabs = 0.0
                    for i in range(m):
                        acc += nv[i] * verts[v, i]
                        aabs += abs(nv[i] * verts[v, i])
                    vmax = max(vmax, acc)
                    vmin = min(vmin, acc)
                    vabs = max(vabs, aabs)
            req_p = spread - vmin - lin
            req_m = spread + vmax + lin
            # slack relative to the magnitudes summed (not to the sums, which may cancel), and
            # the round-off of n itself: an entry that should be 0 is ~1e-17, not 0, so that
            # n·x is known to ZERO_TOL ‖x‖ only (as the n·w_j are)
            tol = SLACK * (sz + labs + spread + vabs + 1e-300) + ZERO_TOL * (np.sqrt(np.sum(oc * oc)) + known_set)
            if (not inf_p and req_p > hp + tol) or (not inf_m and req_m > hm + tol):
                ok = False
        if not ok:
            status[k] = _OUT
        elif full:
            status[k] = _IN
        else:
            status[k] = _FLAT


# ---- helpers ----------------------------------------------------------------------


def _as_W(W: npt.ArrayLike) -> np.ndarray:
    W = as_floats(W, "structure matrices")
    if W.ndim == 2:
        W = W[None]
    if W.ndim != 3 or W.shape[1] < 1 or W.shape[2] < 1:
        raise TautError(f"structure matrices must have shape (N, m, n), got {np.shape(W)}")
    if not np.all(np.isfinite(W)):
        raise TautError("structure matrices must be finite")
    return np.ascontiguousarray(W)


def _bounds(tension_bounds: object, n: int) -> tuple[np.ndarray, np.ndarray]:
    tmin, tmax = bounds_pair(tension_bounds)
    lo, hi = as_floats(tmin, "lower tension bounds"), as_floats(tmax, "upper tension bounds")
    if lo.ndim > 1 or lo.size not in (1, n) or hi.ndim > 1 or hi.size not in (1, n):
        raise TautError(
            f"tension bounds must be numbers or have shape ({n},) for {n} cables, got {lo.shape}, {hi.shape}"
        )
    lo, hi = np.broadcast_to(lo, (n,)).copy(), np.broadcast_to(hi, (n,)).copy()
    if not np.all(np.isfinite(lo)):
        raise TautError(f"lower tension bounds must be finite, got {lo.tolist()}")
    if np.any(np.isnan(hi)) or np.any(hi == -np.inf):
        raise TautError(f"upper tension bounds must be numbers or +inf, got {hi.tolist()}")
    if np.any(lo > hi):
        raise TautError(f"tension bounds are inverted: {lo.tolist()} > {hi.tolist()}")
    return lo, hi


def _set_arrays(ws: WrenchSet, m: int) -> SetArrays | None:
    """``(center, half, shape, has_shape, verts)`` of a built-in set, or None."""
    zeros = np.zeros(m)
    none = np.zeros((0, m))
    if isinstance(ws, SingleWrench):
        return ws.wrench, zeros, np.zeros((m, m)), False, none
    if isinstance(ws, BoxWrenchSet):
        return (ws.lower + ws.upper) / 2, (ws.upper - ws.lower) / 2, np.zeros((m, m)), False, none
    if isinstance(ws, EllipsoidWrenchSet):
        return ws.center_wrench, zeros, ws.shape, True, none
    if isinstance(ws, PolytopeWrenchSet):
        return zeros, zeros, np.zeros((m, m)), False, ws.vertices
    return None


def _set_points(ws: WrenchSet) -> np.ndarray | None:
    """Finitely many points whose hull is the set (for the LP fallback), or None."""
    if isinstance(ws, SingleWrench):
        return ws.wrench[None]
    if isinstance(ws, BoxWrenchSet):
        return np.unique(ws.vertices(), axis=0)
    if isinstance(ws, PolytopeWrenchSet):
        return ws.vertices
    return None


def _set_dimension(ws: WrenchSet, m: int) -> int | None:
    """Affine dimension of the set when it is known."""
    pts = _set_points(ws)
    if pts is not None:
        return int(np.linalg.matrix_rank(pts - pts[0])) if len(pts) > 1 else 0
    if isinstance(ws, EllipsoidWrenchSet):
        return int(np.linalg.matrix_rank(ws.shape))
    return None


def _lp_feasible(W: np.ndarray, tmin: np.ndarray, tmax: np.ndarray, rhs: np.ndarray) -> bool:
    """Is there ``τ_min ≤ τ ≤ τ_max`` with ``W τ = rhs``, for every row of ``rhs`` (``(m,)``
    or ``(K, m)``)?  One LP per row, solved by HiGHS, each warm started from the last."""
    import highspy

    h = _highs()
    m, n = W.shape
    rows = np.atleast_2d(np.asarray(rhs, dtype=float))
    lp = highspy.HighsLp()
    lp.num_col_ = n
    lp.num_row_ = m
    lp.col_cost_ = np.zeros(n)
    inf = highspy.kHighsInf
    lp.col_lower_ = tmin
    lp.col_upper_ = np.where(np.isinf(tmax), inf, tmax)
    lp.row_lower_ = rows[0]
    lp.row_upper_ = rows[0]
    lp.a_matrix_.format_ = highspy.MatrixFormat.kColwise
    lp.a_matrix_.start_ = np.arange(0, m * n + 1, m, dtype=np.int32)
    lp.a_matrix_.index_ = np.tile(np.arange(m, dtype=np.int32), n)
    lp.a_matrix_.value_ = np.ascontiguousarray(W.T).ravel()
    h.clearModel()
    h.passModel(lp)
    for k, r in enumerate(rows):
        for i in range(m) if k else ():
            h.changeRowBounds(i, r[i], r[i])
        h.run()
        if h.getModelStatus() != highspy.HighsModelStatus.kOptimal:
            return False
    return True


_LOCAL = threading.local()


def _highs() -> highspy.Highs:
    """One reused HiGHS instance per thread (dask workers may run several threads)."""
    h = getattr(_LOCAL, "highs", None)
    if h is None:
        from taut.statics._highs import QuietHighs

        h = QuietHighs()
        _LOCAL.highs = h
    return h


def _flat_feasible(W: np.ndarray, tmin: np.ndarray, tmax: np.ndarray, ws: WrenchSet, off: np.ndarray) -> np.ndarray:
    """Exact decisions ``(K,)`` at poses ``W (K, m, n)`` where ``rank W < m`` (``off`` ``(1, m)``
    or ``(K, m)``).  Where the columns are independent and well conditioned (every pose of a
    robot with fewer cables than wrench components, in general) the tensions that balance a
    wrench are unique, ``τ = W⁺ r``: a batched closed form; the other poses get one LP per
    point of the set."""
    K, m, n = W.shape
    out = np.zeros(K, bool)
    dim = _set_dimension(ws, m)
    if K == 0 or dim is None or dim >= m:
        return out
    pts: np.ndarray | None
    if isinstance(ws, EllipsoidWrenchSet):
        if dim > 0:
            return out  # conservative: a flat, non-degenerate ellipsoid (module docstring)
        pts = ws.center_wrench[None]
    else:
        pts = _set_points(ws)
    if pts is None:
        return out
    off = np.broadcast_to(off, (K, m))
    sv = np.linalg.svd(W, compute_uv=False)
    closed = (n <= m) & (sv[:, -1] > sv[:, 0] / FLAT_COND)
    if closed.any():
        Wc = W[closed]
        pinv = np.linalg.pinv(Wc)
        norms = np.linalg.norm(Wc, axis=1)  # ‖w_j‖, (Kc, n)
        ok = np.ones(len(Wc), bool)
        for p in pts:
            r = -(off[closed] + p)
            tau = np.einsum("knm,km->kn", pinv, r)
            resid = np.linalg.norm(np.einsum("kmn,kn->km", Wc, tau) - r, axis=1)
            scale = np.linalg.norm(r, axis=1) + (norms * np.abs(tau)).sum(axis=1)
            ok &= resid <= SLACK * scale
            # the tensions' own round-off: relative to them, and to ‖r‖ / ‖w_j‖
            slack = SLACK * (np.abs(tau) + np.linalg.norm(r, axis=1)[:, None] / norms)
            with np.errstate(invalid="ignore"):
                ok &= np.all(
                    (tau >= tmin - slack - SLACK * np.abs(tmin)) & (tau <= tmax + slack + SLACK * np.abs(tmax)), axis=1
                )
        out[closed] = ok
    for k in np.flatnonzero(~closed):
        out[k] = _lp_feasible(W[k], tmin, tmax, -(off[k] + pts))
    return out


def _fix_constant(
    W: np.ndarray, tmin: np.ndarray, tmax: np.ndarray, offset: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Move cables with ``τ_min = τ_max`` into the offset."""
    fixed = tmin == tmax
    if not fixed.any():
        return W, tmin, tmax, offset
    offset = offset + np.einsum("kij,j->ki", W[:, :, fixed], tmin[fixed])
    keep = ~fixed
    return np.ascontiguousarray(W[:, :, keep]), tmin[keep], tmax[keep], offset


def _run(
    W: np.ndarray,
    tmin: np.ndarray,
    tmax: np.ndarray,
    mode: int,
    off: np.ndarray,
    arrays: SetArrays,
    status: np.ndarray,
    normals: np.ndarray | None = None,
    hz: np.ndarray | None = None,
    valid: np.ndarray | None = None,
) -> None:
    """Call the kernel with contiguous float arrays (and empty outputs unless ``mode`` 2)."""
    m = W.shape[1]
    center, half, shape, has_shape, verts = arrays
    if normals is None or hz is None or valid is None:
        normals, hz, valid = np.zeros((0, 0, 0)), np.zeros((0, 0, 2)), np.zeros((0, 0), np.bool_)
    _facet_kernel(
        W,
        tmin,
        tmax,
        mode,
        np.ascontiguousarray(off, dtype=float),
        np.ascontiguousarray(center, dtype=float),
        np.ascontiguousarray(half, dtype=float),
        np.ascontiguousarray(shape, dtype=float),
        bool(has_shape),
        np.ascontiguousarray(verts, dtype=float).reshape(-1, m),
        status,
        normals,
        hz,
        valid,
    )


def _no_set(m: int) -> SetArrays:
    return np.zeros(m), np.zeros(m), np.zeros((m, m)), False, np.zeros((0, m))


# ---- public API -------------------------------------------------------------------


def facet_normals(
    W: npt.ArrayLike, *, tension_bounds: tuple[npt.ArrayLike, npt.ArrayLike] = (0.0, 1.0)
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Unit facet normals of the zonotopes ``Z = W·[tmin, tmax]`` (``tension_bounds = (tmin,
    tmax)``) and their support.

    Returns ``normals (N, C, m)``, one per combination of ``m − 1`` columns
    (``C = binom(n, m−1)``, in the order of :func:`itertools.combinations`), ``hz (N, C, 2)``
    with ``h_Z(n)`` and ``h_Z(−n)`` (``inf`` where unbounded), and a ``(N, C)`` mask of the
    combinations of rank ``m − 1`` (the others have no normal; their rows are undefined)."""
    W = _as_W(W)
    N, m, n = W.shape
    lo, hi = _bounds(tension_bounds, n)
    C = _binom(n, m - 1) if m >= 2 else 0
    normals = np.zeros((N, C, m))
    hz = np.zeros((N, C, 2))
    valid = np.zeros((N, C), np.bool_)
    if C:
        _run(W, lo, hi, MODE_NORMALS, np.zeros((1, m)), _no_set(m), np.zeros(N, np.int8), normals, hz, valid)
    return normals, hz, valid


def wrench_closure(W: npt.ArrayLike, *, method: str = "auto") -> np.ndarray:
    """Wrench closure: whether the columns of each structure matrix positively span ``R^m``,
    so that the cables balance any wrench with positive tensions (the wrench-closure
    workspace of Rushton (2022), §2.1.4).

    Hyperplane shifting with zero lower and unit upper bounds: ``0`` is interior to
    ``W·[0, 1]^n`` iff ``rank W = m`` and every facet normal has a column strictly on each
    side (relative margin ``CLOSURE_TOL``).  ``method="lp"`` decides instead by one linear
    program per pose (``rank W = m`` and some ``τ ≥ 1`` with ``W τ = 0``); ``"auto"`` uses the
    facets up to :data:`FACET_WORK` work per pose (``C(n, m − 1) n``), else LPs.

    Parameters
    ----------
    W : array_like, shape (N, m, n) or (m, n)
        Structure matrices.

    Returns
    -------
    ndarray of bool, shape (N,)

    Raises
    ------
    TautError
        For matrices of the wrong shape or not finite.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §2.1.4. (docs/references.bib: rushton2022)
    .. [2] M. Gouttefarde, C. M. Gosselin, "Analysis of the wrench-closure workspace of planar
       parallel cable-driven mechanisms", IEEE Transactions on Robotics 22(3), 2006.
       (docs/references.bib: gouttefarde2006)

    Examples
    --------
    Three cables pulling a point at 120° apart span the plane positively; two never do:

    >>> angles = np.radians([90.0, 210.0, 330.0])
    >>> W = np.stack([np.cos(angles), np.sin(angles)])
    >>> wrench_closure(W), wrench_closure(W[:, :2])
    (array([ True]), array([False]))
    """
    W = _as_W(W)
    N, m, n = W.shape
    lp = _use_lp(method, m, n)
    if m == 1:
        return (W[:, 0, :].max(axis=1) > 0) & (W[:, 0, :].min(axis=1) < 0)
    if n > m and lp:
        return _closure_lp(W)
    status = np.zeros(N, np.int8)
    if n > m:  # positive spanning needs at least m + 1 columns
        _run(W, np.zeros(n), np.ones(n), MODE_CLOSURE, np.zeros((1, m)), _no_set(m), status)
    return status == _IN


def wrench_feasible(
    W: npt.ArrayLike,
    wrench_set: WrenchSet,
    *,
    tension_bounds: tuple[npt.ArrayLike, npt.ArrayLike],
    wrench: npt.ArrayLike | None = None,
    method: str = "auto",
) -> np.ndarray:
    """Wrench feasibility: whether, for every wrench ``w`` of ``wrench[k] + wrench_set``, tensions
    ``tmin ≤ τ ≤ tmax`` satisfy ``W[k] τ + w = 0`` (the wrench-feasible workspace of Rushton
    (2022), §2.1.4; hyperplane shifting of Gouttefarde & Gosselin 2006 and Bouchard et al.
    2010).  Poses where ``rank W < m`` are decided by linear programs (module docstring).

    Parameters
    ----------
    W : array_like, shape (N, m, n) or (m, n)
        Structure matrices.
    wrench_set : WrenchSet
        The required set of wrenches, of dimension ``m``.
    tension_bounds : (tmin, tmax)
        Tension bounds [N], each a number or ``(n,)``; ``tmax`` may be ``inf``.
    wrench : array_like, shape (m,) or (N, m), optional
        Shifts the set: the external wrench [N, N m] (default 0).
    method : {"auto", "facets", "lp"}, default "auto"
        ``"facets"``: hyperplane shifting; ``"lp"``: one linear program per vertex of the set
        (a single wrench, a box or a polytope); ``"auto"``: the facets up to
        :data:`FACET_WORK` work per pose (``C(n, m − 1) n``), else LPs.

    Returns
    -------
    ndarray of bool, shape (N,)

    Raises
    ------
    TautError
        For arrays of the wrong shape or not finite, bounds that are inverted or not a pair, a
        set that is not a :class:`WrenchSet` of dimension ``m``, an unknown ``method``, or an
        ellipsoid where only LPs are affordable.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §2.1.4, Eq. 2.11. (docs/references.bib: rushton2022)
    .. [2] S. Bouchard, C. Gosselin, B. Moore, "On the ability of a cable-driven robot to
       generate a prescribed set of wrenches", Journal of Mechanisms and Robotics 2(1), 2010.
       (docs/references.bib: bouchard2010)

    Examples
    --------
    The planar 4-cable robot at the centre of its frame holds its weight plus any force of
    up to 1 N and moment of up to 0.1 N m, but not with tensions of at most 8 N:

    >>> from taut.kinematics import structure_matrix
    >>> from taut.model import example
    >>> robot = example("planar-4cable")
    >>> W = structure_matrix(robot, [0.0, 0.0, 0.0])
    >>> box = BoxWrenchSet.around([0.0, 0.0, 0.0], [1.0, 1.0, 0.1])
    >>> weight = [0.0, -9.81, 0.0]
    >>> wrench_feasible(W, box, tension_bounds=(1.0, 100.0), wrench=weight)
    array([ True])
    >>> wrench_feasible(W, box, tension_bounds=(1.0, 8.0), wrench=weight)
    array([False])
    """
    W = _as_W(W)
    N, m, n = W.shape
    lp = _use_lp(method, m, n)
    if not isinstance(wrench_set, WrenchSet):
        raise TautError(f"wrench_set must be a WrenchSet, got {type(wrench_set).__name__}")
    if wrench_set.dim != m:
        raise TautError(f"the wrench set has dimension {wrench_set.dim}, the structure matrices {m}")
    tmin, tmax = _bounds(tension_bounds, n)
    off = np.zeros((1, m)) if wrench is None else as_floats(wrench, "wrench")
    given = off.shape
    if off.ndim == 1:
        off = off[None]
    if off.ndim != 2 or off.shape[-1] != m or off.shape[0] not in (1, N):
        raise TautError(f"wrench must have shape ({m},) or ({N}, {m}), got {given}")
    if not np.all(np.isfinite(off)):
        raise TautError("offset must be finite")
    if m >= 2 and n >= m and lp:
        return _feasible_lp(W, tmin, tmax, wrench_set, off)
    W0, tmin0, tmax0, off0 = W, tmin, tmax, off
    W, tmin, tmax, off = _fix_constant(W, tmin, tmax, off)
    n = W.shape[2]
    status = np.full(N, _FLAT, np.int8)
    if m >= 2 and n >= m:
        arrays = _set_arrays(wrench_set, m)
        if arrays is not None:
            _run(W, tmin, tmax, MODE_FEASIBLE, off, arrays, status)
        else:
            _generic_status(W, tmin, tmax, off, wrench_set, status)
    out = status == _IN
    flat = np.flatnonzero(status == _FLAT)  # rank W < m: rare for n >= m; every pose if n < m
    if flat.size:
        out[flat] = _flat_feasible(W0[flat], tmin0, tmax0, wrench_set, off0[flat] if off0.shape[0] > 1 else off0)
    return out


#: The ``method`` of :func:`wrench_closure` and :func:`wrench_feasible`.
FEASIBILITY_METHODS = ("auto", "facets", "lp")


def _use_lp(method: str, m: int, n: int) -> bool:
    """Whether ``method`` decides by LPs: ``"lp"``, or ``"auto"`` where the facet test would
    cost more than :data:`FACET_WORK` (``C(n, m − 1)`` normals times ``n`` cables a pose)."""
    if method not in FEASIBILITY_METHODS:
        raise TautError(f"unknown method {method!r}; expected one of {', '.join(FEASIBILITY_METHODS)}")
    return method == "lp" or (method == "auto" and math.comb(n, m - 1) * n > FACET_WORK)


def _projected(W: np.ndarray, start: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    """``τ = start + W⁺ (rhs − W start)`` ``(K, n)``: the tensions nearest ``start`` that
    solve ``W τ = rhs`` at poses where ``W`` ``(K, m, n)`` has full row rank."""
    gram = np.einsum("kin,kjn->kij", W, W)
    miss = rhs - np.einsum("kmn,n->km", W, start)
    return start + np.einsum("kmn,km->kn", W, np.linalg.solve(gram, miss[..., None])[..., 0])


def _closure_lp(W: np.ndarray) -> np.ndarray:
    """Wrench closure by one LP per pose: ``rank W = m`` and some ``τ ≥ 1`` with ``W τ = 0``
    (then ``0 = W (τ / max τ)`` with ``τ / max τ`` interior to ``[0, 1]^n``).  Two
    certificates spare most LPs: the null vector nearest ``(1, …, 1)``, when positive,
    proves the closure; a direction ``v ≠ 0`` (the sum of the unit columns) with
    ``v·w_j ≥ 0`` for every column disproves it (no tensions pull along ``−v``)."""
    N, m, n = W.shape
    sv = np.linalg.svd(W, compute_uv=False)
    full = np.flatnonzero(sv[:, -1] > RANK_TOL * sv[:, 0])
    out = np.zeros(N, bool)
    ones, unbounded, zero = np.ones(n), np.full(n, np.inf), np.zeros(m)
    tau = _projected(W[full], ones, np.zeros((full.size, m)))
    proven = tau.min(axis=1) > CLOSURE_TOL * np.abs(tau).max(axis=1)
    out[full[proven]] = True
    rest = full[~proven]
    U = W[rest] / np.maximum(np.linalg.norm(W[rest], axis=1), 1e-300)[:, None, :]
    v = U.sum(axis=2)
    side = (np.einsum("km,kmn->kn", v, U) >= 0.0).all(axis=1) & (np.linalg.norm(v, axis=1) > ZERO_TOL * n)
    for k in rest[~side]:
        out[k] = _lp_feasible(W[k], ones, unbounded, zero)
    return out


def _feasible_lp(W: np.ndarray, tmin: np.ndarray, tmax: np.ndarray, ws: WrenchSet, off: np.ndarray) -> np.ndarray:
    """Wrench feasibility by LPs, one per point of the set and pose: exact for a set that
    is the hull of finitely many points (a convex set lies in the zonotope iff they do).
    The tensions nearest the middle of the bounds that balance each point
    (:func:`_projected`), when within the bounds, prove a pose feasible without an LP."""
    N, m, n = W.shape
    pts = _set_points(ws)
    if pts is None:
        raise TautError(
            f"{type(ws).__name__} is decided by the facets of the available wrench set: "
            f"C({n}, {m - 1}) = {math.comb(n, m - 1):.3g} of them per pose with {n} cables; "
            "give a box, polytope or single wrench (decided by linear programs)"
        )
    rhs = -(np.broadcast_to(off, (N, m))[:, None, :] + pts[None])
    start = np.where(np.isfinite(tmax), 0.5 * (tmin + tmax), tmin + np.maximum(1.0, np.abs(tmin)))
    sv = np.linalg.svd(W, compute_uv=False)
    full = np.flatnonzero(sv[:, -1] > RANK_TOL * sv[:, 0])
    proven = np.zeros(N, bool)
    inside = np.ones(full.size, bool)
    for p in range(len(pts)):
        tau = _projected(W[full], start, rhs[full, p])
        inside &= np.all((tau >= tmin) & (tau <= tmax), axis=1)
    proven[full[inside]] = True
    out = proven.copy()
    for k in np.flatnonzero(~proven):
        out[k] = _lp_feasible(W[k], tmin, tmax, rhs[k])
    return out


def _generic_status(
    W: np.ndarray,
    tmin: np.ndarray,
    tmax: np.ndarray,
    off: np.ndarray,
    ws: WrenchSet,
    status: np.ndarray,
    block_elems: int = 2_000_000,
) -> None:
    """Facet test for a wrench set known only by its ``support``: normals from the kernel,
    supports in NumPy, in blocks of poses bounding the memory."""
    N, m, n = W.shape
    C = _binom(n, m - 1)
    step = max(1, block_elems // (C * m))
    for s in range(0, N, step):
        e = min(N, s + step)
        normals, hz, valid = facet_normals(W[s:e], tension_bounds=(tmin, tmax))
        o = np.broadcast_to(off[s:e] if off.shape[0] > 1 else off, (e - s, m))
        lin = np.einsum("kcm,km->kc", normals, o)
        labs = np.einsum("kcm,km->kc", np.abs(normals), np.abs(o))
        sup_m = np.asarray(ws.support(-normals))
        sup_p = np.asarray(ws.support(normals))
        req_p = sup_m - lin
        req_m = sup_p + lin
        finite_sum = np.abs(np.where(np.isfinite(hz), hz, 0.0)).sum(-1)
        # as in the kernel, with the round-off of n·o (n known to ZERO_TOL)
        tol = SLACK * (finite_sum + labs + np.abs(sup_m) + np.abs(sup_p) + 1e-300)
        tol += ZERO_TOL * np.linalg.norm(o, axis=1)[:, None]
        with np.errstate(invalid="ignore"):
            bad = ((req_p > hz[..., 0] + tol) | (req_m > hz[..., 1] + tol)) & valid
        # rank W = m iff some valid normal has a column off its hyperplane, i.e. h_Z(n) + h_Z(−n) > 0,
        # and to within round-off iff σ_min > FULL_TOL σ_max (the kernel's test, in other terms)
        full = ((hz[..., 0] + hz[..., 1] > 0) & valid).any(axis=1)
        sv = np.linalg.svd(W[s:e][full], compute_uv=False)
        full[full] = sv[:, -1] > FULL_TOL * sv[:, 0]
        status[s:e] = np.where(bad.any(axis=1), _OUT, np.where(full, _IN, _FLAT))


def static_equilibrium(
    W: npt.ArrayLike,
    wrench: npt.ArrayLike,
    *,
    tension_bounds: tuple[npt.ArrayLike, npt.ArrayLike],
    method: str = "auto",
) -> np.ndarray:
    """Static equilibrium: whether tensions ``tmin ≤ τ ≤ tmax`` satisfy ``W[k] τ + wrench[k] = 0``,
    one wrench per pose (the single-wrench case of the wrench-feasible workspace, Rushton
    (2022), §2.1.4), by the hyperplane-shifting test of :func:`wrench_feasible`, with an exact
    LP where ``rank W < m`` (e.g. every pose of a robot with fewer cables than degrees of
    freedom).

    Parameters
    ----------
    W : array_like, shape (N, m, n) or (m, n)
        Structure matrices.
    wrench : array_like, shape (N, m) or (m,)
        External wrench [N, N m].
    tension_bounds : (tmin, tmax)
        Tension bounds [N], each a number or ``(n,)``; ``tmax`` may be ``inf``.

    Returns
    -------
    ndarray of bool, shape (N,)

    Raises
    ------
    TautError
        As :func:`wrench_feasible`.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §2.1.4, Eq. 2.11. (docs/references.bib: rushton2022)

    Examples
    --------
    Two cables at 45° hold a 9.81 N weight with 6.94 N each (``9.81 / √2``):

    >>> W = np.array([[-1.0, 1.0], [1.0, 1.0]]) / np.sqrt(2)
    >>> static_equilibrium(W, [0.0, -9.81], tension_bounds=(0.0, 7.0))
    array([ True])
    >>> static_equilibrium(W, [0.0, -9.81], tension_bounds=(0.0, 6.9))
    array([False])
    """
    W = _as_W(W)
    m = W.shape[1]
    return wrench_feasible(W, SingleWrench(np.zeros(m)), tension_bounds=tension_bounds, wrench=wrench, method=method)
