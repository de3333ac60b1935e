"""docs/architecture.md §2.7 on the results of taut.atlas: frozen, read-only arrays,
``as_dict()`` in plain JSON types with 0-based charts, cables and objects, equal to the
fields; an atlas stopped by its chart budget says it is incomplete."""

import numpy as np
import pytest
from frozen_results import check_frozen

from taut.atlas import atlas_workspace, build_atlas, direct_ik
from taut.model import example

ROBOT = example("vscr-t-shaped")
START = ROBOT.reference.poses["initial"]


@pytest.fixture(scope="module")
def atlas():
    return build_atlas(ROBOT, START)


def test_structure_atlas_charts_and_edges(atlas):
    keys = {"start", "theta", "complete", "elapsed_s", "charts", "edges", "reachable_area", "chart_list", "edge_list"}
    d = check_frozen(atlas, keys)
    assert d["complete"] is True and d["charts"] == len(atlas.charts) == len(d["chart_list"])
    assert d["edges"] == atlas.n_edges and len(d["edge_list"]) == len(atlas.edges)
    assert d["reachable_area"] == pytest.approx(sum(c.area for c in atlas.charts), rel=1e-9)
    for c, dc in zip(atlas.charts, d["chart_list"]):
        assert check_frozen(c, {"index", "structure", "area", "seed", "domain", "neighbours"}) == dc
        assert dc["neighbours"] == sorted(c.neighbours) and all(isinstance(v, tuple) for v in c.neighbours.values())
        assert dc["structure"] == [[list(w) for w in s] for s in c.states]
    for e, de in zip(atlas.edges, d["edge_list"]):
        assert check_frozen(e, {"charts", "cable", "kind", "object", "segment"}) == de
        assert 0 <= de["cable"] < ROBOT.n_cables and de["object"] == e.obj and de["charts"] == list(e.charts)


def test_a_chart_budget_leaves_an_incomplete_atlas(atlas):
    part = build_atlas(ROBOT, START, max_charts=3)
    assert not part.complete and len(part.charts) == 3 < len(atlas.charts)
    assert all(n < 3 for c in part.charts for n in c.neighbours)
    # the charts it has are the first ones of the whole atlas
    assert [c.nodes for c in part.charts] == [c.nodes for c in atlas.charts[:3]]


def test_atlas_ik_and_workspace(atlas):
    seeds = np.array([c.seed for c in atlas.charts[:4]] + [[100.0, 100.0]])
    ik = direct_ik(atlas, seeds)
    d = check_frozen(ik, {"charts", "found", "lengths", "exit_points"})
    assert d["found"] == [True] * 4 + [False] and d["charts"][-1] == -1
    assert d["lengths"][-1] == [None] * ROBOT.n_cables  # NaN where no chart: null in JSON
    np.testing.assert_array_equal(d["lengths"][:4], ik.lengths[:4])
    ws = atlas_workspace(atlas, "static", step=0.5)
    d = check_frozen(ws, {"condition", "step", "area", "charts", "pruned", "points"})
    assert sorted(d["charts"] + d["pruned"]) == list(range(len(atlas.charts)))
    assert d["area"] == ws.area and len(d["points"]) == len(ws.points)
    assert not any(p.flags.writeable for p in ws.sub_workspaces.values())
