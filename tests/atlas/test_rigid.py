"""Rigid-platform structure atlas (§5.2): platform-reachable area (Eqs. 5.8–5.14), charts
with anchor offsets (Eq. 5.15), one page per orientation."""

import numpy as np
import pytest
import shapely
import shapely.affinity

from taut.atlas import (
    atlas_workspace,
    build_atlas,
    cable_reachable_area,
    direct_ik,
    iterative_ik,
    platform_reachable_area,
)
from taut.atlas._platform import interior_cone, minkowski_sum, platform_outline
from taut.errors import PoseError, TautError
from taut.model import example, robot_from_dict
from taut.wrapping import wrapped_inverse_kinematics

START = [0.8128, -0.2032]


@pytest.fixture(scope="module", params=[0.0, 0.25])
def page(request):
    robot = example("vscr-rigid-t-shaped")
    return build_atlas(robot, START, theta=request.param)


def _variant(**platform):
    d = example("vscr-t-shaped").model_dump(exclude_none=True)
    d["platform"] = platform
    for c in d["cables"]:
        c["anchor"] = [0.0, 0.0]
    d.pop("reference", None)
    d.pop("trajectories", None)
    return robot_from_dict(d)


@pytest.mark.slow
def test_anchors_at_origin_give_the_point_mass_atlas():
    pm = build_atlas(example("vscr-t-shaped"), START)
    for theta in (0.0, 0.7):
        rg = build_atlas(_variant(kind="rigid"), START, theta=theta)
        assert [c.nodes for c in rg.charts] == [c.nodes for c in pm.charts]
        for a, b in zip(rg.charts, pm.charts):
            assert a.domain.symmetric_difference(b.domain).area < 1e-12
        assert sorted((e.charts, e.cable, e.kind) for e in rg.edges) == sorted(
            (e.charts, e.cable, e.kind) for e in pm.edges
        )
        P = np.array([[0.3, -0.2], [0.8, -0.7], [1.4, -0.1]])
        assert np.allclose(direct_ik(rg, P).lengths, direct_ik(pm, P).lengths, atol=1e-12)


@pytest.mark.slow
def test_charts_exclude_platform_collisions(page):
    """At every grid point of every chart the rotated platform outline lies in the
    installation space, off the idlers, the winch pulleys and the disallowed regions."""
    robot = page.robot
    M = platform_outline(robot, page.theta)
    objects = shapely.union_all(
        [shapely.Point(o.center).buffer(o.radius, 256) for o in robot.obstacles]
        + [shapely.Point(c.exit).buffer(c.pulley.radius, 256) for c in robot.cables]
        + [shapely.Polygon(p) for p in robot.disallowed]
    )
    space = shapely.Polygon(robot.installation_space)
    checked = 0
    for c in page.charts:
        x0, y0, x1, y1 = c.domain.bounds
        G = np.stack(np.meshgrid(np.linspace(x0, x1, 25), np.linspace(y0, y1, 25)), -1).reshape(-1, 2)
        G = G[shapely.contains_xy(c.domain, G[:, 0], G[:, 1])]
        for p in G:
            body = shapely.affinity.translate(M, *p)
            assert space.buffer(1e-9).covers(body)
            assert body.intersection(objects).area < 1e-6 * body.area  # arcs are chords of 256-gons
            checked += 1
    assert checked > 1000
    # and the body-only check is not vacuous: the point-mass atlas reaches points the platform cannot
    pm = build_atlas(example("vscr-t-shaped"), START)
    assert page.reachable_area().area < pm.reachable_area().area - 0.1
    for p in ([0.03, -0.2], [0.8128, -1.0], [0.6096 + 0.035, -0.4064]):
        assert pm.reachable_area().contains(shapely.Point(p)) and not page.reachable_area().contains(shapely.Point(p))


def test_charts_exclude_cables_through_the_platform(page):
    """No active or static cable segment crosses the platform interior inside a chart."""
    rng = np.random.default_rng(1)
    M = platform_outline(page.robot, page.theta)
    inner = M.buffer(-1e-6)
    for c in page.charts:
        x0, y0, x1, y1 = c.domain.bounds
        P = rng.uniform([x0, y0], [x1, y1], (200, 2))
        P = P[shapely.contains_xy(c.domain, P[:, 0], P[:, 1])][:20]
        ik = direct_ik(page, P, charts=[c.index])
        for p, A in zip(P, ik.exit_points):
            body = shapely.affinity.translate(inner, *p)
            for i, tree in enumerate(page.trees):
                b = p + page.offsets[i]
                segs = [np.array([A[i], b])] + list(tree.static_segments(c.nodes[i]))
                assert not any(body.intersects(shapely.LineString(s)) for s in segs)


