"""A robot as a MuJoCo model (MJCF), so that a physics engine can simulate it and check taut.

The platform is one body that moves relative to the world:

* spatial rigid platform: a ``freejoint``, whose ``qpos`` is the position ``p`` and the unit
  quaternion ``(w, x, y, z)`` of the platform's rotation ``R``
  (:func:`pose_to_qpos` converts taut's angles in any orientation convention);
* planar rigid platform: ``slide`` joints along x and y and a ``hinge`` about z, in MuJoCo's
  plane ``z = 0``, so that ``qpos = (x, y, θ)`` is taut's planar pose;
* point mass: ``slide`` joints only (x, y and, in space, z).

Its ``inertial`` element holds ``platform.mass`` and ``Robot.inertia`` (``fullinertia``, about
the centre of mass ``platform.wrench_point``).  A planar platform's tensor is written as
``diaginertia (Izz/2, Izz/2, Izz)`` (a thin plate): only ``Izz`` acts on the planar joints.  A
point mass gets the rotational inertia of a 1 mm sphere of its mass, which no slide joint
feels, because MuJoCo refuses moving bodies without one.  ``option gravity`` is the robot's
``Robot.weight / mass``.

Cable *i* is the spatial tendon ``cable{i}`` through the site ``exit{i}`` (world body, at
``a_i``) and the site ``anchor{i}`` (platform body, or the jointed body it hangs from, at
``r_i``), so that MuJoCo's tendon length is ``‖a_i − b_i‖`` (a cable over a swivelling pulley
wraps it, below); a cable routed through via points (``cables[].via``) runs through the sites
``via{i}_{k}`` between them, on the world body or the body each point is fixed to, so that the
tendon's length is the sum of its segments; its length bounds, where the robot gives them, are
the tendon's ``range``.
The actuator ``tension{i}`` is a force actuator on that tendon with ``gear = −1``: its control
is the cable tension ``τ_i`` [N] pulling the platform towards the exit point, its
``ctrlrange`` the tension bounds.  Cables are ideal (massless, inextensible): their
``stiffness`` is not written.

In MuJoCo's generalised coordinates a platform wrench ``(f, m)`` (force in the fixed frame,
moment about ``p``, as :mod:`taut.statics` writes them) is ``(f, Rᵀ m)`` for the freejoint,
whose angular velocity is expressed in the body frame, and ``(f_x, f_y, m_z)`` or ``f`` for the
planar and point-mass joints: ``mj_inverse`` at rest returns that of ``−w_ext``.

A rigid platform's jointed bodies (``platform.bodies``, :mod:`taut.kinematics._jointed`) are
MuJoCo bodies inside their parents': ``platform.bodies[k − 1]`` is ``body<k>`` at its joint's
``origin`` in the parent's frame, with the parent's orientation at joint coordinate 0, on the
joint ``joint<k>``: a ``slide`` along the unit ``axis`` for a prismatic joint, a ``hinge``
about ``axis`` through the body's origin for a revolute one (about ``+z`` on a planar robot,
as taut turns a planar body whatever its one-number axis), with ``range`` the joint's
``limits``.  This is taut's frame (:func:`taut.kinematics.body_frames`: the parent's
frame translated by ``origin + q·axis``, or by ``origin`` and turned by ``q`` about
``axis``), so the joint's ``qpos`` is taut's joint coordinate ``q``, in MuJoCo's depth-first
order of the body tree (:func:`joint_order`).  Its ``inertial`` holds the body's ``mass`` at
its ``com`` and its ``inertia`` about the ``com`` (``fullinertia``; a planar body's ``Izz``
as the platform's), and the anchor sites of its cables are in it.  A joint frame — a body
without mass, com or inertia, carrying no cable, whose one child is jointed at its origin, as
CASPR's universal and spherical joints are read (:func:`joint_frames`) — is no MuJoCo body:
its joint is the first joint of its child's body, which MuJoCo applies in order, each about
its axis in the frame the joints before it have turned (MuJoCo moves no massless body, and
this is the same chain).  The motor ``drive<k>``
(``gear = 1``; its ``ctrlrange`` the bounds of the joint's actuator, ``joint.actuator``, where
both are finite, else no control range; a passive joint's drive stays at zero in taut's use;
the drives follow the tension actuators, so that ``ctrl = (τ, ζ)``) acts on ``joint<k>``: its control is taut's
joint force ``ζ_k`` of :func:`taut.kinematics.joint_forces`, the force along
``+axis`` or the torque about ``+axis`` that the joint's actuator exerts on the child body,
which is MuJoCo's generalised force of that joint (the reaction on the parent is MuJoCo's, as
it is taut's).  Measured with MuJoCo 4.0.0 (``tests/model/test_mjcf_jointed.py``): at rest,
``mj_inverse`` asks for ``−w_ext`` on the platform's freedoms (the bodies' weights included)
and, beyond the tendons' generalised force at tensions ``τ``, for taut's ``ζ`` on the
joints, to 10⁻¹⁵ relative.

A cable *i* that leaves through a swivelling pulley (``Cable.swivel``, axis ``k``, radius
``r``; :mod:`taut.kinematics._swivel`) runs over a body ``pulley{i}`` on the hinge joint
``swivel{i}`` about ``k`` through the exit point ``a_i``.  Its frame has ``x = e``, ``y = k × e``
and ``z = k``, where at the hinge angle ``q`` the pulley plane's ``e = cos q e_0 + sin q (k ×
e_0)`` turns from ``e_0``, a fixed unit normal of ``k`` (:func:`swivel_frames`); the plane
holds ``k`` and ``e``, and the body's origin is the pulley centre ``a_i + r e``.  The body
carries the wrapping cylinder ``wheel{i}`` (radius ``r``, axis normal to the pulley plane,
no contacts), the site ``exit{i}`` just outside the rim at ``a_i`` and the side site
``side{i}`` at ``a_i + r e + 2 r (cos ψ e + sin ψ k)``, ``ψ =`` :data:`SIDE_SITE_ANGLE`.  The
tendon runs ``exit{i}`` → ``wheel{i}`` (with that side site) → ``anchor{i}``: from the point
where the cable comes along the axis onto the pulley, around the arc, tangentially to the
anchor, which is taut's path when ``q`` is taut's swivel angle, the one whose pulley plane
holds the anchor (:func:`pose_to_qpos` sets it).  Two of MuJoCo's rules shape this:

* a tendon end inside (or, by rounding, on) the wrapping circle does not wrap at all, so the
  exit site sits :data:`EXIT_SITE_OFFSET` ``r`` outside the rim, radially; the cable then
  meets the circle ``δ ≈ √(2·10⁻⁸)`` rad later than at ``a_i``, which lengthens the tendon by
  ``r (tan δ − δ) ≈ 10⁻¹² r``;
* MuJoCo chooses between the two ways round the circle by the side site.  Measured with
  MuJoCo 4.0.0 (a scan of side-site and anchor directions, and the tests): with the
  circle's centre as origin, it takes the way that starts over the side of ``+k`` exactly
  when the side site's direction lies counter-clockwise (about ``e × k``) between the
  directions opposite the exit site (``+e``) and opposite the anchor.  (The rule of an
  earlier MuJoCo's source, the pair of tangent points whose chord midpoint lies nearest the
  side site, differs and would take the other way for many anchors: the ``mujoco`` extra
  asks for MuJoCo 4.)  taut's way is that
  one, so MuJoCo follows it unless the anchor's direction from the pulley centre lies
  within ``ψ`` below ``−e``: behind the exit point (``k·(b − a_i) < 0``), nearer the axis
  than the pulley centre and within ``r (1/cos ψ − 1)`` (1.5 % of ``r``) of the rim.  There,
  and for an anchor on or inside the pulley circle, :func:`swivel_wraps_agree` is false and
  :func:`pose_to_qpos` refuses the pose.

The pulley bodies' dynamics are MuJoCo's addition, not taut's (taut's pulleys are massless):
each weighs :data:`PULLEY_MASS_RATIO` times the platform's mass, with its centre of mass on
its swivel axis at ``a_i`` (so that its weight has no moment about the hinge) and the
rotational inertia of a uniform sphere of radius ``r``.  At taut's swivel angle the tendon
exerts no moment on the hinge either: the cable enters along the axis and leaves in the
pulley plane, which holds the axis, so turning the pulley does not change the tendon's length
to first order; the moment grows with the angle's error, which makes the hinge's generalised
force a check of that angle.  That equilibrium is mostly unstable in MuJoCo's model, though:
a wrapping cylinder is infinite and lets the tendon slide along its axis (a helix), so
turning the pulley out of the anchor's plane usually shortens the tendon (for 91–98 % of the
cables and poses sampled on three robots), and the tension turns it further.  A free simulation should
therefore drive or damp the hinges, e.g. towards the angles of :func:`pose_to_qpos`: set before
every step to the angles facing the anchors in MuJoCo's state, and to their rates, the exported
SpiderBot follows taut's forward dynamics through its eight pulleys to 2e-9 m over 1 s.

A robot this description cannot hold raises :class:`~taut.errors.UnsupportedRobotError`
naming the construct: no ``platform.mass``, a rigid platform without a positive-definite
``platform.inertia``, a constant ``platform.wrench`` (MJCF has no constant applied wrench),
a jointed body without a ``mass`` or an ``inertia`` (MuJoCo moves no body without them, and
a made-up mass would change the statics taut computes) or whose joint limits are equal
(MuJoCo refuses an empty ``range``), sagging cables (``cables[].weight``), exit pulleys of non-zero radius and obstacles (the
tendons run straight from exit to anchor, or over swivelling pulleys), swivelling pulleys
smaller than :data:`MIN_PULLEY_RADIUS` or on a cable anchored on a jointed body (the
pulley's angle is computed from the platform's frame), and an exit point, anchor or centre
of mass off its body's origin by less than :data:`SAME_FRAME` in every coordinate (MuJoCo
would move it onto the origin).  The platform's and bodies' collision capsules are not
written.

References
----------
.. [1] E. Todorov, T. Erez, Y. Tassa, "MuJoCo: A physics engine for model-based control",
   IEEE/RSJ International Conference on Intelligent Robots and Systems (IROS), 2012.
   (docs/references.bib: todorov2012)
.. [2] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §2.1.1, Eq. 2.1. (docs/references.bib: rushton2022)
.. [3] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, §3.3, Eq. 3.3.12.
   (docs/references.bib: lieskovsky2020)
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import numpy.typing as npt

from taut.errors import InfeasiblePoseError, PoseError, UnsupportedRobotError
from taut.geometry import axis_frames, rotation_matrix
from taut.model._io import write_file
from taut.model._robot import Robot

#: Radius [m] of the sphere whose rotational inertia a point-mass body is given.
POINT_MASS_RADIUS = 1e-3
#: Mass of each swivelling pulley's body as a fraction of the platform's mass.
PULLEY_MASS_RATIO = 1e-3
#: Distance, in pulley radii, of a swivelling cable's exit site outside the pulley rim.
EXIT_SITE_OFFSET = 1e-8
#: Angle [rad] of a swivelling pulley's side site from the pulley plane's ``e`` towards ``k``.
SIDE_SITE_ANGLE = math.radians(10.0)
#: Relative margin kept from the boundaries of the poses where MuJoCo wraps taut's way.
WRAP_MARGIN = 1e-9
#: MuJoCo moves a site or centre of mass whose coordinates are all smaller than this [m] in
#: its body's frame onto the body's origin (``site_sameframe``, ``body_sameframe``; measured
#: with MuJoCo 4.0.0).
SAME_FRAME = 1e-6
#: Smallest swivelling pulley radius [m] written: a pulley's sites lie ``r`` from its
#: body's origin, well beyond :data:`SAME_FRAME`.
MIN_PULLEY_RADIUS = 1e-5


def _number(x: float) -> str:
    """Shortest text that reads back as the same double (so that lengths agree to rounding)."""
    return repr(float(x))


def _vector(values: npt.ArrayLike) -> str:
    return " ".join(_number(x) for x in np.asarray(values, dtype=float).ravel())


def _in_space(point: npt.ArrayLike, dimension: int) -> np.ndarray:
    """A point of the robot as a point of MuJoCo's 3-D space (planar robots in ``z = 0``)."""
    p = np.asarray(point, dtype=float)
    return p if dimension == 3 else np.append(p, 0.0)


