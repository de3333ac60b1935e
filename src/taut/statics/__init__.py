"""Statics: external wrenches and wrench sets, wrench-closure / wrench-feasibility /
equilibrium tests, tension distribution."""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut.lazy import lazy_exports
from taut.statics.wrench import (
    BoxWrenchSet,
    EllipsoidWrenchSet,
    PolytopeWrenchSet,
    SingleWrench,
    WrenchSet,
    external_wrench,
)

if TYPE_CHECKING:
    from taut.statics.feasibility import static_equilibrium, wrench_closure, wrench_feasible
    from taut.statics.tension import METHODS, TensionResult, distribute_tensions, solve_tensions

#: Names re-exported from modules that load Numba or HiGHS: imported on first use (PEP 562),
#: so that ``import taut.statics.wrench`` does not pay for them.
_LAZY = {
    "static_equilibrium": "taut.statics.feasibility",
    "wrench_closure": "taut.statics.feasibility",
    "wrench_feasible": "taut.statics.feasibility",
    "METHODS": "taut.statics.tension",
    "TensionResult": "taut.statics.tension",
    "distribute_tensions": "taut.statics.tension",
    "solve_tensions": "taut.statics.tension",
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
