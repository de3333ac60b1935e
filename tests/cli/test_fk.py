"""``taut fk`` through real subprocesses: the progress bar on a terminal (and none with
``--json``), and the table headers named after the robot's pose coordinates."""

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from taut.dgp import solve_dgp
from taut.geometry import rotation_matrix
from taut.model import load_robot

TAUT = str(Path(sys.executable).with_name("taut"))


@pytest.mark.slow
def test_fk_shows_a_bar_on_a_terminal_and_none_with_json(terminal_cli):
    run = terminal_cli("fk", "suspended-3cable")
    assert run.code == 0, run.err
    assert run.drew_a_bar and "fk " in run.err and "%" in run.err
    assert "6 equilibria" in run.out and "\x1b" not in run.out  # stdout is the result alone
    run = terminal_cli("fk", "suspended-3cable", "--json")
    assert run.code == 0, run.err
    data = json.loads(run.out)
    assert len(data["solutions"]) == 6 and data["undecided_boxes"] == 0
    assert run.err == ""
    # two worker processes: the same solutions to the bit, in the same order
    done = subprocess.run(
        [TAUT, "fk", "suspended-3cable", "--workers", "2", "--json"], capture_output=True, text=True, timeout=600
    )
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout)["solutions"] == data["solutions"]


TILT_TORSION = """\
format: taut/1
name: suspended 3-cable robot, tilt-and-torsion angles
dimension: 3
orientation: tilt-torsion
platform:
  kind: rigid
  wrench: [0, 0, 1, 0, 0, 0]
  wrench_point: [0, 0, -0.577]
cables:
  - {exit: [0, 0, 0], anchor: [0.817, 0, 0]}
  - {exit: [10, 0, 0], anchor: [-0.408, 0.707, 0]}
  - {exit: [0, 12, 0], anchor: [-0.408, -0.707, 0]}
reference:
  lengths: [7.5, 10, 9.5]
"""


@pytest.mark.slow
def test_fk_headers_and_angles_follow_the_robots_orientation_convention(tmp_path):
    """The suspended robot of Table 4.3 written with tilt-and-torsion angles: the table is
    headed phi, theta, sigma, and each rotation is that of an equilibrium of the built-in
    (xyz-fixed) robot."""
    robot = tmp_path / "tilt.yaml"
    robot.write_text(TILT_TORSION)
    done = subprocess.run([TAUT, "fk", str(robot), "--max-taut", "3"], capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    header = next(line for line in done.stdout.splitlines() if "taut" in line and "stable" in line)
    names = header.replace("┃", " ").split()
    assert names[:7] == ["taut", "x", "y", "z", "phi", "theta", "sigma"]
    assert not {"a", "b", "c"} & set(names)
    done = subprocess.run([TAUT, "fk", str(robot), "--json"], capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    got = json.loads(done.stdout)["solutions"]
    reference = solve_dgp(load_robot("suspended-3cable")).solutions
    assert len(got) == len(reference) == 6
    for s in reference:
        (match,) = [g for g in got if np.allclose(g["position"], s.position, atol=1e-9)]
        R = rotation_matrix(np.array(match["orientation"]), "tilt-torsion")
        assert np.allclose(R, rotation_matrix(s.orientation, "xyz-fixed"), atol=1e-9)
