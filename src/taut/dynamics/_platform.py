"""Equations of motion of a CDPR platform in the robot's pose coordinates.

A rigid platform with mass ``m`` and inertia ``I`` (about its centre of mass ``c``, fixed in
the platform: ``platform.wrench_point``) at the pose ``q = (p, φ)`` — the reference point ``p``
and the orientation angles ``φ`` (``docs/architecture.md`` §2.2) — has the twist ``ν = (ṗ, ω)``
with ``ω = E(φ) φ̇`` (:mod:`taut.geometry._rates`), i.e. ``ν = J(q) q̇`` with ``J = diag(1, E)``
(planar: ``J = 1``, ``ω = θ̇``; point mass: ``J = 1``, no orientation).  With ``r = R c`` the
arm from ``p`` to the centre of mass, the Newton–Euler equations about ``p``, in the fixed
frame and in taut's wrench convention (forces, then moments about ``p``: the rows of the
structure matrix ``W``, §2.4), read

    ``M_ν ν̇ + b_ν = W τ + w₀ + w_ext``,
    ``M_ν = [[m 1, −m [r]×], [m [r]×, I_p]]``,  ``I_p = R I Rᵀ − m [r]×²``,
    ``b_ν = (m ω × (ω × r), ω × I_p ω)``,

with ``w₀`` the robot's own load (its weight ``Robot.weight`` at the centre of mass and the
constant ``platform.wrench``: :func:`taut.statics.external_wrench`).  The moment rows of
``W`` are moments, not generalized forces of the angles: by virtual work the generalized force
of a wrench ``w`` is ``Jᵀ w`` (``Eᵀ n`` for the angles).  Premultiplying by ``Jᵀ`` gives the
Lagrange form in the pose coordinates (Siciliano et al. 2009, §7.1–7.2)

    ``M(q) q̈ + C(q, q̇) q̇ + g(q) = Jᵀ (W τ + w_ext)``,
    ``M = Jᵀ M_ν J``,  ``C = Jᵀ (M_ν J̇ + C_ν J)``,  ``g = −Jᵀ w₀``,

where ``C_ν ν = b_ν`` is the factorization ``C_ν = [[0, −m [ω]×[r]×], [m [ω]×[r]×,
[ω]× I_p + m [r × ṗ]×]]`` (planar: ``C_ν = [[0, −m ω r], [0, 0]]``) for which ``Ṁ_ν − 2 C_ν``
and hence ``Ṁ − 2 C`` are skew-symmetric (Siciliano et al. 2009, §7.2.1, where the inertia
matrix is called ``B``).  ``M`` is symmetric positive definite wherever ``E`` is regular (away from the gimbal lock of the
orientation convention).

A platform carrying jointed bodies (``platform.bodies``) has the pose ``q = (p, φ, q_J)`` with
the joint coordinates: :func:`mass_matrix`, :func:`bias_forces`, :func:`gravity_forces`,
:func:`velocity_jacobian` (``T = diag(1, E, 1)``) and :func:`generalized_forces` (of the rows
of :func:`taut.kinematics.jointed_structure_matrix`: a wrench about ``p``, then joint
forces) and :func:`coriolis_matrix` take it to :mod:`taut.dynamics._jointed` when every body
has a mass and an inertia; :func:`platform_dynamics` describes its platform body alone, and
forward and inverse dynamics run its bodies in :mod:`taut.dynamics._tree`.

References
----------
.. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning and
   Control", Springer, 2009, §3.6 (Eq. 3.64), §7.1–7.2 (Lagrange formulation; §7.2.1 the
   skew-symmetry of Ḃ − 2C) and §7.5 (Newton–Euler formulation). (docs/references.bib: siciliano2009)
.. [2] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §2.1.1, Eqs. 2.8, 2.10 and 2.11. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from taut._results import Result
from taut.dynamics._jointed import (
    jointed_bias_forces,
    jointed_coriolis_matrix,
    jointed_gravity_forces,
    jointed_mass_matrix,
    twist_jacobian,
)
from taut.errors import TautError, UnsupportedRobotError
from taut.geometry import cross, planar_rotation, rate_matrix, rate_matrix_derivative, rotation_matrix
from taut.kinematics import as_poses
from taut.model import Robot

__all__ = [
    "PlatformDynamics",
    "platform_dynamics",
    "velocity_jacobian",
    "mass_matrix",
    "coriolis_matrix",
    "gravity_forces",
    "bias_forces",
    "generalized_forces",
    "own_load",
]

#: Per convention: the axis of each elementary rotation of ``R`` and ``T`` with ``t = T φ``
#: (the factors of :mod:`taut.geometry._rates`), for the compiled kernels.
CONVENTION_FACTORS: dict[str, tuple[tuple[int, int, int], tuple[tuple[float, ...], ...]]] = {
    "xyz-fixed": ((2, 1, 0), ((0.0, 0, 1), (0, 1, 0), (1, 0, 0))),
    "xyz-moving": ((0, 1, 2), ((1.0, 0, 0), (0, 1, 0), (0, 0, 1))),
    "tilt-torsion": ((2, 1, 2), ((1.0, 0, 0), (0, 1, 0), (-1, 0, 1))),
}

POINT_MASS, PLANAR, SPATIAL = 0, 1, 2


@dataclass(frozen=True)
class PlatformDynamics(Result):
    """The inertial data of a robot's platform, checked once (:func:`platform_dynamics`).

    Attributes
    ----------
    kind : int
        ``POINT_MASS`` (0), ``PLANAR`` (1, rigid) or ``SPATIAL`` (2, rigid).
    dimension : int
        2 or 3.
    dof : int
        Pose coordinates (= wrench components).
    mass : float
        [kg].
    com : ndarray, shape (d,)
        Centre of mass in the platform frame [m] (zero for a point mass).
    inertia : ndarray, shape (3, 3)
        About the centre of mass, platform frame [kg m²] (planar: ``Izz`` at ``[2, 2]``).
    force : ndarray, shape (d,)
        Constant force at the centre of mass: the weight and ``platform.wrench`` [N].
    moment : ndarray, shape (dof − d,)
        Constant moment of ``platform.wrench`` [N m].
    orientation : str
        The robot's orientation convention.

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.dynamics import platform_dynamics
    >>> pd = platform_dynamics(example("planar-4cable"))
    >>> pd.mass, pd.force, sorted(pd.as_dict())[:3]
    (1.0, array([ 0.  , -9.81]), ['com', 'dimension', 'dof'])
    """

    kind: int  #: :data:`POINT_MASS`, :data:`PLANAR` (rigid) or :data:`SPATIAL` (rigid)
    dimension: int  #: 2 or 3
    dof: int  #: pose coordinates (= wrench components)
    mass: float
    com: np.ndarray  #: ``(d,)`` centre of mass in the platform frame (zero for a point mass)
    inertia: np.ndarray  #: ``(3, 3)`` about the centre of mass, platform frame (planar: ``Izz`` at ``[2, 2]``)
    force: np.ndarray  #: ``(d,)`` constant force at the centre of mass: weight and ``platform.wrench``
    moment: np.ndarray  #: ``(dof − d,)`` constant moment of ``platform.wrench``
    orientation: str


def platform_dynamics(robot: Robot) -> PlatformDynamics:
    """The platform's mass, centre of mass, inertia and constant load, checked.

    Parameters
    ----------
    robot : Robot

    Returns
    -------
    PlatformDynamics

    Raises
    ------
    UnsupportedRobotError
        For a platform without ``mass``, or a rigid platform without a positive definite
        ``inertia``.  (On a jointed platform the data are the platform body's alone.)

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.dynamics import platform_dynamics
    >>> round(float(platform_dynamics(example("planar-4cable")).inertia[2, 2]), 6)  # 1 kg, 0.2 m × 0.1 m
    0.004167
    """
    plat, d = robot.platform, robot.dimension
    if plat.mass is None:
        raise UnsupportedRobotError(f"{robot.name}: the dynamics needs the platform's mass (platform.mass)")
    kind = POINT_MASS if robot.is_point_mass else (PLANAR if d == 2 else SPATIAL)
    inertia = np.zeros((3, 3))
    if kind != POINT_MASS:
        tensor = robot.inertia
        if tensor is None:
            raise UnsupportedRobotError(
                f"{robot.name}: the dynamics of a rigid platform needs its inertia (platform.inertia, "
                "about the centre of mass platform.wrench_point)"
            )
        if np.linalg.eigvalsh(tensor).min() <= 1e-12 * max(np.abs(tensor).max(), 1e-300):
            raise UnsupportedRobotError(
                f"{robot.name}: platform.inertia {list(plat.inertia or ())} is singular: a rigid platform "
                "needs a positive definite inertia"
            )
        if kind == PLANAR:
            inertia[2, 2] = tensor[0, 0]
        else:
            inertia = np.array(tensor, dtype=float)
    m = robot.wrench_dim
    load = np.zeros(m) if plat.wrench is None else np.asarray(plat.wrench, dtype=float)
    com = np.zeros(d) if kind == POINT_MASS or plat.wrench_point is None else np.asarray(plat.wrench_point, float)
    return PlatformDynamics(
        kind=kind,
        dimension=d,
        dof=m,
        mass=float(plat.mass),
        com=com,
        inertia=inertia,
        force=robot.weight + load[:d],
        moment=load[d:],
        orientation=robot.orientation,
    )


def _poses(robot: Robot, q: npt.ArrayLike) -> tuple[np.ndarray, bool]:
    return as_poses(robot, q)


def positive(value: object, what: str) -> float:
    """``value`` as a float if it is a positive finite number, else a :class:`TautError`."""
    x = float(value) if isinstance(value, numbers.Real) and not isinstance(value, bool) else math.nan
    if not 0 < x < math.inf:
        raise TautError(f"{what} must be a positive finite number, got {value!r}")
    return x


def check_callable(f: object, what: str) -> None:
    """A :class:`TautError` unless ``f`` is None or callable."""
    if f is not None and not callable(f):
        raise TautError(f"{what} must be a function, got {type(f).__name__}")


def as_rates(robot: Robot, qd: npt.ArrayLike, n: int, what: str = "pose velocities") -> np.ndarray:
    """Validate pose rates ``(n, dof)`` (or one ``(dof,)`` broadcast to ``n``)."""
    from taut.errors import PoseError

    try:
        arr = np.asarray(qd, dtype=float)
    except (TypeError, ValueError):
        raise PoseError(f"{what} must be numbers") from None
    if arr.shape[-1:] != (robot.pose_size,) or arr.ndim > 2:
        raise PoseError(f"{robot.name}: {what} have {robot.pose_size} components, got shape {arr.shape}")
    arr = np.atleast_2d(arr)
    if arr.shape[0] not in (1, n):
        raise PoseError(f"{robot.name}: {n} poses but {arr.shape[0]} {what}")
    if not np.isfinite(arr).all():
        raise PoseError(f"{robot.name}: {what} are not finite")
    return np.broadcast_to(arr, (n, robot.pose_size))


def frames(pd: PlatformDynamics, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Rotations ``R (N, 3, 3)`` (planar and point mass: embedded in 3-D) and arms ``r = R c``
    ``(N, 3)`` from ``p`` to the centre of mass, in the fixed frame."""
    N = q.shape[0]
    R = np.broadcast_to(np.eye(3), (N, 3, 3)).copy()
    if pd.kind == PLANAR:
        R[:, :2, :2] = planar_rotation(q[:, 2])
    elif pd.kind == SPATIAL:
        R = rotation_matrix(q[:, 3:6], pd.orientation)
    c = np.zeros(3)
    c[: pd.dimension] = pd.com
    return R, R @ c


def _skew(v: np.ndarray) -> np.ndarray:
    """``[v]×`` ``(N, 3, 3)`` of vectors ``(N, 3)``."""
    S = np.zeros(v.shape[:-1] + (3, 3))
    S[..., 0, 1], S[..., 0, 2] = -v[..., 2], v[..., 1]
    S[..., 1, 0], S[..., 1, 2] = v[..., 2], -v[..., 0]
    S[..., 2, 0], S[..., 2, 1] = -v[..., 1], v[..., 0]
    return S


def _inertia_about_p(pd: PlatformDynamics, R: np.ndarray, S: np.ndarray) -> np.ndarray:
    """``I_p (N, 3, 3)``: the inertia tensor about ``p`` in the fixed frame, from the one about
    the centre of mass and ``S = [r]×`` (parallel axes)."""
    return R @ pd.inertia @ np.swapaxes(R, 1, 2) - pd.mass * S @ S


def twist_inertia(pd: PlatformDynamics, R: np.ndarray, r: np.ndarray) -> np.ndarray:
    """``M_ν (N, dof, dof)``: the platform's inertia for twists ``(ṗ, ω)`` about ``p``."""
    N, m, d = R.shape[0], pd.mass, pd.dimension
    if pd.kind == POINT_MASS:
        return np.broadcast_to(m * np.eye(d), (N, d, d)).copy()
    S = _skew(r)
    Ip = _inertia_about_p(pd, R, S)
    if pd.kind == PLANAR:
        out = np.zeros((N, 3, 3))
        out[:, 0, 0] = out[:, 1, 1] = m
        out[:, 0, 2] = out[:, 2, 0] = -m * r[:, 1]
        out[:, 1, 2] = out[:, 2, 1] = m * r[:, 0]
        out[:, 2, 2] = Ip[:, 2, 2]
        return out
    out = np.zeros((N, 6, 6))
    out[:, :3, :3] = m * np.eye(3)
    out[:, :3, 3:] = -m * S
    out[:, 3:, :3] = m * S
    out[:, 3:, 3:] = Ip
    return out


def velocity_jacobian(robot: Robot, q: npt.ArrayLike) -> np.ndarray:
    """The Jacobian ``J`` of the twist ``(ṗ, ω) = J q̇`` from the pose rates.

    ``J = diag(1, E(φ))`` for a spatial platform (:func:`taut.geometry.rate_matrix`), the
    identity otherwise; a jointed platform's ``J = diag(1, E(φ), 1)`` also maps the joint rates.
    The generalized force of a wrench ``w`` (taut's convention: moments about ``p``) is
    ``Jᵀ w``.

    Parameters
    ----------
    robot : Robot
    q : array_like, shape (N, dof) or (dof,)
        Poses.

    Returns
    -------
    ndarray, shape (N, dof, dof) or (dof, dof) for one pose

    Raises
    ------
    PoseError
        Poses that :func:`~taut.kinematics.as_poses` refuses.
    UnsupportedRobotError
        A robot without mass (or inertia, for a rigid platform).

    References
    ----------
    .. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning
           and Control", Springer, 2009, §3.6, Eq. 3.64. (docs/references.bib: siciliano2009)

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.dynamics import velocity_jacobian
    >>> velocity_jacobian(example("planar-4cable"), [0.1, 0.2, 0.3])
    array([[1., 0., 0.],
           [0., 1., 0.],
           [0., 0., 1.]])
    """
    arr, single = _poses(robot, q)
    J = twist_jacobian(robot, arr) if robot.n_joints else _jacobian(platform_dynamics(robot), arr)
    return J[0] if single else J


def _jacobian(pd: PlatformDynamics, q: np.ndarray) -> np.ndarray:
    J = np.broadcast_to(np.eye(pd.dof), (q.shape[0], pd.dof, pd.dof)).copy()
    if pd.kind == SPATIAL:
        J[:, 3:, 3:] = rate_matrix(q[:, 3:6], pd.orientation)
    return J


def _jacobian_rate(pd: PlatformDynamics, q: np.ndarray, qd: np.ndarray) -> np.ndarray:
    Jd = np.zeros((q.shape[0], pd.dof, pd.dof))
    if pd.kind == SPATIAL:
        Jd[:, 3:, 3:] = rate_matrix_derivative(q[:, 3:6], qd[:, 3:6], pd.orientation)
    return Jd


def _twist_coriolis(pd: PlatformDynamics, R: np.ndarray, r: np.ndarray, nu: np.ndarray) -> np.ndarray:
    """``C_ν (N, dof, dof)`` with ``C_ν ν = b_ν`` and ``Ṁ_ν − 2 C_ν`` skew-symmetric."""
    N, m = R.shape[0], pd.mass
    C = np.zeros((N, pd.dof, pd.dof))
    if pd.kind == PLANAR:
        C[:, 0, 2] = -m * nu[:, 2] * r[:, 0]
        C[:, 1, 2] = -m * nu[:, 2] * r[:, 1]
    elif pd.kind == SPATIAL:
        v, w = nu[:, :3], nu[:, 3:]
        Sr, Sw = _skew(r), _skew(w)
        C[:, :3, 3:] = -m * Sw @ Sr
        C[:, 3:, :3] = m * Sw @ Sr
        C[:, 3:, 3:] = Sw @ _inertia_about_p(pd, R, Sr) + m * _skew(cross(r, v))
    return C


def own_load(pd: PlatformDynamics, R: np.ndarray, r: np.ndarray) -> np.ndarray:
    """``w₀ (N, dof)``: the constant force at the centre of mass and the constant moment, as a
    wrench about ``p`` in the fixed frame."""
    d = pd.dimension
    w = np.zeros((R.shape[0], pd.dof))
    w[:, :d] = pd.force
    if pd.kind != POINT_MASS:
        f3 = np.zeros(3)
        f3[:d] = pd.force
        moment = cross(r, np.broadcast_to(f3, r.shape))
        w[:, d:] = pd.moment + (moment[:, 2:] if pd.kind == PLANAR else moment)
    return w


def mass_matrix(robot: Robot, q: npt.ArrayLike) -> np.ndarray:
    """The mass matrix ``M(q) = Jᵀ M_ν J`` in the pose coordinates.

    Parameters
    ----------
    robot : Robot
    q : array_like, shape (N, dof) or (dof,)
        Poses.

    Returns
    -------
    ndarray, shape (N, dof, dof) or (dof, dof) for one pose
        Symmetric, positive definite away from the gimbal lock of the orientation convention.

    Raises
    ------
    PoseError
        Poses that :func:`~taut.kinematics.as_poses` refuses.
    UnsupportedRobotError
        A robot without mass (or inertia, for a rigid platform); a jointed body without them.

    References
    ----------
    .. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning
           and Control", Springer, 2009, §7.1–7.2. (docs/references.bib: siciliano2009)

    Examples
    --------
    The planar platform: its mass (1 kg) twice, then its moment of inertia about the centre
    of mass (the reference point):

    >>> from taut.model import example
    >>> from taut.dynamics import mass_matrix
    >>> mass_matrix(example("planar-4cable"), [0.0, 0.0, 0.0]).round(4)
    array([[1.    , 0.    , 0.    ],
           [0.    , 1.    , 0.    ],
           [0.    , 0.    , 0.0042]])
    """
    arr, single = _poses(robot, q)
    if robot.n_joints:
        M = jointed_mass_matrix(robot, arr)
        return M[0] if single else M
    pd = platform_dynamics(robot)
    R, r = frames(pd, arr)
    J = _jacobian(pd, arr)
    M = np.swapaxes(J, 1, 2) @ twist_inertia(pd, R, r) @ J
    return M[0] if single else M


def coriolis_matrix(robot: Robot, q: npt.ArrayLike, qd: npt.ArrayLike) -> np.ndarray:
    """The Coriolis matrix ``C(q, q̇) = Jᵀ (M_ν J̇ + C_ν J)``, with ``Ṁ − 2 C`` skew-symmetric.

    Parameters
    ----------
    robot : Robot
    q, qd : array_like, shape (N, dof) or (dof,)
        Poses and pose rates.

    Returns
    -------
    ndarray, shape (N, dof, dof) or (dof, dof) for one pose

    Raises
    ------
    PoseError
        Poses or rates of the wrong shape or not finite.
    UnsupportedRobotError
        A robot without mass (or inertia, for a rigid platform).

    References
    ----------
    .. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning
           and Control", Springer, 2009, §7.2.1. (docs/references.bib: siciliano2009)

    Examples
    --------
    With the centre of mass at the reference point a spinning planar platform has no Coriolis
    forces:

    >>> from taut.model import example
    >>> from taut.dynamics import coriolis_matrix
    >>> coriolis_matrix(example("planar-4cable"), [0.0, 0.0, 0.0], [0.0, 0.0, 1.0])
    array([[0., 0., 0.],
           [0., 0., 0.],
           [0., 0., 0.]])
    """
    arr, single = _poses(robot, q)
    qdot = as_rates(robot, qd, arr.shape[0])
    if robot.n_joints:
        C = jointed_coriolis_matrix(robot, arr, qdot)
        return C[0] if single else C
    C = _platform_coriolis(platform_dynamics(robot), arr, qdot)[0]
    return C[0] if single else C


def _platform_coriolis(
    pd: PlatformDynamics, q: np.ndarray, qd: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``C = Jᵀ (M_ν J̇ + C_ν J)`` of a platform without joints, with the ``J`` and frames
    ``R, r`` it was computed from (:func:`bias_forces` adds the load in them)."""
    R, r = frames(pd, q)
    J = _jacobian(pd, q)
    nu = np.einsum("nij,nj->ni", J, qd)
    C = np.swapaxes(J, 1, 2) @ (twist_inertia(pd, R, r) @ _jacobian_rate(pd, q, qd) + _twist_coriolis(pd, R, r, nu) @ J)
    return C, J, R, r


def gravity_forces(robot: Robot, q: npt.ArrayLike) -> np.ndarray:
    """The generalized forces ``g(q) = −Jᵀ w₀`` of the robot's weight (and of a constant
    ``platform.wrench``).

    A platform at rest is in equilibrium when ``g = Jᵀ W τ``: the statics of
    :func:`taut.statics.external_wrench` (jointed platforms: also the bodies' weights, and the
    joint rows of :func:`taut.kinematics.joint_forces`).

    Parameters
    ----------
    robot : Robot
    q : array_like, shape (N, dof) or (dof,)
        Poses.

    Returns
    -------
    ndarray, shape (N, dof) or (dof,) for one pose

    Raises
    ------
    PoseError
        Poses that :func:`~taut.kinematics.as_poses` refuses.
    UnsupportedRobotError
        A robot without mass (or inertia, for a rigid platform).

    References
    ----------
    .. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning
           and Control", Springer, 2009, §7.2. (docs/references.bib: siciliano2009)

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.dynamics import gravity_forces
    >>> gravity_forces(example("planar-4cable"), [0.0, 0.0, 0.0]) + 0.0
    array([0.  , 9.81, 0.  ])
    """
    arr, single = _poses(robot, q)
    if robot.n_joints:
        g = jointed_gravity_forces(robot, arr)
        return g[0] if single else g
    pd = platform_dynamics(robot)
    R, r = frames(pd, arr)
    g = -np.einsum("nji,nj->ni", _jacobian(pd, arr), own_load(pd, R, r))
    return g[0] if single else g


def bias_forces(robot: Robot, q: npt.ArrayLike, qd: npt.ArrayLike) -> np.ndarray:
    """The bias forces ``h(q, q̇) = C(q, q̇) q̇ + g(q)``.

    Parameters
    ----------
    robot : Robot
    q, qd : array_like, shape (N, dof) or (dof,)
        Poses and pose rates.

    Returns
    -------
    ndarray, shape (N, dof) or (dof,) for one pose

    Raises
    ------
    PoseError
        Poses or rates of the wrong shape or not finite.
    UnsupportedRobotError
        A robot without mass (or inertia, for a rigid platform).

    References
    ----------
    .. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning
           and Control", Springer, 2009, §7.2. (docs/references.bib: siciliano2009)

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.dynamics import bias_forces
    >>> bias_forces(example("planar-4cable"), [0.0, 0.0, 0.0], [0.0, 0.0, 1.0]) + 0.0
    array([0.  , 9.81, 0.  ])
    """
    arr, single = _poses(robot, q)
    qdot = as_rates(robot, qd, arr.shape[0])
    if robot.n_joints:
        h = jointed_bias_forces(robot, arr, qdot)
        return h[0] if single else h
    pd = platform_dynamics(robot)
    C, J, R, r = _platform_coriolis(pd, arr, qdot)
    h = np.einsum("nij,nj->ni", C, qdot) - np.einsum("nji,nj->ni", J, own_load(pd, R, r))  # C q̇ + g
    return h[0] if single else h


def generalized_forces(robot: Robot, q: npt.ArrayLike, wrench: npt.ArrayLike) -> np.ndarray:
    """The generalized forces ``Jᵀ w`` of wrenches in taut's convention.

    ``w`` holds forces, then moments about ``p`` in the fixed frame, like ``W τ``.  On a jointed
    platform it also holds the joint forces (along, or torques about, the joint axes), as the
    rows of :func:`taut.kinematics.jointed_structure_matrix`: the cables' generalized forces are
    ``Jᵀ A[:, :n] τ``.

    Parameters
    ----------
    robot : Robot
    q : array_like, shape (N, dof) or (dof,)
        Poses.
    wrench : array_like, shape (N, dof) or (dof,)
        Wrenches [N, N m].

    Returns
    -------
    ndarray, shape (N, dof) or (dof,) for one pose

    Raises
    ------
    PoseError
        Poses or wrenches of the wrong shape or not finite.
    UnsupportedRobotError
        A robot without mass (or inertia, for a rigid platform).

    Examples
    --------
    A moment about z on the spatial platform at ``b = 0.5`` rad (``xyz-fixed``): the angle
    ``a`` feels ``−sin b``, the angle ``c`` all of it:

    >>> from taut.model import example
    >>> from taut.dynamics import generalized_forces
    >>> generalized_forces(example("spatial-8cable"), [0, 0, 0, 0, 0.5, 0], [0, 0, 0, 0, 0, 1.0]).round(4) + 0.0
    array([ 0.    ,  0.    ,  0.    , -0.4794,  0.    ,  1.    ])
    """
    arr, single = _poses(robot, q)
    w = as_rates(robot, wrench, arr.shape[0], "wrenches")
    J = twist_jacobian(robot, arr) if robot.n_joints else _jacobian(platform_dynamics(robot), arr)
    Q = np.einsum("nji,nj->ni", J, w)
    return Q[0] if single else Q
