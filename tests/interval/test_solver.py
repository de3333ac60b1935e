"""HC4, interval Gauss, Krawczyk + inflation and branch-and-prune on small systems."""

from fractions import Fraction

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from taut.errors import ArgumentError
from taut.interval import (
    branch_and_prune,
    certify,
    compile_system,
    const,
    contract,
    inflate,
    krawczyk,
    preconditioned_solve,
    variables,
)
from taut.interval._branch_prune import bisect_index, smear_scores
from taut.interval._expression import compile_tape
from taut.interval._hc4 import evaluate, evaluate_point
from taut.interval._krawczyk import jacobian
from taut.interval._linear import LinearFilter, float_inverse

X, Y = variables(2)
CIRCLES = compile_system(2, [X**2 + Y**2 - 1, (X - 1) ** 2 + Y**2 - 1])  # Example 1 of §3.2.1


def test_hc4_keeps_solutions_and_proves_emptiness():
    lo, hi = np.array([-2.0, 0.0]), np.array([2.0, 2.0])
    assert contract(CIRCLES.tape, lo, hi)
    s = np.array([0.5, np.sqrt(3) / 2])
    assert np.all(lo <= s) and np.all(s <= hi)
    assert hi[0] <= 1.0 + 1e-12 and lo[0] >= -1e-12  # x ∈ [0, 1] from the two circles
    lo, hi = np.array([1.5, 1.5]), np.array([2.0, 2.0])
    assert not contract(CIRCLES.tape, lo, hi)


def test_krawczyk_proves_uniqueness_and_inflation_gives_a_wider_box():
    s = np.array([0.5, np.sqrt(3) / 2])
    assert krawczyk(CIRCLES, s - 0.05, s + 0.05).status == "unique"
    assert krawczyk(CIRCLES, s + 0.5, s + 0.6).status == "empty"
    cert = certify(CIRCLES, [0.4, 0.8])
    assert np.allclose(cert.x, s, atol=1e-15) and np.all(cert.lo <= s) and np.all(s <= cert.hi)
    assert cert.width < 1e-6
    r = inflate(CIRCLES, s)
    # Eq. 3.40 gives √3/4 with exact symbolic cancellation; the natural extension is sound but smaller
    assert 0.05 < r <= np.sqrt(3) / 4
    assert krawczyk(CIRCLES, s - r, s + r).status != "empty"


@st.composite
def systems_with_a_zero(draw):
    """``f_i(x) = (x_i − s_i)(x_i + b_i) + Σ_j a_ij (x_j − s_j)``: every term vanishes
    exactly at ``x = s`` (a float), so ``s`` is an exact zero; and a box around it."""
    n = draw(st.integers(2, 5))
    num = st.floats(-3.0, 3.0, allow_nan=False)
    s = np.array(draw(st.lists(num, min_size=n, max_size=n)))
    b = draw(st.lists(num, min_size=n, max_size=n))
    a = np.array(draw(st.lists(num, min_size=n * n, max_size=n * n))).reshape(n, n)
    x = variables(n)
    eqs = [
        (x[i] - float(s[i])) * (x[i] + float(b[i]))
        + sum(((x[j] - float(s[j])) * float(a[i, j]) for j in range(n)), const(0.0))
        for i in range(n)
    ]
    below = np.array(draw(st.lists(st.floats(0.0, 0.5), min_size=n, max_size=n)))
    above = np.array(draw(st.lists(st.floats(0.0, 0.5), min_size=n, max_size=n)))
    return compile_system(n, eqs), s, s - below, s + above


@settings(max_examples=300, deadline=None)
@given(systems_with_a_zero())
def test_krawczyk_never_loses_a_zero_of_the_box(case):
    """A zero in X is in K(X) ∩ X: the box is never called empty and keeps the zero."""
    system, s, lo, hi = case
    res = krawczyk(system, lo, hi)
    assert res.status != "empty"
    assert np.all(res.lo <= s) and np.all(s <= res.hi)


