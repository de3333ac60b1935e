"""Compiled forward dynamics of a platform: accelerations and fixed-step RK4 steps.

One pass per state computes the rotation, the angular velocity ``ω = Σₖ uₖ ṫₖ`` and
``Ė φ̇ = Σₖ (Σ_{j<k} uⱼ ṫⱼ) × uₖ ṫₖ`` from the carried axes ``uₖ`` of the convention
(:mod:`taut.geometry._rates`), the cable wrench ``W τ`` from the cables (Rushton 2022,
Eqs. 2.1 and 2.8; elastic cables: Eq. 2.15 with a slack cable pulling nothing), and solves
the Newton–Euler equations about ``p`` in closed form through the centre of mass: with
``F`` and ``N`` the total force and moment about ``p`` and ``r = R c``,

    ``α = R I⁻¹ Rᵀ (N − r × F − ω × R I Rᵀ ω)``,  ``p̈ = F/m + r × α − ω × (ω × r)``,

then ``φ̈ = T⁻¹ U⁻¹ (α − Ė φ̇)`` with ``E = U T`` (Siciliano et al. 2009, §7.5).  The same
equations as :mod:`taut.dynamics._platform` in the other direction, without forming or
factorizing ``M``: a state costs about a microsecond, which is what a control loop needs.

A cable that leaves through a swivelling pulley pulls along its tangent, and its length
holds the wound arc (:func:`taut.dynamics._tree.cable_path`; the pulley's inertia is
neglected).

Status per state: 0 success, 1 the rate matrix is singular (gimbal lock), 2 a cable has zero
length (no direction), 3 the mass matrix of a jointed platform is not positive definite.

A platform carrying jointed bodies has its own kernels (:mod:`taut.dynamics._tree`), to which
:func:`acceleration_one` and :func:`wrench_one` hand its states, so that every loop here
(RK4 steps, inverse-dynamics samples, control updates) runs it too.

References
----------
.. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning and
   Control", Springer, 2009, §3.6 and §7.5. (docs/references.bib: siciliano2009)
.. [2] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §2.1.1 (Eqs. 2.1, 2.8) and §2.1.6 (Eq. 2.15). (docs/references.bib: rushton2022)
"""

from __future__ import annotations

import numpy as np
from numba import njit

from taut.dynamics._tree import (
    GIMBAL_LOCK,
    GIMBAL_TOL,
    JOINTED,
    OK,
    ZERO_LENGTH,
    _cholesky_solve,
    _cross,
    _mv,
    cable_path,
    tree_acceleration,
    tree_wrench,
)
from taut.geometry import rotate_about_axis
from taut.model import MAX_MAGNITUDE

#: Slices of the packed float parameters ``fp`` of the kernels.
FLOAT_LAYOUT = {
    "mass": slice(0, 1),
    "com": slice(1, 4),
    "inertia": slice(4, 13),
    "inertia_inv": slice(13, 22),
    "force": slice(22, 25),
    "moment": slice(25, 28),
    "T": slice(28, 37),
    "Tinv": slice(37, 46),
}


@njit(cache=True, nogil=True)
def _matTvec(A: np.ndarray, x: np.ndarray, out: np.ndarray) -> None:
    """``out = Aᵀ x`` for 3×3 ``A``."""
    for i in range(3):
        out[i] = A[0, i] * x[0] + A[1, i] * x[1] + A[2, i] * x[2]


#: Rows of 3-vectors and 3×3 matrices in a kernel's work buffer (no allocation per state).
VECTORS, MATRICES = 24, 3


