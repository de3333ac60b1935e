"""``taut sag ROBOT [--grid N] [--plot F.png]``: whether sag matters — over a grid of the
workspace, each sagging cable's length difference from the straight model, its largest sag
and its tension increase at the exit (:func:`taut.workspace.sag_map`)."""

from __future__ import annotations

import argparse

from taut.cli import _args as A
from taut.cli._output import console, emit, fmt, markup, print_table, save_figure, table
from taut.cli._progress import progress_bar, wanted
from taut.errors import TautError

SUMMARY = "sagging cables against straight ones over the workspace: length differences, sag, exit tensions"
ROBOT = True

#: How the output names the two models.
MODELS = "static IK with sagging cables (Irvine's elastic catenary) against straight cables"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--grid",
        help="points per axis (default 11 spatial, 41 planar), or per-axis ranges 'x0:x1:n;y0:y1:n[;z0:z1:n]'",
    )
    parser.add_argument("--orientation", help="fixed platform orientation (theta, or a,b,c)")
    parser.add_argument(
        "--method",
        default="lp",
        help="tension distribution of both models: lp | qp | inf | closed-form | improved-closed-form | barycentric",
    )
    parser.add_argument(
        "--weight",
        type=A.real(above=0),
        metavar="N_PER_M",
        help="give every cable this weight per metre [N/m] (what if the robot's cables were heavy)",
    )
    parser.add_argument(
        "--stiffness",
        type=A.real(above=0),
        metavar="EA",
        help="give every cable this axial stiffness EA [N] (default: the robot's; none: inextensible)",
    )
    parser.add_argument("--plot", metavar="FILE.png", help="draw the largest sags and the map of length differences")


def run(ns: argparse.Namespace) -> int:
    from taut.workspace import sag_map

    plot = A.plot_file(ns.plot)
    robot = A.load(ns.robot, ns.cable_set)
    update = {k: v for k, v in (("weight", ns.weight), ("stiffness", ns.stiffness)) if v is not None}
    if update:
        robot = robot.model_copy(update={"cables": tuple(c.model_copy(update=update) for c in robot.cables)})
    if not robot.sagging_cables:
        raise TautError(
            f"{robot.name}: no sagging cables (give cables[].weight in the robot file, or --weight, in N/m)"
        )
    grid, resolution = A.grid(ns.grid, robot.dimension)
    orientation = A.vector(ns.orientation, "--orientation") if ns.orientation is not None else None
    with progress_bar("sag", wanted(ns.json)) as progress:
        res = sag_map(
            robot, grid=grid, resolution=resolution, orientation=orientation, method=ns.method, progress=progress
        )
    data = {"robot": robot.name, "model": MODELS} | res.as_dict()
    if plot is not None:
        from taut.viz import plot_sag

        save_figure(plot_sag(res, robot), plot, data)

    def human(d: dict) -> None:
        con = console()
        s = d["summary"]
        con.print(
            f"[bold]{markup(robot.name)}[/]: {MODELS}, tensions by {res.method}, {s['poses']} grid poses: "
            f"{s['feasible']} with tensions when the cables sag, {s['straight_feasible']} when straight, "
            f"{s['both']} in both ({d['elapsed_s']:.2f} s)"
        )
        if s["both"] == 0:
            con.print("no pose has tensions in both models: nothing to compare")
            return
        rows = [
            [str(i + 1), fmt(1e3 * dl), fmt(sg), fmt(dt)]
            for i, (dl, sg, dt) in enumerate(
                zip(s["largest_length_difference"], s["largest_sag"], s["largest_exit_tension_increase"])
            )
        ]
        head = ["cable", "largest |Δ length| [mm]", "largest sag [m]", "largest exit tension increase [N]"]
        print_table(con, table("over the poses with tensions in both models", head, rows))

    emit(data, ns.json, human)
    return 0