@settings(max_examples=200, deadline=None)
@given(systems_with_a_zero())
def test_krawczyk_with_slopes_keeps_every_zero_and_proves_uniqueness_only_with_the_jacobian(case):
    system, s, lo, hi = case
    res = krawczyk(system, lo, hi, points=1)
    assert res.status != "empty"
    assert np.all(res.lo <= s) and np.all(s <= res.hi)
    if res.status == "unique":
        assert krawczyk(system, lo, hi).status == "unique"


def _below(a, b) -> bool:
    """``a ≤ b`` for floats (infinite ones allowed: an unbounded operator says nothing) and
    rationals."""
    a, b = (Fraction(v) if np.isfinite(float(v)) else float(v) for v in (a, b))
    return a <= b


def _exact_krawczyk(C, y, fl, fh, Jl, Jh, lo, hi, sel=None):
    """``y_S − C f(y) + (I_S − C J)(X − y)`` over the interval data, in exact rationals
    (``S = sel``, all variables by default)."""
    F = Fraction
    h, n = C.shape[0], y.size
    sel = range(n) if sel is None else sel
    out = []
    for i, v in zip(range(h), sel):
        cf = [sorted((F(C[i, k]) * F(fl[k]), F(C[i, k]) * F(fh[k]))) for k in range(h)]
        acc_lo = F(y[v]) - sum(c[1] for c in cf)
        acc_hi = F(y[v]) - sum(c[0] for c in cf)
        for j in range(n):
            terms = [sorted((F(C[i, k]) * F(Jl[k, j]), F(C[i, k]) * F(Jh[k, j]))) for k in range(h)]
            d = F(1 if v == j else 0)
            m_lo, m_hi = d - sum(t[1] for t in terms), d - sum(t[0] for t in terms)
            x_lo, x_hi = F(lo[j]) - F(y[j]), F(hi[j]) - F(y[j])
            prods = [m_lo * x_lo, m_lo * x_hi, m_hi * x_lo, m_hi * x_hi]
            acc_lo, acc_hi = acc_lo + min(prods), acc_hi + max(prods)
        out.append((acc_lo, acc_hi))
    return out


@settings(max_examples=100, deadline=None)
@given(systems_with_a_zero())
def test_midpoint_radius_krawczyk_encloses_the_exact_operator(case):
    """The float midpoint-radius evaluation of K(X) holds the exact interval-arithmetic
    K(X) of the same data (C, f(y), J(X)): its error bounds are not too small."""
    from taut.interval._hc4 import evaluate
    from taut.interval._krawczyk import jacobian, krawczyk_image

    system, _, lo, hi = case
    Jl, Jh = jacobian(system, lo, hi)
    assume(np.linalg.cond(0.5 * Jl + 0.5 * Jh) < 1e12)
    C = np.linalg.inv(0.5 * Jl + 0.5 * Jh)
    assume(np.all(np.isfinite(C)))  # a subnormal pivot overflows the inverse
    y = 0.5 * lo + 0.5 * hi
    fl, fh = evaluate(system.tape, y, y)
    kl, kh = krawczyk_image(C, y, fl, fh, Jl, Jh, lo, hi)
    for i, (elo, ehi) in enumerate(_exact_krawczyk(C, y, fl, fh, Jl, Jh, lo, hi)):
        assert _below(kl[i], elo) and _below(ehi, kh[i])


@settings(max_examples=100, deadline=None)
@given(systems_with_a_zero(), st.data())
def test_parametric_krawczyk_encloses_the_exact_operator(case, data):
    """The first ``h < n`` equations solved for ``h`` of the variables, the others
    parameters: the float operator holds the exact one of the same data."""
    from taut.interval._krawczyk import jacobian, krawczyk_rows

    system, _, lo, hi = case
    n = lo.size
    h = data.draw(st.integers(1, n - 1))
    sel = np.array(data.draw(st.permutations(range(n)))[:h])
    Jl, Jh = (J[:h] for J in jacobian(system, lo, hi))
    Ms = (0.5 * Jl + 0.5 * Jh)[:, sel]
    assume(np.linalg.cond(Ms) < 1e12)
    C = np.linalg.inv(Ms)
    assume(np.all(np.isfinite(C)))  # a subnormal pivot overflows the inverse
    y = 0.5 * lo + 0.5 * hi
    fl, fh = (f[:h] for f in evaluate(system.tape, y, y))
    kl, kh = krawczyk_rows(C, sel, y, fl, fh, Jl, Jh, lo, hi)
    for i, (elo, ehi) in enumerate(_exact_krawczyk(C, y, fl, fh, Jl, Jh, lo, hi, sel)):
        assert _below(kl[i], elo) and _below(ehi, kh[i])


