"""The DGP on seeded random suspended robots (the small version of
benchmarks/bench_dgp_random.py): no undecided box, and every reported equilibrium checked
here from the robot's data — the taut cables reach their anchors, the slack ones do not, the
tensions are non-negative and balance the weight, forces and moments."""

import numpy as np
import pytest
from fold_robot import fold_robot
from hypothesis import given, settings
from hypothesis import strategies as st

from taut.dgp import solve_dgp
from taut.dgp._solve import solve_subset
from taut.errors import TautError
from taut.geometry import rotation_matrix
from taut.interval import LinearFilter, bisect, compile_tape, const
from taut.kinematics import inverse_kinematics
from taut.model import load_robot, random_planar_robot, random_suspended_robot, save_robot

#: (cables, seed): quick robots of the benchmark suite, coplanar and not, with equilibria on
#: two and three taut cables
SUITE = [(3, 1), (3, 7), (3, 16), (3, 23), (4, 1)]


def check_equilibrium(robot, lengths, sol):
    """Residuals of one reported equilibrium, computed from the robot's data alone."""
    R = rotation_matrix(sol.orientation, robot.orientation)
    b = sol.position + robot.anchors @ R.T
    reach = np.linalg.norm(robot.exits - b, axis=1)
    taut = list(sol.taut)
    slack = [i for i in range(robot.n_cables) if i not in taut]
    assert np.allclose(reach[taut], lengths[taut], rtol=0, atol=1e-7)
    assert np.all(reach[slack] <= lengths[slack] + 1e-9)
    assert np.all(sol.tensions[taut] > 0.0) and np.all(sol.tensions[slack] == 0.0)
    u = (robot.exits - b) / reach[:, None]
    force = sol.tensions @ u + robot.weight
    g = sol.position + R @ np.asarray(robot.platform.wrench_point)
    moment = np.cross(b, sol.tensions[:, None] * u).sum(axis=0) + np.cross(g, robot.weight)
    scale = np.linalg.norm(robot.weight) * (1.0 + np.abs(sol.position).max())
    assert np.abs(force).max() <= 1e-6 * np.linalg.norm(robot.weight)
    assert np.abs(moment).max() <= 1e-6 * scale


@pytest.mark.slow
@pytest.mark.parametrize("n, seed", SUITE)
def test_every_equilibrium_certified_and_checked(n, seed):
    robot, lengths = random_suspended_robot(n, seed=seed)
    res = solve_dgp(robot, lengths)
    assert res.undecided == 0 and res.complete
    assert res.solutions
    for sol in res.solutions:
        check_equilibrium(robot, lengths, sol)


def test_singular_generalised_inverse_does_not_stall():
    """Seed 4, 3 cables: near the pose where the three cables are almost horizontal, the
    preconditioner of Berti's Eq. 3.12, (Wᵀ J)⁻¹ Wᵀ, is singular although J has full rank;
    the statics filter then proved nothing, and the tensions of 4 M boxes ran to 1e308
    (undecided).  With the least-squares preconditioner the filter bounds them."""
    robot, lengths = random_suspended_robot(3, seed=4)
    res = solve_dgp(robot, lengths, max_taut=3)
    assert res.undecided == 0 and len([s for s in res.solutions if len(s.taut) == 3]) == 2


def test_least_squares_preconditioner_encloses_the_solution():
    """An over-determined point system whose Eq. 3.12 preconditioner is exactly singular: the
    enclosure holds the exact solution (the filter's contract), from the least-squares one."""
    F = np.array([[1.0, 0.0, 1.0], [0.0, 1.0, 1.0], [1.0, 1.0, 0.0]])
    # Wᵀ J = Fᵀ M + Mᵀ F is singular for M = F S with S skew-symmetric
    S = np.array([[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 0.0]])
    J = np.vstack([F, F @ S])
    t = np.array([1.0, 2.0, 3.0])
    W = np.vstack([J[3:], J[:3]])
    assert abs(np.linalg.det(W.T @ J)) < 1e-12 and np.linalg.matrix_rank(J) == 3
    tape = compile_tape([const(float(v)) for v in [*J.ravel(), *(J @ t)]], [(-np.inf, np.inf)] * 24)
    lo, hi = np.array([-10.0, -10.0, -10.0]), np.array([10.0, 10.0, 10.0])
    enc = LinearFilter(tape, 3).enclosure(lo, hi)
    assert enc is not None
    assert np.all(enc[0] <= t) and np.all(t <= enc[1]) and np.all(enc[1] - enc[0] < 1e-9)


