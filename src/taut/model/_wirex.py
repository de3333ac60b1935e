"""WireX robot files (``.wcrfx``): read into a :class:`~taut.model.Robot`, and written from one.

WireX (A. Pott, Fraunhofer IPA, MIT licence) stores a robot as XML: ``<models>`` holds
``<robot motionpattern=...>`` with one ``<chain>`` per cable in ``<geometry>`` (a ``<base>``
point ``a_i`` with the frame of its winch, ``a11 … a33``, and the pulley ``radius``; a
``<platform>`` point ``b_i`` with its frame), a ``<platform mass=...>`` with its
``<inertiatensor>`` and ``<centerofgravity>``, and an ``<application min_cable_load
max_cable_load>``.  The mapping follows WireX's own reader and kinematics (``WireLib``:
``CRobotData::getXmlNode``, ``CKinematics``, ``CStructureMatrix``):

* **Geometry.** WireX's standard model computes ``l_i = ‖r + R b_i − a_i‖`` and the
  structure matrix ``[u_i; R b_i × u_i]`` with ``u_i`` from the platform to ``a_i``, which is
  taut's model (``docs/architecture.md`` §2.4): ``<base>`` is the exit point, ``<platform>``
  the anchor.  The frames ``a11 … a33`` enter only WireX's pulley kinematics (the winch frame's
  z axis is the swivel axis of the pulley); they are read and checked to be rotations.
  With pulleys the lengths and directions are those of the pulley kinematics (below).
* **Motion patterns.** ``3R3T`` is taut's spatial rigid platform (angles ``xyz-fixed``: the
  file has no angle convention); ``1R2T`` the planar rigid platform in WireX's xy plane;
  ``3T`` and ``2T`` the spatial and planar point mass, with each anchor offset folded into its
  exit point (``a_i − b_i``, exact for a platform that only translates).  Planar patterns need
  every cable in a plane of motion (``<base>`` z = ``<platform>`` z), or the planar lengths
  would not be WireX's.  ``1T`` (a point on a line) and ``2R3T`` (five degrees of freedom)
  have no taut platform and raise :class:`~taut.errors.UnsupportedRobotError`: WireX itself
  gives them kinematics only (``CStructureMatrix::getStructureMatrix`` supports ``3R3T``,
  ``3T``, ``2T`` and ``1R2T``; a ``2R3T`` or ``1T`` robot has 5 or 1 rows, ``CRobotData::
  setMotionPattern``).  A taut point mass in a plane or in space has the lengths of ``1T``
  on its line, but its statics would balance forces across the line too, which the guide of a
  ``1T`` robot takes.  taut's 6-DOF rigid platform has the lengths of ``2R3T`` (for a beam,
  the anchors on the axis the pattern leaves free, any rotation about that axis), but its
  structure matrix keeps the sixth row, the moment about that axis (zero for a beam), so that
  wrench-closure never holds and wrench-feasibility and forward kinematics ask for the
  control of a rotation the robot does not have.  Neither is exact, so neither is done.
* **Pulleys.** WireX's pulley kinematics (``CKinematics::doInverseKinematicsPulleyEx``) wind
  the cable over a pulley of radius ``r`` that swivels about the winch frame's z axis
  through ``<base>``: the anchor ``b`` in the winch frame ``A`` is ``Aᵀ(b − base)``, the
  pulley centre lies ``r`` from the axis towards the anchor, the wrap angle is
  ``β = acos(l_f/ρ) + acos(b_z/ρ)`` and the tangent point ``base + A R_z(γ)((r, 0, 0) +
  R_y(β)(−r, 0, 0))`` is ``base`` itself at ``β = 0``.  That is taut's swivelling pulley
  (``cables[].swivel``, ``taut.kinematics._swivel``) with ``exit`` = ``<base>``, ``axis`` = the
  frame's z axis (third column of ``a11 … a33``) and ``radius`` = ``r``; a ``<base>`` without
  ``radius`` means WireX's default, 0.1 m.  WireX's two-``arccos`` wrap angle equals taut's
  for anchors at least ``r`` from the axis (closer ones WireX's formula gets wrong).  On a
  planar pattern (``2T``, ``1R2T``) the pulley model stays in the plane of motion exactly
  when the swivel axis lies in it (``a33 = 0``): the axis is then taut's planar swivel axis
  ``(a13, a23)``.  A planar pulley whose axis leaves the plane (WireX's default identity
  frame has it normal to the plane) lifts the cable out of the plane and raises
  :class:`~taut.errors.UnsupportedRobotError` naming the chain.  WireX itself computes the
  structure matrix of a planar pattern without its pulleys (``getStructureMatrix`` uses
  pulleys for ``3R3T`` only); taut's uses the tangent point, the derivative of the lengths
  WireX's pulley kinematics gives.  ``pulleys="points"`` asks for WireX's
  standard model instead, each pulley taken as its fixed point, which the robot's
  ``description`` then states.  Radius 0 is that model exactly.
* **Mass properties.** ``mass`` → ``platform.mass``; ``<centerofgravity>`` (body frame) →
  ``platform.wrench_point``; the inertia tensor about the centre of gravity (WireX's
  Newton–Euler wrench uses it so) → ``platform.inertia``: all nine entries for ``3R3T`` (WireX
  reads a tensor only when all nine are there), ``Izz`` for ``1R2T``.  An incomplete tensor is
  not imported, and the description says so.  Gravity is WireX's, 9.81 m/s² along −z (the
  weight in ``CRobotDocument::doElastoGeometricalForwardKinematics``): taut's
  spatial default, and normal to the plane of the planar patterns (``platform.gravity`` =
  ``(0, 0)``).  A point mass has no inertia and no moment arm.
* **Cable loads.** ``min_cable_load`` and ``max_cable_load`` bound every cable's tension;
  without them the bounds are taut's ``[0, ∞)``, as the description says.

Malformed XML, missing elements or attributes, non-finite numbers and inconsistent chain ids
raise :class:`~taut.errors.RobotFileError` with one line naming the file and the element.
Document type declarations (and with them entity expansion) are refused before parsing.

References
----------
.. [1] A. Pott, WireX: scientific software for analysis and design of cable-driven parallel
   robots, 2006–2019, MIT licence; ``WireLib/RobotData.cpp``, ``Kinematics.cpp``,
   ``StructureMatrix.cpp``. (docs/references.bib: wirex)
.. [2] A. Pott, "Cable-Driven Parallel Robots: Theory and Application", Springer Tracts in
   Advanced Robotics 120, Springer, 2018. (docs/references.bib: pott2018)
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path
from typing import Literal
from xml.parsers import expat

import numpy as np
from pydantic import ValidationError

from taut.errors import RobotFileError, UnsupportedRobotError
from taut.geometry import axis_frames
from taut.model._io import read_bytes, write_file
from taut.model._limits import MAX_MAGNITUDE
from taut.model._messages import validation_message
from taut.model._robot import STANDARD_GRAVITY, Robot

#: WireX's motion patterns (``CRobotData::MotionPatternType``) and their degrees of freedom.
MOTION_PATTERNS = {"1T": 1, "2T": 2, "3T": 3, "1R2T": 3, "2R3T": 5, "3R3T": 6}

#: Pulley radius [m] WireX assumes when a ``<base>`` gives none (``CRobotData::getXmlNode``).
DEFAULT_PULLEY_RADIUS = 0.1

#: How to take pulleys of radius > 0: as taut swivelling pulleys (WireX's pulley kinematics),
#: or each as its fixed point (WireX's standard model).
PulleyModel = Literal["swivel", "points"]

#: Order of the nine frame entries in a ``<base>`` or ``<platform>`` tag: ``aRC`` is row R, column C.
FRAME_KEYS = ("a11", "a12", "a13", "a21", "a22", "a23", "a31", "a32", "a33")

#: The inertia tensor's entries, row by row, as WireX names them.
INERTIA_KEYS = ("Ixx", "Ixy", "Ixz", "Iyx", "Iyy", "Iyz", "Izx", "Izy", "Izz")

#: Largest deviation of ``RᵀR`` from the identity accepted for a frame (files print 6 decimals).
FRAME_TOLERANCE = 1e-5


@dataclass(frozen=True)
class WirexChain:
    """One ``<chain>``: cable ``number`` from ``base`` (frame ``base_frame``, pulley
    ``pulley_radius``) to the platform point ``platform`` (frame ``platform_frame``)."""

    number: int
    base: tuple[float, float, float]
    base_frame: np.ndarray  #: ``(3, 3)`` rotation of the winch frame
    pulley_radius: float
    platform: tuple[float, float, float]
    platform_frame: np.ndarray  #: ``(3, 3)`` rotation of the anchor frame


@dataclass(frozen=True)
class WirexModel:
    """The content of a ``.wcrfx`` file that taut uses, as the file states it."""

    name: str
    description: str
    author: str
    motion_pattern: str
    chains: tuple[WirexChain, ...]
    mass: float | None
    center_of_gravity: tuple[float, float, float] | None
    inertia: dict[str, float]  #: the entries of ``<inertiatensor>`` the file gives
    cable_loads: tuple[float | None, float | None]  #: ``min_cable_load``, ``max_cable_load``


def _refuse_doctype(raw: bytes, source: str) -> None:
    """Refuse a document type declaration, in any encoding, before ElementTree expands its entities."""

    def refuse(*_: object) -> None:
        raise RobotFileError(
            f"{source}: XML document type declarations and entities are refused (a WireX file has none)"
        )

    scanner = expat.ParserCreate()
    scanner.StartDoctypeDeclHandler = refuse
    scanner.EntityDeclHandler = refuse
    try:
        scanner.Parse(raw, True)
    except expat.ExpatError as exc:
        raise RobotFileError(f"{source}: not well-formed XML at line {exc.lineno}, column {exc.offset + 1}") from None


def _tag(element: ET.Element, chain: int | None = None) -> str:
    where = f'<chain id="{chain}"> ' if chain is not None else ""
    return f"{where}<{element.tag}>"


def _number(element: ET.Element, key: str, source: str, where: str) -> float | None:
    """The attribute ``key`` as a finite number within taut's limits; None when absent."""
    text = element.get(key)
    if text is None:
        return None
    try:
        value = float(text.strip())
    except ValueError:
        raise RobotFileError(f"{source}: {where} {key}: expected a number, got {text!r}") from None
    if not math.isfinite(value):
        raise RobotFileError(f"{source}: {where} {key}: expected a finite number, got {text!r}")
    if abs(value) > MAX_MAGNITUDE:
        raise RobotFileError(
            f"{source}: {where} {key}: {value:.3g} is out of range (taut takes up to {MAX_MAGNITUDE:g})"
        )
    return value


