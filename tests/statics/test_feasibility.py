"""Hyperplane-shifting feasibility tests against LP oracles (scipy.optimize.linprog)."""

import numpy as np
import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st
from scipy.optimize import linprog

from taut.errors import TautError
from taut.statics._feasibility import facet_normals, static_equilibrium, wrench_closure, wrench_feasible
from taut.statics._wrench import BoxWrenchSet, EllipsoidWrenchSet, PolytopeWrenchSet, SingleWrench, WrenchSet


def lp_equilibrium(W, tmin, tmax, w) -> bool:
    """Oracle: is there tmin <= t <= tmax with W t + w = 0?"""
    bounds = [(lo, None if np.isinf(hi) else hi) for lo, hi in zip(tmin, tmax)]
    res = linprog(np.zeros(W.shape[1]), A_eq=W, b_eq=-np.asarray(w), bounds=bounds, method="highs")
    return res.status == 0


def lp_closure(W) -> bool:
    """Oracle: full row rank and a strictly positive null vector (W t = 0, t >= 1)."""
    m, n = W.shape
    if np.linalg.matrix_rank(W) < m:
        return False
    res = linprog(np.zeros(n), A_eq=W, b_eq=np.zeros(m), bounds=[(1, None)] * n, method="highs")
    return res.status == 0


# Entries on a coarse lattice (multiples of 1/4): exact degeneracies (coplanar columns,
# zero dot products, rank deficiency) happen often, and no verdict sits within LP
# tolerance of a boundary without being on it.
lattice = st.integers(-8, 8).map(lambda k: k / 4)


@st.composite
def problems(draw, m_choices=(2, 3, 6), max_n=9):
    m = draw(st.sampled_from(m_choices))
    n = draw(st.integers(1, max_n))
    rank = draw(st.integers(1, m))
    left = np.array(draw(st.lists(lattice, min_size=m * rank, max_size=m * rank))).reshape(m, rank)
    right = np.array(draw(st.lists(lattice, min_size=rank * n, max_size=rank * n))).reshape(rank, n)
    W = left @ right if rank < m else np.array(draw(st.lists(lattice, min_size=m * n, max_size=m * n))).reshape(m, n)
    tmin = np.array(draw(st.lists(st.integers(0, 4), min_size=n, max_size=n)), float)
    width = np.array(draw(st.lists(st.integers(0, 6), min_size=n, max_size=n)), float)
    tmax = tmin + width
    inf = np.array(draw(st.lists(st.booleans(), min_size=n, max_size=n)))
    if draw(st.booleans()):
        tmax[inf] = np.inf
    w = np.array(draw(st.lists(lattice, min_size=m, max_size=m))) * 2
    return W, tmin, tmax, w


# rank W = 2 < m = 3 with zero columns, a cable pinned at 1 and unbounded ones: the facet
# normal of the flat zonotope, (−2.6e-17, −0.32, 0.95) by round-off, met the pinned
# cable's wrench (−0.3125, 0, 0) at n·o = 8e-18 > 0 and rejected a feasible pose
FLAT_PINNED = (
    np.array([[0, 0, -0.3125, 0.3125, 0, 0, 0.3125], [0, 0, 0, 0.1875, 0, 0, 0], [0, 0, 0, 0.0625, 0, 0, 0]]),
    np.array([0, 0, 1, 0, 0, 0, 0], float),
    np.array([0, 0, 1, 1, 0, np.inf, np.inf]),
    np.zeros(3),
)


# W of rank 5 < m = 6 whose facet normals showed |n·w_j| = 1.8e-12 ‖w_j‖ by round-off: taken
# for rank 6, the pose was declared feasible
RANK5 = (
    np.array(
        [
            [0.375, 0, 0.1875, 0, -0.0625, 0.5, 0, 0.25, 0],
            [0.125, 0, 0.125, 0, 0.5, -0.375, 0, 0.375, 0],
            [-0.1875, 0, 0.125, 0.125, 0.25, 0, 0, -0.125, 0],
            [3.75, 0, -0.0625, 0.125, 0.1875, 1.25, 0, 3.5, 0],
            [2.1875, 0, -0.125, 0.125, 0.25, 0.5, 0, 2.125, 0],
            [-0.0625, 0, 0.25, 0, -0.25, -0.5, 0, 0.125, 0],
        ]
    ),
    np.zeros(9),
    np.array([np.inf, 0, np.inf, np.inf, 1, np.inf, 0, np.inf, 0]),
    np.array([0, 0, 0, 0, 0, -0.5]),
)


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(problems())
@example(FLAT_PINNED)
@example(RANK5)
def test_static_equilibrium_agrees_with_lp(prob):
    W, tmin, tmax, w = prob
    assert static_equilibrium(W[None], w[None], tension_bounds=(tmin, tmax))[0] == lp_equilibrium(W, tmin, tmax, w)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(problems(m_choices=(2, 3)), st.lists(st.integers(0, 2).map(lambda k: k / 4), min_size=3, max_size=3))
