"""``taut COMMAND ROBOT [options]`` (``docs/architecture.md`` §4).

Exit status: 0 success, 2 bad input (any :class:`taut.TautError`, or bad options),
1 internal error.  ``--json`` prints the machine-readable result on stdout; the
fields named in the issues are a contract.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path
from typing import TYPE_CHECKING, NoReturn

from taut.cli import args as A
from taut.cli.progress import progress_bar, wanted
from taut.errors import TautError

if TYPE_CHECKING:
    from types import ModuleType

    from matplotlib.figure import FigureBase
    from rich.console import Console
    from rich.table import Table

    from taut.model.robot import Robot

#: ``command(name, help, fn, robot=True)``: adds a sub-command (see :func:`build_parser`).
Command = Callable[..., argparse.ArgumentParser]

#: Most poses of one ``workspace`` grid: beyond it the verdicts alone fill gigabytes.
MAX_GRID_POSES = 10**9


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> NoReturn:
        self.print_usage(sys.stderr)
        print(f"taut: error: {message}", file=sys.stderr)
        raise SystemExit(2)


def load(spec: str, cable_set: str | None = None) -> Robot:
    """The robot of a command: a file in any format :mod:`taut.model.formats` reads, or a
    built-in example; ``cable_set`` is the ``--cable-set`` of a CASPR model."""
    from taut.model import load_robot

    return load_robot(spec, cable_set=cable_set)


def emit(data: dict, as_json: bool, human: Callable[[dict], None]) -> None:
    """The result: one JSON document on stdout, or the human form.  Called last, after every
    file of the command is written, so that a failure never follows printed output."""
    if as_json:
        print(json.dumps(data, indent=2, allow_nan=False))
    else:
        human(data)


def save_figure(fig: FigureBase, path: str | Path, data: dict | None = None) -> None:
    """Write the figure of a ``--plot`` option (the whole figure a subfigure or an Axes'
    ``.figure`` belongs to) and close it; record the path in ``data``."""
    import matplotlib.pyplot as plt
    from matplotlib.figure import Figure

    root = fig if isinstance(fig, Figure) else fig.get_figure(root=True)
    assert root is not None, "every figure belongs to a root figure"
    root.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(root)
    if data is not None:
        data["plot"] = str(path)


def console() -> Console:
    from rich.console import Console

    return Console()


def _matrix_table(title: str, rows: Sequence[Sequence[str]], header: Sequence[str]) -> Table:
    from rich.table import Table

    t = Table(title=title)
    for h in header:
        t.add_column(h, justify="right")
    for r in rows:
        t.add_row(*r)
    return t


def _fmt(x: float) -> str:
    return f"{x:.6g}"


# ---- commands --------------------------------------------------------------------


def cmd_examples(ns: argparse.Namespace) -> int:
    from taut.model import example_descriptions

    desc = example_descriptions()
    if ns.json:
        print(json.dumps({"examples": [{"name": k, "description": v} for k, v in desc.items()]}, indent=2))
    else:
        width = max(map(len, desc))
        for k, v in desc.items():
            print(f"{k:<{width}}  {v}")
    return 0


def cmd_schema(ns: argparse.Namespace) -> int:
    from taut.model.schema import schema_text

    sys.stdout.write(schema_text())
    return 0


def cmd_ik(ns: argparse.Namespace) -> int:
    from taut.kinematics import inverse_kinematics

    plot = A.plot_file(ns.plot)
    robot = load(ns.robot, ns.cable_set)
    pose = A.pose(robot, ns.pose) if ns.pose is not None else A.default_pose(robot)
    ik = inverse_kinematics(robot, pose)
    data = {
        "robot": robot.name,
        "pose": pose.tolist(),
        "lengths": ik.lengths.tolist(),
        "directions": ik.directions.tolist(),
        "anchors": ik.anchors.tolist(),
        "structure_matrix": ik.structure_matrix.tolist(),
    }

    def human(d: dict) -> None:
        con = console()
        con.print(
            f"[bold]{robot.name}[/] at pose {', '.join(f'{n}={_fmt(v)}' for n, v in zip(robot.pose_names, pose))}"
        )
        dims = "xyz"[: robot.dimension]
        rows = [
            [str(i + 1), _fmt(length), *(_fmt(c) for c in u)]
            for i, (length, u) in enumerate(zip(ik.lengths, ik.directions))
        ]
        con.print(_matrix_table("cables", rows, ["cable", "length [m]", *(f"u_{c}" for c in dims)]))
        W = ik.structure_matrix
        rows = [[f"{x:.4g}" for x in row] for row in W]
        con.print(_matrix_table("structure matrix W", rows, [str(i + 1) for i in range(W.shape[1])]))

    if plot is not None:
        from taut.viz import draw_robot

        save_figure(draw_robot(robot, pose).figure, plot, data)
    emit(data, ns.json, human)
    return 0


def cmd_tensions(ns: argparse.Namespace) -> int:
    from taut.statics.tension import distribute_tensions

    robot = load(ns.robot, ns.cable_set)
    pose = A.pose(robot, ns.pose) if ns.pose is not None else A.default_pose(robot)
    wrench = None
    if ns.wrench is not None:
        wrench = A.vector(ns.wrench, "--wrench")
        if wrench.size != robot.wrench_dim:
            raise TautError(
                f"--wrench: {robot.name} takes a wrench of {robot.wrench_dim} components, got {wrench.size}"
            )
    res = distribute_tensions(robot, pose, wrench=wrench, method=ns.method)
    feasible = bool(res.feasible)
    data = {
        "robot": robot.name,
        "pose": pose.tolist(),
        "tensions": res.tensions.tolist() if feasible else None,
        "feasible": feasible,
        "status": str(res.status),
        "method": res.method,
    }

    def human(d: dict) -> None:
        con = console()
        if not feasible:
            why = (
                "no tension distribution exists"
                if d["status"] == "infeasible"
                else f"method {ns.method} found no solution"
            )
            con.print(f"[bold red]infeasible[/]: {why} at this pose within the tension bounds")
            return
        rows = [[str(i + 1), _fmt(t)] for i, t in enumerate(res.tensions)]
        con.print(_matrix_table(f"tensions ({res.method})", rows, ["cable", "tension [N]"]))

    emit(data, ns.json, human)
    return 0


def _grid(text: str | None, dimension: int) -> tuple[list[tuple[float, float, int]] | None, int | None]:
    """``--grid N`` (points per axis) or ``lo:hi:n;lo:hi:n[;...]`` (one range per axis), with
    at least one point per axis and at most :data:`MAX_GRID_POSES` poses in all."""
    import numpy as np

    if text is None:
        return None, None
    if text.strip().isdigit():
        n = int(text)
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
        raise TautError(f"--grid: {text!r} makes {float(count):.3g} poses, more than {MAX_GRID_POSES:.0e}")
    return axes, None if axes is not None else n


def cmd_workspace(ns: argparse.Namespace) -> int:
    import numpy as np

    from taut.parallel import get_executor
    from taut.statics.wrench import BoxWrenchSet
    from taut.workspace import evaluate_workspace

    out = A.output_file(ns.out, "--out", {".npz"})
    plot = A.plot_file(ns.plot)
    robot = load(ns.robot, ns.cable_set)
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
    data = {"robot": robot.name, "condition": ns.condition} | res.summary()
    if out is not None:
        res.save(out)
        data["out"] = str(out)
    if plot is not None:
        from taut.viz import plot_workspace

        save_figure(plot_workspace(res, robot).figure, plot, data)

    def human(d: dict) -> None:
        console().print(
            f"{robot.name}: {d['condition']} workspace: {d['inside']} of {d['poses']} poses inside "
            f"({100 * d['fraction']:.1f} %), {d['elapsed_s']:.3f} s"
        )

    emit(data, ns.json, human)
    return 0


def cmd_demo(ns: argparse.Namespace) -> int:
    from taut.demo import run_demo

    out = Path(ns.out)
    if out.exists() and not out.is_dir():
        raise TautError(f"--out: {ns.out!r} is a file; give a directory for the report")
    if not out.parent.is_dir():
        raise TautError(f"--out: the directory {str(out.parent)!r} does not exist")
    path = run_demo(out)
    if ns.json:
        print(json.dumps({"report": str(path)}))
    else:
        print(f"report written to {path}")
    return 0


# ---- parser ----------------------------------------------------------------------


def build_parser() -> argparse.ArgumentParser:
    p = _Parser(prog="taut", description="Cable-driven parallel robots: kinematics, statics, workspaces.")
    sub = p.add_subparsers(dest="command", required=True, parser_class=_Parser)

    def command(
        name: str, help: str, fn: Callable[[argparse.Namespace], int], robot: bool = True
    ) -> argparse.ArgumentParser:
        c = sub.add_parser(name, help=help, description=help)
        if robot:
            c.add_argument(
                "robot",
                help="robot file (taut YAML/JSON, or a CASPR X_bodies.xml with its X_cables.xml beside it) "
                "or built-in example name (see `taut examples`)",
            )
            c.add_argument(
                "--cable-set",
                metavar="ID",
                help="CASPR model: the cable set to use (default: the file's default_cable_set)",
            )
        c.add_argument("--json", action="store_true", help="machine-readable result on stdout")
        c.set_defaults(fn=fn)
        return c

    command("examples", "list the built-in example robots", cmd_examples, robot=False)
    command("schema", "print the JSON Schema of the robot file format", cmd_schema, robot=False)

    pose_help = "pose x,y | x,y,theta | x,y,z,a,b,c then joint coordinates (angles in rad, or 30deg, pi/8); write --pose=-1,... for a leading minus"
    c = command("ik", "inverse kinematics: cable lengths, directions, structure matrix", cmd_ik)
    c.add_argument("--pose", help=pose_help)
    c.add_argument("--plot", metavar="FILE.png", help="draw the robot at the pose")

    c = command("tensions", "tension distribution at a pose", cmd_tensions)
    c.add_argument("--pose", help=pose_help)
    c.add_argument("--wrench", help="external wrench (default: the robot's own, weight included)")
    c.add_argument("--method", default="lp", help="lp | qp | inf | closed-form | improved-closed-form | barycentric")

    c = command("workspace", "workspace over a grid of poses", cmd_workspace)
    c.add_argument("--condition", required=True, help="wrench-closure | wrench-feasible | static | interference-free")
    c.add_argument(
        "--grid",
        help="points per axis (e.g. 50), or per-axis ranges 'x0:x1:n;y0:y1:n[;z0:z1:n]' (one per pose coordinate for a full pose grid)",
    )
    c.add_argument(
        "--box",
        metavar="HALF_WIDTHS",
        help="wrench-feasible: box of wrenches around the external wrench, one half-width per component (default: 10 %% of the weight)",
    )
    c.add_argument("--orientation", help="fixed platform orientation (theta, or a,b,c) and joint coordinates")
    c.add_argument(
        "--max-poses", type=int, metavar="N", help="budget of poses: a larger grid is refused (default 10000000)"
    )
    c.add_argument("--out", metavar="FILE.npz", help="save poses and verdicts")
    c.add_argument("--plot", metavar="FILE.png", help="plot the workspace")
    c.add_argument("--workers", type=A.worker_count, default=None, help="local worker processes")
    c.add_argument("--scheduler", metavar="ADDRESS", help="dask.distributed scheduler, e.g. tcp://host:8786")

    c = command("demo", "run taut on the built-in robots and write an HTML report", cmd_demo, robot=False)
    c.add_argument("--out", default="report", help="report directory (default: report)")
    for module in _command_modules():
        module.register(command)
    return p


def _command_modules() -> Iterator[ModuleType]:
    """The modules of ``taut.cli`` that add commands: each defines ``register(command)``,
    where ``command(name, help, fn, robot=True)`` returns a subparser with ROBOT and
    ``--json`` already added."""
    import importlib
    import pkgutil

    import taut.cli

    for info in sorted(pkgutil.iter_modules(taut.cli.__path__), key=lambda i: i.name):
        if info.name not in ("main", "args"):
            module = importlib.import_module(f"taut.cli.{info.name}")
            if hasattr(module, "register"):
                yield module


@contextmanager
def _quiet_warnings() -> Iterator[None]:
    """Library warnings (numba's, dask's, numpy's) are not messages for a user of the
    command line: input that would cause them is refused with an error, and what is left is
    noise on stderr.  Logging of third-party libraries is kept to errors, on stderr."""
    import logging
    import warnings

    logging.basicConfig(level=logging.ERROR, stream=sys.stderr)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        yield


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    ns = parser.parse_args(argv)
    for name, value in vars(ns).items():
        # argparse turns ``--opt=--`` into an empty list; every option here takes one value
        if isinstance(value, list):
            parser.error(f"argument --{name.replace('_', '-')}: expected one value, got '--'")
    try:
        with _quiet_warnings():
            code: int = ns.fn(ns)
        return code
    except TautError as exc:
        print(f"taut: error: {exc}", file=sys.stderr)
        return 2
    except (MemoryError, RecursionError) as exc:
        # input large or deep enough to exhaust the process: bad input, not a bug to report
        print(f"taut: error: the input is too large to process ({type(exc).__name__})", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("taut: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        # the reader (e.g. `| head`) has gone: stop quietly, as Unix tools do
        sys.stderr.close()
        return 0
    except Exception as exc:  # noqa: BLE001 — the CLI reports, it does not dump tracebacks
        print(f"taut: internal error: {type(exc).__name__}: {exc} (please report it)", file=sys.stderr)
        return 1


def entry() -> None:
    raise SystemExit(main())
