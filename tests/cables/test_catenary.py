"""Irvine's elastic catenary (taut.cables) against the textbook formulas written out here,
an independent chain of point masses, and its own properties."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from scipy.integrate import quad
from scipy.optimize import brentq, minimize

from taut.cables import catenary_forces, catenary_lengths, catenary_shape, catenary_tensions
from taut.cables._catenary import ends
from taut.errors import ArgumentError, TautError, UnreachableLengthsError

#: End forces, unstrained lengths, weights and stiffnesses (inextensible too) of the properties.
CABLES = {
    "H": st.floats(5.0, 500.0),
    "V": st.floats(-400.0, 400.0),
    "L0": st.floats(0.5, 20.0),
    "w": st.floats(0.05, 20.0),
    "EA": st.one_of(st.just(math.inf), st.floats(1e3, 1e7)),
}


def test_horizontal_span_is_the_cosh_catenary():
    """``y = a cosh(x/a)`` through two supports at one level: ``L0 = 2a sinh(l/2a)``, ``H = w a``,
    each end carries half the weight, sag ``a (cosh(l/2a) − 1)``."""
    span, L0, w = 12.0, 12.4, 7.5
    a = brentq(lambda a: 2 * a * math.sinh(span / (2 * a)) - L0, 0.5, 1e4, xtol=1e-15, rtol=1e-15)
    c = catenary_forces(span, 0.0, L0, w)
    assert float(c.horizontal_forces) == pytest.approx(w * a, rel=1e-11)
    assert float(c.vertical_forces) == pytest.approx(-w * L0 / 2, rel=1e-11)
    assert float(c.exit_vertical_forces) == pytest.approx(w * L0 / 2, rel=1e-11)
    assert float(c.platform_tensions) == pytest.approx(w * a * math.cosh(span / (2 * a)), rel=1e-11)
    assert float(c.sag) == pytest.approx(a * (math.cosh(span / (2 * a)) - 1), rel=1e-10)
    x, z = catenary_shape(c, 41).T
    assert np.allclose(z, a * np.cosh((x - span / 2) / a) - a * math.cosh(span / (2 * a)), atol=1e-10)


@pytest.mark.parametrize("xi0", [-3.0, 0.5, 4.0])
def test_inclined_span_is_the_cosh_catenary(xi0):
    """Supports at different levels on ``z = a cosh(ξ/a)``: the platform end at ``ξ0`` (its
    vertical force ``H sinh(ξ0/a)``), the exit at ``ξ0 + l``; the length is the arc between."""
    a, span, w = 6.0, 9.0, 3.0
    xi1 = xi0 + span
    rise = a * (math.cosh(xi1 / a) - math.cosh(xi0 / a))
    L0 = a * (math.sinh(xi1 / a) - math.sinh(xi0 / a))
    c = catenary_forces(span, rise, L0, w)
    assert float(c.horizontal_forces) == pytest.approx(w * a, rel=1e-11)
    assert float(c.vertical_forces) == pytest.approx(w * a * math.sinh(xi0 / a), rel=1e-10, abs=1e-10)
    assert float(c.exit_tensions) == pytest.approx(w * a * math.cosh(xi1 / a), rel=1e-11)
    back = catenary_lengths(span, rise, w * a, w)
    assert float(back.unstrained_lengths) == pytest.approx(L0, rel=1e-12)


def _irvine(H, V, L0, w, EA):
    """Irvine's elastic catenary as the book writes it (no rewriting for round-off)."""
    V1 = V + w * L0
    x = H * L0 / EA + H / w * (math.asinh(V1 / H) - math.asinh(V / H))
    z = (V * L0 + w * L0**2 / 2) / EA + (math.hypot(H, V1) - math.hypot(H, V)) / w
    return x, z


