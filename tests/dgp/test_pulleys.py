"""The DGP of robots whose cables leave through swivelling pulleys: every solution is checked
against the pulley inverse kinematics of taut.kinematics (lengths with the wound arc, the
structure matrix through the tangent points), which the closed-form equations of
taut.dgp._pulleys do not use."""

from __future__ import annotations

import numpy as np
import pytest

from taut.dgp import DGPSolution, load, pulley_subproblem, solve_dgp, track_path
from taut.interval import branch_and_prune
from taut.kinematics import inverse_kinematics, swivel_paths
from taut.model import Robot, example

LENGTHS = np.array([7.5, 10.0, 9.5])


def _with_radius(robot: Robot, radius: float | None) -> Robot:
    """``robot`` with every pulley's radius set to ``radius`` (``None``: no pulleys)."""
    cables = tuple(
        c.model_copy(update={"swivel": None if radius is None else c.swivel.model_copy(update={"radius": radius})})
        for c in robot.cables
    )
    return robot.model_copy(update={"cables": cables})


def _check_equilibrium(robot: Robot, position, orientation, tensions, lengths, taut) -> None:
    """Lengths of the taut cables (pulley IK) to 1e-9, slack cables no longer than their
    lengths, tensions ≥ 0 and zero on slack cables, and the wrench balance with the pulley
    structure matrix (columns [u; (b − p) × u] through the tangent points)."""
    pose = np.concatenate([position, orientation])
    ik = inverse_kinematics(robot, pose)
    idx = list(taut)
    np.testing.assert_allclose(ik.lengths[idx], lengths[idx], rtol=0, atol=1e-9)
    slack = [k for k in range(robot.n_cables) if k not in taut]
    assert np.all(ik.lengths[slack] <= lengths[slack] + 1e-9)
    assert np.all(tensions >= 0) and np.all(tensions[slack] == 0)
    f, m, gp = load(robot)
    R = _rotation(robot, orientation)
    g = R @ gp  # load point relative to the platform origin
    wrench = np.concatenate([f, m + np.cross(g, f)])
    np.testing.assert_allclose(ik.structure_matrix @ tensions + wrench, 0.0, atol=1e-9)


def _rotation(robot: Robot, orientation) -> np.ndarray:
    from taut.geometry import rotation_matrix

    return rotation_matrix(np.asarray(orientation, float), robot.orientation)


def test_the_structure_matrix_convention_the_checks_rely_on():
    """The structure matrix's columns are [u; (b − p) × u] with u towards the tangent point:
    a point-exit robot's Table 4.3 equilibrium balances with it (so the checks are sound)."""
    robot = example("suspended-3cable")
    from taut.dgp import solve_igp

    s = solve_igp(robot, [0, 1, 2], {"x": 2.7505, "y": 3.9798, "z": 5.5061}).solutions[0]
    _check_equilibrium(robot, s.position, s.orientation, s.tensions, s.lengths, (0, 1, 2))


def _certify_near(robot: Robot, lengths: np.ndarray, pose: np.ndarray, half: float = 1e-3):
    """Branch-and-prune on a small box about the unknowns of ``pose`` (and the tensions
    free in [0, ∞)): the certified solutions of the pulley system there."""
    sp = pulley_subproblem(robot, lengths, (0, 1, 2))
    R = _rotation(robot, pose[3:])
    x = sp.unknowns(pose[:3], R, np.zeros(3))
    k = sp.pose_unknowns
    lo, hi = x - half, x + half
    lo[k:], hi[k:] = 0.0, np.inf
    lo, hi = np.maximum(lo, sp.lo), np.minimum(hi, sp.hi)
    res = branch_and_prune(sp.system, lo, hi, primary=sp.primary, tol=1e-9, filters=(sp.statics,))
    out = []
    for c in res.solutions:
        p, ang, _ = sp.pose(c.x, robot.orientation)
        out.append((p, ang, sp.tensions(c.x, lengths, robot.n_cables), c))
    return res, out


def test_a_certified_pulley_equilibrium_has_the_pulley_lengths_and_balances():
    robot = example("suspended-3pulley")
    pose = np.array(robot.reference.poses["stable"])
    res, sols = _certify_near(robot, LENGTHS, pose)
    assert res.complete and len(sols) == 1
    p, ang, tau, cert = sols[0]
    _check_equilibrium(robot, p, ang, tau, LENGTHS, (0, 1, 2))
    assert cert.width < 1e-8
    # the reference pose is this equilibrium rounded to 1e-6
    np.testing.assert_allclose(np.concatenate([p, ang]), pose, atol=1e-6)


