"""The figure of a controlled motion (``taut.viz.dynamics.plot_control``) and the demo
report's control section."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402

import taut  # noqa: E402
from taut.dynamics import WrenchSteps, simulate_control  # noqa: E402
from taut.motion import trajectory_from_waypoints  # noqa: E402
from taut.viz import Report  # noqa: E402
from taut.viz.dynamics import control_section, plot_control  # noqa: E402


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


def test_control_section_reports_the_three_runs():
    report = Report("t")
    control_section(report)
    (sec,) = report.sections
    assert [f.filename for f in sec.figures] == ["spatial-8cable-control.png"] and sec.figures[0].png
    exact, heavy, light = sec.table
    assert exact["case"] == "exact model" and exact["max position error [mm]"] < 1e-3
    for row in (heavy, light):
        # a 5 N step on 5 kg at K_p = 400/s² and the weight error: millimetres, not more
        assert 1.0 < row["max position error [mm]"] < 10.0
        assert row["distribution failures"] == 0 and row["min tension margin [N]"] > 0
