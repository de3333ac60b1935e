"""Figures of taut.viz: what is drawn, not how it looks."""

from __future__ import annotations

import re
from dataclasses import dataclass

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.image import AxesImage  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

import taut  # noqa: E402
from taut.errors import ArgumentError  # noqa: E402
from taut.kinematics import anchor_points  # noqa: E402
from taut.model import robot_from_dict  # noqa: E402
from taut.viz import Report, draw_robot, plot_tensions, plot_workspace  # noqa: E402

PLANAR = taut.example("planar-4cable")
SPATIAL = taut.example("spatial-8cable")
POINT_MASS = robot_from_dict(
    {
        "name": "point mass with an obstacle",
        "dimension": 2,
        "platform": {"kind": "point-mass", "mass": 1.0, "gravity": [0, -9.81]},
        "cables": [{"exit": [0, 0]}, {"exit": [2, 0]}, {"exit": [1, 1.5]}],
        "obstacles": [{"kind": "circle", "center": [1.3, 0.9], "radius": 0.1}],
        "installation_space": [[-0.2, -0.2], [2.2, -0.2], [2.2, 1.7], [-0.2, 1.7]],
        "disallowed": [[[0.8, -0.2], [1.2, -0.2], [1.2, 0.1], [0.8, 0.1]]],
    }
)
JOINTED = robot_from_dict(
    {
        "name": "planar platform with a slider",
        "dimension": 2,
        "platform": {
            "kind": "rigid",
            "bodies": [{"name": "slider", "joint": {"kind": "prismatic", "axis": [1, 0], "limits": [0, 0.3]}}],
        },
        "cables": [
            {"exit": [-1, -1], "anchor": [-0.1, -0.05]},
            {"exit": [-1, 1], "anchor": [-0.1, 0.05]},
            {"exit": [0, 1], "anchor": [0.1, 0.0]},
            {"exit": [1, 1], "anchor": [0.1, 0.05], "body": "slider"},
            {"exit": [1, -1], "anchor": [0.1, -0.05], "body": "slider"},
            {"exit": [0.5, -1], "anchor": [0.0, -0.05], "body": "slider"},
        ],
    }
)


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def cable_lines(ax):
    lines = sorted(
        (ln for ln in ax.get_lines() if (ln.get_gid() or "").startswith("cable-")), key=lambda ln: int(ln.get_gid()[6:])
    )
    return lines


# ---- draw_robot --------------------------------------------------------------------------
def test_planar_robot_cables_platform_and_labels():
    pose = np.array([0.2, -0.1, 0.3])
    ax = draw_robot(PLANAR, pose)
    lines = cable_lines(ax)
    assert [ln.get_label() for ln in lines] == ["cable 1", "cable 2", "cable 3", "cable 4"]
    b = anchor_points(PLANAR, pose)
    for i, ln in enumerate(lines):
        x, y = ln.get_data()
        np.testing.assert_allclose([x[0], y[0]], PLANAR.exits[i])
        np.testing.assert_allclose([x[1], y[1]], b[i])
    # the platform polygon is the shape moved to the pose: here its corners are the anchors
    platform = [p for p in ax.patches if p.get_gid() == "platform"]
    assert len(platform) == 1
    corners = platform[0].get_xy()[:4]
    np.testing.assert_allclose(corners, b, atol=1e-12)
    texts = sorted(t.get_text() for t in ax.texts if t.get_gid() == "cable-label")
    assert texts == ["1", "2", "3", "4"]
    assert ax.get_xlabel() == "x [m]" and ax.get_ylabel() == "y [m]"
    assert ax.get_aspect() == 1.0
    assert ax.name != "3d"


def test_planar_robot_default_pose_is_home():
    ax = draw_robot(PLANAR)
    x, y = cable_lines(ax)[0].get_data()
    np.testing.assert_allclose([x[1], y[1]], [-0.1, -0.05])
    assert "theta=0" in ax.get_title()


