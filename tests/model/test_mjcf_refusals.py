"""Robots the MuJoCo model cannot hold exactly are refused by name, and bad poses are refused
(no MuJoCo needed: these run without the optional extra)."""

import math
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import taut
from taut.errors import PoseError, UnsupportedRobotError
from taut.model import mjcf_text, pose_to_qpos, robot_from_dict, robot_to_dict


def with_inertia(name, **platform):
    robot = taut.example(name)
    return robot.model_copy(update={"platform": robot.platform.model_copy(update=platform)})


def adjustable(cables=None, **upper):
    """adjustable-8cable with its body ``upper`` massless and then updated by ``upper``, and its
    cables' dicts updated by ``cables`` ({index: fields})."""
    data = robot_to_dict(taut.example("adjustable-8cable"))
    data.pop("trajectories")
    for field in ("mass", "com", "inertia"):
        data["platform"]["bodies"][0].pop(field)
    data["platform"]["bodies"][0] |= upper
    for i, fields in (cables or {}).items():
        data["cables"][i] |= fields
    return robot_from_dict(data)


MASSIVE = {"mass": 8.0, "inertia": [3.0, 5.0, 7.0, 0.0, 0.0, 0.0]}


@pytest.mark.parametrize(
    "robot, words",
    [
        (with_inertia("adjustable-8cable", mass=None, inertia=None), "no platform.mass"),
        (adjustable(), "platform.bodies[1] (upper) has no mass"),
        (adjustable(mass=8.0), "platform.bodies[1] (upper) has no inertia"),
        (adjustable(mass=8.0, inertia=[1, 1, 3, 0, 0, 0]), "platform.bodies[1] (upper) inertia [1.0, 1.0, 3.0"),
        (adjustable(mass=8.0, inertia=[1, 0, 1, 0, 0, 0]), "singular"),
        (adjustable(mass=8.0, com=[0, 0, 5e-7], inertia=[1, 1, 1, 0, 0, 0]), "the com of platform.bodies[1] (upper)"),
        (
            adjustable(joint={"kind": "prismatic", "axis": [0, 0, 1], "limits": [2.0, 2.0]}, **MASSIVE),
            "platform.bodies[1] (upper) joint limits [2, 2] are equal",
        ),
        (
            adjustable({5: {"swivel": {"axis": [0, 0, 1], "radius": 0.05}}}, **MASSIVE),
            "cable 6 has a swivelling pulley and is anchored on the jointed body upper",
        ),
        (taut.example("vscr-four-cable"), "obstacles"),
        (taut.example("cogiro"), "no platform.mass"),
        (with_inertia("spatial-8cable", inertia=None), "no platform.inertia"),
        (with_inertia("cogiro", mass=1.0, inertia=(1, 1, 1, 0, 0, 0)), "platform.wrench"),
        (with_inertia("spatial-8cable", inertia=(1, 1, 3, 0, 0, 0)), "A + B >= C"),
        (with_inertia("spatial-8cable", inertia=(1, 1, 0, 0, 0, 0)), "singular"),
        (with_inertia("planar-4cable", inertia=(0.0,)), "Izz"),
    ],
    ids=[
        "jointed, no masses",
        "body without mass",
        "body without inertia",
        "body triangle",
        "body singular",
        "body com",
        "equal joint limits",
        "swivel on a body",
        "obstacles",
        "no mass",
        "no inertia",
        "wrench",
        "triangle",
        "singular",
        "planar zero",
    ],
)
def test_unsupported_robots_are_refused_by_name(robot, words):
    with pytest.raises(UnsupportedRobotError, match="cannot be written as a MuJoCo model") as err:
        mjcf_text(robot)
    assert words in str(err.value)


def test_exit_pulleys_are_refused():
    data = robot_to_dict(with_inertia("planar-4cable", inertia=(0.01,)))
    data["cables"][2]["pulley"] = {"radius": 0.02}
    with pytest.raises(UnsupportedRobotError, match="cable 3 leaves an exit pulley"):
        mjcf_text(robot_from_dict(data))


