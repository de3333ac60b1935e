"""``cables[].weight``: sagging cables in the robot file, its validation and the formats."""

from __future__ import annotations

import math

import numpy as np
import pytest

from taut.errors import RobotFileError, UnsupportedRobotError
from taut.model import example, load_robot, robot_from_dict, robot_to_dict, save_robot, write_robot


def _heavy(name="spatial-8cable", weight=2.0, stiffness=None):
    robot = example(name)
    update = {"weight": weight} | ({} if stiffness is None else {"stiffness": stiffness})
    return robot.model_copy(update={"cables": tuple(c.model_copy(update=update) for c in robot.cables)})


def test_weight_and_stiffness_arrays():
    robot = _heavy(stiffness=5e5)
    assert robot.sagging_cables == tuple(range(8))
    assert robot.cable_weights.tolist() == [2.0] * 8
    assert robot.axial_stiffness.tolist() == [5e5] * 8
    straight = example("spatial-8cable")
    assert straight.sagging_cables == ()
    assert straight.cable_weights.tolist() == [0.0] * 8
    assert np.isinf(straight.axial_stiffness).all()


def test_a_robot_mixes_sagging_and_straight_cables():
    robot = example("spatial-8cable")
    cables = list(robot.cables)
    cables[2] = cables[2].model_copy(update={"weight": 0.5})
    mixed = robot.model_copy(update={"cables": tuple(cables)})
    assert mixed.sagging_cables == (2,)


@pytest.mark.parametrize(
    ("field", "value", "words"),
    [
        ("weight", -1.0, "weight: input should be greater than or equal to 0"),
        ("weight", math.nan, "weight: expected a finite number"),
        ("weight", math.inf, "weight: expected a finite number"),
        ("stiffness", 0.0, "stiffness: input should be greater than 0"),
    ],
)
def test_bad_weight_or_stiffness_is_one_line(field, value, words):
    data = robot_to_dict(example("spatial-8cable"))
    data["cables"][0][field] = value
    with pytest.raises(RobotFileError, match=words) as info:
        robot_from_dict(data)
    assert "\n" not in str(info.value)


def test_sagging_cables_need_gravity_and_fixed_exits():
    data = robot_to_dict(example("spatial-8cable"))
    data["cables"][0]["weight"] = 1.0
    data["platform"]["gravity"] = [0.0, 0.0, 0.0]
    with pytest.raises(RobotFileError, match="need a gravity"):
        robot_from_dict(data)
    data = robot_to_dict(example("planar-4cable"))
    data["cables"][0] |= {"weight": 1.0, "pulley": {"radius": 0.05}}
    with pytest.raises(RobotFileError, match="fixed exit point"):
        robot_from_dict(data)


@pytest.mark.parametrize("suffix", ["yaml", "json"])
def test_taut_files_keep_the_weight(tmp_path, suffix):
    robot = _heavy(weight=1.25, stiffness=3e5)
    save_robot(robot, tmp_path / f"r.{suffix}")
    back = load_robot(tmp_path / f"r.{suffix}")
    assert back == robot
    assert back.cable_weights.tolist() == [1.25] * 8


@pytest.mark.parametrize(
    ("target", "words"),
    [
        ("r_bodies.xml", "a CASPR model cannot hold the weight of cable 1"),
        ("r.wcrfx", "cables\\[1\\].weight"),
        ("r.mjcf.xml", "cable 1 has a weight"),
    ],
)
def test_formats_without_sagging_cables_refuse_them(tmp_path, target, words):
    robot = _heavy()
    if target.endswith("wcrfx"):  # without the platform shape WireX cannot hold either
        robot = robot.model_copy(update={"platform": robot.platform.model_copy(update={"shape": None})})
    with pytest.raises(UnsupportedRobotError, match=words):
        write_robot(robot, tmp_path / target)
    assert not list(tmp_path.iterdir())
