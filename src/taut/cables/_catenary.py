"""Irvine's elastic catenary: one heavy, elastic cable hanging between two points.

The cable runs in the vertical plane of its chord from the platform end ``B`` (Lagrangian
coordinate ``s = 0``) to the exit point ``A`` (``s = L0``, the unstrained length); ``span``
is the horizontal distance from ``B`` to ``A`` and ``rise`` the height of ``A`` above ``B``
(against gravity).  ``H`` is the horizontal force the cable exerts on the platform, towards
the exit (constant along the cable), and ``V`` the vertical one, upwards: the force on the
platform is ``(H, V)`` and the vertical force along the cable is ``V(s) = V + w s``, so that
the exit holds ``(−H, −(V + w L0))``.  With ``T(s) = √(H² + V(s)²)`` and the strain
``T/EA``, integrating the cable's equilibrium gives Irvine's two equations of the elastic
catenary (Irvine 1981, §1.3, the inclined elastic catenary; Kozak, Zhou & Wang 2006, Eq. 1):

    ``span = H L0/EA + (H/w) [asinh((V + w L0)/H) − asinh(V/H)]``
    ``rise = (V L0 + w L0²/2)/EA + (1/w) [√(H² + (V + w L0)²) − √(H² + V²)]``

Both are written here in forms without cancellation as ``w → 0`` (the bracket of the first
through ``log1p``, the second as ``L0 (V + V1)/(T0 + T1)``), so that the straight elastic
cable, ``(span, rise) = L0 (1/EA + 1/T) (H, V)``, is the limit ``w = 0`` and not a special case.
``EA = inf`` is the inextensible cable.  The forward problem (``L0`` → ``H, V``) is solved by
Newton's method on the two equations with their analytic Jacobian (Irvine's flexibility
matrix, symmetric), from the start of Peyrot & Goulois, with backtracking; the inverse
(``H`` → ``L0, V``) is the inextensible catenary in closed form, refined by Newton for an
elastic cable.

References
----------
.. [1] H. M. Irvine, "Cable Structures", MIT Press, 1981, Ch. 1, §1.3 (the elastic catenary).
   (docs/references.bib: irvine1981)
.. [2] K. Kozak, Q. Zhou, J. Wang, "Static analysis of cable-driven manipulators with
   non-negligible cable mass", IEEE Transactions on Robotics 22(3), 2006, §II.
   (docs/references.bib: kozak2006)
.. [3] A. H. Peyrot, A. M. Goulois, "Analysis of cable structures", Computers & Structures
   10(5), 1979 (the starting point of the Newton iteration). (docs/references.bib: peyrot1979)
"""

from __future__ import annotations

import numpy as np

Array = np.ndarray

#: Newton iterations of the forward and inverse problems before they give up.
MAX_NEWTON = 60
#: Relative residual (of the chord length) at which Newton's method stops.
NEWTON_RTOL = 1e-13


def _log1p_ratio(q: np.ndarray) -> np.ndarray:
    """``log1p(q)/q``, 1 at ``q = 0``."""
    small = np.abs(q) < 1e-8
    safe = np.where(small, 1.0, q)
    return np.where(small, 1.0 - q / 2, np.log1p(safe) / safe)


def _up(b: np.ndarray) -> np.ndarray:
    """``b + √(1 + b²)`` without cancellation for negative ``b``."""
    r = np.sqrt(1.0 + b * b)
    return np.where(b >= 0, b + r, 1.0 / (r - b))


def _arc(H: np.ndarray, V: np.ndarray, L0: np.ndarray, w: np.ndarray) -> np.ndarray:
    """``∫₀^L0 ds/T(s) = (1/w)[asinh(V1/H) − asinh(V/H)]``, through ``log1p`` (exact at ``w = 0``)."""
    a, b = (V + w * L0) / H, V / H
    flip = a + b < 0
    p, r = np.where(flip, -b, a), np.where(flip, -a, b)
    K = (1.0 + (p + r) / (np.sqrt(1.0 + p * p) + np.sqrt(1.0 + r * r))) / _up(r)
    return (L0 / H) * K * _log1p_ratio(w * L0 / H * K)


def _inv_cubes(H: Array, V: Array, L0: Array, w: Array, T0: Array, T1: Array) -> Array:
    """``B = H² ∫₀^L0 ds/T³ = (V1/T1 − V/T0)/w`` without cancellation."""
    V1 = V + w * L0
    same = V * V1 > 0
    den = np.where(same, V1 * T0 + V * T1, 1.0)
    direct = np.where(w > 0, (V1 / T1 - V / T0) / np.where(w > 0, w, 1.0), L0 * H * H / T0**3)
    return np.where(same, H * H * L0 * (V1 + V) / (T0 * T1 * den), direct)


