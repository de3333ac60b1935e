"""Figure of a calibration (:func:`taut.calibration.calibrate`): :func:`plot_calibration` —
each exit's correction from its nominal position with its ±3σ interval (and, for a synthetic
trial, the truth), and each cable's residual.

References
----------
.. [1] P. Miermeister, A. Pott, "Auto-Calibration Method for Overconstrained Cable-Driven
   Parallel Robots", IEEE ICRA 2012. (docs/references.bib: miermeister2012)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from taut.errors import ArgumentError
from taut.viz._style import cable_color, empty_figure

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from taut.calibration import CalibrationResult
    from taut.model import Robot

__all__ = ["plot_calibration"]


def plot_calibration(
    robot: Robot, result: CalibrationResult, *, truth: npt.ArrayLike | None = None, fig: Figure | None = None
) -> Figure:
    """Figure of a calibration: per cable and coordinate, the estimated exit's correction from
    the nominal exit [mm] with its ±3σ interval, and the true correction where known (left);
    each cable's residual RMS [mm] (right).

    Parameters
    ----------
    robot : Robot
        The nominal robot of the fit.
    result : CalibrationResult
    truth : array_like, shape (n, d), optional
        The true exits in the result's frame (a synthetic trial), drawn as crosses.
    fig : matplotlib.figure.Figure, optional
        An empty figure to lay the two panels out on; ``None``: a new one.

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    ArgumentError
        A result of another robot, a ``truth`` of the wrong shape or not finite, a figure that
        already has axes.

    References
    ----------
    .. [1] P. Miermeister, A. Pott, "Auto-Calibration Method for Overconstrained Cable-Driven
       Parallel Robots", IEEE ICRA 2012. (docs/references.bib: miermeister2012)

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> from taut.model import example
    >>> from taut.calibration import calibrate, plan_poses, simulate_measurements
    >>> from taut.viz import plot_calibration
    >>> robot = example("printer-5cable")
    >>> data = simulate_measurements(robot, plan_poses(robot, 20).poses, offsets=[1.0] * 5, sigma=1e-4, seed=0)
    >>> fig = plot_calibration(robot, calibrate(robot, data))
    >>> len(fig.axes)
    2
    """
    n, d = robot.n_cables, robot.dimension
    if result.exits.shape != (n, d):
        raise ArgumentError(f"result: exits of shape {result.exits.shape}, {robot.name} has {n} cables in {d}-D")
    true = None
    if truth is not None:
        true = np.asarray(truth, dtype=float)
        if true.shape != (n, d) or not np.isfinite(true).all():
            raise ArgumentError(f"truth: expected {n} finite exits of {d} coordinates, got shape {true.shape}")
    fig = empty_figure(fig, "a calibration", (12.0, 4.8))
    ax, res_ax = fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2)
    correction = (result.exits - robot.exits) * 1000
    spread = np.where(np.isfinite(result.exits_std), 3 * result.exits_std * 1000, np.nan)
    width = 0.8 / d
    for k in range(d):
        x = np.arange(n) + (k - (d - 1) / 2) * width
        for i in range(n):
            color = cable_color(i + 1)
            ax.bar(x[i], correction[i, k], width * 0.9, color=color, alpha=0.35 + 0.25 * k)
            ax.errorbar(x[i], correction[i, k], yerr=spread[i, k], color="black", lw=0.9, capsize=2)
            if true is not None:
                ax.plot(x[i], (true[i, k] - robot.exits[i, k]) * 1000, "x", color="black", ms=6)
    ax.axhline(0.0, color="grey", lw=0.8)
    ax.set_xticks(np.arange(n), [f"{i + 1}\n{'xyz'[:d]}" for i in range(n)])
    ax.set_xlabel("cable (bars: x, y[, z])")
    ax.set_ylabel("exit correction from nominal [mm]")
    ax.set_title("estimate ± 3σ" + (" (× the truth)" if true is not None else ""))
    res_ax.bar(np.arange(n), result.residual_rms * 1000, color=[cable_color(i + 1) for i in range(n)])
    res_ax.set_xticks(np.arange(n), [str(i + 1) for i in range(n)])
    res_ax.set_xlabel("cable")
    res_ax.set_ylabel("residual RMS [mm]")
    ident = result.identifiability
    res_ax.set_title(
        f"σ = {result.sigma * 1000:.3g} mm; {'identifiable' if ident.identifiable else 'NOT identifiable'} "
        f"(rank {ident.rank}/{ident.unknowns})"
    )
    fig.suptitle(f"{robot.name}: calibrated {', '.join(result.estimate)} from {len(result.poses)} rows")
    fig.tight_layout()
    return fig
