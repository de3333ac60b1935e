"""``taut ik ROBOT [--pose POSE]``: inverse kinematics — cable lengths, unit directions,
platform anchors and the structure matrix at one pose, and what each encoder reads there when
the robot carries encoder zeros (``cables[].length_offset``, written by ``taut calibrate``); on a robot with sagging cables
(``cables[].weight``) the static inverse kinematics of the elastic catenaries (unstrained
lengths, chord lengths, tensions at both ends, sag)."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from taut.cli import _args as A
from taut.cli._output import console, emit, fmt, markup, print_table, save_figure, table
from taut.errors import TautError

if TYPE_CHECKING:
    from pathlib import Path

    import numpy as np

    from taut.model import Robot

SUMMARY = "inverse kinematics: cable lengths, directions, structure matrix"
ROBOT = True

#: How the human output names the model of a robot with sagging cables.
SAG_MODEL = "static IK with sagging cables (Irvine's elastic catenary)"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--pose", help=A.POSE_HELP)
    parser.add_argument("--plot", metavar="FILE.png", help="draw the robot at the pose")
    parser.add_argument(
        "--method",
        help="robots with sagging cables: the tension distribution method iterated to consistency "
        "(lp, the default | qp | inf | closed-form | improved-closed-form | barycentric)",
    )


def run(ns: argparse.Namespace) -> int:
    from taut.kinematics import inverse_kinematics

    plot = A.plot_file(ns.plot)
    robot = A.load(ns.robot, ns.cable_set)
    pose = A.pose(robot, ns.pose) if ns.pose is not None else A.default_pose(robot)
    if robot.sagging_cables:
        return _sagging(ns, robot, pose, plot)
    if ns.method is not None:
        raise TautError(f"--method: {robot.name} has no sagging cables (cables[].weight); its IK needs no tensions")
    ik = inverse_kinematics(robot, pose)
    data = {"robot": robot.name, "pose": pose.tolist()} | ik.as_dict()
    readings = None
    if robot.encoder_cables:
        # what each winch's encoder reads there, from the zero that calibration estimated
        readings = ik.lengths - robot.length_offsets
        data["encoder_readings"] = readings.tolist()

    def human(d: dict) -> None:
        con = console()
        at = ", ".join(f"{n}={fmt(v)}" for n, v in zip(robot.pose_names, pose))
        con.print(f"[bold]{markup(robot.name)}[/] at pose {markup(at)}")
        dims = "xyz"[: robot.dimension]
        rows = [
            [str(i + 1), fmt(length), *(fmt(c) for c in u)]
            for i, (length, u) in enumerate(zip(ik.lengths, ik.directions))
        ]
        head = ["cable", "length [m]", *(f"u_{c}" for c in dims)]
        if readings is not None:
            head.insert(2, "encoder [m]")
            for row, reading in zip(rows, readings):
                row.insert(2, fmt(reading))
        print_table(con, table("cables", head, rows))
        W = ik.structure_matrix
        rows = [[f"{x:.4g}" for x in row] for row in W]
        print_table(con, table("structure matrix W", [str(i + 1) for i in range(W.shape[1])], rows))

    if plot is not None:
        from taut.viz import draw_robot

        save_figure(draw_robot(robot, pose).figure, plot, data)
    emit(data, ns.json, human)
    return 0


def _sagging(ns: argparse.Namespace, robot: Robot, pose: np.ndarray, plot: Path | None) -> int:
    from taut.cables import sagging_ik

    res = sagging_ik(robot, pose, method=ns.method or "lp")
    data = {"robot": robot.name, "pose": pose.tolist(), "model": SAG_MODEL} | res.as_dict()

    def human(d: dict) -> None:
        con = console()
        at = ", ".join(f"{n}={fmt(v)}" for n, v in zip(robot.pose_names, pose))
        con.print(f"[bold]{markup(robot.name)}[/] at pose {markup(at)}: {SAG_MODEL}, tensions by {res.method}")
        if not res.feasible:
            con.print(f"[bold red]no consistent tensions[/] ({res.status}) at this pose within the tension bounds")
            return
        rows = [
            [str(i + 1), fmt(l0), fmt(c), fmt(s), fmt(t0), fmt(t1)]
            for i, (l0, c, s, t0, t1) in enumerate(
                zip(res.unstrained_lengths, res.chord_lengths, res.sag, res.platform_tensions, res.exit_tensions)
            )
        ]
        head = [
            "cable",
            "unstrained length [m]",
            "chord [m]",
            "sag [m]",
            "tension at platform [N]",
            "tension at exit [N]",
        ]
        print_table(con, table("sagging cables", head, rows))

    if plot is not None:
        from taut.viz import draw_robot

        save_figure(draw_robot(robot, pose).figure, plot, data)
    emit(data, ns.json, human)
    return 0
