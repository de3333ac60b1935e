"""The geometrico-static problems of planar rigid platforms (pose x, y, θ): every equilibrium
checked here from the robot's data alone — the taut cables reach their anchors, the slack
ones do not, the tensions are non-negative and balance the load, forces and moment — and,
on 30 random planar robots, a second formulation finds no equilibrium the solver missed: per
taut subset a sweep of the angle θ, the taut cables' circles intersected in closed form and
the roots of the remaining condition polished by Brent's method."""

import json
import math
from types import SimpleNamespace

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from taut.dgp import solve_dgp, solve_igp, track_equilibrium, track_path
from taut.errors import CableSetError, PoseError, TautError, TrackingLostError
from taut.model import Cable, Platform, Reference, Robot, example, random_planar_robot, save_robot


def rot(theta):
    c, s = math.cos(theta), math.sin(theta)
    return np.array([[c, -s], [s, c]])


def cross(u, v):
    return u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]


def raw_load(robot):
    """``(f, m_z, G)`` from the file's fields: the weight ``mass·gravity`` (default 9.81
    down ``y``) plus ``wrench``, and the body-frame load point."""
    plat = robot.platform
    f, mz = np.zeros(2), 0.0
    if plat.mass is not None:
        f += plat.mass * np.array(plat.gravity if plat.gravity is not None else (0.0, -9.81))
    if plat.wrench is not None:
        f += plat.wrench[:2]
        mz = plat.wrench[2]
    gp = np.array(plat.wrench_point if plat.wrench_point is not None else (0.0, 0.0))
    return f, mz, gp


def raw_geometry(robot):
    a = np.array([c.exit for c in robot.cables], float)
    r = np.array([c.anchor if c.anchor is not None else (0.0, 0.0) for c in robot.cables], float)
    return a, r


def check_planar_equilibrium(robot, lengths, sol, *, atol=1e-7):
    """Residuals of one reported equilibrium, from the robot's data alone."""
    assert sol.position.shape == (2,) and sol.orientation.shape == (1,)
    a, r = raw_geometry(robot)
    f, mz, gp = raw_load(robot)
    R = rot(sol.orientation[0])
    b = sol.position + r @ R.T
    reach = np.linalg.norm(a - b, axis=1)
    taut = list(sol.taut)
    slack = [i for i in range(len(a)) if i not in taut]
    assert np.allclose(reach[taut], lengths[taut], rtol=0, atol=atol)
    assert np.all(reach[slack] <= lengths[slack] + 1e-9)
    assert np.all(sol.tensions[taut] >= 0.0) and np.all(sol.tensions[slack] == 0.0)
    u = (a - b) / reach[:, None]
    force = sol.tensions @ u + f
    g = sol.position + R @ gp
    moment = cross(b, sol.tensions[:, None] * u).sum() + cross(g, f) + mz
    size = np.linalg.norm(f)
    assert np.abs(force).max() <= 1e-6 * size
    assert abs(moment) <= 1e-6 * size * (1.0 + np.abs(sol.position).max())


# ---- the second formulation: a sweep of θ per taut subset ---------------------------------

#: Angles sampled per branch; roots closer than the spacing (2π/SAMPLES) could be missed.
SAMPLES = 7201


def _circles(c1, r1, c2, r2, side):
    """The intersection on ``side`` (±1) of the circles ``(c1, r1)`` and ``(c2, r2)``, the
    second centre an array of centres; NaN where they miss."""
    d = c2 - c1
    dist = np.linalg.norm(d, axis=-1)
    with np.errstate(invalid="ignore", divide="ignore"):
        x = (dist**2 + r1**2 - r2**2) / (2.0 * dist)
        h = np.sqrt(r1**2 - x**2)
        e = d / dist[..., None]
    perp = np.stack([-e[..., 1], e[..., 0]], -1)
    return c1 + x[..., None] * e + side * h[..., None] * perp


