"""The sagging-static workspace condition and the sag map (``taut sag``): the straight limit,
the grid evaluator, the command line."""

from __future__ import annotations

import json

import numpy as np
import pytest

from taut.cables import sagging_ik
from taut.model import example
from taut.statics import distribute_tensions
from taut.workspace import SaggingStatic, evaluate_workspace, sag_bounds, sag_map, straight_model

COGIRO = example("cogiro-sagging")
GRID = [(-6.8, 6.8, 5), (-5.0, 5.0, 4), (0.5, 5.2, 3)]


def _with(robot, **update):
    return robot.model_copy(update={"cables": tuple(c.model_copy(update=update) for c in robot.cables)})


def test_weightless_verdicts_are_the_static_workspace():
    """As the weight goes to 0 the sag-aware verdicts are the straight ``static`` workspace's."""
    straight = example("spatial-8cable")
    light = _with(straight, weight=1e-12)
    grid = [(-1.2, 1.2, 5), (-0.8, 0.8, 4), (-0.8, 0.8, 4)]
    sag = evaluate_workspace(light, "sagging-static", grid=grid)
    ref = evaluate_workspace(straight, "static", grid=grid)
    assert 0 < ref.count < ref.size
    assert np.array_equal(sag.inside, ref.inside)


def test_condition_agrees_with_the_ik_and_the_executor():
    res = evaluate_workspace(COGIRO, "sagging-static", grid=GRID)
    poses = res.poses
    direct = sagging_ik(COGIRO, poses).feasible
    assert np.array_equal(res.inside.ravel(), direct)
    assert 0 < res.count < res.size
    # the cables' weight shrinks the workspace: wherever sagging cables hold it, straight ones do
    straight = evaluate_workspace(straight_model(COGIRO), "static", grid=GRID)
    assert not np.any(res.inside & ~straight.inside)


def test_sag_map_against_an_independent_straight_model():
    m = sag_map(COGIRO, grid=[(-2.0, 2.0, 3), (0.0, 0.0, 1), (1.0, 3.0, 2)], method="qp")
    both = m.feasible & m.straight_feasible
    assert both.all()
    ref = distribute_tensions(_with(COGIRO, weight=None), m.poses, method="qp")
    ik = sagging_ik(COGIRO, m.poses, method="qp")
    straight_lengths = ik.chord_lengths / (1 + ref.tensions / 2.8e6)
    assert np.allclose(m.length_difference, ik.unstrained_lengths - straight_lengths, rtol=0, atol=1e-12)
    assert np.allclose(m.exit_tension_increase, ik.exit_tensions - ref.tensions, rtol=0, atol=1e-9)
    assert np.all(m.sag > 0) and np.all(m.exit_tension_increase > 0)
    summary = m.summary()
    assert summary["largest_sag"] == pytest.approx(m.sag.max(axis=0).tolist())
    text = json.dumps(m.as_dict(), allow_nan=False)
    assert json.loads(text)["summary"]["both"] == 6


def test_weightless_map_has_no_differences():
    light = _with(example("spatial-8cable"), weight=1e-12)
    m = sag_map(light, grid=[(-0.5, 0.5, 3), (0.0, 0.0, 1), (0.0, 0.0, 1)], method="qp")
    assert m.feasible.all()
    assert np.abs(m.length_difference).max() < 1e-12
    assert np.abs(m.exit_tension_increase).max() < 1e-6


def test_default_grid_hangs_below_the_exits_of_a_suspended_robot():
    bounds = sag_bounds(COGIRO)
    top = COGIRO.exits[:, 2].min()
    assert bounds[2, 1] < top and bounds[2, 0] < top - 6.0
    assert np.array_equal(sag_bounds(example("spatial-8cable")), [[-1.44, 1.44], [-0.96, 0.96], [-0.96, 0.96]])


def test_bad_method_is_refused():
    with pytest.raises(Exception, match="unknown tension distribution method"):
        SaggingStatic(method="nope")
    with pytest.raises(Exception, match="unknown tension distribution method"):
        sag_map(COGIRO, method="nope")


def test_cli_sag_json_and_plot(taut_cli, tmp_path):
    plot = tmp_path / "sag.png"
    run = taut_cli(
        "sag", "cogiro-sagging", "--grid=-2:2:3;0:0:1;1:3:2", "--method", "qp", "--plot", str(plot), "--json"
    )
    d = run.json()
    assert d["summary"]["poses"] == 6 == len(d["poses"])
    assert plot.stat().st_size > 0 and d["plot"] == str(plot)
    m = sag_map(COGIRO, grid=[(-2.0, 2.0, 3), (0.0, 0.0, 1), (1.0, 3.0, 2)], method="qp")
    assert d["summary"]["largest_sag"] == pytest.approx(m.summary()["largest_sag"], rel=1e-12)
    assert "catenary" in d["model"]


@pytest.mark.slow
def test_cli_sag_of_a_robot_given_a_weight(taut_cli):
    human = taut_cli("sag", "spatial-8cable", "--weight", "0.5", "--stiffness", "1e5", "--grid", "3")
    assert human.code == 0 and "largest sag" in human.out


#: Each a second of a subprocess: the first runs in the quick suite, the rest with the slow one.
BAD_SAG = [
    (["sag", "spatial-8cable"], "no sagging cables"),
    (["sag", "cogiro-sagging", "--weight", "-1"], "--weight"),
    (["sag", "cogiro-sagging", "--weight", "nan"], "--weight"),
    (["sag", "cogiro-sagging", "--stiffness", "0"], "--stiffness"),
    (["sag", "cogiro-sagging", "--method", "nope"], "unknown tension distribution method"),
    (["sag", "cogiro-sagging", "--grid", "0"], "--grid"),
]


@pytest.mark.parametrize(
    ("argv", "words"), [BAD_SAG[0], *(pytest.param(*case, marks=pytest.mark.slow) for case in BAD_SAG[1:])]
)
def test_cli_sag_bad_input_is_one_line(taut_cli, argv, words):
    run = taut_cli(*argv)
    assert run.code == 2, run.err
    assert run.err.count("\n") == 1 and words in run.err


@pytest.mark.slow
def test_worker_processes_give_the_same_verdicts():
    from taut.parallel import get_executor

    serial = evaluate_workspace(COGIRO, "sagging-static", grid=GRID)
    with get_executor(workers=2) as executor:
        parallel = evaluate_workspace(COGIRO, SaggingStatic(), grid=GRID, executor=executor)
    assert np.array_equal(serial.inside, parallel.inside)
