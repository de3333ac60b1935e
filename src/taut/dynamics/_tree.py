"""Compiled dynamics of a platform carrying jointed bodies: a tree of rigid bodies on
prismatic and revolute joints, the platform its root.

The equations are those of :mod:`taut.dynamics._jointed` in the twist coordinates
``X = (ṗ, ω, q̇_J)`` (the velocity of the reference point ``p``, the platform's angular
velocity in the fixed frame, the joint rates; planar: ``(ṗ, θ̇, q̇_J)``), one state at a time
and without allocating per body: the body frames from the platform outwards, the Jacobian
``J_b`` of each body's centre-of-mass velocity and angular velocity, the velocity-product
accelerations ``J̇_b X`` by the outward recursion, and

    ``M_X Ẋ + h_X = A τ + w``,
    ``M_X = Σ_b J_bᵀ diag(m_b 1, R_b I_b R_bᵀ) J_b``,
    ``h_X = Σ_b J_bᵀ (m_b a_b − F_b, I_b^w α_b + ω_b × I_b^w ω_b) − J_0ᵀ (0, n_0)``

(Featherstone 2008, §3.2 and §5.3, a tree's joint-space inertia from its bodies' Jacobians;
Siciliano et al. 2009, §7.2), with ``A`` the cable columns of the jointed structure matrix
(Lieskovský 2020, Eqs. 3.3.7–3.3.12: ``u_i`` and ``(b_i − p) × u_i`` on the platform rows,
``u_i · ∂b_i/∂q_j`` on the rows of the joints between the cable's body and the platform) and
``w`` an external generalized force (a wrench on the platform about ``p``, then joint forces).
Forward dynamics solves for ``Ẋ`` by a Cholesky factorization of ``M_X``; inverse dynamics
evaluates ``M_X Ẋ + h_X − w``.  The orientation angles follow from ``α = E φ̈ + Ė φ̇``
(:mod:`taut.geometry._rates`), as for a platform without joints
(:mod:`taut.dynamics._kernels`).

Robot data, packed for the kernels (:func:`taut.dynamics._forward.kernel_model`):
``ip = (JOINTED, axis₁, axis₂, axis₃, platform kind, n_joints, parents…, revolute…, n_via)``,
``fp`` the platform's floats (:data:`PLATFORM_FLOATS`, the layout of
:data:`taut.dynamics._kernels.FLOAT_LAYOUT`) then :data:`BODY_FLOATS` per body (joint axis
and origin in the parent frame, mass, centre of mass, inertia, constant force), then
:data:`VIA_FLOATS` per via point of a routed cable (``cables[].via``, in cable order: a chain
of straight segments whose length is their sum, and whose tension pulls each via point on a
moving body towards both its neighbours, Lau, Oetomo & Halgamuge 2013), and
``cables (n, CABLE_COLUMNS)``: exit point, anchor, ``EA``, the body the anchor is on, and
the axis and radius of a swivelling pulley (:func:`cable_path`).  A row whose body is
``−(j + 1)`` is the actuator of joint ``j`` (:data:`ACTUATOR`): its column of ``A`` is the unit
column of that joint's coordinate, its input the force it exerts (also under ``elastic``), so
that joint actuators enter the distribution as extra columns of the structure matrix with their
bounds (Lau, Oetomo & Halgamuge 2013).

Status per state: :data:`OK`, :data:`GIMBAL_LOCK` (the rate matrix is singular),
:data:`ZERO_LENGTH` (a cable without direction), :data:`SINGULAR_INERTIA` (``M_X`` is not
positive definite: a massless body or one whose inertia about its joint axis vanishes).

References
----------
.. [1] R. Featherstone, "Rigid Body Dynamics Algorithms", Springer, 2008, §3.2 (the
   joint-space inertia matrix), §5.3 (the recursive Newton–Euler velocity-product terms).
   (docs/references.bib: featherstone2008)
.. [2] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning and
   Control", Springer, 2009, §7.1–7.2. (docs/references.bib: siciliano2009)
.. [3] A. Pott, "Cable-Driven Parallel Robots: Theory and Application", Springer Tracts in
   Advanced Robotics 120, Springer, 2018, pulley kinematics. (docs/references.bib: pott2018)
.. [4] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, §3.3, Eqs. 3.3.7–3.3.12.
   (docs/references.bib: lieskovsky2020)
.. [5] D. Lau, D. Oetomo, S. K. Halgamuge, "Generalized modeling of multilink cable-driven
   manipulators with arbitrary routing using the cable-routing matrix", IEEE Transactions on
   Robotics 29(5), 2013 (cables and joint actuators in the joint-space equations of motion).
   (docs/references.bib: lau2013)
"""

