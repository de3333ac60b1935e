"""Wrench-feasible path planning (``002_19d5d688a3999fb0.txt``): higher-dimensional
continuation (:mod:`.continuation`) and A* over its charts (:mod:`.search`)."""

from taut.planning.continuation import Atlas, Chart, ImplicitManifold, Polytope, project, tangent_basis
from taut.planning.search import PathResult, plan_path, refine_path

__all__ = [
    "Atlas",
    "Chart",
    "ImplicitManifold",
    "PathResult",
    "Polytope",
    "plan_path",
    "project",
    "refine_path",
    "tangent_basis",
]
