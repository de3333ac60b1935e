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
``a_i``) and the site ``anchor{i}`` (platform body, at ``r_i``), so that MuJoCo's tendon length
is ``‖a_i − b_i‖``; its length bounds, where the robot gives them, are the tendon's ``range``.
The actuator ``tension{i}`` is a force actuator on that tendon with ``gear = −1``: its control
is the cable tension ``τ_i`` [N] pulling the platform towards the exit point, its
``ctrlrange`` the tension bounds.  Cables are ideal (massless, inextensible): their
``stiffness`` is not written.

In MuJoCo's generalised coordinates a platform wrench ``(f, m)`` (force in the fixed frame,
moment about ``p``, as :mod:`taut.statics` writes them) is ``(f, Rᵀ m)`` for the freejoint,
whose angular velocity is expressed in the body frame, and ``(f_x, f_y, m_z)`` or ``f`` for the
planar and point-mass joints: ``mj_inverse`` at rest returns that of ``−w_ext``.

A robot this description cannot hold raises :class:`~taut.errors.UnsupportedRobotError`
naming the construct: no ``platform.mass``, a rigid platform without a positive-definite
``platform.inertia``, a constant ``platform.wrench`` (MJCF has no constant applied wrench),
jointed bodies (the robot file gives them no mass), exit pulleys of non-zero radius,
swivelling pulleys and obstacles (the tendons run straight from exit to anchor).

References
----------
.. [1] E. Todorov, T. Erez, Y. Tassa, "MuJoCo: A physics engine for model-based control",
   IEEE/RSJ International Conference on Intelligent Robots and Systems (IROS), 2012.
   (docs/references.bib: todorov2012)
.. [2] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §2.1.1, Eq. 2.1. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import numpy.typing as npt

from taut.errors import PoseError, UnsupportedRobotError
from taut.geometry.rotation import rotation_matrix
from taut.model.robot import Robot

#: Radius [m] of the sphere whose rotational inertia a point-mass body is given.
POINT_MASS_RADIUS = 1e-3


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


def _check_physical(robot: Robot, tensor: np.ndarray) -> None:
    """MuJoCo accepts a rigid body's tensor only if it is positive definite and its principal
    moments satisfy the triangle inequality ``A + B ≥ C`` of every physical body."""
    moments = np.linalg.eigvalsh(tensor)
    scale = max(1.0, float(moments.max()))
    if moments.min() <= 0:
        raise _refuse(
            robot,
            f"platform.inertia {list(robot.platform.inertia or ())} is singular; MuJoCo needs it positive definite",
        )
    if moments[0] + moments[1] < moments[2] - 1e-12 * scale:
        raise _refuse(
            robot,
            f"platform.inertia {list(robot.platform.inertia or ())} has principal moments "
            f"{moments.tolist()} that break A + B >= C: no rigid body has this tensor",
        )


def check_mjcf(robot: Robot) -> None:
    """Raise :class:`~taut.errors.UnsupportedRobotError` naming the first construct of
    ``robot`` that the MuJoCo model of this module cannot hold exactly (see the module's
    docstring)."""
    plat = robot.platform
    if plat.bodies:
        names = ", ".join(b.name for b in plat.bodies)
        raise _refuse(robot, f"platform.bodies ({names}): the robot file gives jointed bodies no mass or inertia")
    if robot.obstacles:
        raise _refuse(robot, f"obstacles ({len(robot.obstacles)}): MuJoCo tendons here do not wrap around obstacles")
    for i, cable in enumerate(robot.cables, 1):
        if cable.pulley is not None and cable.pulley.radius > 0:
            raise _refuse(
                robot,
                f"cable {i} leaves an exit pulley of radius {cable.pulley.radius:g}; the tendon would run straight from its exit point",
            )
        if cable.swivel is not None:
            raise _refuse(
                robot,
                f"cable {i} has a swivelling pulley of radius {cable.swivel.radius:g}; the tendon would run straight from its exit point",
            )
    if plat.mass is None:
        raise _refuse(robot, "no platform.mass (a MuJoCo body needs one; add platform.mass and platform.gravity)")
    if plat.wrench is not None and any(w != 0 for w in plat.wrench):
        raise _refuse(
            robot,
            f"platform.wrench {list(plat.wrench)}: MJCF has no constant applied wrench (give the load as platform.mass and platform.gravity)",
        )
    if not robot.is_point_mass:
        tensor = robot.inertia
        if tensor is None:
            raise _refuse(robot, "no platform.inertia (a rigid MuJoCo body needs its inertia tensor)")
        if robot.dimension == 2:
            if tensor[0, 0] <= 0:
                raise _refuse(robot, "platform.inertia Izz is 0; MuJoCo needs it positive")
        else:
            _check_physical(robot, tensor)


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


