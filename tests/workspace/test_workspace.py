"""Workspace conditions, grids and grid evaluation."""

import json
import subprocess
import sys

import numpy as np
import pytest
from axis_rotations import rx, ry, rz
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import linprog

import taut
from taut.errors import GridSizeError, PoseError, TautError
from taut.kinematics import batch_structure_matrices, jointed_structure_matrix, structure_matrix
from taut.model import robot_from_dict
from taut.statics import BoxWrenchSet, external_wrench
from taut.workspace import (
    CONDITIONS,
    WorkspaceCondition,
    WorkspaceResult,
    default_bounds,
    default_wrench_set,
    evaluate_workspace,
    make_condition,
    pose_grid,
    position_grid,
)
from taut.workspace import _evaluate as evaluate_module

PLANAR = taut.example("planar-4cable")
SPATIAL = taut.example("spatial-8cable")


def lp_equilibrium(W, tmin, tmax, w) -> bool:
    bounds = [(lo, None if np.isinf(hi) else hi) for lo, hi in zip(tmin, tmax)]
    return linprog(np.zeros(W.shape[1]), A_eq=W, b_eq=-w, bounds=bounds, method="highs").status == 0


def lp_closure(W) -> bool:
    m, n = W.shape
    if np.linalg.matrix_rank(W) < m:
        return False
    return linprog(np.zeros(n), A_eq=W, b_eq=np.zeros(m), bounds=[(1, None)] * n, method="highs").status == 0


def triangle_robot(**platform):
    return robot_from_dict(
        {
            "name": "planar point-mass triangle",
            "dimension": 2,
            "platform": {"kind": "point-mass", **platform},
            "cables": [{"exit": [0, 0]}, {"exit": [2, 0]}, {"exit": [1, 2]}],
        }
    )


def test_registry_and_condition_factory():
    assert {"wrench-closure", "wrench-feasible", "static"} <= set(CONDITIONS)
    for name, cls in CONDITIONS.items():
        assert issubclass(cls, WorkspaceCondition) and cls.name == name
    assert make_condition("static").name == "static"
    ws = BoxWrenchSet.around(np.zeros(3), np.ones(3))
    assert make_condition("wrench-feasible", wrench_set=ws).wrench_set is ws
    with pytest.raises(TautError, match="unknown workspace condition"):
        make_condition("nope")
    with pytest.raises(TautError, match="does not take"):
        make_condition("wrench-closure", wrench_set=ws)


def test_wrench_closure_of_a_point_mass_triangle_is_its_interior():
    robot = triangle_robot()
    axis = 0.05 + 0.1 * np.arange(20)  # never on an edge of the triangle
    res = evaluate_workspace(robot, "wrench-closure", grid=[axis, axis])
    X, Y = np.meshgrid(axis, axis, indexing="ij")
    expected = (Y > 0) & (Y < 2 * X) & (Y < 4 - 2 * X)
    assert res.grid_shape == (20, 20)
    assert np.array_equal(res.inside.reshape(res.grid_shape), expected)
    np.testing.assert_allclose(res.poses.reshape(20, 20, 2)[..., 0], X)
    assert res.measure == pytest.approx(expected.sum() * 0.01)


def test_static_of_a_hanging_point_mass_triangle():
    """Weight down: the cables hold it where the upward cables can (y below the apex)."""
    robot = triangle_robot(mass=1.0, gravity=[0, -9.81])
    res = evaluate_workspace(robot, "static", resolution=15)
    W = structure_matrix(robot, res.poses)
    w = external_wrench(robot, res.poses)
    expected = [lp_equilibrium(W[k], *robot.tension_bounds, w[k]) for k in range(len(res.poses))]
    assert res.inside.tolist() == expected
    assert 0 < res.count < len(res.poses)


def test_zero_length_cable_poses_are_outside():
    robot = triangle_robot(mass=1.0)
    poses = np.array([[1.0, 0.5], [1.0, 2.0], [0.0, 0.0], [1.0, 0.6]])  # two poses on exits
    for name in CONDITIONS:
        res = evaluate_workspace(robot, name, poses=poses)
        assert res.inside.tolist()[1:3] == [False, False]
        assert res.axes == () and res.grid_shape == (4,) and res.measure is None
    assert evaluate_workspace(robot, "wrench-closure", poses=poses).inside.tolist() == [True, False, False, True]


