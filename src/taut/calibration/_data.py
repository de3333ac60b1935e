"""Calibration measurements: the CSV file of cable lengths (or length changes from an encoder
zero) and, where a tracker measured it, the pose of each row.

Columns (one header line, comma-separated, names as below, any order):

* ``l1 … ln`` or ``l_<cable name>``: measured cable lengths [m], positive;
* ``dl1 … dln`` or ``dl_<cable name>``: length changes from the encoder's zero [m]; the cable's
  offset (its length at the zero) is then an unknown of the calibration;
* the pose coordinates as ``taut fk`` names them (``x, y, z, a, b, c`` …), all or none: a row
  that fills them has a measured pose, a row that leaves them empty an unknown one.

An empty cell is a cable not measured in that row (slack, or no reading).  Cables are numbered
from 1 in the file, as on the command line (``docs/architecture.md`` §2.6).
"""

from __future__ import annotations

import csv
import io
import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import numpy.typing as npt

from taut._checks import as_array
from taut._results import Result
from taut.errors import TautError, UnsupportedRobotError
from taut.model import MAX_MAGNITUDE, Robot

#: Most rows a measurement file may hold: the fit keeps a few arrays of this many rows per cable.
MAX_ROWS = 1_000_000

#: Largest measurement file read [bytes].
MAX_MEASUREMENT_BYTES = 256 * 2**20


class MeasurementError(TautError):
    """A measurement file or array that cannot be read: a column of no known name, a duplicate
    header, a cell that is not a finite number, a cable the robot does not have."""


def refuse_unsupported(robot: Robot) -> None:
    """Raise :class:`UnsupportedRobotError` for a robot whose cable lengths calibration does
    not model: straight cables from fixed exit points or swivelling pulleys to anchors on one
    rigid body."""
    if robot.n_joints:
        raise UnsupportedRobotError(
            f"{robot.name}: calibration handles platforms without joints; its platform has jointed bodies"
        )
    if robot.obstacles:
        raise UnsupportedRobotError(
            f"{robot.name}: calibration models straight cables; it has obstacles its cables may wrap around"
        )
    if robot.sagging_cables:
        cables = ", ".join(str(i + 1) for i in robot.sagging_cables)
        raise UnsupportedRobotError(
            f"{robot.name}: calibration models straight cables; cables {cables} sag (cables[].weight)"
        )
    if robot.routed_cables:
        cables = ", ".join(str(i + 1) for i in robot.routed_cables)
        raise UnsupportedRobotError(
            f"{robot.name}: calibration models straight cables from fixed exit points; cables {cables} run through via points"
        )


@dataclass(frozen=True)
class Measurements(Result):
    """Rows of cable measurements, with the pose of each row where it was measured.

    Attributes
    ----------
    values : ndarray, shape (N, n)
        Per row and cable, the measured length [m] (or length change, where ``changes``);
        0 where not measured.
    measured : ndarray of bool, shape (N, n)
        The cells measured.
    changes : ndarray of bool, shape (n,)
        Cables measured as length changes from an encoder zero (``dl`` columns): their
        offsets are unknowns of the calibration.
    poses : ndarray, shape (N, pose_size)
        Measured poses; 0 in the rows where ``pose_known`` is False.
    pose_known : ndarray of bool, shape (N,)
        Rows whose pose was measured.
    """

    values: np.ndarray
    measured: np.ndarray
    changes: np.ndarray
    poses: np.ndarray
    pose_known: np.ndarray

    @property
    def rows(self) -> int:
        """Number of rows ``N``."""
        return int(self.values.shape[0])

    def to_csv(self, robot: Robot) -> str:
        """The measurements as the CSV file :func:`read_measurements` reads.

        Parameters
        ----------
        robot : Robot
            The robot they were taken on (its pose names head the pose columns).

        Returns
        -------
        str
            A header line, then one line per row; empty cells where nothing was measured.

        Examples
        --------
        >>> from taut.model import example
        >>> from taut.calibration import measurements
        >>> robot = example("planar-4cable")
        >>> print(measurements(robot, [[1.2, 1.3, None, 1.1]]).to_csv(robot), end="")
        l1,l2,l3,l4
        1.2,1.3,,1.1
        """
        n = robot.n_cables
        names = [f"{'dl' if self.changes[i] else 'l'}{i + 1}" for i in range(n)]
        with_poses = bool(self.pose_known.any())
        if with_poses:
            names += robot.pose_names
        out = io.StringIO()
        out.write(",".join(names) + "\n")
        for k in range(self.rows):
            cells = [repr(float(v)) if m else "" for v, m in zip(self.values[k], self.measured[k])]
            if with_poses:
                cells += [repr(float(v)) if self.pose_known[k] else "" for v in self.poses[k]]
            out.write(",".join(cells) + "\n")
        return out.getvalue()


