"""Certified verdicts rechecked without floating point: at the corners and the centre of inner
and outer boxes of planar robots with four cables, the tensions are decided in rational
arithmetic (Python's ``fractions``) with the cable lengths bracketed by integer square roots.

With force densities ``s_i = τ_i / L_i`` the equilibrium ``Σ τ_i (u_i, b_i × u_i) = −w`` is
``V s = −w`` for the rational columns ``(v_i, b_i × v_i)``, ``v_i = a_i − b_i − p``: with four
cables and three equations its solutions are a line ``s = s_p + λ N``, solved exactly, and
``τ_min ≤ L_i s_i ≤ τ_max`` cuts it into one interval of ``λ`` per cable whose ends are
``(τ / L_i − s_p,i) / N_i``.  The wrench is balanced iff those intervals meet; the ends are
compared through rational brackets of ``1 / L_i`` a ``2⁻²⁰⁰`` wide, and a comparison the
brackets cannot settle fails the test (it would need a pose on the boundary itself).
"""

from __future__ import annotations

import itertools
import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taut
from taut.kinematics import structure_matrix
from taut.model import random_planar_robot
from taut.workspace import certified, default_wrench_set

BITS = 200


def inverse_sqrt(q: Fraction) -> tuple[Fraction, Fraction]:
    """Rationals ``lo ≤ 1/√q ≤ hi`` a ``2⁻²⁰⁰`` apart (relative), from integer square roots."""
    scale = 1 << (2 * BITS)
    root = math.isqrt(q.numerator * q.denominator * scale)  # ⌊√(q) · den · 2^BITS⌋
    # √q = √(num·den)/den, so 1/√q = den / √(num·den)
    lo = Fraction(q.denominator << BITS, root + 1)
    hi = Fraction(q.denominator << BITS, root)
    return lo, hi


def solve3(A: list[list[Fraction]], b: list[Fraction]) -> list[Fraction] | None:
    """Exact Gaussian elimination of a 3 × 3 rational system (None when singular)."""
    M = [row[:] + [rhs] for row, rhs in zip(A, b)]
    for col in range(3):
        pivot = next((r for r in range(col, 3) if M[r][col] != 0), None)
        if pivot is None:
            return None
        M[col], M[pivot] = M[pivot], M[col]
        for r in range(3):
            if r != col and M[r][col] != 0:
                f = M[r][col] / M[col][col]
                M[r] = [x - f * y for x, y in zip(M[r], M[col])]
    return [M[i][3] / M[i][i] for i in range(3)]


def balanced(robot, position, wrench) -> bool | None:
    """Is ``wrench`` balanced at ``position`` (θ = 0) within the tension bounds?  Exactly;
    None when the brackets cannot settle it."""
    F = Fraction
    p = [F(float(x)) for x in position]
    tmin = [F(float(x)) for x in robot.tension_bounds[0]]
    tmax = [F(float(x)) if np.isfinite(x) else None for x in robot.tension_bounds[1]]
    cols, inv = [], []
    for a, b in zip(robot.exits, robot.anchors):
        a, b = [F(float(x)) for x in a], [F(float(x)) for x in b]
        v = [a[0] - b[0] - p[0], a[1] - b[1] - p[1]]
        cols.append([v[0], v[1], b[0] * v[1] - b[1] * v[0]])
        inv.append(inverse_sqrt(v[0] ** 2 + v[1] ** 2))
    # s = s_p + λ N with s_4 = λ: the first three columns solve V₃ s₃ = −w − λ v₄
    V3 = [[cols[j][i] for j in range(3)] for i in range(3)]
    sp = solve3(V3, [-F(float(x)) for x in wrench])
    sn = solve3(V3, [-c for c in cols[3]])
    if sp is None or sn is None:
        return None
    s_p, N = [*sp, F(0)], [*sn, F(1)]
    lower, upper = [], []  # brackets (lo, hi) of each cable's least and greatest λ
    for i in range(4):
        bound = [(tmin[i] * inv[i][0], tmin[i] * inv[i][1])]  # τ_min / L_i, bracketed
        bound.append(None if tmax[i] is None else (tmax[i] * inv[i][0], tmax[i] * inv[i][1]))
        if N[i] == 0:  # s_i = s_p,i whatever λ: τ_min / L ≤ s_i ≤ τ_max / L
            if bound[0][1] <= s_p[i] and (bound[1] is None or s_p[i] <= bound[1][0]):
                continue
            if s_p[i] < bound[0][0] or (bound[1] is not None and s_p[i] > bound[1][1]):
                return False
            return None
        ends = [None if e is None else tuple(sorted(((e[0] - s_p[i]) / N[i], (e[1] - s_p[i]) / N[i]))) for e in bound]
        least, greatest = ends if N[i] > 0 else ends[::-1]
        if least is not None:
            lower.append(least)
        if greatest is not None:
            upper.append(greatest)
    if not lower or not upper:
        return True
    if max(b[1] for b in lower) <= min(b[0] for b in upper):
        return True
    if max(b[0] for b in lower) > min(b[1] for b in upper):
        return False
    return None


