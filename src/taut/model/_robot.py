"""The robot description: typed, validated data and nothing else (``docs/architecture.md`` §3).

A :class:`Robot` holds what every analysis of taut needs: the cables (exit point ``a_i``,
platform anchor ``r_i`` in the frame of the body it is attached to, tension and length
bounds, axial stiffness), the platform (point mass or rigid, extra bodies joined by
joints, the external wrench), collidable obstacles and the installation space of
variable-structure robots, reference data from the sources and named trajectories.
The validators raise :class:`taut.RobotFileError` (a ``ValueError``, which pydantic
collects into one ``ValidationError``), and :mod:`taut.model._io` turns that back into one
:class:`taut.RobotFileError` naming every field.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §4.1, §6.2. (docs/references.bib: rushton2022)
.. [2] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, §2.3.2, §4.2.
   (docs/references.bib: lieskovsky2020)
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping
from typing import Annotated, Any, Literal, Self, TypeVar

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, PrivateAttr, ValidationError, field_validator, model_validator

from taut.errors import RobotFileError
from taut.geometry import CONVENTIONS
from taut.model._limits import MAX_MAGNITUDE

FORMAT: Literal["taut/1"] = "taut/1"

#: Gravitational acceleration [m/s²] along the last axis (−y planar, −z spatial) when a
#: platform has a mass but no ``gravity``.
STANDARD_GRAVITY = 9.81

Number = Annotated[float, Field(allow_inf_nan=True)]
Finite = Annotated[float, Field(allow_inf_nan=False)]
#: Coordinates [m], within :data:`~taut.model._limits.MAX_MAGNITUDE`.
Coordinate = Annotated[float, Field(allow_inf_nan=False, ge=-MAX_MAGNITUDE, le=MAX_MAGNITUDE)]

Derived = TypeVar("Derived", np.ndarray, tuple[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray, np.ndarray])


#: A numpydoc section header (``Attributes`` and its underline): where a model's docstring
#: stops describing the file format and starts describing the Python class.
_SECTION = re.compile(r"\n\n[A-Z][A-Za-z ]*\n-{3,}\n")


def _schema_description(schema: dict[str, Any], model: type) -> None:
    """The JSON Schema describes a model by its docstring up to the first numpydoc section."""
    text = schema.get("description")
    if isinstance(text, str):
        schema["description"] = _SECTION.split(text, maxsplit=1)[0].rstrip()


class _Strict(BaseModel):
    """Base of the description's models: unknown keys are errors and instances are immutable
    (frozen, with tuples for sequences), so that arrays derived from them cannot go stale."""

    model_config = ConfigDict(extra="forbid", frozen=True, json_schema_extra=_schema_description)

    def __init__(self, /, **data: Any) -> None:
        """Validate ``data``: fields that do not validate raise one
        :class:`~taut.errors.RobotFileError` line naming the class, the first field and what
        is wrong (not pydantic's ``ValidationError``, which is no :class:`~taut.errors.TautError`).
        """
        try:
            super().__init__(**data)
        except ValidationError as exc:
            from taut.model._messages import validation_message

            raise RobotFileError(validation_message(type(self).__name__, exc)) from None

    # what pydantic's own __init__ (and RootModel's) carry: validating a nested model (the
    # cables of a robot) need not call this one, so errors keep their place in the parent's
    __init__.__pydantic_base_init__ = True  # type: ignore[attr-defined]

    def model_copy(self, *, update: Mapping[str, Any] | None = None, deep: bool = False) -> Self:
        """A copy of this instance; with ``update``, a new instance validated from this one's
        fields and the update (pydantic's own copy would take the update unchecked and keep
        the arrays derived from the old fields).

        Raises
        ------
        RobotFileError
            If the updated fields do not validate.
        """
        if not update:
            return super().model_copy(deep=deep)
        fields = {name: getattr(self, name) for name in self.model_fields_set}
        try:
            return type(self).model_validate(fields | dict(update))
        except ValidationError as exc:
            from taut.model._messages import validation_message

            raise RobotFileError(validation_message(f"{type(self).__name__}.model_copy", exc)) from None


class _DerivedArrays(dict[str, Any]):
    """Arrays computed from a robot's fields on first use.  They are not part of the robot's
    value: two robots with equal fields are equal whatever each has computed so far."""

    def __eq__(self, other: object) -> bool:
        return isinstance(other, _DerivedArrays)

    __hash__ = None  # a mutable cache, like dict


def _inertia_matrix(values: tuple[float, ...]) -> np.ndarray:
    """The symmetric tensor of ``Izz`` or of ``Ixx, Iyy, Izz, Ixy, Ixz, Iyz`` (MuJoCo's
    ``fullinertia`` order)."""
    if len(values) == 1:
        return np.array([[values[0]]], dtype=float)
    xx, yy, zz, xy, xz, yz = values
    return np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]], dtype=float)


def _check_inertia(values: tuple[float, ...], d: int, where: str) -> None:
    """Raise ``ValueError`` unless ``values`` is an inertia of a ``d``-dimensional body: one
    ``Izz`` (planar) or six numbers (spatial) of a positive semi-definite tensor."""
    if len(values) != (1 if d == 2 else 6):
        raise RobotFileError(f"{where}.inertia: expected {1 if d == 2 else 6} numbers, got {len(values)}")
    tensor = _inertia_matrix(values)
    # rounding leaves a singular tensor (a rod, a point) slightly negative
    if np.linalg.eigvalsh(tensor).min() < -1e-12 * max(1.0, float(np.abs(tensor).max())):
        raise RobotFileError(f"{where}.inertia: not a positive semi-definite inertia tensor, got {list(values)}")


def _check_bounds(v: tuple[float, float], what: str) -> tuple[float, float]:
    lo, hi = v
    if math.isnan(lo) or math.isnan(hi):
        raise RobotFileError(f"{what} bounds must be numbers, got {list(v)}")
    if lo < 0:
        raise RobotFileError(f"{what} lower bound must be >= 0, got {lo}")
    if lo > hi:
        raise RobotFileError(f"{what} bounds are inverted: lower {lo} > upper {hi}")
    if math.isinf(lo):
        raise RobotFileError(f"{what} lower bound must be finite, got {lo}")
    return (float(lo), float(hi))


class Pulley(_Strict):
    """Exit pulley of a winch: the cable leaves it tangentially (Rushton 2022, §4.1).

    Attributes
    ----------
    radius : float
        Pulley radius [m], ≥ 0.
    direction : {"ccw", "cw"}
        The way the cable wraps it, counter-clockwise or clockwise.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §4.1. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> Pulley(radius=0.05)
    Pulley(radius=0.05, direction='ccw')
    """

    radius: Finite = Field(ge=0)
    direction: Literal["ccw", "cw"] = "ccw"


class SwivelPulley(_Strict):
    """A swivelling exit pulley (CASPR's ``base_rotating_pulley``, the pulley of WireX's and
    Pott's kinematic model).

    The cable comes from its winch along the swivel axis and runs onto the pulley at the
    cable's ``exit`` point, which lies on that axis.  The pulley turns about the axis so that
    its plane contains the platform anchor; its centre lies ``radius`` away from the axis, on
    the anchor's side, the cable wraps around it and leaves it tangentially towards the
    anchor.  The wrap angle and the tangent point follow from the anchor's position
    (``taut.kinematics._swivel``).  On a planar robot the axis lies in the robot's plane (two
    numbers), and so does the pulley: the cable comes along the axis, wraps the pulley on the
    anchor's side of the axis line and leaves towards the anchor.

    Attributes
    ----------
    axis : tuple of float
        Direction of the swivel axis in the fixed frame (3 numbers; 2 in a planar robot's
        plane), the way the cable runs onto the pulley; any non-zero length.
    radius : float
        Pulley radius [m], > 0, to the cable's centre line in the groove.

    References
    ----------
    .. [1] A. Pott, "Cable-Driven Parallel Robots: Theory and Application", Springer Tracts in
       Advanced Robotics 120, Springer, 2018, pulley kinematics. (docs/references.bib: pott2018)

    Examples
    --------
    >>> SwivelPulley(axis=(0, 0, -1), radius=0.03).radius
    0.03
    """

    axis: tuple[Finite, ...] = Field(
        min_length=2,
        max_length=3,
        description="direction of the swivel axis in the fixed frame (x, y, z; x, y in a planar robot's plane): "
        "the way the cable runs, coming from "
        "its winch, onto the pulley at the cable's exit point (CASPR's cable_entry_vector, the z axis of "
        "WireX's winch frame); any non-zero length, it is normalised. Its sign fixes the side the cable "
        "leaves on: the pulley swivels to face the anchor (its centre on the anchor's side of the axis) "
        "and the cable, running along this direction, wraps around it until it heads for the anchor",
    )
    radius: Finite = Field(
        gt=0, le=MAX_MAGNITUDE, description="pulley radius [m] (to the cable's centre line in the groove)"
    )

    @field_validator("axis")
    @classmethod
    def _axis(cls, v: tuple[float, ...]) -> tuple[float, ...]:
        if not math.hypot(*v) > 0:
            raise RobotFileError(f"swivel axis must be a non-zero vector, got {list(v)}")
        return v


class ViaPoint(_Strict):
    """A point that a routed cable runs through between its exit point and its anchor: an
    eyelet or a frictionless guide on the fixed frame or on a platform body.  A cable through
    via points is a chain of straight segments, exit → via points → anchor, its length their
    sum and its tension the same along it: CASPR's cables of more than two attachments, whose
    segments the cable-routing matrix of Lau, Oetomo & Halgamuge (2013, §III) assigns to links.

    Attributes
    ----------
    point : tuple of float
        The point in the frame of its body [m] (``dimension`` numbers).
    body : str
        ``fixed`` (the fixed frame), ``platform`` (default) or a name of ``platform.bodies``.

    References
    ----------
    .. [1] D. Lau, D. Oetomo, S. K. Halgamuge, "Generalized modeling of multilink cable-driven
       manipulators with arbitrary routing using the cable-routing matrix", IEEE Transactions
       on Robotics 29(5), 2013, §III. (docs/references.bib: lau2013)

    Examples
    --------
    >>> ViaPoint(point=(0.0, 0.1, 0.0), body="arm").body
    'arm'
    """

    point: tuple[Coordinate, ...]
    body: str = Field(
        default="platform",
        description="`fixed` (the fixed frame), `platform` or a name of `platform.bodies`: where the point is fixed",
    )


class Cable(_Strict):
    """Cable *i*: from the fixed exit point ``a_i`` to the anchor ``r_i`` on a platform body.

    With ``swivel``, ``a_i`` is the point where the cable runs onto its swivelling pulley.

    Attributes
    ----------
    name : str or None
        A name for messages and figures.
    exit : tuple of float
        The exit point ``a_i`` in the fixed frame [m] (``dimension`` numbers).
    anchor : tuple of float or None
        The anchor ``r_i`` in the frame of its body [m]; the body's origin when not given.
    body : str or None
        The body it is anchored to: ``platform`` (default) or a name of ``platform.bodies``.
    tension : (float, float)
        Tension bounds ``(τ_min, τ_max)`` [N]: ``0 ≤ τ_min ≤ τ_max``, ``τ_max`` may be ``inf``.
    length : (float, float) or None
        Length bounds [m].
    stiffness : float or None
        Axial stiffness ``EA`` [N] (elastic cables in the dynamics; with ``weight``, the
        elastic catenary's; none: inextensible).
    weight : float or None
        Weight per unit length of the unstrained cable [N/m], ``≥ 0``: a cable with a positive
        weight sags along the robot's gravity (an elastic catenary, ``taut.cables``); none or
        0: a straight cable.
    radius : float
        Cable radius for interference checks [m].
    pulley : Pulley or None
        Exit pulley of a planar winch, that collidable cables wrap around.
    swivel : SwivelPulley or None
        Swivelling exit pulley.
    via : tuple of ViaPoint
        Points the cable runs through, in order from its exit point to its anchor (a routed
        cable: a chain of straight segments).
    length_offset : float or None
        The cable's length [m] when its winch encoder reads zero, as ``taut calibrate``
        estimates it: an encoder reading is the length minus this.

    Examples
    --------
    >>> cable = Cable(exit=(0.0, 2.0), tension=(1.0, 50.0))
    >>> cable.tension, cable.anchor
    ((1.0, 50.0), None)
    """

    name: str | None = None
    exit: tuple[Coordinate, ...]
    anchor: tuple[Coordinate, ...] | None = None
    body: str | None = None
    tension: tuple[Number, Number] = (0.0, math.inf)
    length: tuple[Number, Number] | None = None
    stiffness: Finite | None = Field(default=None, gt=0, description="axial stiffness EA [N]")
    weight: Finite | None = Field(
        default=None,
        ge=0,
        le=MAX_MAGNITUDE,
        description="weight per unit length of the unstrained cable [N/m]: a positive weight makes the cable "
        "sag along the robot's gravity (Irvine's elastic catenary, with `stiffness` its EA; inextensible "
        "without one); none or 0: a straight cable",
    )
    radius: Finite = Field(default=0.0, ge=0, description="cable radius for interference checks [m]")
    pulley: Pulley | None = None
    swivel: SwivelPulley | None = Field(
        default=None,
        description="swivelling exit pulley: the cable runs onto it at `exit` and leaves "
        "it tangentially towards the anchor (not to be confused with `pulley`, the exit pulley of a planar "
        "winch that collidable cables wrap around)",
    )
    via: tuple[ViaPoint, ...] = Field(
        default=(),
        description="points the cable runs through from its exit point to its anchor, in order: a routed "
        "cable, a chain of straight segments whose length is their sum (CASPR's cables of more than two "
        "attachments)",
    )
    length_offset: Finite | None = Field(
        default=None,
        description="the cable's length [m] when its winch encoder reads zero (estimated by `taut calibrate`): "
        "an encoder reading is the length minus this",
    )

    @field_validator("tension")
    @classmethod
    def _tension(cls, v: tuple[float, float]) -> tuple[float, float]:
        return _check_bounds(v, "tension")

    @field_validator("length")
    @classmethod
    def _length(cls, v: tuple[float, float] | None) -> tuple[float, float] | None:
        return None if v is None else _check_bounds(v, "length")


class JointActuator(_Strict):
    """A motor acting along a joint: the force (prismatic joint) or torque (revolute joint) it
    exerts on the child body along or about ``+axis``, within ``force``.

    The dynamics gives its force to the tension distribution as one more column of the jointed
    structure matrix, a unit column on the joint's row (Lau, Oetomo & Halgamuge 2013: a
    multilink cable robot's joint actuators beside its cables); a joint without one is
    passive, moved only by the cables across it.

    Attributes
    ----------
    force : (float, float)
        Lower and upper bounds [N or N m]; either may be infinite (the default: unbounded).

    References
    ----------
    .. [1] D. Lau, D. Oetomo, S. K. Halgamuge, "Generalized modeling of multilink cable-driven
       manipulators with arbitrary routing using the cable-routing matrix", IEEE Transactions
       on Robotics 29(5), 2013 (joint actuators beside the cables in the equations of motion).
       (docs/references.bib: lau2013)

    Examples
    --------
    >>> JointActuator(force=(-20.0, 20.0)).force
    (-20.0, 20.0)
    """

    force: tuple[Number, Number] = (-math.inf, math.inf)

    @field_validator("force")
    @classmethod
    def _force(cls, v: tuple[float, float]) -> tuple[float, float]:
        lo, hi = v
        if math.isnan(lo) or math.isnan(hi):
            raise RobotFileError(f"joint actuator force bounds must be numbers, got {list(v)}")
        if lo > hi or lo == math.inf or hi == -math.inf:
            raise RobotFileError(f"joint actuator force bounds must satisfy lower <= upper, got {list(v)}")
        if any(math.isfinite(x) and abs(x) > MAX_MAGNITUDE for x in v):
            raise RobotFileError(f"joint actuator force bounds beyond {MAX_MAGNITUDE:g}, got {list(v)}")
        return (float(lo), float(hi))


class Joint(_Strict):
    """A one-degree-of-freedom joint between a body and its parent.

    ``prismatic``: the child frame is the parent frame translated by ``origin + q·axis``.
    ``revolute``: the child frame is the parent frame translated by ``origin`` and rotated
    by ``q`` about ``axis``.  ``limits`` bound the joint coordinate ``q``.

    Attributes
    ----------
    kind : {"prismatic", "revolute"}
    axis : tuple of float
        Direction of the joint axis in the parent frame (non-zero; one number, ``z``, for a
        planar revolute joint).
    origin : tuple of float or None
        The child frame's origin in the parent frame [m] (zero when not given).
    limits : (float, float)
        Bounds of ``q`` [m or rad].
    name : str or None
        The coordinate's name in poses (the body's name when not given).
    actuator : JointActuator or None
        The joint's motor; None: a passive joint.

    Examples
    --------
    >>> Joint(kind="prismatic", axis=(0, 1), limits=(0.0, 0.5)).limits
    (0.0, 0.5)
    """

    kind: Literal["prismatic", "revolute"]
    axis: tuple[Finite, ...]
    origin: tuple[Coordinate, ...] | None = None
    limits: tuple[Finite, Finite]
    name: str | None = None
    actuator: JointActuator | None = Field(
        default=None, description="the joint's motor with its force or torque bounds; none: a passive joint"
    )

    @field_validator("axis")
    @classmethod
    def _axis(cls, v: tuple[float, ...]) -> tuple[float, ...]:
        if not any(abs(x) > 0 for x in v):
            raise RobotFileError("joint axis must be a non-zero vector")
        return v

    @field_validator("limits")
    @classmethod
    def _limits(cls, v: tuple[float, float]) -> tuple[float, float]:
        if v[0] > v[1]:
            raise RobotFileError(f"joint limits are inverted: lower {v[0]} > upper {v[1]}")
        return v


class Capsule(_Strict):
    """A segment swept by a sphere: the collision model of Lieskovský 2020, §2.3.2.

    Attributes
    ----------
    a, b : tuple of float
        End points of the segment in the body frame [m].
    radius : float
        Radius of the sphere [m], ≥ 0.
    name : str or None

    References
    ----------
    .. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, §2.3.2.
       (docs/references.bib: lieskovsky2020)

    Examples
    --------
    >>> Capsule(a=(0, 0, 0), b=(0, 0, 0.3), radius=0.02).radius
    0.02
    """

    a: tuple[Coordinate, ...]
    b: tuple[Coordinate, ...]
    radius: Finite = Field(ge=0)
    name: str | None = None


class Body(_Strict):
    """An extra platform body attached to ``parent`` (``platform`` or another body) by a joint.

    With a ``mass``, its weight ``mass·g`` (``g`` the robot's gravity, see
    :attr:`Robot.gravity`) acts at ``com``: the statics count it in the platform's external
    wrench and in the joint forces.

    Attributes
    ----------
    name : str
        Unique among the bodies (``platform`` is the platform's).
    parent : str
        ``platform`` or an earlier body.
    joint : Joint
        The joint to its parent.
    capsules : tuple of Capsule
        Collision shape in the body frame.
    mass : float or None
        Mass [kg].
    com : tuple of float or None
        Centre of mass in the body frame [m] (the origin when not given).
    inertia : tuple of float or None
        Rotational inertia about the centre of mass in the body frame [kg m²]: ``Izz``
        (planar), or ``Ixx, Iyy, Izz, Ixy, Ixz, Iyz`` (spatial).

    Examples
    --------
    >>> slider = Body(name="slider", joint=Joint(kind="prismatic", axis=(1, 0), limits=(0, 1)), mass=0.5)
    >>> slider.parent, slider.mass
    ('platform', 0.5)
    """

    name: str
    parent: str = "platform"
    joint: Joint
    capsules: tuple[Capsule, ...] = ()
    mass: Finite | None = Field(default=None, gt=0, description="mass of the body [kg]")
    com: tuple[Coordinate, ...] | None = Field(
        default=None, description="centre of mass in the body frame [m] (the origin when not given)"
    )
    inertia: tuple[Finite, ...] | None = Field(
        default=None,
        description="rotational inertia about the centre of mass in the body frame [kg m²]: "
        "Izz (planar), or Ixx, Iyy, Izz, Ixy, Ixz, Iyz (spatial)",
    )


class Shape(_Strict):
    """Platform outline in its body frame: a polygon (planar) and/or capsules (collision).

    Attributes
    ----------
    polygon : tuple of tuple of float or None
        Vertices of a planar platform's outline [m], in order.
    capsules : tuple of Capsule
        Collision shape.

    Examples
    --------
    >>> len(Shape(polygon=((-0.1, -0.05), (0.1, -0.05), (0.1, 0.05), (-0.1, 0.05))).polygon)
    4
    """

    polygon: tuple[tuple[Coordinate, ...], ...] | None = None
    capsules: tuple[Capsule, ...] = ()


class Platform(_Strict):
    """The moving platform.  The external wrench is ``wrench`` (constant, fixed frame) plus
    the weight ``mass·gravity``; both act at ``wrench_point`` (body frame), which is also
    the centre of mass that ``inertia`` is taken about.

    Attributes
    ----------
    kind : {"rigid", "point-mass"}
    wrench : tuple of float or None
        Constant external wrench in the fixed frame [N, N m] (``wrench_dim`` numbers).
    mass : float or None
        Mass [kg].
    inertia : tuple of float or None
        Rotational inertia about the centre of mass in the body frame [kg m²]: ``Izz``
        (planar), or ``Ixx, Iyy, Izz, Ixy, Ixz, Iyz`` (spatial).
    gravity : tuple of float or None
        Gravitational acceleration [m/s²] (default 9.81 m/s² down the last axis).
    wrench_point : tuple of float or None
        Where ``wrench`` and the weight act, in the body frame [m] (the origin when not given).
    shape : Shape or None
        Outline and collision shape.
    bodies : tuple of Body
        Extra bodies carried by joints.

    Examples
    --------
    >>> Platform(kind="point-mass", mass=2.0).kind
    'point-mass'
    """

    kind: Literal["rigid", "point-mass"] = "rigid"
    wrench: tuple[Finite, ...] | None = None
    mass: Finite | None = Field(default=None, gt=0)
    inertia: tuple[Finite, ...] | None = Field(
        default=None,
        description="rotational inertia about the centre of mass in the body frame [kg m²]: "
        "Izz (planar), or Ixx, Iyy, Izz, Ixy, Ixz, Iyz (spatial)",
    )
    gravity: tuple[Finite, ...] | None = None
    wrench_point: tuple[Coordinate, ...] | None = None
    shape: Shape | None = None
    bodies: tuple[Body, ...] = ()


class Circle(_Strict):
    """A circular obstacle of a planar robot, collidable: cables wrap around it.

    Attributes
    ----------
    kind : {"circle"}
    center : tuple of float
        Its centre [m].
    radius : float
        Its radius [m], ≥ 0 (0: a point cables wrap around).
    name : str or None

    Examples
    --------
    >>> Circle(kind="circle", center=(0.6, -0.4), radius=0.03).radius
    0.03
    """

    kind: Literal["circle"]
    center: tuple[Coordinate, ...]
    radius: Finite = Field(ge=0)
    name: str | None = None


class Polygon(_Strict):
    """A polygonal obstacle of a planar robot, collidable: cables wrap around its corners.

    Attributes
    ----------
    kind : {"polygon"}
    vertices : tuple of tuple of float
        At least 3 vertices [m], in order.
    name : str or None

    Examples
    --------
    >>> len(Polygon(kind="polygon", vertices=((0, 0), (1, 0), (0, 1))).vertices)
    3
    """

    kind: Literal["polygon"]
    vertices: tuple[tuple[Coordinate, ...], ...]
    name: str | None = None

    @field_validator("vertices")
    @classmethod
    def _vertices(cls, v: tuple[tuple[float, ...], ...]) -> tuple[tuple[float, ...], ...]:
        if len(v) < 3:
            raise RobotFileError(f"a polygon needs at least 3 vertices, got {len(v)}")
        return v


Obstacle = Annotated[Circle | Polygon, Field(discriminator="kind")]


class Reference(_Strict):
    """Reference data quoted from a source document (cable lengths of a DGP table, ...).

    Attributes
    ----------
    source : str or None
        Where the data come from, short form (``Berti 2015, Table 4.3``).
    lengths : tuple of float or None
        Cable lengths [m], one per cable (the default of ``taut fk``).
    poses : dict of str to tuple of float
        Named poses.
    notes : str or None

    Examples
    --------
    >>> from taut.model import example
    >>> example("planar-4cable").reference.poses
    {'home': (0.0, 0.0, 0.0)}
    """

    source: str | None = None
    lengths: tuple[Finite, ...] | None = None
    poses: dict[str, tuple[Finite, ...]] = {}
    notes: str | None = None


class Trajectory(_Strict):
    """A named trajectory: waypoints (positions or full poses) joined by straight moves.

    ``steps`` gives the number of samples of each move (pose sequences, Lieskovský 2020, §4.2);
    ``speed`` [m/s] and ``dwell`` [s] time a waypoint sequence (Rushton 2022, §6.2).

    Attributes
    ----------
    description : str or None
    waypoints : tuple of tuple of float
        Positions (``dimension`` numbers) or poses (``pose_size``).
    steps : tuple of int or None
        Samples of each move, one per move.
    speed : float or None
        Speed of the position [m/s], > 0.
    dwell : float
        Time held at every waypoint [s], ≥ 0.

    References
    ----------
    .. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, §4.2.
       (docs/references.bib: lieskovsky2020)
    .. [2] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §6.2. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> Trajectory(waypoints=((0, 0), (0.5, 0)), speed=0.1).dwell
    0.0
    """

    description: str | None = None
    waypoints: tuple[tuple[Finite, ...], ...]
    steps: tuple[int, ...] | None = None
    speed: Finite | None = Field(default=None, gt=0)
    dwell: Finite = Field(default=0.0, ge=0)


class Robot(_Strict):
    """A cable-driven parallel robot (see ``docs/architecture.md`` §2–3 for conventions).

    Attributes
    ----------
    format : {"taut/1"}
    name : str
    description : str or None
        One line shown by ``taut examples``.
    source : str or None
        Where the data come from, short form.
    dimension : {2, 3}
        Planar or spatial.
    orientation : str
        The platform's angle convention, one of :data:`taut.geometry.CONVENTIONS`.
    platform : Platform
    cables : tuple of Cable
        At least one.
    obstacles : tuple of Circle or Polygon
        Collidable obstacles of a planar robot.
    installation_space : tuple of tuple of float or None
        Polygon the cables must stay in.
    disallowed : tuple of polygons
        Regions inside the installation space the cables must avoid.
    reference : Reference or None
        Published data the tests reproduce.
    trajectories : dict of str to Trajectory

    Notes
    -----
    Immutable: the arrays derived from its fields (:attr:`exits`, :attr:`tension_bounds`, ...)
    are computed once and read-only.  Read one with :func:`~taut.model.load_robot` or build
    it from fields; bad fields raise :class:`~taut.errors.RobotFileError`, whether the class
    is called or :func:`~taut.model.robot_from_dict` reads them.

    Examples
    --------
    >>> robot = Robot(
    ...     name="two cables",
    ...     dimension=2,
    ...     platform=Platform(kind="point-mass", mass=1.0),
    ...     cables=(Cable(exit=(0.0, 1.0)), Cable(exit=(1.0, 1.0))),
    ... )
    >>> robot.pose_names, robot.wrench_dim
    (['x', 'y'], 2)
    >>> robot.exits
    array([[0., 1.],
           [1., 1.]])
    """

    format: Literal["taut/1"] = FORMAT
    name: str
    description: str | None = None
    source: str | None = None
    dimension: Literal[2, 3]
    orientation: str = "xyz-fixed"
    platform: Platform = Platform()
    cables: tuple[Cable, ...] = Field(min_length=1)
    obstacles: tuple[Obstacle, ...] = ()
    installation_space: tuple[tuple[Coordinate, ...], ...] | None = None
    disallowed: tuple[tuple[tuple[Coordinate, ...], ...], ...] = ()
    reference: Reference | None = None
    trajectories: dict[str, Trajectory] = {}

    _arrays: _DerivedArrays = PrivateAttr(default_factory=_DerivedArrays)

    @field_validator("orientation")
    @classmethod
    def _orientation(cls, v: str) -> str:
        if v not in CONVENTIONS:
            raise RobotFileError(f"unknown orientation convention {v!r}; expected one of {', '.join(CONVENTIONS)}")
        return v

    @model_validator(mode="after")
    def _consistent(self) -> Self:
        d = self.dimension
        pm = self.platform.kind == "point-mass"
        bodies = {"platform"} | {b.name for b in self.platform.bodies}

        def need(vec: tuple[float, ...] | None, n: int, where: str) -> None:
            if vec is not None and len(vec) != n:
                raise RobotFileError(f"{where}: expected {n} numbers, got {len(vec)}")

        for i, c in enumerate(self.cables, 1):
            need(c.exit, d, f"cables[{i}].exit")
            need(c.anchor, d, f"cables[{i}].anchor")
            if pm and c.anchor is not None and any(x != 0 for x in c.anchor):
                raise RobotFileError(
                    f"cables[{i}].anchor: a point-mass platform has all anchors at its origin, got {c.anchor}"
                )
            if c.swivel is not None and len(c.swivel.axis) != d:
                axis = list(c.swivel.axis)
                if d == 3:
                    raise RobotFileError(f"cables[{i}].swivel.axis: expected 3 numbers, got {axis}")
                out = " points out of the robot's plane" if axis[2] != 0 else " gives a third (z) number"
                raise RobotFileError(
                    f"cables[{i}].swivel.axis {axis}{out}: a planar robot's swivelling pulley turns about an "
                    "axis in its plane (give x, y), so that the pulley and the cable stay in the plane"
                )
            if c.swivel is not None and c.pulley is not None:
                raise RobotFileError(
                    f"cables[{i}]: give either swivel (swivelling pulley) or pulley (planar winch), not both"
                )
            if c.body is not None and c.body not in bodies:
                raise RobotFileError(f"cables[{i}].body: unknown body {c.body!r}; expected one of {sorted(bodies)}")
            for k, v in enumerate(c.via, 1):
                need(v.point, d, f"cables[{i}].via[{k}].point")
                if v.body != "fixed" and v.body not in bodies:
                    raise RobotFileError(
                        f"cables[{i}].via[{k}].body: unknown body {v.body!r}; expected 'fixed' or one of {sorted(bodies)}"
                    )
                if pm and v.body == "platform":
                    raise RobotFileError(
                        f"cables[{i}].via[{k}]: a point-mass platform has no extent for a cable to run through"
                    )
            if c.via and (c.swivel is not None or c.pulley is not None or c.weight):
                raise RobotFileError(
                    f"cables[{i}].via: a routed cable runs straight between its points (no swivel, pulley or weight)"
                )
            if c.weight and (c.swivel is not None or c.pulley is not None):
                raise RobotFileError(
                    f"cables[{i}].weight: a sagging cable runs from a fixed exit point (no swivel or pulley)"
                )
        keys: dict[tuple[tuple[float, ...], tuple[float, ...], str, tuple[ViaPoint, ...]], int] = {}
        for i, c in enumerate(self.cables, 1):
            key = (tuple(c.exit), tuple(c.anchor or [0.0] * d), c.body or "platform", c.via)
            if key in keys:
                raise RobotFileError(
                    f"cables[{i}]: same exit point and anchor as cables[{keys[key]}] (a duplicated cable)"
                )
            keys[key] = i
        p = self.platform
        need(p.wrench, self.wrench_dim, "platform.wrench")
        need(p.gravity, d, "platform.gravity")
        need(p.wrench_point, d, "platform.wrench_point")
        if p.inertia is not None:
            if pm:
                raise RobotFileError("platform.inertia: a point-mass platform has no rotational inertia")
            if p.mass is None:
                raise RobotFileError("platform.inertia is given without platform.mass")
            _check_inertia(p.inertia, d, "platform")
        if p.gravity is not None and p.mass is None and not any(b.mass is not None for b in p.bodies):
            raise RobotFileError("platform.gravity is given without platform.mass (or a mass of platform.bodies)")
        if any(c.weight for c in self.cables) and not np.any(self.gravity):
            raise RobotFileError("cables[].weight: sagging cables need a gravity (platform.gravity is zero)")
        if pm and p.bodies:
            raise RobotFileError("platform.bodies: a point-mass platform cannot carry jointed bodies")
        seen = {"platform"}
        for j, b in enumerate(p.bodies, 1):
            if b.name in seen:
                raise RobotFileError(f"platform.bodies[{j}].name: duplicate body name {b.name!r}")
            if b.name == "fixed":
                raise RobotFileError(f"platform.bodies[{j}].name: 'fixed' names the fixed frame (cables[].via)")
            if b.parent not in seen:
                raise RobotFileError(f"platform.bodies[{j}].parent: unknown or later body {b.parent!r}")
            seen.add(b.name)
            need(b.joint.axis, d if d == 3 or b.joint.kind == "prismatic" else 1, f"platform.bodies[{j}].joint.axis")
            need(b.joint.origin, d, f"platform.bodies[{j}].joint.origin")
            need(b.com, d, f"platform.bodies[{j}].com")
            if b.mass is None and (b.com is not None or b.inertia is not None):
                raise RobotFileError(f"platform.bodies[{j}]: com or inertia is given without mass")
            if b.inertia is not None:
                _check_inertia(b.inertia, d, f"platform.bodies[{j}]")
        for k, o in enumerate(self.obstacles, 1):
            pts = [o.center] if isinstance(o, Circle) else o.vertices
            for pt in pts:
                need(pt, d, f"obstacles[{k}]")
        for name, t in self.trajectories.items():
            width = len(t.waypoints[0]) if t.waypoints else 0
            if width not in (d, self.pose_size):
                raise RobotFileError(
                    f"trajectories.{name}.waypoints: expected {d} (position) or {self.pose_size} (pose) coordinates, got {width}"
                )
            for w in t.waypoints:
                need(w, width, f"trajectories.{name}.waypoints")
            if t.steps is not None and len(t.steps) != len(t.waypoints) - 1:
                raise RobotFileError(
                    f"trajectories.{name}.steps: expected one count per move ({len(t.waypoints) - 1}), got {len(t.steps)}"
                )
        if self.reference is not None and self.reference.lengths is not None:
            need(self.reference.lengths, self.n_cables, "reference.lengths")
            if any(x <= 0 for x in self.reference.lengths):
                raise RobotFileError("reference.lengths: cable lengths must be positive")
        for name, pose in self.reference.poses.items() if self.reference else []:
            need(pose, self.pose_size, f"reference.poses.{name}")
        return self

    # ---- derived sizes -------------------------------------------------------------
    @property
    def n_cables(self) -> int:
        """Number of cables."""
        return len(self.cables)

    @property
    def swivel_cables(self) -> tuple[int, ...]:
        """0-based indices of the cables that leave the frame through a swivelling pulley."""
        return tuple(i for i, c in enumerate(self.cables) if c.swivel is not None)

    @property
    def sagging_cables(self) -> tuple[int, ...]:
        """0-based indices of the cables with a positive ``weight``: they sag (elastic catenaries)."""
        return tuple(i for i, c in enumerate(self.cables) if c.weight)

    @property
    def routed_cables(self) -> tuple[int, ...]:
        """The 0-based indices of the cables routed through via points (``cables[].via``)."""
        return tuple(i for i, c in enumerate(self.cables) if c.via)

    @property
    def encoder_cables(self) -> tuple[int, ...]:
        """The 0-based indices of the cables with a ``length_offset`` (an encoder zero)."""
        return tuple(i for i, c in enumerate(self.cables) if c.length_offset is not None)

    @property
    def is_point_mass(self) -> bool:
        """Whether the platform is a point mass (no orientation)."""
        return self.platform.kind == "point-mass"

    @property
    def n_joints(self) -> int:
        """Number of joint coordinates (one per body of ``platform.bodies``)."""
        return len(self.platform.bodies)

    @property
    def wrench_dim(self) -> int:
        """Size of a platform wrench: 2 / 3 (planar point / rigid), 3 / 6 (spatial)."""
        if self.dimension == 2:
            return 2 if self.is_point_mass else 3
        return 3 if self.is_point_mass else 6

    @property
    def pose_size(self) -> int:
        """Platform pose coordinates (position, orientation) followed by joint coordinates."""
        return self.wrench_dim + self.n_joints

    @property
    def pose_names(self) -> list[str]:
        """Names of the pose coordinates: position (``x, y[, z]``), orientation (``theta``;
        ``a, b, c``; ``phi, theta, sigma`` for ``tilt-torsion``), then the joints.
        """
        pos = ["x", "y", "z"][: self.dimension]
        if self.is_point_mass:
            ang: list[str] = []
        elif self.dimension == 2:
            ang = ["theta"]
        elif self.orientation == "tilt-torsion":
            ang = ["phi", "theta", "sigma"]
        else:
            ang = ["a", "b", "c"]
        return pos + ang + [b.joint.name or b.name for b in self.platform.bodies]

    # ---- arrays (computed from the fields once per robot, read-only) -----------------
    def _derived(self, name: str, build: Callable[[], Derived]) -> Derived:
        value: Derived | None = self._arrays.get(name)
        if value is None:
            value = build()
            self._arrays[name] = value
        # Again on every use: a deep copy or an unpickled robot holds writeable copies.
        for array in value if isinstance(value, tuple) else (value,):
            array.setflags(write=False)
        return value

    @property
    def exits(self) -> np.ndarray:
        """Exit points ``a_i``, shape ``(n, d)``."""
        return self._derived("exits", lambda: np.array([c.exit for c in self.cables], dtype=float))

    @property
    def anchors(self) -> np.ndarray:
        """Anchors ``r_i`` in the frame of their body, shape ``(n, d)``."""
        zero = (0.0,) * self.dimension
        return self._derived("anchors", lambda: np.array([c.anchor or zero for c in self.cables], dtype=float))

    @property
    def cable_bodies(self) -> np.ndarray:
        """Index of each cable's body: 0 for the platform, ``k`` for ``platform.bodies[k-1]``."""
        index = {"platform": 0} | {b.name: k for k, b in enumerate(self.platform.bodies, 1)}
        return self._derived("cable_bodies", lambda: np.array([index[c.body or "platform"] for c in self.cables]))

    @property
    def via_points(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The via points of the routed cables (``cables[].via``), in cable order then in the
        order each cable runs through them: the cable of each ``(V,)``, its body ``(V,)`` (0
        the platform, ``k`` ``platform.bodies[k-1]``, −1 the fixed frame) and the point in that
        body's frame ``(V, d)``."""

        def build() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
            index = {"platform": 0, "fixed": -1} | {b.name: k for k, b in enumerate(self.platform.bodies, 1)}
            rows = [(i, index[v.body], v.point) for i, c in enumerate(self.cables) for v in c.via]
            return (
                np.array([r[0] for r in rows], dtype=int),
                np.array([r[1] for r in rows], dtype=int),
                np.array([r[2] for r in rows], dtype=float).reshape(len(rows), self.dimension),
            )

        return self._derived("via_points", build)

    @property
    def length_offsets(self) -> np.ndarray:
        """Each cable's length at its encoder's zero [m] (``cables[].length_offset``; 0 for a
        cable without one, whose reading is its length), shape ``(n,)``."""
        return self._derived(
            "length_offsets", lambda: np.array([c.length_offset or 0.0 for c in self.cables], dtype=float)
        )

    @property
    def tension_bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """Lower and upper tension bounds [N], each of shape ``(n,)``."""

        def build() -> tuple[np.ndarray, np.ndarray]:
            t = np.array([c.tension for c in self.cables], dtype=float)
            return t[:, 0], t[:, 1]

        return self._derived("tension_bounds", build)

    @property
    def cable_weights(self) -> np.ndarray:
        """Weight per unit length of each cable [N/m], shape ``(n,)``: 0 for a straight cable."""
        return self._derived("cable_weights", lambda: np.array([c.weight or 0.0 for c in self.cables], dtype=float))

    @property
    def axial_stiffness(self) -> np.ndarray:
        """Axial stiffness ``EA`` of each cable [N], shape ``(n,)``: ``inf`` for a cable without
        ``stiffness`` (inextensible)."""
        return self._derived(
            "axial_stiffness",
            lambda: np.array([math.inf if c.stiffness is None else c.stiffness for c in self.cables], dtype=float),
        )

    @property
    def length_bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """Lower and upper length bounds [m], each of shape ``(n,)`` (``0`` and ``inf`` when not given)."""

        def build() -> tuple[np.ndarray, np.ndarray]:
            t = np.array([c.length or (0.0, math.inf) for c in self.cables], dtype=float)
            return t[:, 0], t[:, 1]

        return self._derived("length_bounds", build)

    @property
    def actuated_joints(self) -> np.ndarray:
        """Indices (0-based, in ``platform.bodies``) of the joints with an actuator, ``(n_actuators,)``."""
        return self._derived(
            "actuated_joints",
            lambda: np.array(
                [k for k, b in enumerate(self.platform.bodies) if b.joint.actuator is not None], dtype=int
            ),
        )

    @property
    def actuator_bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """Lower and upper force bounds of the joint actuators [N or N m], each ``(n_actuators,)``
        in the order of :attr:`actuated_joints`."""

        def build() -> tuple[np.ndarray, np.ndarray]:
            t = [b.joint.actuator.force for b in self.platform.bodies if b.joint.actuator is not None]
            a = np.array(t, dtype=float).reshape(-1, 2)
            return a[:, 0], a[:, 1]

        return self._derived("actuator_bounds", build)

    @property
    def joint_limits(self) -> np.ndarray:
        """Limits of the joint coordinates, shape ``(n_joints, 2)``."""
        return self._derived(
            "joint_limits",
            lambda: np.array([b.joint.limits for b in self.platform.bodies], dtype=float).reshape(-1, 2),
        )

    @property
    def inertia(self) -> np.ndarray | None:
        """The platform's inertia tensor about its centre of mass in the body frame, ``(1, 1)``
        planar or ``(3, 3)`` spatial [kg m²]; None when the file gives none."""
        values = self.platform.inertia
        if values is None:
            return None
        return self._derived("inertia", lambda: _inertia_matrix(values))

    @property
    def weight(self) -> np.ndarray:
        """The platform's weight, the force ``mass·g`` [N] in the fixed frame, shape ``(d,)``:
        ``g`` is ``platform.gravity``, by default ``STANDARD_GRAVITY`` = 9.81 m/s² downwards
        along the last axis (``(0, −9.81)`` planar, ``(0, 0, −9.81)`` spatial); zero without a
        ``platform.mass``."""

        def build() -> np.ndarray:
            mass = self.platform.mass
            return np.zeros(self.dimension) if mass is None else mass * self.gravity

        return self._derived("weight", build)

    @property
    def gravity(self) -> np.ndarray:
        """The gravitational acceleration [m/s²] on the platform and its bodies, shape ``(d,)``:
        ``platform.gravity``, by default ``STANDARD_GRAVITY`` downwards along the last axis."""
        g = self.platform.gravity
        d = self.dimension
        return self._derived(
            "gravity", lambda: np.array(g, dtype=float) if g is not None else -STANDARD_GRAVITY * np.eye(d)[-1]
        )

    @property
    def body_weights(self) -> np.ndarray:
        """Weights ``mass·g`` [N] of ``platform.bodies`` (zero for a body without a mass),
        shape ``(n_joints, d)``; each acts at the body's ``com``."""
        masses = np.array([b.mass or 0.0 for b in self.platform.bodies], dtype=float)
        return self._derived("body_weights", lambda: masses[:, None] * self.gravity[None, :])

    @property
    def body_coms(self) -> np.ndarray:
        """Centres of mass of ``platform.bodies`` in their body frames, shape ``(n_joints, d)``."""
        zero = (0.0,) * self.dimension
        return self._derived(
            "body_coms",
            lambda: np.array([b.com or zero for b in self.platform.bodies], dtype=float).reshape(-1, self.dimension),
        )

    @property
    def body_capsules(self) -> list[tuple[int, Capsule]]:
        """``(body index, capsule)`` for the platform shape (body 0) and every extra body."""
        out = [(0, c) for c in self.platform.shape.capsules] if self.platform.shape is not None else []
        for k, body in enumerate(self.platform.bodies, 1):
            out += [(k, c) for c in body.capsules]
        return out
