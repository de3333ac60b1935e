"""CASPR models: read a ``X_bodies.xml`` / ``X_cables.xml`` pair into a :class:`Robot`, and
write one.

CASPR [1]_ describes a robot by its links (``<link_rigid>``, each with a joint to its parent,
mass, centre of mass and inertia) in ``X_bodies.xml`` and by named cable sets in
``X_cables.xml`` beside it. taut reads the single-body models its platform represents:

- one link whose joint is ``SPATIAL_EULER_XYZ`` (pose ``x y z α β γ``, ``R = Rx(α) Ry(β) Rz(γ)``:
  taut's ``xyz-moving``), ``T_XYZ`` (a spatial point mass), ``PLANAR_XY`` / ``PLANAR_XZ`` /
  ``PLANAR_YZ`` (a planar rigid body) or ``P_XY`` / ``P_XZ`` (a planar point mass);
- two links, a massless ``T_XYZ`` link carrying a ``S_EULER_XYZ`` (``xyz-moving``) or
  ``S_FIXED_XYZ`` (``R = Rz(γ) Ry(β) Rx(α)``: taut's ``xyz-fixed``) link, all cables on the
  second: one rigid body with pose ``x y z α β γ``.

A rigid platform (``SPATIAL_EULER_XYZ``, the ``T_XYZ`` + ``S_*`` pair, ``PLANAR_*``) may carry
further links: a jointed platform (``platform.bodies``, like the adjustable platform of
Lieskovský 2020, or the multilink manipulators of Lau, Oetomo & Halgamuge 2013). Each further
link hangs from the platform link or a later link (a tree rooted at the platform). Its joint is
a one-degree-of-freedom joint, ``R_X``, ``R_Y``, ``R_Z``, ``R_AXIS`` (taut's ``revolute`` about
that axis) or ``P_X``, ``P_AXIS`` (``prismatic``), with ``origin`` = its ``<parent><location>``,
or a joint of several degrees of freedom, read as the chain of one-DOF joints CASPR composes it
of (its ``R_pe`` and ``r_rel``), through massless intermediate bodies named ``"link [R_X of
U_XY]"``: the universal joints ``U_XY`` (``Rx(q1) Ry(q2)``), ``U_YZ``, ``U_XZ``, the spherical
joints ``S_EULER_XYZ`` (``Rx Ry Rz``) and ``S_FIXED_XYZ`` (``Rz(q3) Ry(q2) Rx(q1)``: the chain
turns ``q3`` first, so taut's coordinates of that link come as ``q3, q2, q1``, stated in the
description), the translations ``P_XY``, ``P_XZ``, ``T_XYZ`` and ``SPATIAL_EULER_XYZ``.
``limits`` = ``q_min``/``q_max`` (one number per degree of freedom; CASPR's defaults ±π for
rotations when not given; an unbounded translation gets ±1e9 (``MAX_MAGNITUDE``), the largest
pose coordinate taut accepts, so the same poses), and the link's ``mass``, ``com_location`` and
inertia are the (last) body's ``mass``, ``com`` and ``inertia``. A joint with ``actuated="true"``
has a joint actuator on each of its degrees of freedom (``joint.actuator``), unbounded as
CASPR's are (its ``tau_min``/``tau_max`` are ±∞ and the files give none); without it the joint
is passive, moved by the cables across it. taut's pose is CASPR's ``q``: the platform's
coordinates, then the joint coordinates in link order (a further link's ``S_FIXED_XYZ`` in the
chain's order above). Cables attached to a further link get its
name as ``body`` (``link k`` for an unnamed or repeated name). On a planar platform a revolute
joint must turn about the plane's normal and a prismatic one move in the plane; the plane maps
as below, and a joint turning against taut's planar angles (``R_Y`` in the XZ plane) gets the
coordinate ``−q`` (stated in the description).

What does not map onto a platform carrying a tree of bodies is refused, with the reason: a
chain of links jointed to the ground (a multilink arm whose first link turns about a fixed
joint, like the ``R_Z`` chain of ``tests/model/fixtures/caspr/multilink``: taut's platform is
free), a link jointed to the ground or to the ``T_XYZ`` carrier
beside the platform (not reachable from the platform), the quaternion joints of CASPR's earlier
releases (``SPHERICAL``, ``SPATIAL``: four coordinates for three degrees of freedom), a
``PLANAR_*`` joint between two links, further links on a point-mass platform, an actuated
platform joint, a cable whose attachments do not start or end on the base (link 0): a
taut cable runs from a base exit to an anchor on a body, and an empty cable set (CASPR's arms
moved by their joints alone). Since every link has one parent, a
CASPR bodies file holds no closed chain. An unknown joint type is a
:class:`~taut.errors.RobotFileError` naming it.

A cable of more than two attachments (the cable-routing matrix of Lau et al. 2013, a cable
across several links) is a routed cable (``cables[].via``): its first attachment, on the base,
is the exit point, its last the anchor, and the ones between are via points, on the base
(``fixed``, relative to the platform's joint origin as the exits are) or on a link (in its
frame, as anchors are, ``com`` references shifted).  A cable listed from its link to the base
is read in the other direction.  Via points on a planar robot must lie in its plane.

CASPR's own models, as taut reads them (the files of ``tests/model/fixtures/caspr/real``, tested
there; every model and cable set, with the reasons for the refusals, in ``docs/caspr-models.md``):
CoGiRo (``SCDM``, a ``SPATIAL_EULER_XYZ`` platform, 8 cables) and KNTU_planar (a
``PLANAR_XY`` platform, 4 cables) load; SpiderBot_UR3 (``HCDM``: a ``SPATIAL_EULER_XYZ`` base
carrying a UR3 arm on six actuated ``R_Y``/``R_Z`` joints) loads with every cable set
(``CUcablerobot``, through swivelling pulleys; ``set_1``; ``set_IPAnema_inspired``), its six
joints with their actuators, and so does SpiderBot_X52 (its arm on four joints).

Planes map onto taut's ``(x, y)`` so that CASPR's gravity (9.81 m/s² along −z) stays along
taut's −y: ``PLANAR_XZ`` takes ``(x, y) = (X, Z)`` and ``θ = −θ_CASPR`` (CASPR rotates about
+Y, which points out of the XZ plane's taut frame backwards); ``PLANAR_YZ`` takes
``(x, y) = (Y, Z)`` and ``θ = θ_CASPR``; ``PLANAR_XY`` takes ``(X, Y)`` and ``θ_CASPR``, with
no gravity in the plane (CASPR's is perpendicular to it). The description of the robot states
the mapping. Only the moment of inertia about the plane's normal matters to planar motion.

Exit points are given relative to the platform's joint origin (the sum of the ``<parent>
<location>`` offsets), so that taut's pose is CASPR's ``q``. A point mass carries no rotation,
so an attachment ``r`` on it is exactly the point mass at the exit ``a − r``.

Cable attachments are relative to the joint (``attachment_reference="joint"``) or to the
centre of mass (``"com"``); inertia is given about the centre of mass (``ref="com"``) or the
joint (``ref="joint"``, shifted to the centre of mass: ``I_G = I_O − m(|c|² E − c cᵀ)``).
A ``force_max`` beyond ``MAX_MAGNITUDE`` (CASPR's models write "no bound" as 9999999999 N) is an
unbounded tension; a ``<force_error>`` (an error model of the cable force) is refused with
:class:`~taut.errors.UnsupportedRobotError`: taut's tensions are exact.
``cable_linear_spring``'s ``<K>`` is the cable's axial rigidity EA [N]: CASPR's stiffness is
``K / length`` [N/m]; taut's ``stiffness`` is EA. The platform link's ``q_min``/``q_max`` and
every ``q_initial`` bound and start CASPR's simulations and are not part of the robot.

A ``base_rotating_pulley`` (CASPR's ``BaseRotatingPulleyAttachment``, the first attachment of
a cable) is taut's swivelling pulley (``cables[].swivel``): ``fixed_location`` (in the base
frame) is the point where the cable runs onto the pulley, the exit; ``cable_entry_vector``, the
direction of the cable entering that point, is the swivel axis; ``pulley_radius`` the radius.
CASPR puts the pulley centre ``pulley_radius`` from the point, in the plane of the entry
vector and the anchor, normal to the entry vector towards the anchor, takes the tangent point
on the anchor's side and the arc ``r·acos(n₁·n₂)`` between the entry point and the tangent
point; its cable length (segment plus the attachment's ``length_offset``, the arc) is taut's
``r β + l_f`` for wraps up to half a turn (``acos`` cannot give more).  The writer writes a
swivel back as a ``base_rotating_pulley``.

Refused with :class:`UnsupportedRobotError`, never approximated: other pulley attachments
(``screw_base_rotating_pulley``), swivelling pulleys of planar robots whose entry vector
leaves the plane (in the plane, the pulley is taut's planar swivel), cables routed through
attachments that do not start or end on the base, chains of links from the ground,
actuated platform joints, the joints and cable types above, planar cables that leave the
plane; on writing, sagging cables (``cables[].weight``: CASPR's cable models are straight).

References
----------
.. [1] D. Lau, J. Eden, Y. Tan, D. Oetomo, "CASPR: A comprehensive cable-robot analysis and
   simulation platform for the research of cable-driven parallel robots", IEEE/RSJ
   International Conference on Intelligent Robots and Systems (IROS), 2016.
   (docs/references.bib: lau2016)
.. [2] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, §3.1–3.3.
   (docs/references.bib: lieskovsky2020)
.. [3] D. Lau, D. Oetomo, S. K. Halgamuge, "Generalized modeling of multilink cable-driven
   manipulators with arbitrary routing using the cable-routing matrix", IEEE Transactions on
   Robotics 29(5), 2013 (multilink cable robots, the cable-routing matrix).
   (docs/references.bib: lau2013)
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from taut.errors import RobotFileError, UnsupportedRobotError
from taut.model._limits import MAX_MAGNITUDE
from taut.model._robot import STANDARD_GRAVITY, Robot

#: CASPR's gravitational acceleration [m/s²], along its −z axis.
CASPR_GRAVITY = 9.81

#: How the name of a CASPR model's bodies file ends (``X_bodies.xml``) and of the cables file
#: beside it (``X_cables.xml``).
BODIES_SUFFIX = "_bodies.xml"
CABLES_SUFFIX = "_cables.xml"

_ENTITY = re.compile(r"<!ENTITY", re.IGNORECASE)


@dataclass(frozen=True)
class _Plane:
    """How a CASPR plane maps onto taut's planar ``(x, y, θ)``."""

    axes: tuple[int, int]
    normal: int
    in_plane_gravity: bool
    note: str


