"""The sections of the demo report, in order, and :func:`run_demo`, which writes it."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from taut.demo._atlas import atlas_section
from taut.demo._calibration import calibration_section
from taut.demo._certified import certified_section
from taut.demo._check import check_section
from taut.demo._control import control_section
from taut.demo._dgp import dgp_section
from taut.demo._plan import plan_section
from taut.demo._standard import robots_section, standard_model_section
from taut.demo._wrapping import trajectory_section
from taut.viz import Report

#: The report's sections: each runs one analysis and adds its results to the report.
SECTIONS: list[Callable[[Report], object]] = [
    robots_section,
    lambda r: standard_model_section(r, "planar-4cable", shift=[0.8, 0.6], resolution=80),
    lambda r: standard_model_section(r, "spatial-8cable", shift=[1.2, 0.0, 0.8], resolution=30),
    certified_section,
    dgp_section,
    trajectory_section,
    atlas_section,
    check_section,
    plan_section,
    control_section,
    calibration_section,
]


def run_demo(out: Path) -> Path:
    """Run every section of :data:`SECTIONS` and write the report into ``out``.

    Parameters
    ----------
    out
        The report's directory (created if needed).

    Returns
    -------
    Path
        The path of the report's ``index.html``.

    Examples
    --------
    >>> from taut.demo import run_demo
    >>> run_demo("report")  # doctest: +SKIP
    PosixPath('report/index.html')
    """
    import matplotlib

    matplotlib.use("Agg")
    report = Report("taut demo report")
    for section in SECTIONS:
        section(report)
    return report.write(Path(out))
