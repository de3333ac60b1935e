"""The demo's section on calibration: a cable printer built off its drawing, its exits and
encoder zeros found again from 40 measurements at planned poses that nobody measured
(Borgstrom et al. 2009; Miermeister & Pott 2012).

References
----------
.. [1] P. H. Borgstrom et al., "NIMS-PL: A Cable-Driven Robot With Self-Calibration
   Capabilities", IEEE Transactions on Robotics 25(5), 2009. (docs/references.bib: borgstrom2009)
.. [2] P. Miermeister, A. Pott, "Auto-Calibration Method for Overconstrained Cable-Driven
   Parallel Robots", IEEE ICRA 2012. (docs/references.bib: miermeister2012)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from taut.calibration import calibrate, plan_poses, simulate_measurements
from taut.geometry import rigid_alignment
from taut.model import example
from taut.viz import plot_calibration

if TYPE_CHECKING:
    from taut.viz import Report

#: How far the built robot's exits are from the drawing's [m], its encoder zeros' lengths [m],
#: and the noise of its length readings [m].
BUILT_ERROR = 0.03
ZEROS = (1.1, 1.2, 1.3, 1.4, 1.5)
NOISE = 2e-4


def calibration_section(report: Report) -> None:
    """Demo section: ``printer-5cable`` built with its exits up to 3 cm off, calibrated from
    length changes at 40 planned poses."""
    nominal = example("printer-5cable")
    rng = np.random.default_rng(5)
    exits = nominal.exits + rng.uniform(-BUILT_ERROR, BUILT_ERROR, nominal.exits.shape)
    built = nominal.model_copy(
        update={"cables": tuple(c.model_copy(update={"exit": tuple(e)}) for c, e in zip(nominal.cables, exits))}
    )
    plan = plan_poses(nominal, 40)
    data = simulate_measurements(built, plan.poses, offsets=ZEROS, sigma=NOISE, seed=6)
    res = calibrate(nominal, data)
    # the truth in the result's gauge: the built exits aligned onto the drawing's
    Q, t = rigid_alignment(exits, nominal.exits)
    truth = exits @ Q.T + t
    before = float(np.abs(truth - nominal.exits).max())
    after = float(np.abs(res.exits - truth).max())
    worst = float(np.max(np.abs(res.exits - truth) / res.exits_std))
    offset_error = float(np.abs(res.offsets - ZEROS).max())
    text = (
        f"The 5-cable printer as built: exits up to {BUILT_ERROR * 100:.0f} cm from the drawing, encoders zeroed "
        f"at unknown lengths, readings with {NOISE * 1000:.1f} mm noise. taut calibrate --plan chose 40 poses "
        f"(D-optimal among {plan.candidates} wrench-feasible candidates); from the length changes read there, "
        f"the poses unknown, the fit put every exit within {after * 1000:.2f} mm of the truth (the drawing was "
        f"{before * 1000:.1f} mm off), at most {worst:.1f} of its own standard deviations, and every encoder zero "
        f"within {offset_error * 1000:.2f} mm, in {res.elapsed_s:.2f} s. Identifiable: "
        f"{'yes' if res.identifiable else 'no'} (rank {res.identifiability.rank} of "
        f"{res.identifiability.unknowns}, condition number {res.identifiability.condition:.3g}); gauge: {res.gauge}."
    )
    fig = plot_calibration(nominal, res, truth=truth)
    report.add_section(
        "printer-5cable: calibration from its own cable readings",
        text=text,
        figures=[(fig, "printer-5cable-calibration.png", "exit corrections with ±3σ (× the truth); residuals")],
        json={
            "drawing_error_m": before,
            "exit_error_m": after,
            "worst_z": worst,
            "offset_error_m": offset_error,
            "identifiable": res.identifiable,
            "elapsed_s": res.elapsed_s,
        },
    )
