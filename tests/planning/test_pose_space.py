"""Planning in a robot's own pose space (``plan_path(robot, ..., method="rrtconnect" | "grid")``):
paths checked by ``verify_path`` at a fine step and, at their poses, by an independent
equilibrium test (``scipy.optimize.linprog`` on a structure matrix built here from the robot's
exits and anchors); a lattice that proves no path; another angle convention; bad input."""

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from scipy.optimize import linprog
from scipy.spatial.transform import Rotation

from taut.errors import InfeasiblePoseError, TautError
from taut.model import example, load_robot
from taut.planning import plan_path, verify_path

POINT_MASS = """\
format: taut/1
name: planar point mass
description: test fixture, a 1 kg point mass in a 2 m square frame
dimension: 2
platform:
  kind: point-mass
  mass: 1.0
  gravity: [0, -9.81]
cables:
  - {exit: [-1.0, -1.0], tension: [1, 30]}
  - {exit: [1.0, -1.0], tension: [1, 30]}
  - {exit: [1.0, 1.0], tension: [1, 30]}
  - {exit: [-1.0, 1.0], tension: [1, 30]}
"""


def fine_step(robot, path, step=1e-3) -> bool:
    """``verify_path`` with every segment cut at most ``step`` apart (angles the short way)."""
    path = np.asarray(path, float)
    d = np.diff(path, axis=0)
    if not robot.is_point_mass:
        d[:, robot.dimension :] = np.mod(d[:, robot.dimension :] + np.pi, 2 * np.pi) - np.pi
    longest = float(np.linalg.norm(d, axis=1).max())
    return verify_path(robot, path, subdivide=max(1, int(np.ceil(longest / step)))).all_feasible


def balanced(robot, pose) -> bool:
    """Independently of taut's statics: tensions within the bounds balance the weight (or the
    constant wrench) at ``pose`` — a necessary condition of the planners' validity test."""
    d = robot.dimension
    exits = np.array([c.exit for c in robot.cables], float)
    if robot.is_point_mass:
        b = np.tile(pose[:d], (robot.n_cables, 1))
        R = np.eye(d)
    elif d == 2:
        c, s = np.cos(pose[2]), np.sin(pose[2])
        R = np.array([[c, -s], [s, c]])
        b = pose[:2] + np.array([c.anchor for c in robot.cables], float) @ R.T
    else:
        assert robot.orientation == "xyz-fixed"
        R = Rotation.from_euler("xyz", pose[3:]).as_matrix()  # Rz(c) Ry(b) Rx(a)
        b = pose[:3] + np.array([c.anchor for c in robot.cables], float) @ R.T
    u = exits - b
    u /= np.linalg.norm(u, axis=1)[:, None]
    p = pose[:d]
    rows = [u.T]
    if not robot.is_point_mass:
        r = b - p
        rows.append((r[:, 0] * u[:, 1] - r[:, 1] * u[:, 0])[None] if d == 2 else np.cross(r, u).T)
    W = np.vstack(rows)
    plat = robot.platform
    w = np.zeros(W.shape[0])
    if plat.wrench is not None:
        w += np.asarray(plat.wrench, float)
    if plat.mass is not None:
        w[:d] += plat.mass * np.asarray(plat.gravity, float)
    if plat.wrench_point is not None and not robot.is_point_mass:
        arm = R @ np.asarray(plat.wrench_point, float)
        F = w[:d]
        w[d:] += arm[0] * F[1] - arm[1] * F[0] if d == 2 else np.cross(arm, F)
    lo = np.array([c.tension[0] for c in robot.cables], float)
    hi = np.array([c.tension[1] for c in robot.cables], float)
    res = linprog(np.zeros(robot.n_cables), A_eq=W, b_eq=-w, bounds=list(zip(lo, hi)), method="highs")
    return res.status == 0


@pytest.fixture(scope="module")
def point_mass(tmp_path_factory):
    path = tmp_path_factory.mktemp("robots") / "point-mass.yaml"
    path.write_text(POINT_MASS)
    return load_robot(path)


def test_point_mass_around_the_infeasible_top_edge(point_mass):
    # near the top corners the weight cannot be held; the straight line between them leaves
    # the valid set, the lattice and RRT-Connect go below it
    start, goal = np.array([-0.92, 0.92]), np.array([0.92, 0.92])
    assert not verify_path(point_mass, [start, goal], subdivide=200).all_feasible
    for method in ("grid", "rrtconnect"):
        res = plan_path(point_mass, start, goal, method=method, seed=1)
        assert res.found and res.complete and not res.no_path
        assert np.array_equal(res.path[0], start) and np.array_equal(res.path[-1], goal)
        assert fine_step(point_mass, res.path)
        assert all(balanced(point_mass, q) for q in res.path)
        assert 1.84 < res.length < 2.5  # at least the straight line, at most a wide detour
        assert res.path[:, 1].min() < 0.9  # it went down


