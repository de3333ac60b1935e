"""Every command on every built-in example it applies to, run as ``python -m taut`` in a
subprocess; bad input gives exit status 2."""

import json

import numpy as np
import pytest
from axis_rotations import rz

import taut
from taut.kinematics import structure_matrix
from taut.statics import external_wrench

EXAMPLES = taut.example_names()

#: Examples every quick run covers (one process start each costs seconds); the slow suite
#: covers them all.
QUICK_EXAMPLES = {"planar-4cable", "spatial-8cable", "vscr-t-shaped", "suspended-3cable"}


def _examples() -> list:
    return [pytest.param(n, marks=() if n in QUICK_EXAMPLES else pytest.mark.slow) for n in EXAMPLES]


def run(taut_cli, *argv):
    r = taut_cli(*argv)
    return r.code, r.out, r.err


def run_json(taut_cli, *argv):
    return taut_cli(*argv, "--json").json()


def test_examples_lists_every_builtin(taut_cli):
    data = run_json(taut_cli, "examples")
    names = [e["name"] for e in data["examples"]]
    assert names == list(EXAMPLES)
    required = {
        "suspended-3cable",
        "cogiro",
        "marionet-vr",
        "teaching-prototype",
        "robocrane",
        "vscr-single-cable",
        "vscr-four-cable",
        "vscr-agriculture",
        "vscr-rehabilitation",
        "vscr-t-shaped",
        "adjustable-8cable",
    }
    assert required <= set(names)
    assert all(e["description"] for e in data["examples"])


@pytest.mark.parametrize("name", _examples())
def test_ik_and_tensions_on_every_example(name, taut_cli):
    robot = taut.example(name)
    ik = run_json(taut_cli, "ik", name)
    # a robot with sagging cables answers with the static IK: the unstrained lengths to command
    lengths = ik["unstrained_lengths"] if robot.sagging_cables else ik["lengths"]
    assert len(lengths) == robot.n_cables and min(lengths) > 0
    W = np.array(ik["structure_matrix"])
    assert W.shape == (robot.wrench_dim, robot.n_cables)
    u = np.array(ik["directions"])
    np.testing.assert_allclose(np.linalg.norm(u, axis=1), 1.0)
    t = run_json(taut_cli, "tensions", name, "--method", "lp")
    assert t["method"] == "lp" and isinstance(t["feasible"], bool)
    if t["feasible"]:
        tau = np.array(t["tensions"])
        w = external_wrench(robot, t["pose"])
        np.testing.assert_allclose(W @ tau + w, 0, atol=1e-7 * max(1, np.abs(w).max()))
        lo, hi = robot.tension_bounds
        assert np.all(tau >= lo - 1e-9) and np.all(tau <= hi + 1e-9)
    else:
        assert t["tensions"] is None


@pytest.mark.parametrize("name", _examples())
@pytest.mark.parametrize("condition", ["wrench-closure", "static"])
def test_workspace_on_every_example(name, condition, taut_cli):
    robot = taut.example(name)
    res = run_json(taut_cli, "workspace", name, "--condition", condition, "--grid", "5")
    assert res["poses"] == 5**robot.dimension
    assert 0 <= res["inside"] <= res["poses"] and res["fraction"] == pytest.approx(res["inside"] / res["poses"])
    assert res["elapsed_s"] >= 0


@pytest.mark.slow
def test_workspace_outputs(tmp_path, taut_cli):
    out, plot = tmp_path / "ws.npz", tmp_path / "ws.png"
    res = run_json(
        taut_cli,
        "workspace",
        "planar-4cable",
        "--condition",
        "wrench-feasible",
        "--grid=-1:1:21;-1:1:11",
        "--orientation",
        "0",
        "--box",
        "1,1,0.1",
        "--out",
        str(out),
        "--plot",
        str(plot),
    )
    assert res["poses"] == 231 and 0 < res["inside"] < 231
    saved = np.load(out)
    assert saved["inside"].sum() == res["inside"]
    assert plot.stat().st_size > 10_000
    # a larger wrench box can only shrink the wrench-feasible workspace
    bigger = run_json(
        taut_cli,
        "workspace",
        "planar-4cable",
        "--condition",
        "wrench-feasible",
        "--grid=-1:1:21;-1:1:11",
        "--orientation",
        "0",
        "--box",
        "20,20,2",
    )
    assert bigger["inside"] < res["inside"]


def _table_rows(out: str, columns: int) -> np.ndarray:
    """The rows of numbers of the first table of rich's human output with ``columns`` cells."""
    rows = []
    for line in out.splitlines():
        cells = [c.strip() for c in line.strip("│").split("│")]
        if len(cells) == columns and all(c.replace(".", "", 1).replace("-", "", 1).isdigit() for c in cells):
            rows.append([float(c) for c in cells])
    return np.array(rows)