def test_domains_follow_eq_5_15(page):
    """Q = the component of (∩_i (CRA_i − R r_i)) ∩ PRA containing the seed."""
    for c in page.charts[:6]:
        cras = [
            shapely.affinity.translate(cable_reachable_area(t, n, installation_space=page.space), *(-page.offsets[i]))
            for i, (t, n) in enumerate(zip(page.trees, c.nodes))
        ]
        pra = platform_reachable_area(
            page.robot, page.theta, page.space, page.trees, c.nodes, page.offsets, arc_step=0.01, reach=20.0
        )
        sra = shapely.intersection_all(cras + [pra])
        assert c.domain.difference(sra.buffer(1e-7)).area < 1e-9
        part = [g for g in getattr(sra, "geoms", [sra]) if g.distance(shapely.Point(c.seed)) < 1e-7]
        assert part and abs(shapely.union_all(part).area - c.domain.area) < 1e-6


def test_direct_ik_equals_tracking_inside_each_chart(page):
    """Alg. 5.3 on a page equals taut.wrapping tracking of poses (x, y, θ) along paths from
    each chart's seed that stay in the chart."""
    rng = np.random.default_rng(0)
    robot = page.robot
    checked = 0
    for c in page.charts:
        dom = c.domain
        if dom.area < 1e-3:
            continue
        x0, y0, x1, y1 = dom.bounds
        P = rng.uniform([x0, y0], [x1, y1], (400, 2))
        P = P[shapely.contains_xy(dom, P[:, 0], P[:, 1])]
        for p in [p for p in P if dom.covers(shapely.LineString([c.seed, p]))][:3]:
            path = np.linspace(c.seed, p, 30)
            init = {i: page.trees[i].contacts(n) for i, n in enumerate(c.nodes)}
            ref = wrapped_inverse_kinematics(robot, page.poses(path), initial=init)
            d = direct_ik(page, path, charts=[c.index])
            assert d.found.all()
            assert np.abs((d.lengths - d.lengths[0]) - (ref.lengths - ref.lengths[0])).max() < 1e-9
            assert np.allclose(d.exit_points, ref.exit_points, atol=1e-9)
            assert (ref.nodes == np.array(c.nodes)).all()
            checked += 1
    assert checked >= 10


def test_iterative_ik_equals_tracking_along_table_6_6():
    """Alg. 5.4 on the θ = 0 page along the level-platform trajectory (bar ends and stem)."""
    robot = example("vscr-rigid-t-shaped")
    atlas = build_atlas(robot, START)
    W = np.array(robot.trajectories["table-6.6"].waypoints)
    poses = np.concatenate([np.linspace(a, b, 150, endpoint=False) for a, b in zip(W[:-1], W[1:])] + [W[-1:]])
    ref = wrapped_inverse_kinematics(robot, poses)
    it = iterative_ik(atlas, poses[:, :2], chart=0)
    assert np.abs(it.lengths - ref.lengths).max() < 1e-9
    assert all(atlas.charts[c].nodes == tuple(ref.nodes[j]) for j, c in enumerate(it.charts))
    assert len(np.unique(it.charts)) >= 4


def test_workspace_of_a_page(page):
    ws = atlas_workspace(page, "wrench-closure", step=0.02)
    assert 0 < ws.area <= page.reachable_area().area + 0.01
    assert ws.points.shape[1] == 2


def test_minkowski_and_cone():
    sq = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], float)
    assert minkowski_sum(sq, -0.5 * sq).area == pytest.approx(2.25)
    M = shapely.Polygon([[-1, -1], [1, -1], [1, 1], [-1, 1]])
    a0, span = interior_cone(M, [-1, -1])
    assert a0 == pytest.approx(0.0) and span == pytest.approx(np.pi / 2)
    a0, span = interior_cone(M, [0, 1])  # on an edge: a half plane
    assert span == pytest.approx(np.pi) and np.cos(a0 + span / 2) == pytest.approx(0.0, abs=1e-12)
    with pytest.raises(TautError):
        interior_cone(M, [0, 0])


def test_bad_input():
    with pytest.raises(PoseError):
        build_atlas(example("vscr-t-shaped"), START, theta=0.3)
    with pytest.raises(TautError):  # anchors inside the outline
        build_atlas(
            _variant(kind="rigid", shape={"polygon": [[-0.04, -0.02], [0.04, -0.02], [0.04, 0.02], [-0.04, 0.02]]}),
            START,
        )
    with pytest.raises(PoseError):  # the platform overlaps idler 1
        build_atlas(example("vscr-rigid-t-shaped"), [0.6096, -0.36])
    with pytest.raises(TautError):
        build_atlas(example("spatial-8cable"), [0.0, 0.0])
