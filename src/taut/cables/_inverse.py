"""Static inverse kinematics of robots with sagging cables: for a pose and the external
wrench, the unstrained lengths of the cables and their tensions at both ends.

Each sagging cable is an elastic catenary (:mod:`taut.cables._catenary`) in the vertical
plane of its chord, and pulls the platform along the tangent at its platform end, which
depends on its tension.  The cable forces must balance the wrench (``W(u) τ + w = 0``, the
structure matrix built from those tangents ``u``).  Following Kozak, Zhou & Wang (2006,
§III) and Riehl et al. (2009, §III), the tension distribution is iterated to consistency from
the straight-cable solution: with the tangents of the last step, a tension distribution
method of :mod:`taut.statics` picks ``τ`` (with the tension bounds moved by each cable's
tension difference between its ends, so that both ends stay within them); each cable's
horizontal force ``H = τ u·ĥ`` gives its catenary through the chord (closed form for an
inextensible cable, Newton for an elastic one), and its new tangent; until the tangents
change by less than ``tol``.  With 6 cables (``n = m``) the distribution is the unique
solution of the square system and the iteration solves the square nonlinear problem.  With the
closed forms (``closed-form``, ``improved-closed-form``) the iteration runs compiled, pose by
pose (:mod:`taut.cables._kernels`), and hands the poses it does not settle back to the
vectorised one.

The model takes taut catenaries: a sagging cable's tension at its lower end is kept at least
:data:`TAUT_WEIGHTS` times the weight of a cable as long as its chord, whatever its lower
tension bound (with less, a cable over a level span sags by more than an eighth of it; a
slack cable hangs from its exit, and reaches the platform only right below it): at the
platform, ``w (l + max(0, −rise))`` for a chord ``l`` whose exit lies ``−rise`` below it.

A straight cable (no ``weight``) keeps its straight-line direction; its unstrained length is
``l / (1 + τ/EA)`` (Rushton 2022, Eq. 2.15), ``l`` when inextensible.

References
----------
.. [1] K. Kozak, Q. Zhou, J. Wang, "Static analysis of cable-driven manipulators with
   non-negligible cable mass", IEEE Transactions on Robotics 22(3), 2006, §III.
   (docs/references.bib: kozak2006)
.. [2] N. Riehl, M. Gouttefarde, S. Krut, C. Baradat, F. Pierrot, "Effects of non-negligible
   cable mass on the static behavior of large workspace cable-driven parallel mechanisms",
   IEEE ICRA, 2009, §III. (docs/references.bib: riehl2009)
.. [3] H. M. Irvine, "Cable Structures", MIT Press, 1981, Ch. 1, §1.3.
   (docs/references.bib: irvine1981)
.. [4] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, Eq. 2.15. (docs/references.bib: rushton2022)
.. [5] H. F. Walker, P. Ni, "Anderson acceleration for fixed-point iterations", SIAM Journal on
   Numerical Analysis 49(4), 2011. (docs/references.bib: walker2011)
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from taut._checks import as_array, as_count, as_number
from taut._results import Result
from taut.cables import _catenary as K
from taut.errors import TautError, UnsupportedRobotError
from taut.geometry import cross
from taut.kinematics import as_poses, inverse_kinematics
from taut.model import Robot
from taut.statics import EQUILIBRIUM_RTOL, METHODS, external_wrench, solve_tensions

#: Largest change of a cable's unit tangent between two steps at which the iteration stops.
SAG_TOL = 1e-11
#: Steps of the iteration before a pose counts as ``"not-converged"``.
MAX_SAG_STEPS = 200
#: A sagging cable's least tension at its lower end, in weights of a cable as long as its chord.
TAUT_WEIGHTS = 1.0
#: Steps of the iteration whose differences Anderson's acceleration combines.
ANDERSON_DEPTH = 3
#: Poses solved at once (a larger batch is solved in chunks: the arrays of one stay in cache).
IK_CHUNK = 8192
#: Horizontal span, relative to the chord, below which a sagging cable hangs vertically.
VERTICAL_RTOL = 1e-9
#: The tension distribution methods the compiled iteration runs (:mod:`taut.cables._kernels`).
COMPILED_METHODS = ("closed-form", "improved-closed-form")


@dataclass(frozen=True)
class SaggingIKResult(Result):
    """Static inverse kinematics of ``N`` poses of a robot with ``n`` cables, some sagging
    (:func:`sagging_ik`; without the batch axis for one pose).

    Attributes
    ----------
    unstrained_lengths : ndarray, shape (N, n)
        The unstrained cable lengths to command [m] (zeros where not ``feasible``).
    chord_lengths : ndarray, shape (N, n)
        Straight-line distances from the anchors to the exit points [m] (the straight model's lengths).
    platform_tensions, exit_tensions : ndarray, shape (N, n)
        Tensions at the platform end and at the exit [N] (zeros where not ``feasible``).
    sag : ndarray, shape (N, n)
        The largest distance of each cable from its chord [m] (0 for a straight cable).
    directions : ndarray, shape (N, n, d)
        Unit tangents of the cables at their platform ends, towards the exits: the force
        of cable ``i`` on the platform is ``platform_tensions[i] · directions[i]``.
    structure_matrix : ndarray, shape (N, m, n)
        ``W = [u_i ; (b_i − p) × u_i]`` of those tangents: ``W τ + w = 0``.
    feasible : ndarray of bool, shape (N,), or bool
        Consistent tensions were found, within the bounds at both ends of every cable, and
        they balance the wrench (to :data:`~taut.statics.EQUILIBRIUM_RTOL`).
    status : ndarray of str, shape (N,), or str
        ``"optimal"`` (feasible), the distribution's ``"infeasible"`` or ``"not-found"``,
        ``"slack"`` (a sagging cable without tension) or ``"not-converged"``.
    method : str
        The tension distribution method.
    steps : ndarray of int, shape (N,), or int
        Steps of the iteration.

    Examples
    --------
    >>> from taut.model import example
    >>> res = sagging_ik(example("cogiro-sagging"), [0.0, 0.0, 2.0, 0.0, 0.0, 0.0])
    >>> res.status, res.unstrained_lengths.shape
    ('optimal', (8,))
    """

    unstrained_lengths: np.ndarray
    chord_lengths: np.ndarray
    platform_tensions: np.ndarray
    exit_tensions: np.ndarray
    sag: np.ndarray
    directions: np.ndarray
    structure_matrix: np.ndarray
    feasible: np.ndarray | bool
    status: np.ndarray | str
    method: str
    steps: np.ndarray | int

    def as_dict(self) -> dict[str, Any]:
        """The fields in plain JSON types, with the lengths and tensions ``None`` (one pose) or
        a row ``None`` (several) where no consistent tensions were found.

        Returns
        -------
        dict
            ``json.dumps(result.as_dict(), allow_nan=False)`` accepts it.
        """
        d = super().as_dict()
        fields = ("unstrained_lengths", "platform_tensions", "exit_tensions", "sag")
        for name in fields:
            if isinstance(self.feasible, np.ndarray):
                d[name] = [row if ok else None for row, ok in zip(d[name], self.feasible.tolist())]
            elif not self.feasible:
                d[name] = None
        return d


def _moments(r: np.ndarray, u: np.ndarray, robot: Robot) -> np.ndarray:
    """``W (N, m, n)`` of the tangents ``u (N, n, d)`` at the arms ``r (N, n, d)``."""
    if robot.is_point_mass:
        return np.swapaxes(u, 1, 2)
    m = cross(r, u)
    m = m[..., None] if m.ndim == 2 else m
    return np.concatenate([np.swapaxes(u, 1, 2), np.swapaxes(m, 1, 2)], axis=1)


def _vertical(rise: np.ndarray, tau: np.ndarray, w: np.ndarray, ea: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(L0, ok)`` of a cable hanging vertically with tension ``τ`` at the platform end: the
    root of ``(w/2EA) L0² + σ (1 + τ/EA) L0 = rise``, ``σ`` the sign of ``rise``."""
    flex = np.where(np.isinf(ea), 0.0, 1.0 / np.where(np.isinf(ea), 1.0, ea))
    beta = 1.0 + tau * flex
    disc = beta * beta + 2.0 * np.sign(rise) * w * np.abs(rise) * flex
    L0 = 2.0 * np.abs(rise) / (beta + np.sqrt(np.maximum(disc, 0.0)))
    ok = (disc >= 0) & ((rise > 0) | (tau > w * L0))
    return L0, ok


class _Anderson:
    """Anderson's acceleration of the fixed-point iteration ``x ← G(x)`` of each pose, from
    the last :data:`ANDERSON_DEPTH` steps (Walker & Ni 2011, Eq. 2.1 with ``β = 1``)."""

    def __init__(self, N: int, n: int) -> None:
        self.x = np.zeros((N, ANDERSON_DEPTH + 1, n))
        self.g = np.zeros((N, ANDERSON_DEPTH + 1, n))
        self.count = np.zeros(N, dtype=int)

    def step(self, k: np.ndarray, x: np.ndarray, g: np.ndarray) -> np.ndarray:
        """The next iterate of poses ``k``, whose iterate ``x`` the map took to ``g``."""
        self.x[k] = np.roll(self.x[k], -1, axis=1)
        self.g[k] = np.roll(self.g[k], -1, axis=1)
        self.x[k, -1], self.g[k, -1] = x, g
        self.count[k] += 1
        f = self.g[k] - self.x[k]
        dF = np.diff(f, axis=1)
        dG = np.diff(self.g[k], axis=1)
        # only the differences of steps this pose has taken
        valid = np.arange(ANDERSON_DEPTH)[None, :] >= ANDERSON_DEPTH - (self.count[k][:, None] - 1)
        dF, dG = dF * valid[..., None], dG * valid[..., None]
        A = np.einsum("kin,kjn->kij", dF, dF)
        reg = 1e-10 * np.einsum("kii->k", A)[:, None, None] + 1e-300
        gamma = np.linalg.solve(A + reg * np.eye(ANDERSON_DEPTH), np.einsum("kin,kn->ki", dF, f[:, -1])[..., None])
        return g - np.einsum("kin,ki->kn", dG, gamma[..., 0])


def _iterate(
    robot: Robot,
    method: str,
    tol: float,
    max_steps: int,
    r: np.ndarray,
    u: np.ndarray,
    ext: np.ndarray,
    lo0: np.ndarray,
    hi0: np.ndarray,
    catenary: np.ndarray,
    vertical: np.ndarray,
    span: np.ndarray,
    rise: np.ndarray,
    hhat: np.ndarray,
    up: np.ndarray,
    wgt: np.ndarray,
    ea: np.ndarray,
    chord: np.ndarray,
) -> tuple[np.ndarray, ...]:
    """The iteration of :func:`sagging_ik`, vectorised over the poses: the unstrained lengths,
    the tensions at both ends, the final tangent angles, the statuses and the steps taken
    (``u``, the straight cables' directions, is overwritten)."""
    N, n = chord.shape
    L0 = np.zeros((N, n))
    T0 = np.zeros((N, n))
    T1 = np.zeros((N, n))
    delta = np.zeros((N, n))
    # the angle of each cable's force above the horizontal, the unknowns of the iteration
    phi = np.where(catenary, np.arctan2(rise, np.where(catenary, span, 1.0)), 0.0)
    history = _Anderson(N, n)
    status = np.full(N, "not-converged", dtype=object)
    steps = np.zeros(N, dtype=int)
    active = np.arange(N)
    for step in range(1, max_steps + 1):
        if active.size == 0:
            break
        k = active
        cat, ver = catenary[k], vertical[k]
        u[k] = np.where(cat[..., None], np.cos(phi[k])[..., None] * hhat[k] + np.sin(phi[k])[..., None] * up, u[k])
        lo = np.maximum(lo0[k], lo0[k] - delta[k])
        hi = np.minimum(hi0[k], hi0[k] - delta[k])
        narrow = (lo > hi).any(axis=1)
        hi = np.maximum(hi, lo)
        res = solve_tensions(_moments(r[k], u[k], robot), ext[k], tension_bounds=(lo, hi), method=method)
        good = np.asarray(res.feasible) & ~narrow
        status[k[~good]] = np.where(narrow[~good], "infeasible", np.asarray(res.status)[~good])
        steps[k] = step
        k, tau = k[good], res.tensions[good]
        cat, ver = catenary[k], vertical[k]
        w_k, ea_k, sp = wgt[k], ea[k], np.where(cat, span[k], 1.0)
        t = np.where(cat, tau, 1.0)
        with np.errstate(all="ignore"):  # a cable too slack for its catenary overflows: flagged, not used
            if step == 1:
                H = t * np.cos(phi[k])
                L, V, _ = K.solve_inverse(sp, rise[k], H, w_k, ea_k)
            else:
                H, V, L = t * np.cos(phi[k]), t * np.sin(phi[k]), L0[k]
            H, V, L, ok = K.solve_tension(sp, rise[k], t, w_k, ea_k, H, V, L)
            Lv, okv = _vertical(rise[k], tau, w_k, ea_k)
        slack = (cat & ~ok).any(axis=1) | (ver & ~okv).any(axis=1)
        flex = tau / np.where(np.isinf(ea_k), np.inf, ea_k)
        newL = np.where(cat, L, np.where(ver, Lv, chord[k] / (1.0 + flex)))
        sign = np.sign(rise[k])
        t1 = np.where(cat, np.hypot(H, V + w_k * L), np.where(ver, tau + sign * w_k * Lv, tau))
        g = np.where(cat, np.arctan2(V, H), 0.0)
        keep = ~slack
        kk, g = k[keep], g[keep]
        change = np.abs(g - phi[kk]).max(axis=1)
        L0[kk], T0[kk], T1[kk] = newL[keep], tau[keep], t1[keep]
        delta[kk] = t1[keep] - tau[keep]
        status[k[slack]] = "slack"
        done = change <= tol
        status[kk[done]] = "optimal"
        phi[kk[done]] = g[done]
        go = kk[~done]
        phi[go] = history.step(go, phi[go], g[~done])
        active = go
    return L0, T0, T1, phi, status, steps


def _compiled(
    robot: Robot,
    method: str,
    tol: float,
    max_steps: int,
    *data: np.ndarray,
) -> tuple[np.ndarray, ...]:
    """:func:`_iterate` by the compiled kernel (:mod:`taut.cables._kernels`), the poses it
    hands back by :func:`_iterate`.  The two agree to rounding, but where the iteration hardly
    converges rounding decides whether it does within ``max_steps`` (as it does between
    batches of the vectorised one)."""
    from taut.cables._kernels import CONVERGED, HANDED_BACK, sagging_steps

    r, u, ext, lo0, hi0, catenary, vertical, span, rise, hhat, up, wgt, ea, chord = (
        np.ascontiguousarray(a) for a in data
    )
    N, n = chord.shape
    L0, T0, T1, phi = (np.zeros((N, n)) for _ in range(4))
    code, steps = np.zeros(N, dtype=np.int64), np.zeros(N, dtype=np.int64)
    moments = 0 if robot.is_point_mass else (1 if robot.dimension == 2 else 3)
    rounds = 1 if method == "closed-form" else n + 1
    arrays = (r, u, ext, lo0, hi0, catenary, vertical, span, rise, hhat, up, wgt, ea, chord)
    options = (moments, rounds, ANDERSON_DEPTH, tol, max_steps, EQUILIBRIUM_RTOL)
    sagging_steps(*arrays, *options, L0, T0, T1, phi, code, steps)
    status = np.where(code == CONVERGED, "optimal", "not-converged").astype(object)
    back = np.flatnonzero(code == HANDED_BACK)
    if back.size:
        per_pose = [a if a is up else a[back] for a in arrays]
        parts = _iterate(robot, method, tol, max_steps, *per_pose)
        for whole, part in zip((L0, T0, T1, phi, status, steps), parts):
            whole[back] = part
    return L0, T0, T1, phi, status, steps


def sagging_ik(
    robot: Robot,
    poses: npt.ArrayLike,
    *,
    wrench: npt.ArrayLike | None = None,
    method: str = "lp",
    tension_bounds: tuple[npt.ArrayLike, npt.ArrayLike] | None = None,
    tol: float = SAG_TOL,
    max_steps: int = MAX_SAG_STEPS,
) -> SaggingIKResult:
    """Unstrained lengths and end tensions of the cables, sagging ones as elastic catenaries,
    that hold the platform at ``poses`` against the wrench.

    The tension distribution ``method`` is iterated to consistency with the catenaries from
    the straight-cable solution (module docstring); both ends of every cable stay within
    the tension bounds.  A robot without sagging cables gets the straight answer in one step.

    Parameters
    ----------
    robot : Robot
        A robot without jointed bodies.
    poses : array_like, shape (N, pose_size) or (pose_size,)
        Poses, one or a batch.
    wrench : array_like, shape (N, m) or (m,), optional
        External wrench on the platform [N, N m]; default the robot's own (weight included).
    method : str, default "lp"
        A tension distribution method of :data:`taut.statics.METHODS`.
    tension_bounds : (tmin, tmax), optional
        Tension bounds [N] at both ends of every cable; default ``robot.tension_bounds`` (a
        sagging cable pulls at least its weight, :data:`TAUT_WEIGHTS`).
    tol : float, default SAG_TOL
        Largest change of a unit tangent between two steps at convergence.
    max_steps : int, default MAX_SAG_STEPS
        Steps before a pose counts as ``"not-converged"``.

    Returns
    -------
    SaggingIKResult
        Without the batch axis for one pose.

    Raises
    ------
    TautError
        A bad pose, wrench, bounds, method, ``tol`` or ``max_steps``.
    UnsupportedRobotError
        A platform with jointed bodies.

    References
    ----------
    .. [1] K. Kozak, Q. Zhou, J. Wang, "Static analysis of cable-driven manipulators with
       non-negligible cable mass", IEEE Transactions on Robotics 22(3), 2006, §III.
       (docs/references.bib: kozak2006)
    .. [2] N. Riehl et al., "Effects of non-negligible cable mass on the static behavior of
       large workspace cable-driven parallel mechanisms", IEEE ICRA, 2009.
       (docs/references.bib: riehl2009)

    Examples
    --------
    The least tensions (``lp``) leave four of the 8 steel cables of the CoGiRo-size robot at
    about 50 N, where they sag by half a metre; every cable pulls harder at its exit than at
    the platform:

    >>> from taut.model import example
    >>> res = sagging_ik(example("cogiro-sagging"), [0.0, 0.0, 2.0, 0.0, 0.0, 0.0])
    >>> res.sag.round(2)
    array([0.42, 0.03, 0.03, 0.52, 0.51, 0.03, 0.03, 0.47])
    >>> bool((res.exit_tensions > res.platform_tensions).all())
    True
    """
    if robot.n_joints:
        raise UnsupportedRobotError(f"{robot.name}: the sagging-cable statics handle platforms without joints")
    if not isinstance(method, str) or method not in METHODS:
        raise TautError(f"unknown tension distribution method {method!r}; valid methods: {', '.join(METHODS)}")
    tol = as_number(tol, "tol", positive=True)
    max_steps = as_count(max_steps, "max_steps")
    arr, single = as_poses(robot, poses)
    if arr.shape[0] > IK_CHUNK:
        chunks: list[tuple[np.ndarray, npt.ArrayLike | None]]
        if wrench is not None and np.ndim(wrench) == 2:
            chunks = [
                (arr[k : k + IK_CHUNK], np.asarray(wrench)[k : k + IK_CHUNK]) for k in range(0, len(arr), IK_CHUNK)
            ]
        else:
            chunks = [(arr[k : k + IK_CHUNK], wrench) for k in range(0, len(arr), IK_CHUNK)]
        parts = [
            sagging_ik(robot, p, wrench=w, method=method, tension_bounds=tension_bounds, tol=tol, max_steps=max_steps)
            for p, w in chunks
        ]
        fields = [f.name for f in dataclasses.fields(SaggingIKResult) if f.name != "method"]
        joined = {f: np.concatenate([getattr(r, f) for r in parts]) for f in fields}
        return SaggingIKResult(**joined, method=method)
    N, n, d = arr.shape[0], robot.n_cables, robot.dimension
    ik = inverse_kinematics(robot, arr)
    if wrench is None:
        ext = external_wrench(robot, arr)
    else:
        given = as_array(wrench, "wrench")
        if given.shape not in ((robot.wrench_dim,), (N, robot.wrench_dim)) or (single and given.ndim == 2):
            raise TautError(
                f"wrench: expected shape ({robot.wrench_dim},) or ({N}, {robot.wrench_dim}), got {given.shape}"
            )
        ext = np.broadcast_to(given, (N, robot.wrench_dim))
    lo0, hi0 = robot.tension_bounds if tension_bounds is None else tension_bounds
    lo0 = np.broadcast_to(np.asarray(lo0, float), (N, n))
    hi0 = np.broadcast_to(np.asarray(hi0, float), (N, n))
    r = ik.anchors - arr[:, None, :d]
    u = np.array(ik.directions)
    chord = np.array(ik.lengths)
    ea = np.broadcast_to(robot.axial_stiffness, (N, n))
    wgt = np.broadcast_to(robot.cable_weights, (N, n))
    heavy = np.broadcast_to(wgt > 0, (N, n))
    up = -robot.gravity / np.linalg.norm(robot.gravity)
    c = robot.exits[None] - ik.anchors
    rise = c @ up
    # taut catenaries only: a cable pulling at its lower end with less than its own weight sags
    # by more than an eighth of its chord, and a slack one hangs from its exit
    lo0 = np.maximum(lo0, TAUT_WEIGHTS * wgt * (chord + np.maximum(-rise, 0.0)))
    hvec = c - rise[..., None] * up
    span = np.linalg.norm(hvec, axis=-1)
    vertical = heavy & (span <= VERTICAL_RTOL * chord)
    hhat = hvec / np.where(span > 0, span, 1.0)[..., None]
    catenary = heavy & ~vertical

    data = (r, u, ext, lo0, hi0, catenary, vertical, span, rise, hhat, up, wgt, ea, chord)
    solve = _compiled if method in COMPILED_METHODS else _iterate
    L0, T0, T1, phi, status, steps = solve(robot, method, tol, max_steps, *data)
    cat = catenary[..., None]
    u = np.where(cat, np.cos(phi)[..., None] * hhat + np.sin(phi)[..., None] * up, u)
    W = _moments(r, u, robot)
    residual = np.abs(np.einsum("kij,kj->ki", W, T0) + ext).max(axis=1)
    scale = np.maximum(np.abs(ext).max(axis=1), np.abs(W).max(axis=(1, 2)) * T0.max(axis=1))
    slackness = EQUILIBRIUM_RTOL * np.maximum(hi0.max(axis=1, where=np.isfinite(hi0), initial=1.0), 1.0)
    within = ((T0 >= lo0 - slackness[:, None]) & (T0 <= hi0 + slackness[:, None])).all(axis=1)
    within &= ((T1 >= lo0 - slackness[:, None]) & (T1 <= hi0 + slackness[:, None])).all(axis=1)
    feasible = (status == "optimal") & (residual <= EQUILIBRIUM_RTOL * scale) & within
    status = np.where((status == "optimal") & ~feasible, "not-converged", status).astype(str)
    sag = np.zeros((N, n))
    if catenary.any():
        with np.errstate(all="ignore"):  # the rows without a solution are set to 0
            s = K.largest_sag(
                np.where(catenary, span, 1.0),
                rise,
                np.where(catenary, T0 * np.einsum("kid,kid->ki", u, hhat), 1.0),
                T0 * (u @ up),
                L0,
                wgt,
                ea,
            )
        sag = np.where(catenary & feasible[:, None], s, 0.0)
    keep = feasible[:, None]
    L0, T0, T1 = (np.where(keep, a, 0.0) for a in (L0, T0, T1))
    if single:
        return SaggingIKResult(
            L0[0], chord[0], T0[0], T1[0], sag[0], u[0], W[0], bool(feasible[0]), str(status[0]), method, int(steps[0])
        )
    return SaggingIKResult(L0, chord, T0, T1, sag, u, W, feasible, status, method, steps)