@njit(cache=True, nogil=True)
def acceleration_one(
    ip: np.ndarray,
    fp: np.ndarray,
    cables: np.ndarray,
    elastic: bool,
    q: np.ndarray,
    qd: np.ndarray,
    u: np.ndarray,
    w: np.ndarray,
    qdd: np.ndarray,
    tau: np.ndarray,
    vec: np.ndarray,
    mat: np.ndarray,
) -> int:
    """``q̈`` of one state into ``qdd`` and the cable tensions into ``tau``; returns the status.
    ``u`` holds the tensions, or with ``elastic`` the unstretched lengths ``l0``.  The robot is
    packed in three arrays (few arguments: a call's cost is mostly its arguments' dispatch):
    ``ip = (kind, axis₁, axis₂, axis₃)``, ``fp = (m, c, I, I⁻¹, force, moment, T, T⁻¹)``
    (see :data:`FLOAT_LAYOUT`) and ``cables (n, 7)`` = exit point, anchor, ``EA``.  ``vec
    (VECTORS, 3)`` and ``mat (MATRICES, 3, 3)`` are work space.  A jointed platform
    (``ip[0] == JOINTED``) goes to :func:`taut.dynamics._tree.tree_acceleration`."""
    kind = ip[0]
    if kind == JOINTED:
        return tree_acceleration(ip, fp, cables, elastic, q, qd, u, w, qdd, tau)
    mass = fp[0]
    com, force, moment = fp[1:4], fp[22:25], fp[25:28]
    inertia, inertia_inv = fp[4:13].reshape((3, 3)), fp[13:22].reshape((3, 3))
    T, Tinv = fp[28:37].reshape((3, 3)), fp[37:46].reshape((3, 3))
    n = cables.shape[0]
    R, U, tmp = mat[0], mat[1], mat[2]
    omega, Edq, p, F, N, rc, b, v, arm, mom = (
        vec[0],
        vec[1],
        vec[2],
        vec[3],
        vec[4],
        vec[5],
        vec[6],
        vec[7],
        vec[8],
        vec[9],
    )
    t, td, cr = vec[10], vec[11], vec[12]
    for i in range(3):
        for j in range(3):
            R[i, j] = 1.0 if i == j else 0.0
    omega[:] = 0.0
    Edq[:] = 0.0
    d = 2 if kind == 1 or (kind == 0 and q.shape[0] == 2) else 3
    if kind == 1:
        c, s = np.cos(q[2]), np.sin(q[2])
        R[0, 0], R[0, 1], R[1, 0], R[1, 1] = c, -s, s, c
        omega[2] = qd[2]
    elif kind == 2:
        _mv(T, q[3:6], t)
        _mv(T, qd[3:6], td)
        for k in range(3):
            ax = ip[1 + k]
            for i in range(3):
                U[i, k] = R[i, ax]
            _cross(omega, U[:, k], cr)
            for i in range(3):
                Edq[i] += cr[i] * td[k]
                omega[i] += U[i, k] * td[k]
            rotate_about_axis(ax, t[k], R, tmp)
            R[:, :] = tmp
    p[:] = 0.0
    F[:] = 0.0
    N[:] = 0.0
    for i in range(d):
        p[i] = q[i]
        F[i] = force[i] + w[i]
    _mv(R, com, rc)
    if kind == 1:
        N[2] = moment[0] + w[2] + rc[0] * force[1] - rc[1] * force[0]
    elif kind == 2:
        _cross(rc, force, mom)
        for i in range(3):
            N[i] = moment[i] + w[3 + i] + mom[i]
    for i in range(n):
        _mv(R, cables[i, 3:6], arm)
        for j in range(3):
            b[j] = p[j] + arm[j]
        length = cable_path(cables[i], b, v)
        if length < 0.0:
            return ZERO_LENGTH
        if elastic:
            tau[i] = max(cables[i, 6] * (length - u[i]) / u[i], 0.0)
        else:
            tau[i] = u[i]
        for j in range(3):
            F[j] += tau[i] * v[j]
        _cross(arm, v, mom)
        for j in range(3):
            N[j] += tau[i] * mom[j]
    if kind == 0:
        for k in range(d):
            qdd[k] = F[k] / mass
        return OK
    wxr, wwr, nc = vec[13], vec[14], vec[15]
    _cross(rc, F, mom)
    for j in range(3):
        nc[j] = N[j] - mom[j]
    _cross(omega, rc, wxr)
    _cross(omega, wxr, wwr)
    if kind == 1:
        alpha = nc[2] / inertia[2, 2]
        qdd[0] = F[0] / mass + alpha * rc[1] - wwr[0]
        qdd[1] = F[1] / mass - alpha * rc[0] - wwr[1]
        qdd[2] = alpha
        return OK
    wb, h, gyro, nb, ab, alpha = vec[16], vec[17], vec[18], vec[19], vec[20], vec[21]
    _matTvec(R, omega, wb)
    _mv(inertia, wb, h)
    _cross(wb, h, gyro)
    _matTvec(R, nc, nb)
    for j in range(3):
        nb[j] -= gyro[j]
    _mv(inertia_inv, nb, ab)
    _mv(R, ab, alpha)
    _cross(rc, alpha, mom)
    for k in range(3):
        qdd[k] = F[k] / mass + mom[k] - wwr[k]
    det = (
        U[0, 0] * (U[1, 1] * U[2, 2] - U[1, 2] * U[2, 1])
        - U[0, 1] * (U[1, 0] * U[2, 2] - U[1, 2] * U[2, 0])
        + U[0, 2] * (U[1, 0] * U[2, 1] - U[1, 1] * U[2, 0])
    )
    if abs(det) < GIMBAL_TOL:
        return GIMBAL_LOCK
    # ẗ = U⁻¹ (α − Ė φ̇) by Cramer's rule: the rows of U⁻¹ are cross products of the
    # columns of U divided by det U
    rhs, tdd = vec[22], vec[23]
    for j in range(3):
        rhs[j] = alpha[j] - Edq[j]
    for k in range(3):
        a, c = (k + 1) % 3, (k + 2) % 3
        _cross(U[:, a], U[:, c], cr)
        tdd[k] = (cr[0] * rhs[0] + cr[1] * rhs[1] + cr[2] * rhs[2]) / det
    _mv(Tinv, tdd, qdd[3:6])
    return OK


