"""Atlas-based inverse kinematics (Algs. 5.3, 5.4) against cable-state tracking (Alg. 4.4)."""

import numpy as np
import pytest
import shapely

from taut.atlas import build_atlas, direct_ik, iterative_ik, locate
from taut.errors import PoseError
from taut.model import example
from taut.wrapping import wrapped_inverse_kinematics


@pytest.fixture(scope="module")
def t_atlas():
    robot = example("vscr-t-shaped")
    return build_atlas(robot, robot.reference.poses["initial"])


def _polyline(W, k=150):
    W = np.asarray(W, float)
    return np.concatenate([np.linspace(a, b, k, endpoint=False) for a, b in zip(W[:-1], W[1:])] + [W[-1:]])


def test_iterative_ik_equals_tracking_along_table_6_6(t_atlas):
    robot = t_atlas.robot
    P = _polyline(robot.trajectories["table-6.6"].waypoints)
    ref = wrapped_inverse_kinematics(robot, P)
    it = iterative_ik(t_atlas, P, chart=0)
    assert np.abs(it.lengths - ref.lengths).max() < 1e-9
    assert all(t_atlas.charts[c].nodes == tuple(ref.nodes[j]) for j, c in enumerate(it.charts))
    assert len(np.unique(it.charts)) >= 4
    assert np.allclose(it.exit_points, ref.exit_points, atol=1e-9)


@pytest.mark.parametrize("seed", range(3))
def test_direct_ik_equals_tracking_inside_each_chart(t_atlas, seed):
    """At points of a chart, Alg. 5.3 restricted to that chart gives the lengths that the
    tracking gives along a path from the chart's seed that stays in the chart."""
    rng = np.random.default_rng(seed)
    robot = t_atlas.robot
    checked = 0
    for c in t_atlas.charts:
        dom = c.domain
        if dom.area < 1e-3:
            continue
        x0, y0, x1, y1 = dom.bounds
        P = rng.uniform([x0, y0], [x1, y1], (400, 2))
        P = P[shapely.contains_xy(dom, P[:, 0], P[:, 1])]
        seg_in = [p for p in P if dom.covers(shapely.LineString([c.seed, p]))][:3]
        for p in seg_in:
            path = np.linspace(c.seed, p, 30)
            init = {i: t_atlas.trees[i].contacts(n) for i, n in enumerate(c.nodes)}
            ref = wrapped_inverse_kinematics(robot, path, initial=init)
            d = direct_ik(t_atlas, path, charts=[c.index])
            assert d.found.all()
            # tracking counts the winch arc from its own first pose: compare length changes
            assert np.abs((d.lengths - d.lengths[0]) - (ref.lengths - ref.lengths[0])).max() < 1e-9
            assert (ref.nodes == np.array(c.nodes)).all()  # the tracking never left the structure
            checked += 1
    assert checked >= 15


def test_direct_ik_finds_a_chart_everywhere_reachable(t_atlas):
    rng = np.random.default_rng(0)
    Q = rng.uniform(*np.array(t_atlas.space.bounds).reshape(2, 2), size=(20000, 2))
    reach = t_atlas.reachable_area()
    inside = shapely.contains_xy(reach.buffer(-1e-7), Q[:, 0], Q[:, 1])
    ch = locate(t_atlas, Q)
    assert (ch[inside] >= 0).all() and (ch[~shapely.contains_xy(reach.buffer(1e-7), Q[:, 0], Q[:, 1])] < 0).all()
    d = direct_ik(t_atlas, Q)
    assert np.isfinite(d.lengths[d.found]).all() and np.isnan(d.lengths[~d.found]).all()


def test_iterative_ik_rejects_a_move_through_an_obstacle(t_atlas):
    with pytest.raises(PoseError):
        iterative_ik(t_atlas, [[0.8128, -0.2032], [0.8128, 0.3]], chart=0)  # out of the T
