"""Certified workspaces: every pose of an inner box passes the grid's point test, every pose
of an outer box fails it; volumes bracket the grid's estimate; the same boxes on every
executor; one-line refusals through the CLI."""

import json
import subprocess
import sys

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taut
from taut.errors import ArgumentError, GridSizeError, UnsupportedRobotError
from taut.interval import Interval, separating_directions, zonotope_verdicts
from taut.model import random_planar_robot, random_point_mass_robot
from taut.parallel import ProcessExecutor, get_executor
from taut.statics import BoxWrenchSet, wrench_feasible
from taut.workspace import WorkspaceCondition, certified, evaluate_workspace, make_condition


def contradictions(robot, res, condition, samples, seed=0, orientations=None, drawn=None):
    """Poses drawn uniformly in random boxes of each kind, judged by the point test (``drawn``
    collects how many)."""
    rng = np.random.default_rng(seed)
    cond = make_condition(condition)
    bad = 0
    for boxes, want in ((res.inner, True), (res.outer, False)):
        if not len(boxes):
            continue
        if drawn is not None:
            drawn.append(samples)
        pick = rng.integers(0, len(boxes), samples)
        P = rng.uniform(boxes[pick, :, 0], boxes[pick, :, 1])
        if orientations is None:
            O = np.broadcast_to(res.orientation, (samples, res.orientation.size))
        else:
            O = (
                orientations(rng, samples)
                if want
                else np.broadcast_to(res.orientation, (samples, res.orientation.size))
            )
        bad += int(np.sum(cond.evaluate(robot, np.hstack([P, O])) != want))
    return bad


@pytest.mark.parametrize(
    ("name", "condition", "eps"),
    [
        ("planar-4cable", "static", 0.01),
        ("planar-4cable", "wrench-feasible", 0.01),
        pytest.param("planar-4cable", "wrench-closure", 0.02, marks=pytest.mark.slow),
        pytest.param("camera-4cable", "static", 0.25, marks=pytest.mark.slow),
        pytest.param("printer-5cable", "wrench-closure", 0.25, marks=pytest.mark.slow),
    ],
)
def test_inner_and_outer_boxes_agree_with_the_point_test(name, condition, eps):
    robot = taut.example(name)
    res = certified(robot, condition, eps=eps)
    assert res.complete and len(res.inner) and len(res.outer)
    assert contradictions(robot, res, condition, 20_000) == 0
    # the three kinds tile the region
    total = res.inner_volume + res.outer_volume + res.undecided_volume
    assert total == pytest.approx(res.region_volume, rel=1e-9)
    assert np.all((res.undecided[:, :, 1] - res.undecided[:, :, 0]).max(axis=1) <= eps)


@pytest.mark.slow
def test_a_million_samples_across_the_built_in_robots_agree_with_the_point_test():
    """Every built-in robot a certificate takes, each of its kinds (planar and spatial, point
    mass and rigid, suspended and fully constrained) and the three conditions: no sample of
    an inner box fails the point test, none of an outer box passes it."""
    cases = [
        ("planar-4cable", "static", None, 0.01),
        ("planar-4cable", "wrench-feasible", None, 0.01),
        ("planar-4cable", "wrench-closure", None, 0.02),
        ("camera-4cable", "static", None, 0.25),
        ("printer-5cable", "wrench-closure", None, 0.25),
        ("robocrane", "static", None, 0.25),
        ("spatial-8cable", "wrench-feasible", [[0.0, 1.5], [0.0, 1.0], [0.0, 1.0]], 0.1),
        ("camera-4cable", "interference-free", None, 0.5),
    ]
    drawn: list[int] = []
    for seed, (name, condition, region, eps) in enumerate(cases):
        robot = taut.example(name)
        res = certified(robot, condition, region, eps=eps)
        assert res.complete and len(res.inner) + len(res.outer)
        assert contradictions(robot, res, condition, 80_000, seed=seed, drawn=drawn) == 0, (name, condition)
    assert sum(drawn) >= 1_000_000


