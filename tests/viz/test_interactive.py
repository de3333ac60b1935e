"""Interactive views (taut.viz.interactive): what each plotly figure holds, checked against
the robot's geometry and the results computed here, not against the figure's own numbers."""

from __future__ import annotations

import numpy as np
import pytest

import taut
from taut.dgp import solve_dgp
from taut.errors import ArgumentError, PoseError
from taut.viz.interactive import (
    POSE_TRACES,
    view_equilibria,
    view_motion,
    view_robot,
    view_trajectory,
    view_workspace,
    write_html,
)
from taut.workspace import certified, evaluate_workspace
from taut.wrapping import builtin_trajectory, run_trajectory

PLANAR = taut.example("planar-4cable")
SPATIAL = taut.example("spatial-8cable")


def trace(fig, name, visible_only=False):
    found = [t for t in fig.data if t.name == name and (not visible_only or t.visible is not False)]
    assert found, f"no trace {name!r}"
    return found[0]


def vertices(t) -> np.ndarray:
    pts = np.column_stack([np.asarray(t.x, float), np.asarray(t.y, float), np.asarray(t.z, float)])
    return pts[~np.isnan(pts).any(axis=1)]


def planar_anchors(robot, pose):
    """b_i = p + R(θ) r_i, written out here (docs/architecture.md §2.4)."""
    c, s = np.cos(pose[2]), np.sin(pose[2])
    R = np.array([[c, -s], [s, c]])
    r = np.array([cable.anchor for cable in robot.cables], float)[:, :2]
    return pose[:2] + r @ R.T


def test_robot_view_draws_each_cable_from_its_exit_to_its_anchor_coloured_by_tension():
    pose = np.array([0.1, -0.2, 0.3])
    fig = view_robot(PLANAR, pose, tensions=[5.0, 1.0, 3.0, 2.0], slack=[False, True, False, False])
    assert [t.name for t in fig.data[-len(POSE_TRACES) :]] == list(POSE_TRACES)
    b = np.column_stack([planar_anchors(PLANAR, pose), np.zeros(4)])
    a = np.column_stack([PLANAR.exits, np.zeros(4)])
    tight = vertices(trace(fig, "cables"))
    loose = vertices(trace(fig, "slack cables"))
    for i in (0, 2, 3):
        assert np.isclose(tight, a[i], atol=1e-12).all(axis=1).any() and np.isclose(tight, b[i]).all(axis=1).any()
    assert np.allclose(loose, [a[1], b[1]])
    cables = trace(fig, "cables")
    assert (cables.line.cmin, cables.line.cmax) == (1.0, 5.0) and cables.line.showscale
    assert sorted(set(cables.line.color)) == [2.0, 3.0, 5.0]
    assert trace(fig, "slack cables").line.dash == "dash"


def test_robot_view_draws_the_capsules_of_the_adjustable_platform_as_tubes_of_their_radius():
    robot = taut.example("adjustable-8cable")
    fig = view_robot(robot)
    caps = vertices(trace(fig, "capsules"))
    assert len(caps) == len(robot.body_capsules) * (2 * 14 + 2)
    radii = {round(c.radius, 9) for _, c in robot.body_capsules}
    # each tube's ring vertices lie at its radius from its axis: the distance from the tube's
    # centre line of the ring's centre point is one of the capsules' radii
    ring = caps[:14]
    centre = caps[28]
    assert round(float(np.linalg.norm(ring - centre, axis=1).mean()), 6) in {round(r, 6) for r in radii}


def test_swivelling_pulleys_are_drawn_through_the_exit_points():
    robot = taut.example("suspended-3pulley")
    fig = view_robot(robot)
    pulleys = vertices(trace(fig, "pulleys"))
    for exit_point in robot.exits:
        assert np.linalg.norm(pulleys - exit_point, axis=1).min() < 0.01


def test_a_robot_view_refuses_several_poses_and_tensions_of_another_size():
    with pytest.raises(PoseError):
        view_robot(PLANAR, np.zeros((2, 3)))
    with pytest.raises(ArgumentError, match="tensions"):
        view_robot(PLANAR, [0, 0, 0], tensions=[1, 2, 3])


def test_motion_view_frames_show_the_lengths_at_their_sample():
    T = 300
    poses = np.column_stack([np.linspace(-0.3, 0.3, T), 0.1 * np.sin(np.linspace(0, 3, T)), np.zeros(T)])
    times = np.linspace(0, 3, T)
    fig = view_motion(PLANAR, times, poses, frames=25)
    assert len(fig.frames) == len(fig.layout.sliders[0].steps) == 25
    for frame in fig.frames[::6]:
        now = next(t for t in frame.data if t.name == "lengths now")
        s = int(np.flatnonzero(np.isclose(times, now.x[0]))[0])
        expected = np.linalg.norm(PLANAR.exits - planar_anchors(PLANAR, poses[s]), axis=1)
        assert np.allclose(now.y, expected)
    assert [b.label for b in fig.layout.updatemenus[0].buttons] == ["▶ play", "❚❚"]


