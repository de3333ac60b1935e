"""A Robot cannot go stale: it is immutable, its arrays are read-only and follow its fields."""

import copy
import math
import pickle

import numpy as np
import pytest
from pydantic import ValidationError

import taut
from taut.kinematics import inverse_kinematics
from taut.model import robot_from_dict

SPATIAL = {
    "name": "rigid 4-cable",
    "dimension": 3,
    "platform": {"kind": "rigid", "mass": 2.0},
    "cables": [
        {"exit": [0, 0, 3], "anchor": [0.1, 0, 0]},
        {"exit": [2, 0, 3], "anchor": [0, 0.1, 0]},
        {"exit": [2, 2, 3], "anchor": [-0.1, 0, 0]},
        {"exit": [0, 2, 3], "anchor": [0, -0.1, 0]},
    ],
}


def _lengths(exits, anchors, position):
    """Cable lengths at a pose without rotation, from the raw numbers, one cable at a time."""
    return [math.dist(a, [p + r for p, r in zip(position, anchor)]) for a, anchor in zip(exits, anchors)]


def test_copy_with_new_cables_uses_their_exit_points():
    r = robot_from_dict(SPATIAL)
    pose = [1.0, 1.0, 1.0, 0.0, 0.0, 0.0]
    assert r.exits.shape == (4, 3)  # computed and cached before the copy, as a stale copy would keep them
    moved = [[0, 0, 4], [3, 0, 4], [3, 3, 4], [0, 3, 4]]
    cables = [{**c, "exit": e} for c, e in zip(SPATIAL["cables"], moved)]
    r2 = r.model_copy(update={"cables": cables})
    np.testing.assert_array_equal(r2.exits, moved)
    expected = _lengths(moved, [c["anchor"] for c in cables], pose[:3])
    np.testing.assert_allclose(inverse_kinematics(r2, pose).lengths, expected, rtol=1e-14)
    old = _lengths([c["exit"] for c in SPATIAL["cables"]], [c["anchor"] for c in cables], pose[:3])
    np.testing.assert_allclose(inverse_kinematics(r, pose).lengths, old, rtol=1e-14)
    assert not np.allclose(expected, old)


def test_copy_validates_the_update():
    r = robot_from_dict(SPATIAL)
    with pytest.raises(taut.RobotFileError, match=r"cables\[2\].exit: expected 3 numbers"):
        r.model_copy(update={"cables": [SPATIAL["cables"][0], {"exit": [1, 2]}]})
    with pytest.raises(taut.RobotFileError, match="unknown key"):
        r.model_copy(update={"colour": "red"})
    with pytest.raises(taut.RobotFileError, match="tension"):
        r.cables[0].model_copy(update={"tension": (5.0, 1.0)})
    assert r.model_copy(update={"name": "renamed"}).name == "renamed"
    assert r.model_copy() == r


def test_fields_cannot_be_assigned():
    r = robot_from_dict(SPATIAL)
    for target, field, value in [
        (r, "name", "other"),
        (r, "cables", ()),
        (r, "exits", np.zeros((4, 3))),
        (r.platform, "mass", 3.0),
        (r.cables[0], "exit", (9.0, 9.0, 9.0)),
    ]:
        with pytest.raises(ValidationError, match="frozen"):
            setattr(target, field, value)
    with pytest.raises(TypeError):
        r.cables[0] = r.cables[1]  # type: ignore[index]  # sequences are tuples
    with pytest.raises(TypeError):
        r.cables[0].exit[0] = 5.0  # type: ignore[index]


@pytest.mark.parametrize(
    "name", ["exits", "anchors", "cable_bodies", "tension_bounds", "length_bounds", "joint_limits", "weight"]
)
def test_arrays_are_read_only(name):
    r = robot_from_dict(SPATIAL)
    for robot in (r, copy.deepcopy(r), pickle.loads(pickle.dumps(r))):
        value = getattr(robot, name)
        for array in value if isinstance(value, tuple) else (value,):
            assert isinstance(array, np.ndarray) and not array.flags.writeable
            if array.size:
                with pytest.raises(ValueError, match="read-only"):
                    array[...] = 0


def test_equal_fields_equal_robots_whatever_was_computed():
    r, s = robot_from_dict(SPATIAL), robot_from_dict(SPATIAL)
    assert r.exits.shape == (4, 3) and len(r.tension_bounds) == 2  # cached in r, not in s
    assert r == s and r == pickle.loads(pickle.dumps(r))
    assert r != r.model_copy(update={"name": "other"})


def test_weight_is_mass_times_gravity():
    r = robot_from_dict(SPATIAL)
    np.testing.assert_array_equal(r.weight, [0.0, 0.0, -2.0 * 9.81])
    planar = robot_from_dict(
        {"name": "p", "dimension": 2, "platform": {"mass": 3.0}, "cables": [{"exit": [0, 1]}, {"exit": [1, 1]}]}
    )
    np.testing.assert_array_equal(planar.weight, [0.0, -3.0 * 9.81])
    moon = r.model_copy(update={"platform": {"mass": 2.0, "gravity": [0.0, 0.5, -1.62]}})
    np.testing.assert_array_equal(moon.weight, [0.0, 1.0, -3.24])
    massless = r.model_copy(update={"platform": {"wrench": [0, 0, -1, 0, 0, 0]}})
    np.testing.assert_array_equal(massless.weight, [0.0, 0.0, 0.0])


def test_external_wrench_includes_the_weight():
    from taut.statics import external_wrench

    r = robot_from_dict(SPATIAL)
    np.testing.assert_allclose(external_wrench(r, [1, 1, 1, 0, 0, 0]), [0, 0, -19.62, 0, 0, 0])
