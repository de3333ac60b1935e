"""Degenerate data sets are reported as not identifiable, with the combinations in words; a good
design is identifiable, and the planned one better conditioned than random poses."""

from __future__ import annotations

import numpy as np
import pytest
from calibration_truth import lengths

from taut.calibration import calibrate, identifiability, measurements, plan_poses
from taut.model import example

PRINTER = example("printer-5cable")


def changes_at(robot, poses, rng, sigma=2e-4):
    exits = robot.exits + rng.uniform(-0.02, 0.02, robot.exits.shape)
    return measurements(
        robot,
        changes=lengths(robot, exits, robot.anchors, poses) - 1.0 + rng.normal(0, sigma, (len(poses), robot.n_cables)),
    )


LINE = np.column_stack(
    [np.linspace(-0.5, 0.5, 30), 0.3 * np.linspace(-0.5, 0.5, 30), 1.0 + 0.2 * np.linspace(-0.5, 0.5, 30)]
)


def test_collinear_design():
    """Exactly on a line: the exits turn about it, a rank deficiency, the directions named."""
    rep = identifiability(PRINTER, LINE)
    assert not rep.identifiable
    assert "all poses on one line: each exit can turn about that line" in rep.undetermined
    assert rep.rank < rep.unknowns and rep.condition > 1e6
    named = [u for u in rep.undetermined if u.startswith("together: ")]
    assert named and all("exit" in u for u in named)


@pytest.mark.slow
def test_collinear_poses_measured_with_noise():
    """With noise the fit bends the unknown poses off the line; the answer still says so, and
    its standard deviations are decimetres, not millimetres."""
    res = calibrate(PRINTER, changes_at(PRINTER, LINE, np.random.default_rng(0)))
    assert not res.identifiable
    assert "all poses on one line: each exit can turn about that line" in res.identifiability.undetermined
    assert res.exits_std.max() > 0.05


def test_a_single_pose_and_identical_rows():
    rng = np.random.default_rng(1)
    one = calibrate(PRINTER, changes_at(PRINTER, np.array([[0.1, 0.2, 1.0]]), rng))
    assert not one.identifiable and "a single pose" in one.identifiability.undetermined
    same = measurements(PRINTER, changes=np.tile([0.1, 0.2, 0.3, 0.4, 0.5], (12, 1)))
    res = calibrate(PRINTER, same)
    assert not res.identifiable
    assert "all rows identical: the data hold a single pose" in res.identifiability.undetermined


def test_fewer_rows_than_unknowns():
    rng = np.random.default_rng(2)
    poses = np.array([[0.1, 0.2, 1.0], [-0.3, 0.1, 0.8], [0.2, -0.4, 1.4]])
    res = calibrate(PRINTER, changes_at(PRINTER, poses, rng))
    assert not res.identifiable
    assert any(
        u.startswith("fewer measurements than unknowns: 15 lengths for 23 unknowns")
        for u in res.identifiability.undetermined
    )


def test_undetermined_directions_are_named():
    """A planar robot's exits seen from poses on one line: each exit may be mirrored in it (a
    discrete ambiguity), and with known poses on the line nothing else is free."""
    robot = example("planar-4cable")
    t = np.linspace(-0.4, 0.4, 20)
    rep = identifiability(robot, np.column_stack([t, 0.2 * t, np.zeros(20)]), known_poses=True)
    assert any("mirrored in that line" in a for a in rep.ambiguities) or not rep.identifiable


def test_plan_is_identifiable_and_better_than_random():
    plan = plan_poses(PRINTER, 25, seed=3)
    assert plan.identifiability.identifiable
    rng = np.random.default_rng(3)
    random = np.column_stack([rng.uniform(-0.8, 0.8, 25), rng.uniform(-0.7, 0.7, 25), rng.uniform(0.3, 1.9, 25)])
    assert plan.identifiability.condition < identifiability(PRINTER, random).condition
    # every planned pose inside the box of the exits
    lo, hi = PRINTER.exits.min(axis=0), PRINTER.exits.max(axis=0)
    assert np.all((plan.poses >= lo) & (plan.poses <= hi))