def required_wrenches(robot, condition):
    """The wrenches the cables must balance (θ = 0): the weight, with its moment about the
    reference point when it acts at a wrench point, and with ``wrench-feasible`` the vertices
    of the default box around it."""
    assert robot.platform.wrench is None and not len(robot.body_weights), "only the weight is modelled here"
    force = np.asarray(robot.weight, float)
    arm = np.zeros(2) if robot.platform.wrench_point is None else np.asarray(robot.platform.wrench_point, float)
    weight = np.array([*force, arm[0] * force[1] - arm[1] * force[0]])
    if condition == "static":
        return [weight]
    box = default_wrench_set(robot)
    return [weight + np.array(v) for v in itertools.product(*zip(box.lower, box.upper))]


def recheck(robot, res, condition, boxes=150, seed=0):
    rng = np.random.default_rng(seed)
    wrenches = required_wrenches(robot, condition)
    checked = 0
    for kind, want in ((res.inner, True), (res.outer, False)):
        for box in kind[rng.permutation(len(kind))[:boxes]]:
            points = [*itertools.product(*box), box.mean(axis=1)]
            for point in points:
                verdicts = [balanced(robot, point, w) for w in wrenches]
                assert None not in verdicts, f"undecidable at {point}"
                assert all(verdicts) == want, f"{'inner' if want else 'outer'} box {box.tolist()} fails at {point}"
                checked += 1
    return checked


def test_the_rational_columns_are_taut_s_structure_matrix():
    robot = taut.example("planar-4cable")
    position = np.array([0.3, 0.2])
    W = structure_matrix(robot, np.r_[position, 0.0])
    for i, (a, b) in enumerate(zip(robot.exits, robot.anchors)):
        v = a - b - position
        column = np.r_[v, b[0] * v[1] - b[1] * v[0]] / np.linalg.norm(v)
        assert np.allclose(W[:, i], column, atol=1e-14)


@pytest.mark.parametrize("condition", ["static", "wrench-feasible"])
def test_planar_4cable_verdicts_hold_in_rational_arithmetic(condition):
    robot = taut.example("planar-4cable")
    res = certified(robot, condition, eps=0.02)
    assert recheck(robot, res, condition) == 5 * (min(150, len(res.inner)) + min(150, len(res.outer)))


@settings(max_examples=10, deadline=None)
@given(seed=st.integers(0, 2**31))
def test_random_four_cable_robots_hold_in_rational_arithmetic(seed):
    robot, _ = random_planar_robot(4, seed=seed)
    res = certified(robot, "static", eps=0.1, max_boxes=5000)
    recheck(robot, res, "static", boxes=30, seed=seed)
