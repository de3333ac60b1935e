"""AtlasRRT (Jaillet & Porta 2013) on manifolds of known geometry and on the Robocrane's
wrench-feasible slice, every path checked by the independent feasibility test."""

import numpy as np
import pytest

from taut.errors import TautError
from taut.kinematics import platform_frame
from taut.model import load_robot
from taut.planning import ImplicitManifold, plan_path
from taut.planning._manifold import WrenchFeasibleManifold
from taut.planning._verify import verify_path

ROBOT = load_robot("robocrane")
POSES = {k: np.array(v) for k, v in ROBOT.reference.poses.items()}
SIGMA = 7 * np.pi / 36
SLICE = dict(x=0.0, y=0.0, z=2.0, sigma=SIGMA)
M = WrenchFeasibleManifold.from_robot(ROBOT, fixed=SLICE)
SPHERE = ImplicitManifold(lambda x: np.array([x @ x - 1]), lambda x: 2 * x[None, :], 2)


def same_pose(a, b) -> bool:
    """Same platform position and rotation (the robot's own orientation convention)."""
    (pa, Ra), (pb, Rb) = (platform_frame(ROBOT, np.asarray(q, float)[None]) for q in (a, b))
    return bool(np.allclose(pa, pb, atol=1e-9) and np.allclose(Ra, Rb, atol=1e-9))


def test_sphere_path_stays_on_the_sphere_and_is_no_shorter_than_the_great_circle():
    a, b = np.array([1.0, 0, 0]), np.array([-0.6, 0.8, 0])
    geodesic = np.arccos(a @ b)
    res = plan_path(SPHERE, a, b, method="atlasrrt", radius=0.3, seed=3)
    assert res.found and not res.no_path
    np.testing.assert_allclose(np.linalg.norm(res.path, axis=1), 1.0, atol=1e-8)
    np.testing.assert_allclose(res.path[0], a)
    np.testing.assert_allclose(res.path[-1], b, atol=1e-12)
    assert np.linalg.norm(np.diff(res.path, axis=0), axis=1).max() <= 0.3 / 4 * 1.5
    # the chord length of a polyline on the unit sphere never exceeds its arc length
    assert res.length >= 2 * np.sin(geodesic / 2) * 0.999
    short = plan_path(SPHERE, a, b, method="atlasrrt", radius=0.3, seed=3, shorten=True)
    assert short.found and short.length <= res.length + 1e-12
    np.testing.assert_allclose(np.linalg.norm(short.path, axis=1), 1.0, atol=1e-8)


def test_same_seed_same_path_other_seed_other_tree():
    y1, y2 = M.lift(POSES["q1"]), M.lift(POSES["q2"])
    r1 = plan_path(M.implicit(), y1, y2, method="atlasrrt", radius=0.4, step=0.1, metric=M.pose_metric, seed=7)
    r2 = plan_path(M.implicit(), y1, y2, method="atlasrrt", radius=0.4, step=0.1, metric=M.pose_metric, seed=7)
    assert r1.found and np.array_equal(r1.path, r2.path) and r1.charts == r2.charts


@pytest.mark.parametrize("query", [("q1", "q2"), ("q3", "q4")])
@pytest.mark.parametrize("bidirectional", [True, False])
def test_robocrane_queries_are_verified_independently(query, bidirectional):
    a, b = query
    res = plan_path(
        M.implicit(),
        M.lift(POSES[a]),
        M.lift(POSES[b]),
        method="atlasrrt",
        radius=0.4,
        step=0.1,
        metric=M.pose_metric,
        seed=1,
        bidirectional=bidirectional,
        shorten=True,
    )
    assert res.found and not res.no_path
    poses = M.pose(res.path)
    np.testing.assert_allclose(poses[0], POSES[a], atol=1e-9)
    assert same_pose(poses[-1], POSES[b])
    np.testing.assert_allclose(poses[:, [0, 1, 2, 5]], np.broadcast_to([0, 0, 2, SIGMA], (len(poses), 4)), atol=1e-9)
    assert np.abs(np.diff(poses, axis=0)).max() < 0.2  # a continuous path, not a jump
    assert verify_path(ROBOT, poses, subdivide=10).all_feasible
    # not shorter than the shortest straight line between the two poses modulo the symmetry
    ends = [np.r_[POSES[b][3] + h * np.pi + 2 * np.pi * i, (-1) ** h * POSES[b][4]] for h in (0, 1) for i in (-1, 0, 1)]
    assert res.length >= min(np.linalg.norm(e - POSES[a][3:5]) for e in ends) - 1e-9


@pytest.mark.slow
def test_separate_islands_give_no_path_within_the_budget():
    # two "upside-down" islands of the slice (test_robocrane proves them disconnected)
    y1, y2 = M.lift([0, 0, 2, -1.3, 2.2, SIGMA]), M.lift([0, 0, 2, 0.6, 2.4, SIGMA])
    res = plan_path(M.implicit(), y1, y2, method="atlasrrt", radius=0.3, metric=M.pose_metric, seed=0, max_nodes=300)
    assert not res.found and not res.no_path and len(res.path) == 0
    assert res.nodes >= 300
    poses = M.pose(res.atlas.centres)
    assert np.all(poses[:, 4] > 1.4)  # both trees stayed on their islands
    # the complete search proves it
    assert plan_path(M.implicit(), y1, y2, radius=0.3, metric=M.pose_metric).no_path


def test_bad_arguments_are_refused():
    a, b = np.array([1.0, 0, 0]), np.array([0, 1.0, 0])
    with pytest.raises(TautError, match="goal"):
        plan_path(SPHERE, a, 2 * b, method="atlasrrt", radius=0.3)
    with pytest.raises(TautError, match="start"):
        plan_path(SPHERE, 2 * a, b, method="atlasrrt", radius=0.3)
    with pytest.raises(TautError, match="step"):
        plan_path(SPHERE, a, b, method="atlasrrt", radius=0.3, step=0.5)
    with pytest.raises(TautError, match="max_nodes"):
        plan_path(SPHERE, a, b, method="atlasrrt", radius=0.3, max_nodes=1)


def test_q5_to_q6_on_the_3d_slice_x_y_0():
    # experiment 2 of Bohigas et al. (Fig. 7), which A* needs tens of seconds for
    fixed = dict(x=0.0, y=0.0, sigma=SIGMA)
    M3 = WrenchFeasibleManifold.from_robot(ROBOT, fixed=fixed)
    res = plan_path(
        M3.implicit(),
        M3.lift(POSES["q5"]),
        M3.lift(POSES["q6"]),
        method="atlasrrt",
        radius=0.4,
        metric=M3.pose_metric,
        seed=0,
    )
    assert res.found and res.atlas.manifold.dim == 3
    poses = M3.pose(res.path)
    np.testing.assert_allclose(poses[0], POSES["q5"], atol=1e-9)
    assert same_pose(poses[-1], POSES["q6"])
    np.testing.assert_allclose(poses[:, [0, 1, 5]], np.broadcast_to([0, 0, SIGMA], (len(poses), 3)), atol=1e-9)
    assert verify_path(ROBOT, poses, subdivide=10).all_feasible