_PLANES = {
    "XY": _Plane((0, 1), 2, False, "taut (x, y, theta) = CASPR (x, y, theta); no gravity in the XY plane"),
    "XZ": _Plane((0, 2), 1, True, "taut (x, y, theta) = CASPR (x, z, -theta)"),
    "YZ": _Plane((1, 2), 0, True, "taut (x, y, theta) = CASPR (y, z, theta)"),
}

#: Single-link joints: (taut dimension, rigid?, plane or None, orientation convention).
_SINGLE = {
    "SPATIAL_EULER_XYZ": (3, True, None, "xyz-moving"),
    "T_XYZ": (3, False, None, "xyz-fixed"),
    "PLANAR_XY": (2, True, "XY", "xyz-fixed"),
    "PLANAR_XZ": (2, True, "XZ", "xyz-fixed"),
    "PLANAR_YZ": (2, True, "YZ", "xyz-fixed"),
    "P_XY": (2, False, "XY", "xyz-fixed"),
    "P_XZ": (2, False, "XZ", "xyz-fixed"),
}
_SPHERICAL = {"S_EULER_XYZ": "xyz-moving", "S_FIXED_XYZ": "xyz-fixed"}
#: One-degree-of-freedom joints of further links: (taut joint kind, axis; None: the ``axis`` attribute).
_ONE_DOF: dict[str, tuple[str, tuple[float, float, float] | None]] = {
    "R_X": ("revolute", (1.0, 0.0, 0.0)),
    "R_Y": ("revolute", (0.0, 1.0, 0.0)),
    "R_Z": ("revolute", (0.0, 0.0, 1.0)),
    "R_AXIS": ("revolute", None),
    "P_X": ("prismatic", (1.0, 0.0, 0.0)),
    "P_AXIS": ("prismatic", None),
}
_AXIS_JOINTS = ("R_AXIS", "P_AXIS")
#: Joints of several degrees of freedom as chains of one-DOF joints, each about or along an
#: axis of the frame the previous one leaves (CASPR composes ``R_pe`` and ``r_rel`` so):
#: (one-DOF joint, index of its coordinate in CASPR's ``q``) from the parent outwards.
_CHAINS: dict[str, tuple[tuple[str, int], ...]] = {
    "U_XY": (("R_X", 0), ("R_Y", 1)),
    "U_YZ": (("R_Y", 0), ("R_Z", 1)),
    "U_XZ": (("R_X", 0), ("R_Z", 1)),
    "S_EULER_XYZ": (("R_X", 0), ("R_Y", 1), ("R_Z", 2)),
    # R = Rz(γ) Ry(β) Rx(α): the chain turns γ first, so its coordinates come as (γ, β, α)
    "S_FIXED_XYZ": (("R_Z", 2), ("R_Y", 1), ("R_X", 0)),
    "P_XY": (("P_X", 0), ("P_Y", 1)),
    "P_XZ": (("P_X", 0), ("P_Z", 1)),
    "T_XYZ": (("P_X", 0), ("P_Y", 1), ("P_Z", 2)),
    "SPATIAL_EULER_XYZ": (("P_X", 0), ("P_Y", 1), ("P_Z", 2), ("R_X", 3), ("R_Y", 4), ("R_Z", 5)),
}
#: The elementary joints of the chains that CASPR has no one-DOF type for.
_ELEMENTARY = _ONE_DOF | {"P_Y": ("prismatic", (0.0, 1.0, 0.0)), "P_Z": ("prismatic", (0.0, 0.0, 1.0))}
#: Joint types of CASPR's bodies files (its ``JointType``, with the quaternion joints of its
#: earlier releases), for telling an unknown type from one taut does not read.
_CASPR_JOINTS = (
    *_ONE_DOF,
    *_CHAINS,
    "PLANAR_XY",
    "PLANAR_XZ",
    "PLANAR_YZ",
    "SPHERICAL",
    "S_QUATERNION",
    "SPATIAL",
    "SPATIAL_QUATERNION",
)
_QUATERNION = ("SPHERICAL", "S_QUATERNION", "SPATIAL", "SPATIAL_QUATERNION")
#: Bounds CASPR's joint classes give ``q`` when the file gives no ``q_min`` / ``q_max``.
_DEFAULT_LIMITS = {"revolute": (-math.pi, math.pi), "prismatic": (-math.inf, math.inf)}
#: taut refuses pose coordinates beyond this (``taut.kinematics.as_poses``): an
#: unbounded CASPR joint gets these limits, which admit the same poses.
_UNBOUNDED = MAX_MAGNITUDE
_CABLE_TYPES = ("cable_ideal", "cable_linear_spring")
_INERTIA = ("Ixx", "Iyy", "Izz", "Ixy", "Ixz", "Iyz")


def parse_xml(text: str, *, source: str) -> ET.Element:
    """The root element of an XML text.  Entity declarations are refused before parsing (they
    serve no purpose in a model and are how an XML file expands to gigabytes); CASPR's own
    ``<!DOCTYPE ... SYSTEM "...dtd">`` and ``<!ATTLIST>`` lines are harmless and accepted.

    Parameters
    ----------
    text : str
    source : str
        Where the text comes from, for messages.

    Returns
    -------
    xml.etree.ElementTree.Element

    Raises
    ------
    RobotFileError
        For an entity declaration or text that is not XML.

    Examples
    --------
    >>> parse_xml('<links><link_rigid num="1"/></links>', source="example").find("link_rigid").get("num")
    '1'
    """
    if _ENTITY.search(text):
        raise RobotFileError(f"{source}: XML entity declarations (<!ENTITY>) are not accepted in a model file")
    try:
        return ET.fromstring(text)
    except ET.ParseError as exc:
        raise RobotFileError(f"{source}: not valid XML: {exc}") from None