def test_rrtconnect_is_deterministic_per_seed(point_mass):
    a = plan_path(point_mass, [-0.92, 0.92], [0.92, 0.92], method="rrtconnect", seed=4)
    b = plan_path(point_mass, [-0.92, 0.92], [0.92, 0.92], method="rrtconnect", seed=4)
    assert np.array_equal(a.path, b.path) and a.nodes == b.nodes


def test_redundant_spatial_robot_rrtconnect():
    robot = example("spatial-8cable")  # 8 cables, xyz-fixed angles
    start, goal = np.zeros(6), np.array([0.0, 0.0, 0.0, 2.5, 0.0, 0.0])
    assert not verify_path(robot, [start, goal], subdivide=250).all_feasible
    res = plan_path(robot, start, goal, method="rrtconnect", seed=2)
    assert res.found and not res.no_path and res.method == "rrtconnect" and res.nodes > 2
    assert np.array_equal(res.path[0], start) and np.array_equal(res.path[-1], goal)
    assert fine_step(robot, res.path)
    assert all(balanced(robot, q) for q in res.path)
    assert res.length >= 2.5 - 1e-9
    # the benchmark's second query: OMPL's RRTConnect + simplifySolution reach a median of
    # 2.93 over ten seeds (benchmarks/bench_plan.py), this seed's path 2.92 before partial
    # shortcuts and the choice among several paths
    assert res.length < 2.8


@pytest.mark.slow
def test_redundant_robot_turns_the_short_way():
    # The benchmark's first query: the straight turn by 2.5 rad about z is not valid, and a
    # path turning the other way round, through ±π, is at least 2π − 2.5 = 3.78 long.  The one
    # path RRT-Connect finds first takes that way for this seed; the one that shortens best of
    # several does not.
    robot = example("spatial-8cable")
    start, goal = np.zeros(6), np.array([0, 0, 0, 0, 0, 2.5])
    first = plan_path(robot, start, goal, method="rrtconnect", seed=2, shorten=False)
    turn = np.sum(np.mod(np.diff(first.path[:, 5]) + np.pi, 2 * np.pi) - np.pi)
    assert first.found and turn == pytest.approx(2.5 - 2 * np.pi)
    res = plan_path(robot, start, goal, method="rrtconnect", seed=2)
    assert res.found and np.array_equal(res.path[0], start) and np.array_equal(res.path[-1], goal)
    assert 2.5 <= res.length < 2 * np.pi - 2.5
    assert fine_step(robot, res.path)


def test_goal_exactly_as_written_across_the_angle_seam():
    # yaw 3 and -3 are 0.28 rad apart the short way: the path takes it, and still ends at
    # the goal as written
    robot = example("spatial-8cable")
    start, goal = np.array([0, 0, 0, 0, 0, 3.0]), np.array([0, 0, 0, 0, 0, -3.0])
    res = plan_path(robot, start, goal, method="rrtconnect", seed=0)
    assert res.found and np.array_equal(res.path[-1], goal) and np.array_equal(res.path[0], start)
    assert res.length < 0.3
    assert fine_step(robot, res.path)


def test_planar_robot_grid_and_a_proof_of_no_path():
    robot = example("planar-4cable")
    # from the centre to the platform turned upside down: no valid orientation between about
    # 1.2 and 2 rad on either side, so the lattice closes the start's component
    res = plan_path(robot, [0, 0, 0], [0, 0, 3.0], method="grid", max_nodes=4000)
    assert not res.found and res.no_path and res.complete and res.expanded > 10
    # independently: at a sample of orientations between, no pose of the frame is valid
    xs = np.linspace(-0.95, 0.95, 9)
    for th in (1.3, 1.6, 1.9, -1.3, -1.6, -1.9):
        grid = np.array([[x, y, th] for x in xs for y in xs])
        assert not any(balanced(robot, q) for q in grid)
    # a query with a path: found by the lattice and by RRT-Connect
    start, goal = np.array([-0.5, -0.5, 0.0]), np.array([0.8, -0.5, 0.6])
    for method in ("grid", "rrtconnect"):
        res = plan_path(robot, start, goal, method=method, max_nodes=4000)
        assert res.found and np.array_equal(res.path[0], start) and np.array_equal(res.path[-1], goal)
        assert fine_step(robot, res.path)
        assert all(balanced(robot, q) for q in res.path)


