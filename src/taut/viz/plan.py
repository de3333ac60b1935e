"""Figures of a wrench-feasible path (Bohigas et al. 2013, §5, Figs. 5–6):
:func:`slice_map` — the discretised wrench-feasible C-space of a 2-D slice (Fig. 5: green
feasible, blue some tension out of range, red some length out of range);
:func:`plot_plan` — that map with the explored atlas and the path (Fig. 6, top), and the
tension envelope ``f_0 ± v_ii`` of every cable along the path (Fig. 6, bottom); and
:func:`plan_section`, the demo's Robocrane query q1 → q2.

References
----------
.. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of Cable-Driven
   Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots, Mechanisms and
   Machine Science 12, Springer, 2013, §5, Figs. 5–6. (docs/references.bib: bohigas2013)
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from taut.errors import TautError
from taut.model import example
from taut.planning import POSE_NAMES, PathResult, WrenchFeasibleManifold, plan_path, verify_path
from taut.viz._style import DISALLOWED, INSIDE, cable_color, empty_figure

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from taut.viz.report import Report

__all__ = ["FEASIBLE", "FORCE_OUT", "LENGTH_OUT", "plan_section", "plot_plan", "slice_map"]

FEASIBLE, FORCE_OUT, LENGTH_OUT = 0, 1, 2  #: classes of :func:`slice_map`
_FORCE_COLOR = "#5b8fd9"


def _angle_limits(manifold: WrenchFeasibleManifold) -> dict[str, tuple[float, float]]:
    """The natural range of the angular coordinates of a slice: the window of ``φ``, ``θ ∈ [0, π]``."""
    lo, hi = (float(a) for a in manifold.phi_window)
    return {"phi": (lo, hi), "theta": (0.0, float(np.pi))}


def _check_axes(axes: Sequence[str]) -> list[int]:
    """Indices in :data:`POSE_NAMES` of two distinct pose coordinates."""
    if len(axes) != 2 or axes[0] == axes[1] or any(a not in POSE_NAMES for a in axes):
        raise ValueError(f"a slice map is over two distinct pose coordinates of {', '.join(POSE_NAMES)}, got {axes}")
    return [POSE_NAMES.index(a) for a in axes]


def slice_map(
    manifold: WrenchFeasibleManifold,
    pose: npt.ArrayLike,
    axes: Sequence[str] = ("phi", "theta"),
    limits: Sequence[tuple[float, float]] | None = None,
    resolution: tuple[int, int] = (90, 46),
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Classify a grid over two pose coordinates ``axes`` (the others from ``pose``):
    ``(u, v, classes)`` with ``classes[i, j]`` for ``(u[i], v[j])`` one of
    :data:`FEASIBLE`, :data:`FORCE_OUT` (some ``f_0,i ∓ v_ii`` outside the tension bounds, or
    ``J`` singular), :data:`LENGTH_OUT`.  Default limits: ``φ`` over the manifold's window,
    ``θ ∈ [0, π]``; a position coordinate has none (``ValueError`` without ``limits``)."""
    idx = _check_axes(axes)
    if limits is None:
        default = _angle_limits(manifold)
        missing = [a for a in axes if a not in default]
        if missing:
            raise ValueError(f"slice_map needs limits for {', '.join(missing)}: only phi and theta have default limits")
        limits = [default[a] for a in axes]
    if len(limits) != 2:
        raise ValueError(f"slice_map needs (low, high) limits for each of its two axes, got {len(limits)}")
    (u0, u1), (v0, v1) = limits
    u = np.linspace(float(u0), float(u1), resolution[0])
    v = np.linspace(float(v0), float(v1), resolution[1])
    q = np.array(pose, float)
    cls = np.empty((u.size, v.size), int)
    for i, a in enumerate(u):
        for j, b in enumerate(v):
            q[idx[0]], q[idx[1]] = a, b
            ext = manifold.extreme_tensions(q)
            if ext is None:
                cls[i, j] = FORCE_OUT
                continue
            _, _, rho, f0, V = ext
            d = np.diag(V)
            if not (np.all(rho > manifold.rho_min) and np.all(rho < manifold.rho_max)):
                cls[i, j] = LENGTH_OUT
            elif np.all(f0 - d > manifold.f_min) and np.all(f0 + d < manifold.f_max):
                cls[i, j] = FEASIBLE
            else:
                cls[i, j] = FORCE_OUT
    return u, v, cls


