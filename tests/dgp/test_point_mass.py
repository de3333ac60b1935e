"""Equilibria of point-mass platforms, spatial and planar (taut.dgp._point_mass): every
reported equilibrium checked from the robot's data alone, and on random robots a second
formulation — closed-form trilateration of every taut subset (the intersection of its
spheres or circles with the plane of the load) and the linear statics there — finds no
equilibrium the solver missed, nor the solver one it does not.  The CLI through
subprocesses."""

from itertools import combinations
from types import SimpleNamespace

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import taut
from taut.dgp import solve_dgp, solve_igp, track_equilibrium, track_path
from taut.errors import CableSetError, TautError, TrackingLostError
from taut.model import Cable, Platform, Robot, random_point_mass_robot

#: Seeds of the random suites: 30 robots of each kind.
SEEDS = range(30)


def load_of(robot):
    """The force on the point mass, from the robot file's fields (weight: mass × gravity)."""
    f = np.zeros(robot.dimension)
    if robot.platform.wrench is not None:
        f += np.asarray(robot.platform.wrench, float)
    if robot.platform.mass is not None:
        g = robot.platform.gravity
        f += robot.platform.mass * (np.asarray(g, float) if g is not None else -9.81 * np.eye(robot.dimension)[-1])
    return f


def check_equilibrium(robot, lengths, sol):
    """One reported equilibrium against the raw data: position of d numbers, no angles, the
    taut cables at their lengths (1e-9), the slack ones within theirs, tensions ≥ 0 along the
    cables balancing the load."""
    a = np.array([c.exit for c in robot.cables], float)
    d = robot.dimension
    p = np.asarray(sol.position)
    assert p.shape == (d,) and np.asarray(sol.orientation).size == 0
    reach = np.linalg.norm(a - p, axis=1)
    taut_ = list(sol.taut)
    slack = [k for k in range(robot.n_cables) if k not in taut_]
    assert np.abs(reach[taut_] - lengths[taut_]).max() <= 1e-9 * max(1.0, lengths.max())
    assert np.all(reach[slack] <= lengths[slack] * (1 + 1e-12))
    tau = np.asarray(sol.tensions)
    assert np.all(tau >= 0.0) and np.all(tau[slack] == 0.0)
    f = load_of(robot)
    force = ((a - p) / reach[:, None] * tau[:, None]).sum(axis=0) + f
    assert np.abs(force).max() <= 1e-9 * np.linalg.norm(f)
    assert sol.stable  # a point mass hangs at the lowest point its cables allow


def _circle(c1, c2, r1, r2):
    """Centre, radius² and unit axis of the intersection of two spheres (circles: two
    points along the normal)."""
    e = c2 - c1
    dist = np.linalg.norm(e)
    e = e / dist
    x = (r1**2 - r2**2 + dist**2) / (2 * dist)
    return c1 + x * e, r1**2 - x**2, e


def candidates(a, rho, f, taut_):
    """Closed-form positions where the taut cables ``taut_`` reach their lengths and the
    load can lie in the span of the cables (trilateration)."""
    d = a.shape[1]
    c = a[list(taut_)]
    r = rho[list(taut_)]
    m = len(taut_)
    if m == 1:
        return [c[0] + r[0] * f / np.linalg.norm(f)]
    centre, h2, e = _circle(c[0], c[1], r[0], r[1])
    if h2 < 0:
        return []
    h = np.sqrt(h2)
    if h == 0.0:  # tangent spheres: one point
        return [centre]
    if d == 2:
        n = np.array([-e[1], e[0]])
        return [centre + h * n, centre - h * n]
    if m == 2:  # in the plane through both exits parallel to the load
        w = f - (f @ e) * e
        if np.linalg.norm(w) < 1e-12 * np.linalg.norm(f):
            return []
        w /= np.linalg.norm(w)
        return [centre + h * w, centre - h * w]
    # three spheres: the circle of the first two cut by the plane ‖p − c3‖ = r3
    u = c[2] - centre
    u_perp = u - (u @ e) * e
    if np.linalg.norm(u_perp) < 1e-12:
        return []
    ey = u_perp / np.linalg.norm(u_perp)
    ez = np.cross(e, ey)
    # points centre + h (cos φ ey + sin φ ez): ‖p − c3‖² = r3² fixes cos φ
    cos_phi = (h2 + u @ u - r[2] ** 2) / (2 * h * (u @ ey))
    if abs(cos_phi) > 1:
        return []
    sin_phi = np.sqrt(1 - cos_phi**2)
    return [centre + h * (cos_phi * ey + s * sin_phi * ez) for s in (1.0, -1.0)]