class Branch:
    """The poses of a taut subset as functions of θ: the first taut cable's anchor on the
    intersection (side ±1) of its circle with the second's, carried by the platform's
    rigid offset; one taut cable: its anchor straight along the load below the exit."""

    def __init__(self, robot, lengths, taut, side):
        self.a, self.r = raw_geometry(robot)
        self.f, self.mz, self.gp = raw_load(robot)
        self.rho, self.taut, self.side = lengths, taut, side

    def pose(self, theta):
        theta = np.atleast_1d(theta)
        c, s = np.cos(theta), np.sin(theta)
        R = np.stack([np.stack([c, -s], -1), np.stack([s, c], -1)], -2)
        a, r, rho = self.a, self.r, self.rho
        i = self.taut[0]
        if len(self.taut) == 1:
            bi = np.broadcast_to(a[i] + rho[i] * self.f / np.linalg.norm(self.f), (theta.size, 2))
        else:
            j = self.taut[1]
            offset = np.einsum("kab,b->ka", R, r[j] - r[i])
            bi = _circles(a[i], rho[i], a[j] - offset, rho[j], self.side)
        p = bi - np.einsum("kab,b->ka", R, r[i])
        return p, R

    def anchors(self, theta):
        p, R = self.pose(theta)
        return p[:, None, :] + np.einsum("kab,nb->kna", R, self.r), p, R

    def residual(self, theta):
        """What the circles leave to vanish: one cable, the moment of the load about its
        anchor; two, the load's wrench in the span of theirs (a 3 × 3 determinant); three,
        the third cable's length."""
        b, p, R = self.anchors(theta)
        g = p + np.einsum("kab,b->ka", R, self.gp)
        taut = self.taut
        if len(taut) == 1:
            return cross(g - b[:, taut[0]], np.broadcast_to(self.f, g.shape)) + self.mz
        if len(taut) == 3:
            k = taut[2]
            return np.sum((b[:, k] - self.a[k]) ** 2, axis=-1) - self.rho[k] ** 2
        cols = []
        for i in taut:
            d = self.a[i] - b[:, i]
            cols.append(np.column_stack([d, cross(b[:, i], d)]))
        cols.append(
            np.column_stack([np.broadcast_to(self.f, g.shape), cross(g, np.broadcast_to(self.f, g.shape)) + self.mz])
        )
        with np.errstate(invalid="ignore"):
            return np.linalg.det(np.stack(cols, -1))

    def scalar(self, theta):
        return float(self.residual(np.array([theta]))[0])


def sweep_equilibria(robot, lengths, margin=1e-6):
    """Every equilibrium the θ sweep finds whose tensions are clearly positive and whose slack
    cables are clearly short of their anchors: ``(taut, p, θ, stable or None)``."""
    a, r = raw_geometry(robot)
    f, mz, gp = raw_load(robot)
    n = len(a)
    grid = np.linspace(-np.pi, np.pi, SAMPLES)
    found = []
    subsets = [(i,) for i in range(n)]
    subsets += [(i, j) for i in range(n) for j in range(i + 1, n)]
    subsets += [(i, j, k) for i in range(n) for j in range(i + 1, n) for k in range(j + 1, n)]
    for taut in subsets:
        for side in (1.0, -1.0) if len(taut) > 1 else (1.0,):
            br = Branch(robot, lengths, taut, side)
            h = br.residual(grid)
            for k in np.flatnonzero(np.isfinite(h[:-1]) & np.isfinite(h[1:]) & (np.sign(h[:-1]) != np.sign(h[1:]))):
                theta = brentq(br.scalar, grid[k], grid[k + 1], xtol=1e-14, rtol=1e-15)
                b, p, R = br.anchors(np.array([theta]))
                b, p, R = b[0], p[0], R[0]
                d = a - b
                reach = np.linalg.norm(d, axis=1)
                W = np.vstack([d[list(taut)].T, cross(b[list(taut)], d[list(taut)])])
                g = p + R @ gp
                load = np.array([*f, cross(g, f) + mz])
                t, *_ = np.linalg.lstsq(W, -load, rcond=None)
                if np.abs(W @ t + load).max() > 1e-8 * np.linalg.norm(f):
                    continue  # a sign change across the seam of a branch, not a root
                slack = [i for i in range(n) if i not in taut]
                tau = t * reach[list(taut)]
                if np.all(tau > margin * np.linalg.norm(f)) and np.all(reach[slack] < lengths[slack] - margin):
                    found.append((taut, p, theta, br))
    return found