@pytest.mark.parametrize("n", range(3, 9))
def test_random_robot_file_round_trip(n, tmp_path):
    robot, lengths = random_suspended_robot(n, seed=n)
    path = tmp_path / "random.yaml"
    save_robot(robot, path)
    again = load_robot(str(path))
    assert again == robot
    assert robot.n_cables == n and np.array_equal(np.asarray(robot.reference.lengths), lengths)


@settings(max_examples=25, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(3, 8), coplanar=st.booleans())
def test_random_robot_geometry(seed, n, coplanar):
    robot, lengths = random_suspended_robot(n, seed=seed, coplanar=coplanar)
    a, r = robot.exits, robot.anchors
    g = np.asarray(robot.platform.wrench_point)
    assert np.all(lengths > 0) and robot.weight[2] < 0
    # exits above the platform's drawn pose, anchors coplanar or not, the load point below the
    # platform's plane and, for coplanar anchors, off theirs
    centred = r - r.mean(axis=0)
    normal = np.linalg.svd(centred)[2][-1]
    flat = np.abs(centred @ normal).max()
    assert (flat < 1e-12) if coplanar else (flat > 0)
    assert g[2] < 0 and (not coplanar or abs((g - r.mean(axis=0)) @ normal) > 1e-3)
    assert np.ptp(a[:, 0]) > 1.0 and np.ptp(a[:, 1]) > 1.0
    same = random_suspended_robot(n, seed=seed, coplanar=coplanar)
    assert same[0] == robot and np.array_equal(same[1], lengths)


@pytest.mark.parametrize("n, perturbation", [(2, 0.02), (9, 0.02), (3, -0.1), (3, float("nan"))])
def test_random_robot_refuses_bad_arguments(n, perturbation):
    with pytest.raises(TautError):
        random_suspended_robot(n, seed=0, perturbation=perturbation)


@settings(max_examples=25, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(2, 6))
def test_random_planar_robot_geometry(seed, n, tmp_path_factory):
    robot, lengths = random_planar_robot(n, seed=seed)
    a, r = robot.exits, robot.anchors
    g = np.asarray(robot.platform.wrench_point)
    assert robot.dimension == 2 and robot.pose_names == ["x", "y", "theta"]
    assert np.all(lengths > 0) and robot.weight[1] < 0 and robot.weight[0] == 0
    # exits above the platform's drawn pose, left to right, anchors in the same order: the
    # cables do not cross; the load point is off the line of the first two anchors
    assert np.all(np.diff(a[:, 0]) > 0) and np.all(np.diff(r[:, 0]) > 0) and a[:, 1].min() > 2.0
    e, d = r[1] - r[0], g - r[0]
    assert abs(e[0] * d[1] - e[1] * d[0]) > 1e-6
    same = random_planar_robot(n, seed=seed)
    assert same[0] == robot and np.array_equal(same[1], lengths)
    path = tmp_path_factory.mktemp("planar") / "random.yaml"
    save_robot(robot, path)
    assert load_robot(str(path)) == robot


@pytest.mark.parametrize("n, perturbation", [(1, 0.02), (7, 0.02), (3, -0.1), (3, float("nan"))])
def test_random_planar_robot_refuses_bad_arguments(n, perturbation):
    with pytest.raises(TautError):
        random_planar_robot(n, seed=0, perturbation=perturbation)


