"""Hyperplane shifting over interval matrices: is a wrench set inside the available wrench
set of *every* structure matrix of an interval matrix, or outside it for every one?

For one matrix ``W`` (``m × n``) and tension bounds ``τ_min ≤ τ ≤ τ_max``, the available
wrench set is the zonotope ``Z = {W τ}``; a closed convex set ``A`` lies in a
full-dimensional ``Z`` iff ``h_A(±n) ≤ h_Z(±n)`` for the normal ``n`` of every ``m − 1``
independent columns, with ``h_Z(n) = Σ_j max(n·w_j τ_min,j, n·w_j τ_max,j)`` (hyperplane
shifting: Bouchard, Gosselin & Moore 2010; Gouttefarde & Gosselin 2006).  Any direction
gives a valid necessary condition.  Gouttefarde, Daney & Merlet (2011) turn such pointwise
conditions into two sufficient conditions over a box of poses, which this module evaluates
with outward-rounded interval arithmetic, given an interval matrix ``[W]`` that encloses the
structure matrices of the box:

* **inside** (every ``W ∈ [W]`` holds ``A``): ``rank W = m`` is proven (some normal ``n`` of
  ``m − 1`` columns has ``n·w_j`` of one strict sign for a further column ``j``), and every
  inequality holds over the whole enclosure;
* **outside** (no ``W ∈ [W]`` holds ``A``): one inequality fails over the whole enclosure, by
  more than the relative slack :data:`OUTSIDE_RTOL` (the point test of
  :mod:`taut.statics` accepts violations within its own slack of ``1e-9``).

The normals are not divided out of a pivoting elimination (an interval pivot straddling 0
would give nothing) but written as the signed ``(m − 1)``-minors of the chosen columns:
``n·w = det[w_c1 … w_c(m−1) w]``, expanded along the columns so that every minor of a
prefix of the columns is shared by the combinations that extend it (a lexicographic walk,
``2^m`` minors per level).  ``n·w_c`` is 0 for a chosen column, so those terms are dropped
exactly.  The wrench-closure variant asks, for every combination, a column strictly on each
side of the hyperplane (inside), or a proven nonzero normal with every column on one side
(outside).

The required set ``A = −(o + S)`` is the external wrench ``o`` (an interval vector per
box: it may depend on the orientation) shifted by a box ``S = c + [−r, r]`` (a single
wrench: ``r = 0``) or the convex hull of vertices ``x_k``, so that
``h_A(n) = −n·o + h_S(−n)`` with ``h_S(v) = v·c + Σ_k |v_k| r_k`` or ``max_k v·x_k``.

References
----------
.. [1] M. Gouttefarde, D. Daney, J.-P. Merlet, "Interval-analysis-based determination of the
   wrench-feasible workspace of parallel cable-driven robots", IEEE Transactions on Robotics
   27(1), 2011, §III–IV. (docs/references.bib: gouttefarde2011)
.. [2] S. Bouchard, C. Gosselin, B. Moore, "On the ability of a cable-driven robot to generate a
   prescribed set of wrenches", Journal of Mechanisms and Robotics 2(1), 2010.
   (docs/references.bib: bouchard2010)
.. [3] M. Gouttefarde, C. M. Gosselin, "Analysis of the wrench-closure workspace of planar
   parallel cable-driven mechanisms", IEEE Transactions on Robotics 22(3), 2006.
   (docs/references.bib: gouttefarde2006)
"""

from __future__ import annotations

import itertools

import numpy as np
import numpy.typing as npt
from numba import njit

from taut.errors import ArgumentError
from taut.interval._kernels import INF, add, mul, neg, sub, up

__all__ = ["INSIDE", "OUTSIDE", "OUTSIDE_RTOL", "UNDECIDED", "separating_directions", "zonotope_verdicts"]