@settings(max_examples=60, deadline=None)
@given(
    H=st.floats(5.0, 500.0),
    V=st.floats(-400.0, 400.0),
    L0=st.floats(0.5, 20.0),
    w=st.floats(0.05, 20.0),
    EA=st.floats(1e3, 1e7),
)
def test_elastic_forward_matches_irvine_and_inverts(H, V, L0, w, EA):
    span, rise = _irvine(H, V, L0, w, EA)
    if span < 1e-3:
        return
    c = catenary_forces(span, rise, L0, w, EA)
    scale = math.hypot(H, V) + w * L0
    assert abs(float(c.horizontal_forces) - H) <= 1e-7 * scale
    assert abs(float(c.vertical_forces) - V) <= 1e-7 * scale
    # the vertical forces at the two ends differ by the cable's weight
    assert float(c.exit_vertical_forces - c.vertical_forces) == pytest.approx(w * L0, rel=1e-12)
    back = catenary_lengths(span, rise, float(c.horizontal_forces), w, EA)
    assert float(back.unstrained_lengths) == pytest.approx(L0, rel=1e-9)


@settings(max_examples=40, deadline=None)
@given(**CABLES)
def test_flexibility_is_the_derivative_and_symmetric(H, V, L0, w, EA):
    x, z, J = ends(*(np.array(v) for v in (H, V, L0, w, EA)))
    flex = np.array(J, dtype=float).reshape(2, 3)
    assert flex[0, 1] == flex[1, 0]
    for k, h in enumerate((1e-4 * H, 1e-4 * max(abs(V), H), 1e-5 * L0)):
        args = np.array([H, V, L0])
        hi, lo = args.copy(), args.copy()
        hi[k] += h
        lo[k] -= h
        up = ends(*hi, w, EA)[:2]
        dn = ends(*lo, w, EA)[:2]
        fd = (np.array(up) - np.array(dn)) / (2 * h)
        assert np.allclose(fd, flex[:, k], rtol=1e-5, atol=1e-8 * np.abs(flex).max())


@settings(max_examples=40, deadline=None)
@given(**CABLES)
def test_shape_integrates_the_strained_tangent(H, V, L0, w, EA):
    """Each point is the integral of the strained unit tangent ``(H, V + w s)/T (1 + T/EA)``
    (quadrature here): the horizontal force is the same all along the cable."""
    c = catenary_forces(*_irvine_any(H, V, L0, w, EA), L0, w, EA)
    pts = catenary_shape(c, 5)
    H, V = float(c.horizontal_forces), float(c.vertical_forces)  # the forces the shape is drawn with
    flex = 0.0 if math.isinf(EA) else 1.0 / EA

    def T(t):
        return math.hypot(H, V + w * t)

    for s, (x, z) in zip(np.linspace(0, L0, 5), pts):
        xq = quad(lambda t: H / T(t) * (1 + T(t) * flex), 0, s, epsabs=1e-13)[0]
        zq = quad(lambda t: (V + w * t) / T(t) * (1 + T(t) * flex), 0, s, epsabs=1e-13)[0]
        assert x == pytest.approx(xq, abs=1e-7 * L0)
        assert z == pytest.approx(zq, abs=1e-7 * L0)


def _irvine_any(H, V, L0, w, EA):
    """The ends of an elastic cable by :func:`_irvine`, of an inextensible one by the cosh
    catenary; an inextensible cable so taut that its chord rounds to its length is not drawn
    (its sag is below the closed form's rounding, and taut refuses a chord not shorter than it)."""
    if not math.isinf(EA):
        return _irvine(H, V, L0, w, EA)
    ends = _inextensible(H, V, L0, w)
    assume(math.hypot(*ends) < L0 * (1 - 1e-9))
    return ends


def _inextensible(H, V, L0, w):
    a = H / w
    xi0 = a * math.asinh(V / H)
    xi1 = a * math.asinh((V + w * L0) / H)
    return xi1 - xi0, a * (math.cosh(xi1 / a) - math.cosh(xi0 / a))


