"""Self-collision (Lieskovský 2020, §3.4) and singularities (§2.3.1) of the adjustable platform —
simulations a–d of §4.2 — and of every built-in robot."""

import numpy as np
import pytest
from straight_cables import contacts

import taut
from taut.collision import (
    capsule_model,
    check_poses,
    force_closure_singular,
    jacobian_singular,
    proximity,
    trajectory_poses,
)
from taut.collision._capsules import capsule_segments
from taut.errors import PoseError
from taut.geometry import segment_distance
from taut.kinematics import inverse_kinematics
from taut.model import robot_from_dict
from taut.workspace import CONDITIONS, evaluate_workspace

ROBOT = taut.example("adjustable-8cable")


@pytest.fixture(scope="module")
def sims():
    return {name: check_poses(ROBOT, trajectory_poses(ROBOT, name)) for name in ("sim-a", "sim-b", "sim-c", "sim-d")}


def test_trajectory_sampling_gives_the_steps_of_section_4_2():
    a = trajectory_poses(ROBOT, "sim-a")
    assert a.shape == (201, 7)
    assert np.allclose(a[0], ROBOT.reference.poses["sim-a-step1"]) and np.allclose(
        a[200], ROBOT.reference.poses["sim-a-step201"]
    )
    assert np.allclose(a[100], [5, 5, 2.5, 0, 0, 0, 2])
    for step in ("sim-b-step126", "sim-c-step71", "sim-d-step28"):
        name, k = step.rsplit("-step", 1)
        assert np.allclose(trajectory_poses(ROBOT, name)[int(k) - 1], ROBOT.reference.poses[step], atol=5e-6)


def test_simulation_a_is_free_of_singularity_and_collision(sims):
    a = sims["sim-a"]
    assert not a.problems.any()
    assert a.proximity.min_clearance.min() > 0


def test_simulation_b_force_closure_singular_from_step_126(sims):
    b = sims["sim-b"]
    assert np.flatnonzero(b.force_closure_singular).tolist() == list(range(125, 201))  # steps 126..201
    assert not b.collides.any() and not b.jacobian_singular.any()


@pytest.mark.parametrize("name, step", [("sim-c", 71), ("sim-d", 28)])
def test_first_self_collision(sims, name, step):
    r = sims[name]
    assert r.first(r.collides) == step - 1  # 0-based pose index of the source's 1-based step
    assert r.proximity.collisions(step - 1) == [(0, 4), (3, 7)]  # cables 1 & 5 and 4 & 8
    assert r.steps()[step - 1]["index"] == step - 1
    assert r.steps()[step - 1]["collisions"] == [[0, 4], [3, 7]]
    assert not r.force_closure_singular.any() and not r.jacobian_singular.any()


def test_collision_model_of_the_adjustable_platform():
    m = capsule_model(ROBOT)
    assert m.n_capsules == 17 and m.radii[:8].tolist() == [0.1] * 8
    # D_I: 28 cable pairs; D_II: 8 rectangle sides minus the 2 on each cable's anchor; D_III: the column
    pairs = {tuple(p) for p in m.pairs.tolist()}
    assert len(pairs) == 28 + 8 * 6 + 8
    names = m.names
    col = names.index("column 17")
    assert all((i, col) in pairs for i in range(8))
    assert (0, names.index("segment 9 (B1-B2)")) not in pairs and (0, names.index("segment 10 (B2-B3)")) in pairs
    assert (4, names.index("segment 13 (B5-B6)")) not in pairs


def test_D_and_E_match_direct_segment_distances():
    pose = ROBOT.reference.poses["sim-d-step28"]
    res = proximity(ROBOT, pose)
    A, B = capsule_segments(ROBOT, np.atleast_2d(pose))
    D, E = res.D[0], res.E[0]
    assert D.shape == (8, 17)
    m = res.model
    for i in range(8):
        for j in range(17):
            if (i, j) in {tuple(p) for p in m.pairs.tolist()}:
                d = segment_distance(A[0, i], B[0, i], A[0, j], B[0, j])
                assert D[i, j] == pytest.approx(d, abs=1e-12)
                assert E[i, j] == pytest.approx(d - m.radii[i] - m.radii[j], abs=1e-12)
            else:
                assert np.isnan(D[i, j]) and np.isnan(E[i, j])


