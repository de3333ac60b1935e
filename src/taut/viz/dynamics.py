"""Tensions of a motion against time: :func:`plot_motion_tensions`.

The figure of CASPR's inverse-dynamics workflow: one curve per cable over the trajectory's
time, the tension bounds dashed, and the samples without an admissible distribution shaded
(:func:`taut.viz.tensions.plot_tensions` draws it).  For a simulated motion of elastic cables
the samples where a cable is slack are marked infeasible.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from taut.dynamics.forward import ForwardDynamicsResult
from taut.dynamics.inverse import InverseDynamicsResult
from taut.model.robot import Robot
from taut.viz.tensions import plot_tensions

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = ["plot_motion_tensions"]


def plot_motion_tensions(
    robot: Robot, result: InverseDynamicsResult | ForwardDynamicsResult, ax: Axes | None = None
) -> Axes:
    """Plot the tensions of an inverse-dynamics result (against its ``time``, or the sample
    index without one) or of a simulated motion (against time; slack samples marked) on 2-D
    axes ``ax`` (``None``: a new figure) and return the ``Axes``."""
    tmin, tmax = robot.tension_bounds
    if isinstance(result, InverseDynamicsResult):
        ax = plot_tensions(result.time, result.tensions, tmin, tmax, result.feasible, ax)
        what = f"inverse dynamics ({result.method})"
    else:
        taut_all = ~result.slack.any(axis=1)
        ax = plot_tensions(result.time, result.tensions, tmin, tmax, taut_all, ax, mask_infeasible=False)
        what = f"simulated motion ({result.method})"
    ok = int(np.count_nonzero(result.feasible if isinstance(result, InverseDynamicsResult) else taut_all))
    ax.set_title(f"{robot.name}: {what}, {ok} of {len(result.tensions)} samples admissible", fontsize=10)
    return ax
