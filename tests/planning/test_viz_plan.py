"""The planning figures of taut.viz.plan (Figs. 5–6 of Bohigas et al. 2013) and the
demo section: what is drawn."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from taut import InfeasiblePoseError  # noqa: E402
from taut.model import load_robot  # noqa: E402
from taut.planning.manifold import WrenchFeasibleManifold  # noqa: E402
from taut.viz.plan import FEASIBLE, LENGTH_OUT, plan_section, plot_plan, slice_map  # noqa: E402
from taut.viz.report import Report  # noqa: E402

ROBOT = load_robot("robocrane")
Q1 = np.array(ROBOT.reference.poses["q1"])


def test_slice_map_classifies_like_the_manifold():
    M = WrenchFeasibleManifold.from_robot(ROBOT)
    u, v, cls = slice_map(M, Q1, resolution=(24, 12))
    assert cls.shape == (24, 12) and u[0] == -np.pi and v[-1] == np.pi
    for i, j in np.ndindex(cls.shape):
        q = Q1.copy()
        q[3], q[4] = u[i], v[j]
        if cls[i, j] == FEASIBLE:
            M.lift(q)
        else:
            reason = "cable lengths" if cls[i, j] == LENGTH_OUT else "not wrench-feasible|Jacobian is singular"
            with pytest.raises(InfeasiblePoseError, match=reason):
                M.lift(q)
    assert (cls == FEASIBLE).any() and (cls != FEASIBLE).any()
    # lengths: at z = 4.9 cables are longer than 5a = 5 somewhere
    _, _, far = slice_map(M, np.r_[0, 0, 4.9, Q1[3:]], resolution=(8, 6))
    assert (far == LENGTH_OUT).any()


def test_plan_section_draws_the_atlas_path_and_tension_envelope():
    report = Report("t")
    res = plan_section(report)
    (sec,) = report.sections
    (row,) = sec.table
    assert row["found"] and row["independent check"] and row["charts"] == res.charts > 10
    assert [f.filename for f in sec.figures] == ["plan-robocrane-q1-q2.png"] and sec.figures[0].png
    M = WrenchFeasibleManifold.from_robot(ROBOT, fixed=dict(x=0.0, y=0.0, z=2.0, sigma=Q1[5]))
    fig = plot_plan(M, res, grid=slice_map(M, Q1, resolution=(12, 6)))
    ax, tx = fig.axes[:2]
    gids = {ln.get_gid() for ln in ax.lines}
    assert {"path", "charts-closed", "charts-open"} <= gids
    closed = next(ln for ln in ax.lines if ln.get_gid() == "charts-closed").get_xydata()
    assert len(closed) == res.expanded
    path = next(ln for ln in ax.lines if ln.get_gid() == "path").get_xydata()
    np.testing.assert_allclose(path[0], Q1[3:5], atol=1e-9)
    # the path may reach q2 by other angles of the same orientation (through θ = 0)
    end = M.canonical(np.r_[Q1[:3], path[-1], Q1[5]])
    np.testing.assert_allclose(end, M.canonical(ROBOT.reference.poses["q2"]), atol=1e-9)
    tl = {ln.get_gid(): np.asarray(ln.get_ydata()) for ln in tx.lines if ln.get_gid()}
    for i in range(1, 7):
        lo, hi = tl[f"tension-min-{i}"], tl[f"tension-max-{i}"]
        assert len(lo) == len(res.path) and np.all(lo > 0) and np.all(hi < 1) and np.all(lo < hi)
    plt.close(fig)