def _attrs(elem: ET.Element, allowed: tuple[str, ...], where: str) -> None:
    extra = sorted(set(elem.attrib) - set(allowed))
    if extra:
        raise RobotFileError(f"{where}: unknown attribute {extra[0]!r} (expected {', '.join(allowed) or 'none'})")


def _children(elem: ET.Element, allowed: tuple[str, ...], where: str) -> None:
    for child in elem:
        if child.tag not in allowed:
            raise RobotFileError(f"{where}: unknown element <{child.tag}> (expected {', '.join(allowed)})")


def _one(elem: ET.Element, tag: str, where: str) -> ET.Element:
    found = elem.findall(tag)
    if len(found) != 1:
        what = "missing" if not found else f"given {len(found)} times"
        raise RobotFileError(f"{where}: <{tag}> is {what}")
    return found[0]


def _numbers(text: str | None, n: int | None, where: str, *, allow_inf: bool = False) -> list[float]:
    parts = (text or "").split()
    try:
        values = [float(p) for p in parts]
    except ValueError:
        raise RobotFileError(f"{where}: expected numbers, got {text!r}") from None
    if n is not None and len(values) != n:
        raise RobotFileError(f"{where}: expected {n} numbers, got {len(values)} ({text!r})")
    for v in values:
        if math.isnan(v) or (math.isinf(v) and not allow_inf):
            raise RobotFileError(f"{where}: expected finite numbers, got {text!r}")
    return values


def _number(elem: ET.Element, tag: str, where: str, *, allow_inf: bool = False) -> float:
    return _numbers(_one(elem, tag, where).text, 1, f"{where} <{tag}>", allow_inf=allow_inf)[0]


def _vector(elem: ET.Element, tag: str, where: str) -> np.ndarray:
    return np.array(_numbers(_one(elem, tag, where).text, 3, f"{where} <{tag}>"))


def _integer(elem: ET.Element, tag: str, where: str) -> int:
    value = _number(elem, tag, where)
    if value != int(value):
        raise RobotFileError(f"{where} <{tag}>: expected a whole number, got {value}")
    return int(value)


@dataclass(frozen=True)
class _Link:
    num: int
    name: str
    joint: str
    parent: int
    location: np.ndarray
    mass: float
    com: np.ndarray
    inertia: np.ndarray  # about the centre of mass, 3x3
    actuated: bool = False
    q_min: str | None = None
    q_max: str | None = None
    axis: np.ndarray | None = None  #: ``R_AXIS`` / ``P_AXIS`` only


def _read_link(elem: ET.Element, where: str) -> _Link:
    _attrs(elem, ("num", "name"), where)
    _children(elem, ("joint", "physical", "parent"), where)
    num_text = elem.get("num")
    if num_text is None or not num_text.strip().isdigit():
        raise RobotFileError(f"{where}: attribute num must be a link number, got {num_text!r}")
    where = f"{where} (link {num_text})"
    joint = _one(elem, "joint", where)
    _attrs(joint, ("type", "q_initial", "q_min", "q_max", "actuated", "axis"), f"{where} <joint>")
    if joint.get("type") not in _CASPR_JOINTS:
        raise RobotFileError(
            f"{where} <joint>: unknown joint type {joint.get('type')!r}; CASPR's joint types are {', '.join(_CASPR_JOINTS)}"
        )
    axis = None
    if joint.get("axis") is not None:
        if joint.get("type") not in _AXIS_JOINTS:
            raise RobotFileError(f"{where} <joint>: an axis is given for R_AXIS / P_AXIS joints only")
        axis = np.array(_numbers(joint.get("axis"), 3, f"{where} <joint> axis"))
        if not np.any(axis != 0):
            raise RobotFileError(f"{where} <joint> axis: must be a non-zero vector")
    physical = _one(elem, "physical", where)
    _children(physical, ("mass", "com_location", "end_location", "inertia"), f"{where} <physical>")
    mass = _number(physical, "mass", f"{where} <physical>")
    if mass < 0:
        raise RobotFileError(f"{where} <physical> <mass>: must be >= 0, got {mass}")
    com = _vector(physical, "com_location", f"{where} <physical>")
    inertia_el = _one(physical, "inertia", f"{where} <physical>")
    iw = f"{where} <inertia>"
    _attrs(inertia_el, ("ref",), iw)
    _children(inertia_el, _INERTIA, iw)
    xx, yy, zz, xy, xz, yz = (_number(inertia_el, t, iw) for t in _INERTIA)
    tensor = np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])
    ref = inertia_el.get("ref")
    if ref == "joint":
        tensor = tensor - mass * (float(com @ com) * np.eye(3) - np.outer(com, com))
    elif ref != "com":
        raise RobotFileError(f"{iw}: ref must be 'com' or 'joint', got {ref!r}")
    parent = _one(elem, "parent", where)
    _children(parent, ("num", "location"), f"{where} <parent>")
    return _Link(
        num=int(num_text),
        name=elem.get("name", ""),
        joint=joint.get("type", ""),
        parent=_integer(parent, "num", f"{where} <parent>"),
        location=_vector(parent, "location", f"{where} <parent>"),
        mass=mass,
        com=com,
        inertia=tensor,
        actuated=joint.get("actuated", "false").strip().lower() == "true",
        q_min=joint.get("q_min"),
        q_max=joint.get("q_max"),
        axis=axis,
    )


def _read_links(root: ET.Element, source: str) -> list[_Link]:
    if root.tag != "bodies_system":
        raise RobotFileError(f"{source}: expected a <bodies_system> CASPR bodies file, got <{root.tag}>")
    _children(root, ("links",), source)
    links_el = _one(root, "links", source)
    _attrs(links_el, ("display_range", "view_angle"), f"{source} <links>")
    for child in links_el:
        if child.tag != "link_rigid":
            raise UnsupportedRobotError(f"{source}: <{child.tag}> links are not modelled by taut (only <link_rigid>)")
    links = [_read_link(el, f"{source} <link_rigid>") for el in links_el]
    if not links:
        raise RobotFileError(f"{source}: <links> holds no <link_rigid>")
    for k, link in enumerate(links, 1):
        if link.num != k:
            raise RobotFileError(
                f"{source}: link number {link.num} out of order (expected {k}: links are numbered 1, 2, ...)"
            )
        if not 0 <= link.parent < k:
            raise RobotFileError(f"{source}: link {k}: parent {link.parent} must be an earlier link or 0 (the base)")
    return links


@dataclass(frozen=True)
class _Cable:
    name: str
    kind: str
    reference: str
    force: tuple[float, float]
    stiffness: float | None
    base: np.ndarray
    link: int
    location: np.ndarray
    swivel: tuple[np.ndarray, float] | None = None  #: ``cable_entry_vector``, ``pulley_radius``
    #: the attachments between the first and the last, in the cable's order from the base
    via: tuple[tuple[int, np.ndarray], ...] = ()


