"""Workspaces (Rushton 2022, §2.1.4): conditions (wrench closure, wrench
feasibility, static equilibrium) in a registry, pose grids, grid evaluation over an
executor of :mod:`taut.parallel`, and certified workspaces by interval analysis
(Gouttefarde, Daney & Merlet 2011).

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §2.1.4. (docs/references.bib: rushton2022)
.. [2] M. Gouttefarde, D. Daney, J.-P. Merlet, "Interval-analysis-based determination of the
   wrench-feasible workspace of parallel cable-driven robots", IEEE Transactions on Robotics
   27(1), 2011. (docs/references.bib: gouttefarde2011)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports

if TYPE_CHECKING:
    from taut.workspace._certified import CertifiedWorkspace, certified
    from taut.workspace._conditions import (
        CONDITIONS,
        SaggingStatic,
        StaticEquilibrium,
        WorkspaceCondition,
        WrenchClosure,
        WrenchCondition,
        WrenchFeasible,
        default_wrench_set,
        make_condition,
    )
    from taut.workspace._evaluate import WorkspaceResult, evaluate_workspace
    from taut.workspace._grid import MAX_GRID_POSES, PoseGrid, default_bounds, make_grid, pose_grid, position_grid
    from taut.workspace._sag import SagMap, sag_bounds, sag_map, straight_model

#: Every name is imported on first use (PEP 562), so that importing the package loads nothing heavy.
_LAZY = {
    "CertifiedWorkspace": "taut.workspace._certified",
    "certified": "taut.workspace._certified",
    "SagMap": "taut.workspace._sag",
    "sag_bounds": "taut.workspace._sag",
    "sag_map": "taut.workspace._sag",
    "straight_model": "taut.workspace._sag",
    "CONDITIONS": "taut.workspace._conditions",
    "SaggingStatic": "taut.workspace._conditions",
    "StaticEquilibrium": "taut.workspace._conditions",
    "WorkspaceCondition": "taut.workspace._conditions",
    "WrenchClosure": "taut.workspace._conditions",
    "WrenchCondition": "taut.workspace._conditions",
    "WrenchFeasible": "taut.workspace._conditions",
    "default_wrench_set": "taut.workspace._conditions",
    "make_condition": "taut.workspace._conditions",
    "WorkspaceResult": "taut.workspace._evaluate",
    "evaluate_workspace": "taut.workspace._evaluate",
    "MAX_GRID_POSES": "taut.workspace._grid",
    "PoseGrid": "taut.workspace._grid",
    "default_bounds": "taut.workspace._grid",
    "make_grid": "taut.workspace._grid",
    "pose_grid": "taut.workspace._grid",
    "position_grid": "taut.workspace._grid",
}

__all__ = [
    "CONDITIONS",
    "CertifiedWorkspace",
    "MAX_GRID_POSES",
    "PoseGrid",
    "SagMap",
    "SaggingStatic",
    "StaticEquilibrium",
    "WorkspaceCondition",
    "WorkspaceResult",
    "WrenchClosure",
    "WrenchCondition",
    "WrenchFeasible",
    "certified",
    "default_bounds",
    "default_wrench_set",
    "evaluate_workspace",
    "make_condition",
    "make_grid",
    "pose_grid",
    "position_grid",
    "sag_bounds",
    "sag_map",
    "straight_model",
]

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