@njit(cache=True, nogil=True)
def accelerations(
    ip: np.ndarray,
    fp: np.ndarray,
    cables: np.ndarray,
    elastic: bool,
    q: np.ndarray,
    qd: np.ndarray,
    u: np.ndarray,
    w: np.ndarray,
    qdd: np.ndarray,
    tau: np.ndarray,
    status: np.ndarray,
) -> None:
    """:func:`acceleration_one` over ``N`` states: ``q, qd, qdd (N, dof)``, ``u, tau (N, n)``,
    ``w (N, dof)``, ``status (N,)``."""
    vec, mat = np.empty((VECTORS, 3)), np.empty((MATRICES, 3, 3))
    for k in range(q.shape[0]):
        status[k] = acceleration_one(ip, fp, cables, elastic, q[k], qd[k], u[k], w[k], qdd[k], tau[k], vec, mat)


@njit(cache=True, nogil=True)
def rk4_steps(
    ip: np.ndarray,
    fp: np.ndarray,
    cables: np.ndarray,
    elastic: bool,
    q: np.ndarray,
    qd: np.ndarray,
    u: np.ndarray,
    w: np.ndarray,
    dt: float,
    q_out: np.ndarray,
    qd_out: np.ndarray,
    status: np.ndarray,
) -> None:
    """One classical Runge–Kutta step of ``dt`` for each of ``N`` states, the inputs ``u`` and
    ``w`` held over the step; a failing stage leaves the state unchanged and sets its status."""
    dof = q.shape[1]
    st = np.empty((8, dof))
    a1, a2, a3, a4, x, v2, v3, v4 = st[0], st[1], st[2], st[3], st[4], st[5], st[6], st[7]
    tau = np.empty(cables.shape[0])
    vec, mat = np.empty((VECTORS, 3)), np.empty((MATRICES, 3, 3))
    h = 0.5 * dt
    for k in range(q.shape[0]):
        q0, v = q[k], qd[k]
        uk, wk = u[k], w[k]
        s = acceleration_one(ip, fp, cables, elastic, q0, v, uk, wk, a1, tau, vec, mat)
        if s == OK:
            for j in range(dof):
                x[j] = q0[j] + h * v[j]
                v2[j] = v[j] + h * a1[j]
            s = acceleration_one(ip, fp, cables, elastic, x, v2, uk, wk, a2, tau, vec, mat)
        if s == OK:
            for j in range(dof):
                x[j] = q0[j] + h * v2[j]
                v3[j] = v[j] + h * a2[j]
            s = acceleration_one(ip, fp, cables, elastic, x, v3, uk, wk, a3, tau, vec, mat)
        if s == OK:
            for j in range(dof):
                x[j] = q0[j] + dt * v3[j]
                v4[j] = v[j] + dt * a3[j]
            s = acceleration_one(ip, fp, cables, elastic, x, v4, uk, wk, a4, tau, vec, mat)
        status[k] = s
        for j in range(dof):
            if s == OK:
                q_out[k, j] = q0[j] + dt / 6.0 * (v[j] + 2.0 * v2[j] + 2.0 * v3[j] + v4[j])
                qd_out[k, j] = v[j] + dt / 6.0 * (a1[j] + 2.0 * a2[j] + 2.0 * a3[j] + a4[j])
            else:
                q_out[k, j] = q0[j]
                qd_out[k, j] = v[j]