@pytest.mark.slow
def test_human_output_and_plot(tmp_path, taut_cli):
    robot = taut.example("spatial-8cable")
    code, out, _ = run(
        taut_cli, "ik", "spatial-8cable", "--pose", "0.1,0,0.2,0,0,5deg", "--plot", str(tmp_path / "r.png")
    )
    assert code == 0 and "structure matrix" in out
    assert (tmp_path / "r.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    # the cable table (number, length, u) against Eq. 2.1 written out: R = Rz(5°) at p = (0.1, 0, 0.2)
    b = np.array([0.1, 0, 0.2]) + robot.anchors @ rz(np.radians(5)).T
    v = robot.exits - b
    lengths = np.linalg.norm(v, axis=1)
    table = _table_rows(out, 5)[:8]
    np.testing.assert_array_equal(table[:, 0], np.arange(1, 9))
    np.testing.assert_allclose(table[:, 1], lengths, rtol=1e-5)
    np.testing.assert_allclose(table[:, 2:], v / lengths[:, None], atol=1e-5)
    # the printed tensions (6 digits) balance the weight of planar-4cable at the origin
    planar = taut.example("planar-4cable")
    code, out, _ = run(taut_cli, "tensions", "planar-4cable", "--pose", "0,0,0", "--method", "qp")
    assert code == 0 and "tensions (qp)" in out
    tau = _table_rows(out, 2)
    np.testing.assert_array_equal(tau[:, 0], [1, 2, 3, 4])
    W, w = structure_matrix(planar, [0, 0, 0]), external_wrench(planar, [0, 0, 0])
    np.testing.assert_allclose(W @ tau[:, 1] + w, 0, atol=1e-5 * np.abs(w).max())
    lo, hi = planar.tension_bounds
    assert np.all(tau[:, 1] >= lo) and np.all(tau[:, 1] <= hi)
    code, out, _ = run(taut_cli, "tensions", "planar-4cable", "--pose", "0,0,0", "--wrench", "0,-1000,0")
    assert code == 0 and "infeasible" in out and "tension [N]" not in out
    # 1000 N down is more than the four cables can give along y within their upper bounds
    assert 1000 > (hi * np.abs(W[1])).sum()


@pytest.mark.parametrize(
    "argv, words",
    [
        (["ik", "planar-4cable", "--pose", "0,0"], "needs 3 coordinates"),
        (["ik", "planar-4cable", "--pose", "0,zero,0"], "not a number"),
        (["ik", "spatial-8cable", "--pose=-1.65,-0.9,-1.05,0,0,0"], "zero length"),
        (["ik", "adjustable-8cable", "--pose", "5,5,4.5,0,0,0,9"], "outside its limits"),
        (["ik", "no-such-robot"], "not a built-in example"),
        (["tensions", "planar-4cable", "--method", "magic"], "magic"),
        (["tensions", "planar-4cable", "--wrench", "1,2"], "3 components"),
        (["workspace", "planar-4cable", "--condition", "reachable"], "reachable"),
        (["workspace", "planar-4cable", "--condition", "static", "--grid", "1:2"], "--grid"),
        (["workspace", "planar-4cable", "--condition", "wrench-feasible", "--box", "1,2"], "half-widths"),
        (["workspace", "planar-4cable", "--condition", "static", "--workers", "0"], "worker"),
        (
            ["workspace", "planar-4cable", "--condition", "static", "--grid", "4", "--scheduler", "tcp://127.0.0.1:1"],
            "scheduler",
        ),
    ],
)
def test_bad_input_exits_2(argv, words, taut_cli):
    code, _, err = run(taut_cli, *argv)
    assert code == 2, err
    assert words in err
    assert len(err.splitlines()) == 1 and err.startswith("taut: error: "), err


def test_usage_errors_exit_2(taut_cli):
    code, out, err = run(taut_cli, "workspace", "planar-4cable")
    assert code == 2 and out == ""
    assert len(err.splitlines()) == 1 and err.startswith("taut: error: ") and "--condition" in err, err


def test_schema_command(taut_cli):
    code, out, _ = run(taut_cli, "schema")
    assert code == 0 and json.loads(out)["title"].startswith("taut robot file")


@pytest.mark.slow
def test_demo_writes_report(tmp_path, taut_cli):
    data = run_json(taut_cli, "demo", "--out", str(tmp_path / "report"))
    index = tmp_path / "report" / "index.html"
    assert data["report"] == str(index) and index.exists()
    html = index.read_text()
    pngs = sorted(p.name for p in (tmp_path / "report").glob("*.png"))
    assert len(pngs) >= 6 and all(f'src="{p}"' in html for p in pngs)
    assert "wrench-feasible" in html
    assert {"dgp-equilibria.png", "dgp-tracking.png"} <= set(pngs)  # taut fk and tracking
    assert "spatial-8cable-control.png" in pngs  # computed-torque control