def _refuse(robot: Robot, construct: str) -> UnsupportedRobotError:
    return UnsupportedRobotError(f"{robot.name}: cannot be written as a MuJoCo model: {construct}")


def _tensor(values: tuple[float, ...]) -> np.ndarray:
    """The symmetric 3×3 tensor of ``(Ixx, Iyy, Izz, Ixy, Ixz, Iyz)``."""
    xx, yy, zz, xy, xz, yz = values
    return np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]], dtype=float)


def _check_inertia(robot: Robot, what: str, values: tuple[float, ...]) -> None:
    """MuJoCo accepts a moving body's inertia only if it is positive (planar: ``Izz``) or, in
    space, positive definite with principal moments satisfying the triangle inequality
    ``A + B ≥ C`` of every physical body."""
    if robot.dimension == 2:
        if values[0] <= 0:
            raise _refuse(robot, f"{what} Izz is {values[0]:g}; MuJoCo needs it positive")
        return
    moments = np.linalg.eigvalsh(_tensor(values))
    scale = max(1.0, float(moments.max()))
    if moments.min() <= 0:
        raise _refuse(robot, f"{what} {list(values)} is singular; MuJoCo needs it positive definite")
    if moments[0] + moments[1] < moments[2] - 1e-12 * scale:
        raise _refuse(
            robot,
            f"{what} {list(values)} has principal moments {moments.tolist()} that break A + B >= C: "
            "no rigid body has this tensor",
        )


