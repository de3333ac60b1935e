"""Statics: external wrenches and wrench sets, wrench-closure / wrench-feasibility /
equilibrium tests, tension distribution."""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports
from taut.statics._wrench import (
    BoxWrenchSet,
    EllipsoidWrenchSet,
    PolytopeWrenchSet,
    SingleWrench,
    WrenchSet,
    external_wrench,
)

if TYPE_CHECKING:
    from taut.statics._feasibility import static_equilibrium, wrench_closure, wrench_feasible
    from taut.statics._tension import METHODS, TensionResult, distribute_tensions, solve_tensions

#: Names re-exported from modules that load Numba or HiGHS: imported on first use (PEP 562),
#: so that ``import taut.statics._wrench`` does not pay for them.
_LAZY = {
    "static_equilibrium": "taut.statics._feasibility",
    "wrench_closure": "taut.statics._feasibility",
    "wrench_feasible": "taut.statics._feasibility",
    "METHODS": "taut.statics._tension",
    "TensionResult": "taut.statics._tension",
    "distribute_tensions": "taut.statics._tension",
    "solve_tensions": "taut.statics._tension",
}


__all__ = [
    "BoxWrenchSet",
    "EllipsoidWrenchSet",
    "PolytopeWrenchSet",
    "SingleWrench",
    "WrenchSet",
    "external_wrench",
    "static_equilibrium",
    "wrench_closure",
    "wrench_feasible",
    "METHODS",
    "TensionResult",
    "distribute_tensions",
    "solve_tensions",
]

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