@pytest.mark.parametrize("EA", [2e4, math.inf])
def test_weightless_limit_is_the_straight_cable(EA):
    """``w → 0``: the force points along the chord, ``T = EA (l − L0)/L0`` for an elastic cable."""
    span, rise, L0 = 3.0, 4.0, 4.95
    if math.isinf(EA):
        c = catenary_lengths(span, rise, 120.0, 0.0)
        assert float(c.unstrained_lengths) == pytest.approx(5.0, rel=1e-12)
        assert float(c.vertical_forces) == pytest.approx(160.0, rel=1e-12)
        return
    T = EA * (5.0 - L0) / L0
    for w in (0.0, 1e-12):
        c = catenary_forces(span, rise, L0, w, EA)
        assert float(c.horizontal_forces) == pytest.approx(T * 0.6, rel=1e-9)
        assert float(c.vertical_forces) == pytest.approx(T * 0.8, rel=1e-9)
        assert float(c.sag) <= 1e-9


def test_inextensible_limit_of_an_elastic_cable():
    span, rise, L0, w = 8.0, 2.0, 8.5, 4.0
    rigid = catenary_forces(span, rise, L0, w)
    stiff = catenary_forces(span, rise, L0, w, 1e15)
    assert float(stiff.horizontal_forces) == pytest.approx(float(rigid.horizontal_forces), rel=1e-9)
    assert float(stiff.vertical_forces) == pytest.approx(float(rigid.vertical_forces), rel=1e-9)


def _chain(span, rise, L0, w, EA, N):
    """A chain of ``N`` elastic links (stiffness ``EA/h``) with the cable's weight lumped at its
    ``N + 1`` nodes, in equilibrium by minimising its potential energy (scipy); returns the
    nodes and the force of the first link plus the half link's weight on the platform end."""
    h = L0 / N
    k = EA / h
    m = np.full(N + 1, w * h)
    m[[0, -1]] /= 2
    t = np.linspace(0, 1, N + 1)[1:-1]
    x0 = np.concatenate([span * t, rise * t - 0.1 * L0 * np.sin(np.pi * t)])

    def nodes(q):
        x = np.concatenate([[0.0], q[: N - 1], [span]])
        z = np.concatenate([[0.0], q[N - 1 :], [rise]])
        return x, z

    def energy(q):
        x, z = nodes(q)
        dx, dz = np.diff(x), np.diff(z)
        ln = np.hypot(dx, dz)
        e = 0.5 * k * np.sum((ln - h) ** 2) + np.sum(m * z)
        f = k * (ln - h) / ln
        gx = np.zeros(N + 1)
        gz = m.copy()
        gx[:-1] -= f * dx
        gx[1:] += f * dx
        gz[:-1] -= f * dz
        gz[1:] += f * dz
        return e, np.concatenate([gx[1:-1], gz[1:-1]])

    res = minimize(energy, x0, jac=True, method="BFGS", options={"gtol": 1e-11 * w * L0, "maxiter": 20000})
    x, z = nodes(res.x)
    ln = math.hypot(x[1], z[1])
    f = k * (ln - h) / ln
    return x, z, np.array([f * x[1], f * z[1] - m[0]])


@pytest.mark.slow
def test_chain_of_point_masses_converges_at_second_order():
    span, rise, L0, w, EA = 10.0, 3.0, 10.9, 10.0, 5e3
    c = catenary_forces(span, rise, L0, w, EA)
    exact = np.array([float(c.horizontal_forces), float(c.vertical_forces)])
    errors, shape_errors = [], []
    for N in (8, 16, 32):
        x, z, force = _chain(span, rise, L0, w, EA, N)
        pts = catenary_shape(c, N + 1)
        errors.append(np.abs(force - exact).max() / np.abs(exact).max())
        shape_errors.append(np.hypot(x - pts[:, 0], z - pts[:, 1]).max() / L0)
    for e in (errors, shape_errors):
        rates = [math.log2(a / b) for a, b in zip(e, e[1:])]
        assert all(1.8 < r < 2.3 for r in rates), (e, rates)


def test_chain_of_point_masses_is_close_at_sixteen_links():
    span, rise, L0, w, EA = 10.0, 3.0, 10.9, 10.0, 5e3
    c = catenary_forces(span, rise, L0, w, EA)
    x, z, force = _chain(span, rise, L0, w, EA, 16)
    pts = catenary_shape(c, 17)
    assert np.hypot(x - pts[:, 0], z - pts[:, 1]).max() < 1e-3 * L0
    assert force == pytest.approx([float(c.horizontal_forces), float(c.vertical_forces)], rel=2e-3)