@pytest.mark.parametrize("robot", [PLANAR, SPATIAL], ids=["planar-4cable", "spatial-8cable"])
def test_static_and_closure_agree_with_lp_oracles(robot):
    res_s = evaluate_workspace(robot, "static", resolution=9 if robot.dimension == 3 else 25)
    res_c = evaluate_workspace(robot, "wrench-closure", resolution=9 if robot.dimension == 3 else 25)
    rng = np.random.default_rng(0)
    pick = rng.choice(len(res_s.poses), 120, replace=False)
    W = structure_matrix(robot, res_s.poses[pick])
    w = external_wrench(robot, res_s.poses[pick])
    tmin, tmax = robot.tension_bounds
    assert res_s.inside[pick].tolist() == [lp_equilibrium(W[k], tmin, tmax, w[k]) for k in range(len(pick))]
    assert res_c.inside[pick].tolist() == [lp_closure(W[k]) for k in range(len(pick))]
    assert 0 < res_s.count < len(res_s.poses)


@pytest.mark.parametrize("robot", [PLANAR, SPATIAL], ids=["planar-4cable", "spatial-8cable"])
def test_wrench_feasible_agrees_with_vertex_lps(robot):
    res = evaluate_workspace(robot, "wrench-feasible", resolution=7 if robot.dimension == 3 else 21)
    rng = np.random.default_rng(1)
    inside, outside = np.flatnonzero(res.inside), np.flatnonzero(~res.inside)
    assert inside.size and outside.size
    pick = np.concatenate([rng.choice(inside, 12, replace=False), rng.choice(outside, 12, replace=False)])
    W = structure_matrix(robot, res.poses[pick])
    w = external_wrench(robot, res.poses[pick])
    box = default_wrench_set(robot)
    tmin, tmax = robot.tension_bounds
    expected = [all(lp_equilibrium(W[k], tmin, tmax, w[k] + v) for v in box.vertices()) for k in range(len(pick))]
    assert res.inside[pick].tolist() == expected


def test_wrench_feasible_nests_and_reduces_to_static():
    for robot in (PLANAR, SPATIAL):
        res_f = evaluate_workspace(robot, "wrench-feasible", resolution=11)
        res_s = evaluate_workspace(robot, "static", resolution=11)
        assert np.all(res_f.inside <= res_s.inside)  # the box contains the external wrench
        assert res_f.count < res_s.count
        zero = BoxWrenchSet.around(np.zeros(robot.wrench_dim), np.zeros(robot.wrench_dim))
        res_0 = evaluate_workspace(robot, "wrench-feasible", resolution=11, wrench_set=zero)
        assert np.array_equal(res_0.inside, res_s.inside)


def test_default_wrench_set_values():
    box = default_wrench_set(SPATIAL)  # 5 kg: F = 49.05 N; moments from the platform radius
    f = 0.1 * 5 * 9.81
    rho = max(np.linalg.norm(c.anchor) for c in SPATIAL.cables)
    np.testing.assert_allclose(box.upper, [f, f, f] + [f * rho] * 3)
    np.testing.assert_allclose(box.lower, -box.upper)
    box2 = default_wrench_set(PLANAR)  # 1 kg: 0.98 N raised to the 1 N floor
    np.testing.assert_allclose(box2.upper, [1.0, 1.0, np.hypot(0.1, 0.05)])
    assert default_wrench_set(triangle_robot()).upper.tolist() == [1.0, 1.0]


