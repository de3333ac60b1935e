"""CASPR ``*_trajectories.xml``: every joint-trajectory kind against CASPR's own spline
formulas (its ``Spline`` class: polynomial coefficients solved from the boundary conditions in
absolute time, the parabolic blend), a real CASPR file (CoGiRo), and malformed files."""

from __future__ import annotations

from functools import partial
from pathlib import Path

import numpy as np
import pytest

from taut.errors import TautError, TautWarning, TrajectoryError
from taut.motion import read_caspr_trajectories

HERE = Path(__file__).parent / "fixtures" / "caspr"
MODELS = Path(__file__).parents[1] / "model" / "fixtures" / "caspr"
PLANAR_XZ = MODELS / "planar_xz_bodies.xml"
PLANAR_XY = MODELS / "planar_xy_bodies.xml"
COGIRO = MODELS / "real" / "CoGiRo_bodies.xml"


def _polynomial(ts, te, start, end, t):
    """CASPR's Spline.Cubic/QuinticInterpolation: solve ``T a = b`` for the coefficients of
    ``x(t) = Σ a_j t^j`` in absolute time from the boundary states ``start``/``end``
    (position, velocity[, acceleration])."""
    n = 2 * len(start)

    def rows(s):
        return [
            [np.prod(range(j - d + 1, j + 1)) * s ** (j - d) if j >= d else 0.0 for j in range(n)]
            for d in range(len(start))
        ]

    a = np.linalg.solve(np.array(rows(ts) + rows(te), dtype=float), np.concatenate([start, end]))
    x = sum(a[j] * t**j for j in range(n))
    xd = sum(j * a[j] * t ** (j - 1) for j in range(1, n))
    xdd = sum(j * (j - 1) * a[j] * t ** (j - 2) for j in range(2, n))
    return x, xd, xdd


def _parabolic_blend(xs, xe, ts, te, tb, t):
    """CASPR's Spline.ParabolicBlend."""
    acc = (xs - xe) / (tb**2 - (te - ts) * tb)
    xb = xs + acc * tb**2 / 2
    v = ((xs + xe) / 2 - xb) / ((te - ts) / 2 - tb)
    x = np.where(
        t < ts + tb,
        xs + acc * (t - ts) ** 2 / 2,
        np.where(t < te - tb, xb + v * (t - ts - tb), xe - acc * (t - te) ** 2 / 2),
    )
    xd = np.where(t < ts + tb, acc * (t - ts), np.where(t < te - tb, v, -acc * (t - te)))
    xdd = np.where(t < ts + tb, acc, np.where(t < te - tb, 0.0, -acc))
    return x, xd, xdd


def _check(motion, segments, flip, n=41):
    """``segments``: (ts, te, reference(t) -> (q, qd, qdd) in CASPR's coordinates).  At a
    via point the segment that ends there counts, as in CASPR's samples."""
    sign = np.array([1.0, 1.0, -1.0]) if flip else np.ones(motion.waypoints.shape[1])
    for ts, te, ref in segments:
        t = np.linspace(ts, te, n)[0 if ts == 0 else 1 :]
        s = motion.at(t)
        for got, want in zip((s.pose, s.velocity, s.acceleration), ref(t)):
            assert np.allclose(got, np.stack(want, axis=1) * sign, atol=1e-9)


