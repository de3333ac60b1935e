"""CASPR ``*_trajectories.xml``: every joint-trajectory kind against CASPR's own spline
formulas (its ``Spline`` class: polynomial coefficients solved from the boundary conditions in
absolute time, the parabolic blend), a real CASPR file (CoGiRo), and malformed files."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from taut.errors import TautError, TrajectoryError
from taut.motion import read_caspr_trajectories

HERE = Path(__file__).parent / "fixtures" / "caspr"
MODELS = Path(__file__).parents[1] / "model" / "fixtures" / "caspr"
PLANAR_XZ = MODELS / "planar_xz_bodies.xml"
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
        for got, want in zip((s.poses, s.velocity, s.acceleration), ref(t)):
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
    assert np.allclose(end.poses[[0, 2]], qb[[1, 2]] * [1, 1, -1])
    assert end.velocity[1] == pytest.approx([0.0, 0.4 / (1.0 * 1.0), 0.0])  # peak a t_b = Δ/(t_b(T−t_b)) t_b


def test_real_caspr_file_cogiro():
    robot, trajs = read_caspr_trajectories(HERE / "CoGiRo_trajectories.xml", bodies=COGIRO)
    assert robot.orientation == "xyz-moving" and robot.pose_size == 6
    assert sorted(trajs) == ["general_1", "general_2", "general_3", "long_stable"]
    long = trajs["long_stable"]
    assert long.kind == "quintic_spline_trajectory" and long.motion.duration == pytest.approx(18.0)
    g = trajs["general_1"]
    # CASPR samples time_section = t_s : time_step : t_e per segment: 401 samples over 4 s
    s = g.motion.sample(1 / g.time_step)
    assert len(s.times) == 401
    start = np.array([-3.0, -1.0, 2.0, -0.5, 0.2, 0.3])
    mid = np.array([2.0, -3.0, 4.0, 0.2, -0.1, 0.1])
    assert np.allclose(s.poses[0], start) and np.allclose(s.poses[200], mid)
    ref = np.stack(
        [_polynomial(0.0, 2.0, [start[i], 0, 0], [mid[i], 0, 0], s.times[:201])[0] for i in range(6)], axis=1
    )
    assert np.allclose(s.poses[:201], ref, atol=1e-9)
    back = json.loads(json.dumps(g.as_dict(), allow_nan=False))
    assert back["id"] == "general_1" and back["time_step"] == g.time_step
    assert back["motion"]["waypoints"] == g.motion.waypoints.tolist()
    assert np.all(np.isfinite(s.angular_velocity)) and s.angular_velocity.shape == (401, 3)


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
    (f"<bezier_trajectory id='a'>{PTS}</bezier_trajectory>", "unknown joint trajectory <bezier_trajectory>"),
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