def brute_force(robot, lengths, margin=1e-7):
    """Every equilibrium by trilateration and linear statics, over all taut subsets of up to
    ``d`` cables: ``(taut, position, clear)``, ``clear`` when every tension and every slack
    cable's clearance exceeds ``margin`` (relative) — an equilibrium no solver may miss."""
    a = robot.exits
    f = load_of(robot)
    d = robot.dimension
    scale = np.linalg.norm(f)
    out = []
    for m in range(1, min(d, robot.n_cables) + 1):
        for taut_ in combinations(range(robot.n_cables), m):
            for p in candidates(a, lengths, f, taut_):
                A = (a[list(taut_)] - p).T
                t, *_ = np.linalg.lstsq(A, -f, rcond=None)
                if np.abs(A @ t + f).max() > 1e-8 * scale:
                    continue
                reach = np.linalg.norm(a - p, axis=1)
                slack = [k for k in range(robot.n_cables) if k not in taut_]
                tau = t * lengths[list(taut_)]
                if np.any(tau < -margin * scale) or np.any(reach[slack] > lengths[slack] * (1 + margin)):
                    continue
                clear = bool(np.all(tau > margin * scale) and np.all(reach[slack] < lengths[slack] * (1 - margin)))
                out.append((taut_, p, clear))
    return out


def same_equilibria(robot, lengths):
    """Solve and compare with :func:`brute_force` both ways; returns the result."""
    res = solve_dgp(robot, lengths)
    assert res.complete
    for sol in res.solutions:
        check_equilibrium(robot, lengths, sol)
    found = brute_force(robot, lengths)
    for taut_, p, clear in found:
        if clear:
            assert any(s.taut == taut_ and np.allclose(s.position, p, atol=1e-7) for s in res.solutions), (taut_, p)
    for s in res.solutions:
        assert any(s.taut == t and np.allclose(s.position, p, atol=1e-7) for t, p, _ in found), s
    # the lowest point of an intersection of balls: at most one position
    positions = np.array([s.position for s in res.solutions]).reshape(-1, robot.dimension)
    assert all(np.abs(positions - q).max() <= 1e-9 for q in positions)
    return res


@pytest.mark.slow
@pytest.mark.parametrize("dimension", [3, 2])
def test_random_point_masses_against_trilateration(dimension):
    """30 random robots of each kind (2 to 8 cables spatial, 2 to 6 planar), their lengths
    perturbed by 2, 10, 30 or 60 %: some hang on fewer cables, some have no equilibrium."""
    counts = {0: 0, 1: 0}
    for seed in SEEDS:
        high = 8 if dimension == 3 else 6
        n = 2 + seed % (high - 1)
        robot, lengths = random_point_mass_robot(
            n, dimension=dimension, seed=seed, perturbation=(0.02, 0.1, 0.3, 0.6)[seed % 4]
        )
        res = same_equilibria(robot, lengths)
        counts[min(len(res.solutions), 1)] += 1
    assert counts[0] > 0 and counts[1] > 0  # the suite has both answers


