"""Drawing of a robot at one pose: :func:`draw_robot`.

Planar robots (2-D axes, equal aspect) are drawn like the configuration figures of the
variable-structure robots of Rushton (2022) (Figs. 6.5, 6.12, 6.19: the
installation space, grey disallowed regions, circular obstacles, the platform and its
cables in colour; Fig. 3.5 for the installation space): frame exit points (squares,
labelled with 1-based cable numbers), one straight line per cable from exit point to
platform anchor, the platform outline (``platform.shape.polygon`` moved to the pose, or
else the convex hull of the anchors of each body), capsules as rounded outlines, a point
mass as a dot, obstacles (circles, polygons), the installation-space outline and the
shaded disallowed regions.

Spatial robots (3-D ``mplot3d`` axes, equal scale on all axes) are drawn like the
configurations of simulations a)–d) of Lieskovský (2020) (Figs. 4.3–4.4):
exit points, cables, each body as the convex hull of its anchors (faces and edges),
capsules as thick segments, spherical obstacles as wireframes, and the faint hull of
the exit points (the frame).

Cables are straight segments ``a_i → b_i`` (``docs/architecture.md`` §2.4); wrapped cables are not
drawn here.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, Figs. 3.5, 6.5, 6.12, 6.19. (docs/references.bib: rushton2022)
.. [2] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, Figs. 4.3–4.4.
   (docs/references.bib: lieskovsky2020)
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from taut.errors import PoseError
from taut.kinematics import anchor_points, as_poses, body_frames, via_points_at
from taut.model import Circle, Robot
from taut.viz._style import (
    DISALLOWED,
    FRAME,
    OBSTACLE,
    PLATFORM,
    axes_2d,
    axes_3d,
    cable_color,
    set_equal_3d,
)

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.patches import Patch
    from mpl_toolkits.mplot3d.axes3d import Axes3D

__all__ = ["draw_robot", "draw_scene_2d", "draw_scene_3d", "scene_points_3d"]


# ---------------------------------------------------------------------------------------
# geometry helpers (drawing only)
# ---------------------------------------------------------------------------------------
def _hull_2d(points: npt.ArrayLike) -> np.ndarray:
    """Vertices of the convex hull of planar points, counter-clockwise (k, 2); k < 3 when
    the points are collinear (the two extremes) or coincide (one point)."""
    pts = np.unique(np.asarray(points, float).reshape(-1, 2), axis=0)
    if len(pts) <= 2:
        return pts
    c = pts.mean(axis=0)
    _, s, vt = np.linalg.svd(pts - c)
    if s[1] <= 1e-9 * max(s[0], 1e-300):
        t = (pts - c) @ vt[0]
        return pts[[np.argmin(t), np.argmax(t)]]
    from scipy.spatial import ConvexHull

    return pts[ConvexHull(pts).vertices]


def _hull_faces_3d(points: npt.ArrayLike) -> list[np.ndarray]:
    """Faces of the convex hull of spatial points, each an ordered polygon (k, 3).

    Coplanar triangles of the hull are merged (a box has six quadrilateral faces); flat
    point sets give one polygon, collinear ones a segment (one 2-vertex "face"), a single
    point a 1-vertex face."""
    pts = np.unique(np.asarray(points, float).reshape(-1, 3), axis=0)
    if len(pts) <= 2:
        return [pts]
    c = pts.mean(axis=0)
    _, s, vt = np.linalg.svd(pts - c)
    tol = 1e-9 * max(s[0], 1e-300)
    rank = int((s > tol).sum())
    if rank <= 1:
        t = (pts - c) @ vt[0]
        return [pts[[np.argmin(t), np.argmax(t)]]]
    if rank == 2:
        uv = (pts - c) @ vt[:2].T
        from scipy.spatial import ConvexHull

        return [pts[ConvexHull(uv).vertices]]
    from scipy.spatial import ConvexHull

    hull = ConvexHull(pts)
    groups: dict[tuple[float, ...], set[int]] = {}
    for simplex, eq in zip(hull.simplices, hull.equations):
        key = tuple(np.round(eq, 9))
        groups.setdefault(key, set()).update(int(k) for k in simplex)
    faces = []
    for key, idx in groups.items():
        f = pts[sorted(idx)]
        n = np.asarray(key[:3])
        fc = f.mean(axis=0)
        e1 = f[0] - fc
        e1 /= np.linalg.norm(e1)
        e2 = np.cross(n, e1)
        ang = np.arctan2((f - fc) @ e2, (f - fc) @ e1)
        faces.append(f[np.argsort(ang)])
    return faces


def _transform(points: npt.ArrayLike, p: np.ndarray, R: np.ndarray) -> np.ndarray:
    """Body-frame points (k, d') to the fixed frame; 2-D points on a spatial body lie in
    its x–y plane, extra coordinates on a planar body are dropped."""
    pts = np.asarray(points, float)
    d = len(p)
    if pts.shape[1] < d:
        pts = np.concatenate([pts, np.zeros((len(pts), d - pts.shape[1]))], axis=1)
    return p + pts[:, :d] @ np.asarray(R).T


def _frame_outline(robot: Robot) -> list[np.ndarray]:
    if robot.dimension == 2:
        h = _hull_2d(robot.exits)
        return [h] if len(h) >= 3 else []
    faces = _hull_faces_3d(robot.exits)
    return [f for f in faces if len(f) >= 3]


def _label_offsets(exits: np.ndarray) -> np.ndarray:
    """Unit directions from the centre of the exits outwards (labels go there)."""
    v = exits - exits.mean(axis=0)
    n = np.linalg.norm(v, axis=1, keepdims=True)
    out = np.where(n > 0, v / np.where(n > 0, n, 1.0), 0.0)
    out[np.all(out == 0, axis=1), 0] = 1.0
    return out


def _exit_labels(exits: np.ndarray) -> list[tuple[np.ndarray, str, int]]:
    """(exit point, label, first cable index) with the numbers of cables sharing an exit joined."""
    groups: dict[tuple[float, ...], list[int]] = {}
    for i, e in enumerate(exits):
        groups.setdefault(tuple(np.round(e, 12)), []).append(i)
    return [(exits[ix[0]], ",".join(str(i + 1) for i in ix), ix[0]) for ix in groups.values()]


def _scene_scale(robot: Robot) -> float:
    pts = [robot.exits]
    if robot.installation_space:
        pts.append(np.asarray(robot.installation_space, float)[:, : robot.dimension])
    span = max(float(np.ptp(np.concatenate(pts), axis=0).max()), 0.0)
    return span if span > 0 else 1.0


def _default_pose(robot: Robot) -> np.ndarray:
    if robot.reference is not None and robot.reference.poses:
        name = "home" if "home" in robot.reference.poses else next(iter(robot.reference.poses))
        return np.asarray(robot.reference.poses[name], float)
    from taut.kinematics import default_guess

    return default_guess(robot)


# ---------------------------------------------------------------------------------------
# the fixed scene: frame, installation space, disallowed regions, obstacles, exits
# ---------------------------------------------------------------------------------------
def draw_scene_2d(robot: Robot, ax: Axes | None = None, *, labels: bool = True) -> Axes:
    """Draw everything of a planar robot that does not move — installation space, disallowed
    regions, obstacles, the frame outline and the exit points (with cable numbers when
    ``labels``) — on 2-D axes ``ax`` (``None``: a new figure) and return them.

    Raises :class:`~taut.errors.ArgumentError` for 3-D axes."""
    from matplotlib.patches import Circle as CirclePatch
    from matplotlib.patches import Polygon as PolygonPatch

    ax = axes_2d(ax, f"the scene of {robot.name}")

    for outline in _frame_outline(robot):
        ax.add_patch(PolygonPatch(outline, closed=True, fill=False, ec=FRAME, lw=0.8, ls=":", zorder=0.5, gid="frame"))
    if robot.installation_space:
        pts = np.asarray(robot.installation_space, float)[:, :2]
        ax.add_patch(
            PolygonPatch(
                pts,
                closed=True,
                fill=False,
                ec="black",
                lw=1.4,
                zorder=0.6,
                label="installation space",
                gid="installation-space",
            )
        )
    for k, region in enumerate(robot.disallowed):
        pts = np.asarray(region, float)[:, :2]
        ax.add_patch(
            PolygonPatch(
                pts,
                closed=True,
                fc=DISALLOWED,
                ec=DISALLOWED,
                alpha=0.25,
                hatch="//",
                lw=0.8,
                zorder=0.7,
                label="disallowed" if k == 0 else None,
                gid="disallowed",
            )
        )
    for k, o in enumerate(robot.obstacles):
        lab = "obstacle" if k == 0 else None
        patch: Patch
        if isinstance(o, Circle):
            patch = CirclePatch(
                (o.center[0], o.center[1]),
                o.radius,
                fc=OBSTACLE,
                ec="#555555",
                lw=1.0,
                zorder=1,
                label=lab,
                gid="obstacle",
            )
        else:
            patch = PolygonPatch(
                np.asarray(o.vertices, float)[:, :2],
                closed=True,
                fc=OBSTACLE,
                ec="#555555",
                lw=1.0,
                zorder=1,
                label=lab,
                gid="obstacle",
            )
        ax.add_patch(patch)
    ex = robot.exits
    ax.plot(ex[:, 0], ex[:, 1], ls="none", marker="s", ms=6, mfc="white", mec="black", zorder=4, gid="exits")
    if labels:
        offs = _label_offsets(ex)
        for point, text, i in _exit_labels(ex):
            ax.annotate(
                text,
                (float(point[0]), float(point[1])),
                xytext=tuple(11 * offs[i]),
                textcoords="offset points",
                ha="center",
                va="center",
                fontsize=9,
                color=cable_color(i),
                fontweight="bold",
                gid="cable-label",
            )
    return ax


def _floor(robot: Robot, region: Sequence[Sequence[float]]) -> np.ndarray:
    """A region's points in 3-D: a 2-D footprint is drawn on the floor of the frame."""
    pts = np.asarray(region, float)
    if pts.shape[1] == 2:
        pts = np.column_stack([pts, np.full(len(pts), float(robot.exits[:, 2].min()))])
    return pts[:, :3]


def _sphere(center: Sequence[float], radius: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Wireframe grid (x, y, z), each (9, 17), of a spherical obstacle."""
    c = np.asarray(center, float)
    u, v = np.meshgrid(np.linspace(0, 2 * np.pi, 17), np.linspace(0, np.pi, 9))
    return c[0] + radius * np.cos(u) * np.sin(v), c[1] + radius * np.sin(u) * np.sin(v), c[2] + radius * np.cos(v)


def scene_points_3d(robot: Robot) -> np.ndarray:
    """``(k, 3)`` points of everything :func:`draw_scene_3d` draws (for the axes limits)."""
    pts = [robot.exits]
    if robot.installation_space:
        pts.append(_floor(robot, robot.installation_space))
    pts += [_floor(robot, region) for region in robot.disallowed]
    for o in robot.obstacles:
        if isinstance(o, Circle):
            pts.append(np.column_stack([c.ravel() for c in _sphere(o.center, o.radius)]))
        else:
            pts.append(np.asarray(o.vertices, float))
    return np.concatenate(pts)


def draw_scene_3d(robot: Robot, ax: Axes | None = None, *, labels: bool = True) -> Axes3D:
    """Draw the fixed parts of a spatial robot on 3-D axes ``ax`` (``None``: a new figure)
    and return them; :func:`scene_points_3d` gives the points drawn, to set the limits.

    Raises :class:`~taut.errors.ArgumentError` for 2-D axes."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    ax3 = axes_3d(ax, f"the scene of {robot.name}")
    for face in _frame_outline(robot):
        loop = np.vstack([face, face[:1]])
        ax3.plot(loop[:, 0], loop[:, 1], loop[:, 2], color=FRAME, lw=0.6, ls=":", gid="frame")
    if robot.installation_space:
        pts = _floor(robot, robot.installation_space)
        loop = np.vstack([pts, pts[:1]])
        ax3.plot(loop[:, 0], loop[:, 1], loop[:, 2], color="black", lw=1.2, gid="installation-space")
    for region in robot.disallowed:
        ax3.add_collection3d(
            Poly3DCollection(
                [_floor(robot, region)], facecolor=DISALLOWED, alpha=0.25, edgecolor=DISALLOWED, gid="disallowed"
            )
        )
    for o in robot.obstacles:
        if isinstance(o, Circle):
            ax3.plot_wireframe(*_sphere(o.center, o.radius), color="#666666", lw=0.5, gid="obstacle")
        else:
            ax3.add_collection3d(
                Poly3DCollection(
                    [np.asarray(o.vertices, float)], facecolor=OBSTACLE, alpha=0.5, edgecolor="#555555", gid="obstacle"
                )
            )
    ex = robot.exits
    ax3.plot(ex[:, 0], ex[:, 1], ex[:, 2], ls="none", marker="s", ms=5, mfc="white", mec="black", gid="exits")
    if labels:
        offs = _label_offsets(ex) * 0.04 * _scene_scale(robot)
        for point, text, i in _exit_labels(ex):
            q = point + offs[i]
            ax3.text(
                q[0],
                q[1],
                q[2],
                text,
                color=cable_color(i),
                fontsize=9,
                fontweight="bold",
                ha="center",
                va="center",
                gid="cable-label",
            )
    return ax3


# ---------------------------------------------------------------------------------------
# the robot at a pose
# ---------------------------------------------------------------------------------------
def _pose_title(robot: Robot, pose: np.ndarray) -> str:
    return ", ".join(f"{n}={v:.3g}" for n, v in zip(robot.pose_names, pose))


def draw_robot(robot: Robot, pose: npt.ArrayLike | None = None, ax: Axes | None = None) -> Axes:
    """Draw ``robot`` at ``pose`` (default: its ``home`` reference pose, else the centroid of
    its exit points) on ``ax`` and return that ``Axes``.

    A planar robot is drawn on 2-D axes, a spatial one on 3-D axes (an ``Axes3D``, made by
    ``projection="3d"``); with ``ax=None`` a new figure with axes of the right kind is made,
    axes of the other kind raise :class:`~taut.errors.ArgumentError`, several poses a
    :class:`~taut.errors.PoseError`.  Each cable is one line, through its via points, with
    ``gid="cable-<i>"`` and label ``"cable <i>"`` (1-based ``i``)."""
    pose = _default_pose(robot) if pose is None else pose
    arr, _ = as_poses(robot, pose)
    if arr.shape[0] != 1:
        raise PoseError(f"draw_robot draws one pose, got {arr.shape[0]}")
    what = f"{robot.name} ({'spatial' if robot.dimension == 3 else 'planar'})"
    drawn = _draw_3d(axes_3d(ax, what), robot, arr) if robot.dimension == 3 else _draw_2d(axes_2d(ax, what), robot, arr)
    drawn.set_title(f"{robot.name}\n{_pose_title(robot, arr[0])}", fontsize=10)
    return drawn


def _cable_runs(robot: Robot, arr: np.ndarray, anchors: np.ndarray) -> list[np.ndarray]:
    """Each cable as the polyline its line is drawn along: from its exit point through its
    via points (``cables[].via``) to its anchor."""
    vias, owner = via_points_at(robot, arr)[0], robot.via_points[0]
    return [np.vstack([robot.exits[i], vias[owner == i], anchors[i]]) for i in range(robot.n_cables)]


def _draw_2d(ax: Axes, robot: Robot, arr: np.ndarray) -> Axes:
    from matplotlib.patches import Polygon as PolygonPatch
    from shapely import LineString, Point

    draw_scene_2d(robot, ax)
    b = anchor_points(robot, arr)[0]
    pos, rot = body_frames(robot, arr)
    pos, rot = pos[0], rot[0]
    for i, run in enumerate(_cable_runs(robot, arr, b)):
        ax.plot(
            run[:, 0],
            run[:, 1],
            color=cable_color(i),
            lw=1.6,
            zorder=2,
            label=f"cable {i + 1}",
            gid=f"cable-{i + 1}",
        )
    p = arr[0, :2]
    if robot.is_point_mass:
        ax.plot([p[0]], [p[1]], ls="none", marker="o", ms=9, color=PLATFORM, zorder=5, label="platform", gid="platform")
    else:
        shape = robot.platform.shape
        parents = {"platform": 0} | {bb.name: j for j, bb in enumerate(robot.platform.bodies, 1)}
        for k in range(pos.shape[0]):
            if k == 0 and shape is not None and shape.polygon:
                outline = _transform(shape.polygon, pos[0], rot[0])
            else:
                on_body = robot.cable_bodies == k
                outline = _hull_2d(b[on_body]) if on_body.any() else np.empty((0, 2))
            if len(outline) >= 3:
                ax.add_patch(
                    PolygonPatch(
                        outline,
                        closed=True,
                        fc=PLATFORM,
                        ec="black",
                        alpha=0.45,
                        lw=1.2,
                        zorder=3,
                        label="platform" if k == 0 else None,
                        gid="platform",
                    )
                )
            elif len(outline) == 2:
                ax.plot(
                    outline[:, 0], outline[:, 1], color=PLATFORM, lw=4, solid_capstyle="round", zorder=3, gid="platform"
                )
            if k > 0:  # the joint: parent frame origin to body frame origin
                par = parents[robot.platform.bodies[k - 1].parent]
                ax.plot(
                    [pos[par][0], pos[k][0]],
                    [pos[par][1], pos[k][1]],
                    color="black",
                    lw=1,
                    ls="--",
                    zorder=3,
                    gid="joint",
                )
        for k, cap in robot.body_capsules:
            ends = _transform([cap.a, cap.b], pos[k], rot[k])
            geom = (LineString(ends) if np.ptp(ends, axis=0).max() > 0 else Point(ends[0])).buffer(cap.radius, 24)
            if not geom.is_empty:
                ax.add_patch(
                    PolygonPatch(
                        np.asarray(geom.exterior.coords),
                        closed=True,
                        fill=False,
                        ec=PLATFORM,
                        lw=1.0,
                        ls="--",
                        zorder=3,
                        gid="capsule",
                    )
                )
        ax.plot([p[0]], [p[1]], ls="none", marker="+", ms=9, color="black", zorder=5, gid="reference-point")
    ax.plot(b[:, 0], b[:, 1], ls="none", marker="o", ms=3.5, color="black", zorder=4, gid="anchors")
    ax.set_aspect("equal")
    ax.margins(0.08)
    ax.autoscale_view()
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.grid(True, lw=0.3, alpha=0.5)
    handles = [h for h in ax.patches if h.get_label() in ("installation space", "disallowed", "obstacle")]
    if handles:
        ax.legend(handles=handles, fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0)
    return ax


def _draw_3d(ax: Axes3D, robot: Robot, arr: np.ndarray) -> Axes3D:
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    draw_scene_3d(robot, ax)
    drawn = [scene_points_3d(robot)]
    b = anchor_points(robot, arr)[0]
    pos, rot = body_frames(robot, arr)
    pos, rot = pos[0], rot[0]
    drawn.append(b)
    for i, run in enumerate(_cable_runs(robot, arr, b)):
        ax.plot(
            run[:, 0],
            run[:, 1],
            run[:, 2],
            color=cable_color(i),
            lw=1.4,
            label=f"cable {i + 1}",
            gid=f"cable-{i + 1}",
        )
    p = arr[0, :3]
    if robot.is_point_mass:
        ax.plot([p[0]], [p[1]], [p[2]], ls="none", marker="o", ms=8, color=PLATFORM, gid="platform")
    else:
        shape = robot.platform.shape
        for k in range(pos.shape[0]):
            on_body = robot.cable_bodies == k
            if k == 0 and shape is not None and shape.polygon:
                faces = [_transform(shape.polygon, pos[0], rot[0])]
            else:
                faces = _hull_faces_3d(b[on_body]) if on_body.any() else []
            polys = [f for f in faces if len(f) >= 3]
            if polys:
                ax.add_collection3d(
                    Poly3DCollection(
                        polys, facecolor=PLATFORM, alpha=0.3, edgecolor="black", linewidths=0.8, gid="platform"
                    )
                )
            for f in faces:
                if len(f) == 2:
                    ax.plot(f[:, 0], f[:, 1], f[:, 2], color=PLATFORM, lw=4, gid="platform")
        for k, cap in robot.body_capsules:
            ends = _transform([cap.a, cap.b], pos[k], rot[k])
            ax.plot(
                ends[:, 0],
                ends[:, 1],
                ends[:, 2],
                color=PLATFORM,
                lw=7,
                alpha=0.35,
                solid_capstyle="round",
                gid="capsule",
            )
            drawn.append(ends)
        ax.plot([p[0]], [p[1]], [p[2]], ls="none", marker="+", ms=8, color="black", gid="reference-point")
    ax.plot(b[:, 0], b[:, 1], b[:, 2], ls="none", marker="o", ms=3, color="black", gid="anchors")
    set_equal_3d(ax, np.concatenate(drawn))
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_zlabel("z [m]")
    return ax