def _required(element: ET.Element, key: str, source: str, where: str) -> float:
    value = _number(element, key, source, where)
    if value is None:
        raise RobotFileError(f"{source}: {where}: attribute {key} is missing")
    return value


def _point(element: ET.Element, source: str, where: str) -> tuple[float, float, float]:
    return (
        _required(element, "x", source, where),
        _required(element, "y", source, where),
        _required(element, "z", source, where),
    )


def _frame(element: ET.Element, source: str, where: str) -> np.ndarray:
    """The rotation ``a11 … a33`` of a tag: identity when none is given (as in WireX), all
    nine entries otherwise, orthonormal with determinant +1."""
    values = [_number(element, key, source, where) for key in FRAME_KEYS]
    given = [v for v in values if v is not None]
    if not given:
        return np.eye(3)
    if len(given) != 9:
        missing = [k for k, v in zip(FRAME_KEYS, values, strict=True) if v is None]
        raise RobotFileError(
            f"{source}: {where}: frame entries {', '.join(missing)} are missing (give all nine or none)"
        )
    R = np.array(given, dtype=float).reshape(3, 3)
    if np.abs(R.T @ R - np.eye(3)).max() > FRAME_TOLERANCE or np.linalg.det(R) < 0:
        raise RobotFileError(f"{source}: {where}: a11 … a33 is not a rotation matrix")
    return R