def test_under_constrained_robot_static():
    """3 cables, 6 DOF: equilibrium hanging below the centroid of the exits (LP fallback)."""
    exits = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.5, 0.866, 0.0]])
    c = exits.mean(axis=0)
    robot = robot_from_dict(
        {
            "name": "3-cable suspended",
            "dimension": 3,
            "platform": {"kind": "rigid", "mass": 2.0, "gravity": [0, 0, -9.81]},
            "cables": [{"exit": e.tolist(), "anchor": (0.1 * (e - c)).tolist()} for e in exits],
        }
    )
    home = np.array([c[0], c[1], -1.0, 0, 0, 0])
    poses = np.array([home, home + [0.05, 0, 0, 0, 0, 0], home + [0, 0, 0, 0, 0, 0.1], home * [1, 1, -1, 1, 1, 1]])
    res = evaluate_workspace(robot, "static", poses=poses)
    # shifted sideways or twisted it cannot balance; above the exits the cables push
    assert res.inside.tolist() == [True, False, False, False]
    assert not evaluate_workspace(robot, "wrench-closure", poses=poses).inside.any()
    assert not evaluate_workspace(robot, "wrench-feasible", poses=poses).inside.any()


def test_grid_defaults_and_bounds():
    b = default_bounds(PLANAR)
    np.testing.assert_allclose(b, [[-0.96, 0.96], [-0.96, 0.96]])
    g = position_grid(SPATIAL, resolution=5)
    assert g.shape == (5, 5, 5) and g.poses().shape == (125, 6)
    assert np.all(g.poses()[:, 3:] == 0)
    res = evaluate_workspace(PLANAR, "static", grid=[(-0.5, 0.5, 5), (-0.2, 0.2, 3)], orientation=[0.1])
    assert res.grid_shape == (5, 3) and np.all(res.poses[:, 2] == 0.1)
    np.testing.assert_allclose(res.axes[1], [-0.2, 0.0, 0.2])
    assert res.poses[1].tolist() == [-0.5, 0.0, 0.1]  # C order: the last axis varies fastest
    full = evaluate_workspace(PLANAR, "static", grid=[(-0.5, 0.5, 3), (-0.5, 0.5, 3), (-0.2, 0.2, 3)])
    assert full.grid_shape == (3, 3, 3) and len(np.unique(full.poses[:, 2])) == 3
    flat = default_bounds(triangle_robot().model_copy(update={"dimension": 2}))
    assert flat.shape == (2, 2)
    with pytest.raises(TautError):
        evaluate_workspace(PLANAR, "static", grid=[(-0.5, 0.5, 2.5), (0, 1, 3)])
    with pytest.raises(TautError):
        evaluate_workspace(PLANAR, "static", orientation=[0.1, 0.2])
    with pytest.raises(PoseError):
        evaluate_workspace(PLANAR, "static", poses=np.zeros((3, 2)))


def test_result_summary_save_load_and_progress(tmp_path):
    calls = []
    res = evaluate_workspace(
        PLANAR, "wrench-feasible", resolution=30, chunk=100, progress=lambda d, t: calls.append((d, t))
    )
    assert calls[0] == (0, 900) and calls[-1] == (900, 900)
    assert [d for d, _ in calls] == sorted(d for d, _ in calls) and len(calls) == 10
    again = evaluate_workspace(PLANAR, "wrench-feasible", resolution=30)  # one chunk
    assert np.array_equal(res.inside, again.inside)
    s = res.summary()
    assert s["poses"] == 900 and s["inside"] == res.count and s["fraction"] == pytest.approx(res.count / 900)
    cell = (res.axes[0][1] - res.axes[0][0]) * (res.axes[1][1] - res.axes[1][0])
    assert s["measure"] == pytest.approx(res.count * cell)
    path = tmp_path / "ws.npz"
    res.save(path)
    back = WorkspaceResult.load(path)
    assert back.condition == "wrench-feasible" and back.robot_name == PLANAR.name
    assert np.array_equal(back.inside, res.inside) and np.array_equal(back.poses, res.poses)
    assert back.grid_shape == (30, 30) and back.axis_names == ("x", "y")
    np.testing.assert_array_equal(back.axes[1], res.axes[1])


def test_jointed_robot_uses_the_numpy_path():
    robot = taut.example("adjustable-8cable")
    res = evaluate_workspace(robot, "wrench-closure", resolution=4)
    assert res.grid_shape == (4, 4, 4) and res.poses.shape == (64, robot.pose_size)
    assert np.all(res.poses[:, -1] == robot.joint_limits.mean(axis=1))  # joint at mid-range
    # the passive joint's row too: the cables alone must span it (the jointed structure matrix)
    A = jointed_structure_matrix(robot, res.poses)[:, :, : robot.n_cables]
    assert res.inside.tolist() == [lp_closure(A[k]) for k in range(64)]