def _read_cable(elem: ET.Element, n_links: int, where: str) -> _Cable:
    name = elem.get("name") or ""
    where = f"{where} <{elem.tag} name={name!r}>"
    _attrs(elem, ("name", "attachment_reference"), where)
    _children(elem, ("properties", "attachments"), where)
    reference = elem.get("attachment_reference")
    if reference not in ("com", "joint"):
        raise RobotFileError(f"{where}: attachment_reference must be 'com' or 'joint', got {reference!r}")
    props = _one(elem, "properties", where)
    pw = f"{where} <properties>"
    allowed = ("force_min", "force_max", "K") if elem.tag == "cable_linear_spring" else ("force_min", "force_max")
    if props.find("force_error") is not None:
        raise UnsupportedRobotError(
            f"{pw} <force_error>: taut models no error of the cable force (its tensions are exact); "
            "remove the element to read the robot without it"
        )
    _children(props, allowed, pw)
    lo = _number(props, "force_min", pw)
    hi = _number(props, "force_max", pw, allow_inf=True)
    if hi > MAX_MAGNITUDE:
        # CASPR's models write "no bound" as a huge number (9999999999 N)
        hi = math.inf
    stiffness = None
    if elem.tag == "cable_linear_spring":
        stiffness = _number(props, "K", pw)
        if stiffness <= 0:
            raise RobotFileError(f"{pw} <K>: the cable's axial rigidity EA must be > 0 N, got {stiffness}")
    atts = _one(elem, "attachments", where)
    aw = f"{where} <attachments>"
    swivel = None
    points = []
    for k, child in enumerate(atts):
        if child.tag == "base_rotating_pulley" and k == 0:
            pw = f"{aw} <base_rotating_pulley>"
            _children(child, ("fixed_location", "pulley_radius", "cable_entry_vector"), pw)
            radius = _number(child, "pulley_radius", pw)
            if radius <= 0:
                raise RobotFileError(f"{pw} <pulley_radius>: must be > 0, got {radius}")
            entry = _vector(child, "cable_entry_vector", pw)
            if not np.any(entry != 0):
                raise RobotFileError(f"{pw} <cable_entry_vector>: must be a non-zero vector")
            swivel = (entry, radius)
            points.append((0, _vector(child, "fixed_location", pw)))
        elif "pulley" in child.tag:
            raise UnsupportedRobotError(
                f"{aw}: <{child.tag}> is not modelled by taut (cable {name!r}; only a first <base_rotating_pulley>)"
            )
        elif child.tag != "attachment":
            raise RobotFileError(f"{aw}: unknown element <{child.tag}> (expected <attachment>)")
    for el in atts.findall("attachment"):
        _children(el, ("link", "location"), f"{aw} <attachment>")
        link = _integer(el, "link", f"{aw} <attachment>")
        if not 0 <= link <= n_links:
            raise RobotFileError(f"{aw}: attachment on link {link}, but the bodies file has links 1..{n_links}")
        points.append((link, _vector(el, "location", f"{aw} <attachment>")))
    if len(points) < 2:
        raise RobotFileError(f"{aw}: cable {name!r} needs two attachments, got {len(points)}")
    # a cable's segments join consecutive attachments; taut's runs from its exit on the base
    if points[0][0] != 0 and points[-1][0] == 0 and swivel is None:
        points.reverse()
    (l0, base), (l1, loc) = points[0], points[-1]
    if l0 != 0 or l1 == 0:
        route = " -> ".join(str(link) for link, _ in points)
        raise UnsupportedRobotError(
            f"{aw}: cable {name!r} runs through links {route}; a taut cable runs from the base (link 0) to a body"
        )
    return _Cable(name, elem.tag, reference, (lo, hi), stiffness, base, l1, loc, swivel, tuple(points[1:-1]))


def _read_cables(root: ET.Element, source: str, n_links: int, cable_set: str | None) -> tuple[str, list[_Cable]]:
    if root.tag != "cables":
        raise RobotFileError(f"{source}: expected a <cables> CASPR cables file, got <{root.tag}>")
    _attrs(root, ("default_cable_set",), source)
    _children(root, ("cable_set",), source)
    sets: dict[str, ET.Element] = {}
    for el in root.findall("cable_set"):
        _attrs(el, ("id",), f"{source} <cable_set>")
        sid = el.get("id")
        if not sid:
            raise RobotFileError(f"{source}: a <cable_set> has no id")
        if sid in sets:
            raise RobotFileError(f"{source}: cable set id {sid!r} is given twice")
        sets[sid] = el
    wanted = cable_set if cable_set is not None else root.get("default_cable_set")
    if wanted is None:
        raise RobotFileError(
            f"{source}: <cables> has no default_cable_set; pick one of {sorted(sets)} with --cable-set"
        )
    if wanted not in sets:
        raise RobotFileError(f"{source}: no cable set {wanted!r}; the file has {', '.join(sorted(sets)) or 'none'}")
    where = f"{source} <cable_set id={wanted!r}>"
    cables = []
    for el in sets[wanted]:
        if el.tag not in _CABLE_TYPES:
            raise UnsupportedRobotError(
                f"{where}: <{el.tag}> cables are not modelled by taut (only {', '.join(_CABLE_TYPES)})"
            )
        cables.append(_read_cable(el, n_links, where))
    if not cables:
        # CASPR accepts an empty set (PlanarSnakeArm's default: an arm moved by its joints alone);
        # a well-formed file, but a robot taut does not model
        raise UnsupportedRobotError(f"{where}: the cable set holds no cables; taut models robots moved by cables")
    return wanted, cables


def cables_path(bodies_path: str | Path) -> Path:
    """The ``X_cables.xml`` beside ``X_bodies.xml`` (CASPR's naming)."""
    path = Path(bodies_path)
    if not path.name.lower().endswith(BODIES_SUFFIX):
        raise RobotFileError(f"{path}: a CASPR model is given by its X{BODIES_SUFFIX} file")
    return path.with_name(path.name[: -len(BODIES_SUFFIX)] + CABLES_SUFFIX)


def read_caspr(bodies_path: str | Path, *, cable_set: str | None = None) -> Robot:
    """Read the CASPR model ``X_bodies.xml`` and its ``X_cables.xml`` (module docstring).

    Parameters
    ----------
    bodies_path : str or Path
        The ``X_bodies.xml`` file (its name ends in :data:`BODIES_SUFFIX`).
    cable_set : str, optional
        A cable set other than the file's ``default_cable_set``.

    Returns
    -------
    Robot

    Raises
    ------
    RobotFileError
        A missing or malformed file, inconsistent ids, a NaN.
    UnsupportedRobotError
        A construct taut does not model, named.

    References
    ----------
    .. [1] D. Lau, J. Eden, Y. Tan, D. Oetomo, "CASPR: A comprehensive cable-robot analysis and
       simulation platform for the research of cable-driven parallel robots", IEEE/RSJ
       International Conference on Intelligent Robots and Systems (IROS), 2016.
       (docs/references.bib: lau2016)

    Examples
    --------
    >>> from taut.model import example
    >>> import pathlib, tempfile
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "spatial_bodies.xml"
    >>> write_caspr(example("spatial-8cable"), path)
    >>> robot = read_caspr(path)
    >>> robot.n_cables, bool(np.allclose(robot.exits, example("spatial-8cable").exits))
    (8, True)
    """
    from taut.model._io import read_text

    path = Path(bodies_path)
    return parse_caspr(path, read_text(path), cable_set)


def parse_caspr(path: Path, text: str, cable_set: str | None = None) -> Robot:
    """:func:`read_caspr` given the text of the bodies file ``path``."""
    from taut.model._io import read_text

    source = str(path)
    links = _read_links(parse_xml(text, source=source), source)
    cpath = cables_path(path)
    if not cpath.exists():
        raise RobotFileError(
            f"{source}: the cables file {cpath} is missing (CASPR keeps X_cables.xml beside X_bodies.xml)"
        )
    set_id, cables = _read_cables(parse_xml(read_text(cpath), source=str(cpath)), str(cpath), len(links), cable_set)
    return _robot(path, links, set_id, cables)