@settings(max_examples=20, deadline=None)
@given(
    lengths=st.lists(st.floats(0.5, 6.0), min_size=3, max_size=3),
    mass=st.floats(0.1, 20.0),
)
def test_planar_three_cables_any_lengths(lengths, mass):
    """Any lengths of a planar 3-cable point mass: what the solver reports is exactly what
    trilateration finds, at most one position, stable.  Lengths whose circles touch (two
    cables meeting in a single point, as 2 and 2 from exits 4 m apart) are left out: there the
    tensions of an equilibrium grow without bound and the search ends undecided, not
    complete (measure zero among the lengths)."""
    exits = np.array([(0.0, 3.0), (4.0, 3.0), (1.5, 4.0)])
    for i, j in ((0, 1), (0, 2), (1, 2)):
        d = float(np.linalg.norm(exits[i] - exits[j]))
        assume(abs(lengths[i] + lengths[j] - d) > 1e-6 and abs(abs(lengths[i] - lengths[j]) - d) > 1e-6)
    robot = Robot(
        name="planar 3-cable point mass",
        dimension=2,
        platform=Platform(kind="point-mass", mass=mass),
        cables=(Cable(exit=(0.0, 3.0)), Cable(exit=(4.0, 3.0)), Cable(exit=(1.5, 4.0))),
    )
    same_equilibria(robot, np.array(lengths))


def test_one_taut_cable_hangs_straight_below_its_exit():
    """Long other cables: the mass hangs on cable 1 alone, at its length straight along the
    load from its exit — a point (no spin continuum as for a rigid body)."""
    robot = Robot(
        name="three exits",
        dimension=3,
        platform=Platform(kind="point-mass", mass=2.0, wrench=(1.0, 0.0, 0.0)),
        cables=(Cable(exit=(0.0, 0.0, 3.0)), Cable(exit=(4.0, 0.0, 3.0)), Cable(exit=(2.0, 3.0, 3.0))),
    )
    lengths = np.array([1.5, 10.0, 10.0])
    res = solve_dgp(robot, lengths)
    assert res.complete and len(res.solutions) == 1
    (sol,) = res.solutions
    f = np.array([1.0, 0.0, -2.0 * 9.81])
    np.testing.assert_allclose(sol.position, robot.exits[0] + 1.5 * f / np.linalg.norm(f), atol=1e-12)
    assert sol.taut == (0,) and sol.continuum is None and sol.tensions[0] == pytest.approx(np.linalg.norm(f))
    check_equilibrium(robot, lengths, sol)


def test_lengths_without_equilibrium_are_no_solution_and_complete():
    """Cables 1 and 3 of the camera crane cannot both reach: the lengths admit no
    equilibrium, and the search says so completely (no least-squares guess)."""
    robot = taut.example("camera-4cable")
    lengths = np.array([10.0, 30.0, 10.0, 30.0])  # exits 36 m apart on the diagonal
    res = solve_dgp(robot, lengths)
    assert res.solutions == () and res.complete
    assert brute_force(robot, lengths) == []


@pytest.mark.parametrize("name", ["camera-4cable", "printer-5cable"])
def test_examples_hang_where_their_notes_say(name):
    robot = taut.example(name)
    lengths = np.array(robot.reference.lengths)
    res = same_equilibria(robot, lengths)
    (sol,) = res.solutions
    np.testing.assert_allclose(sol.position, robot.reference.poses["equilibrium"], atol=5e-4)
    expected = {"camera-4cable": (1, 2, 3), "printer-5cable": (0, 2, 3)}[name]
    assert sol.taut == expected


def test_point_mass_without_load_is_refused():
    robot = Robot(
        name="weightless",
        dimension=2,
        platform=Platform(kind="point-mass"),
        cables=(Cable(exit=(0.0, 1.0)), Cable(exit=(1.0, 1.0))),
    )
    with pytest.raises(TautError, match="without a load"):
        solve_dgp(robot, [1.0, 1.0])


