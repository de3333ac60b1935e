"""Dynamics of the platform: equations of motion in the pose coordinates, inverse dynamics
along a sampled motion (wrenches and tension distributions) and forward dynamics (solve_ivp
or fixed-step RK4, given tensions or elastic cables with commanded lengths), and closed-loop
computed-torque control with the tension distribution in the loop."""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut.lazy import lazy_exports

if TYPE_CHECKING:
    from taut.dynamics.control import (
        DEFAULT_KD,
        DEFAULT_KP,
        ControlResult,
        WrenchSteps,
        simulate_control,
        with_mass_error,
    )
    from taut.dynamics.forward import (
        INTEGRATORS,
        ForwardDynamicsResult,
        IntegrationError,
        acceleration,
        cable_tensions,
        forward_dynamics,
        rk4_step,
    )
    from taut.dynamics.inverse import InverseDynamicsResult, inverse_dynamics, required_wrench
    from taut.dynamics.loop import LoopModel, loop_model
    from taut.dynamics.platform import (
        bias_forces,
        coriolis_matrix,
        generalized_forces,
        gravity_forces,
        mass_matrix,
        platform_dynamics,
        velocity_jacobian,
    )

#: Every name is imported on first use (PEP 562): the forward dynamics loads Numba and SciPy.
_LAZY = {
    "DEFAULT_KD": "taut.dynamics.control",
    "DEFAULT_KP": "taut.dynamics.control",
    "ControlResult": "taut.dynamics.control",
    "WrenchSteps": "taut.dynamics.control",
    "simulate_control": "taut.dynamics.control",
    "with_mass_error": "taut.dynamics.control",
    "INTEGRATORS": "taut.dynamics.forward",
    "ForwardDynamicsResult": "taut.dynamics.forward",
    "IntegrationError": "taut.dynamics.forward",
    "acceleration": "taut.dynamics.forward",
    "cable_tensions": "taut.dynamics.forward",
    "forward_dynamics": "taut.dynamics.forward",
    "rk4_step": "taut.dynamics.forward",
    "InverseDynamicsResult": "taut.dynamics.inverse",
    "inverse_dynamics": "taut.dynamics.inverse",
    "required_wrench": "taut.dynamics.inverse",
    "LoopModel": "taut.dynamics.loop",
    "loop_model": "taut.dynamics.loop",
    "bias_forces": "taut.dynamics.platform",
    "coriolis_matrix": "taut.dynamics.platform",
    "generalized_forces": "taut.dynamics.platform",
    "gravity_forces": "taut.dynamics.platform",
    "mass_matrix": "taut.dynamics.platform",
    "platform_dynamics": "taut.dynamics.platform",
    "velocity_jacobian": "taut.dynamics.platform",
}

__all__ = [
    "DEFAULT_KD",
    "DEFAULT_KP",
    "ControlResult",
    "WrenchSteps",
    "simulate_control",
    "with_mass_error",
    "INTEGRATORS",
    "ForwardDynamicsResult",
    "IntegrationError",
    "acceleration",
    "cable_tensions",
    "forward_dynamics",
    "rk4_step",
    "InverseDynamicsResult",
    "inverse_dynamics",
    "required_wrench",
    "LoopModel",
    "loop_model",
    "bias_forces",
    "coriolis_matrix",
    "generalized_forces",
    "gravity_forces",
    "mass_matrix",
    "platform_dynamics",
    "velocity_jacobian",
]

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
