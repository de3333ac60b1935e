"""``taut workspace ROBOT --condition C [--grid G]``: the workspace of a condition over a grid
of poses (:func:`taut.workspace.evaluate_workspace`), serial, in local processes or on a
dask cluster."""

from __future__ import annotations

import argparse

from taut.cli import _args as A
from taut.cli._output import console, emit, markup, save_figure, written
from taut.cli._progress import progress_bar, wanted
from taut.errors import TautError

SUMMARY = "workspace over a grid of poses"
ROBOT = True

#: Most poses of one ``workspace`` grid: beyond it the verdicts alone fill gigabytes.


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--condition", required=True, help="wrench-closure | wrench-feasible | static | interference-free"
    )
    parser.add_argument(
        "--grid",
        help="points per axis (e.g. 50), or per-axis ranges 'x0:x1:n;y0:y1:n[;z0:z1:n]' (one per pose coordinate for a full pose grid)",
    )
    parser.add_argument(
        "--box",
        metavar="HALF_WIDTHS",
        help="wrench-feasible: box of wrenches around the external wrench, one half-width per component (default: 10 %% of the weight)",
    )
    parser.add_argument("--orientation", help="fixed platform orientation (theta, or a,b,c) and joint coordinates")
    parser.add_argument(
        "--max-poses", type=A.count(1), metavar="N", help="budget of poses: a larger grid is refused (default 10000000)"
    )
    parser.add_argument("--out", metavar="FILE.npz", help="save poses and verdicts")
    parser.add_argument("--plot", metavar="FILE.png", help="plot the workspace")
    A.add_parallel(parser, workers=None)


def _grid(text: str | None, dimension: int) -> tuple[list[tuple[float, float, int]] | None, int | None]:
    """``--grid N`` (points per axis) or ``lo:hi:n;lo:hi:n[;...]`` (one range per axis), with
    at least one point per axis and at most :data:`MAX_GRID_POSES` poses in all."""
    import numpy as np

    from taut.workspace import MAX_GRID_POSES

    if text is None:
        return None, None
    if text.strip().isdigit():
        # more than 10 digits is more than MAX_GRID_POSES on one axis (and Python refuses
        # to convert thousands of digits)
        n = int(text) if len(text.strip()) <= 10 else MAX_GRID_POSES + 1
        count = n**dimension
        axes = None
    else:
        axes = []
        for part in text.split(";"):
            lo, hi, k = (part.split(":") + [None, None])[:3]
            if lo is None or hi is None or k is None or not k.strip().isdigit() or len(k.strip()) > 9:
                raise TautError(f"--grid: expected N or lo:hi:n;lo:hi:n[;...], got {text!r}")
            axes.append((A.number(lo, "--grid"), A.number(hi, "--grid"), int(k)))
        n = min(k for _, _, k in axes)
        count = int(np.prod([float(k) for _, _, k in axes]))
    if n < 1:
        raise TautError(f"--grid: every axis needs at least one point, got {text!r}")
    if count > MAX_GRID_POSES:
        raise TautError(f"--grid: {text!r} makes {float(count):.3g} poses, more than {MAX_GRID_POSES:,}")
    return axes, None if axes is not None else n


def run(ns: argparse.Namespace) -> int:
    import numpy as np

    from taut.parallel import get_executor
    from taut.statics import BoxWrenchSet
    from taut.workspace import evaluate_workspace

    out = A.output_file(ns.out, "--out", {".npz"})
    plot = A.plot_file(ns.plot)
    robot = A.load(ns.robot, ns.cable_set)
    grid, resolution = _grid(ns.grid, robot.dimension)
    orientation = A.vector(ns.orientation, "--orientation") if ns.orientation is not None else None
    wrench_set = None
    if ns.box is not None:
        if ns.condition != "wrench-feasible":
            raise TautError("--box sets the wrench set of --condition wrench-feasible")
        half = A.vector(ns.box, "--box")
        if half.size != robot.wrench_dim:
            raise TautError(f"--box: {robot.name} takes {robot.wrench_dim} half-widths, got {half.size}")
        if np.any(half < 0):
            raise TautError(f"--box: half-widths must be >= 0, got {ns.box!r}")
        wrench_set = BoxWrenchSet.around(np.zeros(robot.wrench_dim), half)
    with (
        get_executor(workers=ns.workers, scheduler=ns.scheduler) as executor,
        progress_bar("workspace", wanted(ns.json)) as progress,
    ):
        res = evaluate_workspace(
            robot,
            ns.condition,
            grid=grid,
            resolution=resolution,
            orientation=orientation,
            wrench_set=wrench_set,
            executor=executor,
            progress=progress,
            **({} if ns.max_poses is None else {"max_poses": ns.max_poses}),
        )
    data = res.as_dict()
    if out is not None:
        with written(out, "--out") as tmp:
            res.save(tmp)
        data["out"] = str(out)
    if plot is not None:
        from taut.viz import plot_workspace

        save_figure(plot_workspace(res, robot).figure, plot, data)

    def human(d: dict) -> None:
        console().print(
            f"{markup(robot.name)}: {d['condition']} workspace: {d['inside']} of {d['poses']} poses inside "
            f"({100 * d['fraction']:.1f} %), {d['elapsed_s']:.3f} s"
        )
        if d["wrapped"]:
            console().print(
                f"{d['wrapped']} poses left outside: a straight cable meets an obstacle there "
                "(it wraps around it; taut atlas models the wrapping)"
            )

    emit(data, ns.json, human)
    return 0