def test_every_kind_matches_caspr_formulas():
    robot, trajs = read_caspr_trajectories(HERE / "planar_xz_trajectories.xml", bodies=PLANAR_XZ)
    assert robot.pose_names == ["x", "y", "theta"]
    assert sorted(trajs) == ["average", "blend", "cubic", "linear", "quintic"]  # operational ones are not read
    assert {k: t.motion.law for k, t in trajs.items()} == {
        "linear": "linear",
        "cubic": "cubic",
        "quintic": "quintic",
        "average": "cubic",
        "blend": "trapezoidal",
    }
    # PLANAR_XZ: taut's θ is −θ_CASPR
    assert trajs["linear"].motion.waypoints[1].tolist() == [0.7, 0.5, -0.2]
    assert trajs["quintic"].time_step == 0.01

    lin = trajs["linear"].motion  # absolute times 0, 2, 3
    q = np.array([[0.3, 0.5, 0.0], [0.7, 0.5, 0.2], [0.7, 0.9, 0.2]])

    def linear(k, ts, te):
        return lambda t: tuple(
            [np.stack([np.interp(t, [ts, te], [q[k, i], q[k + 1, i]]) for i in range(3)]).T[:, i] for i in range(3)]
            if d == 0
            else [np.full_like(t, (q[k + 1, i] - q[k, i]) / (te - ts)) for i in range(3)]
            if d == 1
            else [np.zeros_like(t)] * 3
            for d in range(3)
        )

    _check(lin, [(0, 2, linear(0, 0, 2)), (2, 3, linear(1, 2, 3))], flip=True)

    def poly(states_s, states_e, ts, te):
        def ref(t):
            out = [_polynomial(ts, te, [s[i] for s in states_s], [e[i] for e in states_e], t) for i in range(3)]
            return tuple([o[d] for o in out] for d in range(3))

        return ref

    cubic = trajs["cubic"].motion  # relative 1.5, 1.0
    qd = np.array([[0, 0, 0], [0.2, 0.1, 0.05], [0, 0, 0]])
    qc = np.array([[0.3, 0.5, 0.0], [0.5, 0.6, 0.1], [0.7, 0.5, 0.2]])
    _check(
        cubic,
        [
            (0, 1.5, poly((qc[0], qd[0]), (qc[1], qd[1]), 0, 1.5)),
            (1.5, 2.5, poly((qc[1], qd[1]), (qc[2], qd[2]), 1.5, 2.5)),
        ],
        flip=True,
    )

    quintic = trajs["quintic"].motion
    qq = np.array([[0.3, 0.5, 0.0], [0.6, 0.7, -0.3], [0.7, 0.5, 0.2]])
    qqd = np.array([[0, 0, 0], [0.1, 0.0, -0.1], [0, 0, 0]])
    qqdd = np.array([[0, 0, 0], [0.0, 0.2, 0.0], [0, 0, 0]])
    _check(
        quintic,
        [
            (0, 2, poly((qq[0], qqd[0], qqdd[0]), (qq[1], qqd[1], qqdd[1]), 0, 2)),
            (2, 3, poly((qq[1], qqd[1], qqdd[1]), (qq[2], qqd[2], qqdd[2]), 2, 3)),
        ],
        flip=True,
    )

    average = trajs["average"].motion  # absolute 0, 1, 3, 4; end velocities given
    qa = np.array([[0.3, 0.5, 0.0], [0.5, 0.6, 0.1], [0.7, 0.4, 0.3], [0.7, 0.5, 0.2]])
    ta = np.array([0.0, 1.0, 3.0, 4.0])
    slopes = np.diff(qa, axis=0) / np.diff(ta)[:, None]
    va = np.vstack([[0, 0, 0], (slopes[:-1] + slopes[1:]) / 2, [0.0, 0.1, 0.0]])
    _check(
        average,
        [(ta[k], ta[k + 1], poly((qa[k], va[k]), (qa[k + 1], va[k + 1]), ta[k], ta[k + 1])) for k in range(3)],
        flip=True,
    )

    blend = trajs["blend"].motion  # relative 2, 2; blend 0.5 (default) then 1.0 (the point's)
    qb = np.array([[0.3, 0.5, 0.0], [0.7, 0.5, 0.2], [0.7, 0.9, 0.2]])

    def pb(k, ts, te, tb):
        def ref(t):
            out = [_parabolic_blend(qb[k, i], qb[k + 1, i], ts, te, tb, t) for i in range(3)]
            return tuple([o[d] for o in out] for d in range(3))

        return ref

    # CASPR's blend of 1.0 in a 2.0 s segment is triangular: its formula divides by zero
    # there, so the reference is checked on the first segment and the end state on the second
    # 43 samples miss the blend ends 0.5 and 1.5 s, where the acceleration jumps (CASPR takes the
    # piece that starts there, taut the one that ends there)
    _check(blend, [(0, 2, pb(0, 0, 2, 0.5))], flip=True, n=43)
    end = blend.at([2.0, 3.0, 4.0])
    assert np.allclose(end.pose[[0, 2]], qb[[1, 2]] * [1, 1, -1])
    assert end.velocity[1] == pytest.approx([0.0, 0.4 / (1.0 * 1.0), 0.0])  # peak a t_b = Δ/(t_b(T−t_b)) t_b