def measurements(
    robot: Robot,
    lengths: npt.ArrayLike | None = None,
    *,
    changes: npt.ArrayLike | None = None,
    poses: npt.ArrayLike | None = None,
) -> Measurements:
    """Measurements from arrays: absolute ``lengths`` or encoder ``changes`` per row and cable
    (``None`` or NaN where a cable was not measured), and measured ``poses`` (a row of NaN
    where the pose is unknown).

    Parameters
    ----------
    robot : Robot
    lengths : array_like, shape (N, n), optional
        Measured lengths [m]; a column may be all NaN where ``changes`` gives the cable.
    changes : array_like, shape (N, n), optional
        Length changes from the encoder zero [m]: the cable's offset is then unknown.
    poses : array_like, shape (N, pose_size), optional
        Measured poses; rows of NaN for the unknown ones.

    Returns
    -------
    Measurements

    Raises
    ------
    MeasurementError
        Arrays of the wrong shape, a cable given both as a length and as a change, a row
        that measures nothing, a pose measured in part.

    Examples
    --------
    >>> from taut.model import example
    >>> data = measurements(example("planar-4cable"), changes=[[0.1, -0.2, 0.0, None]])
    >>> data.changes.tolist(), data.measured.tolist()
    ([True, True, True, False], [[True, True, True, False]])
    """
    refuse_unsupported(robot)
    n, s = robot.n_cables, robot.pose_size
    given = [a for a in (lengths, changes) if a is not None]
    if not given:
        raise MeasurementError("measurements: give lengths or changes")

    def table(value: npt.ArrayLike, what: str) -> np.ndarray:
        raw = np.array(value, dtype=object)
        raw = np.where(raw == None, np.nan, raw)  # noqa: E711 - None cells are unmeasured
        return as_array(raw, what, shape=(None, n), finite=False, error=MeasurementError)

    ls = table(lengths, "lengths") if lengths is not None else None
    dls = table(changes, "changes") if changes is not None else None
    rows = (ls if ls is not None else dls).shape[0]  # type: ignore[union-attr]
    if ls is not None and dls is not None and ls.shape != dls.shape:
        raise MeasurementError(f"lengths and changes: shapes {ls.shape} and {dls.shape} differ")
    if ls is None:
        ls = np.full((rows, n), np.nan)
    if dls is None:
        dls = np.full((rows, n), np.nan)
    for what, arr in (("lengths", ls), ("changes", dls)):
        if np.isinf(arr).any() or (np.abs(np.nan_to_num(arr)) > MAX_MAGNITUDE).any():
            raise MeasurementError(f"{what}: expected finite numbers within {MAX_MAGNITUDE:g}")
    has_l, has_dl = ~np.isnan(ls), ~np.isnan(dls)
    both = has_l.any(axis=0) & has_dl.any(axis=0)
    if both.any():
        raise MeasurementError(f"cable {int(np.argmax(both)) + 1} is given both as lengths and as changes")
    if (has_l & (np.nan_to_num(ls) <= 0)).any():
        k, i = np.argwhere(has_l & (np.nan_to_num(ls) <= 0))[0]
        raise MeasurementError(f"row {k + 1}: the length of cable {i + 1} must be positive, got {ls[k, i]:g}")
    measured = has_l | has_dl
    empty = ~measured.any(axis=1)
    if empty.any():
        raise MeasurementError(f"row {int(np.argmax(empty)) + 1} measures no cable")
    if poses is None:
        pose_arr = np.full((rows, s), np.nan)
    else:
        pose_arr = as_array(poses, "poses", shape=(rows, s), finite=False, error=MeasurementError)
    known = ~np.isnan(pose_arr)
    partial = known.any(axis=1) & ~known.all(axis=1)
    if partial.any():
        raise MeasurementError(
            f"row {int(np.argmax(partial)) + 1}: its pose is measured in part; give all of it or none"
        )
    if np.isinf(pose_arr).any() or (np.abs(np.nan_to_num(pose_arr)) > MAX_MAGNITUDE).any():
        raise MeasurementError(f"poses: expected finite numbers within {MAX_MAGNITUDE:g}")
    values = np.where(has_l, ls, np.where(has_dl, dls, 0.0))
    return Measurements(
        np.nan_to_num(values),
        measured,
        has_dl.any(axis=0),
        np.nan_to_num(pose_arr),
        known.all(axis=1),
    )


