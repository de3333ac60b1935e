"""``taut calibrate ROBOT --data FILE.csv [--out CALIBRATED.yaml]``: a built robot's exits, encoder
offsets, anchors and pulley radii from its own cable measurements (:func:`taut.calibration.calibrate`); with
``--plan N``, N poses to measure, as a CSV (:func:`taut.calibration.plan_poses`)."""

from __future__ import annotations

import argparse
import io
from pathlib import Path
from typing import TYPE_CHECKING

from taut.cli import _args as A
from taut.cli._output import console, emit, fmt, markup, print_table, table, written
from taut.errors import TautError

if TYPE_CHECKING:
    import numpy as np

    from taut.calibration import CalibrationResult, PosePlan
    from taut.model import Robot

SUMMARY = "calibrate exits and encoder offsets from measured cable lengths, or plan where to measure"
DESCRIPTION = (
    "Estimate a built robot's exit points, encoder offsets (dl columns) and, with --estimate anchors "
    "or radii, its platform anchors or the radii of its swivelling pulleys, together with the unknown poses of the measurements, by sparse nonlinear "
    "least squares. The data file has columns l1..ln (lengths) or dl1..dln (changes from the "
    "encoder zero), optional pose columns named as `taut fk` names them, one row per measurement; "
    "an empty cell is a cable not measured. With no pose measured, the frame is fixed by aligning "
    "the estimated exits onto the nominal ones. --plan N prints N poses to measure as a CSV."
)
ROBOT = True


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--data", metavar="FILE.csv", help="the measurements (see the description)")
    parser.add_argument(
        "--out", metavar="CALIBRATED.yaml", help="write the robot with the estimates in (.yaml, .yml or .json)"
    )
    parser.add_argument(
        "--estimate",
        default="exits,offsets",
        help="what to estimate: exits, offsets, anchors, radii (comma-separated; default exits,offsets)",
    )
    parser.add_argument(
        "--robust",
        nargs="?",
        const="soft_l1",
        choices=("soft_l1", "huber"),
        help="robust loss against outlier rows (soft_l1 when given alone)",
    )
    parser.add_argument("--plan", type=A.count(1, 10_000), metavar="N", help="print N poses to measure as a CSV")
    parser.add_argument("--seed", type=A.seed, default=0, help="--plan: seed of the candidate poses (default 0)")
    parser.add_argument(
        "--candidates",
        metavar="POSES.csv",
        help="--plan: choose among these reachable poses (a CSV with the pose columns `taut fk` names) "
        "instead of random ones",
    )


def _estimate(text: str) -> tuple[str, ...]:
    names = tuple(part.strip() for part in text.split(",") if part.strip())
    if not names:
        raise TautError(f"--estimate: expected names from exits, offsets, anchors, radii, got {text!r}")
    return names


def _read_poses(robot: Robot, path: str) -> np.ndarray:
    """The poses of a CSV whose header names every pose coordinate (in any order)."""
    import csv

    import numpy as np

    file = Path(path)
    try:
        if not file.is_file():
            raise TautError(f"--candidates: {path!r} is not a regular file")
        text = file.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise TautError(f"--candidates: cannot read {path!r}: {exc}") from None
    rows = [row for row in csv.reader(text.splitlines()) if any(cell.strip() for cell in row)]
    if not rows:
        raise TautError(f"{file.name}: empty; expected a header {','.join(robot.pose_names)} and one pose per row")
    header = [name.strip() for name in rows[0]]
    missing = [name for name in robot.pose_names if name not in header]
    if missing or len(set(header)) != len(header) or len(header) != robot.pose_size:
        raise TautError(
            f"{file.name}: header {','.join(header)}; expected the pose columns {','.join(robot.pose_names)}"
        )
    order = [header.index(name) for name in robot.pose_names]
    poses = np.empty((len(rows) - 1, robot.pose_size))
    for k, row in enumerate(rows[1:]):
        if len(row) != len(header):
            raise TautError(f"{file.name}: row {k + 2} has {len(row)} cells, the header {len(header)}")
        for j, column in enumerate(order):
            try:
                poses[k, j] = float(row[column])
            except ValueError:
                raise TautError(
                    f"{file.name}: row {k + 2}, column {header[column]}: {row[column]!r} is not a number"
                ) from None
    if not np.isfinite(poses).all():
        raise TautError(f"{file.name}: a cell that is not a finite number")
    return poses