from __future__ import annotations

import numpy as np
from numba import njit

from taut.geometry import rotate_about_axis
from taut.kinematics import MIN_LENGTH

__all__ = [
    "ACTUATOR",
    "BODY_FLOATS",
    "CABLE_COLUMNS",
    "GIMBAL_LOCK",
    "GIMBAL_TOL",
    "JOINTED",
    "OK",
    "PLATFORM_FLOATS",
    "SINGULAR_INERTIA",
    "SWIVEL_TOL",
    "VIA_FLOATS",
    "ZERO_LENGTH",
    "cable_path",
    "tree_acceleration",
    "tree_wrench",
]

OK, GIMBAL_LOCK, ZERO_LENGTH, SINGULAR_INERTIA = 0, 1, 2, 3

#: ``ip[0]`` of a jointed platform (after the point-mass, planar and spatial kinds 0–2).
JOINTED = 3
#: The platform's floats at the start of ``fp``; each body's follow.
PLATFORM_FLOATS = 46
#: Per body: joint axis (3, unit, parent frame), joint origin (3), mass, centre of mass (3),
#: inertia about it (9, body frame), constant force at it (3, fixed frame).
BODY_FLOATS = 22
#: Per via point of a routed cable, after the bodies' floats: its cable, its body (−1: the
#: fixed frame) and the point (3, in that body's frame).
VIA_FLOATS = 5
#: ``cables[i, 7]`` of joint ``j``'s actuator is ``ACTUATOR − j``.
ACTUATOR = -1
#: Columns of ``cables``: exit point (3), anchor (3, in its body's frame), ``EA``, body index,
#: swivel axis (3, unit) and pulley radius (0: a fixed exit point).
CABLE_COLUMNS = 12
#: Relative tolerance of a swivelling pulley's singular configurations (the anchor on the
#: swivel axis, or on the pulley circle), as :mod:`taut.kinematics._swivel` takes them.
SWIVEL_TOL = 1e-9

#: Below this ``|det U|`` the rate matrix counts as singular (gimbal lock).
GIMBAL_TOL = 1e-9


@njit(cache=True, nogil=True)
def _cross(a: np.ndarray, b: np.ndarray, out: np.ndarray) -> None:
    x = a[1] * b[2] - a[2] * b[1]
    y = a[2] * b[0] - a[0] * b[2]
    z = a[0] * b[1] - a[1] * b[0]
    out[0], out[1], out[2] = x, y, z


@njit(cache=True, nogil=True)
def _mv(A: np.ndarray, x: np.ndarray, out: np.ndarray) -> None:
    """``out = A x`` for 3×3 ``A`` (loops: a BLAS call costs more than the product)."""
    for i in range(3):
        out[i] = A[i, 0] * x[0] + A[i, 1] * x[1] + A[i, 2] * x[2]


@njit(cache=True, nogil=True)
def _mm(A: np.ndarray, B: np.ndarray, out: np.ndarray) -> None:
    """``out = A B`` for 3×3 matrices."""
    for i in range(3):
        for j in range(3):
            out[i, j] = A[i, 0] * B[0, j] + A[i, 1] * B[1, j] + A[i, 2] * B[2, j]


