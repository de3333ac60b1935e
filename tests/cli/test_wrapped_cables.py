"""The straight-cable commands on a variable-structure robot (docs/architecture.md §4.4),
through subprocesses: at a pose where a straight cable passes through an obstacle `ik` and
`tensions` exit 2 with one line naming the cable and the obstacle; where every cable clears,
they answer as for the robot without obstacles; `workspace` leaves the poses whose straight
cables meet an obstacle outside and counts them; `check` reports the contact; `simulate`
refuses.  Shapely decides independently (tests/straight_cables.py)."""

from pathlib import Path

import numpy as np
import pytest
from straight_cables import contacts

from taut.model import load_robot, save_robot

FIXTURE = str(Path(__file__).parents[1] / "model/fixtures/taut/vscr_weighted.yaml")
VSCR = load_robot(FIXTURE)
THROUGH = (0.0, -0.7)  # cables 1 and 2 run through objects 2 and 3
CLEAR = (0.75, -0.5)


@pytest.fixture(scope="module")
def bare(tmp_path_factory):
    """The fixture without its obstacles, as a file."""
    path = tmp_path_factory.mktemp("bare") / "bare.yaml"
    save_robot(VSCR.model_copy(update={"obstacles": ()}), path)
    return str(path)


def pose(p):
    return "--pose=" + ",".join(repr(float(x)) for x in p)


def test_the_poses_are_what_shapely_says():
    met, near = contacts(VSCR, [THROUGH, CLEAR])
    assert not near.any()
    assert met.tolist() == [[1, 2, -1, -1], [-1, -1, -1, -1]]


@pytest.mark.parametrize("command", ["ik", "tensions"])
def test_a_cable_through_an_obstacle_is_refused(taut_cli, command):
    run = taut_cli(command, FIXTURE, pose(THROUGH), "--json")
    assert run.code == 2 and run.out == ""
    lines = run.err.strip().splitlines()
    assert len(lines) == 1
    assert lines[0].startswith("taut: error: ")
    assert "cable 1 meets obstacle 2 (object 2)" in lines[0]
    assert "its wrapped length depends on the motion; taut trajectory models the wrapping" in lines[0]


@pytest.mark.parametrize("command", ["ik", "tensions"])
def test_clear_cables_answer_as_without_obstacles(taut_cli, bare, command):
    with_obstacles = taut_cli(command, FIXTURE, pose(CLEAR), "--json").json()
    without = taut_cli(command, bare, pose(CLEAR), "--json").json()
    with_obstacles.pop("robot", None), without.pop("robot", None)
    with_obstacles.pop("elapsed_s", None), without.pop("elapsed_s", None)
    assert with_obstacles == without


@pytest.mark.slow
def test_workspace_counts_the_poses_whose_straight_cables_meet_an_obstacle(taut_cli, bare):
    grid = "-1.8:1.8:13;-1.8:1.8:13"
    d = taut_cli("workspace", FIXTURE, "--condition", "static", f"--grid={grid}", "--json").json()
    b = taut_cli("workspace", bare, "--condition", "static", f"--grid={grid}", "--json").json()
    xs = np.linspace(-1.8, 1.8, 13)
    poses = np.array([(x, y) for x in xs for y in xs])
    met, near = contacts(VSCR, poses)
    assert not near.any()
    wrapped = (met >= 0).any(axis=1)
    assert d["wrapped"] == np.count_nonzero(wrapped) > 0 and b["wrapped"] == 0
    # the bare robot's verdicts at the poses whose cables clear the obstacles stay
    from taut.workspace import evaluate_workspace

    bare_inside = evaluate_workspace(VSCR.model_copy(update={"obstacles": ()}), "static", poses=poses).inside
    assert d["inside"] == np.count_nonzero(bare_inside & ~wrapped) < b["inside"] == np.count_nonzero(bare_inside)


def test_check_reports_the_contact(taut_cli, tmp_path):
    traj = tmp_path / "through.csv"
    traj.write_text(f"x,y\n{CLEAR[0]},{CLEAR[1]}\n0.3,-0.6\n{THROUGH[0]},{THROUGH[1]}\n")
    met, near = contacts(VSCR, [CLEAR, (0.3, -0.6), THROUGH])
    assert not near.any()
    d = taut_cli("check", FIXTURE, "--trajectory", str(traj), "--json").json()
    steps = [k + 1 for k in np.flatnonzero((met >= 0).any(axis=1))]
    assert d["summary"]["first_obstacle_contact"] == steps[0] == d["summary"]["first_problem"]
    for k, step in enumerate(d["steps"]):
        expected = [[i + 1, int(met[k, i]) + 1] for i in np.flatnonzero(met[k] >= 0)]
        assert step["obstacle_contacts"] == expected
        if expected:
            assert d["jacobian_ratio"][k] is None and not step["jacobian_singular"]


@pytest.mark.slow
def test_simulate_refuses_a_motion_through_an_obstacle(taut_cli):
    waypoints = f"{CLEAR[0]},{CLEAR[1]};{THROUGH[0]},{THROUGH[1]}"
    run = taut_cli("simulate", FIXTURE, "--waypoints", waypoints, "--duration", "1", "--json")
    assert run.code == 2 and run.out == ""
    lines = run.err.strip().splitlines()
    assert len(lines) == 1 and "of the reference cable 1 meets obstacle 2 (object 2)" in lines[0]
    clear = taut_cli("simulate", FIXTURE, "--waypoints", f"{CLEAR[0]},{CLEAR[1]};0.8,-0.5", "--duration", "0.5")
    assert clear.code == 0, clear.err