def _child(parent: ET.Element, tag: str, source: str, where: str) -> ET.Element:
    found = parent.find(tag)
    if found is None:
        raise RobotFileError(f"{source}: {where}: element <{tag}> is missing")
    return found


def _chain(element: ET.Element, index: int, source: str) -> WirexChain:
    ident = element.get("id")
    number = index
    if ident is not None:
        try:
            number = int(ident.strip())
        except ValueError:
            raise RobotFileError(f'{source}: <chain id="{ident}">: id must be an integer') from None
    where = f'<chain id="{ident}">' if ident is not None else f"<chain> number {index}"
    base = _child(element, "base", source, where)
    platform = _child(element, "platform", source, where)
    base_where, platform_where = f"{where} <base>", f"{where} <platform>"
    radius = _number(base, "radius", source, base_where)
    if radius is not None and radius < 0:
        raise RobotFileError(f"{source}: {base_where} radius: a pulley radius must be >= 0, got {radius}")
    return WirexChain(
        number=number,
        base=_point(base, source, base_where),
        base_frame=_frame(base, source, base_where),
        pulley_radius=DEFAULT_PULLEY_RADIUS if radius is None else radius,
        platform=_point(platform, source, platform_where),
        platform_frame=_frame(platform, source, platform_where),
    )