def _platform_link(links: list[_Link], source: str) -> tuple[_Link, np.ndarray, tuple[int, bool, str | None, str]]:
    """The platform link (the one with the free joint to the ground), the offset of its joint
    origin from the base's, and how it maps; the links after it are its jointed bodies
    (:func:`_jointed_bodies`)."""
    mapping: tuple[int, bool, str | None, str]
    if len(links) >= 2 and links[0].joint == "T_XYZ" and links[1].joint in _SPHERICAL and links[1].parent == 1:
        carrier, link = links[0], links[1]
        if carrier.mass != 0:
            raise UnsupportedRobotError(
                f"{source}: link 1 (T_XYZ) carries a mass of {carrier.mass}; taut's platform is one rigid body"
            )
        origin, mapping = carrier.location + link.location, (3, True, None, _SPHERICAL[link.joint])
    else:
        link = links[0]
        if link.joint not in _SINGLE:
            if len(links) > 1 and link.parent == 0:
                joints = ", ".join(f"{k.num}:{k.joint}" for k in links)
                raise UnsupportedRobotError(
                    f"{source}: a chain of {len(links)} links ({joints}) jointed to the ground by {link.joint} is a "
                    "multi-link robot; taut models a platform with a free joint (SPATIAL_EULER_XYZ, or T_XYZ carrying "
                    f"{' or '.join(_SPHERICAL)}) and bodies jointed to it"
                )
            raise UnsupportedRobotError(
                f"{source}: link 1 has a {link.joint or '(missing)'} joint; taut reads {', '.join(_SINGLE)}, "
                f"or T_XYZ carrying {' or '.join(_SPHERICAL)}"
            )
        origin, mapping = link.location, _SINGLE[link.joint]
    for k in links[: link.num]:
        if k.actuated:
            raise UnsupportedRobotError(
                f"{source}: link {k.num}: the platform's {k.joint} joint is actuated; actuated platform joints are "
                "not modelled by taut (its cables move the platform)"
            )
    return link, origin, mapping


def _joint_limits(link: _Link, kinds: list[str], where: str) -> tuple[list[tuple[float, float]], bool]:
    """``q_min`` / ``q_max`` of a joint's coordinates in CASPR's order (one number per degree
    of freedom; CASPR's class bounds when not given), and whether an infinite bound became
    ±``_UNBOUNDED``."""
    columns = []
    for text, side in ((link.q_min, 0), (link.q_max, 1)):
        if text is None:
            columns.append([_DEFAULT_LIMITS[k][side] for k in kinds])
        else:
            columns.append(
                _numbers(
                    text,
                    len(kinds),
                    f"{where}: its {link.joint} joint's q_min/q_max (one number per degree of freedom)",
                    allow_inf=True,
                )
            )
    out, unbounded = [], False
    for lo, hi in zip(*columns):
        if lo > hi:
            raise RobotFileError(f"{where}: q_min {lo:g} > q_max {hi:g}")
        clipped = (max(lo, -_UNBOUNDED), min(hi, _UNBOUNDED))
        unbounded = unbounded or clipped != (lo, hi)
        out.append(clipped)
    return out, unbounded


@dataclass(frozen=True)
class _Jointed:
    """The further links of a CASPR model as taut's ``platform.bodies``."""

    bodies: list[dict]
    #: link number → the taut body its cables are anchored on (the last of its joint's chain)
    body_of: dict[int, str]
    #: link number → its frame's offset along a planar model's normal (0 for the platform)
    normal_offsets: dict[int, float]
    unbounded: bool  #: a joint's infinite bound became ±``_UNBOUNDED``
    negated: list[str]  #: joints whose taut coordinate is −q (CASPR's turns the other way)
    massive: bool  #: a further link has a mass
    permuted: list[str]  #: links whose joint coordinates taut orders otherwise than CASPR's q


def _planar_joint(
    kind: str, axis: tuple[float, float, float], plane: _Plane, where: str, joint: str
) -> tuple[list[float], float]:
    """taut's planar joint axis and the sign of its coordinate (−1: taut's ``q`` is −q_CASPR)."""
    i, j = plane.axes
    n = plane.normal
    if kind == "prismatic":
        if axis[n] != 0:
            raise UnsupportedRobotError(f"{where}: its {joint} joint moves out of the plane (axis {list(axis)})")
        return [axis[i], axis[j]], 1.0
    if axis[i] != 0 or axis[j] != 0:
        raise UnsupportedRobotError(
            f"{where}: its {joint} joint turns about {list(axis)}; taut's planar joints turn about the plane's normal"
        )
    # taut's planar angles turn e_i towards e_j, i.e. about e_i × e_j
    normal = float(np.cross(np.eye(3)[i], np.eye(3)[j])[n])
    return [1.0], math.copysign(1.0, axis[n]) * normal


def _elementary(link: _Link, where: str) -> list[tuple[str, str, tuple[float, float, float], int]]:
    """A further link's joint as a chain of one-DOF joints from the parent outwards: (CASPR
    name, taut kind, axis, index of its coordinate in CASPR's ``q``)."""
    if link.joint in _ONE_DOF:
        kind, unit = _ONE_DOF[link.joint]
        if unit is None:
            if link.axis is None:
                raise RobotFileError(f"{where}: a {link.joint} joint needs an axis attribute")
            unit = (float(link.axis[0]), float(link.axis[1]), float(link.axis[2]))
        return [(link.joint, kind, unit, 0)]
    if link.joint in _CHAINS:
        out = []
        for name, index in _CHAINS[link.joint]:
            kind, unit = _ELEMENTARY[name]
            assert unit is not None, "chains are made of coordinate-axis joints"
            out.append((name, kind, unit, index))
        return out
    if link.joint in _QUATERNION:
        raise UnsupportedRobotError(
            f"{where} has a {link.joint} joint, whose coordinates are a quaternion (4 numbers for 3 degrees of "
            "freedom); taut's joint coordinates are one angle or distance per one-DOF joint (S_EULER_XYZ or "
            "S_FIXED_XYZ hold the same rotation)"
        )
    raise UnsupportedRobotError(
        f"{where} has a {link.joint} joint, which taut reads for the platform link only; a further link's joint "
        f"is one of {', '.join((*_ONE_DOF, *_CHAINS))}"
    )