def _about(k, t):
    """Rotation by ``t`` about coordinate axis ``k``."""
    c, s = np.cos(t), np.sin(t)
    R = np.eye(3)
    i, j = (k + 1) % 3, (k + 2) % 3
    R[i, i], R[i, j], R[j, i], R[j, j] = c, -s, s, c
    return R


#: CASPR's orientation conventions: the rotation of the angles, and where each angle is read
#: back from a rotation, ``atan2(s R[y], R[x])``, ``asin(s R[z])``, ``atan2(s R[y], R[x])``
#: (SphericalEulerXYZ: ``R = Rx Ry Rz``, ``b = asin R13``, ``c = −atan2(R12, R11)``,
#: ``a = −atan2(R23, R33)``; SphericalFixedXYZ: ``R = Rz Ry Rx``, ``b = −asin R31``,
#: ``c = atan2(R21, R11)``, ``a = atan2(R32, R33)``).
CONVENTIONS = {
    "xyz-moving": (
        lambda q: _about(0, q[0]) @ _about(1, q[1]) @ _about(2, q[2]),
        (((1, 2), (2, 2), -1), ((0, 2), 1), ((0, 1), (0, 0), -1)),
    ),
    "xyz-fixed": (
        lambda q: _about(2, q[2]) @ _about(1, q[1]) @ _about(0, q[0]),
        (((2, 1), (2, 2), 1), ((2, 0), -1), ((1, 0), (0, 0), 1)),
    ),
}


def _bilinear(p, r):
    """The symmetric bilinear form ``H`` with CASPR's Quaternion.ToRotationMatrix
    ``R(q) = I + 2 H(q, q)`` (so ``Ṙ = 4 H(q, q̇)``, ``R̈ = 4 (H(q̇, q̇) + H(q, q̈))``)."""
    (p0, p1, p2, p3), (r0, r1, r2, r3) = p, r
    return np.array(
        [
            [
                -(p2 * r2 + p3 * r3),
                (p1 * r2 + p2 * r1 - p0 * r3 - p3 * r0) / 2,
                (p0 * r2 + p2 * r0 + p1 * r3 + p3 * r1) / 2,
            ],
            [
                (p1 * r2 + p2 * r1 + p0 * r3 + p3 * r0) / 2,
                -(p1 * r1 + p3 * r3),
                (p2 * r3 + p3 * r2 - p0 * r1 - p1 * r0) / 2,
            ],
            [
                (p1 * r3 + p3 * r1 - p0 * r2 - p2 * r0) / 2,
                (p0 * r1 + p1 * r0 + p2 * r3 + p3 * r2) / 2,
                -(p1 * r1 + p2 * r2),
            ],
        ]
    )


