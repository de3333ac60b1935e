"""``taut view ROBOT [--pose P | --solutions FILE.json | --trajectory FILE.csv | --workspace FILE
| --plan FILE.csv] --out FILE.html``: an interactive 3-D view (:mod:`taut.viz.interactive`) in
one HTML file that opens offline, drawn from the files the other commands write."""

from __future__ import annotations

import argparse
import csv
import json
from pathlib import Path
from typing import TYPE_CHECKING, Any

from taut.cli import _args as A
from taut.cli._output import console, emit, markup, written
from taut.errors import TautError

if TYPE_CHECKING:
    import numpy as np
    from plotly.graph_objects import Figure

    from taut.model import Robot

SUMMARY = "interactive 3-D view of a robot, its equilibria, a trajectory, a workspace or a plan, as one HTML file"
ROBOT = True

DESCRIPTION = """An interactive 3-D view (rotate, zoom, hover) written as one HTML file that opens offline:
plotly.js is embedded in it (--plotlyjs embed, the default) or written once beside it as
plotly.min.js (--plotlyjs beside); no file is fetched from the network.  Needs the extra
taut[view] (plotly).  What is drawn:

  --pose P               the robot at a pose (default: its home pose), cables coloured by the
                         tensions that balance its load (taut tensions), when it has one;
  --solutions FILE.json  the equilibria of `taut fk --json` (or `taut igp --json`), one at a time,
                         chosen in a selector;
  --trajectory FILE.csv  a motion with a time slider and a play button, the cable lengths and
                         tensions below: the CSV of `taut trajectory --out` (a wrapping robot's cables
                         drawn along their wrapped paths), or of `taut simulate --out` (the reference
                         and the simulated robot side by side, the tension margin below);
  --workspace FILE       a workspace as a layer: `taut workspace --out FILE.npz` (the poses inside),
                         or `taut workspace --certified --out FILE.json` (the boxes);
  --plan FILE.csv        a planned path (`taut plan --out`), its steps on the slider."""

