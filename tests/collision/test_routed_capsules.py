"""Capsules of cables routed through via points (``cables[].via``): one per segment, at the
chain's points (exit point, via points, anchor, computed here from the body frames), segments
of one cable not paired, and two cables through one eyelet compared as touching there only."""

from pathlib import Path

import numpy as np

import taut
from taut.collision import capsule_model, capsule_segments, proximity
from taut.kinematics import anchors_at, body_frames
from taut.model import load_robot, robot_from_dict, robot_to_dict

ROUTED = Path(__file__).parents[1] / "model" / "fixtures" / "taut" / "routed.yaml"


def _chain(robot, pose, i):
    """Cable ``i``'s points from its exit point to its anchor, from the body frames."""
    pos, rot = body_frames(robot, pose[None])
    points = [np.asarray(robot.cables[i].exit, float)]
    for v in robot.cables[i].via:
        points.append(np.asarray(v.point, float) if v.body == "fixed" else pos[0, 0] + rot[0, 0] @ v.point)
    return np.array([*points, anchors_at(robot, pose[None])[0, i]])


def test_one_capsule_per_segment_at_the_chain_points():
    robot = load_robot(ROUTED)
    pose = np.array([0.05, -0.02, 0.03, 0.1, -0.05, 0.2])
    model = capsule_model(robot)
    A, B = capsule_segments(robot, pose[None], model=model)
    for i, first in ((0, 8), (4, 10)):
        chain = _chain(robot, pose, i)
        k = len(chain) - 2  # the segments before the cable's own capsule
        segments = [*range(first, first + k), i]
        assert np.allclose(A[0, segments], chain[:-1]) and np.allclose(B[0, segments], chain[1:])
        assert model.names[first] == f"cable {i + 1} segment 1 of {k + 1}"
    owners = [0] * 8 + [0, 0, 4]
    owners[:8] = range(8)
    assert all(owners[a] != owners[b] for a, b in model.pairs if b < model.n_cables)
    assert model.n_cables == 11 and not model.flip.any()


def test_two_cables_through_one_eyelet_touch_only_there():
    """Cable 1 runs through a fixed eyelet; cable 2 starts its last segment there too, so
    that cable 1's first segment ends (B) where cable 2's last segment starts (A): compared
    turned round, the two touch at the eyelet without colliding, while the same segments
    crossing elsewhere would."""
    data = robot_to_dict(taut.example("spatial-8cable"))
    eyelet = [0.0, -1.0, -1.0]
    data["cables"][0]["via"] = [{"point": eyelet, "body": "fixed"}]
    data["cables"][1]["via"] = [{"point": eyelet, "body": "fixed"}]
    robot = robot_from_dict(data)
    model = capsule_model(robot)
    first_of_1 = model.names.index("cable 1 segment 1 of 2")
    pair = [k for k, (a, b) in enumerate(model.pairs) if {a, b} == {1, first_of_1}]
    assert len(pair) == 1 and model.flip[pair[0]] and model.shared[pair[0]].any()
    clearance = proximity(robot, np.zeros(6)).clearances[0, pair[0]]
    assert clearance > 0.0
