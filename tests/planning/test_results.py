"""docs/architecture.md §2.7 on the results of taut.planning: frozen, read-only arrays,
``as_dict()`` in plain JSON types equal to the fields; one entry point for both planners."""

import numpy as np
import pytest
from frozen_results import check_frozen

from taut.errors import TautError
from taut.model import load_robot
from taut.planning import ImplicitManifold, plan_path, verify_path

SPHERE = ImplicitManifold(lambda x: np.array([x @ x - 1]), lambda x: 2 * x[None, :], 2)
#: a sphere cut by the box z ≥ 0.5: the south pole is out of reach
CAP = ImplicitManifold(SPHERE.function, SPHERE.jacobian, 2, lower=np.array([-2, -2, 0.5]), upper=np.array([2, 2, 2]))
KEYS = {"method", "found", "no_path", "complete", "path", "charts", "expanded", "nodes", "length", "elapsed_s"}


@pytest.mark.parametrize("method", ["astar", "atlasrrt"])
def test_a_found_path(method):
    a, b = np.array([1.0, 0, 0]), np.array([0, 1.0, 0])
    res = plan_path(SPHERE, a, b, method=method, radius=0.3)
    d = check_frozen(res, KEYS)
    assert d["method"] == method and d["found"] is True and d["complete"] is True and d["no_path"] is False
    np.testing.assert_array_equal(d["path"], res.path)
    assert d["length"] == res.length == pytest.approx(np.sum(np.linalg.norm(np.diff(res.path, axis=0), axis=1)))
    # A* closes charts, AtlasRRT grows tree nodes: each counts its own
    assert (d["expanded"] > 0, d["nodes"] > 0) == ((True, False) if method == "astar" else (False, True))


def test_no_path_proved_and_no_path_within_a_budget():
    proof = plan_path(CAP, [0, 0, 1.0], [0, 0, -1.0], radius=0.2)
    d = check_frozen(proof, KEYS)
    assert (d["found"], d["no_path"], d["complete"], d["length"], d["path"]) == (False, True, True, None, [])
    # the goal is off the cap but on the sphere: AtlasRRT's budget runs out, which proves nothing
    rrt = plan_path(CAP, [0, 0, 1.0], [0, 0, -1.0], method="atlasrrt", radius=0.3, max_nodes=200)
    d = check_frozen(rrt, KEYS)
    assert (d["found"], d["no_path"], d["complete"], d["length"]) == (False, False, False, None)


def test_unknown_method_is_refused():
    with pytest.raises(TautError, match="astar, atlasrrt"):
        plan_path(SPHERE, [1.0, 0, 0], [0, 1.0, 0], method="rrt")


def test_path_check():
    robot = load_robot("robocrane")
    poses = np.array([robot.reference.poses["q1"], robot.reference.poses["q2"]])
    check = verify_path(robot, poses, subdivide=3)
    d = check_frozen(check, {"poses", "feasible", "lengths", "all_feasible"})
    assert len(d["poses"]) == 4 and d["all_feasible"] == check.all_feasible == all(d["feasible"])
    np.testing.assert_array_equal(d["lengths"], check.lengths)
