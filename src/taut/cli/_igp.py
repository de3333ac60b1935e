"""``taut igp ROBOT --taut 1,2,3 --fix x=0.3,y=0.4,z=0.1 [--box ...] [--max-boxes N] [--strict] [--json]``: the inverse
geometrico-static problem (:func:`taut.dgp.solve_igp`).  No solution is an empty list, not
an error.

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §4.1.2. (docs/references.bib: berti2015)
"""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from taut.cli import _args as A
from taut.cli._incomplete import EXIT_STATUS, add_strict, report
from taut.cli._output import console, emit, markup, print_table, table
from taut.errors import CableSetError, PoseError

if TYPE_CHECKING:
    import numpy as np
    from rich.console import Console

SUMMARY = "pose, tensions and lengths for chosen taut cables (inverse geometrico-static problem)"
ROBOT = True

DESCRIPTION = f"""With the cables of --taut taut (m of them, 2 <= m <= 6; 1 <= m <= 3 for a planar
platform; 1 <= m <= 3, or 2 in the plane, for a point mass) only m pose coordinates can be
assigned: give them with --fix (names x, y, z and the robot's angle names, e.g. a, b, c or
phix, phiy, phiz for xyz conventions, phi, theta, sigma for tilt-torsion, x, y, theta
planar; angles in rad, or 30deg, pi/8).  Every equilibrium with tensions >= 0 is found and
certified (Berti 2015, §4.1.2; interval branch-and-prune): the free
coordinates, the tensions and the cable lengths to command.  A slack cable's length is
its span (pay out at least that much); cables outside their length bounds are listed.
A box that could be neither discarded nor certified (too small to split: a zero-tension or
singular solution; or left when the --max-boxes budget ran out) is undecided: the list is
then possibly incomplete, JSON "complete" is false, "undecided_enclosures" holds every such
box (the cause, the enclosure of the unknowns: the free position coordinates and the cosine
and sine of every free angle, and the taut cables' tensions, null for an unbounded side)
and one warning line goes to stderr.  Every solution not listed lies in one of those boxes.
{EXIT_STATUS}
JSON: {{"robot", "taut", "assigned", "solutions": [{{"taut", "position", "orientation",
"tensions", "lengths", "slack", "length_violations", "stable", "certificate_width",
"uniqueness_radius"}}], "complete", "undecided_boxes", "undecided_enclosures": [{{"taut",
"cause", "enclosure": {{name: [lo, hi]}}, "tensions": [[lo, hi], ...]}}], "boxes",
"exhausted", "elapsed_s"}}."""


def _cables(text: str) -> list[int]:
    try:
        return [int(p) for p in text.split(",")]
    except ValueError:
        raise CableSetError(f"--taut: expected comma-separated cable numbers, got {text!r}") from None


def _assigned(text: str) -> dict[str, float]:
    values = A.assignments(text, "--fix")
    bare = [name for name, v in values.items() if v is None]
    if bare:
        raise PoseError(f"--fix: give a value to {', '.join(bare)} (e.g. {bare[0]}=0.1)")
    return {name: v for name, v in values.items() if v is not None}


def _box(text: str | None, dimension: int) -> tuple[np.ndarray, np.ndarray] | None:
    if text is None:
        return None
    v = A.vector(text, "--box")
    if v.size != 2 * dimension:
        corners = "xmin,ymin,xmax,ymax" if dimension == 2 else "xmin,ymin,zmin,xmax,ymax,zmax"
        raise PoseError(f"--box: expected {corners}, got {v.size} numbers")
    return v[:dimension], v[dimension:]


def run(ns: argparse.Namespace) -> int:
    from taut.cli._cables import cable_indices, cable_numbers, numbered
    from taut.cli._progress import progress_bar, wanted
    from taut.dgp import solve_igp

    robot = A.load(ns.robot, ns.cable_set)
    A.straight_cables(robot, "the inverse geometrico-static problem")
    cables = _cables(ns.taut)
    with progress_bar("igp (boxes)", wanted(ns.json)) as progress:
        res = solve_igp(
            robot,
            cable_indices(cables, robot.n_cables, "--taut"),
            _assigned(ns.fix),
            box=_box(ns.box, robot.dimension),
            max_boxes=ns.max_boxes,
            progress=progress,
        )
    result = numbered(res.as_dict())
    # the coordinates the library calls fixed, the command's JSON prints as assigned
    data = {"robot": robot.name, "taut": sorted(cables), "assigned": result.pop("fixed")} | result

    def tables(con: Console, d: dict) -> None:
        free = [k for k, name in enumerate(robot.pose_names[:6]) if name not in res.fixed]
        rows = []
        for k, s in enumerate(res.solutions, 1):
            pose = [*s.position, *s.orientation]
            rows.append(
                [
                    str(k),
                    *(f"{pose[j]:.4f}" for j in free),
                    *(f"{s.tensions[i - 1]:.4f}" for i in d["taut"]),
                    "yes" if s.stable else "no",
                ]
            )
        header = ["#", *(robot.pose_names[k] for k in free), *(f"τ{i}" for i in d["taut"]), "stable"]
        print_table(con, table("free coordinates and tensions", header, rows))
        # one column per solution: n cables would not fit across a terminal
        rows = [
            [
                str(i + 1),
                *(f"≥{s.lengths[i]:.4f}" if i in s.slack else f"{s.lengths[i]:.4f}" for s in res.solutions),
            ]
            for i in range(robot.n_cables)
        ]
        header = ["cable", *(f"#{k}" for k in range(1, len(res.solutions) + 1))]
        print_table(con, table("cable lengths to command (≥ span: slack cable)", header, rows))
        for k, s in enumerate(res.solutions, 1):
            if s.length_violations:
                con.print(
                    f"[yellow]solution {k}: cables {cable_numbers(s.length_violations)} are outside their length bounds[/]"
                )

    def human(d: dict) -> None:
        con = console()
        fixed = ", ".join(f"{k}={v:.6g}" for k, v in res.fixed.items())
        con.print(
            f"[bold]{markup(robot.name)}[/]: {len(res.solutions)} equilibria with cables {d['taut']} taut at {fixed} "
            f"({res.boxes} boxes, {res.elapsed_s:.2f} s)"
        )
        if res.solutions:
            tables(con, d)
        if res.exhausted:
            con.print(
                f"[yellow]the budget of {ns.max_boxes} boxes ran out ({res.undecided} undecided): the list may be "
                "incomplete — a continuum of solutions? (--max-boxes)[/]"
            )

    status = report(res.undecided_enclosures, "solutions", ns.strict)
    emit(data, ns.json, human)
    return status


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--taut",
        required=True,
        help="taut cables, e.g. 1,2,3 (2 to 6 of them; 1 to 3 planar; 1 to 3, or 2, for a point mass)",
    )
    parser.add_argument(
        "--fix", required=True, help="as many pose coordinates as taut cables, e.g. x=0.3,y=0.4,z=0.1,a=5deg"
    )
    parser.add_argument(
        "--max-boxes", type=A.count(), default=100_000, help="branch-and-prune box budget (default 100000)"
    )
    parser.add_argument(
        "--box",
        help="search box of the free position coordinates xmin,ymin,zmin,xmax,ymax,zmax "
        "(xmin,ymin,xmax,ymax planar; default: the taut cables' reach around their exit points)",
    )
    add_strict(parser)
