"""``taut tensions ROBOT [--pose POSE] [--wrench W] [--method M]``: a tension distribution
balancing the wrench at one pose; an infeasible pose is an answer (``docs/architecture.md`` §4.3)."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from taut.cli import _args as A
from taut.cli._output import console, emit, fmt, print_table, table
from taut.errors import TautError

if TYPE_CHECKING:
    import numpy as np

    from taut.model import Robot

SUMMARY = "tension distribution at a pose"
ROBOT = True


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--pose", help=A.POSE_HELP)
    parser.add_argument("--wrench", help="external wrench (default: the robot's own, weight included)")
    parser.add_argument(
        "--method", default="lp", help="lp | qp | inf | closed-form | improved-closed-form | barycentric"
    )


def run(ns: argparse.Namespace) -> int:
    from taut.statics import distribute_tensions

    robot = A.load(ns.robot, ns.cable_set)
    pose = A.pose(robot, ns.pose) if ns.pose is not None else A.default_pose(robot)
    wrench = None
    if ns.wrench is not None:
        wrench = A.vector(ns.wrench, "--wrench")
        if wrench.size != robot.wrench_dim:
            raise TautError(
                f"--wrench: {robot.name} takes a wrench of {robot.wrench_dim} components, got {wrench.size}"
            )
    if robot.sagging_cables:
        return _sagging(ns, robot, pose, wrench)
    res = distribute_tensions(robot, pose, wrench=wrench, method=ns.method)
    feasible = bool(res.feasible)
    data = {"robot": robot.name, "pose": pose.tolist()} | res.as_dict()

    def human(d: dict) -> None:
        con = console()
        if not feasible:
            why = (
                "no tension distribution exists"
                if d["status"] == "infeasible"
                else f"method {ns.method} found no solution"
            )
            con.print(f"[bold red]infeasible[/]: {why} at this pose within the tension bounds")
            return
        rows = [[str(i + 1), fmt(t)] for i, t in enumerate(res.tensions)]
        print_table(con, table(f"tensions ({res.method})", ["cable", "tension [N]"], rows))
        if robot.n_joints:
            names = robot.pose_names[robot.wrench_dim :]
            acting = dict(zip(robot.actuated_joints.tolist(), res.actuator_forces.tolist()))
            rows = [
                [names[j], fmt(acting[j]) if j in acting else "0 (passive: held by the cables)"]
                for j in range(robot.n_joints)
            ]
            print_table(con, table("joint forces", ["joint", "force [N] or torque [N m]"], rows))

    emit(data, ns.json, human)
    return 0


def _sagging(ns: argparse.Namespace, robot: Robot, pose: np.ndarray, wrench: np.ndarray | None) -> int:
    """The tensions of a robot with sagging cables: the static IK's, at both ends of each cable."""
    from taut.cables import sagging_ik
    from taut.cli._ik import SAG_MODEL

    res = sagging_ik(robot, pose, wrench=wrench, method=ns.method)
    data = {"robot": robot.name, "pose": pose.tolist(), "model": SAG_MODEL} | res.as_dict()
    data["tensions"] = data["platform_tensions"]

    def human(d: dict) -> None:
        con = console()
        con.print(f"{SAG_MODEL}, tensions by {res.method}")
        if not res.feasible:
            con.print(f"[bold red]infeasible[/]: no consistent tensions ({res.status}) within the bounds at both ends")
            return
        rows = [
            [str(i + 1), fmt(t0), fmt(t1)] for i, (t0, t1) in enumerate(zip(res.platform_tensions, res.exit_tensions))
        ]
        print_table(con, table(f"tensions ({res.method})", ["cable", "at platform [N]", "at exit [N]"], rows))

    emit(data, ns.json, human)
    return 0
