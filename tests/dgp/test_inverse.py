"""The inverse geometrico-static problem (Berti 2015, §4.1.2): round trips with
the direct problem on Tables 4.3, 4.4 and 4.6, equilibrium checked by independent code
(structure matrix and external wrench of taut.kinematics / taut.statics), invariance under
the orientation convention, and bad input."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from taut.dgp import solve_igp
from taut.dgp._formulation import build_subproblem
from taut.errors import CableSetError, PoseError, TautError, UnsupportedRobotError
from taut.geometry import rotation_matrix
from taut.interval import certify
from taut.kinematics import inverse_kinematics
from taut.model import Robot, load_robot
from taut.statics import external_wrench

SUSPENDED = load_robot("suspended-3cable")
PROTOTYPE = load_robot("teaching-prototype")
COGIRO = load_robot("cogiro")
# Table 4.3, Conf. 1 (the stable one) as corrected in the example's notes
T43_POSE, T43_TENSIONS = [2.7505, 3.9798, 5.5061, 3.0064, 0.3417, 0.1089], [0.526, 0.512, 0.581]
# Table 4.6, Conf. 1 (6 taut cables)
T46_POSE, T46_TENSIONS = [0.346, 0.453, 0.066, -0.003, 0.005, -0.518], [0.153, 0.228, 0.156, 0.225, 0.163, 0.219]


def equilibrium_residual(robot, s) -> float:
    pose = np.concatenate([s.position, s.orientation])
    W = inverse_kinematics(robot, pose).structure_matrix
    return float(np.max(np.abs(W @ s.tensions + external_wrench(robot, pose))))


def check_solution(robot, s, taut):
    """Equilibrium, lengths = IK lengths, tensions ≥ 0 and 0 on slack cables."""
    pose = np.concatenate([s.position, s.orientation])
    assert equilibrium_residual(robot, s) < 1e-9
    assert np.allclose(inverse_kinematics(robot, pose).lengths, s.lengths, atol=1e-12)
    slack = [k for k in range(robot.n_cables) if k not in taut]
    assert s.taut == tuple(sorted(taut)) and s.slack == tuple(slack)
    assert np.all(s.tensions >= 0) and np.all(s.tensions[slack] == 0)
    assert s.certificate_width < 1e-9 and s.uniqueness_radius > 0


def dgp_certified(robot, taut0, lengths, pose, tensions):
    """The equilibrium of the direct problem with cable ``lengths`` near a printed table
    row, certified on its (reference-point) system: ``(pose, tensions)``."""
    lengths = np.asarray(lengths, float)
    sp = build_subproblem(robot, lengths, taut0)
    R = rotation_matrix(np.asarray(pose[3:], float), robot.orientation)
    cert = certify(sp.system, sp.unknowns(pose[:3], R, np.asarray(tensions)[list(taut0)] / lengths[list(taut0)]))
    assert cert is not None
    p, ang, _ = sp.pose(cert.x, robot.orientation)
    return np.concatenate([p, ang]), sp.tensions(cert.x, lengths, robot.n_cables)


@pytest.fixture(scope="module")
def suspended_m3():
    return solve_igp(SUSPENDED, (0, 1, 2), dict(zip("xyz", T43_POSE[:3])))


def test_table_4_3_round_trip_position_gives_orientation_tensions_and_lengths(suspended_m3):
    res = suspended_m3
    # four equilibria with this origin (Newton from 3000 random starts finds the same four)
    assert res.complete and not res.exhausted and len(res.solutions) == 4
    for s in res.solutions:
        check_solution(SUSPENDED, s, (0, 1, 2))
        assert np.allclose(s.position, T43_POSE[:3], atol=0)
    stable = [s for s in res.solutions if s.stable]
    assert len(stable) == 1
    s = stable[0]
    assert np.allclose(s.orientation, T43_POSE[3:], atol=1e-3)
    assert np.allclose(s.tensions, T43_TENSIONS, atol=1e-3)
    assert np.allclose(s.lengths, SUSPENDED.reference.lengths, atol=1e-3)


def test_every_igp_solution_is_an_equilibrium_of_the_direct_problem(suspended_m3):
    """Cross-formulation check: at the IGP lengths, the DGP's reference-point system
    certifies the IGP pose and tensions."""
    for s in suspended_m3.solutions:
        pose, tau = dgp_certified(
            SUSPENDED, (0, 1, 2), s.lengths, np.concatenate([s.position, s.orientation]), s.tensions
        )
        assert np.allclose(pose, np.concatenate([s.position, s.orientation]), atol=1e-9)
        assert np.allclose(tau, s.tensions, atol=1e-9)


def test_exact_round_trip_with_the_direct_problem():
    """The exact Table 4.3 equilibrium for ρ = (7.5, 10, 9.5): its position gives back its
    orientation, tensions and lengths to Newton precision."""
    lengths = SUSPENDED.reference.lengths
    pose, tau = dgp_certified(SUSPENDED, (0, 1, 2), lengths, T43_POSE, T43_TENSIONS)
    res = solve_igp(SUSPENDED, [2, 0, 1], {"x": pose[0], "y": pose[1], "z": pose[2]})
    match = [s for s in res.solutions if np.allclose(s.orientation, pose[3:], atol=1e-9)]
    assert len(match) == 1
    assert np.allclose(match[0].tensions, tau, atol=1e-9) and np.allclose(match[0].lengths, lengths, atol=1e-9)


def test_table_4_6_six_taut_cables_is_a_linear_problem():
    res = solve_igp(PROTOTYPE, range(6), dict(zip(PROTOTYPE.pose_names, T46_POSE)))
    assert res.undecided == 0 and len(res.solutions) == 1
    s = res.solutions[0]
    check_solution(PROTOTYPE, s, range(6))
    assert np.array_equal(s.position, T46_POSE[:3]) and np.array_equal(s.orientation, T46_POSE[3:])
    assert np.allclose(s.tensions, T46_TENSIONS, atol=8e-3) and s.stable
    assert np.allclose(s.lengths, PROTOTYPE.reference.lengths, atol=2e-3)


def test_table_4_4_conf_8_five_taut_cables_recovers_phi_z():
    """CoGiRo Conf. 8 (cables 3, 4, 6, 7, 8 taut): assign x, y, z, φx, φy of the exact
    equilibrium, get φz back.  The printed row itself sits past a fold of this IGP (its
    rounding removes the two nearby solutions), which is why the exact one is used."""
    printed = [0.255, -0.039, 0.828, 0.033, -0.099, 0.055]
    lengths = np.array(COGIRO.reference.lengths)
    taut0 = [2, 3, 5, 6, 7]
    pose, tau = dgp_certified(COGIRO, taut0, lengths, printed, [0, 0, 0.62, 0.55, 0, 0.01, 0.63, 0.55])
    taut = tuple(taut0)
    res = solve_igp(COGIRO, taut, {"x": pose[0], "y": pose[1], "z": pose[2], "phix": pose[3], "phiy": pose[4]})
    assert res.undecided == 0 and len(res.solutions) == 3
    for s in res.solutions:
        check_solution(COGIRO, s, taut)
        assert np.allclose(s.orientation[:2], pose[3:5], atol=0)
    match = [s for s in res.solutions if abs(s.orientation[2] - pose[5]) < 1e-9]
    assert len(match) == 1
    s = match[0]
    assert np.allclose(s.tensions, tau, atol=1e-9) and np.allclose(s.lengths[taut0], lengths[taut0], atol=1e-9)
    # the slack cables span less than the table's lengths: they are slack there
    assert np.all(s.lengths[[0, 1, 4]] < lengths[[0, 1, 4]])


def test_four_taut_cables_assigning_phi_x():
    taut = (0, 1, 3, 5)
    res = solve_igp(PROTOTYPE, taut, {"x": 0.346, "y": 0.453, "z": 0.066, "φx": -0.003})
    assert res.undecided == 0 and len(res.solutions) == 2  # as many as Newton from random starts
    for s in res.solutions:
        check_solution(PROTOTYPE, s, taut)
        assert s.orientation[0] == -0.003


def test_free_position_coordinate_in_a_given_box():
    """Assigning two angles instead of z (Table 4.6 Conf. 3, cable 5 slack)."""
    taut = (0, 1, 2, 3, 5)
    assigned = {"x": 0.363, "y": 0.454, "a": -2.420, "b": 0.406, "c": -1.341}
    res = solve_igp(PROTOTYPE, taut, assigned)
    assert len(res.solutions) == 1
    s = res.solutions[0]
    check_solution(PROTOTYPE, s, taut)
    assert s.stable and s.length_violations == ()
    inside = solve_igp(PROTOTYPE, taut, assigned, box=([0, 0, s.position[2] - 0.01], [1, 1, s.position[2] + 0.01]))
    assert len(inside.solutions) == 1 and np.allclose(inside.solutions[0].position, s.position, atol=1e-12)
    outside = solve_igp(PROTOTYPE, taut, assigned, box=([0, 0, s.position[2] + 0.01], [1, 1, 1]))
    assert outside.solutions == () and outside.undecided == 0


def test_length_bounds_are_reported_not_enforced():
    data = PROTOTYPE.model_dump()
    data["cables"][0]["length"] = [0.0, 0.75]  # taut cable 1 is 0.80 long
    data["cables"][4]["length"] = [0.0, 0.70]  # slack cable 5 spans 0.78
    robot = Robot.model_validate(data)
    res = solve_igp(robot, (0, 1, 2, 3, 5), {"x": 0.363, "y": 0.454, "z": 0.122, "a": -2.420, "b": 0.406})
    assert len(res.solutions) == 2
    for s in res.solutions:
        assert s.lengths[0] > 0.75 and s.lengths[4] > 0.70
        assert s.length_violations == (0, 4)
        assert s.as_dict()["length_violations"] == [0, 4]


@pytest.mark.parametrize("convention", ["xyz-moving", "tilt-torsion"])
def test_the_rotations_found_do_not_depend_on_the_convention(convention, suspended_m3):
    data = SUSPENDED.model_dump()
    data["orientation"] = convention
    robot = Robot.model_validate(data)
    res = solve_igp(robot, (0, 1, 2), dict(zip("xyz", T43_POSE[:3])))
    assert res.undecided == 0 and len(res.solutions) == 4
    ours = sorted(rotation_matrix(s.orientation, convention).ravel().round(9).tolist() for s in res.solutions)
    fixed = sorted(
        rotation_matrix(s.orientation, "xyz-fixed").ravel().round(9).tolist() for s in suspended_m3.solutions
    )
    assert np.allclose(ours, fixed, atol=1e-8)
    for s in res.solutions:
        check_solution(robot, s, (0, 1, 2))


ROBOCRANE = load_robot("robocrane")


@pytest.fixture(scope="module")
def robocrane_m3():
    return solve_igp(ROBOCRANE, (0, 2, 4), {"x": 0, "y": 0, "z": 2})


def test_tension_bounds_bound_the_domain(robocrane_m3):
    """Robocrane (tilt-and-torsion, tensions in [0, 1] N): every solution respects the bound."""
    res = robocrane_m3
    assert res.complete and not res.exhausted and len(res.solutions) == 4
    for s in res.solutions:
        check_solution(ROBOCRANE, s, (0, 2, 4))
        assert np.all(s.tensions <= 1.0) and 0 <= s.orientation[1] <= np.pi


@pytest.mark.parametrize(
    "fixture, names",
    [
        ("suspended_m3", ("x", "y", "a")),
        ("suspended_m3", ("x", "b", "c")),
        ("suspended_m3", ("a", "b", "c")),
        ("robocrane_m3", ("z", "theta", "sigma")),
        ("robocrane_m3", ("x", "phi", "theta")),
        ("robocrane_m3", ("y", "z", "phi")),
    ],
)
def test_any_three_coordinates_of_a_solution_give_it_back(fixture, names, request):
    """Assigning other coordinates of a solution (free positions, free σ through ψ = σ − φ,
    assigned σ through the difference formulas) finds that solution again."""
    robot, res = {"suspended_m3": SUSPENDED, "robocrane_m3": ROBOCRANE}[fixture], request.getfixturevalue(fixture)
    taut = res.solutions[0].taut
    for s in res.solutions[:2]:
        pose = np.concatenate([s.position, s.orientation])
        again = solve_igp(robot, taut, {n: pose[robot.pose_names.index(n)] for n in names})
        assert again.complete
        assert (
            sum(np.allclose(np.concatenate([q.position, q.orientation]), pose, atol=1e-9) for q in again.solutions) == 1
        )
        for q in again.solutions:
            check_solution(robot, q, taut)


def test_a_continuum_exhausts_the_budget_and_says_so():
    """x = y = 0 and φ of a Robocrane solution: the platform can slide along a curve of
    equilibria (z, θ and σ − φ change together), so no isolated solution is proven there.
    The certifications tried along it are charged to the budget too (``CERTIFY_BOXES`` boxes
    each), so fewer than 3000 boxes are processed."""
    res = solve_igp(ROBOCRANE, (0, 2, 4), {"x": 0, "y": 0, "phi": 2.8797932657906435}, max_boxes=3000)
    assert res.exhausted and 2000 < res.boxes < 3000 and res.undecided > 0 and not res.complete


@settings(max_examples=25, deadline=None)
@given(st.floats(-0.02, 0.02), st.floats(-0.02, 0.02), st.floats(-0.05, 0.05), st.floats(-0.3, 0.3))
def test_six_taut_cables_match_the_linear_solve(dx, dy, dz, dc):
    """m = 6: the IGP returns the tensions of W τ = −w_ext when they are all positive, and
    nothing when one is negative."""
    pose = np.array(T46_POSE) + [dx, dy, dz, 0, 0, dc]
    res = solve_igp(PROTOTYPE, range(6), dict(zip(PROTOTYPE.pose_names, pose)))
    ik = inverse_kinematics(PROTOTYPE, pose)
    tau = np.linalg.solve(ik.structure_matrix, -external_wrench(PROTOTYPE, pose))
    if np.all(tau > 1e-9):
        assert len(res.solutions) == 1 and np.allclose(res.solutions[0].tensions, tau, atol=1e-12)
    elif np.any(tau < -1e-9):
        assert res.solutions == ()


def with_wrench(robot: Robot, wrench: np.ndarray) -> Robot:
    """``robot`` with the constant external wrench ``wrench`` (about the platform origin)."""
    data = robot.model_dump()
    data["platform"].update(wrench=[float(w) for w in wrench], wrench_point=None, mass=None)
    return Robot.model_validate(data)


@settings(max_examples=15, deadline=None)
@given(
    st.tuples(st.floats(0.30, 0.40), st.floats(0.40, 0.50), st.floats(0.05, 0.2)),
    st.tuples(*[st.floats(-0.3, 0.3)] * 3),
    st.tuples(*[st.floats(0.05, 0.5)] * 5),
)
def test_five_taut_cables_find_the_equilibrium_they_were_built_from(position, angles, tensions):
    """A pose of the prototype made an equilibrium with five taut cables by choosing the
    external wrench ``−W τ`` (independent structure matrix): assigning five of its
    coordinates, the search is complete and finds it, with its tensions; every solution
    is an admissible equilibrium."""
    taut = (0, 1, 2, 3, 5)
    pose = np.array([*position, *angles])
    tau = np.zeros(PROTOTYPE.n_cables)
    tau[list(taut)] = tensions
    robot = with_wrench(PROTOTYPE, -inverse_kinematics(PROTOTYPE, pose).structure_matrix @ tau)
    assert np.allclose(inverse_kinematics(robot, pose).structure_matrix @ tau + external_wrench(robot, pose), 0)
    res = solve_igp(robot, taut, dict(zip(("x", "y", "z", "a", "b"), pose[:5])))
    assert res.complete and not res.exhausted and res.undecided == 0
    assert len(res.solutions) >= 1
    for s in res.solutions:
        check_solution(robot, s, taut)
    found = [s for s in res.solutions if abs(s.orientation[2] - pose[5]) < 1e-9]
    assert len(found) == 1
    assert np.array_equal(found[0].position, pose[:3]) and np.allclose(found[0].tensions, tau, atol=1e-9)


POINT_MASS = Robot.model_validate(
    {
        "name": "spatial point mass",
        "dimension": 3,
        "platform": {"kind": "point-mass", "mass": 1.0},
        "cables": [{"exit": [0, 0, 1]}, {"exit": [1, 0, 1]}, {"exit": [0, 1, 1]}],
    }
)


@pytest.mark.parametrize(
    "robot, taut, assigned, error, words",
    [
        (SUSPENDED, (0, 1, 2), {"x": 1, "y": 2}, PoseError, "exactly 3"),
        (SUSPENDED, (0, 1), {"x": 1, "y": 2, "z": 3}, PoseError, "exactly 2"),
        (SUSPENDED, (0, 1), {"x": 1, "w": 2}, PoseError, "unknown pose coordinate 'w'"),
        (SUSPENDED, (0, 1), {"x": 1, "phi": 2}, PoseError, "unknown pose coordinate"),
        (SUSPENDED, (0, 1), {"a": 1, "phix": 2}, PoseError, "assigned twice"),
        (SUSPENDED, (0, 1), {"x": 1, "y": float("nan")}, PoseError, "finite"),
        (SUSPENDED, (0, 1), {"x": 1, "y": float("inf")}, PoseError, "finite"),
        (SUSPENDED, (0, 1), {"x": 1, "y": "two"}, PoseError, "not a number"),
        (SUSPENDED, (0, 1), [1.0, 2.0], PoseError, "mapping"),
        (SUSPENDED, (0, 3), {"x": 1, "y": 2}, CableSetError, r"no cable 4 \(0-based index \[3\]\)"),
        (SUSPENDED, (-1, 0), {"x": 1, "y": 2}, CableSetError, "no cable 0 "),
        (SUSPENDED, (0, 0, 1), {"x": 1, "y": 2, "z": 3}, CableSetError, "twice"),
        (SUSPENDED, (0.5, 1), {"x": 1, "y": 2}, CableSetError, "whole"),
        (SUSPENDED, (0,), {"x": 1}, CableSetError, "2 to 6"),
        (COGIRO, range(7), dict.fromkeys("xyzabc", 0.0), CableSetError, "2 to 6"),
        (SUSPENDED, 3, {"x": 1}, CableSetError, "cable indices 0..2"),
        (load_robot("planar-4cable"), (0, 1), {"x": 0, "y": 0}, UnsupportedRobotError, "planar"),
        (
            POINT_MASS,
            (0, 1),
            {"x": 0, "a": 0},
            PoseError,
            "unknown pose coordinate .a.; spatial point mass has x, y, z",
        ),
        (load_robot("adjustable-8cable"), (0, 1), {"x": 0, "y": 0}, UnsupportedRobotError, "jointed"),
    ],
)
def test_bad_input_raises_typed_errors(robot, taut, assigned, error, words):
    with pytest.raises(error, match=words):
        solve_igp(robot, taut, assigned)


@pytest.mark.parametrize("box", [([0, 0], [1, 1]), ([0, 0, 0], [1, 1, np.nan]), ([0, 0, 1], [1, 1, 0]), "box"])
def test_bad_box_raises(box):
    with pytest.raises(PoseError, match="box"):
        solve_igp(SUSPENDED, (0, 1), {"x": 1, "a": 0}, box=box)


def test_bad_solver_settings_raise():
    with pytest.raises(TautError, match="tol"):
        solve_igp(SUSPENDED, (0, 1), {"x": 1, "a": 0}, tol=0.0)
    with pytest.raises(TautError, match="max_boxes"):
        solve_igp(SUSPENDED, (0, 1), {"x": 1, "a": 0}, max_boxes=0)


def test_progress_counts_boxes_up_to_the_budget():
    calls = []
    res = solve_igp(
        ROBOCRANE,
        (0, 2, 4),
        {"x": 0, "y": 0, "phi": 2.8797932657906435},
        max_boxes=2500,
        progress=lambda done, total: calls.append((done, total)),
    )
    assert res.exhausted and res.boxes == 2500
    assert calls == [(1000, None), (2000, None), (2500, 2500)]
    calls.clear()
    res = solve_igp(
        PROTOTYPE, (0, 1, 3, 5), {"x": 0.346, "y": 0.453, "z": 0.066, "a": -0.003}, progress=lambda *c: calls.append(c)
    )
    assert res.complete and calls[-1] == (res.boxes, res.boxes)
    assert all(t is None for _, t in calls[:-1]) and [d for d, _ in calls] == sorted({d for d, _ in calls})
