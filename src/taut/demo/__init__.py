"""The main job of ``taut demo``: run taut on built-in robots and write an HTML report.

The report is a list of sections, each added by one function taking a
:class:`taut.viz.Report`: the function runs its analysis (solvers, planners, simulations)
and hands the results to the figures of :mod:`taut.viz`, which only draw them
(``docs/architecture.md`` §1).  An analysis joins the demo by adding its function to the
private list of sections.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports

if TYPE_CHECKING:
    from taut.demo._run import run_demo

#: Every name is imported on first use (PEP 562), so that importing the package loads nothing heavy.
_LAZY = {
    "run_demo": "taut.demo._run",
}

__all__ = [
    "run_demo",
]

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
