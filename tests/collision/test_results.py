"""The results of taut.collision follow docs/architecture.md §2.7: frozen, read-only arrays,
``as_dict()`` in plain JSON types holding the fields (0-based cables and capsules)."""

import numpy as np
from result_checks import check_result, same

import taut
from taut.collision import capsule_model, check_poses, proximity, trajectory_poses

ROBOT = taut.example("adjustable-8cable")


def test_capsule_model_and_proximity():
    model = capsule_model(ROBOT)
    d = check_result(model)
    assert set(d) == {"names", "radii", "body", "local", "n_cables", "pairs", "shared", "cut", "flip"}
    assert d["names"][0] == "cable 1" and d["n_cables"] == 8 and d["body"][:8] == [-1] * 8
    assert [0, 1] in d["pairs"] and all(i < j for i, j in d["pairs"])
    for name in ("radii", "local", "pairs", "shared", "cut"):
        same(d[name], getattr(model, name))
    poses = trajectory_poses(ROBOT, "sim-a")[::50]
    res = proximity(ROBOT, poses, model=model)
    p = check_result(res)
    assert set(p) == {"model", "distances", "clearances"} and p["model"] == d
    same(p["distances"], res.distances)
    rho = model.radii[model.pairs].sum(axis=1)
    np.testing.assert_allclose(np.array(p["clearances"]), np.array(p["distances"]) - rho, rtol=1e-15, atol=1e-15)


def test_check_result():
    poses = trajectory_poses(ROBOT, "sim-b")[120:130]
    res = check_poses(ROBOT, poses)
    d = check_result(res)
    assert set(d) == {"capsules", "poses", "jacobian_ratio", "steps", "summary"}
    assert d["summary"]["force_closure_singular_steps"] == [[5, 9]] and d["summary"]["first_problem"] == 5
    assert d["capsules"] == list(res.model.names)
    same(d["poses"], poses)
    same(d["jacobian_ratio"], res.jacobian_ratio)
    assert [s["index"] for s in d["steps"]] == list(range(10))
    assert [s["force_closure_singular"] for s in d["steps"]] == res.force_closure_singular.tolist()
    assert any(s["force_closure_singular"] for s in d["steps"])  # step 126 of simulation b
    clear = res.proximity.clearances.min(axis=1)
    np.testing.assert_allclose([s["min_clearance"] for s in d["steps"]], clear)
