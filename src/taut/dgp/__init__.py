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

from taut.dgp._inverse import IGPResult, IGPSolution, solve_igp
from taut.dgp._solve import DGPResult, DGPSolution, solve_dgp
from taut.dgp._stability import is_stable, reduced_hessian
from taut.dgp._tracking import track, track_path

__all__ = [
    "DGPResult",
    "DGPSolution",
    "IGPResult",
    "IGPSolution",
    "is_stable",
    "reduced_hessian",
    "solve_dgp",
    "solve_igp",
    "track",
    "track_path",
]
