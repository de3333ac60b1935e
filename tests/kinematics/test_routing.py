"""Cables routed through via points (``cables[].via``): lengths, the Jacobian and the
structure matrix of a chain of straight segments (Lau, Oetomo & Halgamuge 2013, §III–IV),
against finite differences of the lengths, an independent sum of segment lengths in the
test, and the equivalence of an eyelet on the platform with an anchor there."""

from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from kinematics.test_jointed import _fd_jacobian  # noqa: E402  (the twist's finite differences)

import taut
from taut.errors import InfeasiblePoseError, RobotFileError, UnsupportedRobotError
from taut.kinematics import anchors_at, body_frames, inverse_kinematics
from taut.kinematics._jointed import actuator_jacobian
from taut.model import robot_from_dict, robot_to_dict


def routed():
    """adjustable-8cable carrying a third body, ``arm``, hanging from the upper body on a
    joint with a motor of ±20 N m, and two more cables: cable 9 from its exit through a fixed eyelet and an
    eyelet on the lower body to the upper body, cable 10 through an eyelet on the upper body
    to the arm."""
    data = robot_to_dict(taut.example("adjustable-8cable"))
    data.pop("trajectories")
    data.pop("reference")
    data["platform"]["bodies"].append(
        {
            "name": "arm",
            "parent": "upper",
            "joint": {
                "kind": "revolute",
                "axis": [0.2, 1, 0.1],
                "origin": [0.1, 0.0, 0.4],
                "limits": [-1.5, 1.5],
                "actuator": {"force": [-20, 20]},
            },
            "mass": 1.0,
            "com": [0.0, 0.0, -0.25],
            "inertia": [0.02, 0.02, 0.005, 0.0, 0.0, 0.0],
        }
    )
    data["cables"] += [
        {
            "exit": [10, 5, 8],
            "via": [{"point": [9.5, 5, 7.5], "body": "fixed"}, {"point": [0.75, 0, 0]}],
            "anchor": [1.25, 0, 0],
            "body": "upper",
        },
        {
            "exit": [0, 5, 8],
            "via": [{"point": [-1.25, 0, 0.3], "body": "upper"}],
            "anchor": [0, 0, -0.5],
            "body": "arm",
        },
    ]
    return robot_from_dict(data)


ROBOT = routed()
#: spatial-8cable with cable 1 through a fixed eyelet and a platform eyelet, cable 5 through a fixed one.
RIGID = Path(__file__).parents[1] / "model" / "fixtures" / "taut" / "routed.yaml"
POSE = np.array([5.0, 5.0, 1.5, 0.1, -0.05, 0.2, 1.5, 0.3])


def _chain_length(robot, pose, i):
    """The length of cable ``i``'s chain, summed here from the body frames."""
    pos, rot = body_frames(robot, pose[None])
    names = {"platform": 0} | {b.name: k for k, b in enumerate(robot.platform.bodies, 1)}
    points = [np.asarray(robot.cables[i].exit, float)]
    for v in robot.cables[i].via:
        k = names.get(v.body)
        points.append(np.asarray(v.point, float) if k is None else pos[0, k] + rot[0, k] @ v.point)
    points.append(anchors_at(robot, pose[None])[0, i])
    return float(sum(np.linalg.norm(b - a) for a, b in zip(points[:-1], points[1:])))


def test_lengths_are_the_sums_of_the_segments():
    lengths = inverse_kinematics(ROBOT, POSE).lengths
    for i in range(ROBOT.n_cables):
        assert lengths[i] == pytest.approx(_chain_length(ROBOT, POSE, i), rel=1e-14)
    assert ROBOT.routed_cables == (8, 9)


def test_jacobian_matches_finite_differences():
    rng = np.random.default_rng(3)
    for _ in range(10):
        pose = np.array(
            [
                *rng.uniform(4, 6, 2),
                rng.uniform(1, 2),
                *rng.uniform(-0.3, 0.3, 3),
                rng.uniform(0.8, 3),
                rng.uniform(-1, 1),
            ]
        )
        J = actuator_jacobian(ROBOT, pose)
        assert np.allclose(J, _fd_jacobian(ROBOT, pose), atol=1e-7)
        assert not np.allclose(J[9, 7], 0.0)  # cable 10 turns the arm