def _tube(system, h, lo, hi, points=0, primary=None):
    """The tube step with the Jacobian over the box (``points=0``) or the slopes; the
    variables not ``primary`` are solved for first."""
    from taut.interval._branch_prune import tube_variables
    from taut.interval._krawczyk import tube_kernel
    from taut.interval._slope import slopes

    vl, vh = slopes(system, lo, hi, points)
    primary = np.ones(lo.size, bool) if primary is None else primary
    gvars, dependent = tube_variables(system, h, primary)
    return tube_kernel(
        *system.tape.arrays[:5], system.tape.end, h, gvars, dependent, system.rows, system.cols, vl, vh, lo, hi
    )


@settings(max_examples=300, deadline=None)
@given(systems_with_a_zero(), st.data())
def test_tube_contraction_never_loses_a_point_of_the_manifold(case, data):
    """A common zero of the first ``h`` equations stays in the contracted box, with the
    Jacobian over the box or the slopes (the equations are quadratic: one node), whichever
    variables are forced to be solved for."""
    system, s, lo, hi = case
    h = data.draw(st.integers(1, lo.size - 1))
    used = np.unique(system.cols[system.rows < h])
    assume(used.size > h)
    primary = np.ones(lo.size, bool)
    primary[data.draw(st.lists(st.sampled_from(used.tolist()), max_size=h, unique=True))] = False
    assert _tube(system, h, lo, hi, data.draw(st.sampled_from([0, 1])), primary) != 2
    assert np.all(lo <= s) and np.all(s <= hi)


#: a circle: the unit sphere cut by the tilted plane x + 2y + 3z = 1, then a third equation
#: that picks two of its points (the tube is the first two)
X3D, Y3D, Z3D = variables(3)
CIRCLE = compile_system(3, [X3D**2 + Y3D**2 + Z3D**2 - 1, X3D + 2 * Y3D + 3 * Z3D - 1, X3D - Y3D])


@pytest.mark.parametrize("points", [0, 1])
def test_tube_contraction_shrinks_a_box_to_the_hull_of_its_piece_of_curve(points):
    """Around a point of the circle, the parametric Krawczyk step keeps every point of the
    circle in the box, shrinks the two variables it solves for to within 25 % of the hull
    of the circle's piece in the box, and proves a box off the circle empty."""
    n = np.array([1.0, 2.0, 3.0]) / np.sqrt(14)
    u = np.cross(n, [1.0, 0.0, 0.0])
    u /= np.linalg.norm(u)
    v = np.cross(n, u)
    theta = np.linspace(0.0, 2 * np.pi, 2_000_001)
    pts = n / np.sqrt(14) + np.sqrt(1 - 1 / 14) * (np.cos(theta)[:, None] * u + np.sin(theta)[:, None] * v)
    near = pts[np.abs(theta - 0.7) <= 0.01]
    lo, hi = near.min(axis=0) - 0.02, near.max(axis=0) + 0.02
    piece = pts[np.all((pts >= lo) & (pts <= hi), axis=1)]
    tl, th = lo.copy(), hi.copy()
    assert _tube(CIRCLE, 2, tl, th, points) == 1
    assert np.all((piece >= tl) & (piece <= th))
    hull = piece.max(axis=0) - piece.min(axis=0)
    assert np.sum(th - tl <= 1.25 * hull) >= 2
    assert _tube(CIRCLE, 2, lo + 0.3, hi + 0.3, points) == 2