@settings(max_examples=15, deadline=None)
@given(seed=st.integers(0, 2**31), n=st.integers(3, 5), kind=st.sampled_from(["planar", "point-mass"]))
def test_random_robots_are_certified_soundly(seed, n, kind):
    if kind == "planar":
        robot, _ = random_planar_robot(n, seed=seed)
    else:
        robot, _ = random_point_mass_robot(n, dimension=2, seed=seed)
    if robot.n_cables < robot.wrench_dim:
        with pytest.raises(UnsupportedRobotError, match="no interior"):
            certified(robot, "static")
        return
    res = certified(robot, "static", eps=0.1, max_boxes=20_000)
    assert contradictions(robot, res, "static", 3000, seed=seed) == 0


@settings(max_examples=20, deadline=None)
@given(seed=st.integers(0, 2**31), kind=st.sampled_from(["planar", "point-mass 2-D", "point-mass 3-D"]))
def test_interference_free_boxes_agree_with_the_capsule_test(seed, kind):
    """Cables that cross (planar robots), and cables sharing their anchor (point masses, cut
    back at the shared end as the point test cuts them)."""
    if kind == "planar":
        robot, _ = random_planar_robot(5, seed=seed)
    else:
        robot, _ = random_point_mass_robot(4, dimension=int(kind[-3]), seed=seed)
    res = certified(robot, "interference-free", eps=0.05, max_boxes=20_000)
    assert contradictions(robot, res, "interference-free", 3000, seed=seed) == 0


def test_crossing_cables_are_outside_for_every_orientation_of_a_box():
    robot, _ = random_planar_robot(5, seed=0)
    box = [[-0.05, 0.05]]
    res = certified(robot, "interference-free", eps=0.05, orientation_box=box, max_boxes=50_000)
    assert len(res.inner) and len(res.outer)

    def spread(rng, k):
        return rng.uniform(-0.05, 0.05, (k, 1))

    assert contradictions(robot, res, "interference-free", 20_000, orientations=spread) == 0


def test_every_orientation_of_an_orientation_box():
    robot = taut.example("planar-4cable")
    box = [[-0.05, 0.05]]
    res = certified(robot, "static", eps=0.02, orientation_box=box)
    fixed = certified(robot, "static", eps=0.02)
    assert 0 < res.inner_volume < fixed.inner_volume  # every orientation is asking more

    def spread(rng, k):
        return rng.uniform(-0.05, 0.05, (k, 1))

    assert contradictions(robot, res, "static", 20_000, orientations=spread) == 0


def test_spatial_rigid_platform_at_a_fixed_orientation():
    robot = taut.example("spatial-8cable")
    res = certified(robot, "wrench-feasible", [[0.2, 0.4], [0.1, 0.3], [0.0, 0.2]], eps=0.05)
    assert res.complete and res.inner_volume > 0
    assert contradictions(robot, res, "wrench-feasible", 5000) == 0


def test_volumes_bracket_the_grid_and_the_boundary_layer_halves_with_eps():
    robot = taut.example("planar-4cable")
    coarse, fine = (certified(robot, "static", eps=e) for e in (0.004, 0.002))
    grid = evaluate_workspace(robot, "static", resolution=401)
    area = grid.count / grid.size * coarse.region_volume
    for res in (coarse, fine):
        assert res.inner_volume <= area + 0.01 and area <= res.inner_volume + res.undecided_volume + 0.01
    assert fine.inner_volume >= coarse.inner_volume
    assert 0.35 < fine.undecided_volume / coarse.undecided_volume < 0.65


@pytest.mark.slow
@pytest.mark.parametrize(
    ("name", "region", "eps"),
    [("planar-4cable", None, 0.01), ("spatial-8cable", [[0.0, 1.5], [0.0, 1.0], [0.0, 1.0]], 0.1)],
)
def test_the_same_boxes_serial_on_processes_and_on_dask(name, region, eps):
    distributed = pytest.importorskip("distributed")
    robot = taut.example(name)
    serial = certified(robot, "wrench-feasible", region, eps=eps)
    with ProcessExecutor(2) as ex:
        runs = [certified(robot, "wrench-feasible", region, eps=eps, executor=ex)]
    with (
        distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster,
        get_executor(scheduler=cluster.scheduler_address) as ex,
    ):
        runs.append(certified(robot, "wrench-feasible", region, eps=eps, executor=ex))
    assert len(serial.inner) and len(serial.outer) and len(serial.undecided)
    for run in runs:
        for kind in ("inner", "outer", "undecided"):
            assert np.array_equal(getattr(serial, kind), getattr(run, kind))