#: Verdicts of :func:`zonotope_verdicts`.
INSIDE, OUTSIDE, UNDECIDED = 1, -1, 0
#: An inequality counts as failed over a box when its lower bound exceeds this fraction of
#: the magnitude of its terms: far above the point test's slack (1e-9), so that no pose of an
#: "outside" box is accepted by it.
OUTSIDE_RTOL = 1e-7

_FEASIBLE, _CLOSURE = 0, 1


@njit(cache=True, fastmath=False)
def _iabs(lo: float, hi: float) -> tuple[float, float]:
    if lo >= 0.0:
        return lo, hi
    if hi <= 0.0:
        return -hi, -lo
    return 0.0, max(-lo, hi)


@njit(cache=True, fastmath=False)
def _support_term(dl: float, dh: float, t0: float, t1: float) -> tuple[float, float]:
    """``max(d τ_min, d τ_max)`` over ``d ∈ [dl, dh]``: increasing in ``d`` (``0 ≤ τ_min ≤ τ_max``)."""
    lo = mul(dl, dl, t0, t0)[0] if dl <= 0.0 else (mul(dl, dl, t1, t1)[0] if t1 < INF else INF)
    if dh <= 0.0:
        hi = mul(dh, dh, t0, t0)[1]
    elif t1 < INF:
        hi = mul(dh, dh, t1, t1)[1]
    else:
        hi = INF
    return lo, hi


# A "triple" is one quantity over a box as a flat array: its enclosure at the box's centre
# (lo, hi), over the whole box (lo, hi), and its gradient over the box (lo, hi per variable).
# Products and sums follow the product rule, so that the centred (mean-value) form
# f(c) + ∇f(box)·(box − c) of every minor is available besides its natural enclosure.


@njit(cache=True, fastmath=False)
def _tmul(x: np.ndarray, y: np.ndarray, out: np.ndarray) -> None:
    out[0], out[1] = mul(x[0], x[1], y[0], y[1])
    out[2], out[3] = mul(x[2], x[3], y[2], y[3])
    for i in range(4, out.size, 2):
        al, ah = mul(x[i], x[i + 1], y[2], y[3])
        bl, bh = mul(x[2], x[3], y[i], y[i + 1])
        out[i], out[i + 1] = add(al, ah, bl, bh)


@njit(cache=True, fastmath=False)
def _tacc(out: np.ndarray, x: np.ndarray, negate: bool) -> None:
    """``out += x`` (or ``−x``)."""
    for i in range(0, out.size, 2):
        lo, hi = (-x[i + 1], -x[i]) if negate else (x[i], x[i + 1])
        out[i], out[i + 1] = add(out[i], out[i + 1], lo, hi)


@njit(cache=True, fastmath=False)
def _enclose(x: np.ndarray, half: np.ndarray) -> tuple[float, float]:
    """The centred form over the box of half-widths ``half``, met with the natural enclosure."""
    lo, hi = x[0], x[1]
    for k in range(half.size):
        tl, th = mul(x[4 + 2 * k], x[5 + 2 * k], -half[k], half[k])
        lo, hi = add(lo, hi, tl, th)
    return max(lo, x[2]), min(hi, x[3])