def potential_curvature(br, theta, f, mz, gp, step=1e-4):
    """``V''(θ)`` of the potential ``V = −f·g − m_z θ`` along the branch (one degree of freedom)."""

    def V(t):
        _, p, R = br.anchors(np.array([t]))
        return -f @ (p[0] + R[0] @ gp) - mz * t

    return (V(theta + step) - 2.0 * V(theta) + V(theta - step)) / step**2


def clear_of_borders(robot, lengths, sol, margin=1e-6):
    """The solution's taut tensions are clearly positive and its slack cables clearly short."""
    a, r = raw_geometry(robot)
    reach = np.linalg.norm(a - sol.position - r @ rot(sol.orientation[0]).T, axis=1)
    slack = [i for i in range(len(a)) if i not in sol.taut]
    size = np.linalg.norm(raw_load(robot)[0])
    return bool(np.all(sol.tensions[list(sol.taut)] > margin * size) and np.all(reach[slack] < lengths[slack] - margin))


def same_pose(sol, p, theta, tol=1e-6):
    return np.allclose(sol.position, p, atol=tol) and abs(math.remainder(sol.orientation[0] - theta, 2 * math.pi)) < tol


#: 30 random planar robots: 2, 3 and 4 cables, lengths perturbed by 2 %, 0.5 % (some hang on
#: three cables) or not at all (4 cables: the drawn pose reaches every anchor)
SUITE = [(2, s, 0.02) for s in range(8)] + [(3, s, 0.02) for s in range(8)] + [(3, s, 0.005) for s in range(6)]
SUITE += [(4, s, 0.0) for s in range(4, 12)]


@pytest.mark.parametrize("n, seed, perturbation", SUITE)
def test_random_planar_robot_against_the_theta_sweep(n, seed, perturbation):
    robot, lengths = random_planar_robot(n, seed=seed, perturbation=perturbation)
    res = solve_dgp(robot, lengths)
    assert res.complete
    for sol in res.solutions:
        check_planar_equilibrium(robot, lengths, sol)
    f, mz, gp = raw_load(robot)
    swept = sweep_equilibria(robot, lengths)
    assert swept, "every suite robot hangs somewhere"
    for taut, p, theta, br in swept:
        hits = [s for s in res.solutions if s.taut == taut and same_pose(s, p, theta)]
        assert len(hits) == 1, (taut, p, theta)
        # stability from the potential along the one free motion (two cables), or by
        # geometry: one cable hangs stably with its load point below the anchor, three
        # taut cables hold the platform rigidly
        if len(taut) == 2:
            curvature = potential_curvature(br, theta, f, mz, gp)
            if abs(curvature) > 1e-3 * np.linalg.norm(f):
                assert hits[0].stable == (curvature > 0), (taut, curvature)
        elif len(taut) == 1:
            g = p + rot(theta) @ gp
            b = p + rot(theta) @ raw_geometry(robot)[1][taut[0]]
            assert hits[0].stable == ((g - b) @ f > 0)
        else:
            assert hits[0].stable
    # and the solver reports nothing the sweep does not, clear of every border (the lengths
    # of a pose that reaches every anchor put some equilibria on one)
    assert len([s for s in res.solutions if clear_of_borders(robot, lengths, s)]) == len(swept)


def test_the_suite_has_every_kind_of_equilibrium():
    """The 30 robots above are not all alike: one, two and three taut cables, stable and unstable."""
    kinds = set()
    for n, seed, perturbation in SUITE:
        robot, lengths = random_planar_robot(n, seed=seed, perturbation=perturbation)
        kinds |= {(len(s.taut), s.stable) for s in solve_dgp(robot, lengths).solutions}
    assert {(1, True), (2, True), (2, False), (3, True)} <= kinds


