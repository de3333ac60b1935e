"""Workspace conditions (Rushton 2022, §2.1.4): one base interface and a
registry, so that adding a condition is adding one class and one entry of
:data:`CONDITIONS`.

* ``wrench-closure`` — the cables can balance any wrench with positive tensions (WCW);
* ``wrench-feasible`` — the cables balance every wrench of a set, within their tension
  bounds (WFW); by default the set is a box around the robot's own external wrench
  (:func:`default_wrench_set`);
* ``static`` — the cables balance the robot's external wrench (weight included) within
  their bounds: the WFW of a single wrench.  It also serves under-constrained robots
  (fewer cables than degrees of freedom), through the exact LP of
  :mod:`taut.statics._feasibility`;
* ``interference-free`` — no two capsules of the collision model interfere (cable–cable,
  cable–platform body; Lieskovský (2020), §3.4, :mod:`taut.collision`).  Cables of radius 0 are
  lines; cables sharing an end point (a point-mass platform) are compared without the
  shared end (see :mod:`taut.collision._capsules`).

A condition maps an array of poses ``(N, pose_size)`` to ``(N,)`` bool.  Poses where the
inverse kinematics does not exist (a zero-length cable) are outside.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §2.1.4. (docs/references.bib: rushton2022)
.. [2] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, §3.4.
   (docs/references.bib: lieskovsky2020)
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from typing import ClassVar

import numpy as np

from taut.collision import proximity
from taut.errors import TautError
from taut.kinematics import as_poses, batch_structure_matrices
from taut.model import Robot
from taut.statics import BoxWrenchSet, WrenchSet, external_wrench, static_equilibrium, wrench_closure, wrench_feasible

__all__ = [
    "CONDITIONS",
    "InterferenceFree",
    "StaticEquilibrium",
    "WorkspaceCondition",
    "WrenchClosure",
    "WrenchCondition",
    "WrenchFeasible",
    "default_wrench_set",
    "make_condition",
]

#: Fraction of the external force (moment) used as the default box half-width.
DEFAULT_FRACTION = 0.1
#: Smallest default force half-width [N].
MIN_FORCE = 1.0


class WorkspaceCondition(ABC):
    """Base interface of a workspace condition.

    Subclasses set ``name`` (the registry key, used on the command line) and implement
    :meth:`evaluate`.  Instances must be picklable: they travel to worker processes."""

    name: ClassVar[str] = ""
    description: ClassVar[str] = ""

    @abstractmethod
    def evaluate(self, robot: Robot, poses: np.ndarray) -> np.ndarray:
        """``(N,)`` bool: which of the poses ``(N, pose_size)`` satisfy the condition."""

    def __repr__(self) -> str:
        return f"<{type(self).__name__} {self.name!r}>"


class WrenchCondition(WorkspaceCondition):
    """A condition on the structure matrix: computes ``W`` for every pose (poses with a
    zero-length cable are outside) and delegates to :meth:`test`."""

    def evaluate(self, robot: Robot, poses: np.ndarray) -> np.ndarray:
        poses = as_poses(robot, poses)[0]
        _, W, ok = batch_structure_matrices(robot, poses)
        out = np.zeros(poses.shape[0], bool)
        if ok.all():
            return self.test(robot, poses, W)
        if ok.any():
            out[ok] = self.test(robot, poses[ok], W[ok])
        return out

    @abstractmethod
    def test(self, robot: Robot, poses: np.ndarray, W: np.ndarray) -> np.ndarray:
        """``(N,)`` bool from the structure matrices ``W (N, m, n)`` of valid poses."""


class WrenchClosure(WrenchCondition):
    name = "wrench-closure"
    description = "the cables positively span the wrench space (any wrench, positive tensions)"

    def test(self, robot: Robot, poses: np.ndarray, W: np.ndarray) -> np.ndarray:
        return wrench_closure(W)


def default_wrench_set(robot: Robot) -> BoxWrenchSet:
    """The default required set of ``wrench-feasible``, relative to the external wrench: a
    box centred at 0 with force half-widths ``f = max(10 % of |F|, 1 N)``, ``F`` the force
    of the robot's external wrench (weights plus constant wrench), and moment half-widths
    ``max(10 % of M, f·ρ)``, where ``M = |constant moment| + |F|·|wrench point|`` bounds the
    external moment over all orientations and ``ρ`` is the platform radius (largest anchor
    distance to the reference point) — the moment of the force uncertainty applied at the
    rim.  ``f·ρ`` falls back to 1 N·m when ``ρ = 0``."""
    d, m = robot.dimension, robot.wrench_dim
    plat = robot.platform
    force = np.zeros(d)
    if plat.wrench is not None:
        force += np.asarray(plat.wrench[:d], float)
    force += robot.weight + robot.body_weights.sum(axis=0)
    F = float(np.linalg.norm(force))
    f = max(DEFAULT_FRACTION * F, MIN_FORCE)
    half = np.full(m, f)
    if m > d:
        const = float(np.linalg.norm(plat.wrench[d:])) if plat.wrench is not None else 0.0
        arm = float(np.linalg.norm(plat.wrench_point)) if plat.wrench_point is not None else 0.0
        rho = float(np.linalg.norm(robot.anchors, axis=1).max()) if robot.n_cables else 0.0
        half[d:] = max(DEFAULT_FRACTION * (const + F * arm), f * rho if rho > 0 else 1.0)
    return BoxWrenchSet.around(np.zeros(m), half)


class WrenchFeasible(WrenchCondition):
    """Wrench-feasible workspace: every wrench of ``w_ext + wrench_set`` (or of
    ``wrench_set`` alone with ``around_external=False``) is balanced within the tension
    bounds.  ``wrench_set`` defaults to :func:`default_wrench_set`."""

    name = "wrench-feasible"
    description = "every wrench of a set around the external wrench is balanced within the tension bounds"

    def __init__(self, wrench_set: WrenchSet | None = None, *, around_external: bool = True) -> None:
        if wrench_set is not None and not isinstance(wrench_set, WrenchSet):
            raise TautError(
                f"wrench_set must be a WrenchSet (box, polytope, ellipsoid, single wrench), got {type(wrench_set).__name__}"
            )
        self.wrench_set = wrench_set
        self.around_external = bool(around_external)

    def required_set(self, robot: Robot) -> WrenchSet:
        ws = self.wrench_set if self.wrench_set is not None else default_wrench_set(robot)
        if ws.dim != robot.wrench_dim:
            raise TautError(
                f"{robot.name}: the wrench set has {ws.dim} components, the robot's wrenches {robot.wrench_dim}"
            )
        return ws

    def test(self, robot: Robot, poses: np.ndarray, W: np.ndarray) -> np.ndarray:
        ws = self.required_set(robot)
        offset = external_wrench(robot, poses) if self.around_external else None
        tmin, tmax = robot.tension_bounds
        return wrench_feasible(W, tmin, tmax, ws, offset)


class StaticEquilibrium(WrenchCondition):
    name = "static"
    description = "the external wrench (weight included) is balanced within the tension bounds"

    def test(self, robot: Robot, poses: np.ndarray, W: np.ndarray) -> np.ndarray:
        tmin, tmax = robot.tension_bounds
        return static_equilibrium(W, tmin, tmax, external_wrench(robot, poses))


class InterferenceFree(WorkspaceCondition):
    name = "interference-free"
    description = "no cable–cable or cable–platform interference of the capsule model (Lieskovský 2020, §3.4)"

    def evaluate(self, robot: Robot, poses: np.ndarray) -> np.ndarray:
        return proximity(robot, poses).interference_free


#: The registry: condition name → class.
CONDITIONS: dict[str, type[WorkspaceCondition]] = {
    cls.name: cls for cls in (WrenchClosure, WrenchFeasible, StaticEquilibrium, InterferenceFree)
}


def make_condition(
    condition: str | WorkspaceCondition | type[WorkspaceCondition], **options: object
) -> WorkspaceCondition:
    """A condition instance from a registry name, a class or an instance.

    ``options`` (e.g. ``wrench_set``) go to the class; ``None`` values are dropped.
    Raises :class:`TautError` for an unknown name or an option the condition does not take."""
    options = {k: v for k, v in options.items() if v is not None}
    if isinstance(condition, WorkspaceCondition):
        if options:
            raise TautError(f"options {sorted(options)} cannot be applied to an existing condition instance")
        return condition
    if isinstance(condition, str):
        cls = CONDITIONS.get(condition)
        if cls is None:
            raise TautError(f"unknown workspace condition {condition!r}; expected one of {', '.join(CONDITIONS)}")
    elif isinstance(condition, type) and issubclass(condition, WorkspaceCondition):
        cls = condition
    else:
        raise TautError(
            f"a workspace condition is a name ({', '.join(CONDITIONS)}) or a WorkspaceCondition, got {condition!r}"
        )
    try:
        return cls(**options)
    except TypeError:
        raise TautError(f"condition {cls.name!r} does not take the options {sorted(options)}") from None
