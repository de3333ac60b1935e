"""Pose, velocity and acceleration of a trajectory against time: :func:`plot_motion`.

Three panels, one above the other and sharing the time axis, with one line per pose
coordinate (labelled with the robot's pose names, metres and radians on the same axes), as
CASPR plots a joint trajectory (``JointTrajectory.plotJointSpace``: trajectory, velocity,
acceleration), and the waypoint times as vertical dotted lines.

References
----------
.. [1] D. Lau, J. Eden, Y. Tan, D. Oetomo, "CASPR: A comprehensive cable-robot analysis and
   simulation platform for the research of cable-driven parallel robots", IEEE/RSJ
   International Conference on Intelligent Robots and Systems (IROS), 2016.
   (docs/references.bib: lau2016)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from taut.viz._style import cable_color, empty_figure

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from taut.motion import MotionSamples

__all__ = ["plot_motion"]


def plot_motion(
    samples: MotionSamples, waypoint_times: npt.ArrayLike | None = None, fig: Figure | None = None
) -> Figure:
    """Plot ``samples`` (e.g. ``motion.sample(100)``) on the empty figure ``fig`` (``None``: a
    new one; a figure that already has axes raises :class:`~taut.errors.ArgumentError`) and
    return it: pose, velocity and acceleration of every pose coordinate against time, with
    dotted lines at ``waypoint_times`` (e.g. ``motion.times``).  Coordinate ``k`` has ``gid="pose-<name>"``,
    ``"velocity-<name>"``, ``"acceleration-<name>"`` in the three panels."""
    fig = empty_figure(fig, "a trajectory's pose, velocity and acceleration", (7.5, 8.0))
    axes = fig.subplots(3, 1, sharex=True)
    panels = (
        ("pose", samples.pose, "pose [m, rad]"),
        ("velocity", samples.velocity, "velocity [m/s, rad/s]"),
        ("acceleration", samples.acceleration, "acceleration [m/s², rad/s²]"),
    )
    marks = np.asarray([] if waypoint_times is None else waypoint_times, float).ravel()
    for ax, (kind, values, label) in zip(axes, panels):
        for k, name in enumerate(samples.pose_names):
            ax.plot(samples.time, values[:, k], color=cable_color(k), lw=1.4, label=name, gid=f"{kind}-{name}")
        for t in marks:
            ax.axvline(t, color="black", ls=":", lw=0.8, gid="waypoint")
        ax.set_ylabel(label)
        ax.grid(True, lw=0.3, alpha=0.5)
    axes[0].legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    axes[0].set_title(f"trajectory: {len(samples.time)} samples over {float(np.ptp(samples.time)):g} s", fontsize=10)
    axes[-1].set_xlabel("time [s]")
    fig.tight_layout()
    return fig
