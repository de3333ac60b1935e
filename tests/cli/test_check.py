"""`taut check`: built-in trajectories, trajectory files, plots and bad input."""

import json

import numpy as np
import pytest

import taut
from taut.collision import check_poses, trajectory_poses

ROBOT = taut.example("adjustable-8cable")


def run(cli, *argv):
    code = cli.main(list(argv))
    out, err = cli.readouterr()
    return code, out, err


def test_builtin_trajectory_json(cli):
    code, out, err = run(cli, "check", "adjustable-8cable", "--trajectory", "sim-d", "--json")
    assert code == 0, err
    data = json.loads(out)
    steps = data["steps"]
    assert len(steps) == 101 and steps[0]["index"] == 1
    assert set(steps[0]) >= {"index", "collisions", "jacobian_singular", "force_closure_singular", "min_clearance"}
    first = next(s for s in steps if s["collisions"])
    assert first["index"] == 28 and first["collisions"] == [[1, 5], [4, 8]]
    assert data["summary"]["first_collision"] == 28


@pytest.mark.slow
def test_sim_b_singular_steps_and_plot(cli, tmp_path):
    png = tmp_path / "b.png"
    code, out, err = run(cli, "check", "adjustable-8cable", "--trajectory", "sim-b", "--json", "--plot", str(png))
    assert code == 0, err
    data = json.loads(out)
    assert data["summary"]["force_closure_singular_steps"] == [[126, 201]]
    assert png.stat().st_size > 10_000


def test_human_output(cli):
    code, out, err = run(cli, "check", "adjustable-8cable", "--trajectory", "sim-c")
    assert code == 0, err
    assert "first collision at step 71" in out


@pytest.mark.parametrize("fmt", ["csv", "yaml", "json", "waypoints"])
def test_trajectory_files(cli, tmp_path, fmt):
    poses = trajectory_poses(ROBOT, "sim-c")
    if fmt == "csv":
        f = tmp_path / "t.csv"
        f.write_text("# sim c\nx,y,z,a,b,c,s23\n" + "\n".join(",".join(repr(float(v)) for v in p) for p in poses))
    elif fmt == "yaml":
        f = tmp_path / "t.yaml"
        f.write_text("poses:\n" + "".join(f"  - {p.tolist()}\n" for p in poses))
    elif fmt == "json":
        f = tmp_path / "t.json"
        f.write_text(json.dumps(poses.tolist()))
    else:
        f = tmp_path / "w.yaml"
        f.write_text("waypoints: [[5, 5, 5, 0, 0, 0, 2], [5, 5, 5, 0.39269908169872414, 0, 0, 2]]\nsteps: [100]\n")
    code, out, err = run(cli, "check", "adjustable-8cable", "--trajectory", str(f), "--json")
    assert code == 0, err
    assert json.loads(out)["summary"]["first_collision"] == 71


@pytest.mark.parametrize(
    "content, suffix, message",
    [
        ("5,5,5,0,0,0\n", ".csv", "7 coordinates"),
        ("[[5, 5, 5, 0, 0, 0]]", ".json", "7 coordinates"),
        ("[[5, 5, 5, 0, 0, 0, 9.0]]", ".json", "outside its limits"),
        ("5,5,5,0,0,0,abc\n5,5,5,0,0,0,2\n", ".csv", "expected numbers"),
        ("waypoints: [[5, 5, 5, 0, 0, 0, 2], [5, 5, 4, 0, 0, 0, 2]]\nsteps: [0]\n", ".yaml", "positive integers"),
        ("{not yaml", ".yaml", "not valid"),
    ],
)
def test_bad_trajectory_files_exit_2(cli, tmp_path, content, suffix, message):
    f = tmp_path / f"bad{suffix}"
    f.write_text(content)
    code, out, err = run(cli, "check", "adjustable-8cable", "--trajectory", str(f))
    assert code == 2 and message in err and "Traceback" not in err


def test_unknown_trajectory_exit_2(cli):
    code, out, err = run(cli, "check", "adjustable-8cable", "--trajectory", "sim-z")
    assert code == 2 and "sim-a" in err


def test_other_robots_with_a_pose_file(cli, tmp_path):
    f = tmp_path / "p.csv"
    f.write_text("0.1,0.0,0.2,0.1,0.05,0\n0.0,0.1,0.0,0,0.1,0.1\n")
    code, out, err = run(cli, "check", "spatial-8cable", "--trajectory", str(f), "--json")
    assert code == 0, err
    steps = json.loads(out)["steps"]
    # the two poses of the file (tilted: no two cables cross exactly), as the library sees them
    ref = check_poses(taut.example("spatial-8cable"), [[0.1, 0.0, 0.2, 0.1, 0.05, 0], [0.0, 0.1, 0.0, 0, 0.1, 0.1]])
    assert [s["index"] for s in steps] == [1, 2]
    np.testing.assert_allclose([s["min_clearance"] for s in steps], ref.proximity.min_clearance, atol=1e-12)
    assert [s["jacobian_singular"] for s in steps] == ref.jacobian_singular.tolist()
    assert [s["force_closure_singular"] for s in steps] == ref.force_closure_singular.tolist()