def _caspr_turn(convention, q_start, q_end, ts, te, t, law):
    """CASPR's spherical joint from ``q_start`` to ``q_end`` over ``[ts, te]``
    (SphericalEulerXYZ / SphericalFixedXYZ ``generateTrajectory…``): the quaternion of
    ``R_sᵀ R_e`` (Quaternion.FromRotationMatrix), its axis ``k`` and angle ``θ``
    (AxisAngle.FromQuaternion), the angle timed from 0 to ``θ`` by the spline with zero end
    velocities (Spline), the quaternion and its derivatives of the axis and angle
    (FromAxisAngle, DerivativeFromAxisAngle, DoubleDerivativeFromAxisAngle), ``R = R_s R(quat)``
    and its derivatives, the angles read back.  Returns the angles and their rates ``(T, 3)``,
    and the angular velocity and acceleration ``(T, 3)`` (from ``Ṙ Rᵀ`` and its derivative)."""
    rotation, reads = CONVENTIONS[convention]
    Rs = rotation(q_start)
    Rse = Rs.T @ rotation(q_end)
    q0 = 0.5 * np.sqrt(1 + np.trace(Rse))
    vec = np.array([Rse[2, 1] - Rse[1, 2], Rse[0, 2] - Rse[2, 0], Rse[1, 0] - Rse[0, 1]]) / (4 * q0)
    theta = 2 * np.arccos(min(q0, 1.0))
    k = vec / np.sin(theta / 2) if theta > 0 else np.zeros(3)
    if law == "linear":
        th, thd, thdd = theta * (t - ts) / (te - ts), np.full_like(t, theta / (te - ts)), np.zeros_like(t)
    elif law == "cubic":
        th, thd, thdd = _polynomial(ts, te, [0.0, 0.0], [theta, 0.0], t)
    else:
        th, thd, thdd = _polynomial(ts, te, [0.0, 0.0, 0.0], [theta, 0.0, 0.0], t)
    (ay, ax, sa), (bz, sb), (cy, cx, sc) = reads
    out = []
    for a, ad, add in zip(np.atleast_1d(th), np.atleast_1d(thd), np.atleast_1d(thdd)):
        c, s = np.cos(a / 2), np.sin(a / 2)
        quat = np.concatenate([[c], k * s])
        quat_d = np.concatenate([[-ad / 2 * s], k * ad / 2 * c])
        quat_dd = np.concatenate([[-add / 2 * s - ad**2 / 4 * c], k * (add / 2 * c - ad**2 / 4 * s)])
        R = Rs @ (np.eye(3) + 2 * _bilinear(quat, quat))
        Rd = Rs @ (4 * _bilinear(quat, quat_d))
        Rdd = Rs @ (4 * (_bilinear(quat_d, quat_d) + _bilinear(quat, quat_dd)))
        angles = [np.arctan2(sa * R[ay], R[ax]), np.arcsin(sb * R[bz]), np.arctan2(sc * R[cy], R[cx])]
        # d/dt atan2(s y, x) = s (x ẏ − y ẋ)/(x² + y²); d/dt asin(s z) = s ż/√(1 − z²)
        rates = [
            sa * (R[ax] * Rd[ay] - R[ay] * Rd[ax]) / (R[ax] ** 2 + R[ay] ** 2),
            sb * Rd[bz] / np.sqrt(1 - R[bz] ** 2),
            sc * (R[cx] * Rd[cy] - R[cy] * Rd[cx]) / (R[cx] ** 2 + R[cy] ** 2),
        ]
        W, Wd = Rd @ R.T, Rdd @ R.T + Rd @ Rd.T
        out.append((angles, rates, [W[2, 1], W[0, 2], W[1, 0]], [Wd[2, 1], Wd[0, 2], Wd[1, 0]]))
    return tuple(np.array(x) for x in zip(*out))


