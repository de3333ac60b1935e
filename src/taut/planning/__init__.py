"""Wrench-feasible path planning (Bohigas et al. 2013): higher-dimensional
continuation (:mod:`.continuation`) and A* over its charts (:mod:`.search`).

References
----------
.. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of Cable-Driven
   Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots, Mechanisms and
   Machine Science 12, Springer, 2013, §2–5. (docs/references.bib: bohigas2013)
"""

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