def _plan(ns: argparse.Namespace, robot: Robot) -> int:
    from taut.calibration import plan_poses

    candidates = None if ns.candidates is None else _read_poses(robot, ns.candidates)
    plan: PosePlan = plan_poses(robot, ns.plan, estimate=_estimate(ns.estimate), candidates=candidates, seed=ns.seed)
    data = plan.as_dict()

    def human(d: dict) -> None:
        out = io.StringIO()
        out.write(",".join(plan.pose_names) + "\n")
        for pose in plan.poses:
            out.write(",".join(f"{v:.6g}" for v in pose) + "\n")
        print(out.getvalue(), end="")

    emit(data, ns.json, human)
    return 0


def _human(robot: Robot, res: CalibrationResult, d: dict) -> None:
    con = console()
    ident = res.identifiability
    d_axes = "xyz"[: robot.dimension]
    rows = []
    for i in range(robot.n_cables):
        row = [str(i + 1)]
        row += [f"{res.exits[i, k]:.5f} ± {res.exits_std[i, k] * 1000:.2g} mm" for k in range(robot.dimension)]
        row.append(f"{res.offsets[i]:.5f} ± {res.offsets_std[i] * 1000:.2g} mm" if res.offsets_std[i] else "-")
        row.append(f"{res.residual_rms[i] * 1000:.3g}")
        rows.append(row)
    header = ["cable", *[f"exit {a} [m]" for a in d_axes], "offset [m]", "residual rms [mm]"]
    print_table(con, table(f"{robot.name}: calibrated {', '.join(res.estimate)}", header, rows))
    if "anchors" in res.estimate:
        anchor_rows = [
            [
                str(i + 1),
                *[f"{res.anchors[i, k]:.5f} ± {res.anchors_std[i, k] * 1000:.2g} mm" for k in range(robot.dimension)],
            ]
            for i in range(robot.n_cables)
        ]
        print_table(con, table("platform anchors", ["cable", *[f"anchor {a} [m]" for a in d_axes]], anchor_rows))
    if "radii" in res.estimate:
        radius_rows = [
            [str(i + 1), f"{res.radii[i]:.5f} ± {res.radii_std[i] * 1000:.2g} mm"] for i in robot.swivel_cables
        ]
        print_table(con, table("swivelling pulleys", ["cable", "radius [m]"], radius_rows))
    con.print(f"residual {fmt(res.sigma * 1000)} mm over {ident.observations} lengths; gauge: {markup(res.gauge)}")
    con.print(
        f"identifiable: {'yes' if ident.identifiable else 'NO'} (rank {ident.rank} of {ident.unknowns}, "
        f"condition number {fmt(ident.condition)})"
    )
    if not res.converged:
        con.print(
            f"NOT converged within the fits' budget ({res.evaluations} residual evaluations in all): "
            "the estimate may sit in a false minimum"
        )
    for text in ident.undetermined:
        con.print(f"  not determined: {markup(text)}")
    for text in ident.ambiguities:
        con.print(f"  ambiguity: {markup(text)}")
    if res.outliers:
        shown = ", ".join(str(k + 1) for k in res.outliers[:20])
        more = f" and {len(res.outliers) - 20} more" if len(res.outliers) > 20 else ""
        con.print(f"outlier rows: {shown}{more}" + (" (left out of the fit)" if res.robust else ""))
    if "out" in d:
        con.print(f"wrote {markup(d['out'])}")


def run(ns: argparse.Namespace) -> int:
    from taut.calibration import calibrate, read_measurements
    from taut.model import write_robot

    robot = A.load(ns.robot, ns.cable_set)
    if ns.plan is not None:
        if ns.data is not None or ns.out is not None or ns.robust is not None:
            raise TautError("--plan prints poses to measure; --data, --out and --robust are for calibrating")
    elif ns.candidates is not None:
        raise TautError("--candidates: the poses --plan chooses from; give --plan N")
    if ns.plan is not None:
        return _plan(ns, robot)
    if ns.data is None:
        raise TautError("give --data FILE.csv to calibrate, or --plan N to plan poses")
    out = A.output_file(ns.out, "--out", {".yaml", ".yml", ".json"})
    data = read_measurements(robot, ns.data)
    res = calibrate(robot, data, estimate=_estimate(ns.estimate), robust=ns.robust)
    d = res.as_dict()
    d["outliers"] = [k + 1 for k in res.outliers]
    d["rows"] = data.rows
    if out is not None:
        with written(out, "--out") as tmp:
            write_robot(res.calibrated_robot(robot), tmp)
        d["out"] = str(out)
    emit(d, ns.json, lambda dd: _human(robot, res, dd))
    return 0
