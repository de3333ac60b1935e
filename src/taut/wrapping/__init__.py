"""Collidable cables of planar variable-structure CDPRs (Chs. 3–4, 6 of Rushton 2022):
cable state (§4.1), cable-state tree (§4.2.1), state update (§4.2.2), VSCR IK (§4.3), trajectories (§6.2).

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, Chs. 3–4 (§4.1–4.3) and Ch. 6 (§6.2). (docs/references.bib: rushton2022)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports

if TYPE_CHECKING:
    from taut.wrapping._ik import WrappedIK, collidable_objects, wrapped_inverse_kinematics
    from taut.wrapping._state import CablePath, CableState, contacts_text, rebuild_path
    from taut.wrapping._trajectory import (
        DEFAULT_SPEED,
        TrajectoryResult,
        builtin_trajectory,
        full_poses,
        run_trajectory,
        timed_moves,
    )
    from taut.wrapping._tree import MAX_TREE_NODES, CableStateTree
    from taut.wrapping._update import Tracking, track_cable_state, update_state

#: Every name is imported on first use (PEP 562), so that importing the package loads nothing heavy.
_LAZY = {
    "WrappedIK": "taut.wrapping._ik",
    "collidable_objects": "taut.wrapping._ik",
    "wrapped_inverse_kinematics": "taut.wrapping._ik",
    "CablePath": "taut.wrapping._state",
    "CableState": "taut.wrapping._state",
    "contacts_text": "taut.wrapping._state",
    "rebuild_path": "taut.wrapping._state",
    "DEFAULT_SPEED": "taut.wrapping._trajectory",
    "TrajectoryResult": "taut.wrapping._trajectory",
    "builtin_trajectory": "taut.wrapping._trajectory",
    "full_poses": "taut.wrapping._trajectory",
    "run_trajectory": "taut.wrapping._trajectory",
    "timed_moves": "taut.wrapping._trajectory",
    "CableStateTree": "taut.wrapping._tree",
    "MAX_TREE_NODES": "taut.wrapping._tree",
    "Tracking": "taut.wrapping._update",
    "track_cable_state": "taut.wrapping._update",
    "update_state": "taut.wrapping._update",
}

__all__ = [
    "CablePath",
    "CableState",
    "CableStateTree",
    "DEFAULT_SPEED",
    "MAX_TREE_NODES",
    "Tracking",
    "TrajectoryResult",
    "WrappedIK",
    "builtin_trajectory",
    "collidable_objects",
    "contacts_text",
    "full_poses",
    "rebuild_path",
    "run_trajectory",
    "timed_moves",
    "track_cable_state",
    "update_state",
    "wrapped_inverse_kinematics",
]

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
