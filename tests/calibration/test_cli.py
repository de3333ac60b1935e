"""``taut calibrate`` through real subprocesses: exit status, stderr, JSON on stdout, the file."""

from __future__ import annotations

import numpy as np
import pytest
from calibration_truth import align, lengths
from conftest import run_taut

from taut.model import example, load_robot

PRINTER = example("printer-5cable")


@pytest.fixture(scope="module")
def built():
    rng = np.random.default_rng(7)
    return PRINTER.exits + rng.uniform(-0.03, 0.03, PRINTER.exits.shape)


def write_data(path, exits, poses, *, offsets=1.2, sigma=2e-4, seed=0):
    rng = np.random.default_rng(seed)
    dl = lengths(PRINTER, exits, PRINTER.anchors, poses) - offsets + rng.normal(0, sigma, (len(poses), 5))
    lines = ["dl1,dl2,dl3,dl4,dl5"] + [",".join(repr(float(v)) for v in row) for row in dl]
    path.write_text("\n".join(lines) + "\n")
    return path


def test_plan_then_calibrate(tmp_path, built):
    plan = run_taut("calibrate", "--plan", "30", "printer-5cable")
    assert plan.code == 0, plan.err
    header, *rows = plan.out.strip().splitlines()
    assert header == "x,y,z" and len(rows) == 30
    poses = np.array([[float(v) for v in r.split(",")] for r in rows])
    data = write_data(tmp_path / "data.csv", built, poses)
    out = tmp_path / "calibrated.yaml"
    run = run_taut("calibrate", "printer-5cable", "--data", str(data), "--out", str(out), "--json")
    d = run.json()
    assert d["identifiable"] is True and d["undetermined"] == []
    assert d["out"] == str(out) and d["rows"] == 30
    assert "Kabsch" in d["gauge"]
    truth = align(built, PRINTER.exits)
    est = np.array(d["exits"])
    assert np.all(np.abs(est - truth) <= 4 * np.array(d["exits_std"]) + 1e-9)
    assert np.allclose(d["offsets"], 1.2, atol=0.01)
    robot = load_robot(out)
    assert np.allclose(robot.exits, est) and robot.description.startswith("calibrated by taut calibrate")
    human = run_taut("calibrate", "printer-5cable", "--data", str(data))
    assert human.code == 0 and "identifiable: yes" in human.out and "Kabsch" in human.out


def test_calibrated_encoder_zeros_drive_ik_and_fk(tmp_path, built):
    """``--out`` writes each encoder's zero (``length_offset``); ``taut ik`` then reports what the
    encoders read at a pose, and ``taut fk --readings`` turns readings back into the pose —
    both checked against the built robot's own lengths."""
    from taut.calibration import plan_poses

    poses = plan_poses(PRINTER, 30, seed=3).poses
    data = write_data(tmp_path / "data.csv", built, poses, offsets=np.array([1.1, 1.2, 1.3, 1.4, 1.5]))
    out = tmp_path / "calibrated.yaml"
    assert run_taut("calibrate", "printer-5cable", "--data", str(data), "--out", str(out)).code == 0
    robot = load_robot(out)
    assert robot.encoder_cables == (0, 1, 2, 3, 4)
    assert np.allclose(robot.length_offsets, [1.1, 1.2, 1.3, 1.4, 1.5], atol=0.01)
    # a pose in the middle of the measured ones, in the calibrated (nominal-aligned) frame
    pose = np.array([0.02, -0.01, 0.3]) + poses.mean(axis=0) * [1, 1, 0]
    truth = align(built, PRINTER.exits)
    readings = lengths(PRINTER, truth, PRINTER.anchors, pose[None])[0] - [1.1, 1.2, 1.3, 1.4, 1.5]
    ik = run_taut("ik", str(out), "--pose", ",".join(map(str, pose)), "--json").json()
    assert np.allclose(ik["encoder_readings"], readings, atol=2e-3)
    assert np.allclose(np.array(ik["lengths"]) - ik["encoder_readings"], robot.length_offsets)
    fk = run_taut("fk", str(out), "--readings", ",".join(map(repr, readings.tolist())), "--json").json()
    # lengths a few tenths of a millimetre off the calibrated geometry admit no equilibrium of
    # five inextensible cables; the least-squares fit is what a printer's firmware uses
    assert np.linalg.norm(np.array(fk["least_squares"]["position"]) - pose) < 5e-3
    nominal = run_taut("fk", "printer-5cable", "--readings", "1,1,1,1,1")
    assert nominal.code == 2 and "no encoder zero" in nominal.err and len(nominal.err.splitlines()) == 1
    ik_plain = run_taut("ik", "printer-5cable", "--json").json()
    assert "encoder_readings" not in ik_plain


def test_identical_rows_answer_not_identifiable(tmp_path):
    data = tmp_path / "same.csv"
    data.write_text("dl1,dl2,dl3,dl4,dl5\n" + "0.1,0.2,0.3,0.4,0.5\n" * 8)
    d = run_taut("calibrate", "printer-5cable", "--data", str(data), "--json").json()
    assert d["identifiable"] is False
    assert "all rows identical: the data hold a single pose" in d["undetermined"]


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("l1,l2,wrong\n1,1,1\n", "unknown name 'wrong'"),
        ("l1,l1\n1,1\n", "duplicate header 'l1'"),
        ("l1,l2\n1,NaN\n", "'NaN' is not a finite number"),
        ("l1,l9\n1,1\n", "has cables 1..5"),
    ],
)
def test_bad_files(tmp_path, text, message):
    data = tmp_path / "bad.csv"
    data.write_text(text)
    run = run_taut("calibrate", "printer-5cable", "--data", str(data), "--json")
    assert run.code == 2 and run.out == ""
    lines = run.err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("taut: error: bad.csv: ") and message in lines[0]


def test_bad_options(tmp_path):
    for argv, message in [
        (["calibrate", "printer-5cable"], "give --data"),
        (["calibrate", "printer-5cable", "--data", str(tmp_path / "none.csv")], "not a regular file"),
        (["calibrate", "printer-5cable", "--plan", "0"], "expected a whole number"),
        (["calibrate", "printer-5cable", "--data", "x.csv", "--out", str(tmp_path / "r.txt")], "must end in one of"),
        (["calibrate", "printer-5cable", "--plan", "5", "--estimate", "exits,radii"], "no radius to estimate"),
    ]:
        run = run_taut(*argv)
        assert run.code == 2 and len(run.err.splitlines()) == 1 and message in run.err, (argv, run.err)
