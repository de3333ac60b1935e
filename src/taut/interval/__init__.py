"""Interval analysis (Berti 2015, §1.3 and Ch. 3): outward-rounded
interval arithmetic, polynomial constraint tapes, HC4 contraction, slope enclosures,
Krawczyk certificates with inflation, a branch-and-prune solver, and hyperplane shifting over
interval matrices (Gouttefarde, Daney & Merlet 2011).

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §1.3 and Ch. 3. (docs/references.bib: berti2015)
.. [2] M. Gouttefarde, D. Daney, J.-P. Merlet, "Interval-analysis-based determination of the
   wrench-feasible workspace of parallel cable-driven robots", IEEE Transactions on Robotics
   27(1), 2011. (docs/references.bib: gouttefarde2011)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports

if TYPE_CHECKING:
    from taut.interval._arithmetic import Interval, centred_form
    from taut.interval._branch_prune import (
        CERTIFY_BOXES,
        MAX_BOXES,
        Box,
        BranchAndPruneResult,
        bisect,
        branch_and_prune,
        file_certificate,
        same_solution,
    )
    from taut.interval._expression import (
        CONST,
        ONE,
        SQR,
        ZERO,
        Expr,
        System,
        Tape,
        atan,
        compile_system,
        compile_tape,
        const,
        derivative,
        sqrt,
        variables,
    )
    from taut.interval._hc4 import contract, evaluate, evaluate_point, point_kernel
    from taut.interval._krawczyk import Certificate, certified_step, certify, inflate, krawczyk, newton
    from taut.interval._linear import LinearFilter, interval_gauss, preconditioned_solve
    from taut.interval._precise import MAX_PRECISE_BOXES, precise_available, solve_precise
    from taut.interval._zonotope import (
        INSIDE,
        OUTSIDE,
        OUTSIDE_RTOL,
        UNDECIDED,
        separating_directions,
        zonotope_verdicts,
    )

#: Every name is imported on first use (PEP 562), so that importing the package loads nothing heavy.
_LAZY = {
    "INSIDE": "taut.interval._zonotope",
    "OUTSIDE": "taut.interval._zonotope",
    "OUTSIDE_RTOL": "taut.interval._zonotope",
    "UNDECIDED": "taut.interval._zonotope",
    "zonotope_verdicts": "taut.interval._zonotope",
    "separating_directions": "taut.interval._zonotope",
    "Interval": "taut.interval._arithmetic",
    "centred_form": "taut.interval._arithmetic",
    "Box": "taut.interval._branch_prune",
    "BranchAndPruneResult": "taut.interval._branch_prune",
    "CERTIFY_BOXES": "taut.interval._branch_prune",
    "MAX_BOXES": "taut.interval._branch_prune",
    "bisect": "taut.interval._branch_prune",
    "branch_and_prune": "taut.interval._branch_prune",
    "file_certificate": "taut.interval._branch_prune",
    "same_solution": "taut.interval._branch_prune",
    "CONST": "taut.interval._expression",
    "Expr": "taut.interval._expression",
    "ONE": "taut.interval._expression",
    "SQR": "taut.interval._expression",
    "System": "taut.interval._expression",
    "Tape": "taut.interval._expression",
    "ZERO": "taut.interval._expression",
    "atan": "taut.interval._expression",
    "compile_system": "taut.interval._expression",
    "compile_tape": "taut.interval._expression",
    "const": "taut.interval._expression",
    "derivative": "taut.interval._expression",
    "sqrt": "taut.interval._expression",
    "variables": "taut.interval._expression",
    "contract": "taut.interval._hc4",
    "evaluate": "taut.interval._hc4",
    "evaluate_point": "taut.interval._hc4",
    "point_kernel": "taut.interval._hc4",
    "Certificate": "taut.interval._krawczyk",
    "certified_step": "taut.interval._krawczyk",
    "certify": "taut.interval._krawczyk",
    "inflate": "taut.interval._krawczyk",
    "krawczyk": "taut.interval._krawczyk",
    "newton": "taut.interval._krawczyk",
    "LinearFilter": "taut.interval._linear",
    "interval_gauss": "taut.interval._linear",
    "preconditioned_solve": "taut.interval._linear",
    "MAX_PRECISE_BOXES": "taut.interval._precise",
    "precise_available": "taut.interval._precise",
    "solve_precise": "taut.interval._precise",
}

__all__ = [
    "INSIDE",
    "OUTSIDE",
    "OUTSIDE_RTOL",
    "UNDECIDED",
    "Box",
    "BranchAndPruneResult",
    "CERTIFY_BOXES",
    "CONST",
    "Certificate",
    "Expr",
    "Interval",
    "LinearFilter",
    "MAX_BOXES",
    "MAX_PRECISE_BOXES",
    "ONE",
    "SQR",
    "System",
    "Tape",
    "ZERO",
    "atan",
    "bisect",
    "branch_and_prune",
    "centred_form",
    "certified_step",
    "certify",
    "compile_system",
    "compile_tape",
    "const",
    "contract",
    "derivative",
    "evaluate",
    "evaluate_point",
    "file_certificate",
    "inflate",
    "interval_gauss",
    "krawczyk",
    "newton",
    "point_kernel",
    "precise_available",
    "preconditioned_solve",
    "same_solution",
    "solve_precise",
    "sqrt",
    "variables",
    "zonotope_verdicts",
    "separating_directions",
]

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