def test_tube_solves_for_the_variables_that_are_not_primary():
    """On the circle near the point where x barely varies along it, pivoting solves for y
    and z (both shrink); with x not bisected, x must be solved for, and z becomes the
    parameter: it keeps its width.  Forcing three variables for two equations fails."""
    n = np.array([1.0, 2.0, 3.0]) / np.sqrt(14)
    u = np.cross(n, [1.0, 0.0, 0.0])
    u /= np.linalg.norm(u)
    p = n / np.sqrt(14) + np.sqrt(1 - 1 / 14) * (np.cos(0.7) * u + np.sin(0.7) * np.cross(n, u))
    for primary, shrinks in (([True, True, True], [False, True, True]), ([False, True, True], [False, True, False])):
        lo, hi = p - 0.01, p + 0.01
        assert _tube(CIRCLE, 2, lo, hi, 1, np.array(primary)) == 1
        assert list(hi - lo < 0.02 * (1 - 1e-3)) == shrinks
    with pytest.raises(ArgumentError, match="cannot all be solved for"):
        _tube(CIRCLE, 1, lo, hi, 1, np.array([False, False, True]))


@pytest.mark.parametrize("method", ["python", "numba"])
def test_branch_and_prune_with_a_tube_finds_the_same_solutions(method):
    res = {t: branch_and_prune(CIRCLE, [-2.0] * 3, [2.0] * 3, tube=t, method=method) for t in (0, 2)}
    key = lambda r: sorted(tuple(np.round(c.x, 12)) for c in r.solutions)  # noqa: E731
    assert key(res[2]) == key(res[0]) and len(res[0].solutions) == 2
    assert not res[2].undecided
    x, y = variables(2)
    with pytest.raises(ArgumentError, match="under-determined"):  # the first equation has one variable
        branch_and_prune(compile_system(2, [x - 1, x + y]), [-3.0, -3.0], [3.0, 3.0], tube=1)
    with pytest.raises(ArgumentError, match="tube must be"):
        branch_and_prune(CIRCLES, [-3.0, -3.0], [3.0, 3.0], tube=2)


def test_branch_and_prune_finds_all_solutions():
    res = branch_and_prune(CIRCLES, [-3.0, -3.0], [3.0, 3.0])
    xs = sorted(tuple(np.round(c.x, 12)) for c in res.solutions)
    assert xs == [(0.5, round(-np.sqrt(3) / 2, 12)), (0.5, round(np.sqrt(3) / 2, 12))]
    assert not res.undecided


def test_branch_and_prune_cubic_roots_and_inequalities():
    (x,) = variables(1)
    sys = compile_system(1, [(x - 1) * (x - 2) * (x + 3)], [(x, (0.0, np.inf))])
    res = branch_and_prune(sys, [-10.0], [10.0])
    assert sorted(round(float(c.x[0]), 12) for c in res.solutions) == [1.0, 2.0]


@settings(max_examples=50, deadline=None)
@given(st.lists(st.floats(-3, 3), min_size=9, max_size=9), st.lists(st.floats(-3, 3), min_size=3, max_size=3))
def test_preconditioned_gauss_encloses_the_solution(a, x):
    A = np.array(a).reshape(3, 3) + 10 * np.eye(3)
    x = np.array(x)
    b = A @ x
    out = preconditioned_solve(A, A, b - 1e-9, b + 1e-9)
    assert out is not None
    lo, hi = out
    assert np.all(lo <= x + 1e-7) and np.all(x - 1e-7 <= hi)


@pytest.mark.parametrize("passes", [1, 3])
def test_compiled_and_python_loops_agree(passes):
    """The Numba driver and the reference Python loop find the same certified solutions."""
    ref = branch_and_prune(CIRCLES, [-3.0, -3.0], [3.0, 3.0], method="python")
    fast = branch_and_prune(CIRCLES, [-3.0, -3.0], [3.0, 3.0], method="numba", passes=passes)
    key = lambda r: sorted(tuple(np.round(c.x, 12)) for c in r.solutions)  # noqa: E731
    assert key(fast) == key(ref) and not fast.undecided
    assert fast.boxes > 0 and sum(fast.stats.values()) > 0
    assert all(c.radius > 0 and c.width < 1e-6 for c in fast.solutions)