@example(FLAT_PINNED, [0.0, 0.0, 0.0])
@example(FLAT_PINNED, [0.25, 0.0, 0.0])  # a box along the flat zonotope, |n_x| ~ 1e-17
def test_box_feasibility_agrees_with_lp_over_vertices(prob, half):
    W, tmin, tmax, w = prob
    m = W.shape[0]
    box = BoxWrenchSet.around(np.zeros(m), half[:m])
    expected = all(lp_equilibrium(W, tmin, tmax, w + v) for v in box.vertices())
    assert wrench_feasible(W[None], box, tension_bounds=(tmin, tmax), wrench=w)[0] == expected


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(problems(m_choices=(6,), max_n=9), st.lists(st.integers(0, 2).map(lambda k: k / 4), min_size=6, max_size=6))
def test_spatial_box_feasibility_agrees_with_lp(prob, half):
    W, tmin, tmax, w = prob
    box = BoxWrenchSet.around(np.zeros(6), half)
    expected = all(lp_equilibrium(W, tmin, tmax, w + v) for v in np.unique(box.vertices(), axis=0))
    assert wrench_feasible(W[None], box, tension_bounds=(tmin, tmax), wrench=w)[0] == expected


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(problems())
def test_wrench_closure_agrees_with_lp(prob):
    W = prob[0]
    assert wrench_closure(W[None])[0] == lp_closure(W)


def test_random_spatial_batch_agrees_with_lp():
    """Continuous random data, a batch of poses with mixed verdicts, m = 6, n = 8."""
    rng = np.random.default_rng(7)
    N = 60
    W = rng.normal(size=(N, 6, 8))
    tmin, tmax = np.full(8, 1.0), np.full(8, 8.0)
    tau = rng.uniform(0, 9, size=(N, 8))
    w = -np.einsum("kij,kj->ki", W, tau)  # balanced by tau, which may violate the bounds
    box = BoxWrenchSet.around(np.zeros(6), np.full(6, 0.3))
    got = wrench_feasible(W, box, tension_bounds=(tmin, tmax), wrench=w)
    expected = [all(lp_equilibrium(W[k], tmin, tmax, w[k] + v) for v in box.vertices()) for k in range(N)]
    assert 0 < got.sum() < N
    assert got.tolist() == expected
    got_static = static_equilibrium(W, w, tension_bounds=(tmin, tmax))
    assert got_static.tolist() == [lp_equilibrium(W[k], tmin, tmax, w[k]) for k in range(N)]
    assert np.all(got <= got_static)  # the box contains the single wrench


def test_signs_on_a_hand_example():
    """Planar point mass hanging from two cables pulling up-left and up-right."""
    u = np.array([[-1.0, 1.0], [1.0, 1.0]]).T / np.sqrt(2)
    W = u[None]
    lo, hi = np.zeros(2), np.full(2, 100.0)
    weight = np.array([0.0, -9.81])  # external wrench: gravity pulls down
    assert static_equilibrium(W, weight, tension_bounds=(lo, hi))[0]
    assert not static_equilibrium(W, -weight, tension_bounds=(lo, hi))[0]  # cables cannot push down
    # each cable carries 9.81/sqrt(2) = 6.94 N: a bound of 6.9 N is too small
    assert not static_equilibrium(W, weight, tension_bounds=(lo, np.full(2, 6.9)))[0]
    assert static_equilibrium(W, weight, tension_bounds=(lo, np.full(2, 7.0)))[0]
    # a box of side wrenches: ±1 N sideways needs tension differences within bounds
    box = BoxWrenchSet.around([0.0, 0.0], [1.0, 0.0])
    assert wrench_feasible(W, box, tension_bounds=(lo, hi), wrench=weight)[0]
    assert not wrench_feasible(W, box, tension_bounds=(lo, np.full(2, 7.0)), wrench=weight)[0]
    assert not wrench_closure(W)[0]


def test_closure_of_a_triangle_of_cables():
    dirs = np.array([[1.0, 0.0], [-0.5, 0.8], [-0.5, -0.8]]).T
    assert wrench_closure(dirs[None])[0]
    assert not wrench_closure(dirs[None, :, :2])[0]  # two cables never span the plane positively
    tilted = np.array([[1.0, 0.0], [-0.5, 0.8], [0.5, -0.8]]).T  # all in a half-plane
    assert not wrench_closure(tilted[None])[0]