def ends(H: Array, V: Array, L0: Array, w: Array, EA: Array) -> tuple[Array, Array, tuple[Array, ...]]:
    """The far end ``(span, rise)`` of a cable with end force ``(H, V)`` at ``s = 0``, and the
    derivatives of ``(span, rise)`` with respect to ``(H, V, L0)``.

    All arguments broadcast; ``H > 0``; ``EA`` may be ``inf``.  Returns ``span, rise`` and the
    Jacobian entries ``xH, xV, xL, zH, zV, zL`` (Irvine's flexibility, ``xV = zH``).
    """
    flex = np.where(np.isinf(EA), 0.0, 1.0 / EA)
    V1 = V + w * L0
    T0, T1 = np.hypot(H, V), np.hypot(H, V1)
    A = _arc(H, V, L0, w)
    B = _inv_cubes(H, V, L0, w, T0, T1)
    span = H * (L0 * flex + A)
    rise = L0 * (V + V1) * (0.5 * flex + 1.0 / (T0 + T1))
    C = -H * L0 * (V1 + V) / ((T0 + T1) * T0 * T1)
    xH = L0 * flex + A - B
    zV = L0 * flex + B
    xL = H * (flex + 1.0 / T1)
    zL = V1 * (flex + 1.0 / T1)
    return span, rise, (xH, C, xL, C, zV, zL)


def start_forces(span: Array, rise: Array, L0: Array, w: Array, EA: Array) -> tuple[Array, Array]:
    """Starting ``(H, V)`` for Newton: Peyrot & Goulois' ``λ`` for a slack cable, the straight
    cable's stretch for a taut elastic one, whichever pulls harder."""
    chord = np.hypot(span, rise)
    ratio = (L0 * L0 - rise * rise) / (span * span)
    lam = np.where(L0 > chord, np.sqrt(3.0 * np.maximum(ratio - 1.0, 0.0)), 0.2)
    lam = np.maximum(lam, 0.2)
    H = w * span / (2.0 * lam)
    stretch = np.where(np.isinf(EA), 0.0, np.where(np.isinf(EA), 0.0, EA) * (chord - L0) / L0)
    H = np.maximum(H, stretch * span / chord)
    H = np.maximum(H, 1e-12 * np.maximum(w * L0, 1.0))
    V = H * rise / span - w * L0 / 2.0
    return H, V


def solve_forward(span: Array, rise: Array, L0: Array, w: Array, EA: Array) -> tuple[Array, Array, Array]:
    """``(H, V, ok)`` with ``ends(H, V, L0, w, EA) = (span, rise)``: damped Newton.

    Arrays of one shape; ``ok`` is False where Newton did not converge."""
    H, V = start_forces(span, rise, L0, w, EA)
    scale = np.hypot(span, rise) + L0
    ok = np.zeros(H.shape, dtype=bool)
    x, z, J = ends(H, V, L0, w, EA)
    fx, fz = x - span, z - rise
    norm = np.hypot(fx, fz)
    for _ in range(MAX_NEWTON):
        ok = norm <= NEWTON_RTOL * scale
        if ok.all():
            break
        xH, xV, _, zH, zV, _ = J
        det = xH * zV - xV * zH
        dH = -(zV * fx - xV * fz) / det
        dV = -(-zH * fx + xH * fz) / det
        step = np.where(ok, 0.0, 1.0)
        for _ in range(30):
            Hn = H + step * dH
            bad = Hn <= 0
            step = np.where(bad, step / 2, step)
            if not bad.any():
                break
        for _ in range(30):
            Hn, Vn = H + step * dH, V + step * dV
            xn, zn, Jn = ends(Hn, Vn, L0, w, EA)
            nn = np.hypot(xn - span, zn - rise)
            worse = (nn > norm) & (step > 1e-12) & ~ok
            if not worse.any():
                break
            step = np.where(worse, step / 2, step)
        H, V, norm = Hn, Vn, nn
        fx, fz, J = xn - span, zn - rise, Jn
    ok = (norm <= NEWTON_RTOL * scale * 10) & np.isfinite(H) & np.isfinite(V)
    return H, V, ok


def inextensible_from_horizontal(span: Array, rise: Array, H: Array, w: Array) -> tuple[Array, Array]:
    """``(L0, V)`` of the inextensible catenary with horizontal force ``H`` through the chord
    ``(span, rise)``: with ``a = H/w``, ``rise = 2a sinh(span/2a) sinh(ξm/a)`` gives the
    midpoint ``ξm`` from the vertex, ``V = H sinh((ξm − span/2)/a)`` and
    ``L0 = 2a cosh(ξm/a) sinh(span/2a)``; the straight cable at ``w = 0``."""
    heavy = w > 0
    a = H / np.where(heavy, w, 1.0)
    half = np.where(heavy, span / (2.0 * a), 0.0)
    with np.errstate(over="ignore", invalid="ignore"):
        sh = np.where(heavy, np.sinh(half), 1.0)
        # 2a sinh(span/2a) → span as w → 0: the chord's horizontal length
        width = np.where(heavy, 2.0 * a * sh, span)
        xm = np.arcsinh(rise / width)
        L0 = np.where(heavy, width * np.cosh(xm), np.hypot(span, rise))
        V = np.where(heavy, H * np.sinh(xm - half), H * rise / span)
    return L0, V