def _check_bodies(robot: Robot) -> None:
    """Every jointed body needs a mass, an inertia (MuJoCo moves no massless body, and taut's
    statics know no other mass) and a joint range, and a cable anchored on one has no
    swivelling pulley.  Bodies are numbered from 1 in messages, as the robot file's checks do."""
    frames = joint_frames(robot)
    for k, body in enumerate(robot.platform.bodies, 1):
        what = f"platform.bodies[{k}] ({body.name})"
        lo, hi = body.joint.limits
        if lo == hi:
            raise _refuse(robot, f"{what} joint limits [{lo:g}, {hi:g}] are equal; MuJoCo needs a joint range of width")
        if k - 1 in frames:
            continue
        if body.mass is None:
            raise _refuse(robot, f"{what} has no mass (a moving MuJoCo body needs one; add its mass, com and inertia)")
        if body.inertia is None:
            raise _refuse(robot, f"{what} has no inertia (a moving MuJoCo body needs its inertia tensor)")
        _check_inertia(robot, f"{what} inertia", body.inertia)
    for i, cable in enumerate(robot.cables, 1):
        if cable.swivel is not None and cable.body is not None:
            raise _refuse(
                robot,
                f"cable {i} has a swivelling pulley and is anchored on the jointed body {cable.body}; "
                "the pulley's angle is written for cables on the platform only",
            )


