"""``taut simulate ROBOT``: a trajectory through waypoints, tracked under computed-torque
control with the tension distribution in the loop (:mod:`taut.dynamics._control`); sagging
cables as quasi-static elastic catenaries.

References
----------
.. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning and
   Control", Springer, 2009, §8.5.2. (docs/references.bib: siciliano2009)
.. [2] D. Lau, J. Eden, Y. Tan, D. Oetomo, "CASPR: A comprehensive cable-robot analysis and
   simulation platform for the research of cable-driven parallel robots", IEEE/RSJ
   International Conference on Intelligent Robots and Systems (IROS), 2016.
   (docs/references.bib: lau2016)
.. [3] H. M. Irvine, "Cable Structures", MIT Press, 1981, Ch. 1, §1.3 (the elastic catenary).
   (docs/references.bib: irvine1981)
"""

from __future__ import annotations

import argparse
import math
from typing import TYPE_CHECKING

from taut.cli import _args as A
from taut.cli._cables import cable_numbers
from taut.cli._output import console, emit, markup, save_figure, written
from taut.errors import TautError

if TYPE_CHECKING:
    import numpy as np

    from taut.dynamics import WrenchSteps
    from taut.model import Robot

SUMMARY = "simulate a trajectory tracked by computed-torque control with the tension distribution in the loop"
ROBOT = True

#: Highest control and sample rate [Hz].
MAX_RATE = 1e6
#: Most RK4 steps of the plant per control period.
MAX_SUBSTEPS = 1000

#: The keys of ``taut simulate --json`` taken from :meth:`ControlResult.as_dict`, each with
#: the field it holds: the per-update arrays the command does not print (velocity, error,
#: command, ...) are left out, and ``feasible`` is the verdict of the whole run.
RESULT_KEYS = {
    "kp": "kp",
    "kd": "kd",
    "rate_hz": "rate_hz",
    "substeps": "substeps",
    "method": "method",
    "pose_names": "pose_names",
    "updates": "updates",
    "reference": "reference",
    "tensions": "tensions",
    "exit_tensions": "exit_tensions",
    "cable_model": "cable_model",
    "tracking_error_max": "tracking_error_max",
    "tracking_error_rms": "tracking_error_rms",
    "position_error_max": "position_error_max",
    "rotation_error_max": "rotation_error_max",
    "min_tension_margin": "min_tension_margin",
    "slack_events": "slack_events",
    "first_failure_time": "first_failure_time",
    "elapsed_s": "elapsed_s",
    "complete": "complete",
    "time": "times",
    "pose": "poses",
    "lower_tension_margin": "lower_margin",
    "upper_tension_margin": "upper_margin",
    "distribution_failures": "failures",
    "feasible": "all_feasible",
    "joint_limit_violations": "joint_limit_violations",
    "first_joint_limit_time": "first_joint_limit_time",
    "actuator_forces": "actuator_forces",
    "actuator_min": "actuator_min",
    "actuator_max": "actuator_max",
    "actuator_margin": "actuator_margin",
    "actuator_force_max": "actuator_peak",
    "tension_margin_per_cable": "cable_margin",
    "slack_events_per_cable": "cable_slack_events",
}

DISTURBANCE_HELP = (
    "external wrench on the platform, unknown to the controller: T0:W (a step from T0 s on) or "
    "T0:T1:W (from T0 to T1 s), W the wrench's components comma-separated (forces [N], then "
    "moments [N m] about the reference point, fixed frame; on a jointed platform optionally "
    "followed by one force or torque per joint); several joined by ';' add up. "
    "Example: '1:5,0,0,0,0,0;2:2.5:0,0,-20,0,0,0'"
)


def waypoints(robot: Robot, text: str) -> np.ndarray:
    """``--waypoints P0;P1;...``: poses (``pose_size`` numbers each) or positions
    (``dimension`` numbers each, the orientation kept at zero)."""
    import numpy as np

    rows = [A.vector(part, "--waypoints") for part in text.split(";")]
    if len(rows) < 2:
        raise TautError(f"--waypoints: give at least two waypoints separated by ';', got {text!r}")
    sizes = {robot.pose_size, robot.dimension}
    for k, row in enumerate(rows):
        if row.size not in sizes or row.size != rows[0].size:
            raise TautError(
                f"--waypoints: waypoint {k + 1} has {row.size} coordinates; {robot.name} needs "
                f"{robot.pose_size} ({','.join(robot.pose_names)}) or {robot.dimension} (a position), the same for all"
            )
    return np.array(rows)


