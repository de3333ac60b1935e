"""The sections of the demo report (``taut.demo``): each runs its analysis and adds what
the sources report; the figures are those of ``taut.viz`` drawn from the results."""

import time

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import taut  # noqa: E402
from taut.demo._atlas import atlas_section  # noqa: E402
from taut.demo._certified import certified_section  # noqa: E402
from taut.demo._check import check_section  # noqa: E402
from taut.demo._control import control_section  # noqa: E402
from taut.demo._plan import plan_section  # noqa: E402
from taut.planning import (
    WrenchFeasibleManifold,  # noqa: E402
    slice_map,  # noqa: E402
)
from taut.viz import (
    Report,  # noqa: E402
    plot_plan,  # noqa: E402
)


@pytest.mark.slow
def test_atlas_section(tmp_path):
    report = Report("atlas")
    atlas_section(report)
    out = report.write(tmp_path)
    html = out.read_text() if out.is_file() else (out / "index.html").read_text()
    assert "structure atlas" in html and "queries/s" in html


def test_certified_section_brackets_the_grid_estimate():
    report = Report("t")
    certified_section(report)
    (sec,) = report.sections
    data = sec.json
    assert data["complete"] and data["boxes"]["inner"] > 0 and data["boxes"]["outer"] > 0
    low, high = data["inner_volume"], data["inner_volume"] + data["undecided_volume"]
    # a Monte Carlo estimate of the area, within four of its standard errors
    region = np.array(data["region"])
    rng = np.random.default_rng(0)
    poses = np.hstack([rng.uniform(region[:, 0], region[:, 1], (200_000, 2)), np.zeros((200_000, 1))])
    inside = taut.workspace.make_condition("wrench-feasible").evaluate(taut.example("planar-4cable"), poses)
    p = inside.mean()
    estimate, error = p * data["region_volume"], 4 * np.sqrt(p * (1 - p) / len(poses)) * data["region_volume"]
    assert low - error <= estimate <= high + error and high - low < 0.05 * high
    assert [f.filename for f in sec.figures] == ["planar-4cable-certified.png"] and sec.figures[0].png


def test_check_section_reports_step_71():
    report = Report("t")
    check_section(report)
    assert "step 71" in report.sections[0].text


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


def test_plan_section_draws_the_atlas_path_and_tension_envelope():
    robot = taut.example("robocrane")
    q1 = np.array(robot.reference.poses["q1"])
    report = Report("t")
    t0 = time.perf_counter()
    res = plan_section(report)
    assert time.perf_counter() - t0 < 15  # ~2 s alone; generous under a loaded test run
    (sec,) = report.sections
    (row,) = sec.table
    assert row["found"] and row["independent check"] and row["charts"] == res.charts > 10
    assert [f.filename for f in sec.figures] == ["plan-robocrane-q1-q2.png"] and sec.figures[0].png
    M = WrenchFeasibleManifold.from_robot(robot, fixed=dict(x=0.0, y=0.0, z=2.0, sigma=q1[5]))
    fig = plot_plan(M, res, slice_map(M, q1, resolution=(12, 6)))
    ax, tx = fig.axes[:2]
    gids = {ln.get_gid() for ln in ax.lines}
    assert {"path", "charts-closed", "charts-open"} <= gids
    closed = next(ln for ln in ax.lines if ln.get_gid() == "charts-closed").get_xydata()
    assert len(closed) == res.expanded
    path = next(ln for ln in ax.lines if ln.get_gid() == "path").get_xydata()
    np.testing.assert_allclose(path[0], q1[3:5], atol=1e-9)
    # the path may reach q2 by other angles of the same orientation (through θ = 0)
    end = M.canonical(np.r_[q1[:3], path[-1], q1[5]])
    np.testing.assert_allclose(end, M.canonical(robot.reference.poses["q2"]), atol=1e-9)
    tl = {ln.get_gid(): np.asarray(ln.get_ydata()) for ln in tx.lines if ln.get_gid()}
    for i in range(1, 7):
        lo, hi = tl[f"tension-min-{i}"], tl[f"tension-max-{i}"]
        assert len(lo) == len(res.path) and np.all(lo > 0) and np.all(hi < 1) and np.all(lo < hi)
    plt.close(fig)


def test_calibration_section_finds_the_built_exits():
    from taut.demo._calibration import BUILT_ERROR, NOISE, calibration_section

    report = Report("t")
    calibration_section(report)
    (sec,) = report.sections
    data = sec.json
    assert data["identifiable"] and data["drawing_error_m"] > BUILT_ERROR / 2
    # millimetres from centimetres: the estimate within a few of its standard deviations
    assert data["exit_error_m"] < 20 * NOISE and data["worst_z"] < 4 and data["offset_error_m"] < 20 * NOISE
    assert [f.filename for f in sec.figures] == ["printer-5cable-calibration.png"] and sec.figures[0].png