def check_mjcf(robot: Robot) -> None:
    """Raise :class:`~taut.errors.UnsupportedRobotError` naming the first construct of
    ``robot`` that the MuJoCo model of this module cannot hold exactly (see the module's
    docstring)."""
    plat = robot.platform
    if robot.obstacles:
        raise _refuse(robot, f"obstacles ({len(robot.obstacles)}): MuJoCo tendons here do not wrap around obstacles")
    for i, cable in enumerate(robot.cables, 1):
        if cable.weight:
            raise _refuse(robot, f"cable {i} has a weight (it sags); the tendon would run straight")
        if cable.pulley is not None and cable.pulley.radius > 0:
            raise _refuse(
                robot,
                f"cable {i} leaves an exit pulley of radius {cable.pulley.radius:g}; the tendon would run straight from its exit point",
            )
        if cable.swivel is not None and cable.swivel.radius < MIN_PULLEY_RADIUS:
            raise _refuse(
                robot,
                f"cable {i} has a swivelling pulley of radius {cable.swivel.radius:g} m, below {MIN_PULLEY_RADIUS:g} m, "
                "too small for MuJoCo's sites on it",
            )
    points = [(f"the exit point of cable {i}", c.exit) for i, c in enumerate(robot.cables, 1) if c.swivel is None]
    points += [(f"the anchor of cable {i}", c.anchor) for i, c in enumerate(robot.cables, 1) if c.anchor is not None]
    points += [("platform.wrench_point", plat.wrench_point)] if plat.wrench_point is not None else []
    points += [(f"the com of platform.bodies[{k}] ({b.name})", b.com) for k, b in enumerate(plat.bodies, 1) if b.com]
    for what, point in points:
        if 0 < np.abs(point).max() < SAME_FRAME:
            raise _refuse(
                robot,
                f"{what} {list(point)} is within {SAME_FRAME:g} of its body's origin but not on it; "
                "MuJoCo would move it onto the origin",
            )
    if plat.mass is None:
        raise _refuse(robot, "no platform.mass (a MuJoCo body needs one; add platform.mass and platform.gravity)")
    if plat.wrench is not None and any(w != 0 for w in plat.wrench):
        raise _refuse(
            robot,
            f"platform.wrench {list(plat.wrench)}: MJCF has no constant applied wrench (give the load as platform.mass and platform.gravity)",
        )
    if not robot.is_point_mass:
        if plat.inertia is None:
            raise _refuse(robot, "no platform.inertia (a rigid MuJoCo body needs its inertia tensor)")
        _check_inertia(robot, "platform.inertia", plat.inertia)
    _check_bodies(robot)


def _inertial(robot: Robot) -> dict[str, str]:
    plat, d = robot.platform, robot.dimension
    mass = float(plat.mass or 0.0)
    attrs = {"mass": _number(mass)}
    if robot.is_point_mass:
        sphere = 0.4 * mass * POINT_MASS_RADIUS**2
        return {"pos": "0 0 0", **attrs, "diaginertia": _vector([sphere] * 3)}
    com = _in_space(plat.wrench_point if plat.wrench_point is not None else np.zeros(d), d)
    tensor = robot.inertia
    assert tensor is not None  # check_mjcf refused a rigid platform without one
    if d == 2:
        izz = float(tensor[0, 0])
        return {"pos": _vector(com), **attrs, "diaginertia": _vector([izz / 2, izz / 2, izz])}
    six = [tensor[0, 0], tensor[1, 1], tensor[2, 2], tensor[0, 1], tensor[0, 2], tensor[1, 2]]
    return {"pos": _vector(com), **attrs, "fullinertia": _vector(six)}


def _joints(robot: Robot, body: ET.Element) -> None:
    if robot.dimension == 3 and not robot.is_point_mass:
        ET.SubElement(body, "freejoint", name="pose")
        return
    for name, axis in zip("xyz"[: robot.dimension], np.eye(3)):
        ET.SubElement(body, "joint", name=name, type="slide", axis=_vector(axis), limited="false")
    if not robot.is_point_mass:
        ET.SubElement(body, "joint", name="theta", type="hinge", axis="0 0 1", limited="false")


def _body_inertial(robot: Robot, k: int) -> dict[str, str]:
    """The ``inertial`` of ``platform.bodies[k]``: its mass at its ``com``, its tensor about
    the ``com`` (a planar body's ``Izz`` as the platform's, a thin plate)."""
    body, d = robot.platform.bodies[k], robot.dimension
    values = body.inertia or ()
    attrs = {"pos": _vector(_in_space(robot.body_coms[k], d)), "mass": _number(float(body.mass or 0.0))}
    if d == 2:
        return attrs | {"diaginertia": _vector([values[0] / 2, values[0] / 2, values[0]])}
    return attrs | {"fullinertia": _vector(values)}