# ---- the built-in examples ----------------------------------------------------------------


def test_planar_2cable_at_its_reference_lengths():
    robot = example("planar-2cable")
    lengths = np.array(robot.reference.lengths)
    res = solve_dgp(robot)
    assert res.complete and res.subproblems == 3
    for sol in res.solutions:
        check_planar_equilibrium(robot, lengths, sol)
    assert [s.stable for s in res.solutions].count(True) == 1
    stable = next(s for s in res.solutions if s.stable)
    assert np.allclose([*stable.position, *stable.orientation], robot.reference.poses["stable"], atol=1e-6)
    swept = sweep_equilibria(robot, lengths)
    assert len(swept) == len(res.solutions) == 2


def test_planar_4cable_hangs_on_its_upper_cables():
    """The fully constrained planar-4cable robot with every cable 1 % longer than at its
    home pose: it sags onto its two upper cables."""
    robot = example("planar-4cable")
    a, r = raw_geometry(robot)
    lengths = 1.01 * np.linalg.norm(a - r, axis=1)
    res = solve_dgp(robot, lengths)
    assert res.complete
    assert [s.taut for s in res.solutions] == [(2, 3)] and res.solutions[0].stable
    for sol in res.solutions:
        check_planar_equilibrium(robot, lengths, sol)
    assert len(sweep_equilibria(robot, lengths)) == 1


def test_planar_4cable_at_its_home_lengths_is_a_border_equilibrium():
    """At the exact home lengths every cable reaches its anchor at the home pose, where the
    weight hangs on the upper two: reported once, with the lower two on its border."""
    robot = example("planar-4cable")
    a, r = raw_geometry(robot)
    lengths = np.linalg.norm(a - r, axis=1)
    res = solve_dgp(robot, lengths)
    assert res.complete and len(res.solutions) == 1
    (sol,) = res.solutions
    assert sol.taut == (2, 3) and sol.boundary == (0, 1, 2, 3)
    assert np.allclose([*sol.position, *sol.orientation], 0.0, atol=1e-9)
    check_planar_equilibrium(robot, lengths, sol)


# ---- one taut cable -----------------------------------------------------------------------


def hanging_bar(**platform):
    cables = (Cable(exit=(-1.0, 2.0), anchor=(-0.25, 0.0)), Cable(exit=(1.0, 2.0), anchor=(0.25, 0.0)))
    return Robot(name="bar", dimension=2, platform=Platform(kind="rigid", mass=1.0, **platform), cables=cables)


def test_one_cable_hangs_its_load_point_below_the_anchor():
    robot = hanging_bar(wrench_point=(0.05, -0.1))
    lengths = np.array([1.0, 3.0])  # cable 2 long enough to be slack either way
    res = solve_dgp(robot, lengths)
    assert res.complete
    one = [s for s in res.solutions if s.taut == (0,)]
    assert len(one) == 2 and sorted(s.stable for s in one) == [False, True]
    for s in one:
        check_planar_equilibrium(robot, lengths, s)
        assert s.continuum is None
        R = rot(s.orientation[0])
        g, b = s.position + R @ [0.05, -0.1], s.position + R @ [-0.25, 0.0]
        assert abs(g[0] - b[0]) < 1e-12 and abs(b[0] + 1.0) < 1e-12  # G and B on the exit's vertical
        assert (g[1] < b[1]) == s.stable
    assert len([s for s in sweep_equilibria(robot, lengths) if len(s[0]) == 1]) == 2


