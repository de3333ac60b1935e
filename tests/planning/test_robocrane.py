"""The Robocrane of Bohigas et al. (2013), §5: the geometry reading, the bounded angle
window that lets an atlas of a slice complete (a no-path proof), and the queries q3 → q4
(slice p = (0, 0, 2), σ = 35°) and q5 → q6 (slice x = y = 0, σ = 35°), each checked by the
independent feasibility test of taut.statics."""

import itertools

import numpy as np
import pytest
from scipy import ndimage

from taut.kinematics import platform_frame
from taut.model import load_robot
from taut.planning import plan_path
from taut.planning._manifold import WrenchFeasibleManifold
from taut.planning._verify import verify_path

ROBOT = load_robot("robocrane")
POSES = {k: np.array(v) for k, v in ROBOT.reference.poses.items()}
SIGMA = 7 * np.pi / 36
SLICE = dict(x=0.0, y=0.0, z=2.0, sigma=SIGMA)
M_SLICE = WrenchFeasibleManifold.from_robot(ROBOT, fixed=SLICE)
PUBLISHED = {
    "q1": (0, 0, 2, -0.5, 0.9),
    "q2": (0, 0, 2, 2.0, 0.9),
    "q3": (0, 0, 2, 0.8, -2.4),
    "q4": (0, 0, 2, -2.4, 2.4),
    "q5": (0, 0, 1.2, 0.8, -2.6),
}  # q6 = q4


def same_pose(robot, a, b) -> bool:
    """Same platform position and rotation (the robot's own orientation convention)."""
    (pa, Ra), (pb, Rb) = (platform_frame(robot, np.asarray(q, float)[None]) for q in (a, b))
    return bool(np.allclose(pa, pb, atol=1e-9) and np.allclose(Ra, Rb, atol=1e-9))


def _feasible(M, pose) -> bool:
    ext = M.extreme_tensions(pose)
    if ext is None:
        return False
    _, _, rho, f0, V = ext
    v = np.diag(V)
    return bool(np.all(f0 - v > M.f_min) and np.all(f0 + v < M.f_max) and np.all(rho < M.rho_max))


def _rz(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1.0]])


def test_no_octahedral_reading_of_section_5_makes_the_published_poses_feasible():
    # a = 1, b = 2, R of Eq. (1); every octahedral pairing (cable set = all base/platform
    # vertex pairs but one perfect matching), the platform turned by k·60°, both signs of Z,
    # moments about P_m or P
    a, b, r3 = 1.0, 2.0, np.sqrt(3)
    A = np.array([[-b, -b * r3 / 3, 0], [b, -b * r3 / 3, 0], [0, 2 * b * r3 / 3, 0]])
    B0 = np.array([[0, -2 * a * r3 / 3, 0], [a, a * r3 / 3, 0], [-a, a * r3 / 3, 0]])
    counts = {}
    for perm, k, zs, pm in itertools.product(
        itertools.permutations(range(3)), range(6), (1, -1), ((a / 5, a / 5, 0), (0, 0, 0))
    ):
        pairs = [(i, j) for i in range(3) for j in range(3) if j != perm[i]]
        Bk = B0 @ _rz(k * np.pi / 3).T
        M = WrenchFeasibleManifold(
            a=A[[i for i, _ in pairs]],
            b=Bk[[j for _, j in pairs]],
            w0=[0, 0, zs, 0, 0, 0],
            E=1e4 * np.eye(6),
            f_min=0.0,
            f_max=1.0,
            rho_min=1e-6,
            rho_max=5.0,
            wrench_point=pm,
        )
        ok = tuple(_feasible(M, np.r_[q, SIGMA]) for q in PUBLISHED.values())
        counts[(perm, k, zs, pm)] = ok
    assert max(sum(ok) for ok in counts.values()) == 4  # never all five
    # the file's pairing (nearest base vertices) leaves out the matching A1-B2, A2-B3, A3-B1
    assert counts[((1, 2, 0), 0, 1, (0.2, 0.2, 0))] == (True, True, False, False, False)
    # the triangle turned by 180°: all but q2
    assert any(ok == (True, False, True, True, True) for (p, k, z, pm), ok in counts.items() if k == 3)


def test_reference_poses_are_wrench_feasible_and_q3_q4_far_apart():
    M = WrenchFeasibleManifold.from_robot(ROBOT)
    for name, q in POSES.items():
        assert _feasible(M, q), name
    assert verify_path(ROBOT, np.array(list(POSES.values())), subdivide=1).all_feasible
    np.testing.assert_allclose(POSES["q6"], POSES["q4"])
    assert POSES["q5"][2] == 1.2 and np.allclose(POSES["q5"][[0, 1, 5]], [0, 0, SIGMA])
    for q in ("q3", "q4"):
        np.testing.assert_allclose(POSES[q][[0, 1, 2, 5]], [0, 0, 2, SIGMA])
    # the straight line q3 → q4 (and q5 → q6) leaves the wrench-feasible C-space
    assert not verify_path(ROBOT, np.array([POSES["q3"], POSES["q4"]]), subdivide=40).all_feasible
    assert not verify_path(ROBOT, np.array([POSES["q5"], POSES["q6"]]), subdivide=40).all_feasible