def test_infinite_upper_bounds_and_zero_dot_products():
    """0·inf must be 0: a column orthogonal to a facet normal with tmax = inf."""
    W = np.array([[1.0, 0.0, -1.0, 0.0], [0.0, 1.0, 0.0, -1.0]])[None]
    lo, hi = np.ones(4), np.full(4, np.inf)
    assert static_equilibrium(W, [5.0, -3.0], tension_bounds=(lo, hi))[0]
    assert wrench_feasible(W, BoxWrenchSet.around([0, 0], [100, 100]), tension_bounds=(lo, hi))[0]
    hi2 = np.array([np.inf, 2.0, 2.0, np.inf])  # column 3 (pushes -x) at most 2
    assert not static_equilibrium(W, [5.0, 0.0], tension_bounds=(lo, hi2))[0]  # needs t1 - t3 = -5
    assert static_equilibrium(W, [1.0, 0.0], tension_bounds=(lo, hi2))[0]


def test_constant_tension_cables_move_into_the_offset():
    W = np.array([[1.0, -1.0, 0.0, 0.0], [0.0, 0.0, 1.0, -1.0]])[None]
    lo = np.array([2.0, 2.0, 0.0, 0.0])
    hi = np.array([2.0, 5.0, 3.0, 3.0])  # cable 1 carries exactly 2 N
    assert static_equilibrium(W, [1.0, 0.0], tension_bounds=(lo, hi))[0]  # t2 = 3
    assert not static_equilibrium(W, [-1.0, 0.0], tension_bounds=(lo, hi))[0]  # t2 = 1 < 2
    assert static_equilibrium(W, [1.0, 0.0], tension_bounds=(lo, hi))[0] == lp_equilibrium(W[0], lo, hi, [1.0, 0.0])


class GenericBox(WrenchSet):
    """A box known only by its support function: exercises the NumPy path."""

    def __init__(self, box):
        self.box = box
        self.dim = box.dim

    def support(self, normals):
        return self.box.support(normals)


@pytest.mark.parametrize("m,n", [(2, 4), (3, 5), (6, 8)])
def test_generic_support_path_matches_the_kernel(m, n):
    rng = np.random.default_rng(m * 10 + n)
    N = 200
    W = rng.normal(size=(N, m, n))
    lo, hi = np.full(n, 0.5), np.full(n, 4.0)
    hi[0] = np.inf
    w = -np.einsum("kij,kj->ki", W, rng.uniform(0, 4.5, (N, n)))
    sets = [
        BoxWrenchSet.around(np.full(m, 0.1), np.full(m, 0.2)),
        EllipsoidWrenchSet(np.zeros(m), np.diag(rng.uniform(0.01, 0.1, m))),
        PolytopeWrenchSet(rng.normal(scale=0.2, size=(5, m))),
    ]
    for ws in sets:
        fast = wrench_feasible(W, ws, tension_bounds=(lo, hi), wrench=w)
        generic = wrench_feasible(
            W, GenericBox(ws) if isinstance(ws, BoxWrenchSet) else _wrap(ws), tension_bounds=(lo, hi), wrench=w
        )
        assert 0 < fast.sum() < N
        assert np.array_equal(fast, generic)


def _wrap(ws):
    class Wrapped(WrenchSet):
        dim = ws.dim

        def support(self, normals):
            return ws.support(normals)

    return Wrapped()


def test_ellipsoid_between_inscribed_and_circumscribed_boxes():
    rng = np.random.default_rng(3)
    N, m, n = 300, 3, 6
    W = rng.normal(size=(N, m, n))
    lo, hi = np.zeros(n), np.full(n, 3.0)
    w = -np.einsum("kij,kj->ki", W, rng.uniform(0, 3, (N, n)))
    r = np.array([0.2, 0.3, 0.1])
    ell = EllipsoidWrenchSet(np.zeros(m), np.diag(r**2))
    inner = BoxWrenchSet.around(np.zeros(m), r / np.sqrt(m))  # inside the ellipsoid
    outer = BoxWrenchSet.around(np.zeros(m), r)  # contains the ellipsoid
    f_ell, f_in, f_out = (wrench_feasible(W, s, tension_bounds=(lo, hi), wrench=w) for s in (ell, inner, outer))
    assert np.all(f_out <= f_ell) and np.all(f_ell <= f_in)
    assert f_out.sum() < f_in.sum()


