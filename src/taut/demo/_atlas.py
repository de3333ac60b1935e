"""The demo's section on the structure atlas of the T-shaped VSCR, its wrench-feasible
workspace and atlas-based direct IK (Rushton 2022, §5.1.3, Algs. 5.1–5.3, Figs. 5.4, 5.9).

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §5.1.3, Algs. 5.1–5.3, Figs. 5.4 and 5.9. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

import time
from typing import TYPE_CHECKING

import numpy as np

from taut.atlas import atlas_workspace, build_atlas, direct_ik
from taut.errors import TautError
from taut.model import example
from taut.viz import plot_atlas

if TYPE_CHECKING:
    from taut.viz import Report


def atlas_section(report: Report) -> None:
    """Demo section: the structure atlas of the T-shaped VSCR and its wrench-feasible
    workspace (Figs. 5.4, 5.9), with atlas-based direct IK timed."""
    robot = example("vscr-t-shaped")
    if robot.reference is None or "initial" not in robot.reference.poses:
        raise TautError(f"{robot.name} has no reference pose 'initial' to start the atlas from")
    start = robot.reference.poses["initial"]
    t0 = time.perf_counter()
    atlas = build_atlas(robot, start)
    t_build = time.perf_counter() - t0
    ws = atlas_workspace(atlas, "wrench-feasible")
    low, high = np.array(atlas.space.bounds).reshape(2, 2)
    Q = np.random.default_rng(0).uniform(low, high, size=(100_000, 2))
    t0 = time.perf_counter()
    direct_ik(atlas, Q)
    rate = len(Q) / (time.perf_counter() - t0)
    reach = atlas.reachable_area().area
    text = (
        f"Structure atlas of the T-shaped VSCR (§5.1.3, Alg. 5.1 of Rushton 2022) from the start point "
        f"{list(start)}: {len(atlas.charts)} charts (one per reachable structure and SRA component), "
        f"{atlas.n_edges} adjacent pairs, built in {t_build:.2f} s. The charts cover {reach:.4f} m² of the "
        f"{atlas.space.area:.4f} m² installation space: the rest is inside the idlers and the winch pulleys. "
        f"Wrench-feasible workspace (Alg. 5.2, grid step {ws.step * 1000:.1f} mm): {ws.area:.4f} m², "
        f"{len(ws.pruned)} charts pruned. Atlas-based direct IK (Alg. 5.3): {rate:,.0f} queries/s."
    )
    fig = plot_atlas(atlas, ws)
    report.add_section(
        "vscr-t-shaped: structure atlas and workspace",
        text=text,
        figures=[(fig, "vscr-t-shaped-atlas.png", "charts and traversable edges; wrench-feasible workspace")],
        json={"charts": len(atlas.charts), "edges": atlas.n_edges, "reachable_area": reach, "workspace_area": ws.area},
    )