@njit(cache=True, nogil=True)
def wrench_one(
    ip: np.ndarray,
    fp: np.ndarray,
    cables: np.ndarray,
    q: np.ndarray,
    qd: np.ndarray,
    qdd: np.ndarray,
    w_ext: np.ndarray,
    wrench: np.ndarray,
    W: np.ndarray,
    vec: np.ndarray,
    mat: np.ndarray,
) -> int:
    """The wrench ``W τ`` the cables must apply for the sample ``(q, q̇, q̈)`` into ``wrench``
    (the rate of momentum about ``p`` minus the weight, the constant load and ``w_ext``;
    Newton–Euler through the centre of mass) and the structure matrix of the cables
    into ``W (dof, n)``; returns the status (:data:`ZERO_LENGTH` for a cable without direction).
    A jointed platform goes to :func:`taut.dynamics._tree.tree_wrench`."""
    kind = ip[0]
    if kind == JOINTED:
        return tree_wrench(ip, fp, cables, q, qd, qdd, w_ext, wrench, W)
    mass = fp[0]
    com, force, moment = fp[1:4], fp[22:25], fp[25:28]
    inertia = fp[4:13].reshape((3, 3))
    T = fp[28:37].reshape((3, 3))
    R, U, tmp = mat[0], mat[1], mat[2]
    omega, alpha, p, rc, ac, wxr, cr, t, td, tdd, arm, b, v, mom, h, Ia = (
        vec[0],
        vec[1],
        vec[2],
        vec[3],
        vec[4],
        vec[5],
        vec[6],
        vec[7],
        vec[8],
        vec[9],
        vec[10],
        vec[11],
        vec[12],
        vec[13],
        vec[14],
        vec[15],
    )
    for i in range(3):
        omega[i] = 0.0
        alpha[i] = 0.0
        p[i] = 0.0
        ac[i] = 0.0
        for j in range(3):
            R[i, j] = 1.0 if i == j else 0.0
    d = 2 if kind == 1 or (kind == 0 and q.shape[0] == 2) else 3
    for i in range(d):
        p[i] = q[i]
        ac[i] = qdd[i]
    if kind == 1:
        c, s = np.cos(q[2]), np.sin(q[2])
        R[0, 0], R[0, 1], R[1, 0], R[1, 1] = c, -s, s, c
        omega[2], alpha[2] = qd[2], qdd[2]
    elif kind == 2:
        _mv(T, q[3:6], t)
        _mv(T, qd[3:6], td)
        _mv(T, qdd[3:6], tdd)
        for k in range(3):
            ax = ip[1 + k]
            for i in range(3):
                U[i, k] = R[i, ax]
            # α = Σ uₖ ẗₖ + (Σ_{j<k} uⱼ ṫⱼ) × uₖ ṫₖ
            _cross(omega, U[:, k], cr)
            for i in range(3):
                alpha[i] += U[i, k] * tdd[k] + cr[i] * td[k]
                omega[i] += U[i, k] * td[k]
            rotate_about_axis(ax, t[k], R, tmp)
            R[:, :] = tmp
    _mv(R, com, rc)
    if kind != 0:
        _cross(alpha, rc, cr)
        _cross(omega, rc, wxr)
        _cross(omega, wxr, mom)
        for i in range(3):
            ac[i] += cr[i] + mom[i]
    for i in range(d):
        wrench[i] = mass * ac[i] - force[i] - w_ext[i]
    if kind != 0:
        # N = I_c α + ω × I_c ω + r × m a_c − r × f₀ − moment, with I_c = R I Rᵀ
        _matTvec(R, omega, b)
        _mv(inertia, b, v)
        _mv(R, v, h)
        _matTvec(R, alpha, b)
        _mv(inertia, b, v)
        _mv(R, v, Ia)
        _cross(omega, h, cr)
        for i in range(3):
            v[i] = mass * ac[i] - force[i]
        _cross(rc, v, mom)
        if kind == 1:
            wrench[2] = Ia[2] + cr[2] + mom[2] - moment[0] - w_ext[2]
        else:
            for i in range(3):
                wrench[3 + i] = Ia[i] + cr[i] + mom[i] - moment[i] - w_ext[3 + i]
    for i in range(cables.shape[0]):
        _mv(R, cables[i, 3:6], arm)
        for j in range(3):
            b[j] = p[j] + arm[j]
        length = cable_path(cables[i], b, v)
        if length < 0.0:
            return ZERO_LENGTH
        for j in range(d):
            W[j, i] = v[j]
        if kind != 0:
            _cross(arm, v, mom)
            if kind == 1:
                W[2, i] = mom[2]
            else:
                for j in range(3):
                    W[3 + j, i] = mom[j]
    return OK


