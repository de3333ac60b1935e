"""Tension distribution (``taut.statics._tension``): equilibrium and bounds of every method
on the built-in robots, agreement of the exact methods with ``scipy.optimize.linprog`` on
random problems, known solutions, infeasible poses, shapes and bad input."""

import dataclasses
import json

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from scipy.optimize import linprog

import taut
from taut.errors import TautError
from taut.kinematics import structure_matrix
from taut.model import robot_from_dict
from taut.statics import distribute_tensions, external_wrench
from taut.statics._tension import METHODS, TensionResult, solve_tensions

EXACT = ["lp", "qp", "inf", "barycentric"]
CLOSED = ["closed-form", "improved-closed-form"]

POSES = {
    "planar-4cable": [[0.0, 0.0, 0.0], [0.1, 0.2, 0.1], [0.3, -0.2, 0.0]],
    "spatial-8cable": [[0.0] * 6, [0.1, 0.2, 0.1, 0.1, 0.05, 0.2]],
}


def assert_balanced(W, w, tmin, tmax, tau):
    """Equilibrium to 1e-9 relative (to ``max(‖w‖∞, max|W| ‖τ‖∞)``) and bounds, per pose."""
    tau = np.atleast_2d(tau)
    W = np.broadcast_to(W, (len(tau), *np.shape(W)[-2:]))
    w = np.broadcast_to(w, (len(tau), W.shape[1]))
    res = np.abs(np.einsum("kij,kj->ki", W, tau) + w).max(axis=1)
    scale = np.maximum(np.abs(w).max(axis=1), np.abs(W).max(axis=(1, 2)) * np.abs(tau).max(axis=1))
    assert np.all(res <= 1e-9 * scale), res / scale
    assert np.all(tau >= tmin) and np.all(tau <= tmax)


def oracle(W, w, tmin, tmax):
    ub = [None if np.isinf(x) else x for x in tmax]
    return linprog(np.ones(W.shape[1]), A_eq=W, b_eq=-w, bounds=list(zip(tmin, ub)), method="highs")


# ---- the built-in robots ---------------------------------------------------------------


@pytest.mark.parametrize("method", list(METHODS))
@pytest.mark.parametrize("name", list(POSES))
def test_examples_balance_within_bounds(name, method):
    robot = taut.example(name)
    poses = np.array(POSES[name])
    res = distribute_tensions(robot, poses, method=method)
    assert isinstance(res, TensionResult) and res.method == method
    assert res.tensions.shape == (len(poses), robot.n_cables)
    assert res.feasible.all() and (res.status == "optimal").all()
    W = structure_matrix(robot, poses)
    w = taut.statics.external_wrench(robot, poses)
    tmin, tmax = robot.tension_bounds
    assert_balanced(W, w, tmin, tmax, res.tensions)


@pytest.mark.parametrize("name", list(POSES))
def test_examples_objectives_ordered(name):
    """Each exact method is best in its own norm among all methods."""
    robot = taut.example(name)
    res = {m: distribute_tensions(robot, POSES[name], method=m).tensions for m in METHODS}
    for m, t in res.items():
        assert np.all(res["lp"].sum(1) <= t.sum(1) * (1 + 1e-9)), m
        assert np.all(np.linalg.norm(res["qp"], axis=1) <= np.linalg.norm(t, axis=1) * (1 + 1e-9)), m
        assert np.all(res["inf"].max(1) <= t.max(1) * (1 + 1e-9)), m


def cube_robot():
    """8 cables from the corners of a 2 m cube to the corners of a 0.2 m cubic platform,
    uncrossed: at the centre every cable passes through the platform centre."""
    corners = [[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1], [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]]
    return robot_from_dict(
        {
            "format": "taut/1",
            "name": "cube",
            "dimension": 3,
            "platform": {"kind": "rigid", "mass": 5.0, "wrench_point": [0, 0, 0]},
            "cables": [{"exit": c, "anchor": [0.1 * x for x in c], "tension": [5, 500]} for c in corners],
        }
    )


def test_rank_deficient_pose_is_solved():
    """At the centre of the uncrossed cube robot W has rank 3 (no moments)."""
    robot = cube_robot()
    W = structure_matrix(robot, [0.0] * 6)
    assert np.linalg.matrix_rank(W) == 3
    for m in METHODS:
        r = distribute_tensions(robot, [0.0] * 6, method=m)
        assert r.feasible and r.status == "optimal", m
        assert_balanced(W, taut.statics.external_wrench(robot, [0.0] * 6), 5, 500, r.tensions)
        if m not in ("lp", "inf"):  # unique answers inherit the symmetry of the pose
            assert np.allclose(r.tensions[:4], r.tensions[0]) and np.allclose(r.tensions[4:], r.tensions[4]), m


