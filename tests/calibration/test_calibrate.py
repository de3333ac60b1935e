"""Synthetic truth (issue 31): exits perturbed by up to 5 cm, offsets by up to 10 cm, 30–100
poses, noise 0.1–1 mm; the estimate's own standard deviations cover the truth."""

from __future__ import annotations

import math

import numpy as np
import pytest
from calibration_truth import lengths, trial

from taut.calibration import calibrate, measurements, simulate_measurements
from taut.errors import TautError, UnsupportedRobotError
from taut.model import example, random_point_mass_robot


def point_mass_8():
    robot, _ = random_point_mass_robot(8, seed=4)
    return robot


#: (robot, box of the random poses) per kind of the issue's checks
CASES = {
    "point-mass 4": (lambda: example("camera-4cable"), np.array([[-6, 6], [-9, 9], [3, 11]])),
    "point-mass 8": (point_mass_8, None),
    "planar rigid": (lambda: example("planar-4cable"), np.array([[-0.5, 0.5], [-0.5, 0.5]])),
    "spatial rigid": (lambda: example("spatial-8cable"), np.array([[-0.6, 0.6], [-0.4, 0.4], [-0.4, 0.4]])),
}


def case(name: str):
    make, box = CASES[name]
    robot = make()
    if box is None:
        lo, hi = robot.exits.min(axis=0), robot.exits.max(axis=0)
        mid = (lo + hi) / 2
        box = np.column_stack([mid - 0.3 * (hi - lo), mid + 0.3 * (hi - lo)])
        box[2] = [lo[2] - 1.5, lo[2] - 0.5]
    return robot, box


def coverage(name: str, seeds: range, **options) -> tuple[float, float, float, float]:
    """Over the trials: the fraction found identifiable; among those, the fraction of parameters
    within 3σ and the fraction of trials with every parameter within 3σ; and what that last
    fraction is expected to be for Gaussian errors."""
    robot, box = case(name)
    inside, whole, params, identified = 0, 0, 0, 0
    for seed in seeds:
        t = trial(robot, seed, box, **options)
        if not t.result.identifiable:  # an honest "not determined", never a confident answer
            assert not np.isfinite(t.z).all() or t.result.identifiability.undetermined
            continue
        identified += 1
        ok = np.abs(t.z) <= 3.0
        inside += int(ok.sum())
        params = ok.size
        whole += int(ok.all())
    trials = len(seeds)
    expected = (math.erf(3 / math.sqrt(2))) ** params
    return identified / trials, inside / max(identified * params, 1), whole / max(identified, 1), expected


@pytest.mark.parametrize("known", [False, True], ids=["unknown poses", "known poses"])
@pytest.mark.parametrize("name", ["point-mass 4", "planar rigid"])
def test_truth_within_three_sigma_quick(name, known):
    identified, per_param, _, _ = coverage(name, range(2), rows=60, sigma=5e-4, known_poses=known)
    assert identified == 1.0 and per_param >= 0.95


#: Trials per case of the slow check: 200 of every case take 40 minutes on two cores, beyond the
#: slow suite's budget; the benchmark-sized runs of the report used 200 (see the issue's note).
TRIALS = {"point-mass 4": 40, "point-mass 8": 30, "planar rigid": 40, "spatial rigid": 12}


#: Known shortfall (issue 31): the 4-cable point mass with unknown poses, one redundant cable per
#: row, its four exits coplanar: every parameter within 3σ in 32 of 38 identifiable trials (84 %;
#: 96 % of the parameters), 2 of 40 answered not identifiable.  Its weakest direction is
#: nonlinear, so the linearised standard deviations are too small there: over 30 trials the
#: scatter of (estimate − truth)/σ is 1.0 in x but 1.24 in y and 1.37 in z, and with the exits
#: 0.5 cm off instead of 5 cm, 4.3 in z along the exits' alternating out-of-plane twist.  From
#: D-optimal planned poses (``plan_poses``) it is 92.5 % of 40 trials (95.8 % expected), 98.6 %
#: of the parameters.  Strict: it fails when fixed.
SHORTFALL = pytest.mark.xfail(
    strict=True, reason="4-cable point mass, unknown poses: standard deviations too small in 16 % of trials"
)


@pytest.mark.slow
@pytest.mark.parametrize(
    ("name", "known"),
    [
        pytest.param(
            name, known, marks=SHORTFALL if (name, known) == ("point-mass 4", False) else (), id=f"{name}-{label}"
        )
        for name in CASES
        for known, label in ((False, "unknown poses"), (True, "known poses"))
    ],
)
def test_truth_within_three_sigma(name, known):
    """Seeded trials. Every parameter within 3σ at once happens with probability 0.9973^P for P
    independent Gaussian errors (0.92 for 32 parameters): that, less a binomial margin, is the
    bar for whole trials (the issue's "95 % of trials" cannot hold for 32 parameters at once);
    each parameter must be within 3σ in 99 % of them, 95 % of the trials answer identifiable."""
    trials = TRIALS[name]
    identified, per_param, whole, expected = coverage(
        name, range(100, 100 + trials), rows=60, sigma=1e-3 if known else 5e-4, known_poses=known
    )
    assert identified >= 0.95
    assert per_param >= 0.99
    assert whole >= expected - 3 * math.sqrt(expected * (1 - expected) / trials)


