"""The promise of taut.viz's package docstring: a one-axes plot draws on the ``ax`` it is
given and returns it (a new figure with ``ax=None``), a several-panel plot lays its panels
out on the empty ``fig`` it is given and returns it (a new figure with ``fig=None``), and
axes or figures of the wrong kind are refused before anything is drawn."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.axes import Axes  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402
from mpl_toolkits.mplot3d.axes3d import Axes3D  # noqa: E402

import taut.viz  # noqa: E402
from taut.atlas import atlas_workspace, build_atlas  # noqa: E402
from taut.collision import check_poses, trajectory_poses  # noqa: E402
from taut.dgp import (  # noqa: E402
    DGPSolution,
    build_subproblem,  # noqa: E402
    track_path,
)
from taut.errors import ArgumentError, TautError  # noqa: E402
from taut.geometry import rotation_matrix  # noqa: E402
from taut.interval import certify  # noqa: E402
from taut.model import example, robot_from_dict  # noqa: E402
from taut.planning import (  # noqa: E402
    WrenchFeasibleManifold,  # noqa: E402
    plan_path,
    slice_map,
)
from taut.viz._atlas import plot_atlas  # noqa: E402
from taut.viz._check import plot_check  # noqa: E402
from taut.viz._dgp import plot_equilibria, plot_tracking  # noqa: E402
from taut.viz._plan import plot_plan  # noqa: E402
from taut.viz._robot import draw_robot, draw_scene_2d, draw_scene_3d, scene_points_3d  # noqa: E402
from taut.viz._tensions import plot_tensions  # noqa: E402
from taut.viz._trajectory import draw_wrapped_cables, plot_trajectory  # noqa: E402
from taut.viz._workspace import plot_workspace  # noqa: E402
from taut.workspace import evaluate_workspace  # noqa: E402
from taut.wrapping import builtin_trajectory, run_trajectory  # noqa: E402

PLANAR = example("planar-4cable")
SPATIAL = example("spatial-8cable")
SPHERE = robot_from_dict(
    {
        "name": "spatial point mass beside a sphere",
        "dimension": 3,
        "platform": {"kind": "point-mass", "mass": 1.0},
        "cables": [{"exit": [0, 0, 2]}, {"exit": [2, 0, 2]}, {"exit": [1, 2, 2]}, {"exit": [1, 1, 0]}],
        "obstacles": [{"kind": "circle", "center": [3.0, 1.0, 1.0], "radius": 0.5}],
    }
)


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


# ---- results to draw, computed once (real solvers, small sizes) --------------------------
@pytest.fixture(scope="module")
def data() -> dict[str, Any]:
    out: dict[str, Any] = {}
    out["ws2d"] = evaluate_workspace(PLANAR, "wrench-feasible", resolution=9, orientation=[0.0])
    out["ws3d"] = evaluate_workspace(SPATIAL, "wrench-feasible", resolution=5, orientation=[0.0, 0.0, 0.0])
    vscr = example("vscr-single-cable")
    t, P = builtin_trajectory(vscr, next(iter(vscr.trajectories)), dt=0.05)
    out["vscr"], out["trajectory"] = vscr, run_trajectory(vscr, t, P)
    t_shaped = example("vscr-t-shaped")
    assert t_shaped.reference is not None
    atlas = build_atlas(t_shaped, t_shaped.reference.poses["initial"])
    out["atlas"], out["atlas_ws"] = atlas, atlas_workspace(atlas, "wrench-feasible")
    adjustable = example("adjustable-8cable")
    out["adjustable"] = adjustable
    out["check"] = check_poses(adjustable, trajectory_poses(adjustable, "sim-c")[60:75])
    # Conf. 1 of Table 4.3 (suspended 3-cable robot), certified by the Krawczyk operator
    suspended = example("suspended-3cable")
    assert suspended.reference is not None and suspended.reference.lengths is not None
    lengths = np.array(suspended.reference.lengths)
    pose, tensions = [2.7505, 3.9798, 5.5061, 3.0064, 0.3417, 0.1089], np.array([0.526, 0.512, 0.581])
    sp = build_subproblem(suspended, lengths, (0, 1, 2))
    cert = certify(
        sp.system, sp.unknowns(pose[:3], rotation_matrix(np.array(pose[3:]), "xyz-fixed"), tensions / lengths)
    )
    p, ang, _ = sp.pose(cert.x, "xyz-fixed")
    start = DGPSolution((0, 1, 2), p, ang, sp.tensions(cert.x, lengths, 3), True, cert.width, cert.radius)
    out["suspended"], out["equilibria"] = suspended, [start]
    out["tracking"] = track_path(
        suspended, start, [lengths + k * 0.002 * np.array([1.0, -1.0, 0.5]) for k in range(1, 6)]
    )
    robocrane = example("robocrane")
    assert robocrane.reference is not None
    q1, q2 = (np.array(robocrane.reference.poses[k]) for k in ("q1", "q2"))
    M = WrenchFeasibleManifold.from_robot(robocrane, fixed=dict(x=0.0, y=0.0, z=2.0, sigma=float(q1[5])))
    out["manifold"] = M
    out["plan"] = plan_path(M.implicit(), M.lift(q1), M.lift(q2), radius=0.2, metric=M.pose_metric)
    out["plan_grid"] = slice_map(M, q1, resolution=(8, 5))
    return out


def _tensions(ax: Axes | None, d: dict[str, Any]) -> Axes:
    return plot_tensions(np.linspace(0, 1, 5), np.ones((5, 3)), 0.5, 2.0, np.ones(5, bool), ax)


#: one-axes plots: name → (3-D?, draw(ax, data) → returned axes)
AX_PLOTS: dict[str, tuple[bool, Callable[[Axes | None, dict[str, Any]], Axes]]] = {
    "draw_robot planar": (False, lambda ax, d: draw_robot(PLANAR, None, ax=ax)),
    "draw_robot spatial": (True, lambda ax, d: draw_robot(SPATIAL, None, ax=ax)),
    "plot_workspace planar": (False, lambda ax, d: plot_workspace(d["ws2d"], PLANAR, ax=ax)),
    "plot_workspace spatial": (True, lambda ax, d: plot_workspace(d["ws3d"], SPATIAL, ax=ax)),
    "plot_tensions": (False, _tensions),
    "draw_scene_2d": (False, lambda ax, d: draw_scene_2d(PLANAR, ax)),
    "draw_scene_3d": (True, lambda ax, d: draw_scene_3d(SPHERE, ax)),
    "draw_wrapped_cables": (False, lambda ax, d: draw_wrapped_cables(d["trajectory"], 10, ax)),
}

#: several-panel plots: name → (draw(fig, data) → returned figure, number of panels)
FIG_PLOTS: dict[str, tuple[Callable[[Figure | None, dict[str, Any]], Figure], int]] = {
    "plot_atlas": (lambda fig, d: plot_atlas(d["atlas"], fig=fig), 1),
    "plot_atlas with workspace": (lambda fig, d: plot_atlas(d["atlas"], d["atlas_ws"], fig=fig), 2),
    "plot_check": (lambda fig, d: plot_check(d["adjustable"], d["check"], fig=fig), 2),
    "plot_equilibria": (lambda fig, d: plot_equilibria(d["suspended"], d["equilibria"], fig=fig), 1),
    "plot_equilibria none": (lambda fig, d: plot_equilibria(d["suspended"], [], fig=fig), 1),
    "plot_tracking": (lambda fig, d: plot_tracking(d["tracking"], fig=fig), 2),
    "plot_trajectory": (lambda fig, d: plot_trajectory(d["vscr"], d["trajectory"], snapshots=2, fig=fig), 3),
    "plot_plan": (lambda fig, d: plot_plan(d["manifold"], d["plan"], grid=d["plan_grid"], fig=fig), 2),
}


def _artists(ax: Axes) -> int:
    return len(ax.lines) + len(ax.patches) + len(ax.collections) + len(ax.images) + len(ax.texts)


def test_every_plotting_function_of_the_docstring_is_tested():
    doc = taut.viz.__doc__ or ""
    named = {name.split(" ")[0] for name in [*AX_PLOTS, *FIG_PLOTS]}
    assert named == {
        "draw_robot",
        "plot_workspace",
        "plot_tensions",
        "draw_scene_2d",
        "draw_scene_3d",
        "draw_wrapped_cables",
        "plot_atlas",
        "plot_check",
        "plot_equilibria",
        "plot_tracking",
        "plot_trajectory",
        "plot_plan",
    }
    for name in named:
        assert f"{name}`" in doc, name


@pytest.mark.parametrize("name", AX_PLOTS)
def test_given_axes_are_drawn_on_and_returned(name, data):
    three_d, draw = AX_PLOTS[name]
    fig = plt.figure()
    ax = fig.add_subplot(projection="3d") if three_d else fig.add_subplot()
    before = plt.get_fignums()
    assert _artists(ax) == 0
    out = draw(ax, data)
    assert out is ax
    assert plt.get_fignums() == before  # no new figure
    assert fig.axes == [ax]  # no other axes in it either
    assert _artists(ax) > 0


@pytest.mark.parametrize("name", AX_PLOTS)
def test_without_axes_a_new_figure_is_made(name, data):
    three_d, draw = AX_PLOTS[name]
    before = plt.get_fignums()
    out = draw(None, data)
    after = plt.get_fignums()
    assert len(after) == len(before) + 1
    fig = out.figure
    assert isinstance(fig, Figure) and fig.number in set(after) - set(before)
    assert isinstance(out, Axes3D) == three_d
    assert fig.axes == [out] and _artists(out) > 0


@pytest.mark.parametrize("name", AX_PLOTS)
def test_axes_of_the_other_kind_raise_argument_error_and_stay_empty(name, data):
    three_d, draw = AX_PLOTS[name]
    fig = plt.figure()
    wrong = fig.add_subplot() if three_d else fig.add_subplot(projection="3d")
    with pytest.raises(ArgumentError, match="3-D axes" if three_d else "2-D axes"):
        draw(wrong, data)
    assert _artists(wrong) == 0 and plt.get_fignums() == [fig.number]


@pytest.mark.parametrize("name", FIG_PLOTS)
def test_given_figure_gets_the_panels_and_is_returned(name, data):
    draw, panels = FIG_PLOTS[name]
    fig = plt.figure()
    before = plt.get_fignums()
    out = draw(fig, data)
    assert out is fig
    assert plt.get_fignums() == before
    assert len(fig.axes) == panels
    assert all(_artists(ax) > 0 for ax in fig.axes)


@pytest.mark.parametrize("name", FIG_PLOTS)
def test_without_figure_a_new_one_is_made(name, data):
    draw, panels = FIG_PLOTS[name]
    before = plt.get_fignums()
    out = draw(None, data)
    after = plt.get_fignums()
    assert len(after) == len(before) + 1 and out.number in set(after) - set(before)
    assert len(out.axes) == panels


@pytest.mark.parametrize("name", FIG_PLOTS)
def test_a_figure_that_has_axes_is_refused(name, data):
    draw, _ = FIG_PLOTS[name]
    fig = plt.figure()
    ax = fig.add_subplot()
    with pytest.raises(ArgumentError, match="empty figure"):
        draw(fig, data)
    assert fig.axes == [ax] and _artists(ax) == 0


# ---- what the newly exposed drawing functions draw ----------------------------------------
def test_wrapped_cables_follow_the_cable_paths(data):
    res = data["trajectory"]
    ax = draw_wrapped_cables(res, 10)
    n = res.ik.lengths.shape[1]
    for i in range(n):
        lines = [ln for ln in ax.lines if ln.get_gid() == f"wrapped-cable-{i + 1}"]
        segments = res.ik.path(10, i).segments
        assert len(lines) == len(segments) >= 1
        for ln, (a, b) in zip(lines, segments):
            np.testing.assert_allclose(np.asarray(ln.get_xydata()), [a[:2], b[:2]])
        assert lines[-1].get_linestyle() == "--"  # the active segment


def test_scene_points_enclose_the_sphere_and_the_exits():
    pts = scene_points_3d(SPHERE)
    np.testing.assert_allclose(pts.min(axis=0), [0.0, 0.0, 0.0], atol=1e-12)
    np.testing.assert_allclose(pts.max(axis=0), [3.5, 2.0, 2.0], atol=1e-12)  # the sphere reaches x = 3 + 0.5
    ax = draw_scene_3d(SPHERE)
    assert len([c for c in ax.collections if c.get_gid() == "obstacle"]) == 1  # the sphere's wireframe
    (exits,) = [ln for ln in ax.lines if ln.get_gid() == "exits"]
    np.testing.assert_allclose(np.column_stack(exits.get_data_3d()), SPHERE.exits)


def test_plot_plan_on_a_slice_with_a_free_position_coordinate():
    """A slice that frees x: the map spans the chart centres in x (no default limits for a
    position coordinate), φ over its window."""
    robocrane = example("robocrane")
    M = WrenchFeasibleManifold.from_robot(robocrane, fixed=dict(y=0.0, z=2.0, theta=0.6, sigma=0.6))
    res = plan_path(
        M.implicit(),
        M.lift([0, 0, 2, 0.3, 0.6, 0.6]),
        M.lift([0.1, 0, 2, 0.3, 0.6, 0.6]),
        radius=0.2,
        metric=M.pose_metric,
    )
    assert res.found
    start = M.pose(res.path[0])
    with pytest.raises(TautError, match="limits for x"):
        slice_map(M, start, axes=("x", "phi"))
    centres = M.pose(res.atlas.centres)
    fig = plot_plan(M, res, slice_map(M, start, axes=("x", "phi"), span=centres, resolution=(12, 8)))
    ax = fig.axes[0]
    x0, x1 = ax.get_xlim()
    assert x0 < centres[:, 0].min() and centres[:, 0].max() < x1
    np.testing.assert_allclose(ax.get_ylim(), M.phi_window)
    path = next(ln for ln in ax.lines if ln.get_gid() == "path").get_xydata()
    np.testing.assert_allclose(path[[0, -1]], [[0.0, 0.3], [0.1, 0.3]], atol=1e-9)
    assert fig.axes[1].get_xlabel() == "path length in (x, phi) [m, rad]"


def test_plot_calibration_refuses_what_it_cannot_draw():
    import matplotlib.pyplot as plt

    from taut.calibration import calibrate, plan_poses, simulate_measurements
    from taut.errors import ArgumentError
    from taut.model import example
    from taut.viz import plot_calibration

    robot = example("printer-5cable")
    res = calibrate(robot, simulate_measurements(robot, plan_poses(robot, 20).poses, sigma=1e-4, seed=1))
    with pytest.raises(ArgumentError, match="truth"):
        plot_calibration(robot, res, truth=np.zeros((4, 3)))
    with pytest.raises(ArgumentError, match="cables"):
        plot_calibration(example("planar-4cable"), res)
    fig = plt.figure()
    fig.add_subplot()
    with pytest.raises(ArgumentError, match="empty figure"):
        plot_calibration(robot, res, fig=fig)
    plt.close("all")
