"""The geometrico-static problems of under-constrained robots (Berti 2015):
the direct one (Ch. 2–3, all equilibria for given cable lengths) and the inverse one
(§4.1.2, the unassigned pose coordinates, tensions and lengths for chosen taut cables), and
tracking forward kinematics (§4.1.2, the equilibrium that follows a known one).

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, Chs. 2–3 and §4.1.2. (docs/references.bib: berti2015)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports

if TYPE_CHECKING:
    from taut.dgp._formulation import build_subproblem, load, reference_choice
    from taut.dgp._inverse import IGPResult, IGPSolution, solve_igp
    from taut.dgp._point_mass import LeastSquaresFit
    from taut.dgp._solve import DGPResult, DGPSolution, solve_dgp, solve_subset
    from taut.dgp._stability import is_stable, reduced_hessian
    from taut.dgp._tracking import track_equilibrium, track_path
    from taut.dgp._undecided import CAUSES, MAX_SUBPROBLEM_BOXES, UndecidedBox

#: Every name is imported on first use (PEP 562), so that importing the package loads nothing heavy.
_LAZY = {
    "build_subproblem": "taut.dgp._formulation",
    "load": "taut.dgp._formulation",
    "reference_choice": "taut.dgp._formulation",
    "IGPResult": "taut.dgp._inverse",
    "IGPSolution": "taut.dgp._inverse",
    "solve_igp": "taut.dgp._inverse",
    "LeastSquaresFit": "taut.dgp._point_mass",
    "DGPResult": "taut.dgp._solve",
    "DGPSolution": "taut.dgp._solve",
    "solve_dgp": "taut.dgp._solve",
    "solve_subset": "taut.dgp._solve",
    "is_stable": "taut.dgp._stability",
    "reduced_hessian": "taut.dgp._stability",
    "track_equilibrium": "taut.dgp._tracking",
    "track_path": "taut.dgp._tracking",
    "CAUSES": "taut.dgp._undecided",
    "MAX_SUBPROBLEM_BOXES": "taut.dgp._undecided",
    "UndecidedBox": "taut.dgp._undecided",
}

__all__ = [
    "CAUSES",
    "DGPResult",
    "DGPSolution",
    "IGPResult",
    "IGPSolution",
    "LeastSquaresFit",
    "MAX_SUBPROBLEM_BOXES",
    "UndecidedBox",
    "build_subproblem",
    "is_stable",
    "load",
    "reduced_hessian",
    "reference_choice",
    "solve_dgp",
    "solve_igp",
    "solve_subset",
    "track_equilibrium",
    "track_path",
]

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
