"""Wrench-feasible path planning (Bohigas et al. 2013): higher-dimensional
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
