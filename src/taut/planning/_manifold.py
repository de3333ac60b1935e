"""The wrench-feasible C-space of a cable-driven hexapod as a smooth manifold.

Eqs. (1)–(8) of Bohigas et al. (2013), §2–3, ``F(x) = 0`` in the 99 variables

    x = (p [3], τ = (φ, θ, σ) [3], R [9, row-major], u_i [18], ρ_i [6], g_i [6],
         f_0 [6], v_1..v_6 [36], s_i [6], t_i [6]),

    (1)  R − Rz(φ) Ry(θ) Rz(σ − φ) = 0                         tilt-and-torsion
    (2)  p + R b_i − u_i − a_i = 0                              loop equations
    (3)  u_iᵀ u_i − ρ_i² = 0
    (8)  (ρ_i − ρ_min,i)(ρ_max,i − ρ_i) g_i − 1 = 0             strict length bounds
    (4)  J f_0 − ŵ_0 = 0                                         nominal tensions
    (5)  v_iᵀ B v_i − 1 = 0,  B^i v_i = 0,  B = Jᵀ E J          extreme tensions f_0 ± v_i
    (6)  (f_0,i − v_i,i − f_min,i) s_i − 1 = 0
    (7)  (f_max,i − f_0,i − v_i,i) t_i − 1 = 0

93 equations: a 6-manifold (Appendix A), ``6 − |fixed|`` for a slice that fixes some pose
coordinates.  ``u_i = B_i − A_i`` points from the base to the platform and the columns of
the screw Jacobian are ``J_i = [u_i/ρ_i ; (R c_i) × u_i/ρ_i]`` so that ``J f = ŵ`` balances
the wrench ``ŵ`` applied to the platform.  Moments are taken about the point ``P_m`` of the
nominal wrench (``c_i = b_i − P_m`` in the platform frame), where §5 states
``ŵ_0 = [0, 0, m, 0, 0, 0]`` is constant; in taut's convention ``W = −J`` about ``P_m``.

Angles are periodic: the slice is invariant under ``φ → φ + 2π``, ``θ → θ + 2π``,
``σ → σ + 2π`` and the half-turn ``(φ, θ) → (φ + π, −θ)`` (the same ``R`` of Eq. 1), and its
:class:`~taut.planning.Symmetry` makes an atlas cover the quotient: a path may
cross ``φ = ±π`` or ``θ = 0``, and since the angles of the quotient are bounded, the atlas
of a slice is finite and can complete — the no-path proof of §4.  Poses are lifted with
canonical angles (``θ ∈ [0, π]``, ``φ`` in ``phi_window``).  The slice is also the graph of
the closed-form solution of Eqs. (1)–(8) over its free pose coordinates (:meth:`graph`),
which makes projections onto it cheap.

The positivity of ``v_i,i``, ``s_i``, ``t_i``, ``g_i`` is implicit on each connected component
(Appendix A), so only upper bounds on ``s``, ``t``, ``g`` are imposed, to keep atlases finite.
The Jacobian ``F_x`` is analytic (chain rule through ``J(R, u, ρ)``).

References
----------
.. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of Cable-Driven
   Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots, Mechanisms and
   Machine Science 12, Springer, 2013, §2–3, Eqs. 1–8, Appendix A, §5.
   (docs/references.bib: bohigas2013)
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import KW_ONLY, dataclass, field
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np
import numpy.typing as npt

from taut._checks import as_array, as_number
from taut.errors import InfeasiblePoseError, PoseError, TautError
from taut.kinematics import refuse_swivels
from taut.planning._continuation import ImplicitManifold, Symmetry

if TYPE_CHECKING:
    from taut.model import Robot

__all__ = ["POSE_NAMES", "WrenchFeasibleManifold", "rotation_derivatives"]

#: Names of the pose coordinates of the planner: position, then tilt-and-torsion angles.
POSE_NAMES = ("x", "y", "z", "phi", "theta", "sigma")

# variable blocks of x
_P, _TAU, _R, _U, _RHO, _G, _F0, _V, _S, _T = (
    slice(0, 3),
    slice(3, 6),
    slice(6, 15),
    slice(15, 33),
    slice(33, 39),
    slice(39, 45),
    slice(45, 51),
    slice(51, 87),
    slice(87, 93),
    slice(93, 99),
)
N_VARS = 99


def _rz(a: float) -> tuple[np.ndarray, np.ndarray]:
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]), np.array(
        [[-s, -c, 0.0], [c, -s, 0.0], [0.0, 0.0, 0.0]]
    )


def _ry(a: float) -> tuple[np.ndarray, np.ndarray]:
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]]), np.array(
        [[-s, 0.0, c], [0.0, 0.0, 0.0], [-c, 0.0, -s]]
    )


def rotation_derivatives(tau: np.ndarray | Sequence[float]) -> tuple[np.ndarray, np.ndarray]:
    """``R = Rz(φ) Ry(θ) Rz(σ − φ)`` (Eq. 1) and ``∂R/∂(φ, θ, σ)`` ``(3, 3, 3)``."""
    phi, theta, sigma = tau
    A, dA = _rz(phi)
    Bm, dB = _ry(theta)
    C, dC = _rz(sigma - phi)
    R = A @ Bm @ C
    return R, np.array([dA @ Bm @ C - A @ Bm @ dC, A @ dB @ C, A @ Bm @ dC])


def _cross_rows(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Row-wise ``a × b`` of ``(m, 3)`` arrays (``np.cross`` costs more than the arithmetic here)."""
    return np.stack(
        [
            a[:, 1] * b[:, 2] - a[:, 2] * b[:, 1],
            a[:, 2] * b[:, 0] - a[:, 0] * b[:, 2],
            a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0],
        ],
        axis=1,
    )