def test_single_and_batch_shapes():
    robot = taut.example("planar-4cable")
    one = distribute_tensions(robot, [0.1, 0.2, 0.1], method="lp")
    assert one.tensions.shape == (4,)
    assert isinstance(one.feasible, bool) and isinstance(one.status, str)
    many = distribute_tensions(robot, POSES["planar-4cable"], method="lp")
    assert many.tensions.shape == (3, 4) and many.feasible.shape == (3,) and many.status.shape == (3,)
    assert np.allclose(many.tensions[1], one.tensions)


def test_result_is_frozen_read_only_and_json():
    robot = taut.example("planar-4cable")
    many = distribute_tensions(robot, POSES["planar-4cable"])
    with pytest.raises(ValueError, match="read-only"):
        many.tensions[0, 0] = 1.0
    with pytest.raises(ValueError, match="read-only"):
        many.feasible[0] = False
    with pytest.raises(dataclasses.FrozenInstanceError):
        many.method = "qp"  # type: ignore[misc]
    back = json.loads(json.dumps(many.as_dict(), allow_nan=False))
    assert back == {
        "tensions": many.tensions.tolist(),
        "feasible": many.feasible.tolist(),
        "status": many.status.tolist(),
        "method": "lp",
        "actuator_forces": [[] for _ in many.tensions],
    }
    one = distribute_tensions(robot, POSES["planar-4cable"][1], method="qp").as_dict()
    assert one["feasible"] is True and one["status"] == "optimal" and len(one["tensions"]) == 4


def test_explicit_wrench_shared_by_poses():
    robot = taut.example("spatial-8cable")
    res = distribute_tensions(robot, POSES["spatial-8cable"], wrench=np.zeros(6), method="qp")
    assert res.feasible.all()
    # no load: the minimum 2-norm is set by the lower bounds' pretension alone
    assert np.all(res.tensions >= 5.0) and np.all(res.tensions.min(axis=1) == pytest.approx(5.0))


@pytest.mark.parametrize("method", list(METHODS))
def test_huge_wrench_is_infeasible_zeros_never_nan(method):
    robot = taut.example("spatial-8cable")
    res = distribute_tensions(robot, POSES["spatial-8cable"], wrench=[0, 0, -1e6, 0, 0, 0], method=method)
    assert not res.feasible.any()
    assert np.all(res.tensions == 0.0) and not np.isnan(res.tensions).any()
    expected = "infeasible" if method in EXACT else "not-found"
    assert (res.status == expected).all()


# ---- known solutions ---------------------------------------------------------------------


def test_known_solutions_one_dof():
    W = np.array([[[1.0, 2.0, 3.0]]])
    w = np.array([[-6.0]])
    lo, hi = np.zeros(3), np.full(3, 10.0)
    assert np.allclose(solve_tensions(W, w, tension_bounds=(lo, hi), method="lp").tensions, [[0, 0, 2]])
    assert np.allclose(
        solve_tensions(W, w, tension_bounds=(lo, hi), method="qp").tensions, [np.array([1, 2, 3]) * 6 / 14]
    )
    assert np.allclose(solve_tensions(W, w, tension_bounds=(lo, hi), method="inf").tensions, [[1, 1, 1]])
    # the feasible set is the triangle (6,0,0), (0,3,0), (0,0,2)
    assert np.allclose(solve_tensions(W, w, tension_bounds=(lo, hi), method="barycentric").tensions, [[2, 1, 2 / 3]])


def test_improved_closed_form_succeeds_where_closed_form_gives_up():
    W, w, lo, hi = np.array([[1.0, 2.0, 3.0]]), np.array([-6.0]), np.zeros(3), np.full(3, 10.0)
    cf = solve_tensions(W, w, tension_bounds=(lo, hi), method="closed-form")
    assert cf.status == "not-found" and not cf.feasible and np.all(cf.tensions == 0)
    icf = solve_tensions(W, w, tension_bounds=(lo, hi), method="improved-closed-form")
    assert icf.feasible and icf.status == "optimal"
    # cable 3 fixed at its lower bound, then the closed form on cables 1, 2 (τm = 5)
    assert np.allclose(icf.tensions, [5 - 9 / 5, 5 - 18 / 5, 0.0])


def test_closed_form_without_upper_bound_uses_lower_bound_as_reference():
    res = solve_tensions(
        np.array([[1.0, 1.0]]), np.array([-4.0]), tension_bounds=(np.ones(2), np.full(2, np.inf)), method="closed-form"
    )
    assert res.feasible and np.allclose(res.tensions, [2.0, 2.0])