def test_point_mass_robot_with_obstacle_and_regions():
    pose = [0.9, 0.6]
    ax = draw_robot(POINT_MASS, pose)
    lines = cable_lines(ax)
    assert len(lines) == 3
    for ln in lines:  # all cables meet at the point mass
        x, y = ln.get_data()
        np.testing.assert_allclose([x[1], y[1]], pose)
    circles = [p for p in ax.patches if isinstance(p, Circle)]
    assert len(circles) == 1 and circles[0].get_radius() == pytest.approx(0.1)
    np.testing.assert_allclose(circles[0].center, [1.3, 0.9])
    dot = [ln for ln in ax.get_lines() if ln.get_gid() == "platform"]
    assert len(dot) == 1 and np.allclose(np.ravel(dot[0].get_data()), pose)
    gids = {p.get_gid() for p in ax.patches}
    assert {"installation-space", "disallowed", "obstacle"} <= gids
    assert sorted(t.get_text() for t in ax.get_legend().get_texts()) == ["disallowed", "installation space", "obstacle"]


def test_jointed_planar_platform_draws_one_hull_per_body():
    pose = [0.0, 0.0, 0.0, 0.25]
    ax = draw_robot(JOINTED, pose)
    assert len(cable_lines(ax)) == 6
    hulls = [p for p in ax.patches if p.get_gid() == "platform"]
    assert len(hulls) == 2
    slider = max(hulls, key=lambda p: p.get_xy()[:, 0].max())
    assert slider.get_xy()[:, 0].max() == pytest.approx(0.35)  # anchors moved by the joint
    assert [ln.get_gid() for ln in ax.get_lines()].count("joint") == 1


def test_spatial_robot():
    pose = np.array([0.3, -0.2, 0.1, 0.1, -0.2, 0.3])
    ax = draw_robot(SPATIAL, pose)
    assert ax.name == "3d"
    lines = cable_lines(ax)
    assert len(lines) == 8
    b = anchor_points(SPATIAL, pose)
    for i, ln in enumerate(lines):
        x, y, z = ln.get_data_3d()
        np.testing.assert_allclose([x[0], y[0], z[0]], SPATIAL.exits[i])
        np.testing.assert_allclose([x[1], y[1], z[1]], b[i])
    ax.figure.canvas.draw()  # 3-D polygons are projected to paths at draw time
    faces = [c for c in ax.collections if isinstance(c, Poly3DCollection) and c.get_gid() == "platform"]
    assert len(faces) == 1 and len(faces[0].get_paths()) == 6  # the anchors span a box: six faces
    capsules = [ln for ln in ax.get_lines() if ln.get_gid() == "capsule"]
    assert len(capsules) == 1 and capsules[0].get_linewidth() > 3
    assert (ax.get_xlabel(), ax.get_ylabel(), ax.get_zlabel()) == ("x [m]", "y [m]", "z [m]")
    assert sorted(int(t.get_text()) for t in ax.texts if t.get_gid() == "cable-label") == list(range(1, 9))
    # equal scale: box aspect proportional to the axis ranges
    spans = np.array([np.ptp(ax.get_xlim()), np.ptp(ax.get_ylim()), np.ptp(ax.get_zlim())])
    box = np.asarray(ax.get_box_aspect())
    np.testing.assert_allclose(box / box[0], spans / spans[0], rtol=1e-6)


def test_axes_of_the_wrong_kind_are_refused():
    fig = plt.figure()
    with pytest.raises(ArgumentError, match="3-D axes"):
        draw_robot(SPATIAL, None, ax=fig.add_subplot())
    with pytest.raises(ArgumentError, match="2-D axes"):
        draw_robot(PLANAR, None, ax=fig.add_subplot(projection="3d"))


# ---- plot_workspace ----------------------------------------------------------------------
@dataclass
class StandInWorkspace:
    """The fields of taut.workspace's WorkspaceResult that the plot reads."""

    robot_name: str
    condition: str
    poses: np.ndarray
    inside: np.ndarray
    axes: tuple
    grid_shape: tuple
    elapsed_s: float = 0.0

    @property
    def count(self):
        return int(self.inside.sum())

    @property
    def fraction(self):
        return self.count / self.inside.size

    @property
    def measure(self):
        return 0.0

    def summary(self):
        return {"inside": self.count, "poses": int(self.inside.size), "fraction": self.fraction}


def grid_result(robot, axes, inside_fn, orientation=()):
    mesh = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, len(axes))
    poses = np.column_stack([mesh, np.tile(np.asarray(orientation, float), (len(mesh), 1))])
    return StandInWorkspace(
        robot.name, "wrench-feasible", poses, inside_fn(mesh), tuple(axes), tuple(len(a) for a in axes)
    )