def test_a_budget_that_runs_out_is_reported():
    res = certified(taut.example("planar-4cable"), "static", eps=0.001, max_boxes=50)
    assert not res.complete and res.evaluated <= 50
    assert res.inner_volume + res.outer_volume + res.undecided_volume == pytest.approx(res.region_volume)


class LeftHalf(WorkspaceCondition):
    """A condition of the user's own, which no certificate knows."""

    name = "left-half"

    def evaluate(self, robot, poses):
        return np.asarray(poses)[:, 0] < 0


@pytest.mark.parametrize(
    ("kwargs", "error", "match"),
    [
        ({"eps": 0.0}, ArgumentError, "eps must be a positive"),
        ({"region": [[0.0, 0.0], [0.0, 1.0]]}, ArgumentError, "region is empty"),
        ({"region": [[1.0, 0.0], [0.0, 1.0]]}, ArgumentError, "inverted"),
        ({"region": [[0.0, np.nan], [0.0, 1.0]]}, ArgumentError, "finite"),
        ({"eps": 1e-9, "region": [[-1e3, 1e3], [-1e3, 1e3]]}, GridSizeError, "1e12 boxes"),
        ({"condition": LeftHalf()}, ArgumentError, "'left-half' condition cannot be certified"),
        ({"orientation_box": [[0.3, 0.1]]}, ArgumentError, "inverted"),
        ({"max_boxes": 0}, ArgumentError, "max_boxes"),
    ],
)
def test_bad_input_is_refused(kwargs, error, match):
    kwargs = dict(kwargs)
    condition = kwargs.pop("condition", "static")
    region = kwargs.pop("region", None)
    with pytest.raises(error, match=match):
        certified(taut.example("planar-4cable"), condition, region, **kwargs)


@pytest.mark.parametrize(
    ("name", "match"),
    [("adjustable-8cable", "jointed bodies"), ("suspended-3cable", "no interior"), ("vscr-four-cable", "obstacles")],
)
def test_robots_without_a_certificate_are_refused_by_name(name, match):
    with pytest.raises(UnsupportedRobotError, match=match):
        certified(taut.example(name), "static")


def test_an_ellipsoid_wrench_set_cannot_be_certified():
    from taut.statics import EllipsoidWrenchSet

    ws = EllipsoidWrenchSet(np.zeros(3), np.eye(3))
    with pytest.raises(ArgumentError, match="EllipsoidWrenchSet cannot be certified"):
        certified(taut.example("planar-4cable"), "wrench-feasible", wrench_set=ws)


# ---- the interval kernel -------------------------------------------------------------------


@settings(max_examples=60, deadline=None)
@given(
    seed=st.integers(0, 2**31),
    m=st.sampled_from([2, 3, 6]),
    extra=st.integers(0, 3),
    width=st.sampled_from([0.0, 1e-3, 3e-2]),
)
def test_zonotope_verdicts_hold_for_every_matrix_of_the_enclosure(seed, m, extra, width):
    """Matrices drawn inside [W − width, W + width] all agree with a decided verdict."""
    rng = np.random.default_rng(seed)
    n = m + extra
    W = rng.normal(size=(m, n))
    tmin = rng.uniform(0, 1, n)
    tmax = tmin + rng.uniform(0.5, 5, n)
    w = rng.normal(size=m)
    r = rng.uniform(0, 0.3, m)
    verdict = zonotope_verdicts(
        (W - width)[None], (W + width)[None], tension_bounds=(tmin, tmax), wrench_lo=w, wrench_hi=w, radius=r
    )[0]
    samples = W + rng.uniform(-width, width, (200, m, n))
    samples[0] = W
    point = wrench_feasible(
        samples, BoxWrenchSet.around(np.zeros(m), r), tension_bounds=(tmin, tmax), wrench=np.tile(w, (200, 1))
    )
    if verdict == 1:
        assert point.all()
    elif verdict == -1:
        assert not point.any()
    if width == 0.0:  # a point matrix is always decided
        assert verdict != 0


