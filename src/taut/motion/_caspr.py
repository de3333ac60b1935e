"""CASPR joint-space trajectories: read an ``X_trajectories.xml`` into :class:`Motion` objects.

CASPR [1]_ keeps a model's trajectories in ``X_trajectories.xml`` beside ``X_bodies.xml``:
``<trajectories><joint_trajectories>`` holds elements with an ``id``, a ``time_definition``
(``relative``: each point's ``time`` is the duration of the segment that ends there;
``absolute``: the time since the start, the first point being at 0) and a sampling
``time_step`` [s], whose ``<points>`` give the joint coordinates ``<q>`` of each point.  They
map onto :func:`~taut.motion.trajectory_from_waypoints` one to one, since taut's pose is
CASPR's ``q`` for the models :func:`taut.model.read_caspr` reads (a ``PLANAR_XZ``
platform has ``θ = −θ_CASPR``: its angle, rates and accelerations change sign):

==========================================  ==============================================
CASPR element                               taut
==========================================  ==============================================
``linear_spline_trajectory``                ``law="linear"``
``cubic_spline_trajectory``                 ``law="cubic"``, ``velocities`` = each ``<q_dot>``
``quintic_spline_trajectory``               ``law="quintic"``, ``<q_dot>`` and ``<q_ddot>``
``cubic_spline_average_velocity_trajectory``  ``law="cubic"``, the mean of the adjacent
                                            segments' average velocities at via points, the
                                            first and last ``<q_dot>`` at the ends
``parabolic_blend_trajectory``              ``law="trapezoidal"``, blend time
                                            ``blend_time_default`` or the point's
                                            ``blend_time`` (for the segment ending there)
``file_trajectory``                         not read (samples of a ``.traj`` file)
==========================================  ==============================================

Orientation.  CASPR's spherical joints (``SPATIAL_EULER_XYZ``, ``S_EULER_XYZ``,
``S_FIXED_XYZ``: taut's spatial rigid platforms) turn the platform about one axis from each
point's orientation to the next's, the spline timing the angle turned (``SphericalEulerXYZ``'s
``generateTrajectory…Spline`` through ``Quaternion.…Interpolation``); so does the reader
(``rotation="axis"`` of :func:`~taut.motion.trajectory_from_waypoints`, :mod:`taut.motion._axis`).
Those joints take only zero angle velocities and accelerations at the points (CASPR asserts
it), so a cubic or quintic trajectory with others, or an average-velocity one whose averages
turn the angles, is not read.  The other coordinates (positions, a planar angle, the joints of
jointed bodies) are interpolated each separately, angles without unwrapping as CASPR does,
unless ``unwrap=True``.

Unsupported trajectories.  CASPR loads a trajectory by its id, so one it cannot build leaves
the others usable; likewise the reader skips a trajectory it does not read (a
``file_trajectory``, an element it does not know, nonzero angle velocities of a spherical
joint), with a :class:`~taut.errors.TautWarning` naming it, and asking for it by id raises a
:class:`~taut.errors.TrajectoryError` saying why (:class:`CasprTrajectories`).  Malformed
trajectories (a missing id, numbers that are not, times that do not increase) are errors.
Operational-space trajectories (``<operational_trajectories>``) are not read.

References
----------
.. [1] D. Lau, J. Eden, Y. Tan, D. Oetomo, "CASPR: A comprehensive cable-robot analysis and
   simulation platform for the research of cable-driven parallel robots", IEEE/RSJ
   International Conference on Intelligent Robots and Systems (IROS), 2016.
   (docs/references.bib: lau2016)
"""

from __future__ import annotations

import math
import warnings
import xml.etree.ElementTree as ET
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from taut.errors import TautWarning, TrajectoryError
from taut.model import BODIES_SUFFIX, Robot, parse_xml, read_caspr, read_text
from taut.motion._trajectory import Motion, trajectory_from_waypoints
from taut.motion._vias import average_velocities
from taut.motion._waypoints import angle_columns, unwrap_angles, validate_waypoints

__all__ = ["KINDS", "TRAJECTORIES_SUFFIX", "CasprTrajectories", "CasprTrajectory", "read_caspr_trajectories"]

TRAJECTORIES_SUFFIX = "_trajectories.xml"

#: CASPR's joint trajectory elements and taut's time law for each.
KINDS = {
    "linear_spline_trajectory": "linear",
    "cubic_spline_trajectory": "cubic",
    "quintic_spline_trajectory": "quintic",
    "cubic_spline_average_velocity_trajectory": "cubic",
    "parabolic_blend_trajectory": "trapezoidal",
}

#: CASPR's joint trajectory elements taut does not read, and what they are.
UNREAD = {"file_trajectory": "samples read from a .traj file"}

_SPHERICAL = (
    "CASPR's spherical joints take only zero angle velocities and accelerations at the points "
    "(CASPR refuses this trajectory too)"
)