@pytest.mark.parametrize(
    "exits, lengths, complete",
    [
        # all exits on one line: the plane of two taut cables is not fixed by their exits
        ([(0.0, 0.0, 3.0), (1.0, 0.0, 3.0), (2.0, 0.0, 3.0), (3.0, 0.0, 3.0)], [2.0, 2.2, 2.8, 3.6], True),
        # nearly coincident exits (1e-9 m apart), equal lengths
        ([(0.0, 0.0, 3.0), (1e-9, 0.0, 3.0), (2.0, 1.0, 3.0)], [2.0, 2.0, 2.5], True),
        # exits on the vertical, their circles all tangent at the origin: a singular equilibrium
        ([(0.0, 1.0), (0.0, 2.0), (0.0, 3.0)], [1.0, 2.0, 3.0], False),
    ],
)
def test_degenerate_robots_terminate(exits, lengths, complete):
    """Degenerate exits end within the box budget (the multi-precision search of narrow
    boxes has its own, :data:`taut.interval.MAX_PRECISE_BOXES`, and is left out to keep this
    quick): what is found is an equilibrium, and a singular one leaves the answer
    incomplete, with its undecided boxes, rather than hanging."""
    robot = Robot(
        name="degenerate",
        dimension=len(exits[0]),
        platform=Platform(kind="point-mass", mass=1.0),
        cables=tuple(Cable(exit=e) for e in exits),
    )
    lengths = np.array(lengths)
    res = solve_dgp(robot, lengths, max_boxes=20_000, multiprecision=False)
    assert res.complete == complete and res.solutions
    for sol in res.solutions:
        check_equilibrium(robot, lengths, sol)
    if complete:
        for _, p, clear in brute_force(robot, lengths):
            assert not clear or any(np.allclose(s.position, p, atol=1e-7) for s in res.solutions)
    else:
        assert {u.cause for u in res.undecided_enclosures} <= {"budget", "narrow"}
        assert all(np.allclose(s.position, 0.0, atol=1e-12) for s in res.solutions)


# ---- more than d cables at their lengths: one equilibrium, one solution ----------------------


def pose_under(robot, rng):
    """A position under the exits: in the middle half of their horizontal span, 20–70 % of
    the lowest exit's height."""
    a = robot.exits
    lo, hi = a[:, :-1].min(axis=0), a[:, :-1].max(axis=0)
    across = (lo + hi) / 2 + rng.uniform(-0.25, 0.25, lo.size) * (hi - lo)
    return np.array([*across, rng.uniform(0.2, 0.7) * a[:, -1].min()])


def balanced_with_every_cable(robot, p):
    """Whether the load at ``p`` is balanced by non-negative tensions along the cables
    (non-negative least squares on the unit directions, from the raw data)."""
    from scipy.optimize import nnls

    a = robot.exits
    f = load_of(robot)
    _, residual = nnls(((a - p) / np.linalg.norm(a - p, axis=1)[:, None]).T, -f)
    return residual <= 1e-9 * np.linalg.norm(f)


def check_one_at_pose(robot, lengths, p, solutions):
    """Exactly one solution, at ``p``, an equilibrium from the raw data, its ``boundary``
    every cable (all at their lengths there)."""
    assert len(solutions) == 1, solutions
    (sol,) = solutions
    np.testing.assert_allclose(sol.position, p, rtol=0.0, atol=1e-9)
    check_equilibrium(robot, lengths, sol)
    assert tuple(sol.boundary) == tuple(range(robot.n_cables))