@settings(max_examples=80, deadline=None)
@given(seed=st.integers(0, 2**31), m=st.sampled_from([2, 3, 6]), extra=st.integers(0, 3))
def test_separating_directions_find_a_gap_exactly_where_the_point_test_fails(seed, m, extra):
    """A positive gap where the LP of the point test finds the box of wrenches infeasible, a
    negative one where it is balanced (random matrices have independent columns), and the gap
    is the support of the required set beyond that of the zonotope along the direction."""
    rng = np.random.default_rng(seed)
    n = m + extra
    W = rng.normal(size=(m, n))
    tmin = rng.uniform(0, 1, n)
    tmax = tmin + rng.uniform(0.5, 5, n)
    w = rng.normal(size=m) * rng.choice([0.3, 3.0])
    r = rng.uniform(0, 0.3, m)
    direction, gap = separating_directions(W[None], tension_bounds=(tmin, tmax), wrench=w, radius=r)
    feasible = wrench_feasible(W, BoxWrenchSet.around(np.zeros(m), r), tension_bounds=(tmin, tmax), wrench=w)
    if abs(gap[0]) > 1e-9:
        assert bool(feasible) == (gap[0] < 0)
    c = direction[0]
    along = c @ W
    support = np.sum(np.where(along > 0, along * tmax, along * tmin))
    assert np.isclose(np.linalg.norm(c), 1.0)
    assert np.isclose(gap[0], -c @ w + np.abs(c) @ r - support)


@settings(max_examples=200, deadline=None)
@given(centre=st.floats(-50, 50), half=st.floats(0, 4), fn=st.sampled_from(["cos", "sin"]))
def test_interval_cos_and_sin_enclose_every_value(centre, half, fn):
    box = getattr(Interval(centre - half, centre + half), fn)()
    x = np.linspace(centre - half, centre + half, 4001)
    y = getattr(np, fn)(x)
    assert box.lo <= y.min() and y.max() <= box.hi
    assert -1.0 <= box.lo <= box.hi <= 1.0


# ---- the command line ----------------------------------------------------------------------


def taut_cli(*argv):
    return subprocess.run([sys.executable, "-m", "taut", *argv], capture_output=True, text=True, timeout=300)


def test_cli_certified_json_and_plot(tmp_path):
    plot = tmp_path / "c.png"
    p = taut_cli(
        "workspace",
        "planar-4cable",
        "--condition",
        "static",
        "--certified",
        "--eps",
        "0.01",
        "--plot",
        str(plot),
        "--json",
    )
    assert p.returncode == 0, p.stderr
    d = json.loads(p.stdout)
    lib = certified(taut.example("planar-4cable"), "static", eps=0.01)
    assert d["boxes"] == {"inner": len(lib.inner), "outer": len(lib.outer), "undecided": len(lib.undecided)}
    assert d["inner_volume"] == pytest.approx(lib.inner_volume) and d["complete"] is True
    assert set(d) >= {"inner_volume", "undecided_volume", "boxes", "elapsed_s"}
    assert plot.stat().st_size > 10_000


def test_cli_certified_interference_free_where_no_cables_ever_meet():
    """The cables of planar-4cable stay in their own quarter of the platform frame: the
    whole region is one inner box, and a grid of the capsule test finds no contact."""
    p = taut_cli("workspace", "planar-4cable", "--condition", "interference-free", "--certified", "--json")
    assert p.returncode == 0, p.stderr
    d = json.loads(p.stdout)
    assert d["inner_volume"] == pytest.approx(d["region_volume"]) and d["boxes"]["inner"] >= 1
    grid = evaluate_workspace(taut.example("planar-4cable"), "interference-free", resolution=60)
    assert grid.count == grid.size


