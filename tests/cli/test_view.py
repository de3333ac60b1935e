"""``taut view``: one HTML file per kind of view, from the files the other commands write, in
real subprocesses; bad input is one line and exit status 2, and nothing is written."""

from __future__ import annotations

import csv
import json
import re
import subprocess
import sys

import numpy as np
import pytest
from conftest import run_taut


def one_error(run, *words):
    lines = run.err.splitlines()
    assert run.code == 2 and len(lines) == 1 and lines[0].startswith("taut: error: "), run.err
    for w in words:
        assert w in lines[0], lines[0]
    assert run.out == ""


def scripts(page: str) -> list[str]:
    return re.findall(r"<script[^>]*\bsrc=\"([^\"]*)\"", page)


def test_robot_view_is_one_file_that_names_no_network_address(tmp_path):
    out = tmp_path / "robot.html"
    d = run_taut("view", "spatial-8cable", "--pose", "0.1,0,0.2,0,0,0", "--out", str(out), "--json").json()
    assert d["view"] == "robot" and d["out"] == str(out) and d["cables"] == 8 and d["plotlyjs"] is None
    page = out.read_text()
    assert d["bytes"] == out.stat().st_size > 3_000_000  # plotly.js is inside
    # plotly.js's own text names its web site; the page's markup and the figure load nothing
    # (tests/browser opens it with the network cut off)
    assert scripts(page) == [] and not re.search(r"(src|href)=\"https?:", page.split("<body>")[1])
    assert list(tmp_path.iterdir()) == [out]


def test_solutions_view_shares_plotly_js_and_refuses_another_robots_solutions(tmp_path):
    fk = tmp_path / "fk.json"
    fk.write_text(run_taut("fk", "suspended-3cable", "--json").out)
    solutions = json.loads(fk.read_text())["solutions"]
    out = tmp_path / "fk.html"
    d = run_taut(
        "view", "suspended-3cable", "--solutions", str(fk), "--out", str(out), "--plotlyjs", "beside", "--json"
    ).json()
    assert d["view"] == "solutions" and d["plotlyjs"] == str(tmp_path / "plotly.min.js")
    assert scripts(out.read_text()) == ["plotly.min.js"] and (tmp_path / "plotly.min.js").stat().st_size > 1_000_000
    assert out.stat().st_size < 200_000
    page = out.read_text()
    for k, s in enumerate(solutions, start=1):
        assert f"#{k}: cables {','.join(map(str, s['taut']))} taut, {'stable' if s['stable'] else 'unstable'}" in page
    bad = tmp_path / "other.html"
    one_error(
        run_taut("view", "spatial-8cable", "--solutions", str(fk), "--out", str(bad)), "not of", "spatial 8-cable"
    )
    assert not bad.exists()


def test_out_in_a_missing_directory_is_refused_before_anything_is_computed(tmp_path):
    one_error(run_taut("view", "planar-4cable", "--out", str(tmp_path / "no" / "v.html")), "does not exist")
    one_error(run_taut("view", "planar-4cable", "--out", str(tmp_path / "v.png")), "must end in")


