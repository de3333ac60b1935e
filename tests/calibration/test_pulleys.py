"""Calibration of robots whose cables leave through swivelling pulleys: the length model's
derivatives against finite differences, and the radii recovered from tracked poses."""

import numpy as np

from taut.calibration import calibrate, simulate_measurements
from taut.calibration._model import Geometry, partials
from taut.kinematics import cable_lengths
from taut.model import example


def pulley_robot(axis=(0.1, -0.2, 1.0), radius=0.07):
    robot = example("spatial-8cable")
    swivel = {"swivel": {"axis": axis, "radius": radius}}
    return robot.model_copy(update={"cables": tuple(c.model_copy(update=swivel) for c in robot.cables)})


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
    built = nominal.model_copy(
        update={
            "cables": tuple(
                c.model_copy(update={"exit": tuple(e), "swivel": c.swivel.model_copy(update={"radius": float(r)})})
                for c, e, r in zip(nominal.cables, exits, radii)
            )
        }
    )
    q = poses(60, 4)
    data = simulate_measurements(built, q, offsets=[1.5] * 8, sigma=1e-4, seed=5, known_poses=True)
    res = calibrate(nominal, data, estimate=("exits", "offsets", "radii"))
    assert res.identifiable and "radii" in res.estimate
    assert np.all(np.abs(res.radii - radii) <= 4 * res.radii_std + 1e-9)
    assert np.all(np.abs(res.exits - exits) <= 4 * res.exits_std + 1e-9)
    calibrated = res.calibrated_robot(nominal)
    assert np.allclose([c.swivel.radius for c in calibrated.cables], res.radii)
