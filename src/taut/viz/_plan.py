"""Figures of a wrench-feasible path (Bohigas et al. 2013, §5, Figs. 5–6):
:func:`plot_plan` — a slice map (:func:`taut.planning.slice_map`, Fig. 5: green feasible,
blue some tension out of range, red some length out of range) with the explored atlas and
the path (Fig. 6, top), and the tension envelope ``f_0 ± v_ii`` of every cable along the
path (Fig. 6, bottom).

References
----------
.. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of Cable-Driven
   Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots, Mechanisms and
   Machine Science 12, Springer, 2013, §5, Figs. 5–6. (docs/references.bib: bohigas2013)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from taut.viz._style import DISALLOWED, INSIDE, cable_color, empty_figure

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from taut.planning import PathResult, SliceMap, WrenchFeasibleManifold

__all__ = ["plot_plan"]

_FORCE_COLOR = "#5b8fd9"


def plot_plan(
    manifold: WrenchFeasibleManifold,
    result: PathResult,
    grid: SliceMap,
    fig: Figure | None = None,
) -> Figure:
    """Figure: the slice map ``grid`` (:func:`taut.planning.slice_map`, over its two
    axes) with the atlas' chart centres (closed charts dark, open ones light) and the path in
    red (left), and the extreme tensions ``f_0 − v_ii`` (lower) and ``f_0 + v_ii`` (upper) of
    each cable along the path against its length, with the tension bounds dashed (right).
    Laid out on the empty figure ``fig`` (``None``: a new one; a figure that already has
    axes raises :class:`~taut.errors.ArgumentError`), which is returned; so does a result of
    a pose-space planner, which has no atlas."""
    from matplotlib.colors import ListedColormap

    from taut.errors import ArgumentError

    if result.atlas is None:
        raise ArgumentError(f"plot_plan draws a path planned on a manifold, not one of method {result.method!r}")
    atlas = result.atlas
    axes = grid.axes
    idx = [manifold.pose_names.index(a) for a in axes]
    centres = manifold.pose(atlas.centres)
    u, v, cls = grid.u, grid.v, grid.classes
    fig = empty_figure(fig, "a planned path", (13.0, 5.5))
    ax, tx = fig.subplots(1, 2)
    cmap = ListedColormap([INSIDE, _FORCE_COLOR, DISALLOWED])
    ax.pcolormesh(u, v, cls.T, cmap=cmap, vmin=-0.5, vmax=2.5, shading="nearest", alpha=0.45, gid="slice-map")
    closed = np.array([c.expanded for c in atlas.charts])
    ax.plot(
        centres[closed, idx[0]],
        centres[closed, idx[1]],
        ".",
        color="#333333",
        ms=3,
        label=f"closed charts ({closed.sum()})",
        gid="charts-closed",
    )
    ax.plot(
        centres[~closed, idx[0]],
        centres[~closed, idx[1]],
        ".",
        color="#999999",
        ms=3,
        label=f"open charts ({(~closed).sum()})",
        gid="charts-open",
    )
    if result.found:
        path = manifold.pose(result.path)
        # drawn in the canonical angles of the map, broken where it crosses the seam of the
        # φ window or θ = 0 (there the half-turn rewrites (φ, −θ) as (φ + π, θ))
        drawn = manifold.canonical(path)[:, idx]
        seam = np.flatnonzero(np.any(np.abs(np.diff(drawn, axis=0)) > np.pi / 2, axis=1)) + 1
        drawn = np.insert(drawn, seam, np.nan, axis=0)
        ax.plot(drawn[:, 0], drawn[:, 1], color="red", lw=2, label="path", gid="path")
        ax.plot(*drawn[0], "o", color="black", ms=6)
        ax.plot(*drawn[-1], "*", color="black", ms=10)
    ax.set_xlabel(axes[0])
    ax.set_ylabel(axes[1])
    ax.set_xlim(u[0], u[-1])
    ax.set_ylim(v[0], v[-1])
    ax.legend(loc="upper right", fontsize=8)
    ax.set_title("slice: green feasible, blue tension out of range, red length out of range", fontsize=9)
    if result.found:
        s = np.r_[0.0, np.cumsum(np.linalg.norm(np.diff(path[:, idx], axis=0), axis=1))]
        lo, hi = manifold.tension_range(result.path)
        for i in range(lo.shape[1]):
            c = cable_color(i)
            tx.plot(s, hi[:, i], color=c, lw=1.4, label=f"cable {i + 1}", gid=f"tension-max-{i + 1}")
            tx.plot(s, lo[:, i], color=c, lw=1.0, ls="-.", gid=f"tension-min-{i + 1}")
        for b in (manifold.f_min.min(), manifold.f_max.max()):
            tx.axhline(b, color="grey", lw=0.8, ls="--")
        units = sorted({"rad" if a in ("phi", "theta", "sigma") else "m" for a in axes})
        tx.set_xlabel(f"path length in ({axes[0]}, {axes[1]}) [{', '.join(units)}]")
        tx.set_ylabel("extreme tensions f₀ ± v_ii [N] (solid max, dash-dot min)")
        tx.legend(loc="best", fontsize=8, ncol=2)
    else:
        tx.text(
            0.5,
            0.5,
            "no path: " + ("none exists at this radius" if result.no_path else "search stopped"),
            ha="center",
            va="center",
            transform=tx.transAxes,
        )
    fig.tight_layout()
    return fig
