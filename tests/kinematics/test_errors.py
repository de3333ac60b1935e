"""Bad input to taut.kinematics raises a TautError subclass with a one-line message, never a
bare ValueError, TypeError or AttributeError (docs/architecture.md §2.7)."""

import numpy as np
import pytest

import taut
from taut.errors import PoseError, TautError
from taut.kinematics import (
    anchors_at,
    body_frames,
    cable_lengths,
    cable_paths,
    forward_kinematics,
    ik_status,
    joint_forces,
    lengths_at,
    swivel_paths,
    tension_from_stretch,
    unstretched_length,
)

SPATIAL = taut.example("spatial-8cable")
ADJUSTABLE = taut.example("adjustable-8cable")
Z = np.zeros(6)

CASES = {
    "fk lengths not numbers": lambda: forward_kinematics(SPATIAL, ["a"] * 8),
    "fk tol not a number": lambda: forward_kinematics(SPATIAL, cable_lengths(SPATIAL, Z), tol="x"),
    "fk tol negative": lambda: forward_kinematics(SPATIAL, cable_lengths(SPATIAL, Z), tol=-1.0),
    "joint forces not numbers": lambda: joint_forces(
        ADJUSTABLE, np.r_[Z, ADJUSTABLE.joint_limits.mean(axis=1)], ["a"] * 8
    ),
    "unstretched not numbers": lambda: unstretched_length(["a"], [1.0], [1.0]),
    "unstretched shapes": lambda: unstretched_length([1.0, 2.0], [1.0, 2.0, 3.0], [1.0]),
    "stretch zero length": lambda: tension_from_stretch([1.0], [0.0], [1.0]),
    "stretch negative EA": lambda: tension_from_stretch([1.0], [0.5], [-1.0]),
    "stretch not numbers": lambda: tension_from_stretch(["x"], [0.5], [1.0]),
    "swivel paths not arrays": lambda: swivel_paths("a", "b", "c", "d"),
    "swivel paths shapes": lambda: swivel_paths(np.zeros((2, 3)), np.ones((2, 3)), np.ones(3), np.zeros((4, 2, 3))),
    "anchors of a list": lambda: anchors_at(SPATIAL, [Z]),
    "frames of one pose": lambda: body_frames(SPATIAL, Z),
    "status of a wrong width": lambda: ik_status(SPATIAL, np.zeros((2, 3))),
    "lengths of a string": lambda: lengths_at(SPATIAL, "x"),
    "paths of wrong anchors": lambda: cable_paths(SPATIAL, np.zeros((2, 3))),
}


@pytest.mark.parametrize("name", CASES)
def test_bad_input_is_a_taut_error(name):
    with pytest.raises(TautError) as info:
        CASES[name]()
    assert "\n" not in str(info.value)


def test_the_unchecked_functions_still_name_the_array_they_need():
    with pytest.raises(PoseError, match=r"\(N, 6\) array of poses checked by as_poses"):
        anchors_at(SPATIAL, [Z])
