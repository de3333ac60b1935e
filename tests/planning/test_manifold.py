"""The wrench-feasible manifold of Eqs. (1)–(8) of Bohigas et al. (2013) and the
Robocrane query q1 → q2, verified independently by taut.statics._feasibility."""

import numpy as np
import pytest

from taut.errors import InfeasiblePoseError, PoseError
from taut.kinematics import platform_frame
from taut.model import load_robot
from taut.planning import plan_path, tangent_basis
from taut.planning._manifold import WrenchFeasibleManifold
from taut.planning._verify import verify_path

ROBOT = load_robot("robocrane")
POSES = {k: np.array(v) for k, v in ROBOT.reference.poses.items()}
SIGMA = 7 * np.pi / 36
SLICE = dict(x=0.0, y=0.0, z=2.0, sigma=SIGMA)


def same_pose(robot, a, b) -> bool:
    """Same platform position and rotation (the robot's own orientation convention)."""
    (pa, Ra), (pb, Rb) = (platform_frame(robot, np.asarray(q, float)[None]) for q in (a, b))
    return bool(np.allclose(pa, pb, atol=1e-9) and np.allclose(Ra, Rb, atol=1e-9))


def test_lift_solves_the_equations_and_jacobian_matches_finite_differences():
    M = WrenchFeasibleManifold.from_robot(ROBOT)
    x = M.full(M.lift(POSES["q1"]))
    assert np.abs(M.full_function(x)).max() < 1e-12
    Ja = M.full_jacobian(x)
    h = 1e-6
    Jn = np.stack([(M.full_function(x + h * e) - M.full_function(x - h * e)) / (2 * h) for e in np.eye(x.size)], 1)
    assert np.abs(Ja - Jn).max() <= 1e-6 * np.abs(Ja).max()
    assert np.linalg.matrix_rank(Ja) == 93  # a smooth 6-manifold (Appendix A)


@pytest.mark.parametrize("fixed,k", [({}, 6), (dict(x=0.0, y=0.0, sigma=SIGMA), 3), (SLICE, 2)])
def test_slices_have_the_right_dimension(fixed, k):
    M = WrenchFeasibleManifold.from_robot(ROBOT, fixed=fixed)
    mf = M.implicit()
    y = M.lift(POSES["q1"])
    assert mf.dim == k and y.size == 99 - len(fixed)
    assert np.abs(mf.function(y)).max() < 1e-12
    J = mf.jacobian(y)
    assert J.shape == (93, y.size) and np.linalg.matrix_rank(J) == 93
    # a tangent step stays on the manifold to second order
    T = tangent_basis(J, k)
    assert np.abs(mf.function(y + 1e-4 * T[:, 0])).max() < 1e-5
    assert np.allclose(M.pose(y), POSES["q1"])


def test_extreme_tensions_bound_the_tensions_of_the_ellipsoid():
    M = WrenchFeasibleManifold.from_robot(ROBOT)
    R, u, rho, f0, V = M.extreme_tensions(POSES["q1"])
    J = np.vstack([(u / rho[:, None]).T, np.cross((M.c @ R.T), u / rho[:, None]).T])
    dirs = np.random.default_rng(0).normal(size=(2000, 6))
    dw = 1e-2 * dirs / np.linalg.norm(dirs, axis=1)[:, None]  # boundary of E = 1e4 I
    f = f0 + np.linalg.solve(J, dw.T).T
    assert np.all(f >= f0 - np.diag(V) - 1e-12) and np.all(f <= f0 + np.diag(V) + 1e-12)
    assert np.allclose(np.abs(f - f0).max(0), np.diag(V), rtol=0.2)  # attained nearly


def test_planner_feasibility_agrees_with_the_independent_test():
    M = WrenchFeasibleManifold.from_robot(ROBOT, fixed=SLICE)
    rng = np.random.default_rng(3)
    poses = np.tile(POSES["q1"], (300, 1))
    poses[:, 3] = rng.uniform(-np.pi, np.pi, 300)
    poses[:, 4] = rng.uniform(0.0, np.pi, 300)
    chk = verify_path(ROBOT, poses, subdivide=1)
    mine = []
    for q in poses:
        try:
            M.lift(q)
            mine.append(True)
        except InfeasiblePoseError:
            mine.append(False)
    assert 0 < sum(mine) < 300
    assert np.array_equal(np.array(mine), chk.feasible[: len(mine)])


def test_lift_rejects_poses_off_the_slice():
    M = WrenchFeasibleManifold.from_robot(ROBOT, fixed=SLICE)
    with pytest.raises(PoseError):
        M.lift([0.1, 0, 2, 0, 0.9, SIGMA])
    with pytest.raises(PoseError):
        WrenchFeasibleManifold.from_robot(ROBOT, fixed=dict(w=1.0))


def test_robocrane_q1_q2_path_is_wrench_feasible_where_the_straight_line_is_not():
    M = WrenchFeasibleManifold.from_robot(ROBOT, fixed=SLICE)
    straight = verify_path(ROBOT, np.array([POSES["q1"], POSES["q2"]]), subdivide=50)
    assert not straight.all_feasible
    res = plan_path(M.implicit(), M.lift(POSES["q1"]), M.lift(POSES["q2"]), radius=0.2, metric=M.pose_metric)
    assert res.found and res.charts < 1000
    q = M.pose(res.path)
    # the path may end at other angles of the same orientation (here through θ = 0)
    assert np.allclose(q[0], POSES["q1"]) and same_pose(ROBOT, q[-1], POSES["q2"])
    assert np.allclose(q[:, [0, 1, 2, 5]], [0, 0, 2, SIGMA])
    assert np.abs(np.diff(q, axis=0)).max() < 0.1
    chk = verify_path(ROBOT, q, subdivide=10)
    assert chk.all_feasible and chk.poses.shape[0] > 500
    lo, hi = M.tension_range(res.path)  # Fig. 6: f_0 ± v_ii inside (0, 1)
    assert lo.min() > 0 and hi.max() < 1


def test_continuation_on_the_full_six_dimensional_c_space():
    """k = 6: the children of the first chart of the unsliced manifold lie on it, spread in
    all six pose coordinates, and are wrench-feasible by the independent check."""
    from taut.planning._continuation import Atlas

    robot = load_robot("robocrane")
    M = WrenchFeasibleManifold.from_robot(robot)
    manifold = M.implicit()
    assert manifold.dim == 6
    atlas = Atlas(manifold, M.lift(np.asarray(robot.reference.poses["q1"])), radius=0.2, metric=M.pose_metric)
    atlas.grow(0)
    assert len(atlas.charts) >= 1 + 2 * 6
    residual = max(np.linalg.norm(manifold.function(c)) for c in atlas.centres)
    assert residual < 1e-8
    poses = M.pose(atlas.centres)
    assert np.all(np.ptp(poses, axis=0) > 0.1)
    for pose in poses:
        assert verify_path(robot, pose[None, :], subdivide=1).all_feasible
