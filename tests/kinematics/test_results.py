"""The results of taut.kinematics follow docs/architecture.md §2.7: frozen, read-only arrays,
``as_dict()`` in plain JSON types holding the fields."""

import numpy as np
from result_checks import check_result, same

import taut
from taut.kinematics import cable_lengths, forward_kinematics, inverse_kinematics, swivel_parameters, swivel_paths

SPATIAL = taut.example("spatial-8cable")


def test_ik_result():
    poses = np.array([[0.0, 0.0, 0.0, 0.0, 0.0, 0.0], [0.1, -0.2, 0.3, 0.1, 0.0, -0.1]])
    res = inverse_kinematics(SPATIAL, poses)
    d = check_result(res)
    assert set(d) == {"lengths", "directions", "anchors", "structure_matrix", "exit_points"}
    for name in d:
        same(d[name], getattr(res, name))
    # the lengths of the dict are those of its own exit points and anchors
    v = np.array(d["exit_points"]) - np.array(d["anchors"])
    np.testing.assert_allclose(d["lengths"], np.linalg.norm(v, axis=-1), rtol=1e-14)


def test_fk_result():
    pose = np.array([0.1, 0.05, -0.1, 0.02, -0.03, 0.04])
    res = forward_kinematics(SPATIAL, cable_lengths(SPATIAL, pose), guess=np.zeros(6))
    d = check_result(res)
    assert set(d) == {"pose", "residual", "evaluations"}
    np.testing.assert_allclose(d["pose"], pose, atol=1e-8)
    assert d["residual"] <= 1e-9 and d["evaluations"] == res.evaluations > 0


def test_swivel_paths():
    robot = SPATIAL.model_copy(
        update={
            "cables": tuple(
                c.model_copy(update={"swivel": {"axis": (0, 0, 1), "radius": 0.02}}) for c in SPATIAL.cables
            )
        }
    )
    idx, axes, radii = swivel_parameters(robot)
    anchors = np.broadcast_to(robot.anchors[idx][None], (2, len(idx), 3)) + np.array([0.0, 0.1])[:, None, None]
    res = swivel_paths(robot.exits[idx], axes, radii, anchors)
    d = check_result(res)
    assert set(d) == {"lengths", "tangent_points", "wrap", "on_axis", "on_pulley"}
    for name in d:
        same(d[name], getattr(res, name))
    assert d["on_axis"] == [[False] * 8] * 2