def solve_inverse(span: Array, rise: Array, H: Array, w: Array, EA: Array) -> tuple[Array, Array, Array]:
    """``(L0, V, ok)`` of the elastic catenary with horizontal force ``H`` through the chord:
    the inextensible closed form, then Newton on ``(V, L0)`` for an elastic cable."""
    L0, V = inextensible_from_horizontal(span, rise, H, w)
    elastic = ~np.isinf(EA)
    if not elastic.any():
        return L0, V, np.isfinite(L0) & np.isfinite(V)
    T = np.hypot(H, V + w * L0 / 2)
    L0 = np.where(elastic, L0 / (1.0 + np.where(elastic, T / np.where(elastic, EA, 1.0), 0.0)), L0)
    scale = np.hypot(span, rise) + L0
    x, z, J = ends(H, V, L0, w, EA)
    for _ in range(MAX_NEWTON):
        fx, fz = x - span, z - rise
        if (np.hypot(fx, fz) <= NEWTON_RTOL * scale).all():
            break
        _, xV, xL, _, zV, zL = J
        det = xV * zL - xL * zV
        dV = -(zL * fx - xL * fz) / det
        dL = -(-zV * fx + xV * fz) / det
        step = np.ones_like(dL)
        for _ in range(30):
            bad = L0 + step * dL <= 0
            if not bad.any():
                break
            step = np.where(bad, step / 2, step)
        V, L0 = V + step * dV, L0 + step * dL
        x, z, J = ends(H, V, L0, w, EA)
    ok = (np.hypot(x - span, z - rise) <= 10 * NEWTON_RTOL * scale) & np.isfinite(L0) & np.isfinite(V)
    return L0, V, ok


def points(H: Array, V: Array, w: Array, EA: Array, s: Array) -> tuple[Array, Array]:
    """Points ``(x, z)`` of the cable at Lagrangian coordinates ``s`` (broadcast with the rest)."""
    x, z, _ = ends(H, V, s, w, EA)
    return x, z


def largest_sag(span: Array, rise: Array, H: Array, V: Array, L0: Array, w: Array, EA: Array) -> Array:
    """The largest distance of the cable from its chord: at the point whose tangent is
    parallel to the chord, ``V(s)/H = rise/span`` (clipped to the cable)."""
    s = np.clip((H * rise / span - V) / np.where(w > 0, w, 1.0), 0.0, L0)
    s = np.where(w > 0, s, 0.0)
    x, z = points(H, V, w, EA, s)
    return np.abs(x * rise - z * span) / np.hypot(span, rise)


def solve_tension(
    span: Array, rise: Array, T0: Array, w: Array, EA: Array, H: Array, V: Array, L0: Array
) -> tuple[Array, Array, Array, Array]:
    """``(H, V, L0, ok)`` of the elastic catenary through the chord whose tension at the
    platform end is ``T0``: Newton on the angle ``φ`` of the end force (``H = T0 cos φ``,
    ``V = T0 sin φ``) and ``L0``, from the catenary ``(H, V, L0)`` given as a start."""
    phi = np.arctan2(V, H)
    chord = np.hypot(span, rise)
    ok = np.zeros(np.shape(T0), dtype=bool)
    for _ in range(MAX_NEWTON):
        H, V = T0 * np.cos(phi), T0 * np.sin(phi)
        x, z, (xH, xV, xL, zH, zV, zL) = ends(H, V, L0, w, EA)
        fx, fz = x - span, z - rise
        # relative to the current length: a far-off start (a slack catenary's) sets no tolerance
        ok = np.hypot(fx, fz) <= NEWTON_RTOL * (chord + L0)
        if ok.all():
            break
        a, c = xV * H - xH * V, zV * H - zH * V
        det = a * zL - xL * c
        dphi = -(zL * fx - xL * fz) / det
        dL = -(-c * fx + a * fz) / det
        # the angle stays within a quarter turn of the start and the length positive
        dphi = np.clip(dphi, -0.5, 0.5)
        step = np.ones_like(dL)
        for _ in range(30):
            bad = (L0 + step * dL <= 0) | (np.abs(phi + step * dphi) >= np.pi / 2)
            if not bad.any():
                break
            step = np.where(bad, step / 2, step)
        phi, L0 = phi + step * dphi, L0 + step * dL
    H, V = T0 * np.cos(phi), T0 * np.sin(phi)
    return H, V, L0, ok & (H > 0) & np.isfinite(L0)
