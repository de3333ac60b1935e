"""Calibration of robots whose cables leave through swivelling pulleys: the length model's
derivatives against finite differences, and the radii recovered from tracked poses."""

import numpy as np
import pytest

from taut.calibration import calibrate, plan_poses, simulate_measurements
from taut.calibration._model import Geometry, partials
from taut.kinematics import cable_lengths
from taut.model import example


def pulley_robot(axis=(0.1, -0.2, 1.0), radius=0.07, name="spatial-8cable"):
    robot = example(name)
    swivel = {"swivel": {"axis": axis, "radius": radius}}
    return robot.model_copy(update={"cables": tuple(c.model_copy(update=swivel) for c in robot.cables)})


def built_robot(nominal, exits, radii):
    """``nominal`` with its exits and pulley radii moved to where the robot was built."""
    return nominal.model_copy(
        update={
            "cables": tuple(
                c.model_copy(update={"exit": tuple(e), "swivel": c.swivel.model_copy(update={"radius": float(r)})})
                for c, e, r in zip(nominal.cables, exits, radii)
            )
        }
    )


def poses(n, seed):
    rng = np.random.default_rng(seed)
    return np.column_stack([rng.uniform(-0.5, 0.5, (n, 3)), rng.uniform(-0.2, 0.2, (n, 3))])


def test_pulley_partials_match_finite_differences_and_the_kinematics():
    robot = pulley_robot()
    q = poses(5, 0)
    rows, cables = np.repeat(np.arange(5), 8), np.tile(np.arange(8), 5)
    g = Geometry.of(robot)
    part = partials(robot, g, q, rows, cables)
    assert np.allclose(part.length, cable_lengths(robot, q).ravel(), atol=1e-12)
    h = 1e-6
    for i in range(8):
        moved = Geometry(g.exits, g.anchors, g.radii + h * (np.arange(8) == i))
        fd = (partials(robot, moved, q, rows, cables).length - part.length) / h
        assert np.allclose(fd[cables == i], part.radius[cables == i], atol=1e-5)
        for k in range(3):
            exits = g.exits.copy()
            exits[i, k] += h
            fd = (partials(robot, Geometry(exits, g.anchors, g.radii), q, rows, cables).length - part.length) / h
            assert np.allclose(fd[cables == i], part.exit[cables == i, k], atol=1e-5)
    for k in range(6):
        q2 = q.copy()
        q2[:, k] += h
        fd = (partials(robot, g, q2, rows, cables).length - part.length) / h
        assert np.allclose(fd, part.pose[:, k], atol=1e-5)


def test_radii_and_exits_come_back_from_tracked_poses():
    nominal = pulley_robot(axis=(0, 0, 1), radius=0.05)
    rng = np.random.default_rng(3)
    exits = nominal.exits + rng.uniform(-0.02, 0.02, nominal.exits.shape)
    radii = rng.uniform(0.04, 0.06, 8)
    built = built_robot(nominal, exits, radii)
    q = poses(60, 4)
    data = simulate_measurements(built, q, offsets=[1.5] * 8, sigma=1e-4, seed=5, known_poses=True)
    res = calibrate(nominal, data, estimate=("exits", "offsets", "radii"))
    assert res.identifiable and "radii" in res.estimate
    assert np.all(np.abs(res.radii - radii) <= 4 * res.radii_std + 1e-9)
    assert np.all(np.abs(res.exits - exits) <= 4 * res.exits_std + 1e-9)
    calibrated = res.calibrated_robot(nominal)
    assert np.allclose([c.swivel.radius for c in calibrated.cables], res.radii)


@pytest.mark.slow
@pytest.mark.parametrize(
    ("name", "seed"), [("spatial-8cable", seed) for seed in range(10)] + [("cogiro", seed) for seed in range(4)]
)
def test_pulley_robot_with_unknown_poses_and_far_offsets(name, seed):
    """Encoder zeros 1–2 m off, exits up to 5 cm and radii up to 20 % off, 60 planned poses
    none measured: the fit reaches the noise and its standard deviations cover the truth.
    Before the start's descent was made to converge, a false minimum left 5–10 mm residuals in
    3 of the 10 spatial seeds; before the robust fits found the basin, CoGiRo's seed 1 ended
    at 4 mm."""
    nominal = pulley_robot(axis=(0, 0, 1), radius=0.05, name=name)
    estimate = ("exits", "offsets", "radii")
    plan = plan_poses(nominal, 60, estimate=estimate, seed=0)
    rng = np.random.default_rng(seed)
    exits = nominal.exits + rng.uniform(-0.05, 0.05, nominal.exits.shape)
    radii = 0.05 * rng.uniform(0.8, 1.2, nominal.n_cables)
    built = built_robot(nominal, exits, radii)
    offsets = rng.uniform(1, 2, nominal.n_cables)
    sigma = 3e-4
    data = simulate_measurements(built, plan.poses, offsets=offsets, sigma=sigma, seed=seed)
    res = calibrate(nominal, data, estimate=estimate)
    assert res.converged and res.identifiable
    assert res.sigma < 1.5 * sigma
    # the truth in the result's gauge: the built exits turned about the common axis and shifted
    # onto the nominal ones (the gauge's Kabsch alignment, computed independently here)
    a, b = exits - exits.mean(axis=0), nominal.exits - nominal.exits.mean(axis=0)
    angle = np.arctan2((a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]).sum(), (a[:, :2] * b[:, :2]).sum())
    c, s = np.cos(angle), np.sin(angle)
    Q = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    truth = (exits - exits.mean(axis=0)) @ Q.T + nominal.exits.mean(axis=0)
    assert np.all(np.abs(res.exits - truth) <= 4 * res.exits_std)
    assert np.all(np.abs(res.radii - radii) <= 4 * res.radii_std)
    assert np.all(np.abs(res.offsets - offsets) <= 4 * res.offsets_std)
