"""Structure atlas of planar variable-structure CDPRs (Ch. 5 of Rushton 2022):
cable-reachable areas (§5.1.2), charts (§5.1.1), the atlas (§5.1.3, Alg. 5.1), its workspace
(§5.3.1, Alg. 5.2) and inverse kinematics (§5.3.2, Algs. 5.3–5.4); for rigid platforms the
platform-reachable area (§5.2.1) and one atlas page per orientation (§5.2.2).

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, Ch. 5 (§5.1–5.3, Algs. 5.1–5.4). (docs/references.bib: rushton2022)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports

if TYPE_CHECKING:
    from taut.atlas._atlas import Edge, StructureAtlas, build_atlas
    from taut.atlas._chart import StructureChart, chart_lengths, structure_reachable_area
    from taut.atlas._ik import AtlasIK, direct_ik, iterative_ik, iterative_step, locate
    from taut.atlas._platform import platform_outline, platform_reachable_area
    from taut.atlas._reachable import cable_reachable_area
    from taut.atlas._workspace import AtlasWorkspace, atlas_workspace

#: Every name is imported on first use (PEP 562), so that importing the package loads nothing heavy.
_LAZY = {
    "Edge": "taut.atlas._atlas",
    "StructureAtlas": "taut.atlas._atlas",
    "build_atlas": "taut.atlas._atlas",
    "StructureChart": "taut.atlas._chart",
    "chart_lengths": "taut.atlas._chart",
    "structure_reachable_area": "taut.atlas._chart",
    "AtlasIK": "taut.atlas._ik",
    "direct_ik": "taut.atlas._ik",
    "iterative_ik": "taut.atlas._ik",
    "iterative_step": "taut.atlas._ik",
    "locate": "taut.atlas._ik",
    "platform_outline": "taut.atlas._platform",
    "platform_reachable_area": "taut.atlas._platform",
    "cable_reachable_area": "taut.atlas._reachable",
    "AtlasWorkspace": "taut.atlas._workspace",
    "atlas_workspace": "taut.atlas._workspace",
}

__all__ = [
    "AtlasIK",
    "AtlasWorkspace",
    "Edge",
    "StructureAtlas",
    "StructureChart",
    "atlas_workspace",
    "build_atlas",
    "cable_reachable_area",
    "chart_lengths",
    "direct_ik",
    "iterative_ik",
    "iterative_step",
    "locate",
    "platform_outline",
    "platform_reachable_area",
    "structure_reachable_area",
]

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