def test_outliers_are_flagged_and_the_estimate_holds():
    robot, box = case("point-mass 8")
    t = trial(robot, 11, box, rows=40, outliers=0.05, robust="soft_l1")
    assert set(t.corrupted) <= set(t.result.outliers)
    assert len(t.result.outliers) <= len(t.corrupted) + 1
    assert np.all(np.abs(t.z) <= 3.0)


def test_point_mass_8_estimate():
    robot, box = case("point-mass 8")
    t = trial(robot, 2, box, rows=40, sigma=1e-4)
    assert t.result.identifiable and np.abs(t.error).max() < 0.005
    assert np.all(np.abs(t.z) <= 4.0)


def test_lengths_given_absolute_fit_exactly_without_noise():
    """Absolute lengths, no offsets, no noise: the exits come back to 1e-6 m in the nominal gauge,
    and the residuals vanish."""
    robot = example("printer-5cable")
    rng = np.random.default_rng(5)
    exits = robot.exits + rng.uniform(-0.03, 0.03, robot.exits.shape)
    poses = np.column_stack([rng.uniform(-0.6, 0.6, 40), rng.uniform(-0.5, 0.5, 40), rng.uniform(0.4, 1.6, 40)])
    data = measurements(robot, lengths(robot, exits, robot.anchors, poses))
    res = calibrate(robot, data)
    from calibration_truth import align

    assert np.abs(res.exits - align(exits, robot.exits)).max() < 1e-6
    assert res.residual_rms.max() < 1e-8
    assert "Kabsch" in res.gauge
    # the estimate is aligned onto the nominal exits: no rigid motion brings it closer
    assert np.abs(align(res.exits, robot.exits) - res.exits).max() < 1e-9


def test_result_is_frozen_and_json():
    import json

    robot = example("printer-5cable")
    poses = np.column_stack([np.linspace(-0.5, 0.5, 12), np.tile([-0.3, 0.3], 6), np.linspace(0.5, 1.5, 12)])
    res = calibrate(robot, simulate_measurements(robot, poses, offsets=[1.0] * 5, sigma=1e-4, seed=0))
    assert not res.exits.flags.writeable
    d = json.loads(json.dumps(res.as_dict(), allow_nan=False))
    assert {"identifiable", "undetermined", "exits_std", "residual_rms", "outliers", "gauge"} <= set(d)


def test_bad_arguments():
    robot = example("printer-5cable")
    data = simulate_measurements(robot, [[0, 0, 1]] * 3, offsets=[1.0] * 5)
    with pytest.raises(TautError, match="unknown 'corners'"):
        calibrate(robot, data, estimate=("exits", "corners"))
    with pytest.raises(TautError, match="offsets"):
        calibrate(robot, data, estimate=("exits",))
    with pytest.raises(TautError, match="robust"):
        calibrate(robot, data, robust="cauchy2")
    with pytest.raises(UnsupportedRobotError, match="point mass has no anchors"):
        calibrate(robot, data, estimate=("exits", "offsets", "anchors"))
    with pytest.raises(UnsupportedRobotError, match="jointed bodies"):
        calibrate(example("adjustable-8cable"), data)
    with pytest.raises(UnsupportedRobotError, match="no radius to estimate"):
        calibrate(robot, data, estimate=("exits", "offsets", "radii"))


@pytest.mark.slow
@pytest.mark.parametrize("name", ["point-mass 8", "spatial rigid"])
def test_outliers_over_seeds(name):
    """5 % of the rows corrupted by 10 cm: with the robust fit every corrupted row is flagged in
    19 of 20 trials, and the parameters stay within 3σ as often as without outliers.  Robots
    with two or more redundant cables per row: with one (4 cables on a point mass) the row's
    pose absorbs most of a 10 cm error on one cable, and a whole trial's corrupted rows were
    all flagged in 8 of 20 trials."""
    robot, box = case(name)
    flagged, inside, total = 0, 0, 0
    trials = 20 if name != "spatial rigid" else 6
    for seed in range(200, 200 + trials):
        t = trial(robot, seed, box, rows=60, outliers=0.05, robust="soft_l1")
        flagged += set(t.corrupted) <= set(t.result.outliers)
        inside += int((np.abs(t.z) <= 3).sum())
        total += t.z.size
    assert flagged >= 0.95 * trials
    assert inside / total >= 0.99
