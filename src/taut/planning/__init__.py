"""Wrench-feasible path planning (Bohigas et al. 2013): higher-dimensional
continuation (:mod:`.continuation`), A* over its charts (:mod:`.search`, complete),
AtlasRRT (Jaillet & Porta 2013, :mod:`.atlasrrt`, randomised), and the classified grid of a
two-dimensional slice (:func:`slice_map`, Fig. 5).

References
----------
.. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of Cable-Driven
   Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots, Mechanisms and
   Machine Science 12, Springer, 2013, §2–5. (docs/references.bib: bohigas2013)
.. [2] L. Jaillet, J. M. Porta, "Path planning under kinematic constraints by rapidly
   exploring manifolds", IEEE Transactions on Robotics 29(1), 2013.
   (docs/references.bib: jaillet2013)
"""

from taut.planning.atlasrrt import atlas_rrt, shorten_path
from taut.planning.continuation import Atlas, Chart, ImplicitManifold, Polytope, Symmetry, project, tangent_basis
from taut.planning.search import PathResult, plan_path, refine_path
from taut.planning.slices import SliceMap, slice_map

__all__ = [
    "Atlas",
    "Chart",
    "ImplicitManifold",
    "PathResult",
    "Polytope",
    "SliceMap",
    "Symmetry",
    "atlas_rrt",
    "plan_path",
    "project",
    "refine_path",
    "shorten_path",
    "slice_map",
    "tangent_basis",
]