def test_a_swivelling_pulley_is_a_hinged_body_the_tendon_wraps():
    data = robot_to_dict(with_inertia("spatial-8cable", mass=2.0, inertia=(1, 1, 1, 0, 0, 0)))
    data["cables"][4]["swivel"] = {"axis": [0, 0, 1], "radius": 0.05}
    root = ET.fromstring(mjcf_text(robot_from_dict(data)))
    body = root.find("./worldbody/body[@name='pulley5']")
    assert body is not None and body.find("joint").get("type") == "hinge"
    assert body.find("geom").get("type") == "cylinder"
    assert [s.get("name") for s in body.findall("site")] == ["exit5", "side5"]
    assert root.find("./worldbody/site[@name='exit5']") is None
    tendon = root.find("./tendon/spatial[@name='cable5']")
    assert [(e.tag, e.get("site") or e.get("geom"), e.get("sidesite")) for e in tendon] == [
        ("site", "exit5", None),
        ("geom", "wheel5", "side5"),
        ("site", "anchor5", None),
    ]
    assert len(root.findall("./worldbody/body")) == 2  # the platform and one pulley


def test_a_swivelling_pulley_too_small_for_mujoco_sites_is_refused():
    data = robot_to_dict(with_inertia("spatial-8cable", inertia=(1, 1, 1, 0, 0, 0)))
    data["cables"][1]["swivel"] = {"axis": [0, 0, 1], "radius": 1e-6}
    with pytest.raises(UnsupportedRobotError, match="cable 2 has a swivelling pulley of radius 1e-06 m, below 1e-05 m"):
        mjcf_text(robot_from_dict(data))


@pytest.mark.parametrize(
    "field, value, words",
    [
        ("anchor", [5e-7, -5e-7, 0.0], "the anchor of cable 1 [5e-07, -5e-07, 0.0] is within 1e-06"),
        ("exit", [0.0, 9e-7, 0.0], "the exit point of cable 1 [0.0, 9e-07, 0.0] is within 1e-06"),
    ],
)
def test_a_point_mujoco_would_move_onto_its_body_origin_is_refused(field, value, words):
    data = robot_to_dict(with_inertia("spatial-8cable", inertia=(1, 1, 1, 0, 0, 0)))
    data["cables"][0][field] = value
    with pytest.raises(UnsupportedRobotError, match=re.escape(words)):
        mjcf_text(robot_from_dict(data))
    data["cables"][0][field] = [0.0, 0.0, 0.0]
    assert "<tendon" in mjcf_text(robot_from_dict(data))
    data["platform"]["wrench_point"] = [0.0, 0.0, 1e-7]
    with pytest.raises(UnsupportedRobotError, match=re.escape("platform.wrench_point [0.0, 0.0, 1e-07]")):
        mjcf_text(robot_from_dict(data))


def test_bad_poses_are_refused():
    robot = with_inertia("planar-4cable", inertia=(0.01,))
    with pytest.raises(PoseError, match="3 coordinates"):
        pose_to_qpos(robot, [0.0, 0.0])
    with pytest.raises(PoseError, match="not finite"):
        pose_to_qpos(robot, [0.0, math.nan, 0.0])


def test_planar_pose_is_qpos_and_the_text_names_every_cable():
    robot = with_inertia("planar-4cable", inertia=(0.01,))
    poses = np.array([[0.1, -0.2, 0.3], [0.0, 0.5, -1.0]])
    assert np.array_equal(pose_to_qpos(robot, poses), poses)
    root = ET.fromstring(mjcf_text(robot))
    tendons = root.findall("./tendon/spatial")
    assert [t.get("name") for t in tendons] == [f"cable{i}" for i in range(1, 5)]
    assert [[s.get("site") for s in t] for t in tendons] == [[f"exit{i}", f"anchor{i}"] for i in range(1, 5)]
    assert [a.get("tendon") for a in root.findall("./actuator/general")] == [t.get("name") for t in tendons]
    assert root.find("./worldbody/body/inertial").get("diaginertia") == "0.005 0.005 0.01"
    assert root.find("./option").get("gravity") == "0.0 -9.81 0.0"
    assert math.isclose(float(root.find("./worldbody/body/inertial").get("mass")), 1.0)


def test_a_joint_coordinate_outside_its_limits_is_refused():
    """MuJoCo's joint limit would push there: the pose is refused, naming the joint."""
    robot = adjustable(**MASSIVE)
    assert pose_to_qpos(robot, [5, 5, 3, 0, 0, 0, 4.5])[7] == 4.5
    with pytest.raises(PoseError, match=re.escape("pose 2: joint s23 = 4.6 is outside its limits [0.4, 4.5]")):
        pose_to_qpos(robot, [[5, 5, 3, 0, 0, 0, 2.0], [5, 5, 3, 0, 0, 0, 4.6]])