@njit(cache=True, nogil=True)
def closed_form_one(
    W: np.ndarray, wrench: np.ndarray, tmin: np.ndarray, tmax: np.ndarray, rtol: float, tau: np.ndarray, G: np.ndarray
) -> bool:
    """The closed-form distribution of Pott, Bruckmann and Mikelsons (2009): ``τ = τm + Wᵀ
    (W Wᵀ)⁻¹ (wrench − W τm)``, ``τm`` the middle of the bounds (``τ_min`` without an upper
    bound; zero, within its bounds, for a joint actuator unbounded below), by a Cholesky
    factorization of ``W Wᵀ`` (``G`` is work space ``(dof, dof)``).
    True when ``W`` has full row rank and ``τ`` is within the bounds with ``‖W τ − wrench‖∞ ≤
    rtol · max(‖wrench‖∞, max|W| ‖τ‖∞)`` (the acceptance test of :mod:`taut.statics._tension`)."""
    m, n = W.shape
    for i in range(n):
        lo, hi = tmin[i], tmax[i]
        if np.isfinite(lo) and np.isfinite(hi):
            tau[i] = 0.5 * (lo + hi)
        elif np.isfinite(lo):
            tau[i] = max(lo, 0.0)
        else:  # a joint actuator unbounded below: about no force, within its bound
            tau[i] = min(hi, 0.0) if np.isfinite(hi) else 0.0
    y = np.empty(m)
    for r in range(m):
        acc = wrench[r]
        for i in range(n):
            acc -= W[r, i] * tau[i]
        y[r] = acc
        for c in range(r + 1):
            g = 0.0
            for i in range(n):
                g += W[r, i] * W[c, i]
            G[r, c] = g
    if not _cholesky_solve(G, y):  # G = L Lᵀ in place (lower triangle), then L Lᵀ y = r
        return False
    wmax, tmaxabs, Wmax = 0.0, 0.0, 0.0
    for i in range(n):
        acc = 0.0
        for r in range(m):
            acc += W[r, i] * y[r]
            Wmax = max(Wmax, abs(W[r, i]))
        tau[i] += acc
        if not (tau[i] >= tmin[i] and tau[i] <= tmax[i]):
            return False
        tmaxabs = max(tmaxabs, abs(tau[i]))
    res = 0.0
    for r in range(m):
        acc = -wrench[r]
        wmax = max(wmax, abs(wrench[r]))
        for i in range(n):
            acc += W[r, i] * tau[i]
        res = max(res, abs(acc))
    return res <= rtol * max(wmax, Wmax * tmaxabs)