def _columns(robot: Robot, header: list[str]) -> list[tuple[str, int]]:
    """For each column, ``("l" | "dl" | "pose", index)``: a cable's or a pose coordinate's."""
    names = {c.name: i for i, c in enumerate(robot.cables) if c.name}
    pose_names = robot.pose_names
    seen: dict[str, int] = {}
    out: list[tuple[str, int]] = []
    pose_cols = [-1] * len(pose_names)
    n = robot.n_cables
    for j, raw in enumerate(header):
        name = raw.strip()
        if name in seen:
            raise MeasurementError(f"column {j + 1}: duplicate header {name!r} (also column {seen[name] + 1})")
        seen[name] = j
        numbered = re.fullmatch(r"(dl|l)(\d+)", name)
        named = re.fullmatch(r"(dl|l)_(.+)", name)
        if name in pose_names:
            pose_cols[pose_names.index(name)] = j
            out.append(("pose", pose_names.index(name)))
        elif numbered:
            k = int(numbered.group(2))
            if not 1 <= k <= n:
                raise MeasurementError(f"column {name!r}: {robot.name} has cables 1..{n}")
            out.append((numbered.group(1), k - 1))
        elif named and named.group(2) in names:
            out.append((named.group(1), names[named.group(2)]))
        else:
            known = f"l1..l{n}, dl1..dl{n}" + (", l_<cable name>" if names else "") + ", " + ", ".join(pose_names)
            raise MeasurementError(f"column {j + 1}: unknown name {name!r}; expected {known}")
    cables = [i for kind, i in out if kind != "pose"]
    dup = {i for i in cables if cables.count(i) > 1}
    if dup:
        raise MeasurementError(f"cable {min(dup) + 1} has two columns")
    given = [c for c in pose_cols if c >= 0]
    if given and len(given) != len(pose_cols):
        missing = [p for p, c in zip(pose_names, pose_cols) if c < 0]
        raise MeasurementError(
            f"pose columns: {', '.join(missing)} missing; give all of {', '.join(pose_names)} or none"
        )
    if not cables:
        raise MeasurementError(f"no cable column (l1..l{n} or dl1..dl{n})")
    return out


def _cell(text: str, row: int, column: str) -> float:
    try:
        x = float(text)
    except ValueError:
        raise MeasurementError(f"row {row}, column {column}: {text.strip()!r} is not a number") from None
    if not math.isfinite(x) or abs(x) > MAX_MAGNITUDE:
        raise MeasurementError(
            f"row {row}, column {column}: {text.strip()!r} is not a finite number within {MAX_MAGNITUDE:g}"
        )
    return x


