"""``taut trajectory ROBOT``: VSCR inverse kinematics along a trajectory (§4.3, §6.2 of
Rushton 2022): cable lengths, CST transitions, tensions per sample.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §4.3, §6.2. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import TYPE_CHECKING

from taut.cli import _args as A
from taut.cli._output import console, emit, markup, save_figure, written
from taut.errors import TautError

if TYPE_CHECKING:
    import numpy as np

SUMMARY = "VSCR trajectory: wrapping cable states, lengths, transitions, tensions"
ROBOT = True


def _read_waypoints(spec: str) -> tuple[str | None, np.ndarray | None]:
    """``builtin`` / ``builtin:NAME`` (the robot's trajectories) or a file: JSON/YAML list
    of waypoints, or text with one waypoint per line (commas or spaces)."""
    import numpy as np

    if spec == "builtin" or spec.startswith("builtin:"):
        return spec.partition(":")[2] or None, None
    path = Path(spec)
    if not path.is_file():
        raise TautError(f"--waypoints: no such file {spec!r} (or write 'builtin')")
    if path.stat().st_size > 16 << 20:
        raise TautError(f"--waypoints {spec}: larger than 16 MiB")
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise TautError(f"--waypoints {spec}: cannot read the file: {exc}") from None
    try:
        if path.suffix.lower() in (".json", ".yaml", ".yml"):
            import yaml

            try:
                data = yaml.safe_load(text)
            except yaml.YAMLError as exc:
                problem = getattr(exc, "problem", None) or "not valid YAML/JSON"
                raise TautError(f"--waypoints {spec}: {problem}") from None
            data = data.get("waypoints", data) if isinstance(data, dict) else data
            W = np.asarray(data, dtype=float)
        else:
            rows = [
                ln.replace(",", " ").split()
                for ln in text.splitlines()
                if ln.strip() and not ln.lstrip().startswith("#")
            ]
            W = np.asarray(rows, dtype=float)
    except TautError:
        raise
    except (ValueError, TypeError, AttributeError, RecursionError) as exc:
        raise TautError(f"--waypoints {spec}: expected rows of numbers ({exc})") from None
    if W.ndim != 2 or len(W) < 1 or not np.isfinite(W).all():
        raise TautError(f"--waypoints {spec}: expected rows of finite numbers")
    return None, W


def run(ns: argparse.Namespace) -> int:
    from taut.wrapping import (
        DEFAULT_SPEED,
        builtin_trajectory,
        contacts_text,
        full_poses,
        run_trajectory,
        timed_moves,
    )

    out = A.output_file(ns.out, "--out")
    plot = A.plot_file(ns.plot)
    robot = A.load(ns.robot, ns.cable_set)
    name, W = _read_waypoints(ns.waypoints)
    if W is None:
        if not robot.trajectories:
            raise TautError(f"{robot.name} has no trajectories of its own: give --waypoints FILE")
        t, P = builtin_trajectory(robot, name, dt=ns.dt, speed=ns.speed, dwell=ns.dwell)
    else:
        W = full_poses(robot, W)
        t, P = timed_moves(W, speed=ns.speed or DEFAULT_SPEED, dwell=1.0 if ns.dwell is None else ns.dwell, dt=ns.dt)
    res = run_trajectory(robot, t, P)
    data = {"robot": robot.name} | res.as_dict()
    # users read 1-based cable and object numbers
    data["transitions"] = [e | {"cable": e["cable"] + 1, "object": e["object"] + 1} for e in data["transitions"]]
    if out is not None:
        n = robot.n_cables
        head = [
            "time",
            *robot.pose_names,
            *(f"l{i + 1}" for i in range(n)),
            *(f"tau{i + 1}" for i in range(n)),
            "feasible",
            *(f"state{i + 1}" for i in range(n)),
        ]
        with written(out, "--out") as tmp, open(tmp, "w") as fh:
            fh.write(",".join(head) + "\n")
            for s in range(len(t)):
                states = [contacts_text(res.ik.contacts(s, i)) for i in range(n)]
                vals = [t[s], *res.ik.poses[s], *res.lengths[s], *res.tensions[s]]
                fh.write(",".join(f"{v:.9g}" for v in vals) + f",{int(res.feasible[s])}," + ",".join(states) + "\n")
        data["out"] = str(out)
    if plot is not None:
        from taut.viz import plot_trajectory

        save_figure(plot_trajectory(robot, res), plot, data)

    def human(d: dict) -> None:
        con = console()
        con.print(
            f"[bold]{markup(robot.name)}[/]: {d['samples']} samples over {d['duration']:.3g} s, "
            f"{len(d['transitions'])} CST transitions"
        )
        for e in d["transitions"]:
            con.print(f"  t = {e['time']:8.3f} s  cable {e['cable']}  {e['kind']:6s} object {e['object']}")
        if d["tension_feasible"]:
            con.print("tension distribution (LP) feasible at every sample")
        else:
            con.print(f"[bold red]no feasible tension distribution[/] at {len(d['infeasible_samples'])} samples")

    emit(data, ns.json, human)
    return 0


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--waypoints",
        default="builtin",
        metavar="FILE|builtin",
        help="waypoints file (x,y per line, or JSON/YAML list), or builtin[:NAME] (default: the robot's first trajectory)",
    )
    parser.add_argument("--dt", type=A.real(above=0), default=0.01, help="sampling step [s] (default 0.01)")
    parser.add_argument(
        "--speed",
        type=A.real(above=0),
        default=None,
        help="speed along waypoint moves [m/s] (default: the trajectory's, else 0.1)",
    )
    parser.add_argument(
        "--dwell",
        type=A.real(least=0),
        default=None,
        help="dwell at each waypoint [s] (default: the trajectory's, 1 s for files)",
    )
    parser.add_argument("--out", metavar="FILE.csv", help="per-sample times, poses, lengths, tensions, cable states")
    parser.add_argument("--plot", metavar="FILE.png", help="lengths over time with transitions, and robot snapshots")