def joint_frames(robot: Robot) -> frozenset[int]:
    """The 0-based indices of ``platform.bodies`` that are joint frames: bodies without mass,
    com or inertia, carrying no cable, whose one child body is jointed at their origin (as
    CASPR's universal and spherical joints are read: chains of one-DOF joints).  Each is no
    MuJoCo body of its own: its joint is the first of its child's (see the module's
    docstring)."""
    bodies = robot.platform.bodies
    children: dict[str, list[int]] = {}
    for k, body in enumerate(bodies):
        children.setdefault(body.parent, []).append(k)
    loaded = {cable.body for cable in robot.cables}
    frames = set()
    for k, body in enumerate(bodies):
        kids = children.get(body.name, [])
        if (
            body.mass is None
            and body.inertia is None
            and body.com is None
            and body.name not in loaded
            and len(kids) == 1
        ):
            origin = bodies[kids[0]].joint.origin
            if origin is None or not np.any(origin):
                frames.add(k)
    return frozenset(frames)


def _jointed_bodies(robot: Robot, platform: ET.Element) -> dict[str, ET.Element]:
    """The MuJoCo body of each of ``platform.bodies`` inside its parent's, by taut name (with
    ``platform``): ``body<k>`` at the joint's origin, on ``joint<k>``, preceded by the joints
    of the joint frames that lead to it (:func:`joint_frames`; see the module's docstring)."""
    d = robot.dimension
    frames = joint_frames(robot)
    elements = {"platform": platform}
    #: a joint frame's MuJoCo parent, position and joints, handed on to its child
    pending: dict[str, tuple[ET.Element, np.ndarray, list[dict[str, str]]]] = {}
    for k, body in enumerate(robot.platform.bodies, 1):
        joint = body.joint
        origin = _in_space(joint.origin if joint.origin is not None else np.zeros(d), d)
        if body.parent in pending:
            parent, origin, joints = pending.pop(body.parent)
        else:
            parent, joints = elements[body.parent], []
        if joint.kind == "prismatic":
            axis = _in_space(joint.axis, d)
            attrs = {"type": "slide", "axis": _vector(axis / np.linalg.norm(axis))}
        elif d == 2:
            # taut turns a planar body about +z whatever the sign of its one-number axis
            attrs = {"type": "hinge", "axis": "0 0 1"}
        else:
            axis = np.asarray(joint.axis, dtype=float)
            attrs = {"type": "hinge", "axis": _vector(axis / np.linalg.norm(axis))}
        joints = [*joints, {"name": f"joint{k}", **attrs, "limited": "true", "range": _vector(joint.limits)}]
        if k - 1 in frames:
            pending[body.name] = (parent, origin, joints)
            continue
        element = ET.SubElement(parent, "body", name=f"body{k}", pos=_vector(origin))
        for attributes in joints:
            ET.SubElement(element, "joint", attributes)
        ET.SubElement(element, "inertial", _body_inertial(robot, k - 1))
        elements[body.name] = element
    return elements


def joint_order(robot: Robot) -> np.ndarray:
    """The 0-based indices of ``platform.bodies`` in MuJoCo's order of their joints in
    ``qpos`` and ``qvel``: depth first through the body tree, children in file order (taut's
    order for a chain)."""
    children: dict[str, list[int]] = {}
    for k, body in enumerate(robot.platform.bodies):
        children.setdefault(body.parent, []).append(k)
    order: list[int] = []
    stack = list(reversed(children.get("platform", [])))
    while stack:
        k = stack.pop()
        order.append(k)
        stack += reversed(children.get(robot.platform.bodies[k].name, []))
    return np.array(order, dtype=int)