#: The orientation conventions written out from elementary rotations (docs/architecture.md §2.3).
ROTATIONS = {
    "xyz-fixed": lambda a, b, c: rz(c) @ ry(b) @ rx(a),
    "xyz-moving": lambda a, b, c: rx(a) @ ry(b) @ rz(c),
    "tilt-torsion": lambda phi, theta, sigma: rz(phi) @ ry(theta) @ rz(sigma - phi),
}


def reference_structure_matrix(robot, pose: np.ndarray) -> np.ndarray:
    """W = [u_i ; (R r_i) × u_i] column by column from the cables' raw exit and anchor
    numbers, u_i = (a_i − b_i)/|a_i − b_i|, b_i = p + R r_i."""
    d = robot.dimension
    p = pose[:d]
    if robot.is_point_mass:
        R = np.eye(d)
    elif d == 2:
        c, s = np.cos(pose[2]), np.sin(pose[2])
        R = np.array([[c, -s], [s, c]])
    else:
        R = ROTATIONS[robot.orientation](*pose[3:6])
    cols = []
    for cable in robot.cables:
        a = np.array(cable.exit, float)
        r = np.zeros(d) if cable.anchor is None else np.array(cable.anchor, float)
        Rr = R @ r
        u = (a - (p + Rr)) / np.linalg.norm(a - (p + Rr))
        if robot.is_point_mass:
            cols.append(u)
        elif d == 2:
            cols.append(np.array([u[0], u[1], Rr[0] * u[1] - Rr[1] * u[0]]))
        else:
            cols.append(np.concatenate([u, np.cross(Rr, u)]))
    return np.array(cols).T


STRUCTURE_ROBOTS = [
    PLANAR,
    triangle_robot(),
    *(SPATIAL.model_copy(update={"orientation": conv}) for conv in ROTATIONS),
]


@given(
    which=st.integers(0, len(STRUCTURE_ROBOTS) - 1),
    unit=st.lists(st.floats(-1.0, 1.0), min_size=6, max_size=6),
)
@settings(max_examples=150, deadline=None)
def test_batch_structure_matrices_match_an_independent_computation(which, unit):
    robot = STRUCTURE_ROBOTS[which]
    d = robot.dimension
    lo, hi = robot.exits.min(axis=0), robot.exits.max(axis=0)
    u = np.array(unit)
    position = (lo + hi) / 2 + 0.45 * (hi - lo) * u[:d]
    pose = np.concatenate([position, np.pi * u[d : d + robot.pose_size - d]])
    _, W, ok = batch_structure_matrices(robot, pose[None])
    expected = reference_structure_matrix(robot, pose)
    assert ok[0] and W.shape == (1, *expected.shape)
    np.testing.assert_allclose(W[0], expected, atol=1e-12)