def parse_wirex(raw: bytes, source: str = "<wcrfx>") -> WirexModel:
    """Parse the bytes of a ``.wcrfx`` file (the first ``<robot>`` of its ``<models>``, as
    WireX reads it) into a :class:`WirexModel`.

    Raises
    ------
    RobotFileError
        Malformed XML, a document type declaration, a missing element or attribute, a
        non-finite number, duplicate chain ids or an unknown motion pattern.
    """
    _refuse_doctype(raw, source)
    try:
        root = ET.fromstring(raw)
    except ET.ParseError as exc:  # expat accepted it above: only a defect ElementTree alone sees
        raise RobotFileError(f"{source}: not well-formed XML: {exc}") from None
    if root.tag != "models":
        raise RobotFileError(f"{source}: the root element is <{root.tag}>, expected WireX's <models>")
    robot = _child(root, "robot", source, "<models>")
    pattern = robot.get("motionpattern", "3R3T").strip()
    if pattern not in MOTION_PATTERNS:
        raise RobotFileError(
            f"{source}: <robot> motionpattern: unknown motion pattern {pattern!r}; WireX knows {', '.join(MOTION_PATTERNS)}"
        )
    geometry = _child(robot, "geometry", source, "<robot>")
    elements = geometry.findall("chain")
    if not elements:
        raise RobotFileError(f"{source}: <geometry>: no <chain> elements (one per cable)")
    chains = tuple(_chain(e, i, source) for i, e in enumerate(elements, 1))
    seen: dict[int, int] = {}
    for i, c in enumerate(chains, 1):
        if c.number in seen:
            raise RobotFileError(f'{source}: <chain id="{c.number}"> appears twice (chains {seen[c.number]} and {i})')
        seen[c.number] = i

    mass = center = None
    inertia: dict[str, float] = {}
    plat = robot.find("platform")
    if plat is not None:
        mass = _number(plat, "mass", source, "<platform>")
        if mass is not None and mass < 0:
            raise RobotFileError(f"{source}: <platform> mass: expected a mass >= 0, got {mass}")
        cog = plat.find("centerofgravity")
        center = _point(cog, source, "<platform> <centerofgravity>") if cog is not None else None
        tensor = plat.find("inertiatensor")
        if tensor is not None:
            for key in INERTIA_KEYS:
                value = _number(tensor, key, source, "<platform> <inertiatensor>")
                if value is not None:
                    inertia[key] = value
    loads: tuple[float | None, float | None] = (None, None)
    application = robot.find("application")
    if application is not None:
        lo = _number(application, "min_cable_load", source, "<application>")
        hi = _number(application, "max_cable_load", source, "<application>")
        if lo is not None and lo < 0:
            raise RobotFileError(f"{source}: <application> min_cable_load: expected a load >= 0, got {lo}")
        if lo is not None and hi is not None and lo > hi:
            raise RobotFileError(f"{source}: <application>: min_cable_load {lo} > max_cable_load {hi}")
        if hi is not None and hi < 0:
            raise RobotFileError(f"{source}: <application> max_cable_load: expected a load >= 0, got {hi}")
        loads = (lo, hi)
    return WirexModel(
        name=(robot.get("name") or "").strip(),
        description=(robot.get("description") or "").strip(),
        author=(robot.get("author") or "").strip(),
        motion_pattern=pattern,
        chains=chains,
        mass=mass,
        center_of_gravity=center,
        inertia=inertia,
        cable_loads=loads,
    )