def _jointed_bodies(links: list[_Link], platform: _Link, rigid: bool, plane: _Plane | None, source: str) -> _Jointed:
    """``platform.bodies`` of taut for the links after the platform link.

    Each such link must hang from the platform link or a later link.  A one-degree-of-freedom
    joint (:data:`_ONE_DOF`) is one body: CASPR's ``R_X``/``R_Y``/``R_Z``/``R_AXIS`` rotate the
    link about the axis through its ``<parent><location>`` and ``P_X``/``P_AXIS`` translate it
    by ``q·axis`` from there (``RevoluteAxis``, ``PrismaticAxis``; the link's frame is the
    parent's moved by ``location + r_rel(q)`` and rotated by ``R_pe(q)``,
    ``SystemModelBodies.update``), which are taut's ``revolute`` and ``prismatic`` joints with
    ``origin = location``.  A joint of several degrees of freedom (:data:`_CHAINS`: universal
    ``U_*``, spherical ``S_EULER_XYZ``/``S_FIXED_XYZ``, ``P_XY``/``P_XZ``, ``T_XYZ``,
    ``SPATIAL_EULER_XYZ``) is the chain of one-DOF joints its ``R_pe`` and ``r_rel`` compose,
    through massless intermediate bodies named ``"link [R_X of U_XY]"``; the link's mass and
    cables are on the last.  A joint with ``actuated="true"`` gets an actuator on each of its
    degrees of freedom, unbounded (CASPR's ``tau_min``/``tau_max`` are ±∞ and its files give
    none); others are passive.  On a planar platform a revolute joint must turn about the
    plane's normal and a prismatic one move in the plane; the plane maps as the platform's
    does, so a joint turning the other way round than taut's planar angles gets the
    coordinate −q.

    References
    ----------
    .. [1] D. Lau, J. Eden, Y. Tan, D. Oetomo, "CASPR: A comprehensive cable-robot analysis and
       simulation platform for the research of cable-driven parallel robots", IEEE/RSJ
       International Conference on Intelligent Robots and Systems (IROS), 2016.
       (docs/references.bib: lau2016)
    .. [2] D. Lau, D. Oetomo, S. K. Halgamuge, "Generalized modeling of multilink cable-driven
       manipulators with arbitrary routing using the cable-routing matrix", IEEE Transactions
       on Robotics 29(5), 2013 (links on joints of several degrees of freedom).
       (docs/references.bib: lau2013)
    """
    rest = links[platform.num :]
    if rest and not rigid:
        raise UnsupportedRobotError(
            f"{source}: links {', '.join(str(k.num) for k in rest)} are jointed to a {platform.joint} platform; a "
            "point mass carries no jointed bodies in taut"
        )
    names = {platform.num: "platform"}
    offsets = {platform.num: 0.0}
    taken = {"platform"}
    bodies: list[dict] = []
    negated: list[str] = []
    permuted: list[str] = []
    unbounded = massive = False
    for link in rest:
        where = f"{source}: link {link.num} ({link.name!r})"
        chain = _elementary(link, where)
        if link.parent not in names:
            to = "the ground (link 0)" if link.parent == 0 else f"link {link.parent} ({links[link.parent - 1].joint})"
            raise UnsupportedRobotError(
                f"{where} is jointed to {to}, which is not the platform (link {platform.num}) nor carried by it; "
                "taut's bodies form a tree rooted at the one free platform"
            )
        limits, clipped = _joint_limits(link, [kind for _, kind, _, _ in chain], where)
        unbounded, massive = unbounded or clipped, massive or link.mass > 0
        name = link.name.strip() or f"link {link.num}"
        while name in taken:
            name = f"{name} (link {link.num})"
        taken.add(name)
        if [index for *_, index in chain] != list(range(len(chain))):
            permuted.append(f"{name} ({link.joint}: {', '.join(f'q{index + 1}' for *_, index in chain)})")
        parent = names[link.parent]
        for step, (elem, kind, unit, index) in enumerate(chain):
            last = step == len(chain) - 1
            body_name = name if last else f"{name} [{elem} of {link.joint}]"
            while not last and body_name in taken:
                body_name = f"{body_name} (link {link.num})"
            taken.add(body_name)
            lo, hi = limits[index]
            origin = link.location if step == 0 else np.zeros(3)
            axis, com = list(unit), link.com
            if plane is not None:
                axis, sign = _planar_joint(kind, unit, plane, where, link.joint)
                origin, com = origin[list(plane.axes)], com[list(plane.axes)]
                if sign < 0:
                    lo, hi = -hi, -lo
                    negated.append(body_name)
            joint: dict[str, object] = {"kind": kind, "axis": axis, "origin": origin.tolist(), "limits": [lo, hi]}
            if link.actuated:
                joint["actuator"] = {"force": [-math.inf, math.inf]}
            body: dict[str, object] = {"name": body_name, "parent": parent, "joint": joint}
            if last and link.mass > 0:
                body["mass"] = link.mass
                if np.any(com != 0):
                    body["com"] = com.tolist()
                if np.any(link.inertia != 0):
                    t = link.inertia
                    body["inertia"] = (
                        [t[0, 0], t[1, 1], t[2, 2], t[0, 1], t[0, 2], t[1, 2]]
                        if plane is None
                        else [t[plane.normal, plane.normal]]
                    )
            bodies.append(body)
            parent = body_name
        names[link.num] = name
        if plane is not None:
            offsets[link.num] = offsets[link.parent] + float(link.location[plane.normal])
    body_of = {num: body for num, body in names.items() if num != platform.num}
    return _Jointed(bodies, body_of, offsets, unbounded, negated, massive, permuted)


def _via_points(
    c: _Cable,
    i: int,
    links: list[_Link],
    platform: _Link,
    body_of: dict[int, str],
    origin: np.ndarray,
    plane: _Plane | None,
    jointed: _Jointed,
    rigid: bool,
    source: str,
) -> list[dict[str, object]]:
    """The via points of cable ``i``: its attachments between the first and the last, on the
    base (``fixed``, relative to the platform's joint origin as the exits are) or on a link
    (in its frame, as anchors are)."""
    if not rigid and np.any(c.location != 0):
        raise UnsupportedRobotError(
            f"{source}: cable {i} ({c.name!r}) runs through via points to an attachment {c.location.tolist()} off a "
            "point mass, which taut takes at the point mass by moving the exit: the segments before it would change"
        )
    out = []
    for link, location in c.via:
        if link == 0:
            point, body, offset = location - origin, "fixed", 0.0
        elif link == platform.num or link in body_of:
            point = location + links[link - 1].com if c.reference == "com" else location
            body = "platform" if link == platform.num else body_of[link]
            offset = jointed.normal_offsets.get(link, 0.0)
        else:
            raise UnsupportedRobotError(
                f"{source}: cable {i} ({c.name!r}) runs through link {link}, which carries no cables in taut's model"
            )
        if plane is not None:
            off = float(point[plane.normal]) + offset  # a link's plane lies -offset along the normal in its frame
            if abs(off) > 1e-9 * max(1.0, float(np.abs(point).max())):
                raise UnsupportedRobotError(
                    f"{source}: cable {i} ({c.name!r}) runs through a point {off:g} m off the robot's plane; "
                    "taut's planar robots keep cables in the plane"
                )
            point = point[list(plane.axes)]
        out.append({"point": point.tolist(), "body": body})
    return out


def _robot(path: Path, links: list[_Link], set_id: str, cables: list[_Cable]) -> Robot:
    source = str(path)
    link, origin, (dim, rigid, plane_name, orientation) = _platform_link(links, source)
    plane = _PLANES[plane_name] if plane_name is not None else None
    jointed = _jointed_bodies(links, link, rigid, plane, source)
    body_of = jointed.body_of
    scale = max(1.0, float(np.abs(origin).max()))
    out = []
    shifted = False
    for i, c in enumerate(cables, 1):
        if c.link != link.num and c.link not in body_of:
            raise UnsupportedRobotError(
                f"{source}: cable {i} ({c.name!r}) is attached to link {c.link}, which carries no cables in taut's model"
            )
        anchor = c.location + links[c.link - 1].com if c.reference == "com" else c.location
        exit_ = c.base - origin
        if not rigid:
            shifted = shifted or bool(np.any(anchor != 0))
            exit_, anchor = exit_ - anchor, np.zeros(3)
        swivel_axis = None if c.swivel is None else c.swivel[0]
        if plane is not None and swivel_axis is not None:
            if swivel_axis[plane.normal] != 0:
                raise UnsupportedRobotError(
                    f"{source}: cable {i} ({c.name!r}) leaves through a base_rotating_pulley whose cable_entry_vector "
                    f"{swivel_axis.tolist()} leaves the {plane_name} plane; taut's planar swivelling pulleys turn "
                    "about an axis in the plane, which keeps the cable in it"
                )
            swivel_axis = swivel_axis[list(plane.axes)]
        if plane is not None:
            off = exit_[plane.normal] - anchor[plane.normal] - jointed.normal_offsets.get(c.link, 0.0)
            if abs(off) > 1e-9 * max(scale, float(np.abs(c.base).max())):
                raise UnsupportedRobotError(
                    f"{source}: cable {i} ({c.name!r}) leaves the {plane_name} plane by {off:g} m; taut's planar robots keep cables in the plane"
                )
            exit_, anchor = exit_[list(plane.axes)], anchor[list(plane.axes)]
        cable: dict[str, object] = {"name": c.name or None, "exit": exit_.tolist(), "tension": list(c.force)}
        if c.via:
            cable["via"] = _via_points(c, i, links, link, body_of, origin, plane, jointed, rigid, source)
        if c.link in body_of:
            cable["body"] = body_of[c.link]
        if rigid:
            cable["anchor"] = anchor.tolist()
        if c.stiffness is not None:
            cable["stiffness"] = c.stiffness
        if c.swivel is not None and swivel_axis is not None:
            cable["swivel"] = {"axis": swivel_axis.tolist(), "radius": c.swivel[1]}
        out.append(cable)
    platform: dict[str, object] = {"kind": "rigid" if rigid else "point-mass"}
    if jointed.bodies:
        platform["bodies"] = jointed.bodies
    if jointed.massive and plane is not None and not plane.in_plane_gravity:
        platform["gravity"] = [0.0, 0.0]
    if link.mass > 0:
        platform["mass"] = link.mass
        if plane is not None and not plane.in_plane_gravity:
            platform["gravity"] = [0.0, 0.0]
        if rigid:
            com = link.com if plane is None else link.com[list(plane.axes)]
            platform["wrench_point"] = com.tolist()
            if np.any(link.inertia != 0):
                t = link.inertia
                platform["inertia"] = (
                    [t[0, 0], t[1, 1], t[2, 2], t[0, 1], t[0, 2], t[1, 2]]
                    if plane is None
                    else [t[plane.normal, plane.normal]]
                )
    stem = path.name[: -len(BODIES_SUFFIX)]
    notes = [f"CASPR model {stem}, cable set {set_id!r}, {' + '.join(k.joint for k in links)}"]
    if plane is not None:
        notes.append(plane.note)
    if np.any(origin != 0):
        notes.append(f"exits relative to the joint origin {origin.tolist()}")
    if shifted:
        notes.append("point-mass exits shifted by their attachments")
    if jointed.unbounded:
        notes.append(f"unbounded joints limited to +-{_UNBOUNDED:g} (the largest pose coordinate taut takes)")
    if jointed.negated:
        notes.append(f"joint coordinates negated (-q of CASPR): {', '.join(jointed.negated)}")
    if jointed.permuted:
        notes.append(f"joint coordinates in the chain's order: {'; '.join(jointed.permuted)}")
    data = {
        "name": stem,
        "description": "; ".join(notes),
        "source": "CASPR model file",
        "dimension": dim,
        "orientation": orientation,
        "platform": platform,
        "cables": out,
    }
    from taut.model._io import robot_from_dict

    return robot_from_dict(data, source=source)