@pytest.mark.parametrize(
    ("call", "error", "words"),
    [
        (lambda: catenary_forces(10.0, 0.0, 9.9, 1.0), UnreachableLengthsError, "not longer than its chord"),
        (lambda: catenary_forces(10.0, 0.0, 10.5, -1.0), ArgumentError, "weight"),
        (lambda: catenary_forces(10.0, 0.0, 10.5, float("nan")), ArgumentError, "weight"),
        (lambda: catenary_forces(10.0, 0.0, 10.5, 1.0, 0.0), ArgumentError, "stiffness"),
        (lambda: catenary_forces(0.0, 3.0, 10.5, 1.0), ArgumentError, "span"),
        (lambda: catenary_forces(10.0, 0.0, 10.5, 0.0), ArgumentError, "weightless inextensible"),
        (lambda: catenary_lengths(10.0, 0.0, -5.0, 1.0), ArgumentError, "horizontal_forces"),
        (lambda: catenary_forces([1.0, 2.0], 0.0, [1.5, 2.5, 3.5], 1.0), ArgumentError, "broadcast"),
        (lambda: catenary_shape(catenary_forces(10.0, 0.0, 10.5, 1.0), 1), TautError, "samples"),
    ],
)
def test_bad_input_is_one_line(call, error, words):
    with pytest.raises(error, match=words) as info:
        call()
    assert "\n" not in str(info.value)


def test_the_catenary_of_a_platform_tension_is_the_one_of_its_length():
    """catenary_tensions inverts catenary_forces' platform-end tension: 64 cables, inclined up
    and down, elastic and inextensible, slack and taut, from a nearby start and cold."""
    rng = np.random.default_rng(3)
    span, rise = rng.uniform(1.0, 20.0, 64), rng.uniform(-10.0, 10.0, 64)
    L0 = np.hypot(span, rise) * rng.uniform(1.0005, 1.1, 64)
    w, ea = rng.uniform(0.5, 30.0, 64), np.where(rng.random(64) < 0.5, np.inf, rng.uniform(1e4, 1e7, 64))
    ref = catenary_forces(span, rise, L0, w, ea)
    cold = catenary_tensions(span, rise, ref.platform_tensions, w, ea)
    near = catenary_forces(span, rise, L0 * 1.001, w, ea)
    warm = catenary_tensions(span, rise, ref.platform_tensions, w, ea, start=near)
    assert np.allclose(warm.unstrained_lengths, L0, rtol=1e-9)
    assert np.allclose(warm.horizontal_forces, ref.horizontal_forces, rtol=1e-8)
    assert np.allclose(warm.vertical_forces, ref.vertical_forces, rtol=1e-8, atol=1e-8 * ref.platform_tensions)
    assert np.allclose(warm.exit_tensions, ref.exit_tensions, rtol=1e-9)
    # a tension may have two catenaries through the ends, a taut and a slacker one: cold, either,
    # whose length gives that tension back by the forward problem (to the conditioning of a taut
    # inextensible cable, whose tension changes 1e6 times faster than its length)
    back = catenary_forces(span, rise, cold.unstrained_lengths, w, ea)
    assert np.allclose(back.platform_tensions, ref.platform_tensions, rtol=1e-6)
    assert np.allclose(back.horizontal_forces, cold.horizontal_forces, rtol=1e-6)
    with pytest.raises(ArgumentError, match="platform_tensions"):
        catenary_tensions(span, rise, -ref.platform_tensions, w, ea)
    with pytest.raises(ArgumentError, match="start"):
        catenary_tensions(span, rise, ref.platform_tensions, w, ea, start=near.span)
    # 1 N cannot hold up 10 m of a 10 N/m cable hanging from an exit 5 m higher
    with pytest.raises(ArgumentError, match="too slack"):
        catenary_tensions(10.0, 5.0, 1.0, 10.0)