@pytest.mark.slow
@pytest.mark.parametrize("dimension", [3, 2])
def test_exact_lengths_of_a_pose_give_one_solution(dimension):
    """The exact lengths of a position under the exits of a random point mass of d + 1 to 8
    (6 in the plane) cables: every cable at its length, several d-subsets balance the load
    (each a border solution, none inside another), one equilibrium — one solution, at the
    position when the cables can hold it there, its tensions one valid distribution."""
    at_pose = 0
    high = 8 if dimension == 3 else 6
    for seed in range(16):
        n = dimension + 1 + seed % (high - dimension)
        robot, _ = random_point_mass_robot(n, dimension=dimension, seed=seed)
        p = pose_under(robot, np.random.default_rng(1000 + seed))[:dimension]
        lengths = np.linalg.norm(robot.exits - p, axis=1)
        res = solve_dgp(robot, lengths)
        assert res.complete
        if balanced_with_every_cable(robot, p):
            at_pose += 1
            check_one_at_pose(robot, lengths, p, res.solutions)
        else:  # the mass hangs lower, on fewer cables: still one equilibrium
            (sol,) = res.solutions
            check_equilibrium(robot, lengths, sol)
    assert at_pose >= 10


@pytest.mark.slow
@pytest.mark.parametrize("name, dimension, cables", [("camera-4cable", 3, 4), ("random", 3, 7), ("random", 2, 5)])
def test_cli_fk_at_the_exact_ik_lengths_of_a_pose(taut_cli, tmp_path, name, dimension, cables):
    """``taut ik`` then ``taut fk`` at its lengths: one equilibrium, at the pose, every cable
    (1-based) at its length."""
    if name == "random":
        robot, _ = random_point_mass_robot(cables, dimension=dimension, seed=7)
        path = tmp_path / "robot.yaml"
        taut.save_robot(robot, path)
        name = str(path)
    else:
        robot = taut.example(name)
    p = pose_under(robot, np.random.default_rng(3))[:dimension]
    assert balanced_with_every_cable(robot, p)
    run = taut_cli("ik", name, "--pose=" + ",".join(map(repr, p.tolist())), "--json")
    assert run.code == 0, run.err
    lengths = run.json()["lengths"]
    run = taut_cli("fk", name, "--lengths", ",".join(map(repr, lengths)), "--json")
    assert run.code == 0, run.err
    data = run.json()
    assert data["complete"] is True
    zero_based = [SimpleNamespace(**sol) for sol in data["solutions"]]
    for sol in zero_based:
        sol.taut = tuple(i - 1 for i in sol.taut)
        sol.boundary = tuple(i - 1 for i in sol.boundary)
    check_one_at_pose(robot, np.array(lengths), p, zero_based)


# ---- the inverse problem and tracking ------------------------------------------------------


def test_igp_of_the_camera_at_its_measured_pose():
    """Cables 2, 3, 4 taut with the position fixed: the tensions of the linear statics, the
    lengths its distances, cable 1 slack."""
    robot = taut.example("camera-4cable")
    p = np.array([3.0, -4.0, 6.0])
    res = solve_igp(robot, [1, 2, 3], {"x": 3.0, "y": -4.0, "z": 6.0})
    assert res.complete and len(res.solutions) == 1
    (sol,) = res.solutions
    a = robot.exits
    t = np.linalg.solve((a[1:] - p).T, -load_of(robot))
    np.testing.assert_allclose(sol.tensions[1:], t * np.linalg.norm(a[1:] - p, axis=1), rtol=1e-12)
    np.testing.assert_allclose(sol.lengths, np.linalg.norm(a - p, axis=1), rtol=1e-14)
    assert sol.slack == (0,) and sol.stable and sol.orientation.size == 0


@pytest.mark.parametrize("dimension", [3, 2])
def test_igp_with_fewer_cables_finds_the_hanging_position(dimension):
    """One taut cable and its height fixed: the mass hangs straight below the exit."""
    robot, _ = random_point_mass_robot(3, dimension=dimension, seed=3)
    height = float(robot.exits[1, -1] - 1.0)
    res = solve_igp(robot, [1], {"z" if dimension == 3 else "y": height})
    assert res.complete and len(res.solutions) == 1
    (sol,) = res.solutions
    expected = robot.exits[1].copy()
    expected[-1] = height
    np.testing.assert_allclose(sol.position, expected, atol=1e-12)
    assert sol.lengths[1] == pytest.approx(1.0) and sol.tensions[1] == pytest.approx(-load_of(robot)[-1])