def _check_turns(motion, points, times, convention, law, n=41):
    """Each segment's orientation against CASPR's spherical joint (angles compared modulo
    2π: CASPR's jump where taut's continue); the angles' accelerations against central
    differences of CASPR's rates."""
    h = 1e-6
    for k in range(len(times) - 1):
        ts, te = times[k], times[k + 1]
        t = np.linspace(ts, te, n)[0 if k == 0 else 1 :]
        s = motion.at(t)

        caspr = partial(_caspr_turn, convention, points[k, 3:], points[k + 1, 3:], ts, te, law=law)
        angles, rates, omega, alpha = caspr(t)
        np.testing.assert_allclose(np.angle(np.exp(1j * (s.pose[:, 3:] - angles))), 0.0, atol=1e-9)
        np.testing.assert_allclose(s.velocity[:, 3:], rates, atol=1e-9)
        np.testing.assert_allclose(s.angular_velocity, omega, atol=1e-9)
        np.testing.assert_allclose(s.angular_acceleration, alpha, atol=1e-9)
        inner = t[(t > ts + h) & (t < te - h)]
        derivative = (caspr(inner + h)[1] - caspr(inner - h)[1]) / (2 * h)
        np.testing.assert_allclose(motion.at(inner).acceleration[:, 3:], derivative, atol=1e-5)


def test_real_caspr_file_cogiro():
    """CoGiRo's quintic trajectories: positions by the quintic of each coordinate, the
    orientation turned about one axis as CASPR's SpatialEulerXYZ joint turns it."""
    robot, trajs = read_caspr_trajectories(HERE / "CoGiRo_trajectories.xml", bodies=COGIRO)
    assert robot.orientation == "xyz-moving" and robot.pose_size == 6
    assert sorted(trajs) == ["general_1", "general_2", "general_3", "long_stable"] and not trajs.skipped
    long = trajs["long_stable"]
    assert long.kind == "quintic_spline_trajectory" and long.motion.duration == pytest.approx(18.0)
    g = trajs["general_1"]
    # CASPR samples time_section = t_s : time_step : t_e per segment: 401 samples over 4 s
    s = g.motion.sample(1 / g.time_step)
    assert len(s.time) == 401
    start = np.array([-3.0, -1.0, 2.0, -0.5, 0.2, 0.3])
    mid = np.array([2.0, -3.0, 4.0, 0.2, -0.1, 0.1])
    assert np.allclose(s.pose[0], start) and np.allclose(s.pose[200], mid)
    ref = np.stack([_polynomial(0.0, 2.0, [start[i], 0, 0], [mid[i], 0, 0], s.time[:201])[0] for i in range(3)], axis=1)
    assert np.allclose(s.pose[:201, :3], ref, atol=1e-9)
    for tr in trajs.values():
        assert tr.motion.rotation == "axis"
        _check_turns(tr.motion, tr.motion.waypoints, tr.motion.times, "xyz-moving", "quintic")


def test_cogiro_angles_interpolated_apart_are_another_motion():
    """What interpolating each angle (taut's reader before) gives on general_2: the angles up
    to 0.030 rad and the cable lengths up to 47 mm from CASPR's."""
    from taut.kinematics import cable_lengths
    from taut.motion import trajectory_from_waypoints

    robot, trajs = read_caspr_trajectories(HERE / "CoGiRo_trajectories.xml", bodies=COGIRO)
    turned = trajs["general_2"].motion
    apart = trajectory_from_waypoints(robot, turned.waypoints, times=turned.times, law="quintic", unwrap=False)
    t = turned.sample(100).time
    a, b = turned.at(t).pose, apart.at(t).pose
    assert np.abs(a - b)[:, 3:].max() == pytest.approx(0.0302, abs=1e-4)
    assert np.abs(cable_lengths(robot, a) - cable_lengths(robot, b)).max() == pytest.approx(0.0470, abs=1e-4)