@njit(cache=True, nogil=True)
def _rodrigues(k: np.ndarray, angle: float, out: np.ndarray) -> None:
    """``out`` = the rotation by ``angle`` about the unit axis ``k``."""
    s, c = np.sin(angle), np.cos(angle)
    C = 1.0 - c
    out[0, 0], out[0, 1], out[0, 2] = c + k[0] * k[0] * C, k[0] * k[1] * C - k[2] * s, k[0] * k[2] * C + k[1] * s
    out[1, 0], out[1, 1], out[1, 2] = k[1] * k[0] * C + k[2] * s, c + k[1] * k[1] * C, k[1] * k[2] * C - k[0] * s
    out[2, 0], out[2, 1], out[2, 2] = k[2] * k[0] * C - k[1] * s, k[2] * k[1] * C + k[0] * s, c + k[2] * k[2] * C


@njit(cache=True, nogil=True)
def cable_path(cable: np.ndarray, anchor: np.ndarray, u: np.ndarray) -> float:
    """The length of a cable (a row of ``cables``) to the anchor ``b`` in the fixed frame, and
    into ``u`` its unit direction at the anchor; −1 where it has none (a zero length, an anchor
    on the swivel axis or on the pulley).

    A straight cable runs to its exit point ``a``: ``l = ‖a − b‖``, ``u = (a − b)/l``.  A cable
    through a swivelling pulley (axis ``k``, radius ``r``, running onto it at ``a``) wraps the
    arc ``β`` and leaves at the tangent point ``C``: with ``v = b − a``, ``h = v·k``, ``w = v −
    h k``, ``d = ‖w‖``, ``e = w/d``, ``x = d − r`` and the free length ``l_f = √(x² + h² −
    r²)``, ``β = atan2(x, h) + atan2(r, l_f)`` in ``[0, 2π)``, ``C = a + r e + r (−cos β e +
    sin β k)``, ``l = r β + l_f`` and ``u = (C − b)/l_f``, since ``∂l/∂b = (b − C)/l_f`` (Pott
    2018; :mod:`taut.kinematics._swivel`).  The pulley's own inertia is neglected."""
    r = cable[11]
    if r == 0.0:
        for j in range(3):
            u[j] = cable[j] - anchor[j]
        length = np.sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2])
        if length < MIN_LENGTH:
            return -1.0
        for j in range(3):
            u[j] /= length
        return length
    k = cable[8:11]
    h, vv = 0.0, 0.0
    for j in range(3):
        v = anchor[j] - cable[j]
        h += v * k[j]
        vv += v * v
    ww = 0.0
    for j in range(3):
        w = anchor[j] - cable[j] - h * k[j]
        ww += w * w
        u[j] = w
    dist = np.sqrt(ww)
    scale = r + np.sqrt(vv)
    if dist <= SWIVEL_TOL * scale:
        return -1.0
    x = dist - r
    free = np.sqrt(max(x * x + h * h - r * r, 0.0))
    if free <= SWIVEL_TOL * scale or free < MIN_LENGTH:
        return -1.0
    wrap = np.arctan2(x, h) + np.arctan2(r, free)
    if wrap < 0.0:
        wrap += 2.0 * np.pi
    c, s = np.cos(wrap), np.sin(wrap)
    for j in range(3):
        e = u[j] / dist
        u[j] = (cable[j] + r * e + r * (-c * e + s * k[j]) - anchor[j]) / free
    return r * wrap + free


@njit(cache=True, nogil=True)
def _offsets(b: int) -> tuple[int, int, int, int]:
    """Where body ``b``'s mass, centre of mass, inertia and force start in ``fp``."""
    if b == 0:
        return 0, 1, 4, 22
    base = PLATFORM_FLOATS + (b - 1) * BODY_FLOATS
    return base + 6, base + 7, base + 10, base + 19


