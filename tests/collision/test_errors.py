"""Bad input to taut.collision raises a TautError subclass with a one-line message, never a
bare ValueError, TypeError or AttributeError (docs/architecture.md §2.7)."""

import numpy as np
import pytest

import taut
from taut.collision import (
    capsule_model,
    capsule_segments,
    check_poses,
    force_closure_singular,
    jacobian_singular,
    positive_span_lp,
    proximity,
    straight_moves,
)
from taut.errors import TautError

SPATIAL = taut.example("spatial-8cable")
PLANAR = taut.example("planar-4cable")
Z = np.zeros(6)

CASES = {
    "model not a model": lambda: proximity(SPATIAL, Z, model="x"),
    "model of another robot": lambda: proximity(SPATIAL, Z, model=capsule_model(PLANAR)),
    "method unknown": lambda: check_poses(SPATIAL, Z, method="zz"),
    "tol not a number": lambda: check_poses(SPATIAL, Z, tol="x"),
    "tol negative": lambda: check_poses(SPATIAL, Z, tol=-1.0),
    "J not numbers": lambda: jacobian_singular("x"),
    "J a vector": lambda: jacobian_singular([1.0, 2.0]),
    "J tol not a number": lambda: jacobian_singular(np.eye(3), tol="x"),
    "W not numbers": lambda: force_closure_singular("x"),
    "W a vector": lambda: force_closure_singular([1.0, 2.0]),
    "W a vector, lp": lambda: force_closure_singular([1.0, 2.0], method="lp"),
    "W not finite": lambda: force_closure_singular(np.full((3, 4), np.nan)),
    "method a list": lambda: force_closure_singular(np.eye(3), method=["lp"]),
    "lp of a string": lambda: positive_span_lp("x"),
    "waypoints not numbers": lambda: straight_moves(SPATIAL, "ab"),
    "segments of a list": lambda: capsule_segments(SPATIAL, [Z]),
}


@pytest.mark.parametrize("name", CASES)
def test_bad_input_is_a_taut_error(name):
    with pytest.raises(TautError) as info:
        CASES[name]()
    assert "\n" not in str(info.value)
