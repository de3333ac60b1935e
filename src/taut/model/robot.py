"""The robot description: typed, validated data and nothing else (``docs/architecture.md`` §3).

A :class:`Robot` holds what every analysis of taut needs: the cables (exit point ``a_i``,
platform anchor ``r_i`` in the frame of the body it is attached to, tension and length
bounds, axial stiffness), the platform (point mass or rigid, extra bodies joined by
joints, the external wrench), collidable obstacles and the installation space of
variable-structure robots, reference data from the sources and named trajectories.
Validation errors are raised by pydantic and turned into :class:`taut.RobotFileError`
by :mod:`taut.model.io`.

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
from functools import cached_property
from typing import Annotated, Literal

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, field_validator, model_validator

from taut.geometry.rotation import CONVENTIONS

FORMAT = "taut/1"

Number = Annotated[float, Field(allow_inf_nan=True)]
Finite = Annotated[float, Field(allow_inf_nan=False)]
#: Coordinates [m]: beyond a million kilometres squares overflow, and no robot is that large.
Coordinate = Annotated[float, Field(allow_inf_nan=False, ge=-1e9, le=1e9)]


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=False, validate_assignment=False)


def _check_bounds(v: tuple[float, float], what: str) -> tuple[float, float]:
    lo, hi = v
    if math.isnan(lo) or math.isnan(hi):
        raise ValueError(f"{what} bounds must be numbers, got {list(v)}")
    if lo < 0:
        raise ValueError(f"{what} lower bound must be >= 0, got {lo}")
    if lo > hi:
        raise ValueError(f"{what} bounds are inverted: lower {lo} > upper {hi}")
    if math.isinf(lo):
        raise ValueError(f"{what} lower bound must be finite, got {lo}")
    return (float(lo), float(hi))


class Pulley(_Strict):
    """Exit pulley of a winch: the cable leaves it tangentially (Rushton 2022, §4.1)."""

    radius: Finite = Field(ge=0)
    direction: Literal["ccw", "cw"] = "ccw"


class Cable(_Strict):
    """Cable *i*: from the fixed exit point ``a_i`` to the anchor ``r_i`` on a platform body."""

    name: str | None = None
    exit: list[Coordinate]
    anchor: list[Coordinate] | None = None
    body: str | None = None
    tension: tuple[Number, Number] = (0.0, math.inf)
    length: tuple[Number, Number] | None = None
    stiffness: Finite | None = Field(default=None, gt=0, description="axial stiffness EA [N]")
    radius: Finite = Field(default=0.0, ge=0, description="cable radius for interference checks [m]")
    pulley: Pulley | None = None

    @field_validator("tension")
    @classmethod
    def _tension(cls, v):
        return _check_bounds(v, "tension")

    @field_validator("length")
    @classmethod
    def _length(cls, v):
        return None if v is None else _check_bounds(v, "length")


class Joint(_Strict):
    """A one-degree-of-freedom joint between a body and its parent.

    ``prismatic``: the child frame is the parent frame translated by ``origin + q·axis``.
    ``revolute``: the child frame is the parent frame translated by ``origin`` and rotated
    by ``q`` about ``axis``.  ``limits`` bound the joint coordinate ``q``.
    """

    kind: Literal["prismatic", "revolute"]
    axis: list[Finite]
    origin: list[Coordinate] | None = None
    limits: tuple[Finite, Finite]
    name: str | None = None

    @field_validator("axis")
    @classmethod
    def _axis(cls, v):
        if not any(abs(x) > 0 for x in v):
            raise ValueError("joint axis must be a non-zero vector")
        return v

    @field_validator("limits")
    @classmethod
    def _limits(cls, v):
        if v[0] > v[1]:
            raise ValueError(f"joint limits are inverted: lower {v[0]} > upper {v[1]}")
        return v


class Capsule(_Strict):
    """A segment swept by a sphere: the collision model of Lieskovský 2020, §2.3.2."""

    a: list[Coordinate]
    b: list[Coordinate]
    radius: Finite = Field(ge=0)
    name: str | None = None


class Body(_Strict):
    """An extra platform body attached to ``parent`` (``platform`` or another body) by a joint."""

    name: str
    parent: str = "platform"
    joint: Joint
    capsules: list[Capsule] = []


class Shape(_Strict):
    """Platform outline in its body frame: a polygon (planar) and/or capsules (collision)."""

    polygon: list[list[Coordinate]] | None = None
    capsules: list[Capsule] = []


class Platform(_Strict):
    """The moving platform.  The external wrench is ``wrench`` (constant, fixed frame) plus
    the weight ``mass·gravity``; both act at ``wrench_point`` (body frame)."""

    kind: Literal["rigid", "point-mass"] = "rigid"
    wrench: list[Finite] | None = None
    mass: Finite | None = Field(default=None, gt=0)
    gravity: list[Finite] | None = None
    wrench_point: list[Coordinate] | None = None
    shape: Shape | None = None
    bodies: list[Body] = []


class Circle(_Strict):
    kind: Literal["circle"]
    center: list[Coordinate]
    radius: Finite = Field(ge=0)
    name: str | None = None


class Polygon(_Strict):
    kind: Literal["polygon"]
    vertices: list[list[Coordinate]]
    name: str | None = None

    @field_validator("vertices")
    @classmethod
    def _vertices(cls, v):
        if len(v) < 3:
            raise ValueError(f"a polygon needs at least 3 vertices, got {len(v)}")
        return v


Obstacle = Annotated[Circle | Polygon, Field(discriminator="kind")]


class Reference(_Strict):
    """Reference data quoted from a source document (cable lengths of a DGP table, ...)."""

    source: str | None = None
    lengths: list[Finite] | None = None
    poses: dict[str, list[Finite]] = {}
    notes: str | None = None


class Trajectory(_Strict):
    """A named trajectory: waypoints (positions or full poses) joined by straight moves.

    ``steps`` gives the number of samples of each move (pose sequences, Lieskovský 2020, §4.2);
    ``speed`` [m/s] and ``dwell`` [s] time a waypoint sequence (Rushton 2022, §6.2).
    """

    description: str | None = None
    waypoints: list[list[Finite]]
    steps: list[int] | None = None
    speed: Finite | None = Field(default=None, gt=0)
    dwell: Finite = Field(default=0.0, ge=0)


class Robot(_Strict):
    """A cable-driven parallel robot (see ``docs/architecture.md`` §2–3 for conventions)."""

    format: Literal["taut/1"] = FORMAT
    name: str
    description: str | None = None
    source: str | None = None
    dimension: Literal[2, 3]
    orientation: str = "xyz-fixed"
    platform: Platform = Platform()
    cables: list[Cable] = Field(min_length=1)
    obstacles: list[Obstacle] = []
    installation_space: list[list[Coordinate]] | None = None
    disallowed: list[list[list[Coordinate]]] = []
    reference: Reference | None = None
    trajectories: dict[str, Trajectory] = {}

    @field_validator("orientation")
    @classmethod
    def _orientation(cls, v):
        if v not in CONVENTIONS:
            raise ValueError(f"unknown orientation convention {v!r}; expected one of {', '.join(CONVENTIONS)}")
        return v

    @model_validator(mode="after")
    def _consistent(self):
        d = self.dimension
        pm = self.platform.kind == "point-mass"
        bodies = {"platform"} | {b.name for b in self.platform.bodies}

        def need(vec, n, where):
            if vec is not None and len(vec) != n:
                raise ValueError(f"{where}: expected {n} numbers, got {len(vec)}")

        for i, c in enumerate(self.cables, 1):
            need(c.exit, d, f"cables[{i}].exit")
            need(c.anchor, d, f"cables[{i}].anchor")
            if pm and c.anchor is not None and any(x != 0 for x in c.anchor):
                raise ValueError(
                    f"cables[{i}].anchor: a point-mass platform has all anchors at its origin, got {c.anchor}"
                )
            if c.body is not None and c.body not in bodies:
                raise ValueError(f"cables[{i}].body: unknown body {c.body!r}; expected one of {sorted(bodies)}")
        keys = {}
        for i, c in enumerate(self.cables, 1):
            key = (tuple(c.exit), tuple(c.anchor or [0.0] * d), c.body or "platform")
            if key in keys:
                raise ValueError(f"cables[{i}]: same exit point and anchor as cables[{keys[key]}] (a duplicated cable)")
            keys[key] = i
        p = self.platform
        need(p.wrench, self.wrench_dim, "platform.wrench")
        need(p.gravity, d, "platform.gravity")
        need(p.wrench_point, d, "platform.wrench_point")
        if p.gravity is not None and p.mass is None:
            raise ValueError("platform.gravity is given without platform.mass")
        if pm and p.bodies:
            raise ValueError("platform.bodies: a point-mass platform cannot carry jointed bodies")
        seen = {"platform"}
        for j, b in enumerate(p.bodies, 1):
            if b.name in seen:
                raise ValueError(f"platform.bodies[{j}].name: duplicate body name {b.name!r}")
            if b.parent not in seen:
                raise ValueError(f"platform.bodies[{j}].parent: unknown or later body {b.parent!r}")
            seen.add(b.name)
            need(b.joint.axis, d if d == 3 or b.joint.kind == "prismatic" else 1, f"platform.bodies[{j}].joint.axis")
            need(b.joint.origin, d, f"platform.bodies[{j}].joint.origin")
        for k, o in enumerate(self.obstacles, 1):
            pts = [o.center] if isinstance(o, Circle) else o.vertices
            for pt in pts:
                need(pt, d, f"obstacles[{k}]")
        for name, t in self.trajectories.items():
            width = len(t.waypoints[0]) if t.waypoints else 0
            if width not in (d, self.pose_size):
                raise ValueError(
                    f"trajectories.{name}.waypoints: expected {d} (position) or {self.pose_size} (pose) coordinates, got {width}"
                )
            for w in t.waypoints:
                need(w, width, f"trajectories.{name}.waypoints")
            if t.steps is not None and len(t.steps) != len(t.waypoints) - 1:
                raise ValueError(
                    f"trajectories.{name}.steps: expected one count per move ({len(t.waypoints) - 1}), got {len(t.steps)}"
                )
        if self.reference is not None and self.reference.lengths is not None:
            need(self.reference.lengths, self.n_cables, "reference.lengths")
            if any(x <= 0 for x in self.reference.lengths):
                raise ValueError("reference.lengths: cable lengths must be positive")
        for name, pose in self.reference.poses.items() if self.reference else []:
            need(pose, self.pose_size, f"reference.poses.{name}")
        return self

    # ---- derived sizes -------------------------------------------------------------
    @property
    def n_cables(self) -> int:
        return len(self.cables)

    @property
    def is_point_mass(self) -> bool:
        return self.platform.kind == "point-mass"

    @property
    def n_joints(self) -> int:
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
        pos = ["x", "y", "z"][: self.dimension]
        if self.is_point_mass:
            ang = []
        elif self.dimension == 2:
            ang = ["theta"]
        elif self.orientation == "tilt-torsion":
            ang = ["phi", "theta", "sigma"]
        else:
            ang = ["a", "b", "c"]
        return pos + ang + [b.joint.name or b.name for b in self.platform.bodies]

    # ---- arrays (computed once per robot) -------------------------------------------
    @cached_property
    def exits(self) -> np.ndarray:
        """Exit points ``a_i``, shape ``(n, d)``."""
        return np.array([c.exit for c in self.cables], dtype=float)

    @cached_property
    def anchors(self) -> np.ndarray:
        """Anchors ``r_i`` in the frame of their body, shape ``(n, d)``."""
        d = self.dimension
        return np.array([c.anchor if c.anchor is not None else [0.0] * d for c in self.cables], dtype=float)

    @cached_property
    def cable_bodies(self) -> np.ndarray:
        """Index of each cable's body: 0 for the platform, ``k`` for ``platform.bodies[k-1]``."""
        index = {"platform": 0} | {b.name: k for k, b in enumerate(self.platform.bodies, 1)}
        return np.array([index[c.body or "platform"] for c in self.cables], dtype=int)

    @cached_property
    def tension_bounds(self) -> tuple[np.ndarray, np.ndarray]:
        t = np.array([c.tension for c in self.cables], dtype=float)
        return t[:, 0], t[:, 1]

    @cached_property
    def length_bounds(self) -> tuple[np.ndarray, np.ndarray]:
        t = np.array([c.length if c.length is not None else (0.0, math.inf) for c in self.cables], dtype=float)
        return t[:, 0], t[:, 1]

    @property
    def body_capsules(self) -> list[tuple[int, Capsule]]:
        """``(body index, capsule)`` for the platform shape (body 0) and every extra body."""
        out = [(0, c) for c in self.platform.shape.capsules] if self.platform.shape is not None else []
        for k, body in enumerate(self.platform.bodies, 1):
            out += [(k, c) for c in body.capsules]
        return out

    @cached_property
    def joint_limits(self) -> np.ndarray:
        return np.array([b.joint.limits for b in self.platform.bodies], dtype=float).reshape(-1, 2)
