"""Tensions of a motion against time: :func:`plot_motion_tensions`; a controlled motion's
tensions and tracking error: :func:`plot_control`.

The figure of CASPR's inverse-dynamics workflow: one curve per cable over the trajectory's
time, the tension bounds dashed, and the samples without an admissible distribution shaded
(:func:`taut.viz._tensions.plot_tensions` draws it).  For a simulated motion of elastic cables
the samples where a cable is slack are marked infeasible.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, cast

import numpy as np

from taut.viz._tensions import plot_tensions

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from taut.dynamics import ControlResult, ForwardDynamicsResult, InverseDynamicsResult
    from taut.model import Robot

__all__ = ["plot_motion_tensions", "plot_control"]


def plot_motion_tensions(
    robot: Robot, result: InverseDynamicsResult | ForwardDynamicsResult, ax: Axes | None = None
) -> Axes:
    """Plot the tensions of an inverse-dynamics result (against its ``time``, or the sample
    index without one) or of a simulated motion (against time; slack samples marked) on 2-D
    axes ``ax`` (``None``: a new figure) and return the ``Axes``."""
    tmin, tmax = robot.tension_bounds
    slack = getattr(result, "slack", None)  # only a simulated motion has slack cables
    admissible: np.ndarray
    if slack is None:
        admissible = np.asarray(cast("InverseDynamicsResult", result).feasible, bool)
        ax = plot_tensions(result.time, result.tensions, tmin, tmax, admissible, ax)
        what = f"inverse dynamics ({result.method})"
    else:
        admissible = np.asarray(~np.asarray(slack, bool).any(axis=1))
        ax = plot_tensions(result.time, result.tensions, tmin, tmax, admissible, ax, mask_infeasible=False)
        what = f"simulated motion ({result.method})"
    ok = int(np.count_nonzero(admissible))
    ax.set_title(f"{robot.name}: {what}, {ok} of {len(result.tensions)} samples admissible", fontsize=10)
    return ax


def plot_control(robot: Robot, result: ControlResult) -> Figure:
    """A new figure of a controlled motion (:func:`taut.dynamics.simulate_control`):
    the commanded tensions against time with their bounds, the updates where the distribution
    failed (the last admissible tensions held) marked; below, the tracking error of each pose
    coordinate (positions in mm, angles in mrad)."""
    import matplotlib.pyplot as plt

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    plot_tensions(
        result.time,
        result.tensions,
        result.tension_min,
        result.tension_max,
        result.admissible,
        top,
        mask_infeasible=False,
    )
    top.set_xlabel("")
    held = f", {result.failures} held" if result.failures else ""
    top.set_title(
        f"{robot.name}: computed-torque control at {result.rate_hz:g} Hz, min. tension margin "
        f"{result.min_tension_margin:.3g} N{held}",
        fontsize=10,
    )
    d = robot.dimension
    for j, name in enumerate(result.pose_names):
        unit = "mm" if j < d else "mrad"
        bottom.plot(result.time, 1e3 * result.error[:, j], label=f"{name} [{unit}]", lw=1.2)
    bottom.axhline(0.0, color="0.6", lw=0.8)
    bottom.set_xlabel("time [s]")
    bottom.set_ylabel("tracking error q_ref − q")
    bottom.legend(fontsize=8, ncol=min(6, len(result.pose_names)), loc="best")
    fig.tight_layout()
    return fig