def _inertia(model: WirexModel, source: str, planar: bool, notes: list[str]) -> tuple[float, ...] | None:
    """taut's ``platform.inertia`` from the file's tensor, or None with a note why."""
    given = model.inertia
    if not given:
        return None
    if model.mass is None or model.mass == 0:
        notes.append("inertia tensor not imported: the platform has no mass")
        return None
    if planar:
        if "Izz" in given:
            return (given["Izz"],)
        notes.append(f"inertia tensor not imported: a planar platform needs Izz, the file gives {', '.join(given)}")
        return None
    if len(given) < 9:
        notes.append(f"inertia tensor not imported: WireX needs all nine entries, the file gives {', '.join(given)}")
        return None
    I = np.array([given[k] for k in INERTIA_KEYS]).reshape(3, 3)
    if np.abs(I - I.T).max() > 1e-9 * max(1.0, float(np.abs(I).max())):
        raise RobotFileError(f"{source}: <platform> <inertiatensor>: not symmetric (Ixy = Iyx, Ixz = Izx, Iyz = Izy)")
    return (I[0, 0], I[1, 1], I[2, 2], I[0, 1], I[0, 2], I[1, 2])


def wirex_robot(model: WirexModel, source: str = "<wcrfx>", *, pulleys: PulleyModel = "swivel") -> Robot:
    """The taut robot of a parsed WireX file (the mapping is in this module's docstring).

    Raises
    ------
    UnsupportedRobotError
        A motion pattern taut has no platform for (``1T``, ``2R3T``), a planar pattern with a
        cable out of its plane, or a pulley of radius > 0 on a planar pattern whose swivel axis
        leaves the plane, without ``pulleys="points"``.
    RobotFileError
        Data that do not make a valid taut robot (e.g. two identical cables).
    """
    pattern = model.motion_pattern
    if pattern == "1T":
        raise UnsupportedRobotError(
            f"{source}: motion pattern 1T (a point moving on a line) has no taut platform: taut's point masses "
            "move in a plane or in space, where the cables would also have to balance every force across the "
            "line, which 1T's guide takes; the lengths would agree, the structure matrix (1 row in 1T) and "
            "every wrench and workspace analysis would not"
        )
    if pattern == "2R3T":
        raise UnsupportedRobotError(
            f"{source}: motion pattern 2R3T (5 degrees of freedom: the rotation about the platform's own axis is "
            "not controlled) has no taut platform: taut's spatial rigid platform has 6, and read so its "
            "structure matrix would keep a sixth row (the moment about that axis, zero for a beam) that "
            "wrench-closure, wrench-feasibility and forward kinematics would ask the cables to control"
        )
    notes: list[str] = []
    planar = pattern in ("2T", "1R2T")
    pulleyed = [c for c in model.chains if c.pulley_radius > 0]
    swivels = pulleys == "swivel" and bool(pulleyed)
    if swivels and planar:
        for c in pulleyed:
            axis = c.base_frame[:, 2]
            if axis[2] != 0:
                raise UnsupportedRobotError(
                    f'{source}: <chain id="{c.number}"> <base>: the swivelling pulley (radius {c.pulley_radius:g} m) '
                    f"turns about the winch frame's z axis ({', '.join(f'{x:g}' for x in axis)}), which leaves the "
                    f"xy plane of motion of {pattern}: the cable would leave the plane over the pulley; taut's "
                    "planar swivels turn about in-plane axes (a13, a23 in the plane, a33 = 0); in Python, "
                    "read_wirex(path, pulleys='points') takes each pulley as its fixed point, WireX's standard model"
                )
    if pulleyed and not swivels:
        radii = sorted({c.pulley_radius for c in pulleyed})
        notes.append(
            f"APPROXIMATION: the swivelling pulleys (radius {', '.join(f'{r:g}' for r in radii)} m) of "
            f"{len(pulleyed)} cables are taken as their fixed points (WireX's standard model, not its pulley "
            "kinematics): lengths and directions differ from the pulley model by about the radius"
        )
    point_mass = pattern in ("2T", "3T")
    d = 2 if planar else 3
    if planar:
        for c in model.chains:
            if c.base[2] != c.platform[2]:
                raise UnsupportedRobotError(
                    f'{source}: <chain id="{c.number}">: motion pattern {pattern} moves in the xy plane, but this '
                    f"cable leaves it (base z = {c.base[2]:g}, platform z = {c.platform[2]:g}); taut's planar "
                    "robots have every cable in the plane"
                )
    lo, hi = model.cable_loads
    tension = (0.0 if lo is None else lo, math.inf if hi is None else hi)
    if lo is None and hi is None:
        notes.append("the file gives no <application> cable loads: tensions bounded by [0, inf)")
    cables = []
    for c in model.chains:
        base, anchor = np.array(c.base[:d]), np.array(c.platform[:d])
        exit_point = base - anchor if point_mass else base
        cable: dict[str, object] = {"name": f"chain {c.number}", "exit": exit_point.tolist(), "tension": tension}
        if not point_mass:
            cable["anchor"] = anchor.tolist()
        if swivels and c.pulley_radius > 0:
            cable["swivel"] = {"axis": c.base_frame[:d, 2].tolist(), "radius": c.pulley_radius}
        cables.append(cable)
    if point_mass and any(any(c.platform[:d]) for c in model.chains):
        notes.append("a translating platform: each anchor offset is folded into its exit point (a_i - b_i)")
    platform: dict[str, object] = {"kind": "point-mass" if point_mass else "rigid"}
    mass = model.mass if model.mass else None
    if mass is not None:
        platform["mass"] = mass
        if planar:
            platform["gravity"] = (0.0, 0.0)
            notes.append("WireX's gravity acts along -z, normal to the plane of motion: no in-plane weight")
    if point_mass and (model.center_of_gravity is not None or model.inertia):
        notes.append("a point mass: the centre of gravity and inertia tensor do not enter its statics, not imported")
    if not point_mass:
        if model.center_of_gravity is not None:
            platform["wrench_point"] = model.center_of_gravity[:d]
        inertia = _inertia(model, source, planar, notes)
        if inertia is not None:
            platform["inertia"] = inertia
    name = model.name or Path(source).stem
    text = model.description + ("." if model.description and not model.description.endswith(".") else "")
    description = " ".join(
        [f"WireX {pattern} robot." if not text else text, *(n[0].upper() + n[1:] + "." for n in notes)]
    )
    data: dict[str, object] = {
        "name": name,
        "description": description,
        "source": f"WireX file {Path(source).name}" + (f" by {model.author}" if model.author else ""),
        "dimension": d,
        "platform": platform,
        "cables": cables,
    }
    try:
        return Robot.model_validate(data)
    except ValidationError as exc:
        raise RobotFileError(validation_message(source, exc).replace("\n", "; ")) from None