@pytest.mark.parametrize("ulps", [-1, 0, 1])
def test_equilibrium_on_the_border_of_two_subsets_reported_once(ulps):
    """Seed 1, 3 cables: its equilibria hang on cables 2 and 3 (0-based 1, 2).  With cable 1's
    length set to its reach at one of them (give or take an ulp) that equilibrium has a zero
    tension in the 3-taut subset and cable 1 exactly at its length in the 2-taut one: both
    sub-problems certified it in a box straddling their bound and dropped it, or left a box
    undecided.  It is now reported once, naming both subsets."""
    robot, lengths = random_suspended_robot(3, seed=1)
    before = solve_dgp(robot, lengths)
    target = before.solutions[0]
    R = rotation_matrix(target.orientation, robot.orientation)
    reach = np.linalg.norm(robot.exits[0] - (target.position + R @ robot.anchors[0]))
    edited = lengths.copy()
    edited[0] = reach
    for _ in range(abs(ulps)):
        edited[0] = np.nextafter(edited[0], np.sign(ulps) * np.inf)
    res = solve_dgp(robot, edited)
    assert res.undecided == 0
    assert len(res.solutions) == len(before.solutions)
    border = [s for s in res.solutions if np.allclose(s.position, target.position, atol=1e-6)]
    assert len(border) == 1
    (sol,) = border
    assert sol.boundary == (0, 1, 2) and sol.taut == (1, 2) and sol.tensions[0] == 0.0
    assert sol.as_dict()["boundary"] == [0, 1, 2]
    check_equilibrium(robot, edited, sol)


def test_smear_bisection_does_not_starve_a_reference_point():
    """Seed 58, 3 cables, cables 1 and 3 taut: the smear rule kept bisecting the two taut
    anchors (widths down to 5e-4 m) while the third reference point stayed 0.4 m wide, and
    HC4 emptied one half of every cut: 1.34 M boxes, 55 s.  The widest primary variable is
    now cut when it is ten times wider than the smear's pick: a few hundred boxes."""
    robot, lengths = random_suspended_robot(3, seed=58)
    sols, undecided, boxes = solve_subset((robot, lengths, (0, 2), 1e-7))
    assert undecided == 0 and len(sols) == 3 and boxes < 20_000
    for sol in sols:
        check_equilibrium(robot, lengths, sol)


def test_bisect_cuts_the_widest_when_the_smear_pick_starves():
    lo, hi = np.zeros(3), np.array([1.0, 0.05, 0.2])
    (_, a_hi), _ = bisect(lo, hi, score=[0.0, 1.0, 0.5], starve=10.0)
    assert a_hi.tolist() == [0.5, 0.05, 0.2]
    (_, a_hi), _ = bisect(lo, hi, score=[0.0, 1.0, 0.5])
    assert a_hi.tolist() == [1.0, 0.025, 0.2]
    (_, a_hi), _ = bisect(lo, np.array([0.3, 0.05, 0.2]), score=[0.0, 1.0, 0.5], starve=10.0)
    assert a_hi.tolist() == [0.3, 0.025, 0.2]


@pytest.mark.slow
def test_border_equilibrium_through_the_cli_names_cables_from_1(taut_cli, tmp_path):
    """The same border equilibrium from ``taut fk --json`` on the saved robot: the JSON names
    the cables 1-based, as every cable field of the CLI does (docs/architecture.md §2.6)."""
    robot, lengths = random_suspended_robot(3, seed=1)
    target = solve_dgp(robot, lengths).solutions[0]
    R = rotation_matrix(target.orientation, robot.orientation)
    edited = lengths.copy()
    edited[0] = np.linalg.norm(robot.exits[0] - (target.position + R @ robot.anchors[0]))
    path = tmp_path / "seed1.yaml"
    save_robot(robot, path)
    run = taut_cli("fk", str(path), "--lengths", ",".join(repr(float(x)) for x in edited), "--json")
    assert run.code == 0, run.err
    data = run.json()
    assert data["complete"] is True
    border = [s for s in data["solutions"] if "boundary" in s]
    assert len(border) == 1
    assert border[0]["boundary"] == [1, 2, 3] and border[0]["taut"] == [2, 3]
    assert border[0]["tensions"][0] == 0.0


