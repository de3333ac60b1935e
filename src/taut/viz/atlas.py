"""Figures of a structure atlas (Figs. 5.4 and 5.9 of Rushton 2022):
:func:`plot_atlas` — the charts in grey (darker where they overlap) with their traversable
edges, the start point (and a rigid platform's outline there, at the page's orientation), and, given a workspace (Alg. 5.2), the workspace in purple over
the charts kept; :func:`atlas_section`, the demo's atlas of the T-shaped VSCR.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, Figs. 5.4 and 5.9, Alg. 5.2. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

import time
from collections.abc import Iterable
from typing import TYPE_CHECKING

import numpy as np

from taut.atlas import AtlasWorkspace, StructureAtlas, atlas_workspace, build_atlas, direct_ik, platform_outline
from taut.errors import TautError
from taut.model import example
from taut.viz._style import empty_figure
from taut.viz.robot import draw_scene_2d

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure
    from shapely.geometry.base import BaseGeometry

    from taut.viz.report import Report

__all__ = ["atlas_section", "plot_atlas"]

WORKSPACE = "#7b2cbf"


def _fill_chart(ax: Axes, domain: BaseGeometry, label: str | None) -> None:
    """A chart's domain (a polygon or several, with holes) in translucent grey."""
    from matplotlib.patches import PathPatch
    from matplotlib.path import Path

    for g in getattr(domain, "geoms", [domain]):
        if g.is_empty:
            continue
        rings = [np.asarray(g.exterior.coords)] + [np.asarray(r.coords) for r in g.interiors]
        verts = np.concatenate(rings)
        codes = np.concatenate([[Path.MOVETO] + [Path.LINETO] * (len(r) - 2) + [Path.CLOSEPOLY] for r in rings])
        ax.add_patch(
            PathPatch(Path(verts, codes), fc="0.35", ec="none", alpha=0.18, zorder=0.2, label=label, gid="chart")
        )
        label = None


def _draw_charts(ax: Axes, atlas: StructureAtlas, charts: Iterable[int], title: str) -> None:
    draw_scene_2d(atlas.robot, ax, labels=False)
    for k, c in enumerate(charts):
        _fill_chart(ax, atlas.charts[c].domain, "chart (darker: overlap)" if k == 0 else None)
    keep = set(charts)
    first = True
    for e in atlas.edges:
        if e.charts[0] in keep and e.charts[1] in keep:
            ax.plot(
                *e.segment.T, color="0.15", lw=1.2, zorder=2, label="traversable edge" if first else None, gid="edge"
            )
            first = False
    ax.plot(*atlas.start, marker="o", color="black", ms=5, zorder=5, label="start", gid="start")
    M = platform_outline(atlas.robot, atlas.theta)
    if M is not None:  # the platform at the start, at the page's orientation
        ax.fill(
            *(np.asarray(M.exterior.coords) + atlas.start).T,
            fc="none",
            ec="black",
            lw=1.0,
            zorder=5,
            label=f"platform (θ = {atlas.theta:.3g} rad)",
            gid="platform",
        )
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_title(title, fontsize=10)


def plot_atlas(atlas: StructureAtlas, workspace: AtlasWorkspace | None = None, fig: Figure | None = None) -> Figure:
    """Figure: the atlas (Fig. 5.4 / 5.9b) and, with ``workspace``, the workspace over the
    charts kept by Alg. 5.2 (Fig. 5.9c) in a second panel; laid out on the empty figure
    ``fig`` (``None``: a new one; a figure that already has axes raises ``ValueError``),
    which is returned."""
    panels = 2 if workspace is not None else 1
    fig = empty_figure(fig, "a structure atlas", (6.5 * panels, 5.5))
    axes = fig.subplots(1, panels, squeeze=False)
    ax = axes[0, 0]
    _draw_charts(
        ax,
        atlas,
        range(len(atlas.charts)),
        f"{atlas.robot.name}: {len(atlas.charts)} charts, {atlas.n_edges} adjacent pairs",
    )
    ax.legend(loc="best", fontsize=7)
    if workspace is not None:
        ax = axes[0, 1]
        _draw_charts(
            ax,
            atlas,
            workspace.charts,
            f"{workspace.condition} workspace: {workspace.area:.4g} m², {len(workspace.pruned)} charts pruned",
        )
        P = workspace.points
        if len(P):
            ax.scatter(
                P[:, 0],
                P[:, 1],
                s=(72 * 0.6 * workspace.step / max(np.ptp(P[:, 0]), 1e-9) * 6) ** 2,
                marker="s",
                color=WORKSPACE,
                alpha=0.5,
                lw=0,
                zorder=1.5,
                label="workspace",
                gid="workspace",
            )
        ax.legend(loc="best", fontsize=7)
    fig.tight_layout()
    return fig


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