def read_wirex(path: str | Path, *, pulleys: PulleyModel = "swivel") -> Robot:
    """Read a WireX ``.wcrfx`` robot file (see the module docstring for the mapping).

    Parameters
    ----------
    path
        The file; read only if it is a regular file of at most
        :data:`taut.model._io.MAX_FILE_BYTES`.
    pulleys
        ``"swivel"`` (default): a pulley of radius > 0 is a swivelling pulley
        (``cables[].swivel``) whose lengths are WireX's pulley kinematics; on a planar motion
        pattern its axis must lie in the plane, or it raises
        :class:`~taut.errors.UnsupportedRobotError`.  ``"points"``: each
        pulley is taken as its fixed point (WireX's standard model), and the robot's
        ``description`` states the approximation.

    Raises
    ------
    RobotFileError
        An unreadable or malformed file (one line naming the file and the element).
    UnsupportedRobotError
        A construct taut does not model (motion patterns 1T and 2R3T, out-of-plane cables of a
        planar pattern, pulleys of a planar pattern turning about an axis out of its plane
        without ``pulleys="points"``).

    References
    ----------
    .. [1] A. Pott, WireX, 2006–2019, ``WireLib/RobotData.cpp``. (docs/references.bib: wirex)
    """
    path = Path(path)
    return wirex_robot(parse_wirex(read_bytes(path), str(path)), str(path), pulleys=pulleys)