def test_another_angle_convention(tmp_path):
    # the 8-cable robot in xyz-moving angles: the same rotations written otherwise
    text = example("spatial-8cable").model_dump(mode="json", exclude_none=True)
    text["orientation"] = "xyz-moving"
    from taut.model import Robot

    robot = Robot.model_validate(text)
    start, goal = np.zeros(6), np.array([0, 0, 0, 0, 0, 2.5])
    res = plan_path(robot, start, goal, method="rrtconnect", seed=1)
    assert res.found and np.array_equal(res.path[-1], goal)
    assert fine_step(robot, res.path)


def test_validity_beyond_wrench_feasibility(point_mass):
    start, goal = np.array([-0.5, -0.5]), np.array([0.5, -0.5])
    lengths = (0.0, 2.2)  # the cables to the top corners are 2.12 m long at the start and the goal
    res = plan_path(point_mass, start, goal, method="grid", lengths=lengths, interference=True, max_nodes=2000)
    assert res.found
    L = np.linalg.norm(res.path[:, None, :] - point_mass.exits[None], axis=2)  # point mass: anchors at p
    assert L.max() < 2.2
    check = verify_path(point_mass, res.path, subdivide=50, lengths=lengths, interference=True)
    assert check.all_feasible and check.lengths.max() < 2.2
    with pytest.raises(InfeasiblePoseError, match="start"):
        plan_path(point_mass, start, goal, method="grid", lengths=(0.0, 1.3))


@pytest.mark.parametrize(
    ("kwargs", "words"),
    [
        ({"method": "astar"}, "manifold"),
        ({"method": "rrtconnect", "bounds": ([0, 0], [1, 1])}, "outside the bounds"),
        ({"method": "grid", "spacing": 1e-4}, "max_nodes"),
        ({"method": "rrtconnect", "lengths": (2.0, 1.0)}, "lengths"),
        ({"method": "rrtconnect", "obstacles": True, "E": np.eye(3)}, "E"),
    ],
)
def test_bad_input_is_one_line(point_mass, kwargs, words):
    with pytest.raises(TautError, match=words) as err:
        plan_path(point_mass, [-0.5, 0.0], [0.5, 0.0], **kwargs)
    assert "\n" not in str(err.value)


def test_under_constrained_robot_is_refused():
    with pytest.raises(TautError, match="as many cables as wrench components"):
        plan_path(example("suspended-3cable"), np.zeros(6), np.zeros(6), method="rrtconnect")


def test_the_manifold_figure_refuses_a_pose_space_result(point_mass):
    from taut.errors import ArgumentError
    from taut.viz import plot_plan

    res = plan_path(point_mass, [-0.5, 0.0], [0.5, 0.0], method="rrtconnect")
    assert res.found and res.atlas is None and res.charts == 0
    with pytest.raises(ArgumentError, match="rrtconnect"):
        plot_plan(None, res, None)


def test_cogiro_path_near_a_thin_invalid_sheet_passes_the_fine_check():
    # The benchmark's fourth query, seed 9: without the planners' margin the path crossed an
    # invalid sheet 0.0008 wide (near a singular pose) between its checked poses, and failed
    # verify_path at a 0.001 step.
    robot = example("cogiro")
    start, goal = np.array([0, 0, 5.35, 0, 0, 1.5]), np.array([0, 0, 5.35, 0, 0, -1.5])
    pts = np.vstack([robot.exits, start[None, :3], goal[None, :3]])
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    half, centre = 0.5 * (hi - lo).max(), 0.5 * (lo + hi)
    box = (np.minimum(lo, centre - half), np.maximum(hi, centre + half))
    res = plan_path(robot, start, goal, method="rrtconnect", seed=9, bounds=box, resolution=0.01)
    assert res.found and np.array_equal(res.path[0], start) and np.array_equal(res.path[-1], goal)
    assert fine_step(robot, res.path, 1e-3)
    assert all(balanced(robot, q) for q in res.path)


@pytest.mark.slow
@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(seed=st.integers(0, 2**16))
def test_shortening_never_lengthens_and_keeps_validity(point_mass, seed):
    from taut.planning._posespace import _rrt, pose_space, simplify, with_margin

    # with the planners' margin, as the planners shorten
    start, goal = np.array([-0.92, 0.92]), np.array([0.92, 0.92])
    space = with_margin(pose_space(point_mass, start, goal), start, goal)
    rng = np.random.default_rng(seed)
    kw = dict(step=None, resolution=0.01, max_nodes=5000, time_limit=None, progress=None)
    raw = _rrt(space, start, goal, rng=rng, shorten=False, final=False, **kw).path
    short = simplify(space, raw, 0.01, rng, np.inf)
    length = lambda p: float(np.linalg.norm(np.diff(p, axis=0), axis=1).sum())  # noqa: E731
    assert length(short) <= length(raw) + 1e-12
    assert np.array_equal(short[0], raw[0]) and np.array_equal(short[-1], raw[-1])
    assert fine_step(point_mass, short)
    assert all(balanced(point_mass, q) for q in short)
