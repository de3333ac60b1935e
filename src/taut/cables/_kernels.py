"""Compiled static inverse kinematics of robots with sagging cables, one pose at a time.

:func:`sagging_steps` runs the iteration of :mod:`taut.cables._inverse` for each pose (the
tension distribution with the catenaries' tangents, each cable's catenary of the
distributed tension, Anderson's acceleration of the tangent angles) with the closed forms of
Pott et al. (2009) and Pott (2014) as the distribution, in scalar arithmetic: the catenary
functions are those of :mod:`taut.cables._catenary` (Irvine 1981, §1.3) written for one
cable, and the pseudo-inverse of the structure matrix comes from a Cholesky factorization of
``W Wᵀ`` instead of a singular value decomposition (the same tensions where ``W`` is well
conditioned).  :func:`tension_catenaries` solves the
catenaries of given platform-end tensions with the same scalar functions.  A pose this path
does not settle the way the vectorised iteration would (a
rank-deficient or ill-conditioned ``W``, a distribution that gives up, tension bounds that
cross, a cable too slack for its catenary or hanging vertically) is handed back
(:data:`HANDED_BACK`) to the vectorised iteration, which decides it.

References
----------
.. [1] H. M. Irvine, "Cable Structures", MIT Press, 1981, Ch. 1, §1.3. (docs/references.bib: irvine1981)
.. [2] A. Pott, T. Bruckmann, L. Mikelsons, "Closed-form force distribution for parallel wire
   robots", Computational Kinematics, Springer, 2009. (docs/references.bib: pott2009)
.. [3] H. F. Walker, P. Ni, "Anderson acceleration for fixed-point iterations", SIAM Journal on
   Numerical Analysis 49(4), 2011. (docs/references.bib: walker2011)
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from taut.cables._catenary import MAX_NEWTON, NEWTON_RTOL

# The kernels take numpy's error model: a division by zero gives inf or NaN, which the
# iterations flag, as the vectorised kernels do under np.errstate.

__all__ = ["CONVERGED", "HANDED_BACK", "NOT_CONVERGED", "sagging_steps", "tension_catenaries"]

#: Status of a pose: the iteration converged.
CONVERGED = 0
#: Status of a pose: handed back to the vectorised iteration.
HANDED_BACK = 1
#: Status of a pose: no convergence within the steps allowed.
NOT_CONVERGED = 2
#: Smallest ratio of a Cholesky pivot of ``W Wᵀ`` to its largest diagonal entry: below it the
#: structure matrix is too ill-conditioned for the normal equations to give the pseudo-inverse's
#: tensions, and the pose is handed back.
PIVOT_RTOL = 1e-12


@njit(cache=True, nogil=True, error_model="numpy")
def _log1p_ratio(q: float) -> float:
    if abs(q) < 1e-8:
        return 1.0 - q / 2
    return math.log1p(q) / q


@njit(cache=True, nogil=True, error_model="numpy")
def _up(b: float) -> float:
    r = math.sqrt(1.0 + b * b)
    return b + r if b >= 0 else 1.0 / (r - b)


@njit(cache=True, nogil=True, error_model="numpy")
def _ends(H: float, V: float, L0: float, w: float, EA: float) -> tuple[float, float, float, float, float, float, float]:
    """``span, rise, xH, xV (= zH), xL, zV, zL``: :func:`taut.cables._catenary.ends` of one cable."""
    flex = 0.0 if math.isinf(EA) else 1.0 / EA
    V1 = V + w * L0
    T0, T1 = math.hypot(H, V), math.hypot(H, V1)
    a, b = V1 / H, V / H
    if a + b < 0:
        p, r = -b, -a
    else:
        p, r = a, b
    K = (1.0 + (p + r) / (math.sqrt(1.0 + p * p) + math.sqrt(1.0 + r * r))) / _up(r)
    A = (L0 / H) * K * _log1p_ratio(w * L0 / H * K)
    if V * V1 > 0:
        B = H * H * L0 * (V1 + V) / (T0 * T1 * (V1 * T0 + V * T1))
    elif w > 0:
        B = (V1 / T1 - V / T0) / w
    else:
        B = L0 * H * H / T0**3
    span = H * (L0 * flex + A)
    rise = L0 * (V + V1) * (0.5 * flex + 1.0 / (T0 + T1))
    C = -H * L0 * (V1 + V) / ((T0 + T1) * T0 * T1)
    return span, rise, L0 * flex + A - B, C, H * (flex + 1.0 / T1), L0 * flex + B, V1 * (flex + 1.0 / T1)


@njit(cache=True, nogil=True, error_model="numpy")
def _solve_inverse(span: float, rise: float, H: float, w: float, EA: float) -> tuple[float, float]:
    """``(L0, V)``: :func:`taut.cables._catenary.solve_inverse` of one cable."""
    if w > 0:
        a = H / w
        half = span / (2.0 * a)
        width = 2.0 * a * math.sinh(half)
        xm = math.asinh(rise / width)
        L0, V = width * math.cosh(xm), H * math.sinh(xm - half)
    else:
        L0, V = math.hypot(span, rise), H * rise / span
    if math.isinf(EA):
        return L0, V
    L0 = L0 / (1.0 + math.hypot(H, V + w * L0 / 2) / EA)
    scale = math.hypot(span, rise) + L0
    x, z, _, xV, xL, zV, zL = _ends(H, V, L0, w, EA)
    for _ in range(MAX_NEWTON):
        fx, fz = x - span, z - rise
        if math.hypot(fx, fz) <= NEWTON_RTOL * scale:
            break
        det = xV * zL - xL * zV
        dV = -(zL * fx - xL * fz) / det
        dL = -(-zV * fx + xV * fz) / det
        step = 1.0
        for _ in range(30):
            if not L0 + step * dL <= 0:
                break
            step /= 2
        V, L0 = V + step * dV, L0 + step * dL
        x, z, _, xV, xL, zV, zL = _ends(H, V, L0, w, EA)
    return L0, V


@njit(cache=True, nogil=True, error_model="numpy")
def _solve_tension(
    span: float, rise: float, T0: float, w: float, EA: float, phi: float, L0: float
) -> tuple[float, float, float, bool]:
    """``(H, V, L0, ok)``: :func:`taut.cables._catenary.solve_tension` of one cable, from the
    angle ``phi`` of its end force and ``L0``."""
    chord = math.hypot(span, rise)
    ok = False
    for _ in range(MAX_NEWTON):
        H, V = T0 * math.cos(phi), T0 * math.sin(phi)
        x, z, xH, xV, xL, zV, zL = _ends(H, V, L0, w, EA)
        fx, fz = x - span, z - rise
        ok = math.hypot(fx, fz) <= NEWTON_RTOL * (chord + L0)
        if ok:
            break
        a, c = xV * H - xH * V, zV * H - xV * V
        det = a * zL - xL * c
        dphi = min(max(-(zL * fx - xL * fz) / det, -0.5), 0.5)
        dL = -(-c * fx + a * fz) / det
        step = 1.0
        for _ in range(30):
            if not (L0 + step * dL <= 0 or abs(phi + step * dphi) >= math.pi / 2):
                break
            step /= 2
        phi, L0 = phi + step * dphi, L0 + step * dL
    H, V = T0 * math.cos(phi), T0 * math.sin(phi)
    return H, V, L0, ok and H > 0 and math.isfinite(L0)


@njit(cache=True, nogil=True, error_model="numpy")
def _pott(
    W: np.ndarray,
    w: np.ndarray,
    lo: np.ndarray,
    hi: np.ndarray,
    iterations: int,
    rtol: float,
    tau: np.ndarray,
    G: np.ndarray,
) -> bool:
    """The (improved) closed form of :func:`taut.statics._tension._pott` for one pose into
    ``tau``, then clipped into the bounds as :func:`taut.statics.solve_tensions` verifies it;
    False where the vectorised distribution might decide otherwise (see the module docstring)."""
    m, n = W.shape
    free = np.ones(n, dtype=np.bool_)
    fixed = np.zeros(n)
    tm = np.empty(n)
    for j in range(n):
        tm[j] = (lo[j] + hi[j]) / 2 if math.isfinite(hi[j]) else lo[j]
    t0, r, y = np.empty(n), np.empty(m), np.empty(m)
    for _ in range(iterations):
        for j in range(n):
            t0[j] = tm[j] if free[j] else fixed[j]
        for i in range(m):
            acc = w[i]
            for j in range(n):
                acc += W[i, j] * t0[j]
            r[i] = acc
        # G = Wf Wfᵀ of the free columns, factorized in place (lower triangle)
        big = 0.0
        for i in range(m):
            for k in range(i + 1):
                g = 0.0
                for j in range(n):
                    if free[j]:
                        g += W[i, j] * W[k, j]
                G[i, k] = g
            big = max(big, G[i, i])
        for i in range(m):
            d = G[i, i]
            for k in range(i):
                d -= G[i, k] * G[i, k]
            if not d > PIVOT_RTOL * big:
                return False
            G[i, i] = math.sqrt(d)
            for k2 in range(i + 1, m):
                s = G[k2, i]
                for k in range(i):
                    s -= G[k2, k] * G[i, k]
                G[k2, i] = s / G[i, i]
        for i in range(m):
            s = r[i]
            for k in range(i):
                s -= G[i, k] * y[k]
            y[i] = s / G[i, i]
        for i in range(m - 1, -1, -1):
            s = y[i]
            for k in range(i + 1, m):
                s -= G[k, i] * y[k]
            y[i] = s / G[i, i]
        for j in range(n):
            acc = 0.0
            if free[j]:
                for i in range(m):
                    acc += W[i, j] * y[i]
            tau[j] = t0[j] - acc
        worst, at, nfree = -np.inf, -1, 0
        for j in range(n):
            if free[j]:
                nfree += 1
                v = max(lo[j] - tau[j], tau[j] - hi[j])
                if v > worst:
                    worst, at = v, j
        if not _balanced(W, w, tau, rtol):
            return False
        if worst <= rtol * _tension_scale(tau, lo, hi):
            for j in range(n):
                tau[j] = min(max(tau[j], lo[j]), hi[j])
            return _balanced(W, w, tau, rtol)
        if nfree <= m:
            return False
        fixed[at] = lo[at] if tau[at] < lo[at] else hi[at]
        free[at] = False
    return False


@njit(cache=True, nogil=True, error_model="numpy")
def _balanced(W: np.ndarray, w: np.ndarray, tau: np.ndarray, rtol: float) -> bool:
    """``‖W τ + w‖∞ ≤ rtol · max(‖w‖∞, max|W| ‖τ‖∞)`` (:mod:`taut.statics._tension`'s test)."""
    m, n = W.shape
    res, wmax, Wmax, tmax = 0.0, 0.0, 0.0, 0.0
    for j in range(n):
        tmax = max(tmax, abs(tau[j]))
    for i in range(m):
        acc = w[i]
        wmax = max(wmax, abs(w[i]))
        for j in range(n):
            acc += W[i, j] * tau[j]
            Wmax = max(Wmax, abs(W[i, j]))
        res = max(res, abs(acc))
    return res <= rtol * max(Wmax * tmax, wmax)


@njit(cache=True, nogil=True, error_model="numpy")
def _tension_scale(tau: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> float:
    s = 0.0
    for j in range(tau.size):
        s = max(s, abs(tau[j]), lo[j], hi[j] if math.isfinite(hi[j]) else 0.0)
    return s


@njit(cache=True, nogil=True, error_model="numpy")
def _anderson(X: np.ndarray, Gs: np.ndarray, count: int, x: np.ndarray, g: np.ndarray, out: np.ndarray) -> None:
    """:class:`taut.cables._inverse._Anderson`'s step of one pose: ``X, Gs (depth + 1, n)``
    hold the last iterates and their images (``count`` steps before this one)."""
    depth, n = X.shape[0] - 1, X.shape[1]
    for i in range(depth):
        X[i], Gs[i] = X[i + 1], Gs[i + 1]
    X[depth], Gs[depth] = x, g
    dF, dG = np.zeros((depth, n)), np.zeros((depth, n))
    for i in range(depth):
        if i >= depth - count:
            for j in range(n):
                dF[i, j] = (Gs[i + 1, j] - X[i + 1, j]) - (Gs[i, j] - X[i, j])
                dG[i, j] = Gs[i + 1, j] - Gs[i, j]
    A, b = dF @ dF.T, np.empty(depth)
    for i in range(depth):
        acc = 0.0
        for j in range(n):
            acc += dF[i, j] * (Gs[depth, j] - X[depth, j])
        b[i] = acc
    reg = 1e-10 * np.trace(A) + 1e-300
    for i in range(depth):
        A[i, i] += reg
    gamma = np.linalg.solve(A, b)
    for j in range(n):
        acc = g[j]
        for i in range(depth):
            acc -= dG[i, j] * gamma[i]
        out[j] = acc


@njit(cache=True, nogil=True, error_model="numpy")
def sagging_steps(
    arms: np.ndarray,
    straight: np.ndarray,
    ext: np.ndarray,
    lo0: np.ndarray,
    hi0: np.ndarray,
    catenary: np.ndarray,
    vertical: np.ndarray,
    span: np.ndarray,
    rise: np.ndarray,
    level: np.ndarray,
    up: np.ndarray,
    weight: np.ndarray,
    stiffness: np.ndarray,
    chord: np.ndarray,
    moments: int,
    iterations: int,
    depth: int,
    tol: float,
    max_steps: int,
    rtol: float,
    L0: np.ndarray,
    T0: np.ndarray,
    T1: np.ndarray,
    phi: np.ndarray,
    status: np.ndarray,
    steps: np.ndarray,
) -> None:
    """The iteration of :func:`taut.cables.sagging_ik` for ``N`` poses of ``n`` cables in
    ``d`` dimensions: arms ``b_i − p`` and chord directions ``(N, n, d)``, wrench ``(N, m)``,
    bounds, masks and chord data ``(N, n)``, ``level`` the horizontal unit vectors ``(N, n,
    d)`` and ``up (d,)``; ``moments`` the rows of moments (0 point mass, 1 planar, 3 spatial);
    ``iterations`` the closed form's rounds (1, or ``n + 1`` improved).  Writes the unstrained
    lengths, the tensions at both ends, the final tangent angles, the status
    (:data:`CONVERGED`, :data:`HANDED_BACK`, :data:`NOT_CONVERGED`) and the steps taken."""
    N, n, d = arms.shape
    m = d + moments
    W, G, u = np.zeros((m, n)), np.zeros((m, m)), np.zeros((n, d))
    lo, hi, tau, g, delta = np.empty(n), np.empty(n), np.empty(n), np.empty(n), np.empty(n)
    newL, t1, nxt = np.empty(n), np.empty(n), np.empty(n)
    X, Gs = np.zeros((depth + 1, n)), np.zeros((depth + 1, n))
    for k in range(N):
        status[k], steps[k] = NOT_CONVERGED, 0
        delta[:] = 0.0
        X[:], Gs[:] = 0.0, 0.0
        handed = False
        for i in range(n):
            if vertical[k, i]:
                handed = True
            phi[k, i] = math.atan2(rise[k, i], span[k, i]) if catenary[k, i] else 0.0
        if handed:
            status[k] = HANDED_BACK
            continue
        for step in range(1, max_steps + 1):
            steps[k] = step
            for i in range(n):
                for c in range(d):
                    if catenary[k, i]:
                        u[i, c] = math.cos(phi[k, i]) * level[k, i, c] + math.sin(phi[k, i]) * up[c]
                    else:
                        u[i, c] = straight[k, i, c]
                    W[c, i] = u[i, c]
                a = arms[k, i]
                if moments == 1:
                    W[d, i] = a[0] * u[i, 1] - a[1] * u[i, 0]
                elif moments == 3:
                    W[3, i] = a[1] * u[i, 2] - a[2] * u[i, 1]
                    W[4, i] = a[2] * u[i, 0] - a[0] * u[i, 2]
                    W[5, i] = a[0] * u[i, 1] - a[1] * u[i, 0]
                lo[i] = max(lo0[k, i], lo0[k, i] - delta[i])
                hi[i] = min(hi0[k, i], hi0[k, i] - delta[i])
                if lo[i] > hi[i]:
                    handed = True
            if handed or not _pott(W, ext[k], lo, hi, iterations, rtol, tau, G):
                status[k] = HANDED_BACK
                break
            change = 0.0
            for i in range(n):
                if catenary[k, i]:
                    w, ea, sp, rs = weight[k, i], stiffness[k, i], span[k, i], rise[k, i]
                    if step == 1:
                        H = tau[i] * math.cos(phi[k, i])
                        L, V = _solve_inverse(sp, rs, H, w, ea)
                        start = math.atan2(V, H)
                    else:
                        L, start = L0[k, i], phi[k, i]
                    H, V, L, ok = _solve_tension(sp, rs, tau[i], w, ea, start, L)
                    if not ok:
                        handed = True
                        break
                    newL[i], t1[i], g[i] = L, math.hypot(H, V + w * L), math.atan2(V, H)
                else:
                    ea = stiffness[k, i]
                    newL[i] = chord[k, i] / (1.0 + (0.0 if math.isinf(ea) else tau[i] / ea))
                    t1[i], g[i] = tau[i], 0.0
                change = max(change, abs(g[i] - phi[k, i]))
            if handed:
                status[k] = HANDED_BACK
                break
            for i in range(n):
                L0[k, i], T0[k, i], T1[k, i] = newL[i], tau[i], t1[i]
                delta[i] = t1[i] - tau[i]
            if change <= tol:
                status[k] = CONVERGED
                phi[k] = g
                break
            _anderson(X, Gs, step - 1, phi[k].copy(), g, nxt)
            phi[k] = nxt


@njit(cache=True, nogil=True, error_model="numpy")
def tension_catenaries(
    span: np.ndarray,
    rise: np.ndarray,
    T0: np.ndarray,
    w: np.ndarray,
    EA: np.ndarray,
    phi: np.ndarray,
    L0: np.ndarray,
    cold: bool,
    H: np.ndarray,
    V: np.ndarray,
    ok: np.ndarray,
) -> None:
    """The catenaries of platform-end tensions ``T0`` through the chords, flat arrays: the
    end forces into ``H, V``, the unstrained lengths into ``L0`` (in place) and whether Newton
    converged into ``ok``; from the angles ``phi`` of the end forces and ``L0``, or ``cold``
    from the catenary whose horizontal force is the tension's share along the chord."""
    for k in range(span.size):
        start, length = phi[k], L0[k]
        if cold:
            h = T0[k] * span[k] / math.hypot(span[k], rise[k])
            length, v = _solve_inverse(span[k], rise[k], h, w[k], EA[k])
            start = math.atan2(v, h)
        H[k], V[k], L0[k], ok[k] = _solve_tension(span[k], rise[k], T0[k], w[k], EA[k], start, length)
