"""Wrench-feasible path planning (Bohigas et al. 2013): higher-dimensional
continuation (:mod:`.continuation`), :func:`plan_path` by A* over its charts
(``method="astar"``, complete) or AtlasRRT (Jaillet & Porta 2013, ``method="atlasrrt"``,
randomised), or in any robot's own pose space by RRT-Connect (``method="rrtconnect"``) or A*
over a lattice (``method="grid"``, a no-path proof at its resolution), with the validity test
of :func:`verify_path` (:func:`pose_validity`), and the classified grid of a two-dimensional
slice (:func:`slice_map`, Fig. 5).

References
----------
.. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of Cable-Driven
   Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots, Mechanisms and
   Machine Science 12, Springer, 2013, §2–5. (docs/references.bib: bohigas2013)
.. [2] L. Jaillet, J. M. Porta, "Path planning under kinematic constraints by rapidly
   exploring manifolds", IEEE Transactions on Robotics 29(1), 2013.
   (docs/references.bib: jaillet2013)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports

if TYPE_CHECKING:
    from taut.planning._atlasrrt import MAX_NODES, shorten_path
    from taut.planning._continuation import (
        MAX_CHARTS,
        Atlas,
        ImplicitManifold,
        ManifoldChart,
        Polytope,
        Symmetry,
        project,
        tangent_basis,
    )
    from taut.planning._manifold import POSE_NAMES, WrenchFeasibleManifold
    from taut.planning._plan import METHODS, RADIUS, plan_path
    from taut.planning._search import PathResult, refine_path
    from taut.planning._slices import SliceMap, slice_map
    from taut.planning._verify import MAX_PATH_POSES, PathCheck, pose_validity, verify_path

#: Every name is imported on first use (PEP 562), so that importing the package loads nothing heavy.
_LAZY = {
    "MAX_NODES": "taut.planning._atlasrrt",
    "shorten_path": "taut.planning._atlasrrt",
    "Atlas": "taut.planning._continuation",
    "ImplicitManifold": "taut.planning._continuation",
    "MAX_CHARTS": "taut.planning._continuation",
    "ManifoldChart": "taut.planning._continuation",
    "Polytope": "taut.planning._continuation",
    "Symmetry": "taut.planning._continuation",
    "project": "taut.planning._continuation",
    "tangent_basis": "taut.planning._continuation",
    "POSE_NAMES": "taut.planning._manifold",
    "WrenchFeasibleManifold": "taut.planning._manifold",
    "METHODS": "taut.planning._plan",
    "RADIUS": "taut.planning._plan",
    "plan_path": "taut.planning._plan",
    "PathResult": "taut.planning._search",
    "refine_path": "taut.planning._search",
    "SliceMap": "taut.planning._slices",
    "slice_map": "taut.planning._slices",
    "MAX_PATH_POSES": "taut.planning._verify",
    "PathCheck": "taut.planning._verify",
    "pose_validity": "taut.planning._verify",
    "verify_path": "taut.planning._verify",
}

__all__ = [
    "Atlas",
    "ImplicitManifold",
    "MAX_CHARTS",
    "MAX_NODES",
    "MAX_PATH_POSES",
    "METHODS",
    "ManifoldChart",
    "POSE_NAMES",
    "PathCheck",
    "PathResult",
    "Polytope",
    "RADIUS",
    "SliceMap",
    "Symmetry",
    "WrenchFeasibleManifold",
    "plan_path",
    "pose_validity",
    "project",
    "refine_path",
    "shorten_path",
    "slice_map",
    "tangent_basis",
    "verify_path",
]

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