@njit(cache=True, fastmath=False)
def _verdicts(
    Wt: np.ndarray,
    half: np.ndarray,
    tmin: np.ndarray,
    tmax: np.ndarray,
    olo: np.ndarray,
    ohi: np.ndarray,
    centre: np.ndarray,
    radius: np.ndarray,
    vertices: np.ndarray,
    combos: np.ndarray,
    changed: np.ndarray,
    kind: int,
    out: np.ndarray,
) -> None:
    B, m, n, L = Wt.shape
    full = (1 << m) - 1
    size = 1 << m
    D = np.zeros((m, size, L))
    term = np.empty(L)
    normal = np.zeros((m, L))
    dj = np.empty(L)
    nlo = np.empty(m)
    nhi = np.empty(m)
    dlo = np.empty(n)
    dhi = np.empty(n)
    chosen = np.zeros(n, np.bool_)
    popcount = np.zeros(size, np.int64)
    for mask in range(size):
        x = mask
        while x:
            popcount[mask] += x & 1
            x >>= 1
    K = vertices.shape[0]
    for b in range(B):
        h = half[b]
        inside, outside, ranked = True, False, False
        for c in range(combos.shape[0]):
            # minors of the rows in each mask over the first r + 1 chosen columns, from the
            # level of the first column that changed
            for r in range(changed[c], m - 1):
                col = combos[c, r]
                for mask in range(1, size):
                    if popcount[mask] != r + 1:
                        continue
                    if r == 0:
                        row = 0
                        while not (mask >> row) & 1:
                            row += 1
                        D[0, mask, :] = Wt[b, row, col, :]
                        continue
                    D[r, mask, :] = 0.0
                    p = 0
                    for row in range(m):
                        if not (mask >> row) & 1:
                            continue
                        _tmul(Wt[b, row, col], D[r - 1, mask ^ (1 << row)], term)
                        _tacc(D[r, mask], term, (p + r) % 2 == 1)
                        p += 1
            nonzero = False
            for k in range(m):
                normal[k, :] = 0.0
                _tacc(normal[k], D[m - 2, full ^ (1 << k)], (k + m - 1) % 2 == 1)
                nlo[k], nhi[k] = _enclose(normal[k], h)
                nonzero = nonzero or nlo[k] > 0.0 or nhi[k] < 0.0
            for j in range(n):
                chosen[j] = False
            for r in range(m - 1):
                chosen[combos[c, r]] = True
            pos, negs, all_pos, all_neg = False, False, True, True
            for j in range(n):
                if chosen[j]:
                    continue
                dj[:] = 0.0
                for k in range(m):
                    _tmul(normal[k], Wt[b, k, j], term)
                    _tacc(dj, term, False)
                sl, sh = _enclose(dj, h)
                dlo[j], dhi[j] = sl, sh
                pos = pos or sl > 0.0
                negs = negs or sh < 0.0
                all_pos = all_pos and sl >= 0.0
                all_neg = all_neg and sh <= 0.0
            ranked = ranked or pos or negs
            if kind == _CLOSURE:
                if not (pos and negs):
                    inside = False
                if nonzero and (all_pos or all_neg):
                    outside = True
                    break
                continue
            for s in (1.0, -1.0):
                # h_A(s n) = −s n·o + h_S(−s n)
                al, ah = 0.0, 0.0
                for k in range(m):
                    tl, th = mul(nlo[k], nhi[k], olo[b, k], ohi[b, k])
                    al, ah = add(al, ah, tl, th)
                if s > 0.0:
                    al, ah = neg(al, ah)
                if K == 0:
                    for k in range(m):
                        vl, vh = nlo[k], nhi[k]
                        if s > 0.0:
                            vl, vh = neg(vl, vh)
                        tl, th = mul(vl, vh, centre[k], centre[k])
                        al, ah = add(al, ah, tl, th)
                        if radius[k] > 0.0:
                            xl, xh = _iabs(vl, vh)
                            tl, th = mul(xl, xh, radius[k], radius[k])
                            al, ah = add(al, ah, tl, th)
                else:
                    ml, mh = -INF, -INF
                    for v in range(K):
                        sl, sh = 0.0, 0.0
                        for k in range(m):
                            tl, th = mul(nlo[k], nhi[k], vertices[v, k], vertices[v, k])
                            sl, sh = add(sl, sh, tl, th)
                        if s > 0.0:
                            sl, sh = neg(sl, sh)
                        ml, mh = max(ml, sl), max(mh, sh)
                    al, ah = add(al, ah, ml, mh)
                zl, zh = 0.0, 0.0
                for j in range(n):
                    if chosen[j]:
                        continue
                    if s > 0.0:
                        tl, th = _support_term(dlo[j], dhi[j], tmin[j], tmax[j])
                    else:
                        tl, th = _support_term(-dhi[j], -dlo[j], tmin[j], tmax[j])
                    zl, zh = add(zl, zh, tl, th)
                gl, gh = sub(al, ah, zl, zh)
                if gh > 0.0:
                    inside = False
                scale = max(abs(al), abs(ah)) + max(abs(zl), abs(zh))
                if gl > up(OUTSIDE_RTOL * scale) and scale < INF:
                    outside = True
                    break
            if outside:
                break
        if outside:
            out[b] = OUTSIDE
        elif inside and ranked:
            out[b] = INSIDE
        else:
            out[b] = UNDECIDED