@settings(max_examples=25, deadline=None)
@given(
    via=st.tuples(*[st.floats(-0.4, 0.4)] * 3),
    inner=st.tuples(*[st.floats(-0.4, 0.4)] * 3),
    pose=st.tuples(st.floats(4, 6), st.floats(4, 6), st.floats(1, 3), *[st.floats(-0.4, 0.4)] * 3),
)
def test_an_eyelet_on_the_platform_is_an_anchor_there(via, inner, pose):
    """A cable through a platform eyelet to an anchor on the platform pulls the platform as
    a straight cable anchored at the eyelet, and is longer by the eyelet–anchor distance."""
    base = taut.example("spatial-8cable")
    data = robot_to_dict(base)
    data["cables"][0]["via"] = [{"point": list(via)}]
    data["cables"][0]["anchor"] = list(inner)
    eyelet = robot_to_dict(base)
    eyelet["cables"][0]["anchor"] = list(via)
    a, b = robot_from_dict(data), robot_from_dict(eyelet)
    gap = np.linalg.norm(np.subtract(via, inner))
    exit_gap = np.linalg.norm(inverse_kinematics(b, pose).exit_points[0] - inverse_kinematics(b, pose).anchors[0])
    if gap < 1e-6 or exit_gap < 1e-6:
        return
    ia, ib = inverse_kinematics(a, pose), inverse_kinematics(b, pose)
    assert ia.lengths[0] == pytest.approx(ib.lengths[0] + gap, rel=1e-12)
    assert np.allclose(ia.structure_matrix, ib.structure_matrix, atol=1e-12)
    assert np.allclose(ia.lengths[1:], ib.lengths[1:], rtol=0, atol=0)


def test_a_zero_length_segment_has_no_direction():
    data = robot_to_dict(taut.example("spatial-8cable"))
    data["cables"][0]["via"] = [{"point": [0.0, 0.0, 0.0]}]
    data["cables"][0]["anchor"] = [0.0, 0.0, 0.0]
    with pytest.raises(InfeasiblePoseError, match="cable 1"):
        inverse_kinematics(robot_from_dict(data), [0, 0, 1, 0, 0, 0])


@pytest.mark.parametrize(
    ("via", "message"),
    [
        ({"point": [0, 0, 0], "body": "nowhere"}, "unknown body 'nowhere'"),
        ({"point": [0, 0]}, r"via\[1\]\.point: expected 3 numbers"),
    ],
)
def test_bad_via_points_are_named(via, message):
    data = robot_to_dict(taut.example("spatial-8cable"))
    data["cables"][2]["via"] = [via]
    with pytest.raises(RobotFileError, match=message):
        robot_from_dict(data)


def test_straight_segment_analyses_refuse_routed_cables():
    from taut.kinematics import cable_paths

    with pytest.raises(UnsupportedRobotError, match=r"cables 9, 10 run through via points"):
        cable_paths(ROBOT, anchors_at(ROBOT, POSE[None]))


@pytest.mark.parametrize("name", ["rigid", "jointed"])
def test_caspr_round_trip_keeps_the_routes(name, tmp_path):
    """Written as CASPR cables of more than two attachments and read back, the routed cables
    have the same lengths and Jacobians at random poses."""
    from taut.model import load_robot, write_caspr

    robot = load_robot(RIGID)
    if name == "jointed":  # without what CASPR cannot hold: cable radii and the motor's bounds
        data = robot_to_dict(ROBOT)
        for cable in data["cables"]:
            cable.pop("radius", None)
        data["platform"]["bodies"][-1]["joint"]["actuator"] = {}
        robot = robot_from_dict(data)
    write_caspr(robot, tmp_path / "routed_bodies.xml")
    again = load_robot(tmp_path / "routed_bodies.xml")
    assert [len(c.via) for c in again.cables] == [len(c.via) for c in robot.cables]
    rng = np.random.default_rng(11)
    for _ in range(20):
        pose = (
            rng.uniform(-0.3, 0.3, 6)
            if name == "rigid"
            else np.array(
                [
                    *rng.uniform(4, 6, 2),
                    rng.uniform(1, 2),
                    *rng.uniform(-0.3, 0.3, 3),
                    rng.uniform(0.8, 3),
                    rng.uniform(-1, 1),
                ]
            )
        )
        assert np.allclose(inverse_kinematics(again, pose).lengths, inverse_kinematics(robot, pose).lengths, atol=1e-12)
        assert np.allclose(actuator_jacobian(again, pose), actuator_jacobian(robot, pose), atol=1e-12)