def test_polytope_equals_box_with_the_same_vertices():
    rng = np.random.default_rng(4)
    W = rng.normal(size=(300, 3, 5))
    lo, hi = np.ones(5), np.full(5, 5.0)
    w = -np.einsum("kij,kj->ki", W, rng.uniform(0, 6, (300, 5)))
    box = BoxWrenchSet([-0.2, -0.1, 0.0], [0.3, 0.1, 0.4])
    assert np.array_equal(
        wrench_feasible(W, box, tension_bounds=(lo, hi), wrench=w),
        wrench_feasible(W, PolytopeWrenchSet(box.vertices()), tension_bounds=(lo, hi), wrench=w),
    )


def test_rank_deficient_structure_matrices():
    """Flat zonotopes: a single wrench goes to the LP, a full-dimensional set is infeasible."""
    W = np.array([[1.0, 0.0, -1.0], [0.0, 0.0, 0.0], [0.0, 1.0, 0.0]])  # rank 2 in R^3
    lo, hi = np.zeros(3), np.full(3, 10.0)
    assert static_equilibrium(W[None], [1.0, 0.0, -2.0], tension_bounds=(lo, hi))[0]
    assert not static_equilibrium(W[None], [1.0, 0.5, -2.0], tension_bounds=(lo, hi))[0]  # out of range(W)
    assert not wrench_feasible(
        W[None], BoxWrenchSet.around(np.zeros(3), [0.1, 0.1, 0.1]), tension_bounds=(lo, hi), wrench=[1.0, 0.0, -2.0]
    )[0]
    # a box flat along the missing direction lies in the plane: decided by vertex LPs
    flat = BoxWrenchSet.around(np.zeros(3), [0.5, 0.0, 0.5])
    assert wrench_feasible(W[None], flat, tension_bounds=(lo, hi), wrench=[1.0, 0.0, -2.0])[0]
    assert not wrench_feasible(W[None], flat, tension_bounds=(lo, hi), wrench=[1.0, 0.0, -0.2])[0]  # needs t2 = -0.3
    # fewer cables than wrench components (under-constrained): 3 cables, m = 6
    W6 = np.zeros((6, 3))
    W6[:3] = np.eye(3)
    assert static_equilibrium(W6[None], [-1.0, -2.0, -3.0, 0, 0, 0], tension_bounds=(np.zeros(3), np.full(3, np.inf)))[
        0
    ]
    assert not static_equilibrium(
        W6[None], [1.0, -2.0, -3.0, 0, 0, 0], tension_bounds=(np.zeros(3), np.full(3, np.inf))
    )[0]
    assert not wrench_closure(W6[None])[0]


def test_facet_normals_are_unit_and_orthogonal_to_their_columns():
    rng = np.random.default_rng(5)
    W = rng.normal(size=(10, 6, 8))
    W[0, :, 3] = W[0, :, 1] * 2  # dependent pair: combinations with both have no normal
    normals, hz, valid = facet_normals(W, tension_bounds=(np.zeros(8), np.ones(8)))
    import itertools

    combos = list(itertools.combinations(range(8), 5))
    assert normals.shape == (10, len(combos), 6)
    for c, cols in enumerate(combos):
        if 1 in cols and 3 in cols:
            assert not valid[0, c]
        else:
            assert valid[0, c]
    n = normals[valid]
    np.testing.assert_allclose(np.linalg.norm(n, axis=-1), 1.0)
    for k in range(10):
        for c, cols in enumerate(combos):
            if valid[k, c]:
                np.testing.assert_allclose(normals[k, c] @ W[k][:, list(cols)], 0.0, atol=1e-12)
                dots = normals[k, c] @ W[k]
                np.testing.assert_allclose(
                    hz[k, c], [np.maximum(dots, 0).sum(), np.maximum(-dots, 0).sum()], atol=1e-12
                )