def test_fixed_xyz_turns_every_law(tmp_path):
    """``T_XYZ`` carrying ``S_FIXED_XYZ`` (taut's ``xyz-fixed``): linear, cubic and parabolic
    blend turns as CASPR's SphericalFixedXYZ joint, and a turn whose angle ``c`` passes π
    continues past it (CASPR's angles jump to −π there)."""
    from scipy.spatial.transform import Rotation

    q = np.array([[0.0, 0.0, 1.0, 0.1, -0.2, 2.8], [0.2, 0.1, 1.1, -0.2, 0.3, 3.0], [0.1, 0.0, 1.0, 0.3, 0.1, -2.9]])
    pts = "".join(
        f"<point time='1.0'><q>{' '.join(map(str, p))}</q><q_dot>0 0 0 0 0 0</q_dot></point>" for p in q
    ).replace(" time='1.0'", "", 1)
    kinds = [("linear", "linear_spline_trajectory", ""), ("cubic", "cubic_spline_trajectory", "")]
    kinds.append(("blend", "parabolic_blend_trajectory", " blend_time_default='0.25'"))
    body = "".join(
        f"<{tag} id='{name}' time_definition='relative' time_step='0.01'{extra}><points>{pts}</points></{tag}>"
        for name, tag, extra in kinds
    )
    path = tmp_path / "fixed_chain_trajectories.xml"
    path.write_text(f"<trajectories><joint_trajectories>{body}</joint_trajectories></trajectories>")
    robot, trajs = read_caspr_trajectories(path, bodies=MODELS / "fixed_chain_bodies.xml")
    assert robot.orientation == "xyz-fixed"
    for law in ("linear", "cubic"):
        motion = trajs[law].motion
        assert motion.waypoints[2, 5] == pytest.approx(2 * np.pi - 2.9)  # continued past π
        _check_turns(motion, q, np.array([0.0, 1.0, 2.0]), "xyz-fixed", law)
        c = motion.sample(1000).pose[:, 5]
        assert np.abs(np.diff(c)).max() < 0.01 and c.max() > np.pi  # no 2π jump
    # the parabolic blend times the angle turned: ω keeps its axis, its size is θ̇(t)
    s = trajs["blend"].motion.at(np.linspace(0, 2, 201))
    rotation = CONVENTIONS["xyz-fixed"][0]
    for k in range(2):
        inside = (s.time > k) & (s.time < k + 1)
        w = s.angular_velocity[inside]
        axis = w[np.argmax(np.linalg.norm(w, axis=1))]
        assert np.abs(np.cross(w, axis / np.linalg.norm(axis))).max() < 1e-9
        theta = np.linalg.norm(Rotation.from_matrix(rotation(q[k, 3:]).T @ rotation(q[k + 1, 3:])).as_rotvec())
        speed = _parabolic_blend(0.0, theta, k, k + 1, 0.25, s.time[inside])[1]
        np.testing.assert_allclose(np.linalg.norm(w, axis=1), speed, atol=1e-9)


def _write(tmp_path, body):
    path = tmp_path / "planar_xz_trajectories.xml"
    path.write_text(
        f"<?xml version='1.0'?>\n<trajectories><joint_trajectories>{body}</joint_trajectories></trajectories>"
    )
    return path