def reference_unknowns(robot, sol, points):
    """The fixed-frame coordinates of an undecided box's reference points at ``sol``."""
    R = rotation_matrix(sol.orientation, robot.orientation)
    return (sol.position + np.asarray(points) @ R.T).ravel()


@pytest.mark.slow
def test_nearly_double_equilibria_are_resolved_in_multiprecision():
    """Two equilibria 1e-4 apart (metres and radians: a near-double root): the double-precision search leaves
    boxes too narrow to split around them, and certifies neither; searched again in 256-bit arb balls with the
    system's exact rational constants, both are certified and the result is complete.

    Independent check: 1e-6 further from the fold (relative), where the pair is 3e-2 apart,
    the double search alone is complete; the equilibria move continuously and none appears
    or vanishes in between, so the two lists pair up one to one, within 0.05."""
    pytest.importorskip("flint")
    robot, lengths, base = fold_robot()
    double = solve_dgp(robot, lengths, max_taut=3, multiprecision=False)
    res = solve_dgp(robot, lengths, max_taut=3)
    assert not double.complete and {u.cause for u in double.undecided_enclosures} == {"narrow"}
    assert res.complete
    for sol in res.solutions:
        check_equilibrium(robot, lengths, sol)
    full = np.array([np.r_[s.position, s.orientation] for s in res.solutions if len(s.taut) == 3])
    gaps = np.linalg.norm(full[:, None] - full[None], axis=-1) + np.diag(np.full(len(full), np.inf))
    assert len(full) == 6 and gaps.min() < 1e-3

    farther = base.copy()
    farther[0] = lengths[0] * (1 + 1e-6)
    ref = solve_dgp(robot, farther, max_taut=3, multiprecision=False)
    assert ref.complete and len(ref.solutions) == len(res.solutions)
    near = np.array([np.r_[s.position, s.orientation] for s in res.solutions])
    far = np.array([np.r_[s.position, s.orientation] for s in ref.solutions])
    dist = np.linalg.norm(near[:, None] - far[None], axis=-1)
    assert sorted(dist.argmin(axis=1).tolist()) == list(range(len(far))) and dist.min(axis=1).max() < 0.05

    # what the double search missed (the pair) lies in its undecided boxes
    missed = 0
    for sol in res.solutions:
        if any(
            np.allclose(np.r_[sol.position, sol.orientation], np.r_[d.position, d.orientation], atol=1e-9)
            for d in double.solutions
        ):
            continue
        missed += 1
        boxes = [u for u in double.undecided_enclosures if u.taut == sol.taut]
        q = [reference_unknowns(robot, sol, u.points) for u in boxes]
        assert any(
            np.all(x >= np.array(u.lo) - 1e-12) and np.all(x <= np.array(u.hi) + 1e-12) for x, u in zip(q, boxes)
        )
    assert missed == 6 - len([s for s in double.solutions if len(s.taut) == 3]) > 0


@pytest.mark.slow
def test_a_root_found_again_in_a_narrow_boxs_margin_is_reported_once():
    """The widened narrow boxes reach into neighbours whose roots double precision already
    certified: in one piece (no :func:`solve_dgp` merging) the fold robot still has 6."""
    pytest.importorskip("flint")
    robot, lengths, _ = fold_robot()
    sols, undecided, _ = solve_subset((robot, lengths, (0, 1, 2), 1e-7))
    assert undecided == 0 and len(sols) == 6
    poses = np.array([np.r_[s.position, s.orientation] for s in sols])
    assert (np.linalg.norm(poses[:, None] - poses[None], axis=-1) + np.eye(6)).min() > 1e-6


# ---- robots whose cables leave through swivelling pulleys ------------------------------------