def _rotation(tau: np.ndarray) -> np.ndarray:
    """``R = Rz(φ) Ry(θ) Rz(σ − φ)`` of Eq. (1) alone."""
    phi, theta, sigma = tau
    return _rz(phi)[0] @ _ry(theta)[0] @ _rz(sigma - phi)[0]


def _block(value: object, what: str, shape: tuple[int, ...], *, finite: bool = True) -> np.ndarray:
    """``value`` as a float array of ``shape`` (given flat, or a scalar for every entry when
    ``shape`` is one axis)."""
    arr = as_array(value, what, finite=finite)
    size = int(np.prod(shape))
    if arr.size == 1 and len(shape) == 1:
        return np.full(shape, float(arr.reshape(())))
    if arr.size != size:
        raise TautError(f"{what}: expected {size} numbers {shape}, got shape {arr.shape}")
    return arr.reshape(shape).copy()


def _skew(v: np.ndarray) -> np.ndarray:
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


@dataclass
class WrenchFeasibleManifold:
    """Eqs. (1)–(8) for the base points ``a`` ``(6, 3)``, platform points ``b`` ``(6, 3)``,
    nominal wrench ``w0`` about the platform point ``wrench_point``, ellipsoid matrix ``E``
    (the set ``(ŵ − ŵ_0)ᵀ E (ŵ − ŵ_0) ≤ 1``), tension and length bounds, and the pose
    coordinates ``fixed`` (names of :data:`POSE_NAMES` → value) of a slice.

    Parameters
    ----------
    a, b : array_like, shape (6, 3)
        Base (exit) points and platform points [m].
    w0 : array_like, shape (6,)
        Nominal wrench ``ŵ_0`` on the platform, about ``wrench_point``.
    E : array_like, shape (6, 6)
        Symmetric positive definite matrix of the wrench ellipsoid.
    f_min, f_max : array_like, shape (6,) or scalar
        Tension bounds [N] (``f_max`` finite).
    rho_min, rho_max : array_like, shape (6,) or scalar
        Length bounds [m], ``0 < ρ_min < ρ_max``.
    wrench_point : array_like, shape (3,), optional
        Platform point of the nominal wrench.
    fixed : mapping of str to float, optional
        The fixed pose coordinates of a slice.
    slack_max : float, optional
        Upper bound of ``s_i, t_i, g_i`` that keeps atlases finite.
    weights : tuple of float, optional
        Scales of the variable blocks in the coordinates of :meth:`implicit`.
    phi_window : (float, float), optional
        Canonical window of ``φ``, of length 2π.

    Raises
    ------
    TautError
        Arrays of the wrong size, an ``E`` that is not positive definite, or bounds that do
        not bracket a feasible set.
    PoseError
        Fixed coordinates that are not pose coordinates with finite values.

    References
    ----------
    .. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of
       Cable-Driven Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots,
       Mechanisms and Machine Science 12, Springer, 2013, §2–3, Eqs. 1–8.
       (docs/references.bib: bohigas2013)

    Examples
    --------
    The slice of the Robocrane's experiment 1 (§5): position and torsion fixed, ``(φ, θ)``
    free.

    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.planning import WrenchFeasibleManifold
    >>> robot = example("robocrane")
    >>> M = WrenchFeasibleManifold.from_robot(robot, fixed=dict(x=0.0, y=0.0, z=2.0, sigma=7 * np.pi / 36))
    >>> y = M.lift(robot.reference.poses["q1"])
    >>> M.dim, np.round(M.pose(y), 4)
    (2, array([ 0.    ,  0.    ,  2.    , -0.5   ,  0.9   ,  0.6109]))
    """

    #: names of the pose coordinates, in the order of a pose ``(6,)``
    pose_names: ClassVar[tuple[str, ...]] = POSE_NAMES

    a: np.ndarray
    b: np.ndarray
    w0: np.ndarray
    E: np.ndarray
    f_min: np.ndarray
    f_max: np.ndarray
    rho_min: np.ndarray
    rho_max: np.ndarray
    _: KW_ONLY
    wrench_point: np.ndarray = field(default_factory=lambda: np.zeros(3))
    fixed: Mapping[str, float] = field(default_factory=dict)
    slack_max: float = 1e2  #: upper bound on s_i, t_i (and g_i) that keeps atlases finite
    #: weights of the variable blocks (p, τ, R, u, ρ, g, f_0, v, s, t) in the coordinates of
    #: :meth:`implicit`: a linear change of variables that keeps chart steps in pose space
    #: of the order of the chart radius (the slacks vary like 1/margin near the boundary)
    weights: tuple[float, ...] = (1.0, 1.0, 0.1, 0.1, 0.1, 0.01, 1.0, 10.0, 0.01, 0.01)
    #: canonical window of the tilt azimuth φ (length 2π): with θ ∈ [0, π] every rotation
    #: has tilt-and-torsion angles in ``[φ_lo, φ_lo + 2π) × [0, π]``
    phi_window: tuple[float, float] = (-np.pi, np.pi)

    def __post_init__(self) -> None:
        self.a = _block(self.a, "exit points a", (6, 3))
        self.b = _block(self.b, "platform points b", (6, 3))
        self.c = self.b - _block(self.wrench_point, "wrench_point", (3,))
        self.w0 = _block(self.w0, "nominal wrench w0", (6,))
        self.E = _block(self.E, "wrench ellipsoid matrix E", (6, 6))
        if not (np.allclose(self.E, self.E.T) and np.all(np.linalg.eigvalsh(self.E) > 0)):
            raise TautError("the wrench ellipsoid matrix E must be symmetric positive definite")
        self._E_inv = np.linalg.inv(self.E)
        for name in ("f_min", "f_max", "rho_min", "rho_max"):
            setattr(self, name, _block(getattr(self, name), name, (6,), finite=False))
        if not isinstance(self.fixed, Mapping):
            raise PoseError(f"fixed: expected a mapping of pose coordinates to values, got {self.fixed!r}")
        bad = set(self.fixed) - set(POSE_NAMES)
        if bad:
            raise PoseError(f"cannot fix {sorted(bad)}: pose coordinates are {', '.join(POSE_NAMES)}")
        self.fixed = {n: as_number(v, f"fixed {n}", error=PoseError) for n, v in self.fixed.items()}
        if not (
            np.all(self.rho_min > 0)
            and np.all(self.rho_max > self.rho_min)
            and np.all(np.isfinite(self.f_max))
            and np.all(self.f_max > self.f_min)
        ):
            raise TautError("the manifold needs 0 < ρ_min < ρ_max and finite f_min < f_max for every cable")
        self._pose_index = [POSE_NAMES.index(n) for n in POSE_NAMES]
        fixed_idx = [POSE_NAMES.index(n) for n in self.fixed]
        self.free = np.array([i for i in range(N_VARS) if i not in fixed_idx])
        self._fixed_idx = np.array(fixed_idx, dtype=int)
        self._fixed_val = np.array([self.fixed[n] for n in self.fixed], float)
        blocks = (_P, _TAU, _R, _U, _RHO, _G, _F0, _V, _S, _T)
        if len(self.weights) != len(blocks) or min(self.weights) <= 0:
            raise TautError(f"weights must be {len(blocks)} positive numbers, got {self.weights}")
        w = np.empty(N_VARS)
        for blk, wi in zip(blocks, self.weights):
            w[blk] = wi
        self._w = w[self.free]
        lo, hi = (float(v) for v in self.phi_window)
        if not np.isclose(hi - lo, 2 * np.pi):
            raise TautError(f"phi_window must span 2π, got {self.phi_window}")

    @classmethod
    def from_robot(
        cls, robot: Robot, *, E: np.ndarray | None = None, fixed: Mapping[str, float] | None = None, **kw: Any
    ) -> WrenchFeasibleManifold:
        """The manifold of a 6-cable spatial robot: exits ``a``, anchors ``b``, the
        platform's constant ``wrench`` about ``wrench_point`` as ``ŵ_0``, the cables'
        tension and length bounds (a zero lower length bound becomes 1e-6: Eq. (8) needs
        ``ρ_min > 0``).

        Parameters
        ----------
        robot : Robot
            A rigid 6-cable spatial robot in tilt-and-torsion angles with a constant
            platform wrench.
        E : array_like, shape (6, 6), optional
            The wrench ellipsoid matrix (default ``10⁴ I``, §5).
        fixed : mapping of str to float, optional
            The fixed pose coordinates of a slice (:data:`POSE_NAMES`).
        **kw
            Further fields (``slack_max``, ``weights``, ``phi_window``).

        Returns
        -------
        WrenchFeasibleManifold

        Raises
        ------
        TautError
            A robot the planner does not handle.
        """
        refuse_swivels(robot, "wrench-feasible path planning")
        if robot.dimension != 3 or robot.n_cables != 6 or robot.is_point_mass or robot.n_joints:
            raise TautError(f"{robot.name}: wrench-feasible path planning needs a rigid 6-cable spatial robot")
        if robot.orientation != "tilt-torsion":
            raise TautError(f"{robot.name}: the planner uses tilt-and-torsion angles (orientation: tilt-torsion)")
        plat = robot.platform
        if plat.mass is not None or plat.wrench is None:
            raise TautError(f"{robot.name}: the planner needs a constant platform wrench (platform.wrench)")
        lengths = [c.length if c.length is not None else (0.0, np.inf) for c in robot.cables]
        return cls(
            a=np.array([c.exit for c in robot.cables], float),
            b=np.asarray(robot.anchors, float),
            w0=np.asarray(plat.wrench, float),
            E=1e4 * np.eye(6) if E is None else E,
            f_min=np.array([c.tension[0] for c in robot.cables], float),
            f_max=np.array([c.tension[1] for c in robot.cables], float),
            rho_min=np.maximum([lo for lo, _ in lengths], 1e-6),
            rho_max=np.array([hi for _, hi in lengths], float),
            wrench_point=np.zeros(3) if plat.wrench_point is None else np.asarray(plat.wrench_point, float),
            fixed=fixed or {},
            **kw,
        )

    # -- Eqs. (1)–(8) on the full variable vector -------------------------------------

    def _screw(self, R: np.ndarray, u: np.ndarray, rho: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        Rc = self.c @ R.T  # (6, 3): R c_i
        d = u / rho[:, None]
        return np.vstack([d.T, _cross_rows(Rc, d).T]), Rc, d

    def full_function(self, x: np.ndarray) -> np.ndarray:
        p, tau = x[_P], x[_TAU]
        R = x[_R].reshape(3, 3)
        u = x[_U].reshape(6, 3)
        rho, g, f0 = x[_RHO], x[_G], x[_F0]
        V = x[_V].reshape(6, 6)  # row i = v_i
        s, t = x[_S], x[_T]
        Rt, _ = rotation_derivatives(tau)
        J, _, _ = self._screw(R, u, rho)
        B = J.T @ self.E @ J
        BV = V @ B  # row i = (B v_i)ᵀ
        e5 = BV.copy()
        vii = np.diag(V)
        e5[np.arange(6), np.arange(6)] = np.einsum("ij,ij->i", BV, V) - 1.0
        return np.concatenate(
            [
                (R - Rt).ravel(),
                (p + self.b @ R.T - u - self.a).ravel(),
                np.einsum("ij,ij->i", u, u) - rho**2,
                (rho - self.rho_min) * (self.rho_max - rho) * g - 1.0,
                J @ f0 - self.w0,
                e5.ravel(),
                (f0 - vii - self.f_min) * s - 1.0,
                (self.f_max - f0 - vii) * t - 1.0,
            ]
        )

    def full_jacobian(self, x: np.ndarray) -> np.ndarray:
        tau = x[_TAU]
        R = x[_R].reshape(3, 3)
        u = x[_U].reshape(6, 3)
        rho, g, f0 = x[_RHO], x[_G], x[_F0]
        V = x[_V].reshape(6, 6)
        s, t = x[_S], x[_T]
        vii = np.diag(V)
        Fx = np.zeros((93, N_VARS))
        i6 = np.arange(6)
        # (1) rows 0..8
        _, dR = rotation_derivatives(tau)
        Fx[0:9, _R] = np.eye(9)
        Fx[0:9, _TAU] = -dR.reshape(3, 9).T
        # (2) rows 9..26: p + R b_i − u_i − a_i
        for i in range(6):
            r = slice(9 + 3 * i, 12 + 3 * i)
            Fx[r, _P] = np.eye(3)
            Fx[r, _R] = np.kron(np.eye(3), self.b[i])
            Fx[r, 15 + 3 * i : 18 + 3 * i] = -np.eye(3)
        # (3) rows 27..32
        for i in range(6):
            Fx[27 + i, 15 + 3 * i : 18 + 3 * i] = 2 * u[i]
        Fx[27 + i6, 33 + i6] = -2 * rho
        # (8) rows 33..38
        Fx[33 + i6, 33 + i6] = (self.rho_max + self.rho_min - 2 * rho) * g
        Fx[33 + i6, 39 + i6] = (rho - self.rho_min) * (self.rho_max - rho)
        # J(R, u, ρ) and its derivatives dJ/dz for z in (R [9], u [18], ρ [6])
        J, Rc, d = self._screw(R, u, rho)
        dJ = np.zeros((33, 6, 6))
        for m in range(9):  # R_{rc}: R c_i changes by e_r c_i[c]
            rr, cc = divmod(m, 3)
            dRc = np.zeros((6, 3))
            dRc[:, rr] = self.c[:, cc]
            dJ[m, 3:, :] = np.cross(dRc, d).T
        for i in range(6):
            for k in range(3):
                dd = np.zeros(3)
                dd[k] = 1.0 / rho[i]
                dJ[9 + 3 * i + k, :3, i] = dd
                dJ[9 + 3 * i + k, 3:, i] = np.cross(Rc[i], dd)
            dJ[27 + i, :3, i] = -d[i] / rho[i]
            dJ[27 + i, 3:, i] = -np.cross(Rc[i], d[i]) / rho[i]
        zcols = np.r_[np.arange(6, 15), np.arange(15, 33), np.arange(33, 39)]
        # (4) rows 39..44: J f0 − w0
        Fx[39:45, zcols] = np.einsum("zab,b->az", dJ, f0)
        Fx[39:45, _F0] = J
        # (5) rows 45..80: for cable i, row i of (B v_i) replaced by v_iᵀ B v_i − 1
        EJ = self.E @ J
        B = J.T @ EJ
        dB = np.einsum("zab,ac->zbc", dJ, EJ)
        dB = dB + dB.transpose(0, 2, 1)  # dJᵀ E J + Jᵀ E dJ
        for i in range(6):
            rows = slice(45 + 6 * i, 51 + 6 * i)
            vi = V[i]
            blk = np.einsum("zab,b->az", dB, vi)  # d(B v_i)/dz
            blk[i] = np.einsum("a,zab,b->z", vi, dB, vi)
            Fx[rows, zcols] = blk
            vb = B.copy()
            vb[i] = 2 * B @ vi
            Fx[rows, 51 + 6 * i : 57 + 6 * i] = vb
        # (6), (7) rows 81..92
        Fx[81 + i6, 45 + i6] = s
        Fx[81 + i6, 51 + 7 * i6] = -s
        Fx[81 + i6, 87 + i6] = f0 - vii - self.f_min
        Fx[87 + i6, 45 + i6] = -t
        Fx[87 + i6, 51 + 7 * i6] = -t
        Fx[87 + i6, 93 + i6] = self.f_max - f0 - vii
        return Fx

    # -- slices ---------------------------------------------------------------------

    @property
    def dim(self) -> int:
        return 6 - len(self.fixed)

    def full(self, y: np.ndarray) -> np.ndarray:
        """The full 99-vector of the (weighted) free variables ``y`` of the slice."""
        x = np.empty(N_VARS)
        x[self.free] = y / self._w
        x[self._fixed_idx] = self._fixed_val
        return x

    def implicit(self) -> ImplicitManifold:
        """The slice as an :class:`ImplicitManifold` in its weighted free variables
        ``y = w · x_free``, with the box ``s_i, t_i, g_i ≤ slack_max``."""
        lo, hi = np.full(N_VARS, -np.inf), np.full(N_VARS, np.inf)
        hi[_G] = hi[_S] = hi[_T] = self.slack_max
        return ImplicitManifold(
            lambda y: self.full_function(self.full(y)),
            lambda y: self.full_jacobian(self.full(y))[:, self.free] / self._w,
            self.dim,
            lower=lo[self.free] * self._w,
            upper=hi[self.free] * self._w,
            symmetry=self.symmetry(),
            graph=self.graph,
            graph_index=self.pose_metric,
        )

    def symmetry(self) -> Symmetry | None:
        """The periodicity of the free angles in the free vector (module doc), ``None`` when
        every angle is fixed; the half-turn when both ``φ`` and ``θ`` are free."""
        pos = {int(v): i for i, v in enumerate(self.free) if v < 6}
        # θ's window [−π/2, 3π/2) holds the canonical θ ∈ [0, π] that the half-turn selects
        lows = {3: self.phi_window[0], 4: -np.pi / 2, 5: -np.pi}
        periods = tuple((pos[v], 2 * np.pi * self._w[pos[v]], lows[v] * self._w[pos[v]]) for v in (3, 4, 5) if v in pos)
        if not periods:
            return None
        return Symmetry(periods, (pos[3], pos[4]) if 3 in pos and 4 in pos else None)

    def graph(self, q: np.ndarray) -> np.ndarray | None:
        """The free vector of the point of the slice over its free pose coordinates ``q``
        (weighted, as in the free vector; angles taken as they are), ``None`` where that
        pose is not strictly wrench-feasible (Eqs. 6–8) or ``J`` is singular."""
        pose = self.pose(q)
        return None if not np.all(np.isfinite(pose)) else self._solve(pose)

    def canonical(self, pose: npt.ArrayLike) -> np.ndarray:
        """The same pose(s) ``(..., 6)`` with ``θ ∈ [0, π]`` and ``φ`` in :attr:`phi_window`:
        ``(φ, θ)`` and ``(φ + π, −θ)`` give the same ``R`` of Eq. (1) for any ``σ``, and ``φ``
        and ``θ`` are ``2π``-periodic."""
        q = np.array(pose, float)
        q[..., 4] = np.mod(q[..., 4] + np.pi, 2 * np.pi) - np.pi  # θ is 2π-periodic too
        neg = q[..., 4] < 0
        q[..., 4] = np.abs(q[..., 4])
        q[..., 3] = q[..., 3] + np.where(neg, np.pi, 0.0)
        lo = self.phi_window[0]
        q[..., 3] = lo + np.mod(q[..., 3] - lo, 2 * np.pi)
        return q

    def align(self, poses: npt.ArrayLike, pose: npt.ArrayLike) -> np.ndarray:
        """The path ``poses`` ``(N, 6)`` moved by the symmetry (half-turn, 2π shifts of the
        angles) that takes its first pose to ``pose``, another writing of the same pose: a
        path from the canonical lift of a start then begins at the start as the user wrote it.
        Unchanged when no such symmetry exists."""
        q = np.array(poses, float)
        target = np.asarray(pose, float)
        for flip in (False, True):
            c = q.copy()
            if flip:
                c[:, 3] += np.pi
                c[:, 4] = -c[:, 4]
            k = np.round((target[3:] - c[0, 3:]) / (2 * np.pi))
            if np.allclose(c[0, :3], target[:3], atol=1e-9) and np.allclose(
                c[0, 3:] + 2 * np.pi * k, target[3:], atol=1e-9
            ):
                c[:, 3:] += 2 * np.pi * k
                c[0] = target
                return c
        return q

    @property
    def pose_metric(self) -> np.ndarray:
        """Indices of the free pose coordinates inside the free vector (for A* costs)."""
        return np.flatnonzero(self.free < 6)

    def pose(self, y: np.ndarray) -> np.ndarray:
        """Poses ``(..., 6)`` ``[x, y, z, φ, θ, σ]`` of free vectors ``(..., n_free)``."""
        y = np.asarray(y, float)
        out = np.empty(y.shape[:-1] + (6,))
        free_pose = self.free[self.free < 6]
        out[..., free_pose] = y[..., : free_pose.size] / self._w[: free_pose.size]
        out[..., self._fixed_idx] = self._fixed_val
        return out

    def lift(self, pose: npt.ArrayLike) -> np.ndarray:
        """The free vector of the point of the slice over ``pose`` (Eqs. 1–8 solved in closed
        form, angles made :meth:`canonical`); :class:`InfeasiblePoseError` if the pose is not
        wrench-feasible."""
        q = as_array(pose, "pose", finite=False, error=PoseError).reshape(-1)
        if q.size != 6 or not np.all(np.isfinite(q)):
            raise PoseError(f"a pose is [x, y, z, phi, theta, sigma], got {pose!r}")
        if not {"phi", "theta"} & set(self.fixed):
            q = self.canonical(q)
        for n, v in self.fixed.items():
            if not np.isclose(q[POSE_NAMES.index(n)], v, atol=1e-9):
                raise PoseError(f"pose {q.tolist()} is not on the slice {n} = {v}")
        y = self._solve(q)
        if y is not None:
            return y
        ext = self.extreme_tensions(q)
        if ext is None:
            raise InfeasiblePoseError(f"pose {q.tolist()}: the screw Jacobian is singular")
        _, _, rho, f0, V = ext
        lo, hi = f0 - np.diag(V), f0 + np.diag(V)
        if not (np.all(rho > self.rho_min) and np.all(rho < self.rho_max)):
            raise InfeasiblePoseError(
                f"pose {q.tolist()}: cable lengths {np.round(rho, 4).tolist()} "
                f"outside ({self.rho_min.min()}, {self.rho_max.max()})"
            )
        raise InfeasiblePoseError(
            f"pose {q.tolist()} is not wrench-feasible: extreme tensions "
            f"{np.round(lo, 4).tolist()} .. {np.round(hi, 4).tolist()}"
        )

    def _solve(self, q: np.ndarray) -> np.ndarray | None:
        """Eqs. (1)–(8) solved in closed form at the pose ``q`` (free vector), or ``None``."""
        ext = self.extreme_tensions(q)
        if ext is None:
            return None
        R, u, rho, f0, V = ext
        lo, hi = f0 - np.diag(V), f0 + np.diag(V)
        if not (
            np.all(rho > self.rho_min)
            and np.all(rho < self.rho_max)
            and np.all(lo > self.f_min)
            and np.all(hi < self.f_max)
        ):
            return None
        x = np.concatenate(
            [
                q[:3],
                q[3:],
                R.ravel(),
                u.ravel(),
                rho,
                1.0 / ((rho - self.rho_min) * (self.rho_max - rho)),
                f0,
                V.ravel(),
                1.0 / (lo - self.f_min),
                1.0 / (self.f_max - hi),
            ]
        )
        return x[self.free] * self._w

    def extreme_tensions(
        self, pose: npt.ArrayLike
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray] | None:
        """``(R, u, ρ, f_0, V)`` at a pose (row ``i`` of ``V`` is ``v_i`` of Eq. 5, ``v_i,i > 0``),
        or ``None`` where ``J`` is singular.  The tension range of cable ``i`` over the
        ellipsoid is ``f_0,i ± v_i,i``."""
        q = np.asarray(pose, float)
        R = _rotation(q[3:])
        u = q[:3] + self.b @ R.T - self.a
        rho = np.sqrt(np.einsum("ij,ij->i", u, u))
        J, _, _ = self._screw(R, u, rho)
        try:
            Jinv = np.linalg.inv(J)
        except np.linalg.LinAlgError:
            return None
        f0 = Jinv @ self.w0
        Binv = Jinv @ self._E_inv @ Jinv.T  # (Jᵀ E J)⁻¹
        d = np.diag(Binv)
        if not (np.all(np.isfinite(d)) and np.all(d > 0)):
            return None  # J numerically singular
        V = (Binv / np.sqrt(d)[None, :]).T  # v_i = B⁻¹ e_i / sqrt(B⁻¹_ii)
        return R, u, rho, f0, V

    def tension_range(self, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``(f_0 − v_ii, f_0 + v_ii)`` ``(N, 6)`` read off free vectors ``(N, n_free)`` (Fig. 6)."""
        X = np.array([self.full(v) for v in np.atleast_2d(y)])
        f0, vii = X[:, _F0], X[:, _V][:, ::7]
        return f0 - vii, f0 + vii
