"""Interval analysis (Berti 2015, §1.3 and Ch. 3): outward-rounded
interval arithmetic, polynomial constraint tapes, HC4 contraction, slope enclosures,
Krawczyk certificates with inflation, and a branch-and-prune solver.

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §1.3 and Ch. 3. (docs/references.bib: berti2015)
"""

from taut.interval.arithmetic import Interval, centred_form
from taut.interval.branch_prune import CERTIFY_BOXES, BranchAndPruneResult, branch_and_prune
from taut.interval.expression import System, compile_system, const, derivative, sqrt, variables
from taut.interval.hc4 import contract, evaluate, evaluate_point
from taut.interval.krawczyk import Certificate, certify, inflate, krawczyk, newton
from taut.interval.linear import LinearFilter, interval_gauss, preconditioned_solve

__all__ = [
    "CERTIFY_BOXES",
    "BranchAndPruneResult",
    "Certificate",
    "Interval",
    "LinearFilter",
    "System",
    "branch_and_prune",
    "centred_form",
    "certify",
    "compile_system",
    "const",
    "contract",
    "derivative",
    "evaluate",
    "evaluate_point",
    "inflate",
    "interval_gauss",
    "krawczyk",
    "newton",
    "preconditioned_solve",
    "sqrt",
    "variables",
]
