"""The results of taut.workspace follow docs/architecture.md §2.7: frozen, read-only arrays,
``as_dict()`` in plain JSON types holding the fields."""

import numpy as np
from result_checks import check_result, same

import taut
from taut.workspace import WorkspaceResult, evaluate_workspace, pose_grid, position_grid

PLANAR = taut.example("planar-4cable")


def test_pose_grid():
    grid = pose_grid(PLANAR, [(-0.4, 0.4, 3), (-0.2, 0.2, 2), np.array([0.0, 0.1])])
    d = check_result(grid)
    assert set(d) == {"axes", "index", "fixed", "names"}
    assert d["index"] == [0, 1, 2] and d["names"] == ["x", "y", "theta"]
    for got, want in zip(d["axes"], ([-0.4, 0.0, 0.4], [-0.2, 0.2], [0.0, 0.1])):
        np.testing.assert_allclose(got, want)
    same(d["fixed"], np.zeros(3))


def test_workspace_result(tmp_path):
    grid = position_grid(PLANAR, resolution=7, orientation=[0.1])
    res = evaluate_workspace(PLANAR, "static", grid=grid)
    d = check_result(res)
    inside = int(np.count_nonzero(res.inside))
    assert 0 < inside < 49
    assert d["robot"] == PLANAR.name and d["condition"] == "static" and d["complete"] is True
    assert d["poses"] == 49 and d["inside"] == inside and d["fraction"] == inside / 49
    assert d["grid_shape"] == [7, 7] and d["axis_names"] == ["x", "y"]
    for got, axis in zip(d["axes"], grid.axes):
        np.testing.assert_array_equal(got, axis)
    assert d["elapsed_s"] == res.elapsed_s >= 0
    # a result read back from its file is the same result
    res.save(tmp_path / "ws.npz")
    again = WorkspaceResult.load(tmp_path / "ws.npz")
    assert check_result(again) == d
    explicit = evaluate_workspace(PLANAR, "static", poses=grid.poses()[:5])
    e = check_result(explicit)
    assert e["grid_shape"] == [5] and e["axes"] == [] and e["measure"] is None