def test_one_cable_through_the_load_point_is_a_continuum_of_angles():
    """The load point on the anchor: every angle balances, those where the slack cable fits form
    an arc, reported at its middle."""
    robot = hanging_bar(wrench_point=(-0.25, 0.0))
    lengths = np.array([1.0, 2.0])
    res = solve_dgp(robot, lengths, max_taut=1)
    (sol,) = [s for s in res.solutions if s.taut == (0,)]
    lo, hi = sol.continuum
    assert any(lo < sol.orientation[0] + k * 2 * np.pi < hi for k in (0, 1, 2))
    a, r = raw_geometry(robot)
    b0 = a[0] + [0.0, -1.0]
    for theta in np.linspace(lo, hi, 50)[1:-1]:
        assert np.linalg.norm(b0 + rot(theta) @ (r[1] - r[0]) - a[1]) <= 2.0 + 1e-12
    for theta in (lo - 1e-3, hi + 1e-3):
        assert np.linalg.norm(b0 + rot(theta) @ (r[1] - r[0]) - a[1]) > 2.0
    check_planar_equilibrium(robot, lengths, sol)
    assert not sol.stable


# ---- properties ---------------------------------------------------------------------------


def shifted(robot, d):
    cables = tuple(c.model_copy(update={"exit": (c.exit[0] + d[0], c.exit[1] + d[1])}) for c in robot.cables)
    return robot.model_copy(update={"cables": cables})


@settings(max_examples=8, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(2, 4), dx=st.floats(-5, 5), dy=st.floats(-5, 5))
def test_moving_the_frame_moves_the_equilibria(seed, n, dx, dy):
    """Translating every exit point translates every equilibrium, its angle and tensions kept."""
    robot, lengths = random_planar_robot(n, seed=seed)
    res = solve_dgp(robot, lengths)
    moved = solve_dgp(shifted(robot, (dx, dy)), lengths)
    assert res.complete and moved.complete
    assert [s.taut for s in res.solutions] == [s.taut for s in moved.solutions]
    for s, t in zip(res.solutions, moved.solutions):
        assert np.allclose(t.position, s.position + [dx, dy], atol=1e-7)
        assert abs(math.remainder(t.orientation[0] - s.orientation[0], 2 * math.pi)) < 1e-7
        assert np.allclose(t.tensions, s.tensions, rtol=1e-6, atol=1e-9) and t.stable == s.stable
        check_planar_equilibrium(shifted(robot, (dx, dy)), lengths, t)


# ---- inverse problem and tracking ---------------------------------------------------------


def check_igp_solution(robot, sol, fixed):
    """An IGP solution from the data: the assigned coordinates kept, the reported lengths the
    spans, and an equilibrium at those lengths."""
    pose = [*sol.position, *sol.orientation]
    for k, name in enumerate(("x", "y", "theta")):
        if name in fixed:
            assert pose[k] == pytest.approx(fixed[name], abs=1e-12)
    a, r = raw_geometry(robot)
    b = sol.position + r @ rot(sol.orientation[0]).T
    assert np.allclose(sol.lengths, np.linalg.norm(a - b, axis=1), atol=1e-12)
    check_planar_equilibrium(robot, sol.lengths, sol)


@pytest.mark.parametrize(
    "taut, fixed",
    [((0, 1), {"x": 0.0, "y": 0.3}), ((0, 1), {"x": 0.0, "theta": -0.2}), ((0,), {"y": 0.6})],
)
def test_igp_solutions_are_equilibria_the_dgp_finds(taut, fixed):
    robot = example("planar-2cable")
    res = solve_igp(robot, taut, fixed)
    assert res.complete and res.solutions
    for sol in res.solutions:
        check_igp_solution(robot, sol, fixed)
        fk = solve_dgp(robot, sol.lengths)
        assert any(
            same_pose(s, sol.position, sol.orientation[0], 1e-7) and s.stable == sol.stable for s in fk.solutions
        )


def test_igp_with_every_coordinate_assigned_solves_the_statics():
    robot = example("planar-4cable")
    res = solve_igp(robot, [1, 2, 3], {"x": 0.1, "y": 0.2, "theta": 0.05})
    assert res.complete and len(res.solutions) <= 1
    for sol in res.solutions:
        check_igp_solution(robot, sol, {"x": 0.1, "y": 0.2, "theta": 0.05})