@njit(cache=True, fastmath=False)
def _null_vector(A: np.ndarray, out: np.ndarray) -> bool:
    """The unit normal of the ``m − 1`` rows of ``A`` (reduced row echelon form with partial
    pivoting); False when they are dependent to within 1e-12 of their largest entry."""
    k, m = A.shape
    scale = 0.0
    for i in range(k):
        for j in range(m):
            scale = max(scale, abs(A[i, j]))
    if scale == 0.0:
        return False
    pivots = np.empty(k, dtype=np.int64)
    row = 0
    for col in range(m):
        if row == k:
            break
        best, value = row, abs(A[row, col])
        for i in range(row + 1, k):
            if abs(A[i, col]) > value:
                best, value = i, abs(A[i, col])
        if value <= 1e-12 * scale:
            continue
        for j in range(m):
            A[row, j], A[best, j] = A[best, j], A[row, j]
        p = A[row, col]
        for j in range(m):
            A[row, j] /= p
        for i in range(k):
            if i != row and A[i, col] != 0.0:
                f = A[i, col]
                for j in range(m):
                    A[i, j] -= f * A[row, j]
        pivots[row] = col
        row += 1
    if row < k:
        return False
    free = 0
    for i in range(k):
        if pivots[i] != free:
            break
        free += 1
    norm = 1.0
    out[free] = 1.0
    for j in range(m):
        if j != free:
            out[j] = 0.0
    for i in range(k):
        out[pivots[i]] = -A[i, free]
        norm += A[i, free] * A[i, free]
    norm = np.sqrt(norm)
    for j in range(m):
        out[j] /= norm
    return True


@njit(cache=True, fastmath=False)
def _separations(
    W: np.ndarray,
    tmin: np.ndarray,
    tmax: np.ndarray,
    o: np.ndarray,
    c: np.ndarray,
    r: np.ndarray,
    V: np.ndarray,
    combos: np.ndarray,
    directions: np.ndarray,
    gaps: np.ndarray,
) -> None:
    B, m, n = W.shape
    k = m - 1
    A = np.empty((k, m))
    normal = np.empty(m)
    along = np.empty(n)
    for b in range(B):
        best = -np.inf
        for ci in range(combos.shape[0]):
            for i in range(k):
                for j in range(m):
                    A[i, j] = W[b, j, combos[ci, i]]
            if not _null_vector(A, normal):
                continue
            for i in range(n):
                total = 0.0
                for j in range(m):
                    total += normal[j] * W[b, j, i]
                along[i] = total
            for sign in (1.0, -1.0):
                # h_Z(s n) and the largest s n · (−(o + x)) over the required set
                support = 0.0
                for i in range(n):
                    d = sign * along[i]
                    support += d * tmax[i] if d > 0.0 else d * tmin[i]
                need = 0.0
                for j in range(m):
                    need -= sign * normal[j] * o[b, j]
                if V.shape[0] > 0:
                    top = -np.inf
                    for v in range(V.shape[0]):
                        total = 0.0
                        for j in range(m):
                            total -= sign * normal[j] * V[v, j]
                        top = max(top, total)
                    need += top
                else:
                    for j in range(m):
                        need += -sign * normal[j] * c[j] + abs(normal[j]) * r[j]
                if need - support > best:
                    best = need - support
                    for j in range(m):
                        directions[b, j] = sign * normal[j] + 0.0  # no −0.0
        gaps[b] = best