def disturbance(robot: Robot, text: str) -> WrenchSteps:
    """``--disturbance T0:W[;T0:T1:W...]`` (:data:`DISTURBANCE_HELP`)."""
    from taut.dynamics import WrenchSteps

    steps = []
    for part in text.split(";"):
        fields = part.split(":")
        if len(fields) not in (2, 3) or not part.strip():
            raise TautError(f"--disturbance: expected T0:W or T0:T1:W (W comma-separated), got {part!r}")
        start = A.number(fields[0], "--disturbance start time")
        end = A.number(fields[1], "--disturbance end time") if len(fields) == 3 else math.inf
        if not (start >= 0 and end > start):
            raise TautError(f"--disturbance: times must satisfy 0 <= T0 < T1, got {part!r}")
        w = A.vector(fields[-1], "--disturbance wrench")
        if w.size not in (robot.wrench_dim, robot.pose_size):
            joints = f" (or {robot.pose_size} with its joint forces)" if robot.n_joints else ""
            raise TautError(
                f"--disturbance: {robot.name} takes a wrench of {robot.wrench_dim} components{joints}, "
                f"got {w.size} in {part!r}"
            )
        # a wrench on the platform alone leaves the joints unloaded
        full = tuple(float(x) for x in w) + (0.0,) * (robot.pose_size - w.size)
        steps.append((start, end, full))
    return WrenchSteps(tuple(steps))


def _gains(text: str, robot: Robot, what: str) -> np.ndarray:
    import numpy as np

    g = A.vector(text, what)
    if g.size not in (1, robot.pose_size) or (g < 0).any():
        raise TautError(
            f"{what}: expected one number >= 0 or {robot.pose_size} (one per pose coordinate), got {text!r}"
        )
    return np.broadcast_to(g, (robot.pose_size,)).copy()


