"""Structure atlas (Alg. 5.1), charts (Eqs. 5.2–5.6), workspace (Alg. 5.2)."""

import numpy as np
import pytest
import shapely

from taut.atlas import atlas_workspace, build_atlas, chart_lengths
from taut.errors import PoseError, TautError
from taut.model import Robot, example


@pytest.fixture(scope="module")
def t_atlas():
    robot = example("vscr-t-shaped")
    return build_atlas(robot, robot.reference.poses["initial"])


def test_t_shaped_atlas_covers_installation_space(t_atlas):
    """The charts cover the T minus the parts no cable end can reach: the idler discs and
    the winch pulleys that overlap the T."""
    atlas = t_atlas
    robot = atlas.robot
    unreachable = shapely.union_all(
        [shapely.Point(o.center).buffer(o.radius, 64) for o in robot.obstacles]
        + [shapely.Point(c.exit).buffer(c.pulley.radius, 64) for c in robot.cables]
    )
    expected = atlas.space.difference(unreachable)
    got = atlas.reachable_area()
    assert got.symmetric_difference(expected).area < 1e-5 * expected.area
    assert len(atlas.charts) > 10 and atlas.n_edges >= len(atlas.charts) - 1


def test_charts_are_distinct_structures_with_valid_domains(t_atlas):
    atlas = t_atlas
    keys = [(c.nodes, c.domain.representative_point().coords[0]) for c in atlas.charts]
    assert len({k[0] for k in keys}) == len(keys)  # the T's structures each have one component
    rng = np.random.default_rng(3)
    for c in atlas.charts:
        assert c.domain.is_valid and c.domain.area > 0
        # every cable is taut and admissible at points of the chart (Eq. 5.6)
        x0, y0, x1, y1 = c.domain.bounds
        P = rng.uniform([x0, y0], [x1, y1], (40, 2))
        P = P[shapely.contains_xy(c.domain.buffer(-1e-6), P[:, 0], P[:, 1])]
        for p in P[:5]:
            assert all(t.is_taut(n, p) for t, n in zip(atlas.trees, c.nodes))


def test_edges_join_charts_differing_in_one_cable(t_atlas):
    atlas = t_atlas
    for e in atlas.edges:
        a, b = (atlas.charts[k] for k in e.charts)
        diff = [i for i in range(len(a.nodes)) if a.nodes[i] != b.nodes[i]]
        assert diff == [e.cable]
        mid = e.segment.mean(axis=0)
        # the two structures give the same lengths on their shared edge (continuity)
        la = chart_lengths(atlas.trees, a.nodes, mid[None])[0]
        lb = chart_lengths(atlas.trees, b.nodes, mid[None])[0]
        assert np.allclose(la, lb, atol=1e-9)


def test_robot_without_obstacles_has_one_chart():
    robot = example("vscr-four-cable")
    data = robot.model_dump()
    data["obstacles"] = []
    free = Robot.model_validate(data)
    atlas = build_atlas(free, [0.75, -0.5])
    assert len(atlas.charts) == 1 and atlas.n_edges == 0


def test_single_cable_atlas_structures():
    robot = example("vscr-single-cable")
    atlas = build_atlas(robot, [0.0, 2.0])
    states = {c.states[0] for c in atlas.charts}
    assert ((0, 1),) in states and ((1, -1),) in states and () in states
    assert all(len(s) <= 3 for s in states)


def test_workspace_prunes_and_is_within_charts(t_atlas):
    atlas = t_atlas
    ws = atlas_workspace(atlas, "wrench-feasible")
    reach = atlas.reachable_area()
    assert 0 < ws.area <= reach.area + 1e-9
    assert shapely.contains_xy(reach.buffer(1e-9), ws.points[:, 0], ws.points[:, 1]).all()
    assert 0 in ws.charts and sorted(ws.charts + ws.pruned) == list(range(len(atlas.charts)))
    st = atlas_workspace(atlas, "static")
    assert st.area >= ws.area  # zero wrench with tensions >= 0: every taut structure balances it


def test_bad_input():
    robot = example("vscr-t-shaped")
    with pytest.raises(PoseError):
        build_atlas(robot, [5.0, 5.0])
    with pytest.raises(PoseError):
        build_atlas(robot, [0.6096, -0.4064])  # the centre of idler 1
    with pytest.raises(TautError):
        build_atlas(example("spatial-8cable"), [0.5, 0.5])
    atlas = build_atlas(example("vscr-agriculture"), [0.0, 0.991])
    with pytest.raises(TautError):
        atlas_workspace(atlas, "interference-free")


def test_progress_counts_charts_expanded_then_charts_decided():
    robot = example("vscr-single-cable")
    calls = []
    atlas = build_atlas(robot, [0.0, 2.0], progress=lambda done, total: calls.append((done, total)))
    n = len(atlas.charts)
    assert n > 1 and calls == [(k, None) for k in range(1, n + 1)] + [(n, n)]
    calls.clear()
    ws = atlas_workspace(atlas, "static", step=0.5, progress=lambda done, total: calls.append((done, total)))
    done = [d for d, _ in calls]
    assert {t for _, t in calls} == {n} and done == sorted(set(done)) and calls[-1] == (n, n)
    assert len(calls) >= len(ws.charts)  # every chart kept was visited