def _combinations(n: int, k: int) -> tuple[np.ndarray, np.ndarray]:
    """The ``k``-combinations of ``range(n)`` in lexicographic order and, for each, the first
    position that differs from the previous one (0 for the first)."""
    combos = np.array(list(itertools.combinations(range(n), k)), dtype=np.int64).reshape(-1, k)
    changed = np.zeros(len(combos), dtype=np.int64)
    if len(combos) > 1:
        diff = combos[1:] != combos[:-1]
        changed[1:] = np.argmax(diff, axis=1)
    return combos, changed


def _bounds(tension_bounds: tuple[npt.ArrayLike, npt.ArrayLike], n: int) -> tuple[np.ndarray, np.ndarray]:
    """``τ_min``, ``τ_max`` of ``n`` cables as contiguous arrays, or an :class:`ArgumentError`."""
    tmin = np.ascontiguousarray(np.broadcast_to(np.asarray(tension_bounds[0], float), (n,)))
    tmax = np.ascontiguousarray(np.broadcast_to(np.asarray(tension_bounds[1], float), (n,)))
    if not (np.all(np.isfinite(tmin)) and np.all(tmin >= 0) and not np.isnan(tmax).any() and np.all(tmax >= tmin)):
        raise ArgumentError("tension bounds must be 0 ≤ τ_min ≤ τ_max (τ_max may be inf), τ_min finite")
    return tmin, tmax


