"""The trajectory figure: pose, velocity and acceleration panels hold the sampled data."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import taut  # noqa: E402
from taut.errors import ArgumentError  # noqa: E402
from taut.motion import trajectory_from_robot  # noqa: E402
from taut.viz._motion import plot_motion  # noqa: E402


def test_three_panels_hold_pose_velocity_and_acceleration(tmp_path):
    robot = taut.example("adjustable-8cable")
    motion = trajectory_from_robot(robot, "sim-a", duration=4.0, law="trapezoidal")
    s = motion.sample(50)
    fig = plot_motion(s, motion.times)
    axes = fig.axes
    assert len(axes) == 3
    for ax, kind, values in zip(axes, ("pose", "velocity", "acceleration"), (s.pose, s.velocity, s.acceleration)):
        lines = {line.get_gid(): line for line in ax.lines}
        for k, name in enumerate(robot.pose_names):
            line = lines[f"{kind}-{name}"]
            assert np.array_equal(line.get_xdata(), s.time)
            assert np.array_equal(line.get_ydata(), values[:, k])
        marks = [line.get_xdata()[0] for line in ax.lines if line.get_gid() == "waypoint"]
        assert marks == [0.0, 2.0, 4.0]
    assert axes[2].get_xlabel() == "time [s]"
    fig.savefig(tmp_path / "motion.png")
    assert (tmp_path / "motion.png").stat().st_size > 0
    with pytest.raises(ArgumentError, match="empty figure"):
        plot_motion(s, fig=fig)
    plt.close("all")
