"""``taut workspace ROBOT --condition C [--grid G]``: the workspace of a condition over a grid
of poses (:func:`taut.workspace.evaluate_workspace`), or with ``--certified`` covered by boxes
proven inside, proven outside and undecided (:func:`taut.workspace.certified`); serial, in
local processes or on a dask cluster."""

from __future__ import annotations

import argparse
import json
from typing import TYPE_CHECKING, Any

from taut.cli import _args as A
from taut.cli._output import console, emit, markup, save_figure, written
from taut.cli._progress import progress_bar, wanted
from taut.errors import TautError

if TYPE_CHECKING:
    from taut.model import Robot
    from taut.statics import BoxWrenchSet

SUMMARY = "workspace over a grid of poses, or certified by interval analysis"
ROBOT = True


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--condition",
        required=True,
        help="wrench-closure | wrench-feasible | static | sagging-static | interference-free",
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
    parser.add_argument(
        "--certified",
        action="store_true",
        help="cover the region with boxes proven inside, proven outside and undecided (interval analysis)",
    )
    parser.add_argument(
        "--eps", type=A.real(above=0), metavar="M", help="--certified: smallest box width [m] (default 0.01)"
    )
    parser.add_argument(
        "--region", metavar="RANGES", help="--certified: 'x0:x1;y0:y1[;z0:z1]' (default: the box of the exit points)"
    )
    parser.add_argument(
        "--orientation-box",
        metavar="RANGES",
        help="--certified: angle ranges 'a0:a1[;b0:b1;c0:c1]': inner boxes hold for every orientation in them",
    )
    parser.add_argument(
        "--orientation-step",
        type=A.real(above=0),
        metavar="RAD",
        help="--certified: widest piece the orientation box is cut into (default 0.05)",
    )
    parser.add_argument(
        "--max-boxes", type=A.count(1), metavar="N", help="--certified: budget of boxes (default 2000000)"
    )
    parser.add_argument(
        "--out",
        metavar="FILE.npz|FILE.json",
        help="save poses and verdicts (.npz); with --certified the boxes (.json, as --json with inner_boxes, "
        "outer_boxes, undecided_boxes); taut view --workspace draws either",
    )
    parser.add_argument("--plot", metavar="FILE.png", help="plot the workspace")
    A.add_parallel(parser, workers=None)


def _ranges(text: str, what: str) -> list[list[float]]:
    """``lo:hi;lo:hi[;...]`` as ``[[lo, hi], ...]``."""
    out = []
    for part in text.split(";"):
        ends = part.split(":")
        if len(ends) != 2:
            raise TautError(f"{what}: expected lo:hi;lo:hi[;...], got {text!r}")
        out.append([A.number(ends[0], what), A.number(ends[1], what)])
    return out


def _certified(ns: argparse.Namespace) -> int:
    from taut.parallel import get_executor
    from taut.workspace import certified

    if ns.grid is not None or ns.max_poses is not None:
        raise TautError("--certified takes --region, --eps and --max-boxes; --grid and --max-poses are for grids")
    out = A.output_file(ns.out, "--out", {".json"})
    plot = A.plot_file(ns.plot)
    robot = A.load(ns.robot, ns.cable_set)
    A.straight_cables(robot, "the certified workspace")
    options: dict[str, Any] = {}
    if ns.box is not None:
        options["wrench_set"] = _box_set(robot, ns.box, ns.condition)
    with (
        get_executor(workers=ns.workers, scheduler=ns.scheduler) as executor,
        progress_bar("certified workspace", wanted(ns.json)) as progress,
    ):
        res = certified(
            robot,
            ns.condition,
            None if ns.region is None else _ranges(ns.region, "--region"),
            orientation=None if ns.orientation is None else A.vector(ns.orientation, "--orientation"),
            orientation_box=None if ns.orientation_box is None else _ranges(ns.orientation_box, "--orientation-box"),
            executor=executor,
            progress=progress,
            **({} if ns.eps is None else {"eps": ns.eps}),
            **({} if ns.orientation_step is None else {"orientation_step": ns.orientation_step}),
            **({} if ns.max_boxes is None else {"max_boxes": ns.max_boxes}),
            **options,
        )
    data = res.as_dict()
    if out is not None:
        with written(out, "--out") as tmp:
            tmp.write_text(json.dumps(res.as_dict(boxes=True), allow_nan=False), encoding="utf-8")
        data["out"] = str(out)
    if plot is not None:
        from taut.viz import plot_certified

        save_figure(plot_certified(res, robot).figure, plot, data)

    def human(d: dict) -> None:
        unit = "m²" if len(d["axis_names"]) == 2 else "m³"
        b = d["boxes"]
        console().print(
            f"{markup(robot.name)}: {d['condition']} workspace, certified to {d['eps']:g} m: "
            f"{d['inner_volume']:.4g} {unit} proven inside, {d['undecided_volume']:.4g} {unit} undecided, "
            f"{d['outer_volume']:.4g} {unit} proven outside of {d['region_volume']:.4g} {unit} "
            f"({b['inner']} + {b['undecided']} + {b['outer']} boxes), {d['elapsed_s']:.3f} s"
        )
        if not d["complete"]:
            console().print(f"the budget of {d['evaluated']} boxes ran out: raise --max-boxes or --eps")

    emit(data, ns.json, human)
    return 0


def _box_set(robot: Robot, text: str, condition: str) -> BoxWrenchSet:
    """``--box``: the wrench set of ``wrench-feasible``, one half-width per wrench component."""
    import numpy as np

    from taut.statics import BoxWrenchSet

    if condition != "wrench-feasible":
        raise TautError("--box sets the wrench set of --condition wrench-feasible")
    half = A.vector(text, "--box")
    m = robot.wrench_dim
    if half.size != m:
        raise TautError(f"--box: {robot.name} takes {m} half-widths, got {half.size}")
    if np.any(half < 0):
        raise TautError(f"--box: half-widths must be >= 0, got {text!r}")
    return BoxWrenchSet.around(np.zeros(m), half)


def run(ns: argparse.Namespace) -> int:

    from taut.parallel import get_executor
    from taut.workspace import evaluate_workspace

    if ns.certified:
        return _certified(ns)
    if any(x is not None for x in (ns.eps, ns.region, ns.orientation_box, ns.orientation_step, ns.max_boxes)):
        raise TautError("--eps, --region, --orientation-box, --orientation-step and --max-boxes go with --certified")
    out = A.output_file(ns.out, "--out", {".npz"})
    plot = A.plot_file(ns.plot)
    robot = A.load(ns.robot, ns.cable_set)
    if ns.condition != "sagging-static":
        A.straight_cables(robot, f"the {ns.condition} condition", "--condition sagging-static includes their weight")
    grid, resolution = A.grid(ns.grid, robot.dimension)
    orientation = A.vector(ns.orientation, "--orientation") if ns.orientation is not None else None
    wrench_set = None if ns.box is None else _box_set(robot, ns.box, ns.condition)
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