def test_barycentric_flat_polytope_uses_its_affine_hull():
    """Cable 3 has τ_min = τ_max: the polytope is the segment τ1 + τ2 = 4 in the plane τ3 = 2."""
    res = solve_tensions(
        np.array([[1.0, 1.0, 1.0]]), np.array([-6.0]), tension_bounds=([0, 0, 2], [10, 10, 2]), method="barycentric"
    )
    assert res.feasible and np.allclose(res.tensions, [2.0, 2.0, 2.0])


def test_barycentric_needs_finite_upper_bounds():
    with pytest.raises(TautError, match="finite upper"):
        solve_tensions(np.eye(2), [-1.0, -1.0], tension_bounds=([0, 0], [np.inf, 1.0]), method="barycentric")


def test_dependent_rows_and_columns():
    W = np.array([[1.0, -1.0, 2.0, 2.0], [2.0, -2.0, 4.0, 4.0]])  # rank 1
    w = np.array([-3.0, -6.0])
    lo, hi = np.zeros(4), np.full(4, 5.0)
    for m in METHODS:
        r = solve_tensions(W, w, tension_bounds=(lo, hi), method=m)
        assert r.feasible, m
        assert_balanced(W[None], w, lo, hi, r.tensions)
    w_out = np.array([-3.0, -5.0])  # not in the range of W
    for m in EXACT:
        r = solve_tensions(W, w_out, tension_bounds=(lo, hi), method=m)
        assert r.status == "infeasible" and np.all(r.tensions == 0), m


# ---- random problems against linprog -----------------------------------------------------


@st.composite
def problems(draw):
    m = draw(st.integers(1, 4))
    n = draw(st.integers(1, 6))
    num = st.floats(-3, 3).map(lambda x: round(x, 2))
    W = np.array(draw(st.lists(num, min_size=m * n, max_size=m * n))).reshape(m, n)
    tmin = np.array(draw(st.lists(st.floats(0, 2).map(lambda x: round(x, 2)), min_size=n, max_size=n)))
    width = np.array(draw(st.lists(st.floats(0, 10).map(lambda x: round(x, 2)), min_size=n, max_size=n)))
    tmax = np.full(n, np.inf) if draw(st.booleans()) and draw(st.booleans()) else tmin + width
    if draw(st.booleans()):  # a wrench that some tensions balance, possibly perturbed
        u = np.array(draw(st.lists(st.floats(0, 1), min_size=n, max_size=n)))
        t = tmin + u * np.where(np.isfinite(tmax), width, 5.0)
        w = np.round(-W @ t * draw(st.sampled_from([1.0, 0.9, 1.3])), 4)  # no margins below 1e-4
    else:
        w = np.array(draw(st.lists(st.floats(-20, 20).map(lambda x: round(x, 1)), min_size=m, max_size=m)))
    return W, w, tmin, tmax


@settings(max_examples=300, deadline=None)
@given(problems())
def test_random_problems_against_linprog(problem):
    W, w, tmin, tmax = problem
    # A wrench off the range of a rank-deficient W by between the two tolerances (ours is
    # relative, 1e-9; HiGHS's absolute, 1e-7) is decided differently by each, rightly: skip it.
    U, S, _ = np.linalg.svd(W)
    off = np.linalg.norm(U[:, int(np.sum(S > S.max(initial=0) * 1e-12)) :].T @ w)
    assume(not 1e-12 * (1 + np.linalg.norm(w)) < off < 1e-6)
    ref = oracle(W, w, tmin, tmax)
    feasible = ref.status == 0
    assert ref.status in (0, 2)
    res = {}
    for m in METHODS:
        if m == "barycentric" and np.isinf(tmax).any():
            continue
        r = res[m] = solve_tensions(W, w, tension_bounds=(tmin, tmax), method=m)
        assert r.tensions.shape == (W.shape[1],) and not np.isnan(r.tensions).any()
        if r.feasible:
            assert r.status == "optimal"
            assert_balanced(W[None], w, tmin, tmax, r.tensions)
        else:
            assert np.all(r.tensions == 0)
        if m in EXACT:
            assert r.feasible == feasible, (m, r.status, ref.message)
            assert r.status == ("optimal" if feasible else "infeasible"), m
        else:
            assert feasible or not r.feasible, m  # sound: never claims an infeasible problem
    if feasible:
        lp = res["lp"].tensions
        assert lp.sum() == pytest.approx(ref.fun, rel=1e-7, abs=1e-9)
        assert np.linalg.norm(res["qp"].tensions) <= np.linalg.norm(lp) * (1 + 1e-9) + 1e-12
        assert res["inf"].tensions.max(initial=0) <= lp.max(initial=0) * (1 + 1e-9) + 1e-12