def swivel_frames(robot: Robot) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``(indices (s,), unit axes k (s, 3), zero directions e_0 (s, 3), radii (s,))`` of the
    robot's swivelling pulleys: ``e_0`` is the unit normal of ``k`` nearest the fixed ``x``
    axis (``y`` for an axis within 26° of ``x``), the direction of the hinge angle ``q = 0``."""
    idx = np.array(robot.swivel_cables, dtype=int)
    swivels = [s for s in (robot.cables[i].swivel for i in idx) if s is not None]
    frames = axis_frames(np.array([s.axis for s in swivels], dtype=float).reshape(-1, 3))
    k, e0 = frames[:, :, 2], frames[:, :, 0]
    return idx, k, e0, np.array([s.radius for s in swivels], dtype=float)


def _pulley(robot: Robot, world: ET.Element, i: int, k: np.ndarray, e0: np.ndarray, r: float) -> None:
    """The body, hinge, wrapping cylinder and sites of cable ``i``'s (1-based) swivelling pulley.

    The body's origin is the pulley centre, not the exit point: MuJoCo puts a site within
    :data:`SAME_FRAME` of its body's origin at the origin, which would put an exit site
    :data:`EXIT_SITE_OFFSET` ``r`` from the exit point back on the rim."""
    frame = np.column_stack([e0, np.cross(k, e0)])
    body = ET.SubElement(
        world,
        "body",
        name=f"pulley{i}",
        pos=_vector(robot.exits[i - 1] + r * e0),
        quat=_vector(quaternions(np.column_stack([frame, k]))),
    )
    ET.SubElement(
        body, "joint", name=f"swivel{i}", type="hinge", axis="0 0 1", pos=_vector([-r, 0.0, 0.0]), limited="false"
    )
    mass = PULLEY_MASS_RATIO * float(robot.platform.mass or 0.0)
    sphere = 0.4 * mass * r * r
    ET.SubElement(body, "inertial", pos=_vector([-r, 0.0, 0.0]), mass=_number(mass), diaginertia=_vector([sphere] * 3))
    # the cylinder's local x, y are the pulley plane's e, k: its axis e × k is the plane's normal
    ET.SubElement(
        body,
        "geom",
        name=f"wheel{i}",
        type="cylinder",
        size=_vector([r, r / 4]),
        xyaxes="1 0 0 0 0 1",
        contype="0",
        conaffinity="0",
    )
    ET.SubElement(body, "site", name=f"exit{i}", pos=_vector([-(1 + EXIT_SITE_OFFSET) * r, 0.0, 0.0]))
    side = [2 * r * math.cos(SIDE_SITE_ANGLE), 0.0, 2 * r * math.sin(SIDE_SITE_ANGLE)]
    ET.SubElement(body, "site", name=f"side{i}", pos=_vector(side))


def mjcf_text(robot: Robot) -> str:
    """The MuJoCo model (MJCF XML) of ``robot`` (module docstring): a free (or planar) platform
    body with the jointed bodies, one spatial tendon per cable whose tension is the control
    of an actuator.

    Parameters
    ----------
    robot : Robot

    Returns
    -------
    str

    Raises
    ------
    UnsupportedRobotError
        For a robot the model cannot hold exactly (:func:`check_mjcf`).

    References
    ----------
    .. [1] E. Todorov, T. Erez, Y. Tassa, "MuJoCo: A physics engine for model-based control",
       IEEE/RSJ International Conference on Intelligent Robots and Systems (IROS), 2012.
       (docs/references.bib: todorov2012)

    Examples
    --------
    >>> from taut.model import example
    >>> text = mjcf_text(example("planar-4cable"))
    >>> text.splitlines()[0], text.count("<spatial ")
    ('<mujoco model="planar 4-cable robot">', 4)
    """
    check_mjcf(robot)
    d = robot.dimension
    root = ET.Element("mujoco", model=robot.name)
    # the robot's name stays in the attribute: a comment cannot hold every string ("--")
    root.append(ET.Comment(" written by taut; cable i is tendon cable<i>, its tension the control of tension<i> "))
    ET.SubElement(root, "compiler", angle="radian", autolimits="false")
    mass = float(robot.platform.mass or 0.0)
    ET.SubElement(root, "option", gravity=_vector(_in_space(robot.weight / mass, d)))
    world = ET.SubElement(root, "worldbody")
    swivel = set(robot.swivel_cables)
    for i, exit_point in enumerate(robot.exits, 1):
        if i - 1 not in swivel:
            ET.SubElement(world, "site", name=f"exit{i}", pos=_vector(_in_space(exit_point, d)))
    platform = ET.SubElement(world, "body", name="platform", pos="0 0 0")
    _joints(robot, platform)
    ET.SubElement(platform, "inertial", _inertial(robot))
    bodies = _jointed_bodies(robot, platform)
    for i, (anchor, cable) in enumerate(zip(robot.anchors, robot.cables), 1):
        ET.SubElement(bodies[cable.body or "platform"], "site", name=f"anchor{i}", pos=_vector(_in_space(anchor, d)))
        for k, via in enumerate(cable.via, 1):
            where = world if via.body == "fixed" else bodies[via.body]
            ET.SubElement(where, "site", name=f"via{i}_{k}", pos=_vector(_in_space(via.point, d)))
    idx, axes, zeros, radii = swivel_frames(robot)
    for j, i in enumerate(idx):
        _pulley(robot, world, int(i) + 1, axes[j], zeros[j], float(radii[j]))
    tendons = ET.SubElement(root, "tendon")
    lmin, lmax = robot.length_bounds
    for i in range(1, robot.n_cables + 1):
        attrs = {"name": f"cable{i}"}
        if lmin[i - 1] > 0 or math.isfinite(lmax[i - 1]):
            attrs |= {"limited": "true", "range": _vector([lmin[i - 1], lmax[i - 1]])}
        tendon = ET.SubElement(tendons, "spatial", attrs)
        ET.SubElement(tendon, "site", site=f"exit{i}")
        if i - 1 in swivel:
            ET.SubElement(tendon, "geom", geom=f"wheel{i}", sidesite=f"side{i}")
        for k in range(1, len(robot.cables[i - 1].via) + 1):
            ET.SubElement(tendon, "site", site=f"via{i}_{k}")
        ET.SubElement(tendon, "site", site=f"anchor{i}")
    actuators = ET.SubElement(root, "actuator")
    tmin, tmax = robot.tension_bounds
    for i in range(1, robot.n_cables + 1):
        ET.SubElement(
            actuators,
            "general",
            name=f"tension{i}",
            tendon=f"cable{i}",
            gear="-1",
            ctrllimited="true",
            ctrlrange=_vector([tmin[i - 1], tmax[i - 1]]),
        )
    for k, body in enumerate(robot.platform.bodies, 1):
        drive = {"name": f"drive{k}", "joint": f"joint{k}", "gear": "1", "ctrllimited": "false"}
        motor = body.joint.actuator
        if motor is not None and all(math.isfinite(f) for f in motor.force):
            drive |= {"ctrllimited": "true", "ctrlrange": _vector(list(motor.force))}
        ET.SubElement(actuators, "general", drive)
    ET.indent(root)
    return ET.tostring(root, encoding="unicode") + "\n"


def write_mjcf(robot: Robot, path: str | Path) -> None:
    """Write the MuJoCo model of ``robot`` (:func:`mjcf_text`) to ``path``, e.g.
    ``robot.mjcf.xml``.

    Parameters
    ----------
    robot : Robot
    path : str or Path

    Raises
    ------
    UnsupportedRobotError
        For a robot the model cannot hold exactly.
    RobotFileError
        If the file cannot be written.

    References
    ----------
    .. [1] E. Todorov, T. Erez, Y. Tassa, "MuJoCo: A physics engine for model-based control",
       IEEE/RSJ International Conference on Intelligent Robots and Systems (IROS), 2012.
       (docs/references.bib: todorov2012)

    Examples
    --------
    >>> from taut.model import example
    >>> import pathlib, tempfile
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "robot.mjcf.xml"
    >>> write_mjcf(example("spatial-8cable"), path)
    >>> path.read_text().startswith('<mujoco model="spatial 8-cable robot">')
    True
    """
    write_file(path, mjcf_text(robot))


def quaternions(R: npt.ArrayLike) -> np.ndarray:
    """Unit quaternions ``(w, x, y, z)`` with ``w ≥ 0`` of rotation matrices ``(..., 3, 3)``,
    shape ``(..., 4)``: Shepperd's method, from the largest of ``4w², 4x², 4y², 4z²`` so that
    no division loses precision."""
    R = np.asarray(R, dtype=float)
    r00, r11, r22 = R[..., 0, 0], R[..., 1, 1], R[..., 2, 2]
    squares = np.stack([1 + r00 + r11 + r22, 1 + r00 - r11 - r22, 1 - r00 + r11 - r22, 1 - r00 - r11 + r22], -1)
    k = np.argmax(squares, axis=-1)
    big = 0.5 * np.sqrt(np.maximum(np.take_along_axis(squares, k[..., None], -1)[..., 0], 0.0))
    f = 0.25 / big
    s21, s02, s10 = R[..., 2, 1] - R[..., 1, 2], R[..., 0, 2] - R[..., 2, 0], R[..., 1, 0] - R[..., 0, 1]
    a01, a02, a12 = R[..., 0, 1] + R[..., 1, 0], R[..., 0, 2] + R[..., 2, 0], R[..., 1, 2] + R[..., 2, 1]
    candidates = np.stack(
        [
            np.stack([big, s21 * f, s02 * f, s10 * f], -1),
            np.stack([s21 * f, big, a01 * f, a02 * f], -1),
            np.stack([s02 * f, a01 * f, big, a12 * f], -1),
            np.stack([s10 * f, a02 * f, a12 * f, big], -1),
        ],
        -2,
    )
    q = np.take_along_axis(candidates, k[..., None, None], -2)[..., 0, :]
    return np.where(q[..., :1] < 0, -q, q)


def _checked_poses(robot: Robot, poses: npt.ArrayLike) -> tuple[np.ndarray, bool]:
    check_mjcf(robot)
    try:
        arr = np.asarray(poses, dtype=float)
    except (TypeError, ValueError):
        raise PoseError(f"{robot.name}: poses must be numbers, got {poses!r}") from None
    single = arr.ndim == 1
    arr = np.atleast_2d(arr)
    if arr.ndim != 2 or arr.shape[1] != robot.pose_size:
        raise PoseError(
            f"{robot.name}: a pose has {robot.pose_size} coordinates ({', '.join(robot.pose_names)}), got shape {np.shape(poses)}"
        )
    if not np.all(np.isfinite(arr)):
        raise PoseError(f"{robot.name}: a pose coordinate is not finite")
    q, limits = arr[:, robot.wrench_dim :], robot.joint_limits
    outside = (q < limits[:, 0]) | (q > limits[:, 1])
    if outside.any():
        n, j = np.argwhere(outside)[0]
        raise PoseError(
            f"{robot.name}: pose {n + 1}: joint {robot.pose_names[robot.wrench_dim + j]} = {q[n, j]:g} is outside "
            f"its limits [{limits[j, 0]:g}, {limits[j, 1]:g}], where MuJoCo's joint limit would push"
        )
    return arr, single


def _swivels(robot: Robot, arr: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Hinge angles ``(N, s)`` of the swivelling pulleys at checked poses, and where MuJoCo's
    wrap is taut's path ``(N, s)`` (see the module's docstring)."""
    idx, k, e0, r = swivel_frames(robot)
    if robot.is_point_mass:
        b = np.broadcast_to(arr[:, None, :3], (len(arr), len(idx), 3))
    else:
        R = rotation_matrix(arr[:, 3:6], robot.orientation)
        b = arr[:, None, :3] + np.einsum("nij,sj->nsi", R, robot.anchors[idx])
    v = b - robot.exits[idx][None]
    h = np.einsum("nsi,si->ns", v, k)
    w = v - h[..., None] * k[None]
    q = np.arctan2(np.einsum("nsi,si->ns", w, np.cross(k, e0)), np.einsum("nsi,si->ns", w, e0))
    # the anchor about the pulley centre, along e and k
    x = np.linalg.norm(w, axis=-1) - r
    m = WRAP_MARGIN * r
    wedge = (x < 0) & (h <= m) & (-h <= -x * math.tan(SIDE_SITE_ANGLE) + m)
    return q, (np.hypot(x, h) > r + m) & ~wedge