def test_bad_inputs():
    W = np.eye(2)[None]
    with pytest.raises(TautError):
        wrench_feasible(W, SingleWrench([0.0, 0.0]), tension_bounds=([1, 1], [0, 0]))
    with pytest.raises(TautError):
        wrench_feasible(W, SingleWrench([0.0, 0.0, 0.0]), tension_bounds=([0, 0], [1, 1]))
    with pytest.raises(TautError):
        wrench_feasible(W, SingleWrench([0.0, 0.0]), tension_bounds=([0, 0], [1, 1]), wrench=np.zeros((3, 2)))
    with pytest.raises(TautError):
        wrench_closure(np.full((1, 2, 3), np.nan))


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(problems(m_choices=(2, 3, 6)), st.lists(st.integers(0, 2).map(lambda k: k / 4), min_size=6, max_size=6))
def test_the_lp_method_agrees_with_the_oracles(prob, half):
    """``method="lp"`` (what robots with many cables get): the closure by one LP, a box by
    one LP per vertex, whatever the rank of ``W``."""
    W, tmin, tmax, w = prob
    m = W.shape[0]
    assert wrench_closure(W[None], method="lp")[0] == lp_closure(W)
    assert static_equilibrium(W[None], w[None], tension_bounds=(tmin, tmax), method="lp")[0] == lp_equilibrium(
        W, tmin, tmax, w
    )
    box = BoxWrenchSet.around(np.zeros(m), half[:m])
    expected = all(lp_equilibrium(W, tmin, tmax, w + v) for v in np.unique(box.vertices(), axis=0))
    assert wrench_feasible(W[None], box, tension_bounds=(tmin, tmax), wrench=w, method="lp")[0] == expected


def test_many_cables_are_decided_by_lps_and_an_ellipsoid_is_refused_there():
    """2000 cables in the plane of a point mass: C(2000, 1) normals, the facets; with m = 3
    C(2000, 2) = 2 M normals per pose, LPs decide (the same verdicts as the oracle)."""
    rng = np.random.default_rng(11)
    W = rng.normal(size=(4, 3, 2000))
    W[0] = np.abs(W[0])  # every column in one octant: no closure
    tau = rng.uniform(1.0, 2.0, (4, 2000))
    w = -np.einsum("kij,kj->ki", W, tau)
    assert wrench_closure(W).tolist() == [lp_closure(W[k]) for k in range(4)] == [False, True, True, True]
    got = static_equilibrium(W, w, tension_bounds=(1.0, 2.0))
    assert got.tolist() == [lp_equilibrium(W[k], np.ones(2000), np.full(2000, 2.0), w[k]) for k in range(4)]
    assert got.all()
    ellipsoid = EllipsoidWrenchSet(np.zeros(3), np.eye(3))
    with pytest.raises(TautError, match=r"C\(2000, 2\) = 2e\+06 .* box, polytope"):
        wrench_feasible(W, ellipsoid, tension_bounds=(1.0, 2.0), wrench=w)
    with pytest.raises(TautError, match="unknown method"):
        wrench_closure(W, method="simplex")


def test_under_constrained_poses_are_decided_in_one_closed_form():
    """Fewer cables than wrench components: the tensions balancing a wrench are unique where
    the columns are independent; a batch of such poses, half in range(W) exactly, half off
    it by 1e-3, with tensions on both sides of their bounds, against the LP oracle."""
    rng = np.random.default_rng(2)
    K, m, n = 400, 6, 3
    W = rng.normal(size=(K, m, n))
    tau = rng.uniform(-0.5, 2.0, (K, n))
    w = -np.einsum("kmn,kn->km", W, tau)
    w[::2] += 1e-3 * rng.normal(size=(K // 2, m))
    got = static_equilibrium(W, w, tension_bounds=(0.0, 1.5))
    expected = [lp_equilibrium(W[k], np.zeros(n), np.full(n, 1.5), w[k]) for k in range(K)]
    assert got.tolist() == expected
    assert 20 < got.sum() < K // 2


@pytest.mark.parametrize(
    "call",
    [
        lambda: static_equilibrium("ab", [0.0, 0.0], tension_bounds=(0, 1)),
        lambda: static_equilibrium(np.eye(2), "ab", tension_bounds=(0, 1)),
        lambda: static_equilibrium(np.eye(2), [0.0, 0.0], tension_bounds=("a", 1)),
        lambda: static_equilibrium(np.eye(2), [0.0, 0.0], tension_bounds=([0, 0, 0], 1)),
        lambda: static_equilibrium(np.eye(2), [0.0, 0.0], tension_bounds=None),
        lambda: wrench_feasible(np.eye(2), "not a set", tension_bounds=(0, 1)),
        lambda: wrench_closure("ab"),
        lambda: SingleWrench("ab"),
        lambda: BoxWrenchSet("a", [1.0]),
        lambda: PolytopeWrenchSet("ab"),
        lambda: EllipsoidWrenchSet([0.0, 0.0], "ab"),
        lambda: SingleWrench([1.0, 2.0]).support(np.ones(3)),
        lambda: BoxWrenchSet([0.0], [1.0]).support("x"),
    ],
)
def test_bad_input_is_a_taut_error_never_a_bare_value_error(call):
    """docs/architecture.md §2.7: bad input raises a TautError subclass."""
    with pytest.raises(TautError):
        call()
