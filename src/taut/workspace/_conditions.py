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
* ``sagging-static`` — the static condition with sagging cables (``cables[].weight``):
  the cables, each an elastic catenary carrying its own weight, balance the robot's
  external wrench with tensions within their bounds at both ends
  (:func:`taut.cables.sagging_ik`; Riehl et al. 2009, §IV);
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
.. [3] N. Riehl, M. Gouttefarde, S. Krut, C. Baradat, F. Pierrot, "Effects of non-negligible
   cable mass on the static behavior of large workspace cable-driven parallel mechanisms",
   IEEE ICRA, 2009, §IV. (docs/references.bib: riehl2009)
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from typing import ClassVar

import numpy as np

from taut.cables import sagging_ik
from taut.collision import proximity
from taut.errors import TautError, UnsupportedRobotError
from taut.kinematics import as_poses, batch_structure_matrices
from taut.model import Robot
from taut.statics import (
    METHODS,
    BoxWrenchSet,
    PolytopeWrenchSet,
    SingleWrench,
    WrenchSet,
    equilibrium_equations,
    external_wrench,
    static_equilibrium,
    wrench_closure,
    wrench_feasible,
)

__all__ = [
    "CONDITIONS",
    "InterferenceFree",
    "SaggingStatic",
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

    Subclasses set ``name`` (the registry key, used on the command line) and ``description``
    and implement :meth:`evaluate`; adding a condition is adding one class and one entry of
    :data:`CONDITIONS`.  Instances must be picklable: they travel to worker processes.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §2.1.4. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.model import example
    >>> robot = example("planar-4cable")
    >>> poses = np.array([[0.0, 0.0, 0.0], [0.9, 0.9, 0.0]])  # the centre, and near exit 3
    >>> from taut.workspace import WorkspaceCondition
    >>> class Left(WorkspaceCondition):
    ...     name = "left"
    ...     def evaluate(self, robot, poses):
    ...         return np.asarray(poses)[:, 0] < 0
    >>> Left().evaluate(robot, poses - 0.5)
    array([ True, False])
    """

    name: ClassVar[str] = ""
    description: ClassVar[str] = ""

    @abstractmethod
    def evaluate(self, robot: Robot, poses: np.ndarray) -> np.ndarray:
        """Which poses satisfy the condition.

        Parameters
        ----------
        robot : Robot
        poses : array_like, shape (N, pose_size)

        Returns
        -------
        ndarray of bool, shape (N,)
        """

    def numbers_per_pose(self, robot: Robot) -> int:
        """How many numbers :meth:`evaluate` holds per pose: its structure matrix,
        ``wrench_dim × n_cables``, unless a subclass holds more.
        :func:`~taut.workspace.evaluate_workspace` sizes its chunks by it, so that their
        memory stays bounded and progress is reported as often for any robot.

        Parameters
        ----------
        robot : Robot

        Returns
        -------
        int

        Examples
        --------
        >>> from taut.model import example
        >>> from taut.workspace import StaticEquilibrium
        >>> StaticEquilibrium().numbers_per_pose(example("adjustable-8cable"))  # W is 6 × 8
        48
        """
        return robot.wrench_dim * max(1, robot.n_cables)

    def __repr__(self) -> str:
        return f"<{type(self).__name__} {self.name!r}>"


class WrenchCondition(WorkspaceCondition):
    """A condition on the structure matrix: computes ``W`` for every pose (poses with a
    zero-length cable are outside) and delegates to :meth:`test`.

    Examples
    --------
    >>> import numpy as np
    >>> from taut.model import example
    >>> robot = example("planar-4cable")
    >>> poses = np.array([[0.0, 0.0, 0.0], [0.9, 0.9, 0.0]])  # the centre, and near exit 3
    >>> from taut.workspace import WrenchCondition
    >>> class FullRank(WrenchCondition):
    ...     name = "full-rank"
    ...     def test(self, robot, poses, W):
    ...         return np.linalg.matrix_rank(W) == W.shape[1]
    >>> FullRank().evaluate(robot, poses)
    array([ True,  True])
    """

    def evaluate(self, robot: Robot, poses: np.ndarray) -> np.ndarray:
        """Which poses satisfy the condition (False where a cable has no direction).

        Parameters
        ----------
        robot : Robot
        poses : array_like, shape (N, pose_size)

        Returns
        -------
        ndarray of bool, shape (N,)

        Raises
        ------
        PoseError
            Poses that :func:`~taut.kinematics.as_poses` refuses.
        """
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
        """The condition at valid poses, from their structure matrices.

        Parameters
        ----------
        robot : Robot
        poses : ndarray, shape (N, pose_size)
        W : ndarray, shape (N, m, n)
            The structure matrices at ``poses``.

        Returns
        -------
        ndarray of bool, shape (N,)
        """


class WrenchClosure(WrenchCondition):
    """The wrench-closure workspace (WCW): the cables positively span the wrench space, so
    that they balance any wrench with positive tensions.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §2.1.4. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.model import example
    >>> robot = example("planar-4cable")
    >>> poses = np.array([[0.0, 0.0, 0.0], [0.9, 0.9, 0.0]])  # the centre, and near exit 3
    >>> from taut.workspace import WrenchClosure
    >>> WrenchClosure().evaluate(robot, poses)
    array([ True, False])
    """

    name = "wrench-closure"
    description = "the cables positively span the wrench space (any wrench, positive tensions)"

    def test(self, robot: Robot, poses: np.ndarray, W: np.ndarray) -> np.ndarray:
        """:func:`taut.statics.wrench_closure` of ``W`` (of a jointed platform: of its
        equilibrium equations, :func:`taut.statics.equilibrium_equations`): ``(N,)`` bool."""
        if robot.n_joints:
            W = equilibrium_equations(robot, poses)[0]
        return wrench_closure(W)


def _on_platform(ws: WrenchSet, joints: int) -> WrenchSet:
    """``ws`` acting on the platform of a jointed one: no wrench on its ``joints`` (the
    rows of the equilibrium equations after the platform's)."""
    zero = np.zeros(joints)
    if isinstance(ws, SingleWrench):
        return SingleWrench(np.concatenate([ws.wrench, zero]))
    if isinstance(ws, BoxWrenchSet):
        return BoxWrenchSet(np.concatenate([ws.lower, zero]), np.concatenate([ws.upper, zero]))
    if isinstance(ws, PolytopeWrenchSet):
        return PolytopeWrenchSet(np.column_stack([ws.vertices, np.zeros((len(ws.vertices), joints))]))
    raise UnsupportedRobotError(
        f"a {type(ws).__name__} on a jointed platform: its wrench-feasible workspace takes a single wrench, a box "
        "or a polytope (the set then acts on the platform, not on the joints)"
    )


def default_wrench_set(robot: Robot) -> BoxWrenchSet:
    """The default required wrench set of ``wrench-feasible``, relative to the external wrench.

    A box centred at 0 with force half-widths ``f = max(10 % of |F|, 1 N)``, ``F`` the force
    of the robot's external wrench (weights plus constant wrench), and moment half-widths
    ``max(10 % of M, f·ρ)``, where ``M = |constant moment| + |F|·|wrench point|`` bounds the
    external moment over all orientations and ``ρ`` is the platform radius (largest anchor
    distance to the reference point) — the moment of the force uncertainty applied at the
    rim.  ``f·ρ`` falls back to 1 N·m when ``ρ = 0``.

    Parameters
    ----------
    robot : Robot

    Returns
    -------
    BoxWrenchSet
        Of the robot's wrench size.

    Examples
    --------
    The planar robot weighs 9.81 N (``f = 1`` N) and its anchors are ``‖(0.1, 0.05)‖`` from
    the reference point:

    >>> from taut.model import example
    >>> from taut.workspace import default_wrench_set
    >>> box = default_wrench_set(example("planar-4cable"))
    >>> box.upper.round(4)
    array([1.    , 1.    , 0.1118])
    """
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
    """The wrench-feasible workspace (WFW): every wrench of a set is balanced within the
    tension bounds.

    Parameters
    ----------
    wrench_set : WrenchSet, optional
        The required set; default :func:`default_wrench_set`.
    around_external : bool, optional
        True: the set is centred at the robot's external wrench (weight included), i.e. the
        wrenches ``w_ext + w`` for ``w`` in the set; False: the set alone.

    Raises
    ------
    TautError
        A ``wrench_set`` that is not a :class:`~taut.statics.WrenchSet`.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §2.1.4. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.model import example
    >>> robot = example("planar-4cable")
    >>> poses = np.array([[0.0, 0.0, 0.0], [0.9, 0.9, 0.0]])  # the centre, and near exit 3
    >>> from taut.workspace import WrenchFeasible
    >>> WrenchFeasible().evaluate(robot, poses)
    array([ True, False])
    """

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
        """The wrench set required of ``robot``.

        Parameters
        ----------
        robot : Robot

        Returns
        -------
        WrenchSet
            ``wrench_set``, or :func:`default_wrench_set` of ``robot``.

        Raises
        ------
        TautError
            A set whose size is not the robot's wrench size.
        """
        ws = self.wrench_set if self.wrench_set is not None else default_wrench_set(robot)
        if ws.dim != robot.wrench_dim:
            raise TautError(
                f"{robot.name}: the wrench set has {ws.dim} components, the robot's wrenches {robot.wrench_dim}"
            )
        return ws

    def test(self, robot: Robot, poses: np.ndarray, W: np.ndarray) -> np.ndarray:
        """:func:`taut.statics.wrench_feasible` of ``W`` and the required set: ``(N,)`` bool.
        On a jointed platform, of its equilibrium equations
        (:func:`taut.statics.equilibrium_equations`): the set acts on the platform, the
        bodies' weights on the joints."""
        ws = self.required_set(robot)
        if not robot.n_joints:
            wrench = external_wrench(robot, poses) if self.around_external else None
            return wrench_feasible(W, ws, tension_bounds=robot.tension_bounds, wrench=wrench)
        W, w, bounds = equilibrium_equations(robot, poses, wrench=None if self.around_external else np.zeros(ws.dim))
        return wrench_feasible(W, _on_platform(ws, robot.n_joints), tension_bounds=bounds, wrench=w)


class StaticEquilibrium(WrenchCondition):
    """The static workspace: the robot's external wrench (weight included) is balanced within
    the tension bounds — the wrench-feasible workspace of a single wrench.  It also serves
    under-constrained robots (fewer cables than degrees of freedom).

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §2.1.4. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.model import example
    >>> robot = example("planar-4cable")
    >>> poses = np.array([[0.0, 0.0, 0.0], [0.9, 0.9, 0.0]])  # the centre, and near exit 3
    >>> from taut.workspace import StaticEquilibrium
    >>> StaticEquilibrium().evaluate(robot, poses)
    array([ True, False])
    """

    name = "static"
    description = "the external wrench (weight included) is balanced within the tension bounds"

    def test(self, robot: Robot, poses: np.ndarray, W: np.ndarray) -> np.ndarray:
        """:func:`taut.statics.static_equilibrium` at the external wrench (of a jointed
        platform: of its equilibrium equations, :func:`taut.statics.equilibrium_equations`):
        ``(N,)`` bool."""
        if robot.n_joints:
            W, w, bounds = equilibrium_equations(robot, poses)
            return static_equilibrium(W, w, tension_bounds=bounds)
        return static_equilibrium(W, external_wrench(robot, poses), tension_bounds=robot.tension_bounds)


class SaggingStatic(WorkspaceCondition):
    """The static workspace of a robot with sagging cables: the cables, sagging ones as
    elastic catenaries carrying their own weight, balance the robot's external wrench with
    tensions within their bounds at both ends (:func:`taut.cables.sagging_ik`).  Without
    sagging cables it is the ``static`` condition.

    Parameters
    ----------
    method : str, default "lp"
        The tension distribution method iterated to consistency where Pott's improved closed
        form (tried first, fast, incomplete) finds none; ``lp`` is exact at every step.

    References
    ----------
    .. [1] N. Riehl, M. Gouttefarde, S. Krut, C. Baradat, F. Pierrot, "Effects of non-negligible
       cable mass on the static behavior of large workspace cable-driven parallel mechanisms",
       IEEE ICRA, 2009, §IV. (docs/references.bib: riehl2009)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.workspace import SaggingStatic
    >>> poses = np.array([[0.0, 0.0, 2.0, 0, 0, 0], [0.0, 0.0, 7.0, 0, 0, 0]])  # above the exits: no
    >>> SaggingStatic().evaluate(example("cogiro-sagging"), poses)
    array([ True, False])
    """

    name = "sagging-static"
    description = (
        "the external wrench is balanced by the cables, sagging ones as elastic catenaries carrying their own "
        "weight, within the tension bounds at both ends"
    )

    def __init__(self, *, method: str = "lp") -> None:
        if not isinstance(method, str) or method not in METHODS:
            raise TautError(f"unknown tension distribution method {method!r}; valid methods: {', '.join(METHODS)}")
        self.method = method

    def evaluate(self, robot: Robot, poses: np.ndarray) -> np.ndarray:
        """Whether :func:`taut.cables.sagging_ik` finds consistent tensions: ``(N,)`` bool
        (False where a cable has no direction)."""
        poses = as_poses(robot, poses)[0]
        ok = batch_structure_matrices(robot, poses)[2]
        out = np.zeros(poses.shape[0], bool)
        if not ok.any():
            return out
        # consistent tensions found by the fast closed form are a proof; the rest is decided by `method`
        out[ok] = sagging_ik(robot, poses[ok], method="improved-closed-form").feasible
        rest = ok & ~out
        if rest.any() and self.method != "improved-closed-form":
            out[rest] = sagging_ik(robot, poses[rest], method=self.method).feasible
        return out


class InterferenceFree(WorkspaceCondition):
    """The interference-free workspace: no two capsules of the collision model interfere
    (cable–cable, cable–body; :func:`taut.collision._proximity`).

    References
    ----------
    .. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, §3.4.
       (docs/references.bib: lieskovsky2020)
    """

    name = "interference-free"
    description = "no cable–cable or cable–platform interference of the capsule model (Lieskovský 2020, §3.4)"

    def evaluate(self, robot: Robot, poses: np.ndarray) -> np.ndarray:
        """Whether every checked capsule pair has a positive clearance: ``(N,)`` bool."""
        return proximity(robot, poses).interference_free

    def numbers_per_pose(self, robot: Robot) -> int:
        """Two per checked capsule pair (its distance and clearance): ``n (n − 1)`` for the
        cable pairs, four million per pose for 2000 cables, and at most two per cable and body
        capsule."""
        n = robot.n_cables
        return max(1, n * (n - 1) + 2 * n * len(robot.body_capsules))


#: The registry of workspace conditions: name (as on the command line) → class:
#: ``wrench-closure`` :class:`WrenchClosure`, ``wrench-feasible`` :class:`WrenchFeasible`,
#: ``static`` :class:`StaticEquilibrium`, ``sagging-static`` :class:`SaggingStatic`, ``interference-free`` (no two capsules of the
#: collision model interfere, :mod:`taut.collision`).
CONDITIONS: dict[str, type[WorkspaceCondition]] = {
    cls.name: cls for cls in (WrenchClosure, WrenchFeasible, StaticEquilibrium, SaggingStatic, InterferenceFree)
}


def make_condition(
    condition: str | WorkspaceCondition | type[WorkspaceCondition], **options: object
) -> WorkspaceCondition:
    """A condition instance from a registry name, a class or an instance.

    Parameters
    ----------
    condition : str, WorkspaceCondition or type
        A name of :data:`CONDITIONS`, a subclass of :class:`WorkspaceCondition`, or an
        instance (returned as is).
    **options
        Passed to the class (e.g. ``wrench_set``); ``None`` values are dropped.

    Returns
    -------
    WorkspaceCondition

    Raises
    ------
    TautError
        An unknown name, or an option the condition does not take.

    Examples
    --------
    >>> from taut.workspace import make_condition
    >>> make_condition("static")
    <StaticEquilibrium 'static'>
    """
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
