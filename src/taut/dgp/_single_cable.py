"""The DGP with one taut cable (Berti 2015, §2.3.3, Algorithm 2).

With cable ``i`` alone in tension the cable is parallel to the load: ``b_i = a_i + ρ_i f̂``,
``τ_i = ‖f‖``, and ``G`` lies on the same vertical, below ``B_i`` (``G_a``, stable) or above
it (``G_b``, unstable); the platform can still spin by ``ϑ`` about that line.  Instead of
the per-cable minimum of Algorithm 2 (which tests each slack cable separately), the
distance of every slack anchor is written exactly as
``D_k(ϑ) = A_k + B_k cos ϑ + C_k sin ϑ`` (Eq. 2.12) and the angles where *all* slack
cables fit (``D_k ≤ ρ_k²``) are intersected; each admissible arc is one solution family,
reported at its middle angle.

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §2.3.3, Algorithm 2, Eq. 2.12. (docs/references.bib: berti2015)
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from taut.dgp._formulation import load
from taut.model import Robot

TWO_PI = 2.0 * np.pi


def _rotation_to(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """A rotation taking the unit vector ``u`` to the unit vector ``v``."""
    w = np.cross(u, v)
    c = float(np.dot(u, v))
    if np.linalg.norm(w) < 1e-14:
        if c > 0:
            return np.eye(3)
        axis = np.cross(u, [1.0, 0.0, 0.0])
        if np.linalg.norm(axis) < 1e-8:
            axis = np.cross(u, [0.0, 1.0, 0.0])
        axis /= np.linalg.norm(axis)
        return 2.0 * np.outer(axis, axis) - np.eye(3)
    K = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
    return np.eye(3) + K + K @ K / (1.0 + c)


def _axis_rotation(axis: np.ndarray, theta: float) -> np.ndarray:
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(theta) * K + (1.0 - np.cos(theta)) * K @ K


def _arcs(conditions: Sequence[tuple[float, float, float]]) -> list[tuple[float, float]]:
    """Arcs of ``[0, 2π)`` where every ``A + B cos ϑ + C sin ϑ ≤ 0`` holds."""
    angles = [0.0, TWO_PI]
    for A, B, C in conditions:
        r = np.hypot(B, C)
        if r > 0 and abs(A) <= r:
            phi = np.arctan2(C, B)
            d = np.arccos(np.clip(-A / r, -1.0, 1.0))
            angles += [(phi + d) % TWO_PI, (phi - d) % TWO_PI]
    cuts = np.unique(angles)

    def ok(th: float) -> bool:
        return all(A + B * np.cos(th) + C * np.sin(th) <= 0.0 for A, B, C in conditions)

    arcs = [(lo, hi) for lo, hi in zip(cuts[:-1], cuts[1:]) if hi > lo and ok(0.5 * (lo + hi))]
    # merge neighbours, including across 2π → 0
    merged: list[list[float]] = []
    for lo, hi in arcs:
        if merged and abs(merged[-1][1] - lo) < 1e-15:
            merged[-1][1] = hi
        else:
            merged.append([lo, hi])
    if len(merged) > 1 and merged[0][0] == 0.0 and merged[-1][1] == TWO_PI:
        first = merged.pop(0)
        merged[-1][1] = TWO_PI + first[1]
    return [(lo, hi) for lo, hi in merged]


def single_cable_equilibria(robot: Robot, lengths: np.ndarray, i: int) -> list[dict]:
    """Equilibria with cable ``i`` alone taut: dicts with ``R``, ``p``, ``tensions``,
    ``stable`` and the admissible spin arc ``continuum = (ϑ_lo, ϑ_hi)``.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §2.3.3, Algorithm 2. (docs/references.bib: berti2015)
    """
    f, mext, gp = load(robot)
    F = np.linalg.norm(f)
    if F == 0.0 or np.any(mext != 0.0):
        return []
    fh = f / F
    a, r = robot.exits, robot.anchors
    bi = a[i] + lengths[i] * fh
    v = gp - r[i]
    if np.linalg.norm(v) == 0.0:
        return []  # G on the anchor: every orientation is an equilibrium (not isolated)
    out = []
    for side in (1.0, -1.0):  # G below B_i (along the load) or above it
        R0 = _rotation_to(v / np.linalg.norm(v), side * fh)
        conds = []
        for k in range(robot.n_cables):
            if k == i:
                continue
            c = bi - a[k]
            w0 = R0 @ (r[k] - r[i])
            wpar = np.dot(w0, fh) * fh
            wperp = w0 - wpar
            base = c + wpar
            conds.append(
                (base @ base + wperp @ wperp - lengths[k] ** 2, 2.0 * base @ wperp, 2.0 * base @ np.cross(fh, wperp))
            )
        for lo, hi in _arcs(conds):
            R = _axis_rotation(fh, 0.5 * (lo + hi)) @ R0
            tau = np.zeros(robot.n_cables)
            tau[i] = F
            out.append({"R": R, "p": bi - R @ r[i], "tensions": tau, "stable": side > 0, "continuum": (lo, hi)})
    return out