@dataclass(frozen=True)
class CasprTrajectory:
    """One trajectory of a CASPR file: its ``id``, CASPR element ``kind``, the
    :class:`Motion` and CASPR's sampling ``time_step`` [s].  ``motion.sample(1 / time_step)``
    gives CASPR's samples when the points' times are whole multiples of ``time_step`` (CASPR
    restarts its grid ``t_s : time_step : t_e`` at every point; taut's grid runs on from 0
    and ends at the end point)."""

    id: str
    kind: str
    motion: Motion
    time_step: float


class CasprTrajectories(Mapping[str, CasprTrajectory]):
    """The trajectories of a CASPR file that taut reads, by id (a read-only mapping), and
    ``skipped``: the id of each trajectory it does not read and why.  Asking for a skipped
    id raises :class:`~taut.errors.TrajectoryError` with the reason; an id the file does not
    have raises ``KeyError``."""

    def __init__(self, source: str, trajectories: dict[str, CasprTrajectory], skipped: dict[str, str]) -> None:
        self.source = source
        self._trajectories = dict(trajectories)
        self.skipped = dict(skipped)

    def __getitem__(self, key: str) -> CasprTrajectory:
        if key in self._trajectories:
            return self._trajectories[key]
        if key in self.skipped:
            raise TrajectoryError(f"{self.source}: trajectory {key!r} is not read: {self.skipped[key]}")
        raise KeyError(key)

    def __contains__(self, key: object) -> bool:
        return key in self._trajectories

    def __iter__(self) -> Iterator[str]:
        return iter(self._trajectories)

    def __len__(self) -> int:
        return len(self._trajectories)

    def __repr__(self) -> str:
        return f"CasprTrajectories({self.source!r}, read={list(self)}, skipped={list(self.skipped)})"


class _Unsupported(Exception):
    """A trajectory the reader skips (the message says why)."""


def _vector(point: ET.Element, tag: str, n: int, where: str) -> np.ndarray | None:
    found = point.findall(tag)
    if not found:
        return None
    if len(found) > 1:
        raise TrajectoryError(f"{where}: <{tag}> is given {len(found)} times")
    text = found[0].text or ""
    try:
        values = np.array([float(x) for x in text.split()])
    except ValueError:
        raise TrajectoryError(f"{where} <{tag}>: expected numbers, got {text!r}") from None
    if len(values) != n:
        raise TrajectoryError(f"{where} <{tag}>: expected {n} numbers (the robot's pose size), got {len(values)}")
    if not np.all(np.isfinite(values)):
        raise TrajectoryError(f"{where} <{tag}>: expected finite numbers, got {text!r}")
    return values


def _number(value: str | None, what: str, *, positive: bool) -> float:
    try:
        x = float(value) if value is not None else math.nan
    except ValueError:
        x = math.nan
    if not math.isfinite(x) or (positive and x <= 0):
        raise TrajectoryError(f"{what} must be a number{' > 0' if positive else ''}, got {value!r}")
    return x


def _required(vectors: list[np.ndarray | None], tag: str, where: str) -> np.ndarray:
    missing = [k for k, v in enumerate(vectors) if v is None]
    if missing:
        raise TrajectoryError(f"{where}: point {missing[0] + 1} has no <{tag}>")
    return np.array(vectors)


def _still(vectors: np.ndarray, robot: Robot, axis: bool) -> None:
    """Refuse nonzero angle velocities or accelerations of a spherical joint."""
    if axis and np.any(vectors[:, angle_columns(robot)] != 0):
        raise _Unsupported(_SPHERICAL)