# ---- writing -----------------------------------------------------------------------------


def _refuse(robot: Robot, why: str) -> UnsupportedRobotError:
    return UnsupportedRobotError(f"{robot.name}: a CASPR model cannot hold {why}")


def _horizontal(robot: Robot) -> bool:
    """Whether a planar robot's plane is horizontal: a mass without gravity in the plane."""
    gravity = robot.platform.gravity
    massive = robot.platform.mass is not None or any(b.mass is not None for b in robot.platform.bodies)
    return robot.dimension == 2 and massive and gravity is not None and not any(gravity)


def _weight(robot: Robot) -> tuple[float, np.ndarray]:
    """Mass and centre of mass (taut frame) whose weight under CASPR's gravity is the robot's
    external wrench exactly."""
    plat, d = robot.platform, robot.dimension
    point = np.array(plat.wrench_point if plat.wrench_point is not None else [0.0] * d)
    if plat.wrench is not None and plat.mass is not None:
        raise _refuse(robot, "both a constant wrench and a mass")
    if _horizontal(robot):
        return float(plat.mass or 0.0), point
    down = -np.eye(d)[-1]
    if plat.wrench is not None:
        w = np.array(plat.wrench)
        force, moment = w[:d], w[d:]
        if np.any(moment != 0) or np.any(force[:-1] != 0) or force[-1] > 0:
            raise _refuse(robot, f"the external wrench {list(plat.wrench)}: CASPR's only load is the weight (along -z)")
        return float(-force[-1]) / CASPR_GRAVITY, point
    if plat.mass is None:
        return 0.0, point
    if plat.gravity is not None and not np.allclose(plat.gravity, STANDARD_GRAVITY * down, rtol=0, atol=1e-12):
        raise _refuse(robot, f"gravity {list(plat.gravity)}: CASPR's is {CASPR_GRAVITY} m/s² along -z")
    return float(plat.mass), point


def _fmt(values: np.ndarray | list[float] | tuple[float, ...]) -> str:
    return " ".join(repr(float(v)) for v in values)


def _joint_type(kind: str, axis: tuple[float, ...]) -> str:
    """CASPR's joint type for a taut joint: ``R_X``/``R_Y``/``R_Z``/``P_X`` along a positive
    coordinate axis, else ``R_AXIS``/``P_AXIS`` with the axis given."""
    for name, (k, unit) in _ONE_DOF.items():
        if (
            k == kind
            and unit is not None
            and all((a > 0) == (u > 0) and (a == 0) == (u == 0) for a, u in zip(axis, unit))
        ):
            return name
    return "R_AXIS" if kind == "revolute" else "P_AXIS"


def _write_bodies(
    robot: Robot, links: ET.Element, platform_num: int, lift: Callable[[np.ndarray], np.ndarray], horizontal: bool
) -> dict[str, str]:
    """Append ``platform.bodies`` to ``links`` as one-DOF links after the platform's
    link ``platform_num`` (``actuated="true"`` where the joint has an actuator) (the inverse of :func:`_jointed_bodies`; ``lift`` takes a planar
    robot's vectors into its CASPR plane, ``horizontal`` the XY plane); return the CASPR link
    number of each body name (``platform`` included).  Joint names and collision capsules
    have no place in a CASPR model and are not written."""
    link_of = {"platform": str(platform_num)}
    d = robot.dimension
    down = -CASPR_GRAVITY * np.eye(d)[-1]
    masses = [b for b in robot.platform.bodies if b.mass is not None]
    if masses and not horizontal and not np.allclose(robot.gravity, down, rtol=0, atol=1e-12):
        raise _refuse(robot, f"gravity {robot.gravity.tolist()}: CASPR's is {CASPR_GRAVITY} m/s² along -z")
    for k, b in enumerate(robot.platform.bodies, platform_num + 1):
        link_of[b.name] = str(k)
        j = b.joint
        if d == 3:
            axis = np.array(j.axis, dtype=float)
        elif j.kind == "revolute":  # taut's planar angles turn x towards y: about +z (XY), -y (XZ)
            axis = np.array([0.0, 0.0, 1.0]) if horizontal else np.array([0.0, -1.0, 0.0])
        else:
            axis = lift(np.array(j.axis, dtype=float))
        kind = _joint_type(j.kind, tuple(axis))
        lo, hi = j.limits
        attrs = {"type": kind, "actuated": "false", "q_initial": repr(float(min(max(0.0, lo), hi)))}
        if j.actuator is not None:
            if any(math.isfinite(f) for f in j.actuator.force):
                raise _refuse(
                    robot,
                    f"the force bounds {list(j.actuator.force)} of the actuator of {b.name}'s joint (CASPR's joint "
                    "actuators are unbounded)",
                )
            attrs["actuated"] = "true"
        attrs |= {"q_min": repr(float(lo)), "q_max": repr(float(hi))}
        if kind in _AXIS_JOINTS:
            attrs["axis"] = _fmt(axis)
        inertia = np.zeros(6)
        if b.inertia is not None:
            if d == 3:
                inertia = np.array(b.inertia)
            else:  # the moment about the plane's normal: Izz (XY plane) or Iyy (XZ plane)
                inertia[2 if horizontal else 1] = b.inertia[0]
        link = ET.SubElement(links, "link_rigid", num=str(k), name=b.name)
        ET.SubElement(link, "joint", attrs)
        phys = ET.SubElement(link, "physical")
        ET.SubElement(phys, "mass").text = repr(float(b.mass or 0.0))
        ET.SubElement(phys, "com_location").text = _fmt(lift(np.array(b.com or (0.0,) * d, dtype=float)))
        ET.SubElement(phys, "end_location").text = _fmt(np.zeros(3))
        inert = ET.SubElement(phys, "inertia", ref="com")
        for tag, value in zip(_INERTIA, inertia):
            ET.SubElement(inert, tag).text = repr(float(value))
        parent = ET.SubElement(link, "parent")
        ET.SubElement(parent, "num").text = link_of[b.parent]
        ET.SubElement(parent, "location").text = _fmt(lift(np.array(j.origin or (0.0,) * d, dtype=float)))
    return link_of


