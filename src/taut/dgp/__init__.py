"""The direct geometrico-static problem of under-constrained robots
(``001_eb92e2f6589fc229.txt`` Ch. 2–3): all equilibria for given cable lengths."""

from taut.dgp.solve import DGPResult, DGPSolution, solve_dgp
from taut.dgp.stability import is_stable, reduced_hessian

__all__ = ["DGPResult", "DGPSolution", "is_stable", "reduced_hessian", "solve_dgp"]