PTS = "<points><point><q>0.3 0.5 0</q></point><point time='1'><q>0.4 0.5 0</q></point></points>"
BAD = [
    (
        f"<linear_spline_trajectory time_definition='relative' time_step='0.1'>{PTS}</linear_spline_trajectory>",
        "attribute id is missing",
    ),
    (
        f"<linear_spline_trajectory id='a' time_definition='later' time_step='0.1'>{PTS}</linear_spline_trajectory>",
        "time_definition must be",
    ),
    (
        f"<linear_spline_trajectory id='a' time_definition='relative' time_step='0'>{PTS}</linear_spline_trajectory>",
        "time_step must be a number > 0",
    ),
    (
        "<linear_spline_trajectory id='a' time_definition='relative' time_step='0.1'><points><point><q>0.3 0.5 0</q></point></points></linear_spline_trajectory>",
        "at least 2 points, got 1",
    ),
    (
        "<linear_spline_trajectory id='a' time_definition='relative' time_step='0.1'><points><point><q>0.3 0.5</q></point><point time='1'><q>0.3 0.5 0</q></point></points></linear_spline_trajectory>",
        "expected 3 numbers",
    ),
    (
        "<linear_spline_trajectory id='a' time_definition='relative' time_step='0.1'><points><point><q>0.3 nan 0</q></point><point time='1'><q>0.3 0.5 0</q></point></points></linear_spline_trajectory>",
        "expected finite numbers",
    ),
    (
        "<linear_spline_trajectory id='a' time_definition='relative' time_step='0.1'><points><point><q>0.3 0.5 0</q></point><point time='-1'><q>0.3 0.5 0</q></point></points></linear_spline_trajectory>",
        "time must be a number > 0",
    ),
    (
        "<linear_spline_trajectory id='a' time_definition='absolute' time_step='0.1'><points><point><q>0.3 0.5 0</q></point><point time='2'><q>0.3 0.5 0</q></point><point time='1'><q>0.4 0.5 0</q></point></points></linear_spline_trajectory>",
        "times must increase",
    ),
    (
        f"<cubic_spline_trajectory id='a' time_definition='relative' time_step='0.1'>{PTS}</cubic_spline_trajectory>",
        "point 1 has no <q_dot>",
    ),
    (
        f"<parabolic_blend_trajectory id='a' time_definition='relative' time_step='0.1'>{PTS}</parabolic_blend_trajectory>",
        "blend time of segment 1 must be a number > 0",
    ),
    (
        f"<parabolic_blend_trajectory id='a' time_definition='relative' time_step='0.1' blend_time_default='0.6'>{PTS}</parabolic_blend_trajectory>",
        "more than half",
    ),
    (
        f"<linear_spline_trajectory id='a' time_definition='relative' time_step='0.1'>{PTS}</linear_spline_trajectory>"
        f"<linear_spline_trajectory id='a' time_definition='relative' time_step='0.1'>{PTS}</linear_spline_trajectory>",
        "two trajectories have the id 'a'",
    ),
    ("", "no <joint_trajectories>"),
]


@pytest.mark.parametrize(("body", "message"), BAD, ids=[m for _, m in BAD])
def test_malformed_files(tmp_path, body, message):
    with pytest.raises(TrajectoryError, match=message.replace("(", r"\(")) as info:
        read_caspr_trajectories(_write(tmp_path, body), bodies=PLANAR_XZ)
    assert "\n" not in str(info.value)


def test_unwrap_on_request(tmp_path):
    body = (
        "<linear_spline_trajectory id='turn' time_definition='relative' time_step='0.1'><points>"
        "<point><q>0.3 0.5 3.0</q></point><point time='1'><q>0.3 0.5 -3.0</q></point>"
        "</points></linear_spline_trajectory>"
    )
    path = _write(tmp_path, body)
    as_caspr = read_caspr_trajectories(path, bodies=PLANAR_XZ)[1]["turn"].motion
    assert as_caspr.waypoints[:, 2].tolist() == [-3.0, 3.0]  # θ = −θ_CASPR, the long way, as CASPR
    short = read_caspr_trajectories(path, bodies=PLANAR_XZ, unwrap=True)[1]["turn"].motion
    assert short.waypoints[:, 2] == pytest.approx([-3.0, -2 * np.pi + 3.0])


def test_file_names_and_missing_model(tmp_path):
    path = tmp_path / "motion.xml"
    path.write_text("<trajectories/>")
    with pytest.raises(TrajectoryError, match="named X_trajectories.xml; give bodies="):
        read_caspr_trajectories(path)
    with pytest.raises(TautError):  # the model beside it is missing
        read_caspr_trajectories(_write(tmp_path, ""))
    other = tmp_path / "x_trajectories.xml"
    other.write_text("<bodies_system/>")
    with pytest.raises(TrajectoryError, match="expected a <trajectories> CASPR trajectory file"):
        read_caspr_trajectories(other, bodies=PLANAR_XZ)