@njit(cache=True, nogil=True)
def inverse_samples(
    ip: np.ndarray,
    fp: np.ndarray,
    cables: np.ndarray,
    closed_form: bool,
    q: np.ndarray,
    qd: np.ndarray,
    qdd: np.ndarray,
    w_ext: np.ndarray,
    tmin: np.ndarray,
    tmax: np.ndarray,
    rtol: float,
    wrench: np.ndarray,
    W: np.ndarray,
    tau: np.ndarray,
    status: np.ndarray,
) -> None:
    """:func:`wrench_one` over ``N`` samples, and with ``closed_form`` :func:`closed_form_one`:
    ``status`` 0 solved by the closed form, 1 not solved here (to the caller), :data:`ZERO_LENGTH`
    no structure matrix."""
    vec, mat = np.empty((VECTORS, 3)), np.empty((MATRICES, 3, 3))
    G = np.empty((W.shape[1], W.shape[1]))
    for k in range(q.shape[0]):
        s = wrench_one(ip, fp, cables, q[k], qd[k], qdd[k], w_ext[k], wrench[k], W[k], vec, mat)
        if s != OK:
            status[k] = s
        elif closed_form and closed_form_one(W[k], wrench[k], tmin, tmax, rtol, tau[k], G):
            status[k] = 0
        else:
            status[k] = 1


