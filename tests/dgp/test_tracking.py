"""Tracking forward kinematics (Berti 2015, §4.1.2) from the stable Table 4.3
equilibrium of the suspended 3-cable robot: small length steps along a path and back."""

import numpy as np
import pytest

from taut.dgp._formulation import build_subproblem, load
from taut.dgp._solve import DGPSolution
from taut.dgp._tracking import track_equilibrium, track_path
from taut.errors import TautError, TrackingLostError
from taut.geometry import rotation_matrix
from taut.interval import certify
from taut.model import load_robot

ROBOT = load_robot("suspended-3cable")
LENGTHS = np.array(ROBOT.reference.lengths)
POSE, TENSIONS = [2.7505, 3.9798, 5.5061, 3.0064, 0.3417, 0.1089], [0.526, 0.512, 0.581]  # Conf. 1
DIRECTION = np.array([1.0, -1.0, 0.5])


@pytest.fixture(scope="module")
def start():
    sp = build_subproblem(ROBOT, LENGTHS, (0, 1, 2))
    R = rotation_matrix(np.array(POSE[3:]), "xyz-fixed")
    cert = certify(sp.system, sp.unknowns(POSE[:3], R, np.array(TENSIONS) / LENGTHS))
    p, ang, _ = sp.pose(cert.x, "xyz-fixed")
    return DGPSolution((0, 1, 2), p, ang, sp.tensions(cert.x, LENGTHS, 3), True, cert.width, cert.radius)


def _assert_equilibrium(sol, lengths):
    R = rotation_matrix(sol.orientation, ROBOT.orientation)
    b = sol.position + ROBOT.anchors @ R.T
    a = ROBOT.exits
    f, m, gp = load(ROBOT)
    taut = list(sol.taut)
    assert np.all(sol.tensions >= 0.0)
    span = np.linalg.norm(b - a, axis=1)
    assert np.allclose(span[taut], lengths[taut], atol=1e-9, rtol=0)
    assert np.all(span <= lengths + 1e-9)  # slack cables are not stretched
    u = (a - b) / lengths[:, None] * sol.tensions[:, None]  # cable forces on the platform
    g = sol.position + R @ gp
    force = u.sum(axis=0) + f
    moment = np.cross(b, u).sum(axis=0) + np.cross(g, f) + m
    assert np.max(np.abs(force)) < 1e-9 and np.max(np.abs(moment)) < 1e-9


def test_path_and_back_satisfies_the_equations_and_returns_to_the_start(start):
    path = [LENGTHS + k * 0.002 * DIRECTION for k in range(1, 41)]
    there = track_path(ROBOT, start, path)
    back = track_path(ROBOT, there[-1], path[-2::-1] + [LENGTHS])
    for sol, lengths in zip(there + back, path + path[-2::-1] + [LENGTHS]):
        assert sol.taut == (0, 1, 2) and sol.stable and sol.certificate_width < 1e-3
        _assert_equilibrium(sol, lengths)
    assert not np.allclose(there[-1].position, start.position, atol=1e-3)  # it did move
    assert np.allclose(back[-1].position, start.position, atol=1e-9, rtol=0)
    assert np.allclose(back[-1].orientation, start.orientation, atol=1e-9, rtol=0)
    assert np.allclose(back[-1].tensions, start.tensions, atol=1e-9, rtol=0)


@pytest.mark.slow
def test_a_cable_going_slack_switches_sub_problem_and_back(start):
    d = np.array([-1.0, 1.0, 0.0])  # cable 1 in, cable 2 out: cable 2 goes slack near 2.5 m
    out = [LENGTHS + k * 0.02 * d for k in range(1, 151)]
    path = out + out[-2::-1] + [LENGTHS]
    sols = track_path(ROBOT, start, path)
    sets = [s.taut for s in sols]
    first, last = sets.index((0, 2)), len(sets) - 1 - sets[::-1].index((0, 2))
    assert set(sets[:first]) == {(0, 1, 2)} and set(sets[first : last + 1]) == {(0, 2)}
    assert set(sets[last + 1 :]) == {(0, 1, 2)}
    assert 0.0 < sols[first - 1].tensions[1] < 0.02  # dropped where its tension reached zero
    assert sols[first].tensions[1] == 0.0
    for sol, lengths in zip(sols, path):
        _assert_equilibrium(sol, lengths)
    assert np.allclose(sols[-1].position, start.position, atol=1e-9, rtol=0)


def test_single_track_step_matches_track_path(start):
    lengths = LENGTHS + 0.001 * DIRECTION
    one = track_equilibrium(ROBOT, start, lengths)
    _assert_equilibrium(one, lengths)
    assert np.allclose(one.position, track_path(ROBOT, start, [lengths])[0].position, atol=1e-12)


def test_lengths_no_pose_fits_lose_tracking(start):
    with pytest.raises(TrackingLostError, match="Krawczyk|Newton|cycles"):
        track_equilibrium(ROBOT, start, 0.3 * LENGTHS)  # cables 1 and 2 together shorter than their 10 m gap


def test_bad_lengths(start):
    with pytest.raises(TautError):
        track_equilibrium(ROBOT, start, LENGTHS[:2])
    with pytest.raises(TautError):
        track_equilibrium(ROBOT, start, [1.0, -1.0, 1.0])
    assert track_path(ROBOT, start, []) == []
    for bad in ([LENGTHS, LENGTHS[:2]], [LENGTHS[:2], LENGTHS[:2]], [LENGTHS, [1.0, np.nan, 1.0]], LENGTHS):
        with pytest.raises(TautError, match="cables|lengths|table"):
            track_path(ROBOT, start, bad)


def test_six_taut_cables_track_without_tension_unknowns():
    robot = load_robot("marionet-vr")  # Table 4.5 Conf. 3 (m = 6)
    L = np.array(robot.reference.lengths)
    sp = build_subproblem(robot, L, tuple(range(6)))
    assert not sp.tension_unknowns
    pose = np.array([-0.278, -1.470, 0.549, -0.670, 0.014, -0.043])
    cert = certify(sp.system, sp.unknowns(pose[:3], rotation_matrix(pose[3:], "xyz-fixed")))
    p, ang, _ = sp.pose(cert.x, "xyz-fixed")
    start = DGPSolution(tuple(range(6)), p, ang, sp.tensions(cert.x, L, 6), True, cert.width, cert.radius)
    assert np.all(start.tensions > 0)
    path = [L + k * 0.001 * np.array([1.0, -1.0, 0.5, 0.0, 0.5, -1.0]) for k in range(1, 21)]
    sols = track_path(robot, start, path)
    for sol, lengths in zip(sols, path):
        R = rotation_matrix(sol.orientation, robot.orientation)
        b = sol.position + robot.anchors @ R.T
        taut = list(sol.taut)
        assert np.allclose(np.linalg.norm(b[taut] - robot.exits[taut], axis=1), lengths[taut], atol=1e-9)
        f, m, gp = load(robot)
        u = (robot.exits - b) / np.linalg.norm(robot.exits - b, axis=1)[:, None] * sol.tensions[:, None]
        assert np.max(np.abs(u.sum(axis=0) + f)) < 1e-9
        assert np.max(np.abs(np.cross(b - sol.position, u).sum(axis=0) + np.cross(R @ gp, f) + m)) < 1e-9
    assert not np.allclose(sols[-1].position, start.position, atol=1e-3)