@njit(cache=True, nogil=True)
def tree_terms(
    ip: np.ndarray,
    fp: np.ndarray,
    cables: np.ndarray,
    q: np.ndarray,
    qd: np.ndarray,
    M: np.ndarray,
    h: np.ndarray,
    A: np.ndarray,
    lengths: np.ndarray,
    U: np.ndarray,
    Edq: np.ndarray,
) -> int:
    """``M_X (P, P)``, ``h_X (P,)`` and the cable columns ``A (P, n)`` at the state
    ``(q, q̇)``, the cable lengths ``(n,)``, and the platform's ``E = U T`` factor ``U`` and
    ``Ė φ̇`` (spatial); returns :data:`OK` or :data:`ZERO_LENGTH`."""
    pk, nj = ip[4], ip[5]
    B = nj + 1
    d = 2 if pk == 1 else 3
    m = 3 if pk == 1 else 6
    P = m + nj
    pos, rot = np.zeros((B, 3)), np.zeros((B, 3, 3))
    axes, coms = np.zeros((B, 3)), np.zeros((B, 3))
    omega, alpha, oacc, ovel = np.zeros((B, 3)), np.zeros((B, 3)), np.zeros((B, 3)), np.zeros((B, 3))
    J = np.zeros((B, 6, P))
    beyond = np.zeros((B, B), np.bool_)
    v3, v4, v5, tmp = np.empty(3), np.empty(3), np.empty(3), np.empty((3, 3))
    R0 = rot[0]
    for i in range(3):
        R0[i, i] = 1.0
        Edq[i] = 0.0
    for i in range(d):
        pos[0, i] = q[i]
    if pk == 1:
        c, s = np.cos(q[2]), np.sin(q[2])
        R0[0, 0], R0[0, 1], R0[1, 0], R0[1, 1] = c, -s, s, c
        omega[0, 2] = qd[2]
    else:
        t, td = np.empty(3), np.empty(3)
        _mv(fp[28:37].reshape((3, 3)), q[3:6], t)
        _mv(fp[28:37].reshape((3, 3)), qd[3:6], td)
        for k in range(3):
            ax = ip[1 + k]
            for i in range(3):
                U[i, k] = R0[i, ax]
            _cross(omega[0], U[:, k], v3)
            for i in range(3):
                Edq[i] += v3[i] * td[k]
                omega[0, i] += U[i, k] * td[k]
            rotate_about_axis(ax, t[k], R0, tmp)
            R0[:, :] = tmp
    for i in range(d):
        ovel[0, i] = qd[i]
    for k in range(1, B):
        par = ip[5 + k]
        revolute = ip[5 + nj + k] == 1
        base = PLATFORM_FLOATS + (k - 1) * BODY_FLOATS
        local, origin = fp[base : base + 3], fp[base + 3 : base + 6]
        _mv(rot[par], local, axes[k])
        qk, qdk = q[m + k - 1], qd[m + k - 1]
        if revolute:
            _mv(rot[par], origin, v3)
            _rodrigues(local, qk, tmp)
            _mm(rot[par], tmp, rot[k])
        else:
            for i in range(3):
                v4[i] = origin[i] + qk * local[i]
            _mv(rot[par], v4, v3)
            rot[k] = rot[par]
        pos[k] = pos[par] + v3
        j = k
        while j != 0:
            beyond[k, j] = True
            j = ip[5 + j]
        # the velocity-product recursion: ω, α, and the origin's velocity and acceleration
        e = axes[k]
        arm = pos[k] - pos[par]
        _cross(omega[par], e, v3)  # ė
        _cross(omega[par], arm, v4)  # the arm's rate, without the joint's own
        _cross(alpha[par], arm, v5)
        omega[k], alpha[k] = omega[par], alpha[par]
        oacc[k] = oacc[par] + v5
        if revolute:
            omega[k] += e * qdk
            alpha[k] += v3 * qdk
        else:
            v4 += e * qdk
            oacc[k] += v3 * qdk
        _cross(omega[par], v4, v5)
        oacc[k] += v5
        ovel[k] = ovel[par] + v4
    for i in range(P):
        h[i] = 0.0
        for j in range(P):
            M[i, j] = 0.0
    IJ = np.empty((3, P))
    f, n_, Iw, anchor = np.empty(3), np.empty(3), np.empty((3, 3)), np.empty(3)
    for b in range(B):
        om, oc, oi, of = _offsets(b)
        mass = fp[om]
        I = fp[oi : oi + 9].reshape((3, 3))
        _mv(rot[b], fp[oc : oc + 3], v3)
        coms[b] = pos[b] + v3
        r = coms[b] - pos[0]
        Jb = J[b]
        for i in range(d):
            Jb[i, i] = 1.0
        if pk == 1:
            Jb[0, 2], Jb[1, 2], Jb[5, 2] = -r[1], r[0], 1.0
        else:
            for c in range(3):
                # e_c × r
                Jb[(c + 1) % 3, 3 + c] = -r[(c + 2) % 3]
                Jb[(c + 2) % 3, 3 + c] = r[(c + 1) % 3]
                Jb[3 + c, 3 + c] = 1.0
        for j in range(1, B):
            if not beyond[b, j]:
                continue
            col = m + j - 1
            if ip[5 + nj + j] == 1:
                _cross(axes[j], coms[b] - pos[j], v3)
                for i in range(3):
                    Jb[i, col] = v3[i]
                    Jb[3 + i, col] = axes[j, i]
            else:
                for i in range(3):
                    Jb[i, col] = axes[j, i]
        _mm(rot[b], I, tmp)
        for i in range(3):
            for j in range(3):
                Iw[i, j] = tmp[i, 0] * rot[b, j, 0] + tmp[i, 1] * rot[b, j, 1] + tmp[i, 2] * rot[b, j, 2]
        rho = coms[b] - pos[b]
        _cross(omega[b], rho, v3)
        _cross(omega[b], v3, v4)
        _cross(alpha[b], rho, v5)
        force = fp[of : of + 3]
        for i in range(3):
            f[i] = mass * (oacc[b, i] + v5[i] + v4[i]) - force[i]
        _mv(Iw, omega[b], v4)
        _cross(omega[b], v4, v3)
        _mv(Iw, alpha[b], n_)
        n_ += v3
        for i in range(3):
            for c in range(P):
                IJ[i, c] = Iw[i, 0] * Jb[3, c] + Iw[i, 1] * Jb[4, c] + Iw[i, 2] * Jb[5, c]
        for a in range(P):
            acc = 0.0
            for i in range(3):
                acc += Jb[i, a] * f[i] + Jb[3 + i, a] * n_[i]
            h[a] += acc
            for c in range(a, P):
                s = 0.0
                for i in range(3):
                    s += mass * Jb[i, a] * Jb[i, c] + Jb[3 + i, a] * IJ[i, c]
                M[a, c] += s
    for a in range(P):
        for c in range(a + 1, P):
            M[c, a] = M[a, c]
    # the platform's constant moment (planar: about z, stored first)
    if pk == 1:
        h[2] -= fp[25]
    else:
        for i in range(3):
            h[3 + i] -= fp[25 + i]
    n_via = ip[6 + 2 * nj]
    vias = fp[PLATFORM_FLOATS + nj * BODY_FLOATS :].reshape((n_via, VIA_FLOATS))
    world = np.empty((n_via, 3))
    row, prev, f = np.empty(CABLE_COLUMNS), np.empty(3), np.empty(3)
    first = 0  # the cable's first via row (the rows are in cable order)
    for i in range(cables.shape[0]):
        body = int(cables[i, 7])
        if body < 0:
            # a joint actuator: its force is the generalized force of its joint's coordinate
            for j in range(P):
                A[j, i] = 0.0
            A[m - body - 1, i] = 1.0
            lengths[i] = 0.0
            continue
        _mv(rot[body], cables[i, 3:6], anchor)
        anchor += pos[body]
        row[:] = cables[i]
        last = first
        while last < n_via and int(vias[last, 0]) == i:
            last += 1
        # a routed cable's chain up to its last via point, whose straight segment ends at the anchor
        chain = 0.0
        prev[:] = cables[i, :3]
        for v in range(first, last):
            b = int(vias[v, 1])
            if b < 0:
                world[v] = vias[v, 2:5]
            else:
                _mv(rot[b], vias[v, 2:5], world[v])
                world[v] += pos[b]
            seg = np.sqrt(np.sum((world[v] - prev) ** 2))
            if seg < MIN_LENGTH:
                return ZERO_LENGTH
            chain += seg
            prev[:] = world[v]
        row[:3] = prev
        length = cable_path(row, anchor, v3)
        if length < 0.0:
            return ZERO_LENGTH
        lengths[i] = length + chain
        for j in range(P):
            A[j, i] = 0.0
        _add_point_column(A, i, body, anchor, v3, pos, axes, beyond, ip, m, d, pk, v4, v5)
        for v in range(first, last):
            b = int(vias[v, 1])
            if b < 0:
                continue
            # pulled towards both its neighbours along the chain
            before = cables[i, :3] if v == first else world[v - 1]
            after = anchor if v == last - 1 else world[v + 1]
            f[:] = (before - world[v]) / np.sqrt(np.sum((before - world[v]) ** 2))
            f += (after - world[v]) / np.sqrt(np.sum((after - world[v]) ** 2))
            _add_point_column(A, i, b, world[v], f, pos, axes, beyond, ip, m, d, pk, v4, v5)
        first = last
    return OK