def test_the_pulleys_move_the_equilibrium_away_from_the_point_exit_one():
    """The pulley model is not the fixed-exit one: the arcs and tangent points move the
    stable equilibrium of Table 4.3 by centimetres, so fixed-exit equations would fail the
    pulley lengths."""
    pulleys = example("suspended-3pulley")
    point = [2.7505, 3.9798, 5.5061, 3.0064, 0.3417, 0.1089]
    ik = inverse_kinematics(pulleys, point)
    assert np.max(np.abs(ik.lengths - LENGTHS)) > 5e-3
    moved = np.array(pulleys.reference.poses["stable"])
    assert np.linalg.norm(moved[:3] - point[:3]) > 5e-3


@pytest.mark.parametrize("radius", [1e-5, 1e-7])
def test_small_pulleys_give_the_point_exit_equilibrium(radius):
    """Radius → 0: the pulley robot's certified equilibrium near Table 4.3's stable one tends
    to the point-exit robot's (the IGP solution of Berti's example), linearly in the radius."""
    robot = _with_radius(example("suspended-3pulley"), radius)
    from taut.dgp import solve_igp

    point = solve_igp(example("suspended-3cable"), [0, 1, 2], {"x": 2.7505, "y": 3.9798, "z": 5.5061}).solutions[0]
    lengths = point.lengths
    start = np.concatenate([point.position, point.orientation])
    res, sols = _certify_near(robot, lengths, start, half=1e-2)
    assert res.complete and len(sols) == 1
    p, ang, tau, _ = sols[0]
    _check_equilibrium(robot, p, ang, tau, lengths, (0, 1, 2))
    scale = 100.0 * radius + 1e-9
    np.testing.assert_allclose(p, point.position, atol=scale)
    np.testing.assert_allclose(ang, point.orientation, atol=scale)
    np.testing.assert_allclose(tau, point.tensions, atol=scale)


def test_one_taut_cable_along_its_swivel_axis_hangs_unwrapped():
    """Cables 2 and 3 paid out far: cable 1 alone holds the platform.  Its load is along its
    swivel axis (the way the cable comes), so it hangs straight down from the exit point,
    unwrapped, with the anchor on the axis — where the pulley IK flags the swivel angle
    undefined but gives the length."""
    robot = example("suspended-3pulley")
    lengths = np.array([7.5, 30.0, 30.0])
    res = solve_dgp(robot, lengths, max_taut=1)
    assert res.complete
    assert len(res.solutions) == 2  # G below the anchor (stable) and above it
    assert sorted(s.stable for s in res.solutions) == [False, True]
    f, _, gp = load(robot)
    for s in res.solutions:
        assert s.taut == (0,) and s.continuum is not None
        R = _rotation(robot, s.orientation)
        b = s.position + robot.anchors @ R.T
        np.testing.assert_allclose(b[0] - robot.exits[0], [0, 0, 7.5], atol=1e-9)
        paths = swivel_paths(robot.exits, [[0, 0, 1]] * 3, [0.1] * 3, b[None])
        assert paths.on_axis[0, 0]
        np.testing.assert_allclose(paths.lengths[0, 0], 7.5, atol=1e-9)
        assert np.all(paths.lengths[0, 1:] <= 30.0)
        np.testing.assert_allclose(s.tensions, [np.linalg.norm(f), 0, 0], atol=1e-12)
        # the load point on the cable's line
        g = s.position + R @ gp
        np.testing.assert_allclose(np.cross(g - b[0], f), 0.0, atol=1e-9)