#: The sources a view is drawn from (at most one).
SOURCES = ("solutions", "trajectory", "workspace", "plan")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--pose", help=A.POSE_HELP + " (default: the robot's home pose)")
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--solutions", metavar="FILE.json", help="equilibria: the JSON of taut fk --json or igp --json")
    group.add_argument("--trajectory", metavar="FILE.csv", help="the CSV of taut trajectory --out or simulate --out")
    group.add_argument(
        "--workspace", metavar="FILE", help="taut workspace --out FILE.npz, or --certified --out FILE.json"
    )
    group.add_argument("--plan", metavar="FILE.csv", help="the CSV of taut plan --out")
    parser.add_argument("--out", required=True, metavar="FILE.html", help="the HTML file to write")
    parser.add_argument(
        "--plotlyjs",
        choices=("embed", "beside"),
        default="embed",
        help="plotly.js inside the file (embed, default) or written once beside it as plotly.min.js (beside)",
    )
    parser.add_argument(
        "--frames", type=A.count(1, 5000), default=200, help="most animation frames of a motion (default 200)"
    )


def _read_text(path_text: str, what: str) -> str:
    path = Path(path_text)
    if not path.is_file():
        raise TautError(f"{what}: no such file {path_text!r}")
    if path.stat().st_size > 256 << 20:
        raise TautError(f"{what} {path_text}: larger than 256 MiB")
    try:
        return path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise TautError(f"{what} {path_text}: cannot read the file: {exc}") from None


def _columns(path_text: str, what: str) -> dict[str, list[str]]:
    """The columns of a CSV file by their header's names (every row as long as the header)."""
    rows = list(csv.reader(_read_text(path_text, what).splitlines()))
    if len(rows) < 2:
        raise TautError(f"{what} {path_text}: expected a header line and at least one row")
    head = [h.strip() for h in rows[0]]
    for k, row in enumerate(rows[1:], start=2):
        if len(row) != len(head):
            raise TautError(f"{what} {path_text}: line {k} has {len(row)} fields, the header {len(head)}")
    return {h: [r[j] for r in rows[1:]] for j, h in enumerate(head)}


def _numbers(cols: dict[str, list[str]], names: list[str], path_text: str, what: str) -> np.ndarray:
    """The named columns as a float array ``(rows, len(names))``; a missing column or a field
    that is not a finite number is an error naming the file."""
    import numpy as np

    missing = [n for n in names if n not in cols]
    if missing:
        raise TautError(f"{what} {path_text}: no column {missing[0]!r} (expected {', '.join(names)})")
    try:
        a = np.array([[float(x) for x in cols[n]] for n in names], float).T
    except ValueError as exc:
        raise TautError(f"{what} {path_text}: {exc}") from None
    if not np.isfinite(a).all():
        raise TautError(f"{what} {path_text}: every value must be a finite number")
    return a


def _solutions(robot: Robot, path_text: str) -> Figure:
    import numpy as np

    from taut.dgp import DGPSolution
    from taut.viz.interactive import view_equilibria

    try:
        data = json.loads(_read_text(path_text, "--solutions"))
    except json.JSONDecodeError as exc:
        raise TautError(f"--solutions {path_text}: not JSON ({exc.msg}, line {exc.lineno})") from None
    if not isinstance(data, dict) or not isinstance(data.get("solutions"), list):
        raise TautError(f"--solutions {path_text}: expected the JSON of taut fk --json or taut igp --json")
    if data.get("robot") != robot.name:
        raise TautError(f"--solutions {path_text}: the solutions are of {data.get('robot')!r}, not of {robot.name!r}")
    n, d = robot.n_cables, robot.dimension
    sols = []
    for k, s in enumerate(data["solutions"], start=1):
        try:
            position = np.asarray(s["position"], float)
            orientation = np.asarray(s.get("orientation") or [], float)
            tensions = np.asarray(s["tensions"], float)
            taut = tuple(int(i) - 1 for i in s["taut"])
            stable = bool(s.get("stable", False))
        except (KeyError, TypeError, ValueError):
            raise TautError(
                f"--solutions {path_text}: solution {k} lacks its position, tensions or taut cables"
            ) from None
        if position.size != d or position.size + orientation.size != robot.pose_size or tensions.size != n:
            raise TautError(
                f"--solutions {path_text}: solution {k} does not fit {robot.name} "
                f"({robot.pose_size} pose coordinates, {n} cables)"
            )
        if not all(0 <= i < n for i in taut):
            raise TautError(f"--solutions {path_text}: solution {k} names cables beyond 1..{n}")
        sols.append(
            DGPSolution(
                taut=taut,
                position=position,
                orientation=orientation,
                tensions=tensions,
                stable=stable,
                certificate_width=float(s.get("certificate_width") or 0.0),
                uniqueness_radius=float(s.get("uniqueness_radius") or 0.0),
            )
        )
    return view_equilibria(robot, sols)


def _trajectory(robot: Robot, path_text: str, frames: int) -> Figure:
    from taut.viz.interactive import view_control, view_motion, view_trajectory

    cols = _columns(path_text, "--trajectory")
    n, names = robot.n_cables, list(robot.pose_names)
    taus = [f"tau{i + 1}" for i in range(n)]
    if "time" in cols and any(c.startswith("ref_") for c in cols):  # taut simulate --out
        a = _numbers(cols, ["time", *names, *(f"ref_{p}" for p in names), *taus], path_text, "--trajectory")
        m = len(names)
        return view_control(robot, a[:, 0], a[:, 1 : 1 + m], a[:, 1 + m : 1 + 2 * m], a[:, 1 + 2 * m :], frames=frames)
    lengths = [f"l{i + 1}" for i in range(n)]
    if "time" not in cols or not set(lengths) <= set(cols):
        raise TautError(
            f"--trajectory {path_text}: expected the columns of taut trajectory --out (time, {', '.join(names)}, "
            f"l1..l{n}, tau1..tau{n}) or of taut simulate --out (time, {', '.join(names)}, ref_..., tau1..tau{n}); "
            f"got {', '.join(list(cols)[:8])}{', ...' if len(cols) > 8 else ''}"
        )
    if f"l{n + 1}" in cols:
        raise TautError(
            f"--trajectory {path_text}: the file has the lengths of more cables than the {n} of {robot.name}"
        )
    a = _numbers(cols, ["time", *names, *lengths, *taus], path_text, "--trajectory")
    m = len(names)
    t, P, L, T = a[:, 0], a[:, 1 : 1 + m], a[:, 1 + m : 1 + m + n], a[:, 1 + m + n :]
    if robot.obstacles:
        import numpy as np

        from taut.wrapping import run_trajectory

        # the cables' wrapped paths are not in the file: the trajectory is run again, and
        # must give the file's lengths
        res = run_trajectory(robot, t, P)
        if not np.allclose(res.lengths, L, atol=1e-6, rtol=1e-6):
            raise TautError(f"--trajectory {path_text}: the lengths in the file are not {robot.name}'s along its poses")
        return view_trajectory(robot, res, frames=frames)
    return view_motion(robot, t, P, lengths=L, tensions=T, frames=frames)


def _plan(robot: Robot, path_text: str, frames: int) -> Figure:
    import numpy as np

    from taut.viz.interactive import view_motion

    cols = _columns(path_text, "--plan")
    names = list(robot.pose_names)
    if "f_min_1" in cols:  # a path on the wrench-feasible manifold: the ellipsoid's extreme tensions
        k = robot.n_cables
        a = _numbers(
            cols,
            [*names, *(f"f_min_{i + 1}" for i in range(k)), *(f"f_max_{i + 1}" for i in range(k))],
            path_text,
            "--plan",
        )
        m = len(names)
        centre = (a[:, m : m + k] + a[:, m + k :]) / 2
        steps = np.arange(len(a), dtype=float)
        return view_motion(
            robot, steps, a[:, :m], tensions=centre, frames=frames, time_label="path step", tension_label="f₀ [N]"
        )
    lengths = [f"length_{i + 1}" for i in range(robot.n_cables)]
    if not set(lengths) <= set(cols):
        raise TautError(
            f"--plan {path_text}: expected the columns of taut plan --out ({', '.join(names)}, then length_1.. "
            f"or f_min_1.., f_max_1..); got {', '.join(list(cols)[:8])}"
        )
    a = _numbers(cols, [*names, *lengths], path_text, "--plan")
    m = len(names)
    return view_motion(
        robot, np.arange(len(a), dtype=float), a[:, :m], lengths=a[:, m:], frames=frames, time_label="path step"
    )


def _workspace(robot: Robot, path_text: str, pose: np.ndarray | None) -> Figure:
    import numpy as np

    from taut.viz.interactive import view_workspace
    from taut.workspace import CertifiedWorkspace, WorkspaceResult

    path = Path(path_text)
    if not path.is_file():
        raise TautError(f"--workspace: no such file {path_text!r}")
    result: WorkspaceResult | CertifiedWorkspace
    if path.suffix.lower() == ".npz":
        result = WorkspaceResult.load(path)
    elif path.suffix.lower() == ".json":
        try:
            d: dict[str, Any] = json.loads(_read_text(path_text, "--workspace"))
            k = len(d["axis_names"])

            def boxes(key: str) -> np.ndarray:
                return np.asarray(d[key], float).reshape(-1, k, 2)

            result = CertifiedWorkspace(
                robot_name=str(d["robot"]),
                condition=str(d["condition"]),
                axis_names=tuple(d["axis_names"]),
                region=np.asarray(d["region"], float),
                orientation=np.asarray(d["orientation"], float),
                orientation_box=None if d["orientation_box"] is None else np.asarray(d["orientation_box"], float),
                eps=float(d["eps"]),
                inner=boxes("inner_boxes"),
                outer=boxes("outer_boxes"),
                undecided=boxes("undecided_boxes"),
                complete=bool(d["complete"]),
                evaluated=int(d["evaluated"]),
                elapsed_s=float(d["elapsed_s"]),
            )
        except (json.JSONDecodeError, KeyError, TypeError, ValueError):
            raise TautError(
                f"--workspace {path_text}: expected the boxes of taut workspace --certified --out FILE.json"
            ) from None
    else:
        raise TautError(f"--workspace {path_text}: expected a .npz (taut workspace --out) or .json (--certified --out)")
    if result.robot_name != robot.name:
        raise TautError(f"--workspace {path_text}: the workspace is of {result.robot_name!r}, not of {robot.name!r}")
    return view_workspace(robot, result, pose)


def _tensions(robot: Robot, pose: np.ndarray) -> np.ndarray | None:
    """The tensions that balance the robot's own load at ``pose`` (``taut tensions``); None where
    none do, or where all are zero (a robot without a load)."""
    import numpy as np

    from taut.statics import distribute_tensions

    res = distribute_tensions(robot, pose)
    tensions = np.asarray(res.tensions, float)
    return tensions if bool(res.feasible) and np.abs(tensions).max() > 0 else None


def run(ns: argparse.Namespace) -> int:
    from taut.viz.interactive import PLOTLY_JS, view_robot, write_html

    out = A.output_file(ns.out, "--out", {".html", ".htm"})
    robot = A.load(ns.robot, ns.cable_set)
    A.straight_cables(robot, "the view")
    pose = A.pose(robot, ns.pose) if ns.pose is not None else None
    kind = next((s for s in SOURCES if getattr(ns, s) is not None), "robot")
    if pose is not None and kind not in ("robot", "workspace"):
        raise TautError(f"--pose goes with a view of the robot or of a workspace, not with --{kind}")
    if kind == "solutions":
        fig = _solutions(robot, ns.solutions)
    elif kind == "trajectory":
        fig = _trajectory(robot, ns.trajectory, ns.frames)
    elif kind == "plan":
        fig = _plan(robot, ns.plan, ns.frames)
    elif kind == "workspace":
        fig = _workspace(robot, ns.workspace, pose)
    else:
        shown = A.default_pose(robot) if pose is None else pose
        fig = view_robot(robot, shown, tensions=_tensions(robot, shown))
    assert out is not None  # --out is required
    with written(out, "--out") as tmp:
        write_html(fig, tmp, title=f"{robot.name}: taut view", plotlyjs=ns.plotlyjs)
    data = {
        "robot": robot.name,
        "view": kind,
        "out": str(out),
        "bytes": out.stat().st_size,
        "frames": len(fig.frames),
        "traces": len(fig.data),
        "cables": robot.n_cables,
        "plotlyjs": str(out.parent / PLOTLY_JS) if ns.plotlyjs == "beside" else None,
    }

    def human(d: dict) -> None:
        con = console()
        beside = f", plotly.js in {markup(d['plotlyjs'])}" if d["plotlyjs"] else ""
        con.print(f"{markup(robot.name)}: {kind} view written to {markup(d['out'])} ({d['bytes']:,} bytes{beside})")

    emit(data, ns.json, human)
    return 0
