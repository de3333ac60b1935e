"""The demo's section on certified workspaces: the wrench-feasible workspace of
``planar-4cable`` covered by boxes proven inside, proven outside and undecided (Gouttefarde,
Daney & Merlet 2011), drawn over the grid evaluation of the same region.

References
----------
.. [1] M. Gouttefarde, D. Daney, J.-P. Merlet, "Interval-analysis-based determination of the
   wrench-feasible workspace of parallel cable-driven robots", IEEE Transactions on Robotics
   27(1), 2011. (docs/references.bib: gouttefarde2011)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut.model import example
from taut.viz import plot_certified
from taut.workspace import certified, evaluate_workspace

if TYPE_CHECKING:
    from taut.viz import Report

#: The smallest box of the demo's covering [m].
EPS = 0.005


def certified_section(report: Report) -> None:
    """Demo section: the certified wrench-feasible workspace of ``planar-4cable`` at θ = 0."""
    robot = example("planar-4cable")
    res = certified(robot, "wrench-feasible", eps=EPS)
    grid = evaluate_workspace(robot, "wrench-feasible", resolution=41)
    estimate = grid.count / grid.size * res.region_volume
    ax = plot_certified(res, robot, grid=grid)
    text = (
        f"The wrench-feasible workspace of planar-4cable at θ = 0 (box wrench set around the weight), "
        f"certified to {1000 * EPS:g} mm boxes in {res.elapsed_s:.2f} s: {len(res.inner)} boxes proven inside for "
        f"every position in them ({res.inner_volume:.4f} m²), {len(res.outer)} proven outside "
        f"({res.outer_volume:.4f} m²) and {len(res.undecided)} undecided along the boundary "
        f"({res.undecided_volume:.4f} m², {100 * res.undecided_volume / res.region_volume:.2f} % of the region). "
        f"The true area lies between {res.inner_volume:.4f} and {res.inner_volume + res.undecided_volume:.4f} m²; "
        f"a 41 × 41 grid estimates {estimate:.4f} m² and says nothing between its points."
    )
    report.add_section(
        "planar-4cable: certified wrench-feasible workspace",
        text=text,
        figures=[(ax.figure, "planar-4cable-certified.png", "inner boxes green, undecided grey, grid dots")],
        json=res.as_dict(),
    )
