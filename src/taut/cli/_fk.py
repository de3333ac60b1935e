"""``taut fk ROBOT [--lengths L1,...,Ln | --readings R1,...,Rn] [--max-taut K] [--max-boxes N] [--strict] [--workers N]
[--scheduler ADDRESS] [--plot FILE] [--json]``:
all equilibrium poses for given cable lengths (the direct geometrico-static problem,
:func:`taut.dgp.solve_dgp`).  Without ``--lengths`` the robot's ``reference.lengths`` are
used; ``--readings`` gives encoder readings instead, each length its reading plus the
cable's encoder zero (``cables[].length_offset``, written by ``taut calibrate``).  No
equilibrium is an empty list, not an error."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import TYPE_CHECKING

from taut.cli import _args as A
from taut.cli._cables import cable_numbers, numbered
from taut.cli._incomplete import EXIT_STATUS, add_strict, report
from taut.cli._output import console, emit, markup, print_table, save_figure, table
from taut.errors import TautError

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

    from taut.model import Robot
from taut.cli._progress import progress_bar, wanted

SUMMARY = "all equilibria for given cable lengths (direct geometrico-static problem)"
ROBOT = True

DESCRIPTION = f"""All equilibrium poses of the platform for given cable lengths, every one certified
(interval branch-and-prune, Krawczyk).  A box double precision leaves too small to split
(a double or nearly double solution) is searched again in 256-bit balls when python-flint is
installed (pip install 'taut[precise]').  A box that could be neither discarded nor
certified (too small to split even so; or left when the --max-boxes budget ran out) is
undecided: the list of equilibria is then possibly incomplete, JSON "complete" is false,
"undecided_enclosures" holds every such box (its sub-problem's taut cables, the cause, the
enclosure of the unknowns: the fixed-frame coordinates q1_x ... q3_z of the platform's
reference points (q1_x ... q2_y of a planar platform's two; x, y[, z] of a point mass),
given in the body frame as "reference_points", the normal n_x, n_y, n_z of their plane,
and for a cable k through a swivelling pulley its anchor's distance d_k from the swivel
axis and its free length l_f_k; and the taut cables' tensions, null for an unbounded
side), and one
warning line on stderr names the sub-problems.  Every equilibrium not listed lies in one of
those boxes.  An equilibrium on the border of two taut sets (a taut cable at zero tension,
or a slack one exactly at its length) is listed once, under the smaller set, with "boundary"
naming the larger one.
{EXIT_STATUS}
JSON: {{"robot", "solutions": [{{"taut", "position", "orientation", "tensions", "stable", "boundary"?, ...}}],
"complete", "exhausted", "subproblems", "undecided_boxes", "undecided_enclosures": [{{"taut", "cause",
"enclosure": {{name: [lo, hi]}}, "tensions": [[lo, hi], ...], "reference_points"}}], "boxes",
"elapsed_s", "least_squares"?: {{"position", "residuals", "rms_residual"}}}}.  A point mass
(position x, y[, z], no orientation) hangs on at most 3 (2 in the plane) taut cables, at
the lowest point its cables allow: lengths that admit none give no equilibrium, complete.
"least_squares" is then, apart, the least-squares fit of all the lengths that cable-printer
firmware computes (every cable assumed taut): not an equilibrium.  With more than 3 (2)
cables at their lengths, the point mass's equilibrium is listed once, "boundary" naming them
all, its tensions those of one taut set: one of many distributions that balance the load."""


def run(ns: argparse.Namespace) -> int:
    from taut.dgp import MAX_SUBPROBLEM_BOXES, solve_dgp
    from taut.parallel import get_executor

    plot = A.plot_file(ns.plot)
    robot = A.load(ns.robot, ns.cable_set)
    lengths = A.vector(ns.lengths, "--lengths") if ns.lengths is not None else None
    if ns.readings is not None:
        lengths = _from_readings(robot, ns)
    if robot.sagging_cables:
        return _sagging(ns, robot, lengths, plot)
    with (
        get_executor(workers=ns.workers, scheduler=ns.scheduler) as executor,
        progress_bar("fk", wanted(ns.json)) as progress,
    ):
        res = solve_dgp(
            robot,
            lengths,
            max_taut=ns.max_taut,
            executor=executor,
            max_boxes=MAX_SUBPROBLEM_BOXES if ns.max_boxes is None else ns.max_boxes,
            progress=progress,
        )
    data = {"robot": robot.name} | numbered(res.as_dict())
    if plot is not None:
        from taut.viz import plot_equilibria

        save_figure(plot_equilibria(robot, res.solutions), plot, data)
    status = report(res.undecided_enclosures, "equilibria", ns.strict, multiprecision_hint=True)

    def human(d: dict) -> None:
        con = console()
        t = table(
            f"{robot.name}: {len(res.solutions)} equilibria ({res.subproblems} sub-problems, {res.elapsed_s:.2f} s)"
            + ("" if res.complete else f", incomplete: {res.undecided} boxes undecided"),
            ["taut", *robot.pose_names, *(f"τ{i + 1}" for i in range(robot.n_cables)), "stable"],
            [
                [
                    ",".join(map(str, cable_numbers(s.taut))),
                    *(f"{v:.4f}" for v in s.position),
                    *(f"{v:.4f}" for v in s.orientation),
                    *(f"{v:.4f}" for v in s.tensions),
                    "yes" if s.stable else "no",
                ]
                for s in res.solutions
            ],
        )
        print_table(con, t)
        if res.least_squares is not None:
            fit = res.least_squares
            con.print(
                f"least-squares fit of all the lengths, as firmware computes it (not an equilibrium): "
                f"({', '.join(f'{v:.4f}' for v in fit.position)}), rms residual {fit.rms_residual:.3g} m"
            )

    emit(data, ns.json, human)
    return status


#: How the output names the model of a robot with sagging cables.
SAG_MODEL = (
    "static FK with sagging cables (Irvine's elastic catenary): Newton continuation from the straight-cable "
    "pose, one local equilibrium, not a certified list"
)


def _sagging(ns: argparse.Namespace, robot: Robot, lengths: npt.NDArray[np.float64] | None, plot: Path | None) -> int:
    import numpy as np

    from taut.cables import sagging_fk

    if lengths is None:
        lengths = (
            None if robot.reference is None or robot.reference.lengths is None else np.array(robot.reference.lengths)
        )
    if lengths is None:
        raise TautError(f"--lengths: {robot.name} has no reference lengths; give its cables' unstrained lengths")
    if ns.max_taut is not None or ns.max_boxes is not None:
        raise TautError("--max-taut and --max-boxes go with the certified search of straight cables")
    res = sagging_fk(robot, lengths)
    data = {"robot": robot.name, "model": SAG_MODEL, "lengths": lengths.tolist()} | res.as_dict()
    if plot is not None and res.found:
        from taut.viz import draw_robot

        save_figure(draw_robot(robot, res.pose).figure, plot, data)

    def human(d: dict) -> None:
        con = console()
        con.print(f"[bold]{markup(robot.name)}[/]: {SAG_MODEL}")
        if not res.found:
            con.print("no equilibrium found for these unstrained lengths")
            return
        at = ", ".join(f"{n}={v:.6g}" for n, v in zip(robot.pose_names, res.pose))
        con.print(f"equilibrium at {at}: {'stable' if res.stable else 'unstable'}")
        rows = [
            [str(i + 1), f"{t0:.6g}", f"{t1:.6g}", f"{sg:.4g}"]
            for i, (t0, t1, sg) in enumerate(zip(res.platform_tensions, res.exit_tensions, res.sag))
        ]
        head = ["cable", "tension at platform [N]", "tension at exit [N]", "sag [m]"]
        print_table(con, table("cables", head, rows))

    emit(data, ns.json, human)
    return 0


def _from_readings(robot: Robot, ns: argparse.Namespace) -> npt.NDArray[np.float64]:
    """The lengths of ``--readings``: each encoder's reading plus the length at its zero."""
    if ns.lengths is not None:
        raise TautError("give --lengths or --readings, not both")
    readings = A.vector(ns.readings, "--readings")
    if readings.size != robot.n_cables:
        raise TautError(f"--readings: expected {robot.n_cables} numbers, got {readings.size}")
    missing = [i + 1 for i in range(robot.n_cables) if i not in robot.encoder_cables]
    if missing:
        raise TautError(
            f"--readings: {robot.name} has no encoder zero (cables[].length_offset) for cables "
            f"{', '.join(map(str, missing))}; calibrate it (taut calibrate --out) or give --lengths"
        )
    return readings + robot.length_offsets


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--lengths",
        help="cable lengths L1,...,Ln (default: the robot's reference lengths); unstrained lengths of sagging cables",
    )
    parser.add_argument(
        "--readings",
        help="encoder readings R1,...,Rn instead of lengths: each cable's length is its reading plus its "
        "cables[].length_offset (written by taut calibrate --out)",
    )
    parser.add_argument(
        "--max-taut",
        type=A.count(),
        default=None,
        metavar="K",
        help="largest number of taut cables (default min(n, 6))",
    )
    parser.add_argument(
        "--max-boxes",
        type=A.count(),
        default=None,
        metavar="N",
        help="box budget of every sub-problem; the boxes left when it runs out are undecided (default 2000000)",
    )
    add_strict(parser)
    A.add_parallel(parser, workers=1)
    parser.add_argument("--plot", metavar="FILE.png", help="the robot in every equilibrium found")
