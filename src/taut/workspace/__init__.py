"""Workspaces (Rushton 2022, §2.1.4): conditions (wrench closure, wrench
feasibility, static equilibrium) in a registry, pose grids, and grid evaluation over an
executor of :mod:`taut.parallel`.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §2.1.4. (docs/references.bib: rushton2022)
"""

from taut.workspace.conditions import (
    CONDITIONS,
    StaticEquilibrium,
    WorkspaceCondition,
    WrenchClosure,
    WrenchCondition,
    WrenchFeasible,
    default_wrench_set,
    make_condition,
)
from taut.workspace.evaluate import WorkspaceResult, evaluate_workspace
from taut.workspace.grid import MAX_GRID_POSES, PoseGrid, default_bounds, make_grid, pose_grid, position_grid

__all__ = [
    "CONDITIONS",
    "MAX_GRID_POSES",
    "PoseGrid",
    "StaticEquilibrium",
    "WorkspaceCondition",
    "WorkspaceResult",
    "WrenchClosure",
    "WrenchCondition",
    "WrenchFeasible",
    "default_bounds",
    "default_wrench_set",
    "evaluate_workspace",
    "make_condition",
    "make_grid",
    "pose_grid",
    "position_grid",
]