def parse_measurements(robot: Robot, text: str, *, source: str = "measurements") -> Measurements:
    """Measurements from the text of a CSV file (module docstring).

    Parameters
    ----------
    robot : Robot
        The robot measured; its cable count and pose names fix the columns.
    text : str
        The file's text.
    source : str
        Named in messages (the file's name).

    Returns
    -------
    Measurements

    Raises
    ------
    MeasurementError
        One line naming the file, the row or column and what is wrong.
    UnsupportedRobotError
        A robot with jointed bodies, obstacles, sagging or routed cables.

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.calibration import parse_measurements
    >>> data = parse_measurements(example("planar-4cable"), "dl1,dl2,l3,l4\\n0.1,0.2,1.3,\\n")
    >>> data.changes.tolist(), data.measured.tolist()
    ([True, True, False, False], [[True, True, True, False]])
    """
    refuse_unsupported(robot)
    try:
        return _parse(robot, text)
    except MeasurementError as exc:
        raise MeasurementError(f"{source}: {exc}") from None


def _parse(robot: Robot, text: str) -> Measurements:
    reader = csv.reader(io.StringIO(text))
    lines = [(k, r) for k, r in enumerate(reader, start=1) if any(c.strip() for c in r)]
    if not lines:
        raise MeasurementError("empty file: expected a header line and rows")
    (_, header), body = lines[0], lines[1:]
    if not body:
        raise MeasurementError("no rows after the header")
    if len(body) > MAX_ROWS:
        raise MeasurementError(f"{len(body):,} rows, more than {MAX_ROWS:,}")
    columns = _columns(robot, header)
    n, s = robot.n_cables, robot.pose_size
    ls = np.full((len(body), n), np.nan)
    dls = np.full((len(body), n), np.nan)
    poses = np.full((len(body), s), np.nan)
    for r, (line, cells) in enumerate(body):
        if len(cells) != len(header):
            raise MeasurementError(f"line {line}: {len(cells)} cells, the header has {len(header)}")
        for (kind, i), name, text in zip(columns, header, cells):
            if not text.strip():
                continue
            x = _cell(text, line, name.strip())
            (ls if kind == "l" else dls if kind == "dl" else poses)[r, i] = x
    changed = {i for kind, i in columns if kind == "dl"}
    return measurements(
        robot,
        ls,
        changes=dls if changed else None,
        poses=poses,
    )


def read_measurements(robot: Robot, path: str | Path) -> Measurements:
    """Measurements from a CSV file (module docstring).

    Parameters
    ----------
    robot : Robot
    path : str or Path

    Returns
    -------
    Measurements

    Raises
    ------
    MeasurementError
        A file that cannot be read, or whose contents :func:`parse_measurements` refuses.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from taut.model import example
    >>> from taut.calibration import read_measurements
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "data.csv"
    >>> _ = path.write_text("l1,l2,l3,l4,x,y,theta\\n1.3,1.3,1.3,1.3,0,0,0\\n")
    >>> read_measurements(example("planar-4cable"), path).pose_known.tolist()
    [True]
    """
    p = Path(path)
    try:
        if not p.is_file():
            raise MeasurementError(f"{str(p)!r}: not a regular file")
        if p.stat().st_size > MAX_MEASUREMENT_BYTES:
            raise MeasurementError(f"{str(p)!r}: larger than {MAX_MEASUREMENT_BYTES // 2**20} MiB")
        text = p.read_text(encoding="utf-8")
    except OSError as exc:
        raise MeasurementError(f"{str(p)!r}: cannot read: {exc.strerror or exc}") from None
    except UnicodeDecodeError:
        raise MeasurementError(f"{str(p)!r}: not a UTF-8 text file") from None
    return parse_measurements(robot, text, source=p.name)