def test_motion_view_refuses_poses_and_times_of_different_counts():
    with pytest.raises(ArgumentError, match="one per time"):
        view_motion(PLANAR, [0, 1, 2], np.zeros((2, 3)))
    with pytest.raises(ArgumentError, match="do not decrease"):
        view_motion(PLANAR, [0, 2, 1], np.zeros((3, 3)))


def test_wrapping_trajectory_view_draws_cables_as_long_as_their_wrapped_lengths():
    robot = taut.example("vscr-four-cable")
    res = run_trajectory(robot, *builtin_trajectory(robot, dt=0.05))
    fig = view_trajectory(robot, res, frames=12)
    for frame in fig.frames:
        now = next(t for t in frame.data if t.name == "lengths now")
        s = int(np.flatnonzero(np.isclose(res.times, now.x[0]))[0])
        drawn = 0.0
        for name in ("cables", "slack cables"):
            t = next(t for t in frame.data if t.name == name)
            pts = np.column_stack([np.asarray(t.x, float), np.asarray(t.y, float)])
            steps = np.linalg.norm(np.diff(pts, axis=0), axis=1)
            drawn += float(np.nansum(steps))
        # the polylines follow the arcs with 16 points each: a little shorter than the arcs
        assert drawn == pytest.approx(res.lengths[s].sum(), rel=2e-3)


def test_equilibria_view_selector_shows_one_solution_at_a_time():
    robot = taut.example("suspended-3cable")
    sols = solve_dgp(robot).solutions
    fig = view_equilibria(robot, sols)
    m = len(POSE_TRACES)
    fixed = len(fig.data) - m * len(sols)
    buttons = fig.layout.updatemenus[0].buttons
    assert len(buttons) == len(sols)
    for k, (button, s) in enumerate(zip(buttons, sols)):
        visible = button.args[0]["visible"]
        shown = [j for j in range(fixed, len(fig.data)) if visible[j]]
        assert shown == list(range(fixed + k * m, fixed + (k + 1) * m))
        anchors = fig.data[fixed + k * m + POSE_TRACES.index("anchors")]
        assert np.allclose([anchors.x[-1], anchors.y[-1], anchors.z[-1]], s.position)
        loose = fig.data[fixed + k * m + POSE_TRACES.index("slack cables")]
        assert len(vertices(loose)) == 2 * (robot.n_cables - len(s.taut))
        assert ("stable" if s.stable else "unstable") in button.label


def test_workspace_layers_hold_the_certified_boxes_and_the_grid_points():
    boxes = certified(PLANAR, "static", eps=0.05)
    fig = view_workspace(PLANAR, boxes, [0, 0, 0])
    inner = trace(fig, "proven inside")
    assert len(inner.x) == 4 * len(boxes.inner)
    area = 0.0
    for tri in zip(inner.i, inner.j, inner.k):
        p = np.array([[inner.x[v], inner.y[v]] for v in tri])
        (u, v), (w, z) = p[1] - p[0], p[2] - p[0]
        area += 0.5 * abs(u * z - v * w)
    assert area == pytest.approx(boxes.inner_volume, rel=1e-9)
    grid = evaluate_workspace(PLANAR, "wrench-feasible", resolution=20, orientation=[0.0])
    fig = view_workspace(PLANAR, grid)
    layer = next(t for t in fig.data if t.legendgroup == "workspace")
    assert len(layer.x) == grid.count
    with pytest.raises(ArgumentError, match="not of"):
        view_workspace(SPATIAL, grid)


def test_write_html_shares_plotly_js_or_embeds_it(tmp_path):
    fig = view_robot(SPATIAL)
    page = write_html(fig, tmp_path / "a.html", plotlyjs="beside")
    text = page.read_text()
    assert '<script src="plotly.min.js"' in text and "http" not in text.split("<body>")[0]
    assert (tmp_path / "plotly.min.js").stat().st_size > 1_000_000
    embedded = write_html(fig, tmp_path / "b.html")
    assert embedded.stat().st_size > (tmp_path / "plotly.min.js").stat().st_size
    with pytest.raises(ArgumentError):
        write_html(fig, tmp_path / "missing" / "c.html")


def test_report_embeds_views_and_writes_plotly_js_once(tmp_path):
    from taut.viz import Report

    report = Report("views")
    report.add_section("one", views=[(view_robot(PLANAR, [0, 0, 0]), "planar")])
    report.add_section("two", views=[(view_robot(SPATIAL), "spatial")])
    index = report.write(tmp_path)
    page = index.read_text()
    assert page.count('<script src="plotly.min.js"') == 1 and page.count("Plotly.newPlot") == 2
    assert 'id="view-1"' in page and 'id="view-2"' in page and "<figcaption>spatial</figcaption>" in page
    assert (tmp_path / "plotly.min.js").stat().st_size > 1_000_000
    plain = Report("no views")
    plain.add_section("text only", text="nothing to draw")
    assert "plotly" not in plain.html()