@njit(cache=True, nogil=True)
def _add_point_column(
    A: np.ndarray,
    i: int,
    body: int,
    point: np.ndarray,
    f: np.ndarray,
    pos: np.ndarray,
    axes: np.ndarray,
    beyond: np.ndarray,
    ip: np.ndarray,
    m: int,
    d: int,
    pk: int,
    v4: np.ndarray,
    v5: np.ndarray,
) -> None:
    """Add to cable ``i``'s column of ``A`` the generalized force of a unit force ``f`` at the
    point ``point`` of body ``body``: ``f`` and ``(point − p) × f`` on the platform rows,
    ``f · ∂point/∂q_j`` on the rows of the joints between the body and the platform."""
    nj = ip[5]
    for j in range(d):
        A[j, i] += f[j]
    _cross(point - pos[0], f, v4)
    if pk == 1:
        A[2, i] += v4[2]
    else:
        for j in range(3):
            A[3 + j, i] += v4[j]
    for j in range(1, nj + 1):
        if not beyond[body, j]:
            continue
        if ip[5 + nj + j] == 1:
            _cross(axes[j], point - pos[j], v5)
        else:
            v5[:] = axes[j]
        A[m + j - 1, i] += f[0] * v5[0] + f[1] * v5[1] + f[2] * v5[2]


