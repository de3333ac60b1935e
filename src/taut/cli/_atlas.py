"""``taut atlas ROBOT``: the structure atlas of a planar VSCR and its workspace — for a rigid
platform one page of constant orientation (Ch. 5, Algs. 5.1–5.2 and §5.2 of
Rushton (2022); :mod:`taut.atlas`).

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, Ch. 5, Algs. 5.1–5.2, §5.2. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

import argparse
import json

from taut.cli import _args as A
from taut.cli._output import console, emit, markup, save_figure, written
from taut.errors import TautError

SUMMARY = "structure atlas and workspace of a planar VSCR (rigid: one orientation page)"
ROBOT = True

DESCRIPTION = """Build the structure atlas of a planar VSCR (one chart per reachable structure,
Alg. 5.1) from a start point, and its workspace under a condition (Alg. 5.2).  For a
rigid platform the atlas is the page of constant orientation T (§5.2): charts hold the
platform reference points whose anchors R(T) r_i + p are cable-reachable and where the
platform outline (platform.shape.polygon) hits no object, border or cable.

--start x,y     start point (default: the robot's first reference pose)
--theta T       platform orientation [rad] of a rigid platform (default: that of the
                first reference pose, else 0); only 0 for a point-mass platform
--condition C   wrench-feasible (default), wrench-closure or static
--out FILE.json the charts: structure (per cable, wrapped objects as [object, +1|-1],
                1-based), domain polygon, area, neighbours; and the edges
JSON: {"charts", "edges", "theta", "reachable_area", "workspace_area", "pruned", "time"}."""


def _chart(chart: dict) -> dict:
    """A chart of :meth:`StructureAtlas.as_dict` with 1-based chart and object numbers."""
    return chart | {
        "index": chart["index"] + 1,
        "structure": [[[k + 1, d] for k, d in s] for s in chart["structure"]],
        "neighbours": [n + 1 for n in chart["neighbours"]],
    }


def _edge(edge: dict) -> dict:
    """An edge of :meth:`StructureAtlas.as_dict` with 1-based chart, cable and object numbers."""
    return edge | {"charts": [c + 1 for c in edge["charts"]], "cable": edge["cable"] + 1, "object": edge["object"] + 1}


def run(ns: argparse.Namespace) -> int:
    import time

    import numpy as np

    from taut.atlas import atlas_workspace, build_atlas
    from taut.cli._progress import progress_bar, wanted
    from taut.wrapping import contacts_text

    out = A.output_file(ns.out, "--out")
    plot = A.plot_file(ns.plot)
    robot = A.load(ns.robot, ns.cable_set)
    ref = None
    if robot.reference is not None and robot.reference.poses:
        ref = np.asarray(next(iter(robot.reference.poses.values())), float)
    if ns.start is not None:
        start = A.vector(ns.start, "--start")
        if start.size != 2:
            raise TautError(f"--start: expected x,y, got {ns.start!r}")
    elif ref is not None:
        start = ref[:2]
    else:
        raise TautError(f"{robot.name} has no reference pose; give --start x,y")
    theta = ns.theta if ns.theta is not None else 0.0
    if robot.is_point_mass and theta != 0.0:
        raise TautError("--theta: a point-mass platform has no orientation (only 0)")
    if ns.theta is None and not robot.is_point_mass and ref is not None and ref.size == 3:
        theta = float(ref[2])
    t0 = time.perf_counter()
    with progress_bar("atlas (charts expanded)", wanted(ns.json)) as progress:
        atlas = build_atlas(robot, start, theta=theta, progress=progress)
    if not atlas.complete:
        raise TautError(f"{robot.name}: more than {len(atlas.charts)} charts; the atlas is too large")
    with progress_bar("workspace (charts)", wanted(ns.json)) as progress:
        ws = atlas_workspace(atlas, ns.condition, progress=progress)
    pages = atlas.as_dict()
    region = ws.as_dict()
    data = {
        "robot": robot.name,
        **{k: pages[k] for k in ("start", "theta", "charts", "edges", "reachable_area")},
        "workspace_area": region["area"],
        "condition": region["condition"],
        "pruned": [c + 1 for c in region["pruned"]],
        "time": time.perf_counter() - t0,
    }
    if out is not None:
        full = data | {
            "chart_list": [_chart(c) for c in pages["chart_list"]],
            "edge_list": [_edge(e) for e in pages["edge_list"]],
        }
        with written(out, "--out") as tmp, open(tmp, "w") as fh:
            json.dump(full, fh, indent=1, allow_nan=False)
        data["out"] = str(out)
    if plot is not None:
        from taut.viz import plot_atlas

        save_figure(plot_atlas(atlas, ws), plot, data)

    def human(d: dict) -> None:
        con = console()
        page = "" if robot.is_point_mass else f" (page θ = {d['theta']:.6g} rad)"
        con.print(
            f"[bold]{markup(robot.name)}[/]{page}: {d['charts']} charts, {d['edges']} adjacent pairs, "
            f"reachable area {d['reachable_area']:.6g} m², {d['condition']} workspace {d['workspace_area']:.6g} m² "
            f"({len(d['pruned'])} charts pruned) in {d['time']:.2f} s"
        )
        for c in atlas.charts:
            states = "; ".join(contacts_text(st) or "-" for st in c.states)
            con.print(f"  chart {c.index + 1:3d}  area {c.area:10.6f}  wraps [{states}]")

    emit(data, ns.json, human)
    return 0


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--start", metavar="x,y", help="start point (default: the first reference pose)")
    parser.add_argument(
        "--theta",
        type=A.real(),
        metavar="T",
        help="orientation [rad] of a rigid platform's atlas page (0 for a point mass)",
    )
    parser.add_argument(
        "--condition",
        default="wrench-feasible",
        choices=("wrench-feasible", "wrench-closure", "static"),
        help="workspace condition (Alg. 5.2)",
    )
    parser.add_argument("--out", metavar="FILE.json", help="write the charts and edges")
    parser.add_argument("--plot", metavar="FILE.png", help="atlas and workspace figure (Figs. 5.4, 5.9)")