def test_chunked_verdicts_equal_unchunked_ones():
    """Any chunk and batch size gives the verdicts of one chunk, on a full pose grid and on
    the same poses given as an array."""
    grid = [(-0.8, 0.8, 9), (-0.8, 0.8, 7), (-0.4, 0.4, 5)]
    whole = evaluate_workspace(PLANAR, "wrench-feasible", grid=grid, chunk=10_000)
    assert 0 < whole.count < whole.size == 315

    @given(chunk=st.integers(1, 400), batch=st.integers(1, 400))
    @settings(max_examples=25, deadline=None)
    def check(chunk: int, batch: int) -> None:
        with pytest.MonkeyPatch.context() as mp:
            mp.setattr(evaluate_module, "BATCH_POSES", batch)
            calls = []
            res = evaluate_workspace(
                PLANAR, "wrench-feasible", grid=grid, chunk=chunk, progress=lambda d, t: calls.append(d)
            )
            explicit = evaluate_workspace(PLANAR, "wrench-feasible", poses=whole.poses, chunk=chunk)
        assert np.array_equal(res.inside, whole.inside)
        assert np.array_equal(explicit.inside, whole.inside)
        assert calls[-1] == 315 and len(calls) == 1 + -(-315 // chunk)

    check()


def test_grid_poses_are_generated_on_demand():
    res = evaluate_workspace(SPATIAL, "static", grid=[(-0.3, 0.3, 4), (-0.3, 0.3, 3), (-0.2, 0.2, 2)])
    assert res.explicit_poses is None and res.grid is not None
    X, Y, Z = np.meshgrid(*res.axes, indexing="ij")
    expected = np.stack([X.ravel(), Y.ravel(), Z.ravel()], axis=1)
    np.testing.assert_array_equal(res.poses[:, :3], expected)
    np.testing.assert_array_equal(res.poses_at([23, 0, 5])[:, :3], expected[[23, 0, 5]])
    assert not res.poses[:, 3:].any()
    with pytest.raises(TautError, match="indices"):
        res.poses_at([24])
    # 2**25 poses of 6 coordinates: 1.5 GiB as one array, refused; single poses are fine
    huge = pose_grid(SPATIAL, [(-0.1, 0.1, 32)] * 5 + [(0.1, 0.1, 1)])
    big = WorkspaceResult("r", "static", np.zeros(huge.size, bool), huge.axes, huge.shape, 0.0, grid=huge)
    with pytest.raises(GridSizeError, match="33,554,432 poses"):
        _ = big.poses
    np.testing.assert_allclose(big.poses_at([huge.size - 1]), [[0.1] * 5 + [0.1]])


def test_absurd_grids_are_refused_before_any_allocation():
    with pytest.raises(GridSizeError, match=r"1,000,000,000,000,000,000,000 poses .*EiB"):
        evaluate_workspace(SPATIAL, "static", resolution=10_000_000)
    with pytest.raises(GridSizeError, match="1,099,511,627,776 poses"):
        evaluate_workspace(PLANAR, "static", grid=[(0, 1, 2**20), (0, 1, 2**20)])
    with pytest.raises(GridSizeError):
        pose_grid(SPATIAL, [(0, 1, 100)] * 6)
    assert issubclass(GridSizeError, TautError)


BOUNDED_MEMORY_SCRIPT = """
import resource, sys
import numpy as np
import taut
from taut.workspace import evaluate_workspace

robot = taut.example("planar-4cable")
grid = [(-0.9, 0.9, 160), (-0.9, 0.9, 125), (-0.5, 0.5, 100)]  # 2,000,000 poses
evaluate_workspace(robot, "wrench-closure", grid=[(-0.9, 0.9, 3)] * 3, chunk=7)  # warm up
vm = next(int(line.split()[1]) for line in open("/proc/self/status") if line.startswith("VmSize")) * 1024
headroom = 32 << 20  # below the 48 MB of the full (2e6, 3) pose array
resource.setrlimit(resource.RLIMIT_AS, (vm + headroom, vm + headroom))
before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
res = evaluate_workspace(robot, "wrench-closure", grid=grid)
growth = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before
pick = np.random.default_rng(0).choice(res.size, 2000, replace=False)
sample = evaluate_workspace(robot, "wrench-closure", poses=res.poses_at(pick))
try:
    np.ones((res.size, 3))
    full = "allocated"
except MemoryError:
    full = "refused"
print(res.size, res.count, growth, full, bool(np.array_equal(sample.inside, res.inside[pick])))
"""


@pytest.mark.slow
def test_a_large_grid_runs_in_bounded_memory():
    """2 M poses under an address-space limit that a (2e6, 3) pose array does not fit in."""
    out = subprocess.run([sys.executable, "-c", BOUNDED_MEMORY_SCRIPT], capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    size, count, growth_kib, full, same = out.stdout.split()
    assert int(size) == 2_000_000 and 0 < int(count) < 2_000_000
    assert full == "refused"  # the limit would have stopped a full pose array
    assert int(growth_kib) < 24 * 1024  # verdicts (2 MB) and a few chunks' work
    assert same == "True"


def test_a_grid_too_large_to_list_its_poses_still_plots():
    """27 M poses (the ``--grid 300`` grid of spatial-8cable): 1.2 GiB of poses, refused as
    one array; the figure computes only the poses it draws."""
    import matplotlib

    matplotlib.use("Agg")
    from taut.viz import plot_workspace

    grid = position_grid(SPATIAL, resolution=300, orientation=[0.0, 0.1, 0.0])
    X, Y, Z = np.meshgrid(*grid.axes, indexing="ij", sparse=True)
    box = ((np.abs(X) < 0.5) & (np.abs(Y) < 0.3) & (np.abs(Z) < 0.5)).ravel()  # bool only: 27 MB
    res = WorkspaceResult(SPATIAL.name, "static", box, grid.axes, grid.shape, 0.0, ("x", "y", "z"), grid)
    with pytest.raises(GridSizeError):
        _ = res.poses
    ax = plot_workspace(res, SPATIAL, max_points=500)
    (scatter,) = [c for c in ax.collections if c.get_gid() == "workspace"]
    pts = np.column_stack(scatter._offsets3d)
    assert pts.shape == (500, 3) and np.all(np.abs(pts) < [0.5, 0.3, 0.5])
    assert "b=0.1" in ax.get_title() and "a=0" in ax.get_title()


def test_save_and_load_keep_the_poses_without_storing_those_of_a_grid(tmp_path):
    res = evaluate_workspace(SPATIAL, "static", grid=[(-0.3, 0.3, 20), (-0.3, 0.3, 20), (-0.3, 0.3, 20)])
    res.save(tmp_path / "grid.npz")
    with np.load(tmp_path / "grid.npz") as f:
        assert "poses" not in f.files  # the grid's definition stands for its poses
    back = WorkspaceResult.load(tmp_path / "grid.npz")
    assert np.array_equal(back.poses, res.poses) and np.array_equal(back.inside, res.inside)
    explicit = evaluate_workspace(SPATIAL, "static", poses=res.poses[::7])
    explicit.save(tmp_path / "poses.npz")
    again = WorkspaceResult.load(tmp_path / "poses.npz")
    assert again.grid is None and np.array_equal(again.poses, res.poses[::7])
    assert np.array_equal(again.inside, res.inside[::7]) and again.grid_shape == (len(res.poses[::7]),)
    # the first format stored the poses themselves
    meta = {"robot": "r", "condition": "static", "grid_shape": [20, 20, 20], "elapsed_s": 1.0}
    np.savez_compressed(
        tmp_path / "v1.npz",
        poses=res.poses,
        inside=res.inside,
        metadata=np.array(json.dumps(meta | {"format": "taut-workspace/1"})),
        **{f"axis_{i}": a for i, a in enumerate(res.axes)},
    )
    old = WorkspaceResult.load(tmp_path / "v1.npz")
    assert np.array_equal(old.poses, res.poses) and old.measure == res.measure
    with pytest.raises(TautError, match="not a taut workspace file"):
        WorkspaceResult.load(tmp_path / "nothing.npz")


@pytest.mark.slow
def test_chunks_of_many_capsule_pairs_hold_one_pose_each(robot_2000_cables):
    """2000 cables have 2 million capsule pairs: the interference-free condition is evaluated
    (and its progress reported) pose by pose, not in chunks of 349 poses that would hold
    11 GB of distances and report nothing for minutes."""
    robot = robot_2000_cables
    poses = np.array([[0.0, 0.0, 0.0], [0.5, 0.0, 0.0]])
    calls = []
    res = evaluate_workspace(robot, "interference-free", poses=poses, progress=lambda d, t: calls.append((d, t)))
    assert calls == [(0, 2), (1, 2), (2, 2)]
    assert evaluate_module.CHUNK_ELEMENTS // (robot.wrench_dim * robot.n_cables) == 349  # the old chunk
    # independently: no two cables (radius 0, no end shared) cross, by GEOS's segment tests
    import shapely

    crossing = []
    for x, y, t in poses:
        rot = np.array([[np.cos(t), -np.sin(t)], [np.sin(t), np.cos(t)]])
        lines = shapely.linestrings(np.stack([robot.exits, robot.anchors @ rot.T + [x, y]], axis=1))
        i, j = shapely.STRtree(lines).query(lines, predicate="intersects")
        crossing.append(int(np.count_nonzero(i < j)))
    assert crossing[0] == 0 and crossing[1] > 0  # both verdicts occur
    assert res.inside.tolist() == [c == 0 for c in crossing]
