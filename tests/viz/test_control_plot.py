"""The figure of a controlled motion (``taut.viz._dynamics.plot_control``)."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402

import taut  # noqa: E402
from taut.dynamics import WrenchSteps, simulate_control  # noqa: E402
from taut.motion import trajectory_from_waypoints  # noqa: E402
from taut.viz._dynamics import plot_control  # noqa: E402


def test_plot_control_draws_tensions_and_errors():
    robot = taut.example("spatial-8cable")
    motion = trajectory_from_waypoints(robot, [[0.0] * 6, [0.2, 0.1, 0.1, 0, 0, 0.1]], duration=1.0)
    res = simulate_control(robot, motion, disturbance=WrenchSteps.step(0.5, [4.0, 0, 0, 0, 0, 0]))
    fig = plot_control(robot, res)
    top, bottom = fig.axes[:2]
    tensions = {ln.get_gid(): np.asarray(ln.get_ydata()) for ln in top.lines if ln.get_gid()}
    for i in range(8):
        np.testing.assert_allclose(tensions[f"tension-{i + 1}"], res.tensions[:, i])
    errors = [np.asarray(ln.get_ydata()) for ln in bottom.lines if ln.get_label().startswith(("x ", "c "))]
    np.testing.assert_allclose(errors[0], 1e3 * res.error[:, 0])
    np.testing.assert_allclose(errors[1], 1e3 * res.error[:, 5])