def write_caspr(robot: Robot, bodies_path: str | Path) -> None:
    """Write ``robot`` as the CASPR pair ``X_bodies.xml`` (``bodies_path``) and ``X_cables.xml``.

    A spatial rigid platform becomes a ``SPATIAL_EULER_XYZ`` link (``xyz-moving``) or a massless
    ``T_XYZ`` link carrying a ``S_FIXED_XYZ`` one (``xyz-fixed``); a planar one a
    ``PLANAR_XZ`` link (taut's ``y`` is CASPR's ``z``, where its gravity acts), or ``PLANAR_XY``
    when it has a mass and no gravity in its plane; point masses ``T_XYZ``, ``P_XZ`` or ``P_XY``.
    A constant external wrench that is a downward force becomes the mass whose weight it is.
    A cable routed through via points has them as attachments between its first (link 0) and
    its last, on link 0 for a point on the fixed frame.
    Jointed bodies become links after the platform's, actuated where their joint has an
    (unbounded) actuator (``R_X``/``R_Y``/``R_Z``/``P_X``
    along a positive coordinate axis, else ``R_AXIS``/``P_AXIS``; a planar revolute joint
    ``R_Z`` in the XY plane, ``R_AXIS`` about −y in the XZ plane, so that CASPR's ``q`` is
    taut's) with their masses.  Reference data, trajectories, joint names and the collision
    shapes of the platform and its bodies are not part of a CASPR model and are not written.

    Parameters
    ----------
    robot : Robot
    bodies_path : str or Path
        The ``X_bodies.xml`` file to write; ``X_cables.xml`` goes beside it.

    Raises
    ------
    UnsupportedRobotError
        For what the format cannot hold: obstacles, exit pulleys, length bounds, cable radii,
        other wrenches and gravities, the ``tilt-torsion`` convention, bounded joint actuators.
    RobotFileError
        For a name that does not end in :data:`BODIES_SUFFIX`, or files that cannot be written.

    References
    ----------
    .. [1] D. Lau, J. Eden, Y. Tan, D. Oetomo, "CASPR: A comprehensive cable-robot analysis and
       simulation platform for the research of cable-driven parallel robots", IEEE/RSJ
       International Conference on Intelligent Robots and Systems (IROS), 2016.
       (docs/references.bib: lau2016)

    Examples
    --------
    >>> from taut.model import example
    >>> import pathlib, tempfile
    >>> folder = pathlib.Path(tempfile.mkdtemp())
    >>> write_caspr(example("planar-4cable"), folder / "planar_bodies.xml")
    >>> sorted(p.name for p in folder.iterdir())
    ['planar_bodies.xml', 'planar_cables.xml']
    """
    from taut.model._io import write_file

    bodies = Path(bodies_path)
    cables = cables_path(bodies)
    if robot.obstacles or robot.installation_space is not None or robot.disallowed:
        raise _refuse(robot, "obstacles or an installation space")
    for i, c in enumerate(robot.cables, 1):
        if c.pulley is not None:
            raise _refuse(robot, f"the exit pulley of cable {i}")
        if c.length is not None:
            raise _refuse(robot, f"the length bounds of cable {i}")
        if c.radius != 0:
            raise _refuse(robot, f"the radius of cable {i}")
        if c.weight:
            raise _refuse(robot, f"the weight of cable {i} (a sagging cable; CASPR's cable models are straight)")
    if robot.orientation == "tilt-torsion" and not robot.is_point_mass and robot.dimension == 3:
        raise _refuse(robot, "the tilt-torsion orientation convention")
    mass, com = _weight(robot)
    d, rigid = robot.dimension, not robot.is_point_mass

    # a planar robot goes into CASPR's vertical XZ plane, where its gravity acts, unless it
    # has a mass and no gravity in its plane: then into the horizontal XY plane
    horizontal = _horizontal(robot)

    def lift(v: np.ndarray) -> np.ndarray:
        if d == 3:
            return v
        return np.array([v[0], v[1], 0.0]) if horizontal else np.array([v[0], 0.0, v[1]])

    exits = np.array([lift(e) for e in robot.exits])
    start = exits.mean(axis=0)
    inertia = np.zeros(6)
    if robot.platform.inertia is not None:
        values = robot.platform.inertia
        if d == 3:
            inertia = np.array(values)
        else:  # the moment about the plane's normal: Izz (XY plane) or Iyy (XZ plane)
            inertia[2 if horizontal else 1] = values[0]
    if d == 3:
        translation = [start[0], start[1], start[2]]
        if not rigid:
            joints = [("T_XYZ", translation)]
        elif robot.orientation == "xyz-moving":
            joints = [("SPATIAL_EULER_XYZ", translation + [0.0, 0.0, 0.0])]
        else:
            joints = [("T_XYZ", translation), ("S_FIXED_XYZ", [0.0, 0.0, 0.0])]
    else:
        plane, (i, j) = ("XY", (0, 1)) if horizontal else ("XZ", (0, 2))
        joints = [(f"PLANAR_{plane}", [start[i], start[j], 0.0])] if rigid else [(f"P_{plane}", [start[i], start[j]])]
    root = ET.Element("bodies_system")
    links = ET.SubElement(root, "links")
    for k, (joint, q0) in enumerate(joints, 1):
        last = k == len(joints)
        link = ET.SubElement(links, "link_rigid", num=str(k), name=robot.name if last else "translation")
        ET.SubElement(link, "joint", type=joint, q_initial=_fmt(q0))
        phys = ET.SubElement(link, "physical")
        ET.SubElement(phys, "mass").text = repr(mass if last else 0.0)
        ET.SubElement(phys, "com_location").text = _fmt(lift(com) if last and rigid else np.zeros(3))
        ET.SubElement(phys, "end_location").text = _fmt(np.zeros(3))
        inert = ET.SubElement(phys, "inertia", ref="com")
        for tag, value in zip(_INERTIA, inertia if last else np.zeros(6)):
            ET.SubElement(inert, tag).text = repr(float(value))
        parent = ET.SubElement(link, "parent")
        ET.SubElement(parent, "num").text = str(k - 1)
        ET.SubElement(parent, "location").text = _fmt(np.zeros(3))
    link_of = _write_bodies(robot, links, len(joints), lift, horizontal)
    croot = ET.Element("cables", default_cable_set="taut")
    cset = ET.SubElement(croot, "cable_set", id="taut")
    for i, c in enumerate(robot.cables, 1):
        kind = "cable_ideal" if c.stiffness is None else "cable_linear_spring"
        el = ET.SubElement(cset, kind, name=c.name or f"cable {i}", attachment_reference="joint")
        props = ET.SubElement(el, "properties")
        if c.stiffness is not None:
            ET.SubElement(props, "K").text = repr(float(c.stiffness))
        ET.SubElement(props, "force_min").text = repr(float(c.tension[0]))
        ET.SubElement(props, "force_max").text = "Inf" if math.isinf(c.tension[1]) else repr(float(c.tension[1]))
        atts = ET.SubElement(el, "attachments")
        if c.swivel is not None:
            pulley = ET.SubElement(atts, "base_rotating_pulley")
            ET.SubElement(pulley, "fixed_location").text = _fmt(exits[i - 1])
            ET.SubElement(pulley, "pulley_radius").text = repr(float(c.swivel.radius))
            ET.SubElement(pulley, "cable_entry_vector").text = _fmt(lift(np.array(c.swivel.axis)))
        route = [("0", exits[i - 1])]
        route += [("0" if v.body == "fixed" else link_of[v.body], lift(np.array(v.point, float))) for v in c.via]
        route.append((link_of[c.body or "platform"], lift(robot.anchors[i - 1])))
        for k, (link_num, point) in enumerate(route):
            if k == 0 and c.swivel is not None:
                continue
            att = ET.SubElement(atts, "attachment")
            ET.SubElement(att, "link").text = link_num
            ET.SubElement(att, "location").text = _fmt(point)
    for tree, target in ((root, bodies), (croot, cables)):
        ET.indent(tree)
        write_file(target, '<?xml version="1.0" encoding="utf-8"?>\n' + ET.tostring(tree, encoding="unicode") + "\n")
