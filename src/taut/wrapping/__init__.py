"""Collidable cables of planar variable-structure CDPRs (Chs. 3–4, 6 of Rushton 2022):
cable state (§4.1), cable-state tree (§4.2.1), state update (§4.2.2), VSCR IK (§4.3), trajectories (§6.2).

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, Chs. 3–4 (§4.1–4.3) and Ch. 6 (§6.2). (docs/references.bib: rushton2022)
"""

from taut.wrapping._ik import WrappedIK, wrapped_inverse_kinematics
from taut.wrapping._state import CablePath, CableState, rebuild_path
from taut.wrapping._trajectory import TrajectoryResult, builtin_trajectory, run_trajectory
from taut.wrapping._tree import CableStateTree
from taut.wrapping._update import track, update_state

__all__ = [
    "CablePath",
    "CableState",
    "CableStateTree",
    "TrajectoryResult",
    "WrappedIK",
    "builtin_trajectory",
    "rebuild_path",
    "run_trajectory",
    "track",
    "update_state",
    "wrapped_inverse_kinematics",
]