@pytest.mark.slow
def test_igp_of_a_planar_point_mass_in_a_box(taut_cli, tmp_path):
    """Planar: two taut cables fix the position and the linear statics the tensions; with one
    taut cable and ``y`` fixed the box of the free ``x`` has two corners of two numbers
    (``--box xmin,ymin,xmax,ymax``), and a box of three numbers is one line."""
    robot = Robot(
        name="planar point mass",
        dimension=2,
        platform=Platform(kind="point-mass", mass=1.0),
        cables=(Cable(exit=(0.0, 3.0)), Cable(exit=(4.0, 3.0))),
    )
    res = solve_igp(robot, [0, 1], {"x": 1.0, "y": 1.0})
    (sol,) = res.solutions
    p = np.array([1.0, 1.0])
    t = np.linalg.solve((robot.exits - p).T, [0.0, 9.81])
    np.testing.assert_allclose(sol.tensions, t * np.linalg.norm(robot.exits - p, axis=1), rtol=1e-12)
    path = tmp_path / "planar.yaml"
    taut.save_robot(robot, path)
    run = taut_cli("igp", str(path), "--taut", "1", "--fix", "y=1", "--box=-1,-5,5,2.9", "--json")
    assert run.code == 0, run.err
    (sol,) = run.json()["solutions"]
    assert sol["position"] == [0.0, 1.0] and sol["lengths"][0] == pytest.approx(2.0)
    run = taut_cli("igp", str(path), "--taut", "1", "--fix", "y=1", "--box=-1,-5,5")
    assert run.code == 2 and run.err.count("\n") == 1 and "xmin,ymin,xmax,ymax" in run.err


def test_igp_refuses_more_taut_cables_than_the_dimension():
    with pytest.raises(CableSetError, match="1 to 3 taut cables"):
        solve_igp(taut.example("camera-4cable"), [0, 1, 2, 3], {"x": 0, "y": 0, "z": 5, "a": 0})


@pytest.mark.parametrize("dimension", [3, 2])
def test_tracking_follows_the_unique_equilibrium(dimension):
    """Along a ramp of lengths, tracking (Newton + Krawczyk from the last step, taut-set
    switches included) lands where the complete DGP has its only equilibrium."""
    robot, lengths = random_point_mass_robot(4, dimension=dimension, seed=11, perturbation=0.0)
    start = solve_dgp(robot, lengths * 1.01).solutions[0]
    rows = lengths * 1.01 + np.linspace(0.0, 0.3, 7)[:, None] * np.array([0.0, 1.0, 0.0, 0.5])
    path = track_path(robot, start, rows)
    assert len(path) == len(rows)
    for sol, row in zip(path, rows):
        check_equilibrium(robot, row, sol)
        (ref,) = solve_dgp(robot, row).solutions
        np.testing.assert_allclose(sol.position, ref.position, atol=1e-9)
        assert sol.taut == ref.taut


def test_tracking_switches_to_a_cable_that_becomes_taut():
    """Shortening the camera's slack cable 1 by 1 cm: it becomes taut and another cable
    slack (a point hangs on at most three)."""
    robot = taut.example("camera-4cable")
    lengths = np.array(robot.reference.lengths)
    start = solve_dgp(robot, lengths).solutions[0]
    moved = lengths - [0.01, 0.0, 0.0, 0.0]
    sol = track_equilibrium(robot, start, moved)
    (ref,) = solve_dgp(robot, moved).solutions
    assert sol.taut == ref.taut and 0 in sol.taut
    np.testing.assert_allclose(sol.position, ref.position, atol=1e-9)


def test_tracking_into_lengths_without_equilibrium_is_lost():
    robot = taut.example("printer-5cable")
    lengths = np.array(robot.reference.lengths)
    start = solve_dgp(robot, lengths).solutions[0]
    with pytest.raises(TrackingLostError):
        track_equilibrium(robot, start, lengths * [1.0, 0.3, 1.0, 1.0, 1.0])