def test_canonical_angles_keep_the_rotation():
    M = WrenchFeasibleManifold.from_robot(ROBOT)
    rng = np.random.default_rng(0)
    q = np.c_[np.zeros((50, 3)), rng.uniform(-9, 9, (50, 3))]
    c = M.canonical(q)
    assert np.all((c[:, 4] >= 0) & (c[:, 4] <= np.pi)) and np.all((c[:, 3] >= -np.pi) & (c[:, 3] <= np.pi))
    for a, b in zip(q, c):
        Ra, Rb = (M.extreme_tensions(np.r_[0, 0, 2, v[3:]])[0] for v in (a, b))
        np.testing.assert_allclose(Ra, Rb, atol=1e-12)
    # the published q3 (θ < 0) lifts onto the window
    y = WrenchFeasibleManifold.from_robot(ROBOT, fixed=SLICE).lift(POSES["q1"])
    assert np.all(WrenchFeasibleManifold.from_robot(ROBOT, fixed=SLICE).implicit().in_box(y))


def _components(n_phi=90, n_theta=46):
    M = WrenchFeasibleManifold.from_robot(ROBOT)
    ph = np.linspace(-np.pi, np.pi, n_phi, endpoint=False)
    th = np.linspace(0, np.pi, n_theta)
    F = np.array([[_feasible(M, [0, 0, 2, p, t, SIGMA]) for t in th] for p in ph])
    lab, _ = ndimage.label(F)
    for j in range(n_theta):  # φ is periodic
        if lab[0, j] and lab[-1, j] and lab[0, j] != lab[-1, j]:
            lab[lab == lab[-1, j]] = lab[0, j]
    return ph, th, lab


@pytest.mark.slow
def test_atlas_of_a_slice_completes_and_proves_that_no_path_exists():
    # Fig. 5 (top centre): the discretised feasibility map of the slice p = (0, 0, 2), σ = 35°
    ph, th, lab = _components()
    comp = lambda p, t: lab[np.argmin(np.abs(ph - p)), np.argmin(np.abs(th - t))]  # noqa: E731
    start, goal = (-1.3, 2.2), (0.6, 2.4)  # two "upside-down" islands
    assert comp(*start) and comp(*goal) and comp(*start) != comp(*goal)
    assert comp(-0.5, 0.9) == comp(2.0, 0.9) != comp(*start)  # q1, q2: one component
    M = WrenchFeasibleManifold.from_robot(ROBOT, fixed=SLICE)
    res = plan_path(
        M.implicit(),
        M.lift([0, 0, 2, *start, SIGMA]),
        M.lift([0, 0, 2, *goal, SIGMA]),
        radius=0.3,
        metric=M.pose_metric,
    )
    assert not res.found and res.no_path and res.expanded == res.charts
    poses = M.pose(res.atlas.centres)
    # the atlas stayed on the start's island
    assert np.all(poses[:, 4] > 1.4) and np.all(np.abs(poses[:, 3] - start[0]) < 0.8)


def _plan_and_verify(fixed, q_start, q_goal, radius):
    M = WrenchFeasibleManifold.from_robot(ROBOT, fixed=fixed)
    res = plan_path(M.implicit(), M.lift(q_start), M.lift(q_goal), radius=radius, metric=M.pose_metric)
    assert res.found
    poses = M.pose(res.path)
    np.testing.assert_allclose(poses[0], q_start, atol=1e-9)
    assert same_pose(ROBOT, poses[-1], q_goal)
    for n, v in fixed.items():
        np.testing.assert_allclose(poses[:, ["x", "y", "z", "phi", "theta", "sigma"].index(n)], v, atol=1e-9)
    assert np.abs(np.diff(poses, axis=0)).max() < radius  # a continuous path, not a jump
    check = verify_path(ROBOT, poses, subdivide=10)
    assert check.all_feasible
    lo, hi = M.tension_range(res.path)
    assert np.all(lo > 0) and np.all(hi < 1)
    return res


def test_q3_to_q4_on_the_slice_p_0_0_2_crosses_phi_pi():
    # φ is periodic: q3 (φ = −2.2) and q4 (φ = 1.95) are 2.13 apart across φ = −π, 4.15 the
    # other way; the straight line across the seam is infeasible too
    q4_across = POSES["q4"] - [0, 0, 0, 2 * np.pi, 0, 0]
    assert not verify_path(ROBOT, np.array([POSES["q3"], q4_across]), subdivide=40).all_feasible
    res = _plan_and_verify(SLICE, POSES["q3"], POSES["q4"], 0.3)
    poses = M_SLICE.pose(res.path)
    assert poses[:, 3].min() < -np.pi  # it crossed the seam of the φ window
    np.testing.assert_allclose(poses[-1], q4_across, atol=1e-9)
    straight = np.linalg.norm(q4_across[3:5] - POSES["q3"][3:5])
    assert straight < res.length < np.linalg.norm(POSES["q4"][3:5] - POSES["q3"][3:5])


@pytest.mark.slow
def test_q5_to_q6_on_the_3d_slice_x_y_0():
    # experiment 2 (Fig. 7): z, φ, θ free; about 6 s and 500 charts at radius 0.45, 700 at
    # 0.3 (45 s and 1 900 charts before angles were periodic and projections used the graph)
    res = _plan_and_verify(dict(x=0.0, y=0.0, sigma=SIGMA), POSES["q5"], POSES["q6"], 0.45)
    assert res.atlas.manifold.dim == 3
