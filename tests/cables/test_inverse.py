"""Static inverse kinematics with sagging cables: equilibrium checked here from the
catenaries' end forces (solved again from the unstrained lengths), bounds at both ends, the
straight limits, and the command line."""

from __future__ import annotations

import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from taut.cables import catenary_forces, sagging_ik
from taut.errors import PoseError, TautError, UnsupportedRobotError
from taut.kinematics import inverse_kinematics
from taut.model import example
from taut.statics import distribute_tensions, external_wrench

COGIRO = example("cogiro-sagging")


def _with(robot, **update):
    return robot.model_copy(update={"cables": tuple(c.model_copy(update=update) for c in robot.cables)})


def _balance(robot, pose, res):
    """The largest residual of the platform's force and moment balance, relative to the
    wrench, with each cable's force from the forward catenary of its unstrained length."""
    pose = np.asarray(pose, float)
    d = robot.dimension
    b = inverse_kinematics(robot, pose).anchors
    up = -robot.gravity / np.linalg.norm(robot.gravity)
    total = np.array(external_wrench(robot, pose), dtype=float)
    for i in range(robot.n_cables):
        chord = robot.exits[i] - b[i]
        if robot.cables[i].weight:
            rise = chord @ up
            horizontal = chord - rise * up
            span = np.linalg.norm(horizontal)
            c = catenary_forces(span, rise, res.unstrained_lengths[i], robot.cables[i].weight, robot.axial_stiffness[i])
            f = float(c.horizontal_forces) * horizontal / span + float(c.vertical_forces) * up
            assert float(c.exit_tensions) == pytest.approx(res.exit_tensions[i], rel=1e-8)
        else:
            f = res.platform_tensions[i] * chord / np.linalg.norm(chord)
        total[:d] += f
        if not robot.is_point_mass:
            arm = b[i] - pose[:d]
            total[d:] += np.cross(arm, f) if d == 3 else arm[0] * f[1] - arm[1] * f[0]
    return np.abs(total).max() / np.abs(external_wrench(robot, pose)).max()


@pytest.mark.parametrize("method", ["lp", "qp", "inf", "barycentric"])
def test_platform_balances_with_the_catenary_forces(method):
    pose = [0.5, -0.8, 2.5, 0.05, -0.03, 0.1]
    res = sagging_ik(COGIRO, pose, method=method)
    assert res.feasible and res.status == "optimal"
    assert _balance(COGIRO, pose, res) < 1e-9
    lo, hi = COGIRO.tension_bounds
    for t in (res.platform_tensions, res.exit_tensions):
        assert np.all(t >= lo - 1e-9) and np.all(t <= hi + 1e-9)
    # the cables sag below their chords and the exits carry their weights
    assert np.all(res.sag > 0)
    assert np.all(res.exit_tensions > res.platform_tensions)


@settings(max_examples=15, deadline=None)
@given(
    x=st.floats(-3.0, 3.0),
    y=st.floats(-2.5, 2.5),
    z=st.floats(0.5, 3.0),
    angles=st.tuples(*[st.floats(-0.1, 0.1)] * 3),
)
def test_every_feasible_answer_balances(x, y, z, angles):
    pose = [x, y, z, *angles]
    res = sagging_ik(COGIRO, pose, method="qp")
    if res.feasible:
        assert _balance(COGIRO, pose, res) < 1e-9
        # each sagging cable's unstrained length is longer than its chord less its stretch
        assert np.all(res.unstrained_lengths * (1 + res.exit_tensions / COGIRO.axial_stiffness) > res.chord_lengths)
    else:
        assert res.status in {"infeasible", "not-found", "slack", "not-converged"}
        assert res.unstrained_lengths.tolist() == [0.0] * 8


def test_six_cables_square_system():
    # a load Q = 1 N and a least tension of 0.004 N (cable 4): cables of 0.1 mN/m
    robot = _with(example("marionet-vr"), weight=1e-4, stiffness=1e5)
    pose = robot.reference.poses["table-4.5-no3"]
    straight = distribute_tensions(example("marionet-vr"), pose, method="qp", tension_bounds=(0.0, np.inf))
    res = sagging_ik(robot, pose, method="qp", tension_bounds=(0.0, np.inf))
    assert straight.feasible and res.feasible
    assert _balance(robot, pose, res) < 1e-9
    assert res.steps > 1
    assert np.abs(res.platform_tensions - straight.tensions).max() > 1e-5


def test_planar_robot_sags_along_minus_y():
    robot = _with(example("planar-4cable"), weight=0.2)
    pose = [0.1, 0.2, 0.05]
    res = sagging_ik(robot, pose, method="qp")
    assert res.feasible
    assert _balance(robot, pose, res) < 1e-9