def swivel_wraps_agree(robot: Robot, poses: npt.ArrayLike) -> np.ndarray | bool:
    """Whether MuJoCo wraps every swivelling pulley of the model of :func:`mjcf_text` as taut
    does at ``poses``: ``(N,)`` booleans for ``(N, pose_size)`` poses, one boolean for one
    pose (all true for a robot without swivelling pulleys).

    MuJoCo picks the way round a wrapping cylinder by its side site, which is taut's way
    unless the anchor lies on or inside the pulley circle or in a thin wedge just outside its
    rim, behind the exit point and nearer the axis than the pulley centre (the module's
    docstring).

    Raises
    ------
    PoseError
        For poses of the wrong size or with a non-finite coordinate.
    UnsupportedRobotError
        For a robot the model cannot hold (:func:`check_mjcf`).
    """
    arr, single = _checked_poses(robot, poses)
    ok = np.ones(len(arr), dtype=bool)
    if robot.swivel_cables:
        ok = np.all(_swivels(robot, arr)[1], axis=1)
    return bool(ok[0]) if single else ok


def pose_to_qpos(robot: Robot, poses: npt.ArrayLike) -> np.ndarray:
    """MuJoCo's ``qpos`` of the model of :func:`mjcf_text` at taut poses.

    Spatial rigid platform: ``(x, y, z, w, qx, qy, qz)``, the quaternion of the rotation of the
    pose's three angles in the robot's orientation convention (``docs/architecture.md`` §2.3);
    planar rigid platform: ``(x, y, θ)``; point mass: its position.  Then the joint
    coordinates of the jointed bodies in MuJoCo's order (:func:`joint_order`).  Then the hinge
    angle of each swivelling pulley, in cable order: the angle about the swivel axis ``k`` from
    the pulley's ``e_0`` (:func:`swivel_frames`) to the anchor's direction from the axis, so
    that the pulley plane holds the anchor, as in :mod:`taut.kinematics._swivel`.

    Parameters
    ----------
    robot : Robot
    poses : array_like, shape (N, pose_size) or (pose_size,)

    Returns
    -------
    ndarray, shape (N, nq) or (nq,)

    Raises
    ------
    PoseError
        For poses that are not numbers, of the wrong size, with a non-finite coordinate or a
        joint coordinate outside its limits (where MuJoCo's joint limit would push).
    InfeasiblePoseError
        For a pose at which MuJoCo would wrap a swivelling pulley another way than taut
        (:func:`swivel_wraps_agree`).
    UnsupportedRobotError
        For a robot the model cannot hold (:func:`check_mjcf`).

    References
    ----------
    .. [1] E. Todorov, T. Erez, Y. Tassa, "MuJoCo: A physics engine for model-based control",
       IEEE/RSJ International Conference on Intelligent Robots and Systems (IROS), 2012.
       (docs/references.bib: todorov2012)

    Examples
    --------
    A quarter turn about ``z`` is the quaternion ``(cos π/4, 0, 0, sin π/4)``:

    >>> from taut.model import example
    >>> np.round(pose_to_qpos(example("spatial-8cable"), [0.1, 0.2, 0.3, 0.0, 0.0, np.pi / 2]), 6)
    array([0.1     , 0.2     , 0.3     , 0.707107, 0.      , 0.      , 0.707107])
    """
    arr, single = _checked_poses(robot, poses)
    m = robot.wrench_dim
    if robot.dimension == 3 and not robot.is_point_mass:
        qpos = np.concatenate([arr[:, :3], quaternions(rotation_matrix(arr[:, 3:6], robot.orientation))], axis=1)
    else:
        qpos = arr[:, :m].copy()
    qpos = np.concatenate([qpos, arr[:, m + joint_order(robot)]], axis=1)
    if robot.swivel_cables:
        q, agree = _swivels(robot, arr)
        if not agree.all():
            n, j = np.argwhere(~agree)[0]
            raise InfeasiblePoseError(
                f"{robot.name}: at pose {n + 1} the anchor of cable {robot.swivel_cables[j] + 1} is on or inside "
                "its swivelling pulley's circle, or just outside it behind the exit point, where MuJoCo's tendon "
                "would not wrap the pulley as taut's cable does"
            )
        qpos = np.concatenate([qpos, q], axis=1)
    return qpos[0] if single else qpos
