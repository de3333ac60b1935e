"""``taut check ROBOT --trajectory FILE|NAME``: self-collision and singularities along a
trajectory (Lieskovský 2020, §2.3, §3.4, §4.2; :mod:`taut.collision`).

References
----------
.. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, §2.3, §3.4, §4.2.
   (docs/references.bib: lieskovsky2020)
"""

from __future__ import annotations

import argparse
from pathlib import Path

from taut.cli import _args as A
from taut.cli._output import console, emit, markup, save_figure
from taut.errors import TautError

SUMMARY = "self-collision and singularity check along a trajectory"
ROBOT = True

DESCRIPTION = """Check every step of a trajectory for cable/platform self-collision (capsule model),
Jacobian singularity and force-closure singularity.

--trajectory is the name of one of the robot's built-in trajectories (e.g. sim-a ... sim-d
of adjustable-8cable) or a file:
  CSV        one pose per line, comma-separated (x,y,z,a,b,c then joint coordinates);
             an optional header line of the pose names; '#' starts a comment
  YAML/JSON  a list of poses; or {poses: [...]}; or {waypoints: [...], steps: [...]}
             (straight moves of steps[k] increments, default 100 each)
Steps, cables and capsules are numbered from 1 (cables first, then the platform capsules).
JSON: {"capsules", "poses", "jacobian_ratio", "steps": [{"index", "collisions": [[i, j], ...], "jacobian_singular",
"force_closure_singular", "min_clearance"}, ...], "summary": {...}}."""


def _summary(summary: dict) -> dict:
    """:meth:`CheckResult.summary` with 1-based steps, as users read them."""
    out = {}
    for key, value in summary.items():
        if key.startswith("first_"):
            value = None if value is None else value + 1
        elif key.endswith("_steps"):
            value = [[a + 1, b + 1] for a, b in value]
        out[key] = value
    return out


def run(ns: argparse.Namespace) -> int:
    from taut.collision import check_poses, load_trajectory, trajectory_poses

    plot = A.plot_file(ns.plot)
    robot = A.load(ns.robot, ns.cable_set)
    A.straight_cables(robot, "the collision and singularity checks")
    spec = ns.trajectory
    if spec in robot.trajectories:
        poses = trajectory_poses(robot, spec)
    elif Path(spec).is_file():
        poses = load_trajectory(robot, spec)
    else:
        known = ", ".join(robot.trajectories) or "none"
        raise TautError(
            f"--trajectory: {spec!r} is neither a file nor a built-in trajectory of {robot.name} (built-in: {known})"
        )
    res = check_poses(robot, poses, method=ns.method)
    result = res.as_dict()
    data = {"robot": robot.name, "trajectory": spec} | result
    data["summary"] = _summary(result["summary"])
    data["steps"] = [
        r
        | {
            "index": r["index"] + 1,
            "collisions": [[i + 1, j + 1] for i, j in r["collisions"]],
            "obstacle_contacts": [[i + 1, j + 1] for i, j in r["obstacle_contacts"]],
        }
        for r in result["steps"]
    ]
    if plot is not None:
        from taut.viz import plot_check

        save_figure(plot_check(robot, res), plot, data)

    def human(d: dict) -> None:
        con = console()
        s = d["summary"]
        con.print(
            f"[bold]{markup(robot.name)}[/], trajectory {markup(spec)}: {s['poses']} steps, smallest clearance {s['min_clearance']:.4g} m"
        )
        names = res.model.names
        for label, key in (
            ("self-collision", "collision_steps"),
            ("Jacobian singular", "jacobian_singular_steps"),
            ("force-closure singular", "force_closure_singular_steps"),
            ("cable meets obstacle", "obstacle_contact_steps"),
        ):
            runs = s[key]
            text = ", ".join(f"{a}" if a == b else f"{a}-{b}" for a, b in runs) if runs else "none"
            con.print(f"  {label:<23} steps {text}")
        if s["first_collision"] is not None:
            k = s["first_collision"] - 1
            pairs = "; ".join(f"{names[i]} & {names[j]}" for i, j in res.proximity.collisions(k))
            con.print(f"  first collision at step {k + 1}: {markup(pairs)}")
        if s["first_obstacle_contact"] is not None:
            k = s["first_obstacle_contact"] - 1
            met = "; ".join(f"cable {i} meets obstacle {j}" for i, j in d["steps"][k]["obstacle_contacts"])
            con.print(
                f"  first obstacle contact at step {k + 1}: {met} (it wraps; taut trajectory models the wrapping)"
            )

    emit(data, ns.json, human)
    return 0


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--trajectory",
        required=True,
        metavar="FILE|NAME",
        help="trajectory file (CSV, YAML, JSON) or built-in trajectory name (e.g. sim-c)",
    )
    parser.add_argument(
        "--method",
        default="fast",
        choices=("fast", "lp"),
        help="force-closure test: fast (vectorised) or lp (one LP per step, the reference)",
    )
    parser.add_argument(
        "--plot", metavar="FILE.png", help="clearance and singularity flags over the steps, robot at the first problem"
    )