def _downward_load(robot: Robot) -> float | None:
    """``F`` when the robot's external wrench is a constant ``(0, 0, −F)`` force without moment,
    ``F > 0``, which WireX's gravity writes as the weight of a mass ``F / 9.81``; else None."""
    w = robot.platform.wrench
    if w is None or robot.dimension != 3 or robot.platform.mass is not None:
        return None
    if w[2] < 0 and all(v == 0 for k, v in enumerate(w) if k != 2):
        return -w[2]
    return None


def _refusal(robot: Robot) -> str | None:
    """What of ``robot`` a WireX file cannot hold, or None."""
    plat = robot.platform
    if plat.bodies:
        return "a jointed platform (platform.bodies)"
    if robot.obstacles or robot.installation_space is not None or robot.disallowed:
        return "an obstacle or installation space (obstacles, installation_space)"
    if plat.shape is not None:
        return "a platform shape (platform.shape)"
    for i, c in enumerate(robot.cables, 1):
        for field, value in (("pulley", c.pulley), ("stiffness", c.stiffness), ("length", c.length)):
            if value is not None:
                return f"cables[{i}].{field}"
        if c.radius > 0:
            return f"cables[{i}].radius (a cable radius)"
        if c.weight:
            return f"cables[{i}].weight (a sagging cable; WireX's cables are straight)"
        if c.via:
            return f"cables[{i}].via (a cable routed through via points; a WireX cable runs from its exit point to its anchor)"
    if len({c.tension for c in robot.cables}) > 1:
        return "different tension bounds per cable (WireX has one min_cable_load and max_cable_load)"
    lo, hi = robot.cables[0].tension
    if math.isinf(hi) and lo > 0:
        return "a lower tension bound without an upper one"
    if robot.dimension == 3 and not robot.is_point_mass and robot.orientation != "xyz-fixed":
        return f"orientation {robot.orientation} (a WireX file has no angle convention; taut reads it as xyz-fixed)"
    if plat.wrench is not None and _downward_load(robot) is None:
        return "platform.wrench other than a downward force (0, 0, -F) without moment"
    if plat.mass is not None and plat.gravity is not None:
        wirex_gravity = (0.0, 0.0) if robot.dimension == 2 else (0.0, 0.0, -STANDARD_GRAVITY)
        if tuple(plat.gravity) != wirex_gravity:
            return f"platform.gravity {list(plat.gravity)} (WireX's gravity is 9.81 m/s² along -z)"
    if plat.mass is not None and plat.gravity is None and robot.dimension == 2:
        return "a weight in the plane of a planar robot (WireX's gravity is along -z, normal to the plane)"
    return None


def _fmt(value: float) -> str:
    return repr(float(value))


def _set_point(element: ET.Element, point: np.ndarray | tuple[float, ...]) -> None:
    for key, value in zip("xyz", point, strict=True):
        element.set(key, _fmt(value))