@pytest.mark.parametrize(
    "taut, fixed, error",
    [
        ([0, 1], {"x": 0.0}, PoseError),
        ([0, 1], {"x": 0.0, "z": 1.0}, PoseError),
        ([0, 1, 2, 3], {"x": 0.0, "y": 0.0, "theta": 0.0}, CableSetError),
        ([], {}, CableSetError),
    ],
)
def test_igp_refuses_what_a_planar_platform_cannot_have(taut, fixed, error):
    with pytest.raises(error):
        solve_igp(example("planar-4cable"), taut, fixed)


def test_tracking_follows_the_dgp_and_changes_taut_set():
    """Paying cable 2 out of the stable pose of planar-2cable: the tracked equilibria are those
    the DGP finds at every step, until cable 2 goes slack and the bar hangs on cable 1."""
    robot = example("planar-2cable")
    start = next(s for s in solve_dgp(robot).solutions if s.stable)
    rows = np.array(robot.reference.lengths) + np.linspace(0.0, 1.5, 31)[:, None] * [0.0, 1.0]
    path = track_path(robot, start, rows)
    assert path[0].taut == (0, 1) and path[-1].taut == (0,)
    for sol, lengths in zip(path[::5], rows[::5]):
        check_planar_equilibrium(robot, lengths, sol)
        fk = solve_dgp(robot, lengths)
        assert any(s.taut == sol.taut and same_pose(s, sol.position, sol.orientation[0]) for s in fk.solutions)
    moved = track_equilibrium(robot, start, rows[1])
    assert same_pose(moved, path[1].position, path[1].orientation[0], 1e-12)


def test_tracking_refuses_lengths_of_the_wrong_count():
    robot = example("planar-2cable")
    start = solve_dgp(robot).solutions[0]
    with pytest.raises(TautError):
        track_equilibrium(robot, start, [1.0, 1.0, 1.0])
    with pytest.raises(TrackingLostError):
        track_equilibrium(robot, start, [0.2, 0.2])  # no equilibrium: the cables cannot reach the bar


# ---- degenerate robots --------------------------------------------------------------------


def test_coincident_exits_terminate_complete():
    """Two cables from one exit point: the bar hangs from it as from a single pulley."""
    cables = (Cable(exit=(0.0, 2.0), anchor=(-0.25, 0.0)), Cable(exit=(0.0, 2.0), anchor=(0.25, 0.0)))
    robot = Robot(
        name="v", dimension=2, platform=Platform(kind="rigid", mass=1.0, wrench_point=(0.05, -0.1)), cables=cables
    )
    lengths = np.array([1.5, 1.6])
    res = solve_dgp(robot, lengths, max_boxes=200_000)
    assert res.complete and res.solutions
    for sol in res.solutions:
        check_planar_equilibrium(robot, lengths, sol)
    assert len(res.solutions) == len(sweep_equilibria(robot, lengths))


def test_collinear_robot_terminates_with_an_honest_answer():
    """Every exit on one horizontal line, every platform point on the bar and the load point
    on the middle anchor: with the middle cable alone taut every angle balances.  The search
    terminates complete; that family is reported as the arc of angles where the other cables
    stay slack (its middle), and where the arc ends on another cable reaching its anchor, as
    border equilibria of the two-cable sets."""
    cables = tuple(Cable(exit=(x, 2.0), anchor=(0.25 * x, 0.0)) for x in (-1.0, 0.0, 1.0))
    robot = Robot(
        name="collinear",
        dimension=2,
        platform=Platform(kind="rigid", mass=1.0, wrench_point=(0.0, 0.0)),
        cables=cables,
    )
    lengths = np.array([1.9, 1.8, 2.1])
    res = solve_dgp(robot, lengths, max_boxes=20_000)
    assert res.complete
    for sol in res.solutions:
        check_planar_equilibrium(robot, lengths, sol)
    (family,) = [s for s in res.solutions if s.continuum is not None]
    ends = sorted(s.orientation[0] for s in res.solutions if s.taut == (1,) and s.boundary is not None)
    assert family.taut == (1,) and len(ends) == 2
    assert ends[0] < family.orientation[0] < ends[1]
    assert np.allclose(np.array(family.continuum) - 2 * np.pi, ends, atol=1e-6) or np.allclose(
        family.continuum, ends, atol=1e-6
    )


