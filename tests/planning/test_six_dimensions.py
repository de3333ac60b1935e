"""Full six-dimensional queries (no slice) by AtlasRRT on the Robocrane (q5 → q6 of the
3-D slice test, now with x, y and σ free too) and on a second cable hexapod, MARIONET-VR
(Berti 2015, Table 4.5) read in tilt-and-torsion angles with finite tension and length
bounds; every path checked by the independent feasibility test, and through the CLI."""

import json

import numpy as np
import pytest

from taut.kinematics import platform_frame
from taut.model import load_robot, save_robot
from taut.planning import plan_path
from taut.planning._manifold import WrenchFeasibleManifold
from taut.planning._verify import verify_path

ROBOCRANE = load_robot("robocrane")
POSES = {k: np.array(v) for k, v in ROBOCRANE.reference.poses.items()}
_MARIONET = load_robot("marionet-vr")
MARIONET = _MARIONET.model_copy(
    update={
        "name": "MARIONET-VR (tilt-and-torsion)",
        "orientation": "tilt-torsion",
        "cables": tuple(c.model_copy(update={"tension": (0.0, 2.0), "length": (0.0, 6.0)}) for c in _MARIONET.cables),
    }
)
M_START = np.array([0.25, -2.25, 0.75, 0.5, 0.2, 0.3])
M_GOAL = np.array([-1.0, 0.0, -0.25, -1.0, 0.3, -0.4])


def same_pose(robot, a, b) -> bool:
    (pa, Ra), (pb, Rb) = (platform_frame(robot, np.asarray(q, float)[None]) for q in (a, b))
    return bool(np.allclose(pa, pb, atol=1e-9) and np.allclose(Ra, Rb, atol=1e-9))


@pytest.mark.parametrize(
    ("robot", "start", "goal"),
    [(ROBOCRANE, POSES["q5"], POSES["q6"]), (MARIONET, M_START, M_GOAL)],
    ids=["robocrane-q5-q6", "marionet-vr"],
)
def test_six_dimensional_query(robot, start, goal):
    M = WrenchFeasibleManifold.from_robot(robot)
    assert M.dim == 6
    # the straight line leaves the wrench-feasible C-space: the query is not trivial
    assert not verify_path(robot, np.array([start, goal]), subdivide=50).all_feasible
    res = plan_path(
        M.implicit(),
        M.lift(start),
        M.lift(goal),
        method="atlasrrt",
        radius=0.4,
        metric=M.pose_metric,
        seed=0,
        max_nodes=3000,
    )
    assert res.found and res.charts >= 2
    poses = M.pose(res.path)
    assert same_pose(robot, poses[0], start) and same_pose(robot, poses[-1], goal)
    assert np.abs(np.diff(poses, axis=0)).max() < 0.2
    assert verify_path(robot, poses, subdivide=10).all_feasible
    assert res.length >= np.linalg.norm(poses[-1] - poses[0]) - 1e-9


@pytest.mark.slow
def test_six_dimensional_query_through_the_cli(taut_cli, tmp_path):
    run = taut_cli("plan", "robocrane", "--start", "q5", "--goal", "q6", "--planner", "atlasrrt", "--json")
    assert run.code == 0, run.err
    d = run.json()
    assert d["found"] and d["verified"] and d["fixed"] == {}
    path = np.array(d["path"])
    assert path.shape[1] == 6 and np.ptp(path[:, 2]) >= 0.8 - 1e-9  # z from 1.2 to 2
    assert verify_path(ROBOCRANE, path, subdivide=20).all_feasible
    file = tmp_path / "marionet.yaml"
    save_robot(MARIONET, file)
    pose = lambda q: ",".join(repr(float(v)) for v in q)  # noqa: E731
    run = taut_cli(
        "plan", str(file), f"--start={pose(M_START)}", f"--goal={pose(M_GOAL)}", "--planner", "auto", "--json"
    )
    assert run.code == 0, run.err
    d = json.loads(run.out)
    assert d["method"] == "atlasrrt" and d["found"] and d["verified"]
    assert verify_path(MARIONET, np.array(d["path"]), subdivide=20).all_feasible