def test_planar_workspace_image_matches_grid():
    axes = (np.linspace(-0.9, 0.9, 13), np.linspace(-0.8, 0.8, 7))  # not square: catches a transpose
    res = grid_result(PLANAR, axes, lambda p: (p[:, 0] > 0.1) & (np.abs(p[:, 1]) < 0.5), orientation=[0.0])
    ax = plot_workspace(res, PLANAR)
    images = [im for im in ax.get_images() if isinstance(im, AxesImage)]
    assert len(images) == 1
    arr = np.asarray(images[0].get_array())
    assert arr.shape == (7, 13)  # rows = y, columns = x
    np.testing.assert_array_equal(arr.T.astype(bool), res.inside.reshape(res.grid_shape))
    assert images[0].origin == "lower"
    x0, x1, y0, y1 = images[0].get_extent()
    assert x0 < -0.9 < 0.9 < x1 and y0 < -0.8 < 0.8 < y1
    title = ax.get_title()
    assert "wrench-feasible" in title and f"{100 * res.fraction:.1f} %" in title and "theta=0" in title
    exits = [ln for ln in ax.get_lines() if ln.get_gid() == "exits"]
    assert len(exits) == 1 and len(exits[0].get_xdata()) == PLANAR.n_cables
    assert ax.get_xlabel() == "x [m]" and ax.get_ylabel() == "y [m]"


def test_spatial_workspace_scatter_and_subsampling():
    axes = (np.linspace(-1.2, 1.2, 12), np.linspace(-0.8, 0.8, 10), np.linspace(-0.8, 0.8, 8))
    res = grid_result(SPATIAL, axes, lambda p: np.linalg.norm(p, axis=1) < 0.7, orientation=[0, 0, 0])
    n_in = int(res.inside.sum())
    ax = plot_workspace(res, SPATIAL)
    assert ax.name == "3d"
    scatter = [c for c in ax.collections if c.get_gid() == "workspace"]
    assert len(scatter) == 1
    xs, ys, zs = scatter[0]._offsets3d
    assert len(xs) == n_in
    assert np.all(np.sqrt(np.asarray(xs) ** 2 + np.asarray(ys) ** 2 + np.asarray(zs) ** 2) < 0.7)
    assert "wrench-feasible" in ax.get_title() and ax.get_zlabel() == "z [m]"
    plt.close("all")
    ax = plot_workspace(res, SPATIAL, max_points=50)
    (scatter,) = [c for c in ax.collections if c.get_gid() == "workspace"]
    assert len(scatter._offsets3d[0]) == 50 and "50 shown" in ax.get_title()


def test_spatial_slice_is_an_image():
    axes = (np.linspace(-1, 1, 10), np.linspace(-0.5, 0.5, 6), np.array([0.25]))
    res = grid_result(SPATIAL, axes, lambda p: (p[:, 0] > 0) & (p[:, 1] > 0.1), orientation=[0, 0, 0])
    ax = plot_workspace(res, SPATIAL)
    assert ax.name != "3d"
    (im,) = ax.get_images()
    arr = np.asarray(im.get_array())
    assert arr.shape == (6, 10)  # rows = y, columns = x
    np.testing.assert_array_equal(arr.astype(bool), (axes[1][:, None] > 0.1) & (axes[0][None, :] > 0))
    assert "z=0.25" in ax.get_title()


# ---- plot_tensions -----------------------------------------------------------------------
def test_tensions_lines_bounds_and_infeasible_marks():
    N, n = 30, 4
    t = np.linspace(0.0, 2.9, N)
    tensions = 10 + np.outer(np.sin(t), np.arange(1, n + 1))
    feasible = np.ones(N, bool)
    feasible[[3, 4, 5, 20]] = False
    tensions[~feasible] = 0.0  # what a solver may return where no distribution exists
    ax = plot_tensions(t, tensions, 1.0, 100.0, feasible)
    lines = [ln for ln in ax.get_lines() if (ln.get_gid() or "").startswith("tension-")]
    assert [ln.get_label() for ln in lines] == [f"cable {i}" for i in range(1, n + 1)]
    np.testing.assert_array_equal(lines[1].get_ydata()[feasible], tensions[feasible, 1])
    assert np.all(np.isnan(lines[1].get_ydata()[~feasible]))  # not drawn: the line breaks
    bounds = [ln for ln in ax.get_lines() if ln.get_gid() == "bound"]
    assert sorted(ln.get_ydata()[0] for ln in bounds) == [1.0, 100.0]
    assert all(ln.get_linestyle() == "--" for ln in bounds)
    (marks,) = [ln for ln in ax.get_lines() if ln.get_gid() == "infeasible"]
    np.testing.assert_allclose(marks.get_xdata(), t[~feasible])
    spans = [p for p in ax.patches if p.get_gid() == "infeasible-span"]
    assert len(spans) == 2  # samples 4-6 and 21 (1-based): two runs
    assert ax.get_ylabel() == "tension [N]" and ax.get_xlabel() == "time [s]"
    assert "26 of 30" in ax.get_title()
    plt.close("all")
    ax = plot_tensions(t, tensions, 1.0, 100.0, feasible, mask_infeasible=False)
    assert ax.get_lines()[0].get_ydata()[3] == 0.0