@njit(cache=True, nogil=True)
def _cholesky_solve(M: np.ndarray, x: np.ndarray) -> bool:
    """Solve ``M y = x`` in place (``M`` overwritten by its Cholesky factor); False when ``M``
    is not positive definite."""
    P = M.shape[0]
    for j in range(P):
        s = M[j, j]
        for k in range(j):
            s -= M[j, k] * M[j, k]
        if not s > 1e-14 * (M[j, j] + 1e-300):
            return False
        M[j, j] = np.sqrt(s)
        for i in range(j + 1, P):
            s = M[i, j]
            for k in range(j):
                s -= M[i, k] * M[j, k]
            M[i, j] = s / M[j, j]
    for i in range(P):
        s = x[i]
        for k in range(i):
            s -= M[i, k] * x[k]
        x[i] = s / M[i, i]
    for i in range(P - 1, -1, -1):
        s = x[i]
        for k in range(i + 1, P):
            s -= M[k, i] * x[k]
        x[i] = s / M[i, i]
    return True


@njit(cache=True, nogil=True)
def tree_acceleration(
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
) -> int:
    """``q̈`` of one state of a jointed platform into ``qdd`` and the tensions into ``tau``
    (``u``: the tensions, or with ``elastic`` the unstretched lengths); ``w (P,)`` an external
    generalized force; returns the status."""
    pk, nj, n = ip[4], ip[5], cables.shape[0]
    d = 2 if pk == 1 else 3
    m = 3 if pk == 1 else 6
    P = m + nj
    M, h, A = np.empty((P, P)), np.empty(P), np.empty((P, n))
    lengths, U, Edq = np.empty(n), np.empty((3, 3)), np.empty(3)
    status = tree_terms(ip, fp, cables, q, qd, M, h, A, lengths, U, Edq)
    if status != OK:
        return status
    x = w - h
    for i in range(n):
        if elastic and cables[i, 7] >= 0:
            tau[i] = max(cables[i, 6] * (lengths[i] - u[i]) / u[i], 0.0)
        else:
            tau[i] = u[i]
        for j in range(P):
            x[j] += A[j, i] * tau[i]
    if not _cholesky_solve(M, x):
        return SINGULAR_INERTIA
    for i in range(d):
        qdd[i] = x[i]
    for i in range(m, P):
        qdd[i] = x[i]
    if pk == 1:
        qdd[2] = x[2]
        return OK
    det = (
        U[0, 0] * (U[1, 1] * U[2, 2] - U[1, 2] * U[2, 1])
        - U[0, 1] * (U[1, 0] * U[2, 2] - U[1, 2] * U[2, 0])
        + U[0, 2] * (U[1, 0] * U[2, 1] - U[1, 1] * U[2, 0])
    )
    if abs(det) < GIMBAL_TOL:
        return GIMBAL_LOCK
    # ẗ = U⁻¹ (α − Ė φ̇) by Cramer's rule, then φ̈ = T⁻¹ ẗ
    rhs, tdd, cr = x[3:6] - Edq, np.empty(3), np.empty(3)
    for k in range(3):
        _cross(U[:, (k + 1) % 3], U[:, (k + 2) % 3], cr)
        tdd[k] = (cr[0] * rhs[0] + cr[1] * rhs[1] + cr[2] * rhs[2]) / det
    _mv(fp[37:46].reshape((3, 3)), tdd, qdd[3:6])
    return OK