def test_a_platform_that_is_a_single_point_is_refused_in_one_line(tmp_path, taut_cli):
    cables = (Cable(exit=(-1.0, 2.0), anchor=(0.0, 0.0)), Cable(exit=(1.0, 2.0), anchor=(0.0, 0.0)))
    robot = Robot(
        name="point",
        dimension=2,
        platform=Platform(kind="rigid", mass=1.0),
        cables=cables,
        reference=Reference(lengths=(2.0, 2.0)),
    )
    with pytest.raises(TautError, match="coincide"):
        solve_dgp(robot)
    path = tmp_path / "point.yaml"
    save_robot(robot, path)
    run = taut_cli("fk", str(path))
    assert run.code == 2 and run.err.startswith("taut: error:") and run.err.count("\n") == 1


# ---- the command line ---------------------------------------------------------------------


@pytest.mark.slow
def test_fk_planar_2cable_json(taut_cli, tmp_path):
    robot = example("planar-2cable")
    plot = tmp_path / "equilibria.png"
    data = taut_cli("fk", "planar-2cable", "--json", "--plot", str(plot)).json()
    assert plot.stat().st_size > 10_000  # one planar panel per equilibrium
    assert data["complete"] is True and len(data["solutions"]) == 2
    for s in data["solutions"]:
        assert len(s["position"]) == 2 and len(s["orientation"]) == 1 and s["taut"] == [1, 2]
        sol = SimpleNamespace(
            position=np.array(s["position"]),
            orientation=np.array(s["orientation"]),
            tensions=np.array(s["tensions"]),
            taut=tuple(i - 1 for i in s["taut"]),
        )
        check_planar_equilibrium(robot, np.array(robot.reference.lengths), sol)


@pytest.mark.slow
def test_igp_on_a_planar_robot_through_the_cli(taut_cli):
    data = taut_cli("igp", "planar-2cable", "--taut", "1,2", "--fix", "x=0,y=0.3", "--json").json()
    assert data["complete"] is True and data["assigned"] == {"x": 0.0, "y": 0.3}
    assert len(data["solutions"]) == 2
    lengths = data["solutions"][0]["lengths"]
    fk = taut_cli("fk", "planar-2cable", "--lengths", ",".join(repr(v) for v in lengths), "--json").json()
    theta = data["solutions"][0]["orientation"][0]
    assert any(
        np.allclose(s["position"], [0.0, 0.3], atol=1e-7) and abs(s["orientation"][0] - theta) < 1e-7
        for s in fk["solutions"]
    )
    box = taut_cli("igp", "planar-2cable", "--taut", "1,2", "--fix", "x=0,y=0.3", "--box", "0,0,0,1,1,1")
    assert box.code == 2 and "xmin,ymin,xmax,ymax" in box.err and box.err.count("\n") == 1


@pytest.mark.parametrize("lengths", ["1.5,1.7,1.0", "1.5,-1.7", "1.5,nan"])
def test_bad_lengths_get_one_line(lengths, taut_cli):
    run = taut_cli("fk", "planar-2cable", "--lengths", lengths)
    assert run.code == 2 and run.err.startswith("taut: error:") and run.err.count("\n") == 1 and not run.out


@pytest.mark.slow
def test_inconsistent_lengths_have_no_equilibrium(taut_cli):
    """Cables too short to hold the bar between their exits: no equilibrium, and that is complete."""
    data = taut_cli("fk", "planar-2cable", "--lengths", "0.5,0.6", "--json").json()
    assert data["solutions"] == [] and data["complete"] is True
    assert json.loads(json.dumps(data)) == data