def test_a_robot_mixes_sagging_and_straight_cables():
    robot = example("cogiro-sagging")
    cables = list(robot.cables)
    for i in (1, 2, 5, 6):
        cables[i] = cables[i].model_copy(update={"weight": None, "stiffness": None})
    mixed = robot.model_copy(update={"cables": tuple(cables)})
    pose = [0.0, 0.5, 2.0, 0.0, 0.0, 0.0]
    res = sagging_ik(mixed, pose, method="qp")
    assert res.feasible
    assert _balance(mixed, pose, res) < 1e-9
    straight = [1, 2, 5, 6]
    assert res.sag[straight].tolist() == [0.0] * 4
    assert np.array_equal(res.unstrained_lengths[straight], res.chord_lengths[straight])
    assert np.array_equal(res.exit_tensions[straight], res.platform_tensions[straight])


@pytest.mark.parametrize("limit", ["weightless", "inextensible"])
def test_limits_are_the_straight_cable_answer(limit):
    """As the weight goes to 0 and EA to infinity, the lengths and tensions are the straight
    model's (the strictly convex qp distribution is unique) to 1e-9 relative."""
    straight = example("spatial-8cable")
    robot = _with(straight, weight=1e-12) if limit == "weightless" else _with(straight, weight=1e-12, stiffness=1e16)
    poses = np.array([[0.0, 0.0, 0.0, 0.0, 0.0, 0.0], [0.3, -0.2, 0.1, 0.1, -0.05, 0.08]])
    res = sagging_ik(robot, poses, method="qp")
    ref = distribute_tensions(straight, poses, method="qp")
    lengths = inverse_kinematics(straight, poses).lengths
    assert res.feasible.all() and ref.feasible.all()
    assert np.allclose(res.platform_tensions, ref.tensions, rtol=1e-9, atol=0)
    assert np.allclose(res.exit_tensions, ref.tensions, rtol=1e-9, atol=0)
    assert np.allclose(res.unstrained_lengths, lengths, rtol=1e-9, atol=0)


def test_straight_robot_is_answered_in_one_step():
    robot = example("spatial-8cable")
    res = sagging_ik(robot, [0.1, 0.0, 0.0, 0.0, 0.0, 0.0], method="qp")
    ref = distribute_tensions(robot, [0.1, 0.0, 0.0, 0.0, 0.0, 0.0], method="qp")
    assert res.steps == 1
    assert np.array_equal(res.platform_tensions, ref.tensions)
    assert res.sag.tolist() == [0.0] * 8


def test_batch_equals_single_poses_and_freezes():
    poses = np.array([[0.0, 0.0, 2.0, 0.0, 0.0, 0.0], [1.0, 0.5, 1.5, 0.0, 0.05, 0.0]])
    batch = sagging_ik(COGIRO, poses, method="qp")
    for k, pose in enumerate(poses):
        one = sagging_ik(COGIRO, pose, method="qp")
        assert np.allclose(one.unstrained_lengths, batch.unstrained_lengths[k], rtol=1e-12)
    assert not batch.unstrained_lengths.flags.writeable
    json.dumps(batch.as_dict(), allow_nan=False)


def test_infeasible_pose_is_an_answer():
    res = sagging_ik(COGIRO, [6.5, 4.5, 5.0, 0.0, 0.0, 0.0], method="lp")
    assert not res.feasible
    assert res.as_dict()["unstrained_lengths"] is None


@pytest.mark.parametrize(
    ("kwargs", "error", "words"),
    [
        ({"method": "nope"}, TautError, "unknown tension distribution method"),
        ({"tol": -1.0}, TautError, "tol"),
        ({"max_steps": 0}, TautError, "max_steps"),
        ({"wrench": [1.0, 2.0]}, TautError, "wrench"),
    ],
)
def test_bad_arguments(kwargs, error, words):
    with pytest.raises(error, match=words):
        sagging_ik(COGIRO, [0.0, 0.0, 2.0, 0.0, 0.0, 0.0], **kwargs)


def test_bad_pose_and_jointed_robot():
    with pytest.raises(PoseError):
        sagging_ik(COGIRO, [0.0, 0.0])
    jointed = example("adjustable-8cable")
    with pytest.raises(UnsupportedRobotError, match="without joints"):
        sagging_ik(jointed, np.zeros(jointed.pose_size))


def test_cli_ik_on_a_sagging_robot(taut_cli):
    run = taut_cli("ik", "cogiro-sagging", "--pose", "0.5,-0.8,2.5,0.05,-0.03,0.1", "--method", "qp", "--json")
    data = run.json()
    for key in ("unstrained_lengths", "chord_lengths", "exit_tensions", "platform_tensions", "sag"):
        assert len(data[key]) == 8
    assert "catenary" in data["model"]
    res = sagging_ik(COGIRO, [0.5, -0.8, 2.5, 0.05, -0.03, 0.1], method="qp")
    assert data["unstrained_lengths"] == pytest.approx(res.unstrained_lengths.tolist(), rel=1e-12)
    human = taut_cli("ik", "cogiro-sagging")
    assert human.code == 0 and "elastic catenary" in human.out