def _read_one(elem: ET.Element, robot: Robot, flip: bool, unwrap: bool, source: str) -> CasprTrajectory:
    ident = elem.get("id") or ""
    where = f"{source} <{elem.tag} id={ident!r}>"
    if not ident:
        raise TrajectoryError(f"{source} <{elem.tag}>: attribute id is missing")
    definition = elem.get("time_definition")
    if definition not in ("relative", "absolute"):
        raise TrajectoryError(f"{where}: time_definition must be 'relative' or 'absolute', got {definition!r}")
    time_step = _number(elem.get("time_step"), f"{where}: time_step", positive=True)
    points_el = elem.findall("points")
    if len(points_el) != 1:
        raise TrajectoryError(f"{where}: expected one <points>, got {len(points_el)}")
    points = [p for p in points_el[0] if p.tag == "point"]
    n = robot.pose_size
    q, qd, qdd, times, blend_times = [], [], [], [0.0], []
    for k, p in enumerate(points):
        pw = f"{where} point {k + 1}"
        value = _vector(p, "q", n, pw)
        if value is None:
            raise TrajectoryError(f"{pw}: <q> is missing")
        q.append(value)
        qd.append(_vector(p, "q_dot", n, pw))
        qdd.append(_vector(p, "q_ddot", n, pw))
        if k > 0:
            relative = definition == "relative"
            t = _number(p.get("time"), f"{pw}: time", positive=relative)
            times.append(times[-1] + t if relative else t)
            blend_times.append(p.get("blend_time"))
        elif p.get("blend_time") is not None:
            raise TrajectoryError(f"{pw}: blend_time belongs to the segment that ends at a point; the first ends none")
    if len(points) < 2:
        raise TrajectoryError(f"{where}: a trajectory needs at least 2 points, got {len(points)}")
    W = validate_waypoints(robot, q, where)
    sign = np.ones(n)
    if flip:
        sign[2] = -1.0
    W = W * sign
    if unwrap:
        W = unwrap_angles(robot, W)
    axis = robot.dimension == 3 and not robot.is_point_mass
    velocities = accelerations = blends = None
    if elem.tag == "cubic_spline_trajectory":
        velocities = _required(qd, "q_dot", where) * sign
        _still(velocities, robot, axis)
    elif elem.tag == "quintic_spline_trajectory":
        velocities = _required(qd, "q_dot", where) * sign
        accelerations = _required(qdd, "q_ddot", where) * sign
        _still(velocities, robot, axis)
        _still(accelerations, robot, axis)
    elif elem.tag == "cubic_spline_average_velocity_trajectory":
        ends = _required([qd[0], qd[-1]], "q_dot", f"{where} (first and last points)") * sign
        velocities = average_velocities(np.array(times), W, ends[0], ends[-1])
        _still(velocities, robot, axis)
    elif elem.tag == "parabolic_blend_trajectory":
        default = elem.get("blend_time_default")
        blends = []
        for k, (tb_text, h) in enumerate(zip(blend_times, np.diff(times))):
            what = f"{where}: blend time of segment {k + 1}"
            tb = _number(tb_text if tb_text is not None else default, what, positive=True)
            if h > 0 and tb > h / 2:
                raise TrajectoryError(f"{what}, {tb:g} s, is more than half the segment's duration {h:g} s")
            blends.append(tb / h if h > 0 else 0.5)
    motion = trajectory_from_waypoints(
        robot,
        W,
        times=times,
        law=KINDS[elem.tag],
        velocities=velocities,
        accelerations=accelerations,
        blend=blends,
        unwrap=False,
        rotation="axis" if axis else "angles",
    )
    return CasprTrajectory(ident, elem.tag, motion, time_step)


def read_caspr_trajectories(
    path: str | Path, bodies: str | Path | None = None, *, unwrap: bool = False
) -> tuple[Robot, CasprTrajectories]:
    """The robot of the CASPR model and the joint-space trajectories of its
    ``X_trajectories.xml`` ``path``, by id (see the module docstring).

    ``bodies`` is the model's ``X_bodies.xml`` (default: the one beside ``path``), read by
    :func:`taut.model._caspr.read_caspr`.  A trajectory taut does not read is skipped with a
    :class:`~taut.errors.TautWarning` and listed in the result's ``skipped``.  Raises
    :class:`~taut.errors.TrajectoryError` for a malformed trajectory, or a file without one
    that taut reads (and the model's errors for the model)."""
    path = Path(path)
    if bodies is None:
        if not path.name.lower().endswith(TRAJECTORIES_SUFFIX):
            raise TrajectoryError(f"{path}: a CASPR trajectory file is named X{TRAJECTORIES_SUFFIX}; give bodies=")
        bodies = path.with_name(path.name[: -len(TRAJECTORIES_SUFFIX)] + BODIES_SUFFIX)
    bodies = Path(bodies)
    robot = read_caspr(bodies)
    joints = [j.get("type") for j in parse_xml(read_text(bodies), str(bodies)).iter("joint")]
    flip = joints == ["PLANAR_XZ"]
    source = str(path)
    root = parse_xml(read_text(path), source)
    if root.tag != "trajectories":
        raise TrajectoryError(f"{source}: expected a <trajectories> CASPR trajectory file, got <{root.tag}>")
    out: dict[str, CasprTrajectory] = {}
    skipped: dict[str, str] = {}
    for group in root.findall("joint_trajectories"):
        for elem in group:
            ident = elem.get("id") or ""
            if ident and (ident in out or ident in skipped):
                raise TrajectoryError(f"{source}: two trajectories have the id {ident!r}")
            try:
                if elem.tag in UNREAD:
                    raise _Unsupported(f"<{elem.tag}> ({UNREAD[elem.tag]}) is not read by taut")
                if elem.tag not in KINDS:
                    raise _Unsupported(f"unknown joint trajectory <{elem.tag}> (taut reads {', '.join(KINDS)})")
                out[ident] = _read_one(elem, robot, flip, unwrap, source)
            except _Unsupported as e:
                skipped[ident] = str(e)
                warnings.warn(
                    f"{source}: skipped <{elem.tag} id={ident!r}>: {e}; the other trajectories are read",
                    TautWarning,
                    stacklevel=2,
                )
    if not out:
        if skipped:
            raise TrajectoryError(f"{source}: no trajectory taut reads ({'; '.join(skipped.values())})")
        raise TrajectoryError(f"{source}: no <joint_trajectories> (operational-space trajectories are not read)")
    return robot, CasprTrajectories(source, out, skipped)