def wirex_text(robot: Robot) -> str:
    """The WireX XML of ``robot`` (see :func:`write_wirex`)."""
    why = _refusal(robot)
    if why is not None:
        raise UnsupportedRobotError(f"write_wirex: {robot.name}: {why} has no WireX equivalent")
    d, point_mass = robot.dimension, robot.is_point_mass
    pattern = {(2, True): "2T", (2, False): "1R2T", (3, True): "3T", (3, False): "3R3T"}[(d, point_mass)]
    root = ET.Element("models", version="0.32")
    xrobot = ET.SubElement(root, "robot", name=robot.name, description=robot.description or "", motionpattern=pattern)
    geometry = ET.SubElement(xrobot, "geometry")
    pad = np.zeros((robot.n_cables, 3))
    exits, anchors = pad.copy(), pad.copy()
    exits[:, :d], anchors[:, :d] = robot.exits, robot.anchors
    identity = dict(zip(FRAME_KEYS, ("1.0", "0.0", "0.0", "0.0", "1.0", "0.0", "0.0", "0.0", "1.0"), strict=True))
    for i in range(robot.n_cables):
        chain = ET.SubElement(geometry, "chain", id=str(i + 1))
        base = ET.SubElement(chain, "base")
        _set_point(base, exits[i])
        swivel = robot.cables[i].swivel
        if swivel is None:
            base.attrib.update(identity)
            base.set("radius", "0.0")
        else:
            frame = axis_frames([*swivel.axis, 0.0][:3])
            base.attrib.update({k: _fmt(v) for k, v in zip(FRAME_KEYS, frame.ravel(), strict=True)})
            base.set("radius", _fmt(swivel.radius))
        anchor = ET.SubElement(chain, "platform")
        _set_point(anchor, anchors[i])
        anchor.attrib.update(identity)
    plat = robot.platform
    load = _downward_load(robot)
    mass = plat.mass if load is None else load / STANDARD_GRAVITY
    if mass is not None:
        xplat = ET.SubElement(xrobot, "platform", name="platform", mass=_fmt(mass))
        if plat.inertia is not None:
            tensor = ET.SubElement(xplat, "inertiatensor")
            if d == 2:
                tensor.set("Izz", _fmt(plat.inertia[0]))
            else:
                I = robot.inertia
                assert I is not None  # given with platform.inertia
                tensor.attrib.update({k: _fmt(v) for k, v in zip(INERTIA_KEYS, I.ravel(), strict=True)})
        if plat.wrench_point is not None and not point_mass:
            center = np.zeros(3)
            center[:d] = plat.wrench_point
            _set_point(ET.SubElement(xplat, "centerofgravity"), center)
    lo, hi = robot.cables[0].tension
    if not (lo == 0 and math.isinf(hi)):
        ET.SubElement(xrobot, "application", min_cable_load=_fmt(lo), max_cable_load=_fmt(hi))
    ET.indent(root)
    return ET.tostring(root, encoding="unicode") + "\n"


def write_wirex(robot: Robot, path: str | Path) -> None:
    """Write ``robot`` as a WireX ``.wcrfx`` file that :func:`read_wirex` reads back as the same robot.

    Written: the cables (``<chain>``: exit point as ``<base>`` with an identity frame and
    pulley radius 0, or for a swivelling pulley a winch frame whose z axis is the unit swivel
    axis and the pulley radius; anchor as ``<platform>``), the motion pattern (``3R3T`` spatial rigid,
    ``1R2T`` planar rigid, ``3T``/``2T`` point masses), the name and description, the mass,
    centre of gravity and inertia, and the tension bounds as ``<application>`` cable loads.
    A constant downward force ``(0, 0, −F)`` without moment is written as the weight of the
    mass ``F / 9.81`` under WireX's gravity, acting at ``platform.wrench_point``.  Not written:
    ``source``, ``reference`` and ``trajectories`` (documentation, not the robot model).

    Raises
    ------
    UnsupportedRobotError
        For what a WireX file cannot hold: jointed platforms, obstacles, platform shapes,
        planar exit pulleys, cable stiffness, radius, weight or length bounds, different tension bounds per cable,
        other wrenches or gravities, a weight in a planar robot's plane, and spatial rigid
        platforms whose angles are not ``xyz-fixed``.

    References
    ----------
    .. [1] A. Pott, WireX, 2006–2019, ``WireLib/RobotData.cpp`` (``CRobotData::setXmlNode``).
       (docs/references.bib: wirex)
    """
    write_file(path, wirex_text(robot))