@pytest.mark.parametrize(
    ("extra", "match"),
    [
        (["--eps", "0"], "--eps: expected a finite number greater than 0"),
        (["--region", "1:0;0:1"], "region is inverted"),
        (["--region", "0:1"], "region must be finite numbers of shape"),
        (["--orientation-box", "0.5:0.1"], "orientation_box is inverted"),
        (["--grid", "20"], "--certified takes --region"),
    ],
)
def test_cli_certified_bad_input_is_one_line_and_exit_2(extra, match):
    p = taut_cli("workspace", "planar-4cable", "--condition", "static", "--certified", *extra)
    assert p.returncode == 2 and p.stderr.count("\n") == 1 and match in p.stderr, p.stderr


def test_cli_certified_options_need_certified():
    p = taut_cli("workspace", "planar-4cable", "--condition", "static", "--eps", "0.1")
    assert p.returncode == 2 and "go with --certified" in p.stderr


def test_cli_budget_out_is_incomplete_not_an_error():
    p = taut_cli("workspace", "planar-4cable", "--condition", "static", "--certified", "--max-boxes", "10", "--json")
    assert p.returncode == 0
    d = json.loads(p.stdout)
    assert d["complete"] is False and d["evaluated"] <= 10


@pytest.mark.slow
def test_a_wide_orientation_box_is_cut_into_pieces():
    robot = taut.example("planar-4cable")
    res = certified(robot, "static", eps=0.02, orientation_box=[[-0.2, 0.2]])
    assert res.inner_volume > 0

    def spread(rng, k):
        return rng.uniform(-0.2, 0.2, (k, 1))

    assert contradictions(robot, res, "static", 20_000, orientations=spread) == 0
    with pytest.raises(ArgumentError, match="more than 4096 pieces"):
        certified(robot, "static", orientation_box=[[-3.0, 3.0]], orientation_step=1e-4)


@pytest.mark.slow
def test_spatial_total_orientation_workspace():
    robot = taut.example("spatial-8cable")
    box = [[-0.005, 0.005]] * 3
    res = certified(robot, "wrench-feasible", [[0.2, 0.4], [0.1, 0.3], [0.0, 0.2]], eps=0.05, orientation_box=box)
    assert res.inner_volume > 0

    def spread(rng, k):
        return rng.uniform(-0.005, 0.005, (k, 3))

    assert contradictions(robot, res, "wrench-feasible", 5000, orientations=spread) == 0


@pytest.mark.parametrize("name", ["planar-4cable", "spatial-8cable", "robocrane", "cogiro"])
def test_derivative_enclosures_hold_the_finite_differences(name):
    """The enclosures behind the mean-value form, against central differences of the
    structure matrices of the kinematics (positions and angles)."""
    from taut.kinematics import batch_structure_matrices
    from taut.workspace._certified import _enclosures, _spec

    robot = taut.example(name)
    d = robot.dimension
    k = 1 if d == 2 else 3
    rng = np.random.default_rng(3)
    pose = np.concatenate([rng.uniform(-0.1, 0.1, d), rng.uniform(-0.2, 0.2, k)])
    if name == "robocrane":
        pose[:d] += [0.0, 0.0, 2.0]
        pose[d + 1] = 0.3  # away from the tilt-torsion angles' singularity
    spec = _spec(robot, make_condition("static"), pose[d:], None, 0.05)
    P = pose[None, :d]
    angles = Interval(pose[None, d:] - 1e-7, pose[None, d:] + 1e-7)
    W, G, _ = _enclosures(spec, P - 1e-7, P + 1e-7, angles, by_angles=True)
    h = 1e-6
    for q in range(d + k):
        step = np.zeros(d + k)
        step[q] = h
        _, Wp, _ = batch_structure_matrices(robot, (pose + step)[None])
        _, Wm, _ = batch_structure_matrices(robot, (pose - step)[None])
        fd = (Wp - Wm)[0] / (2 * h)
        assert np.all(G.lo[0, :, :, q] - 1e-5 <= fd) and np.all(fd <= G.hi[0, :, :, q] + 1e-5), q
    _, W0, _ = batch_structure_matrices(robot, pose[None])
    assert np.all(W.lo[0] - 1e-9 <= W0[0]) and np.all(W0[0] <= W.hi[0] + 1e-9)