def test_unread_trajectory_leaves_the_others():
    """A ``<file_trajectory>`` among the joint trajectories (as in CASPR's planar XY example):
    skipped with a warning naming it, the others read, and asking for it by id says why in
    one line."""
    with pytest.warns(
        TautWarning, match=r"skipped <file_trajectory id='traj_file'>: .*\.traj file.*is not read"
    ) as got:
        robot, trajs = read_caspr_trajectories(HERE / "planar_xy_trajectories.xml", bodies=PLANAR_XY)
    assert len(got) == 1
    assert sorted(trajs) == ["traj_average", "traj_blend", "traj_cubic", "traj_linear", "traj_quintic"]
    assert list(trajs.skipped) == ["traj_file"] and "traj_file" not in trajs and len(trajs) == 5
    assert trajs["traj_linear"].motion.at([1.0]).pose[0] == pytest.approx([0.5, 0.2, 0.05])
    with pytest.raises(TrajectoryError, match=r"trajectory 'traj_file' is not read: <file_trajectory> \(samples") as e:
        trajs["traj_file"]
    assert "\n" not in str(e.value)
    with pytest.raises(KeyError):
        trajs["no_such_id"]


def test_unknown_elements_are_skipped(tmp_path):
    good = (
        f"<linear_spline_trajectory id='b' time_definition='relative' time_step='0.1'>{PTS}</linear_spline_trajectory>"
    )
    with pytest.warns(TautWarning, match="unknown joint trajectory <bezier_trajectory>"):
        _, trajs = read_caspr_trajectories(_write(tmp_path, f"<bezier_trajectory id='a'/>{good}"), bodies=PLANAR_XZ)
    assert list(trajs) == ["b"]
    with pytest.raises(TrajectoryError, match="'a' is not read: unknown joint trajectory <bezier_trajectory>"):
        trajs["a"]
    with pytest.warns(TautWarning), pytest.raises(TrajectoryError, match="no trajectory taut reads .*bezier"):
        read_caspr_trajectories(_write(tmp_path, "<bezier_trajectory id='a'/>"), bodies=PLANAR_XZ)


def test_spherical_joints_stop_turning_at_points(tmp_path):
    """CASPR's spherical joints refuse nonzero angle velocities or accelerations at the points
    (and so average velocities that turn the angles): those trajectories are skipped; moving
    positions through a point are read."""
    still, moving = "0 0 0 0 0 0", "0.1 0 0 0 0.2 0"
    pts = (
        "<point><q>0 0 2 0 0 0</q><q_dot>{v}</q_dot><q_ddot>{a}</q_ddot></point>"
        "<point time='1'><q>0.5 0 2 0.1 0 0</q><q_dot>{w}</q_dot><q_ddot>{a}</q_ddot></point>"
        "<point time='1'><q>1 0 2 0 0.2 0</q><q_dot>{v}</q_dot><q_ddot>{a}</q_ddot></point>"
    )
    body = "".join(
        f"<{tag} id='{ident}' time_definition='relative' time_step='0.1'><points>{pts.format(v=still, w=w, a=a)}</points></{tag}>"
        for tag, ident, w, a in [
            ("cubic_spline_trajectory", "turning", moving, still),
            ("quintic_spline_trajectory", "spinning", still, "0 0 0 0.3 0 0"),
            ("cubic_spline_average_velocity_trajectory", "average", still, still),
            ("cubic_spline_trajectory", "passing", "0.4 0.1 0 0 0 0", still),
        ]
    )
    path = tmp_path / "CoGiRo_trajectories.xml"
    path.write_text(f"<trajectories><joint_trajectories>{body}</joint_trajectories></trajectories>")
    with pytest.warns(TautWarning, match="spherical joints take only zero angle velocities") as got:
        robot, trajs = read_caspr_trajectories(path, bodies=COGIRO)
    assert len(got) == 3 and list(trajs) == ["passing"] and sorted(trajs.skipped) == ["average", "spinning", "turning"]
    assert trajs["passing"].motion.at([1.0]).velocity[0] == pytest.approx([0.4, 0.1, 0, 0, 0, 0])
    with pytest.raises(TrajectoryError, match="'turning' is not read: CASPR's spherical joints"):
        trajs["turning"]