def test_trajectory_csv_with_the_wrong_columns_is_refused(tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("t,x,y\n0,0,0\n1,0.1,0\n")
    one_error(
        run_taut("view", "vscr-four-cable", "--trajectory", str(bad), "--out", str(tmp_path / "v.html")),
        "expected the columns",
    )
    bad.write_text("time,x,y,l1,l2,l3,l4,tau1,tau2,tau3,tau4\n0,0.75,-0.5,1,1,1,1,0,0,0,oops\n")
    one_error(run_taut("view", "vscr-four-cable", "--trajectory", str(bad), "--out", str(tmp_path / "v.html")), "oops")
    assert not (tmp_path / "v.html").exists()


def test_trajectory_view_of_a_wrapping_robot_from_its_csv(tmp_path):
    traj = tmp_path / "traj.csv"
    run_taut("trajectory", "vscr-four-cable", "--dt", "0.05", "--out", str(traj), "--json").json()
    rows = list(csv.DictReader(traj.open()))
    out = tmp_path / "traj.html"
    d = run_taut(
        "view", "vscr-four-cable", "--trajectory", str(traj), "--out", str(out), "--frames", "40", "--json"
    ).json()
    assert d["view"] == "trajectory" and d["frames"] == min(40, len(rows))
    # a file whose lengths are not the robot's along its poses is refused
    rows[3]["l2"] = str(float(rows[3]["l2"]) + 0.01)
    forged = tmp_path / "forged.csv"
    with forged.open("w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    one_error(run_taut("view", "vscr-four-cable", "--trajectory", str(forged), "--out", str(out)), "lengths")


def test_controlled_motion_view_from_simulate_out(tmp_path):
    sim = tmp_path / "sim.csv"
    run_taut(
        "simulate", "spatial-8cable", "--waypoints=0,0,0;0.2,0.1,0.1", "--duration", "1", "--out", str(sim), "--json"
    ).json()
    out = tmp_path / "sim.html"
    d = run_taut("view", "spatial-8cable", "--trajectory", str(sim), "--out", str(out), "--json").json()
    samples = len(sim.read_text().splitlines()) - 1
    assert d["view"] == "trajectory" and d["frames"] == min(200, samples)
    page = out.read_text()
    assert '"scene2"' in page and "tension margin" in page


def test_plan_view_has_one_frame_per_path_pose(tmp_path):
    plan = tmp_path / "plan.csv"
    argv = [
        "plan",
        "robocrane",
        "--start",
        "q1",
        "--goal",
        "q2",
        "--fix",
        "x=0,y=0,z=2,sigma=35deg",
        "--planner",
        "astar",
    ]
    assert run_taut(*argv, "--out", str(plan), "--json").json()["found"]
    poses = np.loadtxt(plan, delimiter=",", skiprows=1, ndmin=2)
    out = tmp_path / "plan.html"
    d = run_taut("view", "robocrane", "--plan", str(plan), "--out", str(out), "--json").json()
    assert d["view"] == "plan" and d["frames"] == min(200, len(poses))


def test_workspace_views_of_a_grid_and_of_certified_boxes(tmp_path):
    grid = tmp_path / "ws.npz"
    run_taut(
        "workspace",
        "planar-4cable",
        "--condition",
        "wrench-feasible",
        "--grid",
        "20",
        "--orientation",
        "0",
        "--out",
        str(grid),
        "--json",
    ).json()
    d = run_taut("view", "planar-4cable", "--workspace", str(grid), "--out", str(tmp_path / "ws.html"), "--json").json()
    assert d["view"] == "workspace"
    boxes = tmp_path / "boxes.json"
    c = run_taut(
        "workspace",
        "planar-4cable",
        "--condition",
        "static",
        "--certified",
        "--eps",
        "0.05",
        "--out",
        str(boxes),
        "--json",
    ).json()
    saved = json.loads(boxes.read_text())
    assert len(saved["inner_boxes"]) == c["boxes"]["inner"] and c["out"] == str(boxes)
    d = run_taut("view", "planar-4cable", "--workspace", str(boxes), "--out", str(tmp_path / "b.html"), "--json").json()
    assert d["view"] == "workspace" and "proven inside" in (tmp_path / "b.html").read_text()
    one_error(
        run_taut("view", "spatial-8cable", "--workspace", str(boxes), "--out", str(tmp_path / "c.html")), "not of"
    )


def test_pose_goes_with_robot_and_workspace_views_only(tmp_path):
    fk = tmp_path / "fk.json"
    fk.write_text(run_taut("fk", "planar-2cable", "--json").out)
    run = run_taut(
        "view", "planar-2cable", "--solutions", str(fk), "--pose", "0,0,0", "--out", str(tmp_path / "v.html")
    )
    one_error(run, "--pose")


@pytest.mark.parametrize("blocked", ["plotly"])
def test_without_the_view_extra_the_error_names_it(tmp_path, blocked):
    code = (
        f"import sys; sys.modules[{blocked!r}] = None; sys.argv = ['taut', 'view', 'planar-4cable', '--out', {str(tmp_path / 'v.html')!r}]; "
        "from taut.cli._main import main; raise SystemExit(main())"
    )
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 2 and proc.stderr.strip().count("\n") == 0
    assert "pip install 'taut[view]'" in proc.stderr
