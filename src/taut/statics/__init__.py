"""Statics: external wrenches and wrench sets, wrench-closure / wrench-feasibility /
equilibrium tests, tension distribution."""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports

if TYPE_CHECKING:
    from taut.statics._feasibility import FEASIBILITY_METHODS, static_equilibrium, wrench_closure, wrench_feasible
    from taut.statics._highs import QuietHighs
    from taut.statics._inputs import distribute_tensions, equilibrium_equations, input_bounds, solve_inputs
    from taut.statics._tension import EQUILIBRIUM_RTOL, METHODS, TensionResult, solve_tensions
    from taut.statics._wrench import (
        BoxWrenchSet,
        EllipsoidWrenchSet,
        PolytopeWrenchSet,
        SingleWrench,
        WrenchSet,
        external_wrench,
    )

#: Every name is imported on first use (PEP 562), so that importing the package loads nothing heavy.
_LAZY = {
    "FEASIBILITY_METHODS": "taut.statics._feasibility",
    "static_equilibrium": "taut.statics._feasibility",
    "wrench_closure": "taut.statics._feasibility",
    "wrench_feasible": "taut.statics._feasibility",
    "QuietHighs": "taut.statics._highs",
    "equilibrium_equations": "taut.statics._inputs",
    "input_bounds": "taut.statics._inputs",
    "solve_inputs": "taut.statics._inputs",
    "EQUILIBRIUM_RTOL": "taut.statics._tension",
    "METHODS": "taut.statics._tension",
    "TensionResult": "taut.statics._tension",
    "distribute_tensions": "taut.statics._inputs",
    "solve_tensions": "taut.statics._tension",
    "BoxWrenchSet": "taut.statics._wrench",
    "EllipsoidWrenchSet": "taut.statics._wrench",
    "PolytopeWrenchSet": "taut.statics._wrench",
    "SingleWrench": "taut.statics._wrench",
    "WrenchSet": "taut.statics._wrench",
    "external_wrench": "taut.statics._wrench",
}

__all__ = [
    "BoxWrenchSet",
    "EQUILIBRIUM_RTOL",
    "EllipsoidWrenchSet",
    "FEASIBILITY_METHODS",
    "METHODS",
    "PolytopeWrenchSet",
    "QuietHighs",
    "SingleWrench",
    "TensionResult",
    "WrenchSet",
    "distribute_tensions",
    "equilibrium_equations",
    "external_wrench",
    "input_bounds",
    "solve_inputs",
    "solve_tensions",
    "static_equilibrium",
    "wrench_closure",
    "wrench_feasible",
]

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