def _required_set(
    m: int, centre: npt.ArrayLike | None, radius: npt.ArrayLike | None, vertices: npt.ArrayLike | None
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The box ``centre ± radius`` and the polytope's ``vertices`` (``(0, m)`` when none) of
    ``m`` components, or an :class:`ArgumentError`."""
    c = np.zeros(m) if centre is None else np.asarray(centre, float)
    r = np.zeros(m) if radius is None else np.asarray(radius, float)
    if c.shape != (m,) or r.shape != (m,) or not (np.all(np.isfinite(c)) and np.all(np.isfinite(r)) and np.all(r >= 0)):
        raise ArgumentError(f"centre and radius must be finite of shape ({m},), the radius ≥ 0")
    V = np.zeros((0, m)) if vertices is None else np.ascontiguousarray(vertices, dtype=float)
    if V.ndim != 2 or V.shape[1] != m or not np.all(np.isfinite(V)):
        raise ArgumentError(f"vertices must be finite of shape (K, {m})")
    return c, r, V


def zonotope_verdicts(
    W_lo: npt.ArrayLike,
    W_hi: npt.ArrayLike,
    *,
    tension_bounds: tuple[npt.ArrayLike, npt.ArrayLike],
    wrench_lo: npt.ArrayLike | None = None,
    wrench_hi: npt.ArrayLike | None = None,
    centre: npt.ArrayLike | None = None,
    radius: npt.ArrayLike | None = None,
    vertices: npt.ArrayLike | None = None,
    closure: bool = False,
    mean_value: tuple[npt.ArrayLike, npt.ArrayLike, npt.ArrayLike, npt.ArrayLike, npt.ArrayLike] | None = None,
) -> np.ndarray:
    """For each interval matrix ``[W]`` of a batch: is the required wrench set balanced within
    the tension bounds by every matrix of ``[W]`` (:data:`INSIDE`), by none
    (:data:`OUTSIDE`), or is that not decided (:data:`UNDECIDED`)?

    The required wrenches are ``o + x`` for the external wrench ``o ∈ [wrench_lo, wrench_hi]``
    and ``x`` in the box ``centre ± radius`` or the convex hull of ``vertices``; the cables
    must give ``W τ = −(o + x)``.  With ``closure``, the question is wrench closure instead
    (the columns positively span the wrench space); the bounds and wrenches are then unused.

    Parameters
    ----------
    W_lo, W_hi : array_like, shape (B, m, n)
        Lower and upper ends of the interval matrices, ``1 < m ≤ n``.
    tension_bounds : (array_like, array_like)
        ``τ_min`` (≥ 0) and ``τ_max`` (≥ ``τ_min``, may be ``inf``), shape (n,) each.
    wrench_lo, wrench_hi : array_like, shape (B, m) or (m,), optional
        The external wrench's enclosure (default 0).
    centre, radius : array_like, shape (m,), optional
        The box of required wrenches relative to the external one (default the point 0).
    vertices : array_like, shape (K, m), optional
        Instead of a box: the vertices of a polytope of required wrenches.
    closure : bool, default False
        Decide wrench closure instead of feasibility.
    mean_value : (Wc_lo, Wc_hi, G_lo, G_hi, half), optional
        When the matrices are functions of ``q`` variables over boxes of half-widths
        ``half`` ``(B, q)``: ``[Wc_lo, Wc_hi]`` ``(B, m, n)`` encloses them at the boxes'
        centres and ``[G_lo, G_hi]`` ``(B, m, n, q)`` their derivatives over the boxes.
        Every minor is then also enclosed by its centred form ``f(c) + [∇f]·[−half, half]``
        (product rule throughout) and met with its natural enclosure: far tighter on
        narrow boxes, where the natural one loses the correlation of the entries.

    Returns
    -------
    ndarray of int8, shape (B,)
        :data:`INSIDE` (1), :data:`OUTSIDE` (−1) or :data:`UNDECIDED` (0) per matrix.

    Raises
    ------
    ArgumentError
        Arrays of inconsistent shapes, ``m < 2`` or ``n < m``, bounds that are not
        ``0 ≤ τ_min ≤ τ_max``, or ends that are not ordered.

    References
    ----------
    .. [1] M. Gouttefarde, D. Daney, J.-P. Merlet, "Interval-analysis-based determination of
       the wrench-feasible workspace of parallel cable-driven robots", IEEE Transactions on
       Robotics 27(1), 2011, §III–IV. (docs/references.bib: gouttefarde2011)
    .. [2] S. Bouchard, C. Gosselin, B. Moore, "On the ability of a cable-driven robot to
       generate a prescribed set of wrenches", Journal of Mechanisms and Robotics 2(1), 2010.
       (docs/references.bib: bouchard2010)

    Examples
    --------
    Three planar cables pulling at 0°, 120° and 240°, each within [1, 10] N, and a wrench of
    (0, −2) N to balance: a matrix known to ±0.01 still holds it, one known to ±0.5 is
    undecided, and a required force of 30 N is beyond every matrix of the first:

    >>> import numpy as np
    >>> a = np.radians([0.0, 120.0, 240.0])
    >>> W = np.array([np.cos(a), np.sin(a)])[None]
    >>> bounds = (np.ones(3), np.full(3, 10.0))
    >>> zonotope_verdicts(W - 0.01, W + 0.01, tension_bounds=bounds, wrench_lo=[0.0, -2.0], wrench_hi=[0.0, -2.0])
    array([1], dtype=int8)
    >>> zonotope_verdicts(W - 0.5, W + 0.5, tension_bounds=bounds, wrench_lo=[0.0, -2.0], wrench_hi=[0.0, -2.0])
    array([0], dtype=int8)
    >>> zonotope_verdicts(W - 0.01, W + 0.01, tension_bounds=bounds, wrench_lo=[0.0, -30.0], wrench_hi=[0.0, -30.0])
    array([-1], dtype=int8)
    """
    try:
        Wlo = np.ascontiguousarray(W_lo, dtype=float)
        Whi = np.ascontiguousarray(W_hi, dtype=float)
    except (TypeError, ValueError):
        raise ArgumentError("the interval matrices must be arrays of numbers") from None
    if Wlo.ndim != 3 or Wlo.shape != Whi.shape:
        raise ArgumentError(f"W_lo and W_hi must both have shape (B, m, n), got {Wlo.shape} and {Whi.shape}")
    B, m, n = Wlo.shape
    if not 1 < m <= n:
        raise ArgumentError(f"the matrices need 2 ≤ m ≤ n (rows ≤ columns), got m = {m}, n = {n}")
    if np.isnan(Wlo).any() or np.isnan(Whi).any() or np.any(Wlo > Whi):
        raise ArgumentError("the interval matrices need lower ends ≤ upper ends, without NaN")
    tmin, tmax = _bounds(tension_bounds, n)

    def per_box(x: npt.ArrayLike | None, name: str) -> np.ndarray:
        a = np.zeros(m) if x is None else np.asarray(x, float)
        if a.shape not in ((m,), (B, m)) or not np.all(np.isfinite(a)):
            raise ArgumentError(f"{name} must be finite with shape ({m},) or ({B}, {m})")
        return np.ascontiguousarray(np.broadcast_to(a, (B, m)))

    olo, ohi = per_box(wrench_lo, "wrench_lo"), per_box(wrench_hi, "wrench_hi")
    if np.any(olo > ohi):
        raise ArgumentError("wrench_lo must be ≤ wrench_hi")
    c, r, V = _required_set(m, centre, radius, vertices)
    if mean_value is None:
        Wt = np.stack([Wlo, Whi, Wlo, Whi], axis=-1)
        half = np.zeros((B, 0))
    else:
        try:
            c_lo, c_hi, g_lo, g_hi, half = (np.asarray(x, dtype=float) for x in mean_value)
        except (TypeError, ValueError):
            raise ArgumentError("mean_value must be five arrays of numbers (Wc_lo, Wc_hi, G_lo, G_hi, half)") from None
        q = half.shape[-1] if half.ndim == 2 else -1
        if c_lo.shape != (B, m, n) or c_hi.shape != (B, m, n) or g_lo.shape != (B, m, n, q) or g_hi.shape != g_lo.shape:
            raise ArgumentError(
                f"mean_value: expected shapes ({B}, {m}, {n}) twice, ({B}, {m}, {n}, q) twice and ({B}, q), "
                f"got {c_lo.shape}, {c_hi.shape}, {g_lo.shape}, {g_hi.shape}, {half.shape}"
            )
        if np.isnan(g_lo).any() or np.isnan(g_hi).any() or not np.all(np.isfinite(half)) or np.any(half < 0):
            raise ArgumentError("mean_value: gradients without NaN and finite half-widths ≥ 0")
        grads = np.stack([g_lo, g_hi], axis=-1).reshape(B, m, n, 2 * q)
        Wt = np.concatenate([np.stack([c_lo, c_hi, Wlo, Whi], axis=-1), grads], axis=-1)
    Wt = np.ascontiguousarray(Wt)
    combos, changed = _combinations(n, m - 1)
    out = np.empty(B, dtype=np.int8)
    _verdicts(
        Wt,
        np.ascontiguousarray(half),
        tmin,
        tmax,
        olo,
        ohi,
        c,
        r,
        V,
        combos,
        changed,
        _CLOSURE if closure else _FEASIBLE,
        out,
    )
    return out


def separating_directions(
    W: npt.ArrayLike,
    *,
    tension_bounds: tuple[npt.ArrayLike, npt.ArrayLike],
    wrench: npt.ArrayLike | None = None,
    centre: npt.ArrayLike | None = None,
    radius: npt.ArrayLike | None = None,
    vertices: npt.ArrayLike | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """For each structure matrix of a batch, the facet normal of its available wrench set
    that the required set crosses farthest: the unit direction ``n`` of the largest
    ``gap = max_{a ∈ A} n·a − h_Z(n)`` over the normals ``±n`` of every ``m − 1``
    independent columns (hyperplane shifting, in floating point).

    A positive gap means the required set ``A = −(o + S)`` is not balanced by this matrix:
    some required wrench lies beyond the facet (Bouchard, Gosselin & Moore 2010).  A fixed
    direction is a valid separation for every matrix near this one whose support stays below
    the required value, which an interval evaluation can prove over a box of poses.

    Parameters
    ----------
    W : array_like, shape (B, m, n)
        Structure matrices, ``1 < m ≤ n``.
    tension_bounds : (array_like, array_like)
        ``τ_min`` (≥ 0) and ``τ_max`` (≥ ``τ_min``, may be ``inf``), shape (n,) each.
    wrench : array_like, shape (B, m) or (m,), optional
        The external wrench ``o`` (default 0).
    centre, radius : array_like, shape (m,), optional
        The box ``S`` of required wrenches relative to the external one (default the point 0).
    vertices : array_like, shape (K, m), optional
        Instead of a box: the vertices of a polytope ``S``.

    Returns
    -------
    directions : ndarray, shape (B, m)
        Unit directions (zeros where no ``m − 1`` columns are independent).
    gaps : ndarray, shape (B,)
        The largest gap along them (``-inf`` where no ``m − 1`` columns are independent):
        positive where the required set is not balanced.

    Raises
    ------
    ArgumentError
        Arrays of inconsistent shapes, ``m < 2`` or ``n < m``, or bounds that are not
        ``0 ≤ τ_min ≤ τ_max``.

    References
    ----------
    .. [1] S. Bouchard, C. Gosselin, B. Moore, "On the ability of a cable-driven robot to
       generate a prescribed set of wrenches", Journal of Mechanisms and Robotics 2(1), 2010.
       (docs/references.bib: bouchard2010)

    Examples
    --------
    Three planar cables at 0°, 120° and 240°, each within [1, 10] N: a weight of 2 N is
    balanced (negative gap), one of 30 N is not, and the facet it crosses faces down:

    >>> import numpy as np
    >>> a = np.radians([0.0, 120.0, 240.0])
    >>> W = np.array([np.cos(a), np.sin(a)])[None]
    >>> bounds = (np.ones(3), np.full(3, 10.0))
    >>> _, gap = separating_directions(W, tension_bounds=bounds, wrench=[0.0, -2.0])
    >>> bool(gap[0] < 0)
    True
    >>> n, gap = separating_directions(W, tension_bounds=bounds, wrench=[0.0, -30.0])
    >>> bool(gap[0] > 0), n.round(3)
    (True, array([[0., 1.]]))
    """
    try:
        Wf = np.ascontiguousarray(W, dtype=float)
    except (TypeError, ValueError):
        raise ArgumentError("the structure matrices must be an array of numbers") from None
    if Wf.ndim != 3 or not np.all(np.isfinite(Wf)):
        raise ArgumentError(f"W must be finite with shape (B, m, n), got shape {Wf.shape}")
    B, m, n = Wf.shape
    if not 1 < m <= n:
        raise ArgumentError(f"the matrices need 2 ≤ m ≤ n (rows ≤ columns), got m = {m}, n = {n}")
    tmin, tmax = _bounds(tension_bounds, n)
    o = np.zeros(m) if wrench is None else np.asarray(wrench, float)
    if o.shape not in ((m,), (B, m)) or not np.all(np.isfinite(o)):
        raise ArgumentError(f"wrench must be finite with shape ({m},) or ({B}, {m})")
    c, r, V = _required_set(m, centre, radius, vertices)
    combos, _ = _combinations(n, m - 1)
    directions = np.zeros((B, m))
    gaps = np.empty(B)
    _separations(Wf, tmin, tmax, np.ascontiguousarray(np.broadcast_to(o, (B, m))), c, r, V, combos, directions, gaps)
    return directions, gaps