def test_batch_agrees_with_single_poses():
    rng = np.random.default_rng(7)
    W = rng.normal(size=(30, 3, 5))
    w = -np.einsum("kij,kj->ki", W, rng.uniform(0, 4, (30, 5))) * rng.uniform(0.7, 1.4, (30, 1))
    lo, hi = np.zeros(5), np.full(5, 4.0)
    for m in METHODS:
        batch = solve_tensions(W, w, tension_bounds=(lo, hi), method=m)
        for k in range(0, 30, 3):
            one = solve_tensions(W[k], w[k], tension_bounds=(lo, hi), method=m)
            assert one.feasible == batch.feasible[k] and one.status == batch.status[k], m
            if m in ("qp", "closed-form", "improved-closed-form", "barycentric"):  # unique answers
                assert np.allclose(one.tensions, batch.tensions[k], atol=1e-8), m
        assert_balanced(W[batch.feasible], w[batch.feasible], lo, hi, batch.tensions[batch.feasible])


# ---- bad input ---------------------------------------------------------------------------


def test_unknown_method_lists_valid_ones():
    with pytest.raises(TautError, match="valid methods: lp, qp, inf, closed-form, improved-closed-form, barycentric"):
        solve_tensions(np.eye(2), [0, 0], tension_bounds=([0, 0], [1, 1]), method="simplex")
    with pytest.raises(TautError, match="valid methods"):
        distribute_tensions(taut.example("planar-4cable"), [0, 0, 0], method="nope")


@pytest.mark.parametrize(
    "W, w, lo, hi, match",
    [
        (np.eye(2), [0.0, 0.0, 0.0], [0, 0], [1, 1], "wrench must have shape"),
        (np.ones(3), [0.0], [0], [1], "structure matrix must have shape"),
        (np.eye(2), [np.nan, 0.0], [0, 0], [1, 1], "non-finite"),
        (np.array([[1.0, np.inf]]), [0.0], [0, 0], [1, 1], "non-finite"),
        (np.eye(2), [0.0, 0.0], [0, 0, 0], [1, 1], "lower tension bounds must have shape"),
        (np.eye(2), [0.0, 0.0], [2, 0], [1, 1], "inverted"),
        (np.eye(2), [0.0, 0.0], [-1, 0], [1, 1], ">= 0"),
        (np.eye(2), [0.0, 0.0], [0, 0], [np.nan, 1], "NaN"),
        (np.ones((3, 2, 2)), np.zeros((2, 2)), [0, 0], [1, 1], "3 structure matrices but 2 wrenches"),
    ],
)
def test_bad_input_raises_taut_error(W, w, lo, hi, match):
    with pytest.raises(TautError, match=match):
        solve_tensions(W, w, tension_bounds=(lo, hi))


@pytest.mark.parametrize(
    "call, match",
    [
        (lambda: solve_tensions(np.eye(2), [0.0, 0.0], tension_bounds=None), "must be a pair"),
        (lambda: solve_tensions(np.eye(2), [0.0, 0.0], tension_bounds=(0, 1, 2)), "must be a pair"),
        (lambda: solve_tensions(np.eye(2), [0.0, 0.0], tension_bounds=(0, 1), method=["lp"]), "unknown"),
        (lambda: distribute_tensions(taut.example("planar-4cable"), [0.1, 0.2, 0.0], method=None), "unknown"),
        (lambda: distribute_tensions(taut.example("planar-4cable"), [0.1, 0.2, 0.0], wrench="ab"), "numbers"),
    ],
)
def test_bad_options_raise_taut_error(call, match):
    with pytest.raises(TautError, match=match):
        call()


def test_tension_bounds_override_the_robots():
    """``tension_bounds`` replaces ``robot.tension_bounds``: bounds too low for the weight make
    the pose infeasible, the same as a robot whose cables carry them."""
    robot = taut.example("planar-4cable")
    pose = POSES["planar-4cable"][1]
    assert distribute_tensions(robot, pose).feasible
    low = distribute_tensions(robot, pose, tension_bounds=(0.0, 1e-3))
    assert not low.feasible and low.status == "infeasible"
    W = structure_matrix(robot, pose)
    w = external_wrench(robot, pose)
    bounds = (np.full(4, 2.0), np.full(4, 50.0))
    res = distribute_tensions(robot, pose, tension_bounds=bounds, method="qp")
    assert res.feasible and np.all(res.tensions >= 2.0 - 1e-12) and np.all(res.tensions <= 50.0)
    np.testing.assert_allclose(W @ res.tensions + w, 0.0, atol=1e-9 * np.abs(w).max())