@njit(cache=True, nogil=True)
def control_updates(
    ip_plant: np.ndarray,
    fp_plant: np.ndarray,
    ip_model: np.ndarray,
    fp_model: np.ndarray,
    cables: np.ndarray,
    start: int,
    stop: int,
    time: np.ndarray,
    ref: np.ndarray,
    mid: np.ndarray,
    gains: np.ndarray,
    angles: np.ndarray,
    predict: bool,
    disturbance: np.ndarray,
    tmin: np.ndarray,
    tmax: np.ndarray,
    rtol: float,
    state: np.ndarray,
    last: np.ndarray,
    Q: np.ndarray,
    V: np.ndarray,
    E: np.ndarray,
    A: np.ndarray,
    T: np.ndarray,
) -> int:
    """Control updates ``start, start + 1, …, stop − 1`` of :func:`taut.dynamics.simulate_control`
    while the closed-form distribution (:func:`closed_form_one`) succeeds: the law
    ``q̈_cmd = q̈_r + K_d ė + K_p e`` (angle errors wrapped into ``[−π, π)``; with ``predict``
    evaluated at the state predicted half a period ahead with the acceleration measured over the
    last period), the controller model's wrench
    (:func:`wrench_one`), its tensions held over ``disturbance.shape[1]`` RK4 steps of the
    plant.  ``ref`` ``(3, K + 1, dof)``, ``mid`` ``(3, K, dof)``: reference pose, velocity, acceleration at
    the updates and at the middle of each period; ``gains (2, dof)`` = ``K_p``, ``K_d``;
    ``angles`` the first and last + 1 angle columns; ``disturbance (K + 1, substeps, dof)``;
    ``state`` rows 0 and 1 = ``(q, q̇)``, advanced in place; ``last (n,)`` the tensions held.
    Fills row ``k`` of ``Q, V, E, A (K + 1, dof)`` and ``T (K + 1, n)``.  Returns ``stop``
    when done, else the update to redo outside (the state is that of its start)."""
    K = time.shape[0] - 1
    dof, n = state.shape[1], cables.shape[0]
    vec, mat = np.empty((VECTORS, 3)), np.empty((MATRICES, 3, 3))
    G = np.empty((dof, dof))
    W = np.empty((dof, n))
    wrench, tau = np.empty(dof), np.empty(n)
    qc, qdc, cmdc, zero = np.empty(dof), np.empty(dof), np.empty(dof), np.zeros(dof)
    q2, qd2, u2, w2 = np.empty((1, dof)), np.empty((1, dof)), np.empty((1, n)), np.empty((1, dof))
    qn, qdn, status = np.empty((1, dof)), np.empty((1, dof)), np.zeros(1, np.int64)
    two_pi = 2.0 * np.pi
    for k in range(start, stop):
        q, qd = state[0], state[1]
        for j in range(dof):
            e = ref[0, k, j] - q[j]
            if angles[0] <= j < angles[1]:
                e = (e + np.pi) % two_pi - np.pi
            E[k, j] = e
            A[k, j] = ref[2, k, j] + gains[1, j] * (ref[1, k, j] - qd[j]) + gains[0, j] * e
            qc[j], qdc[j], cmdc[j] = q[j], qd[j], A[k, j]
        if predict and k < K:
            h2 = 0.5 * (time[k + 1] - time[k])
            for j in range(dof):
                # the acceleration of the last period, measured (the commanded one at the start)
                a = A[k, j] if k == 0 else (qd[j] - V[k - 1, j]) / (time[k] - time[k - 1])
                qc[j] = q[j] + h2 * qd[j] + 0.5 * h2 * h2 * a
                qdc[j] = qd[j] + h2 * a
                e = mid[0, k, j] - qc[j]
                if angles[0] <= j < angles[1]:
                    e = (e + np.pi) % two_pi - np.pi
                cmdc[j] = mid[2, k, j] + gains[1, j] * (mid[1, k, j] - qdc[j]) + gains[0, j] * e
        if wrench_one(ip_model, fp_model, cables, qc, qdc, cmdc, zero, wrench, W, vec, mat) != OK:
            return k
        if not closed_form_one(W, wrench, tmin, tmax, rtol, tau, G):
            return k
        for j in range(dof):
            Q[k, j], V[k, j] = q[j], qd[j]
        for i in range(n):
            T[k, i] = tau[i]
        if k == K:
            for i in range(n):
                last[i] = tau[i]
            return stop
        substeps = disturbance.shape[1]
        h = (time[k + 1] - time[k]) / substeps
        for j in range(dof):
            q2[0, j], qd2[0, j] = q[j], qd[j]
        for i in range(n):
            u2[0, i] = tau[i]
        for s in range(substeps):
            for j in range(dof):
                w2[0, j] = disturbance[k, s, j]
            rk4_steps(ip_plant, fp_plant, cables, False, q2, qd2, u2, w2, h, qn, qdn, status)
            if status[0] != OK:
                return k
            for j in range(dof):
                q2[0, j], qd2[0, j] = qn[0, j], qdn[0, j]
        for j in range(dof):
            if not (np.isfinite(q2[0, j]) and np.isfinite(qd2[0, j]) and abs(q2[0, j]) <= MAX_MAGNITUDE):
                return k
        for j in range(dof):
            state[0, j], state[1, j] = q2[0, j], qd2[0, j]
        for i in range(n):
            last[i] = tau[i]
    return stop