@njit(cache=True, nogil=True)
def tree_wrench(
    ip: np.ndarray,
    fp: np.ndarray,
    cables: np.ndarray,
    q: np.ndarray,
    qd: np.ndarray,
    qdd: np.ndarray,
    w_ext: np.ndarray,
    wrench: np.ndarray,
    W: np.ndarray,
) -> int:
    """The generalized force ``A τ = M_X Ẋ + h_X − w`` the cables must apply for the sample
    ``(q, q̇, q̈)`` of a jointed platform into ``wrench (P,)``, and the cable columns of the
    jointed structure matrix into ``W (P, n)``; returns the status."""
    pk, nj, n = ip[4], ip[5], cables.shape[0]
    d = 2 if pk == 1 else 3
    m = 3 if pk == 1 else 6
    P = m + nj
    M, h = np.empty((P, P)), np.empty(P)
    lengths, U, Edq = np.empty(n), np.empty((3, 3)), np.empty(3)
    status = tree_terms(ip, fp, cables, q, qd, M, h, W, lengths, U, Edq)
    if status != OK:
        return status
    Xd = np.empty(P)
    for i in range(d):
        Xd[i] = qdd[i]
    for i in range(m, P):
        Xd[i] = qdd[i]
    if pk == 1:
        Xd[2] = qdd[2]
    else:
        tdd, alpha = np.empty(3), np.empty(3)
        _mv(fp[28:37].reshape((3, 3)), qdd[3:6], tdd)
        _mv(U, tdd, alpha)
        Xd[3:6] = alpha + Edq
    for i in range(P):
        acc = h[i] - w_ext[i]
        for j in range(P):
            acc += M[i, j] * Xd[j]
        wrench[i] = acc
    return OK