@pytest.mark.parametrize("method", ["python", "numba"])
def test_smear_bisection_finds_the_same_solutions_with_fewer_boxes_on_a_badly_scaled_system(method):
    """Circles of Example 1 with ``y`` scaled by 100: the widest variable is ``y`` long after
    the equations stopped depending on it much; the smear rule follows ``x``."""
    x, y = variables(2)
    sys = compile_system(2, [x**2 + (y / 100) ** 2 - 1, (x - 1) ** 2 + (y / 100) ** 2 - 1])
    res = {
        b: branch_and_prune(sys, [-3.0, -300.0], [3.0, 300.0], bisection=b, method=method) for b in ("width", "smear")
    }
    key = lambda r: sorted(tuple(np.round(c.x, 9)) for c in r.solutions)  # noqa: E731
    s = round(50 * np.sqrt(3), 9)
    assert key(res["smear"]) == key(res["width"]) == [(0.5, -s), (0.5, s)]
    assert not res["smear"].undecided
    assert res["smear"].boxes < res["width"].boxes
    with pytest.raises(ArgumentError, match="bisection"):
        branch_and_prune(sys, [-3.0, -300.0], [3.0, 300.0], bisection="largest")


@settings(max_examples=100, deadline=None)
@given(systems_with_a_zero(), st.floats(0.01, 1.0))
def test_relative_smears_share_out_each_equation(case, shrink):
    """Each equation's relative smears sum to 1 over the variables it depends on; a
    variable outside ``primary`` has none."""
    system, s, lo, hi = case
    lo, hi = s - shrink * (s - lo) - 0.01, s + shrink * (hi - s) + 0.01
    n = lo.size
    primary = np.arange(n) != n - 1
    score = smear_scores(*system.jacobian.arrays[:7], system.rows, system.cols, system.n_equations, lo, hi, primary)
    assert score[-1] == 0.0 and np.all(score >= 0.0)
    Jl, Jh = jacobian(system, lo, hi)
    rows = np.sum(np.any(np.maximum(np.abs(Jl), np.abs(Jh)) * (hi - lo) * primary > 0, axis=1))
    assert np.isclose(score.sum(), rows)
    j = bisect_index(hi - lo, primary, 1e-7, score, np.inf)
    assert primary[j] and score[j] == score.max()


X3, Y3 = variables(2)
_COMMON = (X3 - Y3) ** 2 * (X3 + 1)
#: a shared product, a constraint equal to an earlier one's subexpression, and a structural
#: copy of it built from new objects (merged by hash-consing)
SHARED_EXPRS = [_COMMON + Y3, _COMMON * 2, _COMMON, X3 * Y3 - 3, (X3 - Y3) ** 2 * (X3 + 1)]


@settings(max_examples=100, deadline=None)
@given(st.lists(st.floats(-5, 5), min_size=2, max_size=2), st.lists(st.floats(0, 3), min_size=2, max_size=2))
def test_a_shared_tape_evaluates_every_constraint_as_it_alone(centre, radius):
    bounds = [(-np.inf, np.inf)] * len(SHARED_EXPRS)
    shared = compile_tape(SHARED_EXPRS, bounds)
    alone = [compile_tape([e], bounds[:1]) for e in SHARED_EXPRS]
    assert shared.op.size < sum(t.op.size for t in alone)
    # x is one node, used by x − y, x + 1 and x·y; the root of the last constraint by none
    assert shared.parents(0) == 3 and shared.parents(shared.end[-1] - 1) == 0
    lo, hi = np.array(centre) - radius, np.array(centre) + radius
    vl, vh = evaluate(shared, lo, hi)
    point = evaluate_point(shared, lo)
    for c, t in enumerate(alone):
        al, ah = evaluate(t, lo, hi)
        assert vl[c] == al[0] and vh[c] == ah[0]
        assert point[c] == evaluate_point(t, lo)[0]


