"""The platform's inertia tensor: read from the file in MuJoCo's ``fullinertia`` order, checked
to be a physical tensor, refused where it has no meaning."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import taut
from taut.errors import RobotFileError
from taut.model import robot_from_dict, robot_to_dict


def with_platform(**fields):
    data = robot_to_dict(taut.example("spatial-8cable"))
    data["platform"] = {**data.get("platform", {}), **fields}
    return data


@given(st.lists(st.floats(-1.0, 1.0), min_size=9, max_size=9), st.floats(1e-3, 10.0))
def test_tensor_of_a_rigid_body_round_trips(entries, mass):
    """Any A Aᵀ is a valid tensor; its six numbers come back as the same matrix."""
    A = np.array(entries).reshape(3, 3)
    I = A @ A.T
    six = [I[0, 0], I[1, 1], I[2, 2], I[0, 1], I[0, 2], I[1, 2]]
    robot = robot_from_dict(with_platform(mass=mass, inertia=six))
    assert np.allclose(robot.inertia, I, atol=1e-12)
    assert not robot.inertia.flags.writeable


def test_planar_inertia_is_one_number():
    data = robot_to_dict(taut.example("planar-4cable"))
    data["platform"] = {**data["platform"], "inertia": [0.02]}
    assert robot_from_dict(data).inertia.tolist() == [[0.02]]


@pytest.mark.parametrize(
    "fields, words",
    [
        ({"mass": 1.0, "inertia": [1.0, 1.0, 1.0, 2.0, 0.0, 0.0]}, "positive semi-definite"),
        ({"mass": 1.0, "inertia": [1.0, 1.0, 1.0]}, "expected 6 numbers"),
        ({"mass": None, "gravity": None, "inertia": [1.0, 1.0, 1.0, 0.0, 0.0, 0.0]}, "without platform.mass"),
    ],
)
def test_unphysical_inertia_is_refused(fields, words):
    with pytest.raises(RobotFileError, match=words):
        robot_from_dict(with_platform(**fields))


def test_point_mass_has_no_rotational_inertia():
    data = robot_to_dict(taut.example("vscr-four-cable"))
    data["platform"] = {**data.get("platform", {}), "mass": 1.0, "inertia": [0.1]}
    with pytest.raises(RobotFileError, match="point-mass"):
        robot_from_dict(data)


def test_no_inertia_without_the_field():
    assert taut.example("cogiro").inertia is None
    assert robot_from_dict(with_platform(inertia=None)).inertia is None


def test_the_examples_inertia_is_the_box_their_files_state():
    """spatial-8cable: a 5 kg box of 0.3 m x 0.2 m x 0.1 m; planar-4cable: a 1 kg plate of
    0.2 m x 0.1 m (both about their centres, as the YAML comments say)."""
    box = 5.0 / 12 * np.array([0.2**2 + 0.1**2, 0.3**2 + 0.1**2, 0.3**2 + 0.2**2])
    assert np.allclose(taut.example("spatial-8cable").inertia, np.diag(box), rtol=1e-15, atol=0)
    assert np.allclose(taut.example("planar-4cable").inertia, [[1.0 / 12 * (0.2**2 + 0.1**2)]], rtol=1e-15)