def test_one_taut_cable_through_a_tilted_pulley_wraps_it():
    """With the swivel axes tilted off the load, cable 1 alone wraps its pulley: its free
    segment hangs along the load from the tangent point, and its length is the arc plus
    the free length (pulley IK)."""
    robot = example("suspended-3pulley")
    cables = tuple(
        c.model_copy(update={"swivel": c.swivel.model_copy(update={"axis": (1.0, 0.0, 1.0)})}) for c in robot.cables
    )
    robot = robot.model_copy(update={"cables": cables})
    lengths = np.array([7.5, 30.0, 30.0])
    res = solve_dgp(robot, lengths, max_taut=1)
    # the pulley faces the anchor on one branch only (the other would need a free length
    # shorter than the pulley), G below or above the anchor
    assert res.complete and len(res.solutions) == 2
    assert sorted(s.stable for s in res.solutions) == [False, True]
    for s in res.solutions:
        _check_equilibrium(robot, s.position, s.orientation, s.tensions, lengths, (0,))
        ik = inverse_kinematics(robot, np.concatenate([s.position, s.orientation]))
        free = ik.anchors[0] - ik.exit_points[0]
        np.testing.assert_allclose(free / np.linalg.norm(free), [0, 0, 1], atol=1e-9)
        assert np.linalg.norm(free) < 7.5 - 0.05  # the arc takes up some of the length


@pytest.mark.parametrize("radius", [0.1, 0.5, 2.0])
def test_a_pulley_not_smaller_than_its_cable_is_refused(radius):
    robot = _with_radius(example("suspended-3pulley"), radius)
    from taut.errors import TautError

    lengths = np.array([0.1, 10.0, 9.5])
    with pytest.raises(TautError, match=f"cable 1's pulley radius {radius:g} m is not smaller"):
        solve_dgp(robot, lengths)


@pytest.mark.slow
def test_the_whole_pulley_dgp_and_its_point_exit_limit():
    """Every equilibrium of the pulley robot at Table 4.3's lengths is certified, has the
    pulley lengths and balances; with pulleys of radius 1e-6 the solution set is Table 4.3's
    (the point-exit robot's) to within 1e-4."""
    robot = example("suspended-3pulley")
    res = solve_dgp(robot)
    assert res.complete and len(res.solutions) == 6
    assert sum(s.stable for s in res.solutions) == 1
    for s in res.solutions:
        _check_equilibrium(robot, s.position, s.orientation, s.tensions, LENGTHS, s.taut)
    tiny = solve_dgp(_with_radius(robot, 1e-6))
    point = solve_dgp(_with_radius(robot, None))
    assert tiny.complete and point.complete
    assert len(tiny.solutions) == len(point.solutions) == 6
    for a, b in zip(tiny.solutions, point.solutions):
        assert a.taut == b.taut and a.stable == b.stable
        np.testing.assert_allclose(a.position, b.position, atol=1e-4)
        np.testing.assert_allclose(a.orientation, b.orientation, atol=1e-4)


def _start(robot: Robot) -> DGPSolution:
    """The reference equilibrium as a tracking start: its tensions solved from the pulley
    structure matrix at the reference pose."""
    pose = np.array(robot.reference.poses["stable"])
    ik = inverse_kinematics(robot, pose)
    f, m, gp = load(robot)
    g = _rotation(robot, pose[3:]) @ gp
    tau = np.linalg.lstsq(ik.structure_matrix, -np.concatenate([f, m + np.cross(g, f)]), rcond=None)[0]
    return DGPSolution((0, 1, 2), pose[:3], pose[3:], tau, True, 0.0, 0.0)


def test_tracking_follows_the_pulley_equilibrium():
    """Cable 1 paid out by 5 cm in 5 steps: every tracked equilibrium has the pulley
    lengths and balances, and the last one is the equilibrium a certified search finds in a
    box about it."""
    robot = example("suspended-3pulley")
    rows = LENGTHS + np.linspace(0.0, 0.05, 6)[:, None] * [1.0, 0.0, 0.0]
    path = track_path(robot, _start(robot), rows)
    assert len(path) == 6
    for s, lengths in zip(path, rows):
        assert s.taut == (0, 1, 2) and s.stable
        _check_equilibrium(robot, s.position, s.orientation, s.tensions, lengths, s.taut)
        assert 0.0 < s.certificate_width < 0.1  # the Krawczyk box covers the step
    last = path[-1]
    res, sols = _certify_near(robot, rows[-1], np.concatenate([last.position, last.orientation]))
    assert res.complete and len(sols) == 1
    np.testing.assert_allclose(sols[0][0], last.position, atol=1e-8)
    np.testing.assert_allclose(sols[0][1], last.orientation, atol=1e-8)
    # the platform moved: tracking did not stand still
    assert np.linalg.norm(last.position - path[0].position) > 5e-3


