"""``taut ik ROBOT [--pose POSE]``: inverse kinematics — cable lengths, unit directions,
platform anchors and the structure matrix at one pose."""

from __future__ import annotations

import argparse

from taut.cli import _args as A
from taut.cli._output import console, emit, fmt, markup, print_table, save_figure, table

SUMMARY = "inverse kinematics: cable lengths, directions, structure matrix"
ROBOT = True


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--pose", help=A.POSE_HELP)
    parser.add_argument("--plot", metavar="FILE.png", help="draw the robot at the pose")


def run(ns: argparse.Namespace) -> int:
    from taut.kinematics import inverse_kinematics

    plot = A.plot_file(ns.plot)
    robot = A.load(ns.robot, ns.cable_set)
    pose = A.pose(robot, ns.pose) if ns.pose is not None else A.default_pose(robot)
    ik = inverse_kinematics(robot, pose)
    data = {"robot": robot.name, "pose": pose.tolist()} | ik.as_dict()

    def human(d: dict) -> None:
        con = console()
        at = ", ".join(f"{n}={fmt(v)}" for n, v in zip(robot.pose_names, pose))
        con.print(f"[bold]{markup(robot.name)}[/] at pose {markup(at)}")
        dims = "xyz"[: robot.dimension]
        rows = [
            [str(i + 1), fmt(length), *(fmt(c) for c in u)]
            for i, (length, u) in enumerate(zip(ik.lengths, ik.directions))
        ]
        print_table(con, table("cables", ["cable", "length [m]", *(f"u_{c}" for c in dims)], rows))
        W = ik.structure_matrix
        rows = [[f"{x:.4g}" for x in row] for row in W]
        print_table(con, table("structure matrix W", [str(i + 1) for i in range(W.shape[1])], rows))

    if plot is not None:
        from taut.viz import draw_robot

        save_figure(draw_robot(robot, pose).figure, plot, data)
    emit(data, ns.json, human)
    return 0
