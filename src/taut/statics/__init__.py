"""Statics: external wrenches and wrench sets, wrench-closure / wrench-feasibility /
equilibrium tests, tension distribution."""

from taut.statics.feasibility import static_equilibrium, wrench_closure, wrench_feasible
from taut.statics.tension import METHODS, TensionResult, distribute_tensions, solve_tensions
from taut.statics.wrench import (
    BoxWrenchSet,
    EllipsoidWrenchSet,
    PolytopeWrenchSet,
    SingleWrench,
    WrenchSet,
    external_wrench,
)

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