def run(ns: argparse.Namespace) -> int:
    import numpy as np

    from taut.cli._progress import progress_bar, wanted
    from taut.dynamics import DEFAULT_KD, DEFAULT_KP, simulate_control, with_mass_error
    from taut.motion import trajectory_from_waypoints
    from taut.statics import METHODS

    out = A.output_file(ns.out, "--out", {".csv"})
    plot = A.plot_file(ns.plot)
    robot = A.load(ns.robot, ns.cable_set)
    duration, rate, sample_rate = ns.duration, ns.rate, ns.sample_rate
    if duration * rate > 1e7:
        raise TautError(f"--duration {duration:g} s at --rate {rate:g} Hz makes more than 1e7 control updates")
    if ns.method not in METHODS:
        raise TautError(f"--method: unknown method {ns.method!r}; valid methods: {', '.join(METHODS)}")
    if ns.controller == "none" and (ns.kp is not None or ns.kd is not None):
        raise TautError("--kp and --kd are the gains of --controller ctc")
    if ns.controller == "none":
        kp = kd = np.zeros(robot.pose_size)
    else:
        kp = _gains(str(DEFAULT_KP) if ns.kp is None else ns.kp, robot, "--kp")
        kd = _gains(str(DEFAULT_KD) if ns.kd is None else ns.kd, robot, "--kd")
    W = waypoints(robot, ns.waypoints)
    wd = disturbance(robot, ns.disturbance) if ns.disturbance is not None else None
    model = None
    if ns.mass_error is not None:
        model = with_mass_error(robot, ns.mass_error)
    motion = trajectory_from_waypoints(robot, W, duration=duration, law=ns.law)
    # the samples written: every control update at --sample-rate, and the last
    every = max(1, int(round(rate / sample_rate)))
    with progress_bar("simulate", wanted(ns.json)) as progress:
        res = simulate_control(
            robot,
            motion,
            kp=kp,
            kd=kd,
            rate_hz=rate,
            substeps=ns.substeps,
            model=model,
            disturbance=wd,
            method=ns.method,
            decimate=every,
            progress=progress,
        )
    result = res.as_dict()
    data = {
        "robot": robot.name,
        "controller": ns.controller,
        "law": ns.law,
        "duration": duration,
        "mass_error": ns.mass_error,
        "disturbance": None
        if wd is None
        else [{"start": a, "end": None if math.isinf(b) else b, "wrench": list(w)} for a, b, w in wd.steps],
        "samples": len(result["times"]),
        "actuated_joints": [robot.pose_names[robot.wrench_dim + j] for j in robot.actuated_joints],
        "sagging_cables": cable_numbers(res.sagging_cables),
    } | {key: result[name] for key, name in RESULT_KEYS.items()}
    if out is not None:
        n = robot.n_cables
        # a sagging cable's tension at its exit too (the platform's is the commanded one)
        exits = [i for i in range(n) if i in res.sagging_cables]
        head = [
            "time",
            *robot.pose_names,
            *(f"ref_{p}" for p in robot.pose_names),
            *(f"tau{i + 1}" for i in range(n)),
            *(f"exit_tau{i + 1}" for i in exits),
            "admissible",
        ]
        with written(out, "--out") as tmp, open(tmp, "w") as fh:
            fh.write(",".join(head) + "\n")
            for k in range(res.times.size):
                vals = [res.times[k], *res.poses[k], *res.reference[k], *res.tensions[k], *res.exit_tensions[k, exits]]
                fh.write(",".join(f"{v:.9g}" for v in vals) + f",{int(res.feasible[k])}\n")
        data["out"] = str(out)
    if plot is not None:
        from taut.viz import plot_control

        save_figure(plot_control(robot, res), plot, data)

    def human(d: dict) -> None:
        con = console()
        con.print(
            f"[bold]{markup(robot.name)}[/]: {ns.law} trajectory through {len(W)} waypoints over {duration:g} s, "
            f"{ns.controller} control at {rate:g} Hz ({d['updates']} updates)"
        )
        if d["sagging_cables"]:
            con.print(
                f"cable model: {d['cable_model']} (Irvine 1981, §1.3) for cables "
                f"{', '.join(map(str, d['sagging_cables']))}: each pulls along its tangent at the platform with its "
                "commanded tension there; their mass is left out of the platform's inertia"
            )
        else:
            con.print(f"cable model: {d['cable_model']}")
        errs = ", ".join(f"{p}={e:.3g}" for p, e in zip(robot.pose_names, d["tracking_error_max"]))
        con.print(f"max tracking error: {errs} (m, rad)")
        con.print(f"min tension margin: {d['min_tension_margin']:.4g} N; slack events: {d['slack_events']}")
        if d["actuated_joints"]:
            forces = ", ".join(f"{j}={f:.4g}" for j, f in zip(d["actuated_joints"], d["actuator_force_max"]))
            con.print(f"max joint actuator force: {forces} (N, N m)")
        if d["joint_limit_violations"]:
            con.print(
                f"[bold red]joints beyond their limits[/] at {d['joint_limit_violations']} updates "
                f"(first at t = {d['first_joint_limit_time']:g} s)"
            )
        if d["feasible"]:
            con.print("tension distribution admissible at every update")
        else:
            con.print(
                f"[bold red]no admissible tensions[/] at {d['distribution_failures']} updates "
                f"(first at t = {d['first_failure_time']:g} s): the last admissible tensions were held"
            )

    emit(data, ns.json, human)
    return 0


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--waypoints",
        required=True,
        metavar="P0;P1;...",
        help="waypoints separated by ';', each a pose (x,y,z,a,b,c; angles in rad, 30deg or pi/8) or a position; "
        "write --waypoints=-0.1,0,0;... for a leading minus",
    )
    parser.add_argument(
        "--duration", type=A.real(above=0), required=True, help="total duration [s], shared out by segment length"
    )
    parser.add_argument(
        "--law", default="quintic", help="time law: linear | cubic | quintic | trapezoidal (default quintic)"
    )
    parser.add_argument(
        "--controller",
        default="ctc",
        choices=("ctc", "none"),
        help="ctc: computed torque (PD + feed-forward inverse dynamics); none: feed-forward only",
    )
    parser.add_argument("--kp", help="proportional gain [1/s^2], one or one per pose coordinate (default 400)")
    parser.add_argument("--kd", help="derivative gain [1/s], one or one per pose coordinate (default 44)")
    parser.add_argument(
        "--rate", type=A.real(above=0, most=MAX_RATE), default=1000.0, help="control rate [Hz] (default 1000)"
    )
    parser.add_argument(
        "--substeps",
        type=A.count(1, MAX_SUBSTEPS),
        default=1,
        help=f"RK4 steps of the plant per control period, 1 to {MAX_SUBSTEPS} (default 1)",
    )
    parser.add_argument("--disturbance", metavar="T0:W[;T0:T1:W]", help=DISTURBANCE_HELP)
    parser.add_argument(
        "--mass-error",
        type=A.real(above=-1, below=1),
        metavar="F",
        help="relative error of the controller's mass and inertia (0.1: its model is 10 %% heavier)",
    )
    parser.add_argument(
        "--method",
        default="qp",
        help="tension distribution where the closed form gives up: lp | qp | inf | closed-form | improved-closed-form | barycentric",
    )
    parser.add_argument(
        "--sample-rate",
        type=A.real(above=0, most=MAX_RATE),
        default=100.0,
        help="samples per second kept for the JSON and CSV output (default 100; statistics cover every update)",
    )
    parser.add_argument(
        "--out",
        metavar="FILE.csv",
        help="per-sample time, pose, reference pose, tensions (sagging cables: at the platform, then at the exits), "
        "admissible",
    )
    parser.add_argument("--plot", metavar="FILE.png", help="tensions and tracking error against time")