def _plan_limits(
    manifold: WrenchFeasibleManifold, centres: np.ndarray, axes: Sequence[str]
) -> list[tuple[float, float]]:
    """Limits of the map of :func:`plot_plan`: the natural range of ``φ`` and ``θ``, the span
    of the chart centres (padded by a tenth, at least 0.1) for any other coordinate."""
    angles = _angle_limits(manifold)
    out = []
    for a in axes:
        if a in angles:
            out.append(angles[a])
        else:
            c = centres[:, POSE_NAMES.index(a)]
            lo, hi = float(c.min()), float(c.max())
            pad = max(0.1 * (hi - lo), 0.1)
            out.append((lo - pad, hi + pad))
    return out


def plot_plan(
    manifold: WrenchFeasibleManifold,
    result: PathResult,
    axes: Sequence[str] = ("phi", "theta"),
    grid: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None,
    fig: Figure | None = None,
) -> Figure:
    """Figure: the slice map ``grid`` (from :func:`slice_map`, computed if ``None``: ``φ``
    and ``θ`` over their natural range, another coordinate over the span of the chart centres) with
    the atlas' chart centres (closed charts dark, open ones light) and the path in red
    (left), and the extreme tensions ``f_0 − v_ii`` (lower) and ``f_0 + v_ii`` (upper) of
    each cable along the path against its length, with the tension bounds dashed (right).
    Laid out on the empty figure ``fig`` (``None``: a new one; a figure that already has
    axes raises ``ValueError``), which is returned."""
    from matplotlib.colors import ListedColormap

    idx = _check_axes(axes)
    centres = manifold.pose(result.atlas.centres)
    if grid is None:
        grid = slice_map(manifold, centres[0], axes, _plan_limits(manifold, centres, axes))
    u, v, cls = grid
    fig = empty_figure(fig, "a planned path", (13.0, 5.5))
    ax, tx = fig.subplots(1, 2)
    cmap = ListedColormap([INSIDE, _FORCE_COLOR, DISALLOWED])
    ax.pcolormesh(u, v, cls.T, cmap=cmap, vmin=-0.5, vmax=2.5, shading="nearest", alpha=0.45, gid="slice-map")
    closed = np.array([c.expanded for c in result.atlas.charts])
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
            "no path: " + ("component exhausted" if result.exhausted else "search stopped"),
            ha="center",
            va="center",
            transform=tx.transAxes,
        )
    fig.tight_layout()
    return fig


def plan_section(report: Report, radius: float = 0.2) -> PathResult:
    """The Robocrane query q1 → q2 of experiment 1 (slice p = (0, 0, 2), σ = 35°): A* over
    the atlas, checked by the independent feasibility test, as Figs. 5–6.  Returns the
    :class:`~taut.planning.PathResult`."""
    robot = example("robocrane")
    if robot.reference is None:
        raise TautError(f"{robot.name} has no reference poses q1, q2 to plan between")
    q = {k: np.asarray(v, float) for k, v in robot.reference.poses.items()}
    fixed = dict(x=0.0, y=0.0, z=2.0, sigma=float(q["q1"][5]))
    M = WrenchFeasibleManifold.from_robot(robot, fixed=fixed)
    t0 = time.perf_counter()
    res = plan_path(M.implicit(), M.lift(q["q1"]), M.lift(q["q2"]), radius=radius, metric=M.pose_metric)
    elapsed = time.perf_counter() - t0
    check = verify_path(robot, M.pose(res.path), subdivide=5) if res.found else None
    fig = plot_plan(M, res)
    row = {
        "query": "q1 → q2",
        "found": res.found,
        "charts": res.charts,
        "closed": res.expanded,
        "path length [rad]": round(res.length, 3) if res.found else None,
        "time [s]": round(elapsed, 2),
        "paper [s]": 20.0,
        "independent check": None if check is None else check.all_feasible,
    }
    report.add_section(
        "Wrench-feasible path planning (Robocrane)",
        text=(
            "A path from q1 to q2 on the slice p = (0, 0, 2), σ = 35° of the Robocrane's "
            "wrench-feasible C-space (Bohigas et al. 2013, §5, Figs. 5–6): Henderson's "
            "atlas of Eqs. (1)–(8) expanded in A* order, every interpolated pose of the path "
            "then checked by the general wrench-feasibility test.\n\n"
            "The cable pairing is our reading of §5 (robocrane.yaml, reference.notes)."
        ),
        figures=[
            (
                fig,
                "plan-robocrane-q1-q2",
                "Left: the slice (green feasible, blue tension, red length out of range), the "
                "chart centres and the path. Right: extreme tensions f₀ ± v_ii along the path.",
            )
        ],
        table=[row],
    )
    return res
