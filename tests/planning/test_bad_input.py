"""docs/architecture.md §2.7: bad input to taut.planning raises a TautError subclass naming what
is wrong, never the ValueError, TypeError or IndexError NumPy would raise deeper down."""

import numpy as np
import pytest

from taut.errors import PoseError, TautError
from taut.model import load_robot
from taut.planning import Atlas, ImplicitManifold, Polytope, Symmetry, WrenchFeasibleManifold, plan_path, verify_path

SPHERE = ImplicitManifold(lambda x: np.array([x @ x - 1]), lambda x: 2 * x[None, :], 2)
CAP = ImplicitManifold(SPHERE.function, SPHERE.jacobian, 2, lower=np.array([-2, -2, 0.5]), upper=np.array([2, 2, 2]))
A, B = np.array([1.0, 0, 0]), np.array([0, 1.0, 0])
ROBOCRANE = load_robot("robocrane")
Q1 = ROBOCRANE.reference.poses["q1"]


@pytest.mark.parametrize(
    "call, words",
    [
        (lambda: plan_path(SPHERE, A, B, method=None), "method"),
        (lambda: plan_path(SPHERE, A, B, radius="x"), "radius"),
        (lambda: plan_path(SPHERE, A, B, radius=np.nan), "radius"),
        (lambda: plan_path(SPHERE, [1.0, 0], B), "goal point"),
        (lambda: plan_path(SPHERE, "x", B), "start point"),
        (lambda: plan_path(SPHERE, [np.nan, 0, 0], B), "start point"),
        (lambda: plan_path(SPHERE, A, [0, 1.0]), "goal point"),
        (lambda: plan_path(SPHERE, A, B, max_charts=0), "max_charts"),
        (lambda: plan_path(SPHERE, A, B, max_charts="x"), "max_charts"),
        (lambda: plan_path(SPHERE, A, B, spacing=0), "spacing"),
        (lambda: plan_path(SPHERE, A, B, metric=[7]), "metric"),
        (lambda: plan_path(SPHERE, A, B, epsilon="x"), "epsilon"),
        (lambda: plan_path(SPHERE, A, B, method="atlasrrt", max_nodes="x"), "max_nodes"),
        (lambda: plan_path(SPHERE, A, B, method="atlasrrt", step="x"), "step"),
        (lambda: plan_path(SPHERE, A, B, method="atlasrrt", goal_bias=2.0), "goal_bias"),
        (lambda: plan_path(SPHERE, A, B, method="atlasrrt", seed="x"), "seed"),
        (lambda: plan_path(SPHERE, A, B, method="atlasrrt", time_limit="x"), "time_limit"),
        (lambda: Atlas(SPHERE, A, radius="x"), "radius"),
        (lambda: Atlas(CAP, [1.0, 0], radius=0.2), "start point has 2 coordinates"),
        (lambda: Polytope(0, 1.0), "k"),
        (lambda: Symmetry("x"), "symmetry"),
        (lambda: WrenchFeasibleManifold.from_robot(ROBOCRANE, E="x"), "E"),
        (lambda: WrenchFeasibleManifold.from_robot(ROBOCRANE, E=np.eye(3)), "E"),
        (lambda: verify_path(ROBOCRANE, [Q1], E=np.eye(3)), "E"),
        (lambda: verify_path(ROBOCRANE, [Q1, Q1], subdivide=0), "subdivide"),
    ],
)
def test_bad_arguments_raise_taut_errors(call, words):
    with pytest.raises(TautError, match=words):
        call()


@pytest.mark.parametrize(
    "call",
    [
        lambda: WrenchFeasibleManifold.from_robot(ROBOCRANE, fixed={"x": "a"}),
        lambda: WrenchFeasibleManifold.from_robot(ROBOCRANE, fixed=[1]),
        lambda: WrenchFeasibleManifold.from_robot(ROBOCRANE).lift("x"),
        lambda: verify_path(ROBOCRANE, "x"),
        lambda: verify_path(ROBOCRANE, [[0, 0, 2]]),
    ],
)
def test_bad_poses_raise_pose_errors(call):
    with pytest.raises(PoseError):
        call()


def test_one_pose_is_a_path_of_one_pose():
    one, two = verify_path(ROBOCRANE, Q1), verify_path(ROBOCRANE, [Q1])
    np.testing.assert_array_equal(one.poses, [Q1])
    assert one.all_feasible == two.all_feasible