def test_tensions_per_cable_bounds_and_index_axis():
    tensions = np.array([[1.0, 2.0, 3.0], [2.0, 3.0, 4.0]])
    ax = plot_tensions(None, tensions, [0.5, 1.0, 1.5], [np.inf, 10.0, 20.0], np.array([True, True]))
    bounds = [ln for ln in ax.get_lines() if ln.get_gid() == "bound"]
    assert sorted(ln.get_ydata()[0] for ln in bounds) == [0.5, 1.0, 1.5, 10.0, 20.0]  # the infinite bound is not drawn
    assert ax.get_xlabel() == "sample"
    assert not [ln for ln in ax.get_lines() if ln.get_gid() == "infeasible"]


@pytest.mark.parametrize(
    "args, what",
    [
        ((None, [["a", 1.0]], 0.0, 1.0), "tensions"),
        (([0.0, "later"], np.ones((2, 2)), 0.0, 1.0), "times"),
        ((None, np.ones((2, 2)), {"low": 0}, 1.0), "tension bounds"),
    ],
)
def test_tensions_that_are_not_numbers_are_named(args, what):
    with pytest.raises(ArgumentError, match=f"^{what}: expected numbers"):
        plot_tensions(*args)


# ---- Report ------------------------------------------------------------------------------
def test_report_writes_html_with_existing_pngs_and_escapes_text(tmp_path):
    report = Report("taut <test> & report")
    robot_fig = draw_robot(PLANAR).figure
    tension_fig = plot_tensions(None, np.ones((5, 3)), 0.0, 2.0, np.ones(5, bool)).figure
    report.add_section(
        "Robot <drawing>",
        text="First paragraph with <script>alert(1)</script> & more.\n\nSecond paragraph.",
        figures=[(robot_fig, "robot.png", "caption <b>bold</b>"), (tension_fig, "tensions", "tensions")],
    )
    report.add_section(
        "Numbers",
        table=[{"name": "<x>", "value": 1.23456789, "ok": True}, {"name": "y", "extra": np.int64(3)}],
        json={"fraction": np.float64(0.5), "inside": np.arange(3), "note": "</pre><i>"},
    )
    assert not plt.fignum_exists(robot_fig.number) and not plt.fignum_exists(tension_fig.number)
    index = report.write(tmp_path / "out")
    assert index == tmp_path / "out" / "index.html" and index.is_file()
    text = index.read_text(encoding="utf-8")
    srcs = re.findall(r'<img src="([^"]+)"', text)
    assert srcs == ["robot.png", "tensions.png"]
    for src in srcs:
        png = index.parent / src
        assert png.is_file() and png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "<script>" not in text and "&lt;script&gt;alert(1)&lt;/script&gt; &amp; more." in text
    assert "<title>taut &lt;test&gt; &amp; report</title>" in text
    assert "caption &lt;b&gt;bold&lt;/b&gt;" in text and "<b>" not in text
    assert text.count("<p>") >= 2
    assert "<th>name</th><th>value</th><th>ok</th><th>extra</th>" in text
    assert "&lt;x&gt;" in text and "1.235" in text
    assert "&quot;fraction&quot;: 0.5" in text and "&lt;/pre&gt;&lt;i&gt;" in text


def test_report_rejects_bad_or_duplicate_file_names():
    report = Report("r")
    report.add_section("a", figures=[(plt.figure(), "one.png")])
    with pytest.raises(ArgumentError, match="used twice"):
        report.add_section("b", figures=[(plt.figure(), "one.png")])
    with pytest.raises(ArgumentError, match="plain file name"):
        report.add_section("c", figures=[(plt.figure(), "../escape.png")])