@pytest.mark.slow
def test_igp_with_pulleys_commands_the_pulley_lengths():
    """The inverse problem at the reference position: four certified equilibria, each
    balancing with the pulley structure matrix at the lengths the pulley IK gives (the ones
    to command, arcs included), stable as the load potential on the manifold of those
    lengths says; the stable one is the reference pose, whose lengths are the reference
    lengths."""
    robot = example("suspended-3pulley")
    from taut.dgp import solve_igp

    pose = np.array(robot.reference.poses["stable"])
    res = solve_igp(robot, [0, 1, 2], {"x": pose[0], "y": pose[1], "z": pose[2]})
    assert res.complete and len(res.solutions) == 4
    assert [s.stable for s in res.solutions] == [True, False, False, False]
    for s in res.solutions:
        ik = inverse_kinematics(robot, np.concatenate([s.position, s.orientation]))
        np.testing.assert_allclose(s.lengths, ik.lengths, rtol=0, atol=1e-12)
        _check_equilibrium(robot, s.position, s.orientation, s.tensions, s.lengths, s.taut)
        # the arcs: longer than the straight exit-to-anchor spans
        assert np.all(s.lengths > np.linalg.norm(ik.anchors - robot.exits, axis=1))
        # stable (reduced Hessian with the swivel term) exactly when no nearby pose of the
        # same pulley lengths has a lower load potential
        assert s.stable == (not _energy_decreases(robot, np.concatenate([s.position, s.orientation]), s.taut))
    stable = res.solutions[0]
    np.testing.assert_allclose(stable.orientation, pose[3:], atol=2e-6)
    np.testing.assert_allclose(stable.lengths, LENGTHS, atol=2e-6)


def test_caspr_pulleys_with_tilted_axes_in_the_igp_and_tracking():
    """CASPR's pulley fixture (swivel axes off the vertical and not of unit length, radii
    0.05 and 0.08 m) hung from cables 1–3: the inverse problem's solutions and a tracking
    step from the stable one have the pulley lengths and balance."""
    from pathlib import Path

    from taut.dgp import solve_igp, track_equilibrium
    from taut.model import load_robot

    robot = load_robot(Path(__file__).parents[1] / "model" / "fixtures" / "caspr" / "pulley_bodies.xml")
    res = solve_igp(robot, [0, 1, 2], {"x": 0.1, "y": 0.05, "z": 1.0})
    assert res.complete and len(res.solutions) == 4
    for s in res.solutions:
        _check_equilibrium(robot, s.position, s.orientation, s.tensions, s.lengths, s.taut)
    stable = [s for s in res.solutions if s.stable]
    assert len(stable) == 1
    # the slack cables paid out half a metre beyond their spans
    lengths = stable[0].lengths + [0.01, -0.01, 0.0, 0.5, 0.5, 0.5, 0.5, 0.5]
    moved = track_equilibrium(robot, stable[0], lengths)
    assert moved.taut == (0, 1, 2) and moved.stable
    _check_equilibrium(robot, moved.position, moved.orientation, moved.tensions, lengths, moved.taut)


def _energy_decreases(robot: Robot, pose: np.ndarray, taut: tuple[int, ...], eps: float = 1e-3) -> bool:
    """Whether the load's potential ``−f·g`` decreases somewhere on the manifold of poses
    that keep the taut cables' pulley-IK lengths, within ``eps`` of ``pose``: sampled
    directions of the lengths' null space, each step pulled back onto the manifold by
    Newton — the definition of an unstable equilibrium, computed without the Hessian."""
    from taut.kinematics import cable_lengths

    idx = list(taut)
    target = cable_lengths(robot, pose)[idx]
    f, _, gp = load(robot)

    def energy(x):
        return -f @ (x[:3] + _rotation(robot, x[3:]) @ gp)

    def jac(x):
        h = 1e-7
        return np.array(
            [(cable_lengths(robot, x + h * e)[idx] - cable_lengths(robot, x - h * e)[idx]) / (2 * h) for e in np.eye(6)]
        ).T

    J = jac(pose)
    null = np.linalg.svd(J)[2][len(idx) :].T
    back = np.linalg.pinv(J)  # chord Newton: the step is eps, the error eps² per iteration
    rng = np.random.default_rng(0)
    e0 = energy(pose)
    for u in rng.normal(size=(60, null.shape[1])):
        x = pose + eps * null @ (u / np.linalg.norm(u))
        for _ in range(5):
            x = x - back @ (cable_lengths(robot, x)[idx] - target)
        if energy(x) < e0 - 1e-12:
            return True
    return False