def test_point_mass_cables_share_their_end_without_interfering():
    robot = taut.example("vscr-four-cable")
    assert robot.is_point_mass and robot.n_cables == 4
    m = capsule_model(robot)
    # every pair of cables meets at the point mass, none shares an exit point
    assert m.pairs.tolist() == [[i, j] for i in range(4) for j in range(i + 1, 4)]
    assert m.shared[:, 1].all() and not m.shared[:, 0].any()
    poses = np.array(list(robot.reference.poses.values()), float)
    A, B = capsule_segments(robot, poses)
    for k in range(len(poses)):
        for i, j in m.pairs.tolist():
            assert segment_distance(A[k, i], B[k, i], A[k, j], B[k, j]) == 0.0
    # the common end alone is no interference: the cables leave it at distinct angles
    assert proximity(robot, poses).interference_free.all()
    # cables of radius 0 meeting at a point mass interfere only when they overlap (same
    # direction); with a radius, when their angle is below about one degree
    pm = robot_from_dict(
        {
            "name": "three",
            "dimension": 2,
            "platform": {"kind": "point-mass"},
            "cables": [{"exit": [0, 0]}, {"exit": [2, 0]}, {"exit": [1, 3]}],
        }
    )
    assert proximity(pm, [[1.0, 1.0], [0.5, 0.0], [3.0, 0.0]]).interference_free.tolist() == [True, True, False]
    thick = robot_from_dict(
        {
            "name": "thick",
            "dimension": 2,
            "platform": {"kind": "point-mass"},
            "cables": [
                {"exit": [0, 0], "radius": 0.01},
                {"exit": [10, 0.1], "radius": 0.01},
                {"exit": [10, -20], "radius": 0.01},
            ],
        }
    )
    # at (20, 0.2) cable 2 runs along cable 1 (interference); at (5, 5) they are far apart
    free = proximity(thick, [[20.0, 0.2], [5.0, 5.0]])
    assert free.collisions(0) == [(0, 1)] and free.interference_free[1]


def _point_segment(p, a, b):
    v = b - a
    vv = np.einsum("...i,...i", v, v)
    t = np.clip(np.einsum("...i,...i", p - a, v) / np.where(vv > 0, vv, 1.0), 0.0, 1.0)
    return np.linalg.norm(a + t[..., None] * v - p, axis=-1)


def _segments_apart(a1, b1, a2, b2):
    """Distance of segments as the least of the four end-point distances and, where the lines'
    closest points fall inside both segments, the distance of the lines."""
    d = np.minimum.reduce(
        [_point_segment(a1, a2, b2), _point_segment(b1, a2, b2), _point_segment(a2, a1, b1), _point_segment(b2, a1, b1)]
    )
    u, v, w = b1 - a1, b2 - a2, a1 - a2
    uu, uv, vv = (np.einsum("...i,...i", x, y) for x, y in ((u, u), (u, v), (v, v)))
    uw, vw = np.einsum("...i,...i", u, w), np.einsum("...i,...i", v, w)
    den = uu * vv - uv * uv
    ok = den > 1e-12 * np.maximum(uu * vv, 1e-300)
    s = (uv * vw - vv * uw) / np.where(ok, den, 1.0)
    t = (uu * vw - uv * uw) / np.where(ok, den, 1.0)
    inner = ok & (s >= 0) & (s <= 1) & (t >= 0) & (t <= 1)
    line = np.linalg.norm(w + s[..., None] * u - t[..., None] * v, axis=-1)
    return np.where(inner, np.minimum(d, line), d)


def _cut_back(end, other, c):
    """``end`` moved by ``c`` towards ``other`` (at most onto it)."""
    v = other - end
    L = np.linalg.norm(v, axis=-1)
    return end + v * (np.minimum(c, L) / np.where(L > 0, L, 1.0))[..., None]


