"""The main job of ``taut demo``: run taut on built-in robots and write an HTML report.

The report is a list of sections, each added by one function taking a
:class:`taut.viz.Report`: the function runs its analysis (solvers, planners, simulations)
and hands the results to the figures of :mod:`taut.viz`, which only draw them
(``docs/architecture.md`` §1).  An analysis joins the demo by adding its function to the
private list of sections.
"""

from taut.demo._run import run_demo

__all__ = ["run_demo"]
