"""Where to measure (``plan_poses``) on every built-in robot: candidates in the workspace a robot
of its kind has — wrench-feasible, static for a suspended one, its equilibria when it has fewer
cables than pose coordinates, or the user's own poses — and a one-line reason where none exist."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import run_taut

from taut.calibration import plan_poses
from taut.errors import TautError, UnsupportedRobotError
from taut.kinematics import structure_matrix
from taut.model import example, example_names
from taut.statics import external_wrench


def unsupported(robot) -> bool:
    return bool(robot.n_joints or robot.obstacles or robot.routed_cables or robot.sagging_cables)


@pytest.mark.parametrize("name", example_names())
def test_every_built_in_gets_a_plan_or_a_reason(name):
    robot = example(name)
    if unsupported(robot):
        with pytest.raises(UnsupportedRobotError, match="calibration"):
            plan_poses(robot, 8)
        return
    plan = plan_poses(robot, 8, known_poses=True)
    assert plan.poses.shape == (8, robot.pose_size) and np.isfinite(plan.log_det)
    assert len({tuple(p) for p in plan.poses}) == 8  # eight distinct poses, none chosen twice
    # each pose is in equilibrium on non-negative tensions, by least squares on W τ = −w
    for pose in plan.poses:
        W, w = structure_matrix(robot, pose), external_wrench(robot, pose)
        if robot.n_cables < robot.pose_size:
            tau = np.linalg.lstsq(W, -w, rcond=None)[0]
            assert np.abs(W @ tau + w).max() <= 1e-6 * max(np.abs(w).max(), 1.0)
            assert np.all(tau >= -1e-9)


def test_a_suspended_robot_with_no_load_has_no_pose_to_plan():
    """Nothing pulls the platform down: no pose is in equilibrium on taut cables, and the
    reason says so in one line."""
    robot = example("cogiro")
    loose = robot.model_copy(update={"platform": robot.platform.model_copy(update={"wrench": None})})
    with pytest.raises(TautError, match="its platform carries no load") as err:
        plan_poses(loose, 8)
    assert "\n" not in str(err.value)


def centre_height(robot, pose):
    """Height of a planar platform's centre of mass (the wrench point), where the weight acts."""
    cx, cy = robot.platform.wrench_point
    return pose[1] + np.sin(pose[2]) * cx + np.cos(pose[2]) * cy


def test_two_cables_hang_below_their_exits_in_stable_equilibria():
    """The planar 2-cable platform: every planned pose is an equilibrium with both cables taut
    (W τ = −w on positive tensions), below the exits, and a minimum of the potential energy along
    the one motion the two lengths allow (a stable equilibrium, Carricato & Merlet 2013)."""
    robot = example("planar-2cable")
    plan = plan_poses(robot, 10, known_poses=True, seed=4)
    assert plan.condition.startswith("stable equilibria")
    from taut.kinematics import cable_lengths

    for pose in plan.poses:
        W, w = structure_matrix(robot, pose), external_wrench(robot, pose)
        tau = np.linalg.lstsq(W, -w, rcond=None)[0]
        assert np.abs(W @ tau + w).max() < 1e-6 and np.all(tau > 0)
        assert pose[1] < robot.exits[:, 1].min()
        # the motion keeping both lengths: the null space of the length Jacobian Wᵀ
        null = np.linalg.svd(W.T)[2][-1]
        target = cable_lengths(robot, pose)

        ends = []
        for step in (0.02, -0.02):
            # along the motion, then back onto both lengths by Gauss–Newton
            q = pose + step * null
            for _ in range(20):
                q = q - np.linalg.pinv(-structure_matrix(robot, q).T) @ (cable_lengths(robot, q) - target)
            ends.append(q)
        assert all(centre_height(robot, q) > centre_height(robot, pose) for q in ends)


def test_candidates_are_chosen_from():
    robot = example("printer-5cable")
    rng = np.random.default_rng(0)
    candidates = np.column_stack([rng.uniform(-0.4, 0.4, 60), rng.uniform(-0.4, 0.4, 60), rng.uniform(0.3, 1.5, 60)])
    plan = plan_poses(robot, 12, candidates=candidates)
    assert plan.condition == "given candidates" and plan.candidates == 60
    assert all(any(np.array_equal(p, c) for c in candidates) for p in plan.poses)
    assert len({tuple(p) for p in plan.poses}) == 12
    with pytest.raises(TautError, match="fewer than the 61 asked"):
        plan_poses(robot, 61, candidates=candidates)


def test_cli_candidates_and_reasons(tmp_path):
    poses = tmp_path / "poses.csv"
    # columns in another order than the robot's
    poses.write_text("z,x,y\n" + "".join(f"{0.5 + 0.1 * k},{0.05 * k - 0.3},{0.2 - 0.04 * k}\n" for k in range(12)))
    run = run_taut("calibrate", "--plan", "6", "printer-5cable", "--candidates", str(poses), "--json")
    d = run.json()
    assert d["condition"] == "given candidates" and d["candidates"] == 12
    given = {(round(0.05 * k - 0.3, 9), round(0.2 - 0.04 * k, 9), round(0.5 + 0.1 * k, 9)) for k in range(12)}
    assert all(tuple(round(v, 9) for v in p) in given for p in d["poses"])
    bad = tmp_path / "bad.csv"
    bad.write_text("x,y\n0,0\n")
    for argv, message in [
        (["calibrate", "--plan", "3", "printer-5cable", "--candidates", str(bad)], "expected the pose columns x,y,z"),
        (["calibrate", "printer-5cable", "--candidates", str(poses)], "give --plan N"),
    ]:
        run = run_taut(*argv)
        assert run.code == 2 and len(run.err.splitlines()) == 1 and message in run.err, (argv, run.err)