def check_pulley_equilibrium(robot, lengths, sol):
    """One equilibrium of a pulley robot against the pulley inverse kinematics of
    taut.kinematics (lengths with the wound arcs, structure matrix through the tangent
    points): the taut cables at their lengths to 1e-9, the slack ones within theirs, the
    tensions ≥ 0 balancing the weight, forces and moments about the reference point."""
    pose = np.concatenate([sol.position, sol.orientation])
    ik = inverse_kinematics(robot, pose)
    taut = list(sol.taut)
    slack = [i for i in range(robot.n_cables) if i not in taut]
    np.testing.assert_allclose(ik.lengths[taut], lengths[taut], rtol=0, atol=1e-9)
    assert np.all(ik.lengths[slack] <= lengths[slack] + 1e-9)
    assert np.all(sol.tensions >= 0.0) and np.all(sol.tensions[slack] == 0.0)
    R = rotation_matrix(sol.orientation, robot.orientation)
    f = robot.weight
    wrench = np.concatenate([f, np.cross(R @ np.asarray(robot.platform.wrench_point), f)])
    np.testing.assert_allclose(ik.structure_matrix @ sol.tensions + wrench, 0.0, atol=1e-9 * np.linalg.norm(f))


@settings(max_examples=25, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(3, 8), radius=st.floats(0.005, 0.5))
def test_random_pulley_robot_is_the_point_exit_one_with_pulleys(seed, n, radius, tmp_path_factory):
    """At the drawn pose the pulley inverse kinematics gives back the exact lengths, and the
    cables leave the pulleys at the point-exit robot's exit points (its tangent points);
    the platform, anchors and noise are that robot's; the file round-trips."""
    robot, lengths = random_suspended_robot(n, seed=seed, perturbation=0.0, pulley_radius=radius)
    point, straight = random_suspended_robot(n, seed=seed, perturbation=0.0)
    assert robot.swivel_cables == tuple(range(n)) and robot.platform == point.platform
    np.testing.assert_array_equal(robot.anchors, point.anchors)
    ik = inverse_kinematics(robot, robot.reference.poses["drawn"])
    np.testing.assert_allclose(ik.lengths, lengths, rtol=1e-12)
    np.testing.assert_allclose(ik.exit_points, point.exits, atol=1e-9)
    assert np.all(np.linalg.norm(robot.exits - point.exits, axis=1) <= 2 * radius)
    assert np.all(lengths > straight)  # the arcs
    # the same noise as the point-exit robot of the seed
    noisy, measured = random_suspended_robot(n, seed=seed, pulley_radius=radius)
    np.testing.assert_allclose(measured / lengths, random_suspended_robot(n, seed=seed)[1] / straight, rtol=1e-12)
    path = tmp_path_factory.mktemp("pulleys") / "random.yaml"
    save_robot(noisy, path)
    assert load_robot(str(path)) == noisy


@pytest.mark.parametrize("radius", [0.0, -0.1, 0.6, float("nan"), "0.1"])
def test_random_pulley_robot_refuses_a_bad_radius(radius):
    with pytest.raises(TautError, match="pulley radius"):
        random_suspended_robot(3, seed=0, pulley_radius=radius)


#: (cables, seed, max_taut): quick pulley robots, 5 cm pulleys; seed 2 has equilibria on all three
#: cables, found in about a second.
PULLEY_SUITE = [(3, 1, 2), (3, 2, 3), (4, 2, 2), (6, 2, 2)]


@pytest.mark.parametrize("n, seed, max_taut", PULLEY_SUITE)
def test_random_pulley_robots_equilibria_have_the_pulley_lengths(n, seed, max_taut):
    robot, lengths = random_suspended_robot(n, seed=seed, pulley_radius=0.05)
    res = solve_dgp(robot, lengths, max_taut=max_taut)
    assert res.complete and res.solutions
    for sol in res.solutions:
        check_pulley_equilibrium(robot, lengths, sol)


@pytest.mark.slow
@pytest.mark.parametrize("seed", [3, 5])
def test_random_pulley_robots_every_taut_subset(seed):
    """The whole DGP of 3-cable pulley robots (seconds each): every equilibrium checked."""
    robot, lengths = random_suspended_robot(3, seed=seed, pulley_radius=0.05)
    res = solve_dgp(robot, lengths)
    assert res.complete and any(len(s.taut) == 3 for s in res.solutions)
    for sol in res.solutions:
        check_pulley_equilibrium(robot, lengths, sol)
