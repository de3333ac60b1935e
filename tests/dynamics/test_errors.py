"""Bad input to taut.dynamics raises a TautError subclass with a one-line message, never a
bare ValueError, TypeError or AttributeError (docs/architecture.md §2.7)."""

import numpy as np
import pytest

import taut
from taut.dynamics import (
    WrenchSteps,
    acceleration,
    forward_dynamics,
    inverse_dynamics,
    loop_model,
    rk4_step,
    simulate_control,
    with_mass_error,
)
from taut.errors import TautError
from taut.motion import trajectory_from_waypoints

S = taut.example("spatial-8cable")
Z = np.zeros(6)
TAU = np.full(8, 10.0)


def zero(t):
    return np.zeros(8)


def motion():
    return trajectory_from_waypoints(S, [Z, Z + 0.01], duration=0.01)


CASES = {
    "dt not a number": lambda: rk4_step(S, Z, Z, TAU, "x"),
    "dt None": lambda: rk4_step(S, Z, Z, TAU, None),
    "tensions not numbers": lambda: acceleration(S, Z, Z, ["a"] * 8),
    "wrench not numbers": lambda: acceleration(S, Z, Z, TAU, wrench=["a"] * 6),
    "duration not a number": lambda: forward_dynamics(S, Z, Z, "x", tensions=zero),
    "step not a number": lambda: forward_dynamics(S, Z, Z, 1.0, tensions=zero, step="x"),
    "rtol negative": lambda: forward_dynamics(S, Z, Z, 0.01, tensions=zero, rtol=-1.0),
    "atol not a number": lambda: forward_dynamics(S, Z, Z, 0.01, tensions=zero, atol="x"),
    "times not numbers": lambda: forward_dynamics(S, Z, Z, 0.01, tensions=zero, times=["a"]),
    "tensions not a function": lambda: forward_dynamics(S, Z, Z, 0.01, tensions=np.zeros(8)),
    "wrench not a function": lambda: forward_dynamics(S, Z, Z, 0.01, tensions=zero, wrench=np.zeros(6)),
    "progress not a function": lambda: forward_dynamics(
        S, Z, Z, 0.01, tensions=zero, method="RK4", step=0.005, progress=3
    ),
    "sample times not numbers": lambda: inverse_dynamics(S, Z, Z, Z, times="x"),
    "method a list": lambda: inverse_dynamics(S, Z, Z, Z, method=["qp"]),
    "mass error not a number": lambda: with_mass_error(S, "x"),
    "loop method a list": lambda: loop_model(S, method=["qp"]),
    "loop state of another size": lambda: loop_model(S).tensions(Z[:3], Z, Z),
    "loop tensions of another size": lambda: loop_model(S).step(Z, Z, np.zeros(3), 1e-3),
    "loop dt not a number": lambda: loop_model(S).step(Z, Z, TAU, "x"),
    "step start not a number": lambda: WrenchSteps.step("a", [1.0, 2.0]),
    "steps not numbers": lambda: WrenchSteps((("a", 1.0, (1.0,)),)),
    "steps at strings": lambda: WrenchSteps.step(0.0, [1.0]).at("x"),
    "motion not a motion": lambda: simulate_control(S, "x"),
    "rate not a number": lambda: simulate_control(S, motion(), rate_hz="x"),
    "substeps not a number": lambda: simulate_control(S, motion(), substeps="x"),
    "model not a robot": lambda: simulate_control(S, motion(), model="x"),
    "disturbance not a function": lambda: simulate_control(S, motion(), disturbance=[1.0] * 6),
}


@pytest.mark.parametrize("name", CASES)
def test_bad_input_is_a_taut_error(name):
    with pytest.raises(TautError) as info:
        CASES[name]()
    assert "\n" not in str(info.value)


def test_wrench_steps_hold_floats():
    steps = WrenchSteps(((1, 2, (3, 4)),))
    assert steps.steps == ((1.0, 2.0, (3.0, 4.0)),) and all(type(x) is float for x in steps.steps[0][2])
    np.testing.assert_array_equal(steps.at([0.5, 1.5, 2.0]), [[0, 0], [3, 4], [0, 0]])
    assert WrenchSteps.step(0.5, [1.0], end=1.0).steps == ((0.5, 1.0, (1.0,)),)
