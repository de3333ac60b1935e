"""Dynamics of the platform: equations of motion in the pose coordinates, inverse dynamics
along a sampled motion (wrenches and tension distributions) and forward dynamics (solve_ivp
or fixed-step RK4, given tensions or elastic cables with commanded lengths), and closed-loop
computed-torque control with the tension distribution in the loop."""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports

if TYPE_CHECKING:
    from taut.dynamics._control import (
        DEFAULT_KD,
        DEFAULT_KP,
        ControlResult,
        WrenchSteps,
        simulate_control,
        with_mass_error,
    )
    from taut.dynamics._forward import (
        INTEGRATORS,
        ForwardDynamicsResult,
        IntegrationError,
        acceleration,
        cable_tensions,
        forward_dynamics,
        rk4_step,
    )
    from taut.dynamics._inverse import InverseDynamicsResult, inverse_dynamics, required_wrench
    from taut.dynamics._loop import LoopModel, loop_model
    from taut.dynamics._platform import (
        PlatformDynamics,
        bias_forces,
        coriolis_matrix,
        generalized_forces,
        gravity_forces,
        mass_matrix,
        platform_dynamics,
        velocity_jacobian,
    )

#: Every name is imported on first use (PEP 562), so that importing the package loads nothing heavy.
_LAZY = {
    "ControlResult": "taut.dynamics._control",
    "DEFAULT_KD": "taut.dynamics._control",
    "DEFAULT_KP": "taut.dynamics._control",
    "WrenchSteps": "taut.dynamics._control",
    "simulate_control": "taut.dynamics._control",
    "with_mass_error": "taut.dynamics._control",
    "ForwardDynamicsResult": "taut.dynamics._forward",
    "INTEGRATORS": "taut.dynamics._forward",
    "IntegrationError": "taut.dynamics._forward",
    "acceleration": "taut.dynamics._forward",
    "cable_tensions": "taut.dynamics._forward",
    "forward_dynamics": "taut.dynamics._forward",
    "rk4_step": "taut.dynamics._forward",
    "InverseDynamicsResult": "taut.dynamics._inverse",
    "inverse_dynamics": "taut.dynamics._inverse",
    "required_wrench": "taut.dynamics._inverse",
    "LoopModel": "taut.dynamics._loop",
    "loop_model": "taut.dynamics._loop",
    "PlatformDynamics": "taut.dynamics._platform",
    "bias_forces": "taut.dynamics._platform",
    "coriolis_matrix": "taut.dynamics._platform",
    "generalized_forces": "taut.dynamics._platform",
    "gravity_forces": "taut.dynamics._platform",
    "mass_matrix": "taut.dynamics._platform",
    "platform_dynamics": "taut.dynamics._platform",
    "velocity_jacobian": "taut.dynamics._platform",
}

__all__ = [
    "ControlResult",
    "DEFAULT_KD",
    "DEFAULT_KP",
    "ForwardDynamicsResult",
    "INTEGRATORS",
    "IntegrationError",
    "InverseDynamicsResult",
    "LoopModel",
    "PlatformDynamics",
    "WrenchSteps",
    "acceleration",
    "bias_forces",
    "cable_tensions",
    "coriolis_matrix",
    "forward_dynamics",
    "generalized_forces",
    "gravity_forces",
    "inverse_dynamics",
    "loop_model",
    "mass_matrix",
    "platform_dynamics",
    "required_wrench",
    "rk4_step",
    "simulate_control",
    "velocity_jacobian",
    "with_mass_error",
]

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