# ---- the command line --------------------------------------------------------------------------


@pytest.mark.slow
@pytest.mark.parametrize("name, taut_numbers", [("camera-4cable", [2, 3, 4]), ("printer-5cable", [1, 3, 4])])
def test_cli_fk_of_the_examples(taut_cli, name, taut_numbers):
    robot = taut.example(name)
    run = taut_cli("fk", name, "--json")
    assert run.code == 0, run.err
    data = run.json()
    assert data["complete"] is True and len(data["solutions"]) == 1
    sol = data["solutions"][0]
    assert sol["taut"] == taut_numbers and sol["orientation"] == [] and len(sol["position"]) == 3
    lengths = np.array(robot.reference.lengths)
    reach = np.linalg.norm(robot.exits - np.array(sol["position"]), axis=1)
    idx = [i - 1 for i in taut_numbers]
    np.testing.assert_allclose(reach[idx], lengths[idx], atol=1e-9)


@pytest.mark.slow
def test_cli_fk_inconsistent_lengths_no_equilibrium(taut_cli):
    run = taut_cli("fk", "camera-4cable", "--lengths", "10,30,10,30", "--json")
    assert run.code == 0, run.err
    data = run.json()
    assert data["solutions"] == [] and data["complete"] is True
    # apart, firmware's least-squares fit: a position, far from fitting these lengths
    fit = data["least_squares"]
    a = taut.example("camera-4cable").exits
    residuals = np.linalg.norm(a - np.array(fit["position"]), axis=1) - [10.0, 30.0, 10.0, 30.0]
    np.testing.assert_allclose(fit["residuals"], residuals, atol=1e-9)
    assert fit["rms_residual"] == pytest.approx(np.sqrt(np.mean(residuals**2))) and fit["rms_residual"] > 1.0


def test_least_squares_fit_is_apart_and_only_for_point_masses():
    """The camera's rounded lengths: the fit lands within a millimetre of the certified
    equilibrium (every cable nearly taut), a rigid robot has none."""
    robot = taut.example("camera-4cable")
    res = solve_dgp(robot)
    assert res.least_squares is not None and "least_squares" in res.as_dict()
    np.testing.assert_allclose(res.least_squares.position, res.solutions[0].position, atol=1e-3)
    assert solve_dgp(taut.example("suspended-3cable"), max_taut=1).least_squares is None


@pytest.mark.parametrize("lengths", ["1,2,3", "1,2,3,-4", "1,2,nan,4", "1,2,3,4,5"])
def test_cli_fk_bad_lengths_one_line(taut_cli, lengths):
    run = taut_cli("fk", "camera-4cable", "--lengths", lengths, "--json")
    assert run.code == 2 and run.out == ""
    assert run.err.startswith("taut: error: ") and run.err.count("\n") == 1


@pytest.mark.slow
def test_cli_igp_on_a_point_mass(taut_cli):
    run = taut_cli("igp", "printer-5cable", "--taut", "1,3,4", "--fix", "x=0.1,y=0.05,z=0.3", "--json")
    assert run.code == 0, run.err
    data = run.json()
    assert data["complete"] is True and len(data["solutions"]) == 1
    sol = data["solutions"][0]
    assert sol["taut"] == [1, 3, 4] and sol["slack"] == [2, 5] and sol["position"] == [0.1, 0.05, 0.3]
    robot = taut.example("printer-5cable")
    np.testing.assert_allclose(sol["lengths"], np.linalg.norm(robot.exits - [0.1, 0.05, 0.3], axis=1), rtol=1e-14)
    run = taut_cli("igp", "printer-5cable", "--taut", "1,2,3,4", "--fix", "x=0,y=0,z=0.3,a=0")
    assert run.code == 2 and run.err.count("\n") == 1 and "1 to 3 taut cables" in run.err