@settings(max_examples=200, deadline=None)
@given(st.lists(st.floats(-5, 5), min_size=2, max_size=2), st.lists(st.floats(0, 3), min_size=4, max_size=4))
def test_dag_contraction_keeps_every_point_that_satisfies_the_constraints(point, pads):
    """HC4 over the shared DAG (one sweep each way for all constraints) is sound: a point
    whose constraint values lie in the bounds is never cut from a box that holds it."""
    x = np.array(point)
    xl, xh = evaluate(compile_tape(SHARED_EXPRS, [(-np.inf, np.inf)] * len(SHARED_EXPRS)), x, x)
    tape = compile_tape(SHARED_EXPRS, list(zip(xl, xh)))
    lo, hi = x - np.array(pads[:2]), x + np.array(pads[2:])
    assert contract(tape, lo, hi)
    assert np.all(lo <= x) and np.all(x <= hi)


def test_compiled_loop_with_a_linear_filter_matches_the_python_filter():
    """x² + y² = 1 with a tension-like unknown t: (1 + x²) t = 2 (the LinearFilter bounds t)."""
    x, y, t = variables(3)
    sys = compile_system(3, [x**2 + y**2 - 1, x - y, (1 + x**2) * t - 2])
    filt = LinearFilter(compile_tape([1 + x**2, const(2.0)], [(-np.inf, np.inf)] * 2), 1)
    lo, hi = np.array([-2.0, -2.0, 0.0]), np.array([2.0, 2.0, np.inf])
    primary = np.array([True, True, False])
    res = {
        m: branch_and_prune(sys, lo, hi, primary=primary, filters=(filt,), method=m, certify_width=1.0)
        for m in ("python", "numba")
    }
    for r in res.values():
        xs = sorted(tuple(np.round(c.x, 10)) for c in r.solutions)
        s = np.sqrt(0.5)
        assert xs == [
            (-round(s, 10), -round(s, 10), round(2 / 1.5, 10)),
            (round(s, 10), round(s, 10), round(2 / 1.5, 10)),
        ]
        assert not r.undecided
    b_lo, b_hi = np.array([0.5, 0.5, 0.0]), np.array([0.75, 0.75, np.inf])
    assert filt(b_lo, b_hi) and 2 / (1 + 0.75**2) * (1 - 1e-12) <= b_lo[2] and b_hi[2] <= 2 / 1.25 * (1 + 1e-12)
    with pytest.raises(ArgumentError):
        branch_and_prune(sys, lo, hi, filters=(lambda lo, hi: True,), method="numba")


def test_filters_run_only_on_boxes_narrower_than_filter_width():
    """The filter is skipped on boxes whose primary variables are wider than
    ``filter_width``; the solutions stay the same in both loops."""
    x, y, t = variables(3)
    sys = compile_system(3, [x**2 + y**2 - 1, x - y, (1 + x**2) * t - 2])
    filt = LinearFilter(compile_tape([1 + x**2, const(2.0)], [(-np.inf, np.inf)] * 2), 1)
    lo, hi = np.array([-2.0, -2.0, 0.0]), np.array([2.0, 2.0, np.inf])
    primary = np.array([True, True, False])
    widths = []

    def spy(blo, bhi):
        widths.append(np.max((bhi - blo)[primary]))
        return filt(blo, bhi)

    key = lambda r: sorted(tuple(np.round(c.x, 10)) for c in r.solutions)  # noqa: E731
    every = branch_and_prune(sys, lo, hi, primary=primary, filters=(filt,), method="python", certify_width=1.0)
    narrow = {
        m: branch_and_prune(
            sys,
            lo,
            hi,
            primary=primary,
            filters=(spy if m == "python" else filt,),
            method=m,
            certify_width=1.0,
            filter_width=0.5,
        )
        for m in ("python", "numba")
    }
    assert widths and max(widths) < 0.5
    assert all(key(r) == key(every) and len(r.solutions) == 2 and not r.undecided for r in narrow.values())


def test_float_inverse_flags_singular_matrices():
    ok, inv = float_inverse(np.array([[2.0, 1.0], [1.0, 3.0]]))
    assert ok and np.allclose(inv @ np.array([[2.0, 1.0], [1.0, 3.0]]), np.eye(2))
    assert not float_inverse(np.array([[1.0, 2.0], [2.0, 4.0]]))[0]
    assert not float_inverse(np.array([[np.inf, 0.0], [0.0, 1.0]]))[0]