@pytest.mark.parametrize(
    ("argv", "words"),
    [
        (["ik", "cogiro-sagging", "--method", "nope"], "unknown tension distribution method"),
        (["ik", "spatial-8cable", "--method", "qp"], "has no sagging cables"),
    ],
)
def test_cli_bad_input_is_one_line(taut_cli, argv, words):
    run = taut_cli(*argv)
    assert run.code == 2
    assert run.err.count("\n") == 1 and words in run.err


@pytest.mark.parametrize(
    ("field", "value", "words"),
    [
        ("weight", "-1", "weight: input should be greater than or equal to 0"),
        pytest.param("weight", ".nan", "weight: expected a finite number", marks=pytest.mark.slow),
        pytest.param("stiffness", "0", "stiffness: input should be greater than 0", marks=pytest.mark.slow),
    ],
)
def test_cli_bad_robot_file_is_one_line(taut_cli, tmp_path, field, value, words):
    text = tmp_path / "r.yaml"
    from taut.model import robot_to_dict, save_robot

    save_robot(COGIRO, text)
    body = text.read_text().replace("weight: 2.45", f"{field}: {value}" if field == "weight" else "weight: 2.45", 1)
    if field == "stiffness":
        body = body.replace("stiffness: 2800000.0", f"stiffness: {value}", 1)
    text.write_text(body)
    assert robot_to_dict(COGIRO)["cables"][0]["weight"] == 2.45
    run = taut_cli("ik", str(text))
    assert run.code == 2
    assert run.err.count("\n") == 1 and words in run.err


def test_cli_tensions_on_a_sagging_robot(taut_cli):
    d = taut_cli("tensions", "cogiro-sagging", "--method", "qp", "--json").json()
    res = sagging_ik(COGIRO, [0.0, 0.0, 2.0, 0.0, 0.0, 0.0], method="qp")
    assert d["tensions"] == pytest.approx(res.platform_tensions.tolist(), rel=1e-12)
    assert d["exit_tensions"] == pytest.approx(res.exit_tensions.tolist(), rel=1e-12)
    assert "catenary" in d["model"]


def test_the_chord_kernels_refuse_sagging_cables_and_the_cli_warns_of_straight_conditions(taut_cli):
    """The dynamics' kernels under given tensions pull along chords: acceleration refuses sagging
    cables and names what models them (tests/dynamics/test_sagging.py tests those)."""
    from taut.dynamics import acceleration

    with pytest.raises(UnsupportedRobotError, match=r"cables \[1, 2, 3, 4, 5, 6, 7, 8\] sag .* forward_dynamics"):
        acceleration(example("cogiro-sagging"), [0, 0, 2, 0, 0, 0], np.zeros(6), np.ones(8))
    ws = taut_cli("workspace", "cogiro-sagging", "--condition", "static", "--grid", "2", "--json")
    assert ws.code == 0 and ws.err.startswith("taut: warning:") and "sagging-static" in ws.err
    json.loads(ws.out)


@pytest.mark.parametrize(
    "name, weight, stiffness, method, low, high",
    [
        (
            "spatial-8cable",
            0.5,
            1e5,
            "improved-closed-form",
            [-0.6, -0.4, -0.4, -0.1, -0.1, -0.1],
            [0.6, 0.4, 0.4] + [0.1] * 3,
        ),
        ("planar-4cable", 0.2, 1e4, "improved-closed-form", [-0.3, -0.3, -0.1], [0.3, 0.3, 0.1]),
        ("camera-4cable", 2.0, None, "closed-form", [-6.0, -10.0, 3.0], [6.0, 10.0, 10.0]),
    ],
)
def test_the_compiled_iteration_answers_as_the_vectorised_one(monkeypatch, name, weight, stiffness, method, low, high):
    """The closed forms run pose by pose in a compiled kernel; the vectorised iteration (every
    other method's) is the reference, over 200 poses of a spatial, a planar and a point-mass
    robot.  Where the iteration hardly converges (100 steps or more) rounding decides whether it
    converges within its budget, in either."""
    import taut.cables._inverse as inverse

    robot = _with(example(name), weight=weight, stiffness=stiffness)
    poses = np.random.default_rng(1).uniform(low, high, (200, len(low)))
    compiled = sagging_ik(robot, poses, method=method)
    monkeypatch.setattr(inverse, "COMPILED_METHODS", ())
    reference = sagging_ik(robot, poses, method=method)
    steady = (compiled.steps < 100) & (reference.steps < 100)
    assert steady.mean() > 0.95 and (compiled.status == "optimal").sum() >= 20
    assert (compiled.status[steady] == reference.status[steady]).all()
    for field in ("unstrained_lengths", "platform_tensions", "exit_tensions", "sag", "structure_matrix"):
        a, b = getattr(compiled, field)[steady], getattr(reference, field)[steady]
        assert np.allclose(a, b, rtol=1e-9, atol=1e-9 * np.abs(b).max()), field
    k = int(np.flatnonzero(compiled.status == "optimal")[0])
    single = sagging_ik(robot, poses[k], method=method)
    assert _balance(robot, poses[k], single) < 1e-9