@pytest.mark.parametrize("name", taut.example_names())
def test_interference_free_condition_on_every_builtin(name):
    """The workspace condition against the rule of §3.4 written out here: every checked pair
    of capsules keeps a positive clearance, cables sharing an end point compared with that
    end cut back by ``(ρ_i + ρ_j) / sin 1°`` (at least 1e-6 of the shorter cable)."""
    robot = taut.example(name)
    assert "interference-free" in CONDITIONS
    res = evaluate_workspace(robot, "interference-free", resolution=4)
    assert res.inside.shape[0] == res.poses.shape[0] > 0
    m = capsule_model(robot)
    A, B = capsule_segments(robot, res.poses)
    i, j = m.pairs[:, 0], m.pairs[:, 1]
    ai, bi, aj, bj = A[:, i], B[:, i], A[:, j], B[:, j]
    c = np.maximum(
        (m.radii[i] + m.radii[j]) / np.sin(np.radians(1.0)),
        1e-6 * np.minimum(np.linalg.norm(bi - ai, axis=-1), np.linalg.norm(bj - aj, axis=-1)),
    )
    exit_, anchor = m.shared[:, 0][None, :, None], m.shared[:, 1][None, :, None]
    ai, aj = np.where(exit_, _cut_back(ai, bi, c), ai), np.where(exit_, _cut_back(aj, bj, c), aj)
    bi, bj = np.where(anchor, _cut_back(bi, ai, c), bi), np.where(anchor, _cut_back(bj, aj, c), bj)
    least = (_segments_apart(ai, bi, aj, bj) - (m.radii[i] + m.radii[j])).min(axis=1, initial=np.inf)
    # a pose where a straight cable meets an obstacle is outside (shapely decides, tests/straight_cables.py)
    wrapped = (contacts(robot, res.poses)[0] >= 0).any(axis=1)
    assert res.wrapped == np.count_nonzero(wrapped) and not (res.inside & wrapped).any()
    # cables of radius 0 that cross at the symmetric grid poses have a clearance of 0 up to
    # rounding: either verdict is right there
    assert np.all(least[res.inside] > -1e-12) and np.all(least[~res.inside & ~wrapped] < 1e-12)


def test_fast_and_lp_force_closure_agree():
    rng = np.random.default_rng(3)
    W = rng.normal(size=(300, 6, 8))
    W[:100, 2, :] = np.abs(W[:100, 2, :])  # all cables pull one way: not closure
    W[100:130, 2, :4] = 0.0
    W[100:130, 2, 4:] = np.abs(W[100:130, 2, 4:])  # on the boundary: a facet with four columns on it
    fast, lp = force_closure_singular(W), force_closure_singular(W, method="lp")
    assert np.array_equal(fast, lp)
    assert fast[:130].all() and not fast.all()
    for name in ("sim-a", "sim-b"):
        W = inverse_kinematics(ROBOT, trajectory_poses(ROBOT, name)).structure_matrix
        assert np.array_equal(force_closure_singular(W), force_closure_singular(W, method="lp"))


def test_jacobian_singularity_threshold():
    J = np.random.default_rng(0).normal(size=(5, 9, 7))
    J[0, :, 6] = J[0, :, 5]  # dependent columns: rank 6
    J[1, :, 6] = J[1, :, 5] + 1e-3 * np.arange(9.0)
    sing, ratio = jacobian_singular(J)
    assert sing.tolist() == [True, False, False, False, False]
    assert ratio[0] < 1e-12 < ratio[1]
    assert jacobian_singular(np.ones((1, 2, 3)))[0].all()  # fewer actuators than DOF


def test_bad_poses_are_rejected():
    with pytest.raises(PoseError, match="outside its limits"):
        check_poses(ROBOT, [[5, 5, 5, 0, 0, 0, 0.1]])
    with pytest.raises(PoseError):
        proximity(ROBOT, [[5, 5, 5, 0, 0, 0]])