def mjcf_text(robot: Robot) -> str:
    """The MuJoCo model (MJCF XML) of ``robot``; see the module's docstring for what it holds.

    Raises
    ------
    UnsupportedRobotError
        For a robot the model cannot hold exactly (:func:`check_mjcf`).

    References
    ----------
    .. [1] E. Todorov, T. Erez, Y. Tassa, "MuJoCo: A physics engine for model-based control",
       IEEE/RSJ International Conference on Intelligent Robots and Systems (IROS), 2012.
       (docs/references.bib: todorov2012)
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
    for i, exit_point in enumerate(robot.exits, 1):
        ET.SubElement(world, "site", name=f"exit{i}", pos=_vector(_in_space(exit_point, d)))
    platform = ET.SubElement(world, "body", name="platform", pos="0 0 0")
    _joints(robot, platform)
    ET.SubElement(platform, "inertial", _inertial(robot))
    for i, anchor in enumerate(robot.anchors, 1):
        ET.SubElement(platform, "site", name=f"anchor{i}", pos=_vector(_in_space(anchor, d)))
    tendons = ET.SubElement(root, "tendon")
    lmin, lmax = robot.length_bounds
    for i in range(1, robot.n_cables + 1):
        attrs = {"name": f"cable{i}"}
        if lmin[i - 1] > 0 or math.isfinite(lmax[i - 1]):
            attrs |= {"limited": "true", "range": _vector([lmin[i - 1], lmax[i - 1]])}
        tendon = ET.SubElement(tendons, "spatial", attrs)
        ET.SubElement(tendon, "site", site=f"exit{i}")
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
    ET.indent(root)
    return ET.tostring(root, encoding="unicode") + "\n"


def write_mjcf(robot: Robot, path: str | Path) -> None:
    """Write the MuJoCo model of ``robot`` (:func:`mjcf_text`) to ``path``, e.g. ``robot.mjcf.xml``.

    References
    ----------
    .. [1] E. Todorov, T. Erez, Y. Tassa, "MuJoCo: A physics engine for model-based control",
       IEEE/RSJ International Conference on Intelligent Robots and Systems (IROS), 2012.
       (docs/references.bib: todorov2012)
    """
    Path(path).write_text(mjcf_text(robot), encoding="utf-8")


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


def pose_to_qpos(robot: Robot, poses: npt.ArrayLike) -> np.ndarray:
    """MuJoCo's ``qpos`` of the model of :func:`mjcf_text` at taut poses: ``(N, nq)`` for
    ``(N, pose_size)`` poses, ``(nq,)`` for one pose.

    Spatial rigid platform: ``(x, y, z, w, qx, qy, qz)``, the quaternion of the rotation of the
    pose's three angles in the robot's orientation convention (``docs/architecture.md`` §2.3);
    planar rigid platform: ``(x, y, θ)``; point mass: its position.

    Raises
    ------
    PoseError
        For poses of the wrong size or with a non-finite coordinate.
    UnsupportedRobotError
        For a robot the model cannot hold (:func:`check_mjcf`).
    """
    check_mjcf(robot)
    arr = np.asarray(poses, dtype=float)
    single = arr.ndim == 1
    arr = np.atleast_2d(arr)
    if arr.ndim != 2 or arr.shape[1] != robot.pose_size:
        raise PoseError(
            f"{robot.name}: a pose has {robot.pose_size} coordinates ({', '.join(robot.pose_names)}), got shape {np.shape(poses)}"
        )
    if not np.all(np.isfinite(arr)):
        raise PoseError(f"{robot.name}: a pose coordinate is not finite")
    if robot.dimension == 3 and not robot.is_point_mass:
        qpos = np.concatenate([arr[:, :3], quaternions(rotation_matrix(arr[:, 3:6], robot.orientation))], axis=1)
    else:
        qpos = arr.copy()
    return qpos[0] if single else qpos
