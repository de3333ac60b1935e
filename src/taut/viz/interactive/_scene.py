"""The pieces of every interactive view: the fixed scene of a robot (frame, exit points,
obstacles, installation space) and the robot at a pose (platform and its bodies, capsules,
swivelling pulleys, cables coloured by tension, slack cables dashed), as plotly traces in one
3-D scene.  A planar robot is drawn in the plane ``z = 0``, seen from above.

The traces of the robot at a pose are always the same :data:`POSE_TRACES`, in the same
order, empty where a robot has no such part: an animation frame or a selector then replaces
them by position, whatever the robot.  The drawing follows :func:`taut.viz.draw_robot`
(``docs/architecture.md`` §2.4): straight cables from exit point (or pulley tangent point) to
anchor, unless the wrapped paths of a variable-structure robot are given.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from taut.errors import ArgumentError
from taut.kinematics import (
    anchor_points,
    as_poses,
    body_frames,
    cable_paths,
    swivel_parameters,
    swivel_paths,
    via_points_at,
)
from taut.model import Circle, Robot
from taut.viz._robot import _exit_labels, _frame_outline, _hull_faces_3d, _sphere, _transform
from taut.viz._style import CABLE_COLORS, DISALLOWED, FRAME, OBSTACLE, PLATFORM
from taut.viz.interactive._plotly import graph_objects

if TYPE_CHECKING:
    from plotly.basedatatypes import BaseTraceType

#: Names of the traces of the robot at a pose, in their order.
POSE_TRACES = ("platform", "platform edges", "capsules", "pulleys", "cables", "slack cables", "anchors")

#: The colour scale of tensions (low: dark, high: bright).
TENSION_SCALE = "Viridis"


def lift(points: npt.ArrayLike) -> np.ndarray:
    """Points ``(..., d)`` as ``(..., 3)``: a planar robot's in the plane ``z = 0``."""
    pts = np.asarray(points, float)
    if pts.shape[-1] == 3:
        return pts
    return np.concatenate([pts, np.zeros((*pts.shape[:-1], 3 - pts.shape[-1]))], axis=-1)


def polylines(paths: Sequence[np.ndarray]) -> np.ndarray:
    """Several polylines ``(k_j, 3)`` as one ``(K, 3)`` array, NaN rows between them (plotly
    breaks a line at a gap)."""
    rows: list[np.ndarray] = []
    for p in paths:
        if len(p):
            rows += [np.asarray(p, float), np.full((1, 3), np.nan)]
    return np.concatenate(rows) if rows else np.empty((0, 3))


def loop(points: np.ndarray) -> np.ndarray:
    """A closed polygon's outline."""
    return np.vstack([points, points[:1]])


def _circle(centre: np.ndarray, radius: float, e1: np.ndarray, e2: np.ndarray, n: int = 33) -> np.ndarray:
    t = np.linspace(0.0, 2 * np.pi, n)
    return centre + radius * (np.cos(t)[:, None] * e1 + np.sin(t)[:, None] * e2)


#: The type of drawn coordinates: single precision (7 digits) is finer than any screen, and
#: halves a view's file; the numbers a view reports (lengths, tensions) stay double.
DRAWN = np.float32


def _line(go: Any, pts: np.ndarray, name: str, **style: Any) -> BaseTraceType:
    pts = pts.astype(DRAWN)
    return go.Scatter3d(x=pts[:, 0], y=pts[:, 1], z=pts[:, 2], mode="lines", name=name, **style)


def mesh(go: Any, vertices: np.ndarray, triangles: np.ndarray, name: str, **style: Any) -> BaseTraceType:
    """A triangle mesh: ``vertices`` ``(V, 3)`` and the vertex indices of its ``triangles`` ``(F, 3)``."""
    v, t = np.asarray(vertices), np.asarray(triangles)
    return go.Mesh3d(x=v[:, 0], y=v[:, 1], z=v[:, 2], i=t[:, 0], j=t[:, 1], k=t[:, 2], name=name, **style)


def scene_traces(robot: Robot) -> list[BaseTraceType]:
    """The traces of everything of ``robot`` that does not move: the frame (the hull of the
    exit points, dotted), the installation space and disallowed regions, the obstacles
    (planar circles and polygons; spheres in space) and the exit points labelled with their
    1-based cable numbers."""
    go = graph_objects()
    out = []
    outline = [lift(loop(f)) for f in _frame_outline(robot)]
    if outline:
        out.append(
            _line(go, polylines(outline), "frame", line=dict(color=FRAME, width=2, dash="dot"), hoverinfo="skip")
        )
    floor = float(robot.exits[:, -1].min()) if robot.dimension == 3 else 0.0

    def flat(region: Sequence[Sequence[float]]) -> np.ndarray:
        pts = np.asarray(region, float)
        return pts[:, :3] if pts.shape[1] == 3 else np.column_stack([pts[:, :2], np.full(len(pts), floor)])

    if robot.installation_space:
        pts = loop(flat(robot.installation_space))
        out.append(_line(go, pts, "installation space", line=dict(color="black", width=3)))
    if robot.disallowed:
        pts = polylines([loop(flat(r)) for r in robot.disallowed])
        out.append(_line(go, pts, "disallowed", line=dict(color=DISALLOWED, width=3)))
    shapes = []
    for o in robot.obstacles:
        if isinstance(o, Circle) and robot.dimension == 2:
            c = lift(np.asarray(o.center, float)[:2])
            shapes.append(_circle(c, o.radius, np.eye(3)[0], np.eye(3)[1]))
        elif isinstance(o, Circle):
            xs, ys, zs = _sphere(o.center, o.radius)
            shapes += [np.column_stack([xs[k], ys[k], zs[k]]) for k in range(xs.shape[0])]
            shapes += [np.column_stack([xs[:, k], ys[:, k], zs[:, k]]) for k in range(xs.shape[1])]
        else:
            shapes.append(lift(loop(np.asarray(o.vertices, float))))
    if shapes:
        out.append(_line(go, polylines(shapes), "obstacles", line=dict(color=OBSTACLE, width=4)))
    ex = lift(robot.exits)
    labels = _exit_labels(robot.exits)
    out.append(
        go.Scatter3d(
            x=ex[:, 0],
            y=ex[:, 1],
            z=ex[:, 2],
            mode="markers",
            name="exit points",
            marker=dict(symbol="square", size=4, color="white", line=dict(color="black", width=1)),
            hovertext=[f"exit of cable {i + 1}" for i in range(robot.n_cables)],
            hoverinfo="text",
        )
    )
    pts = lift(np.array([p for p, _, _ in labels]))
    out.append(
        go.Scatter3d(
            x=pts[:, 0],
            y=pts[:, 1],
            z=pts[:, 2],
            mode="text",
            text=[t for _, t, _ in labels],
            textposition="top center",
            textfont=dict(color="black", size=13),
            name="cable numbers",
            hoverinfo="skip",
            showlegend=False,
        )
    )
    return out


@dataclass(frozen=True)
class Poses:
    """The geometry of a robot at ``N`` poses, computed once for every frame of a view.

    ``anchors`` ``(N, n, 3)``; ``origins`` ``(N, B, 3)`` and ``rotations`` ``(N, B, d, d)`` of
    the platform's bodies; ``starts`` ``(N, n, 3)``, where the straight segment of each cable
    that ends at its anchor begins (its exit point, its pulley's tangent point or its last via
    point); ``lengths`` ``(N, n)`` of straight or routed cables; ``vias`` ``(N, V, 3)``, the via
    points of the routed cables (:func:`taut.kinematics.via_points_at`)."""

    poses: np.ndarray
    anchors: np.ndarray
    origins: np.ndarray
    rotations: np.ndarray
    starts: np.ndarray
    lengths: np.ndarray
    vias: np.ndarray


def at_poses(robot: Robot, poses: npt.ArrayLike) -> Poses:
    """The geometry of ``robot`` at ``poses`` ``(N, pose_size)`` (or one pose)."""
    arr, _ = as_poses(robot, poses)
    b = anchor_points(robot, arr)
    origins, rotations = body_frames(robot, arr)
    vias = via_points_at(robot, arr)
    lengths, starts, _ = cable_paths(robot, b, via=vias if robot.routed_cables else None)
    return Poses(arr, lift(b), lift(origins), rotations, lift(starts), lengths, lift(vias))


def bounds(robot: Robot, geometry: Sequence[Poses], extra: Sequence[np.ndarray] = ()) -> dict[str, Any]:
    """The 3-D scene's layout: fixed axis ranges over the scene and every pose (so that an
    animation does not rescale), metres equal on all axes; a planar robot seen from above."""
    pts = [lift(robot.exits), *(g.anchors.reshape(-1, 3) for g in geometry), *(lift(e).reshape(-1, 3) for e in extra)]
    pts += [lift(g.origins.reshape(-1, g.origins.shape[-1])) for g in geometry]
    for o in robot.obstacles:
        c = lift(np.asarray(o.center if isinstance(o, Circle) else o.vertices, float).reshape(-1, robot.dimension))
        r = o.radius if isinstance(o, Circle) else 0.0
        pts += [c - r, c + r]
    regions: list[Sequence[Sequence[float]]] = [robot.installation_space or [], *robot.disallowed]
    for region in regions:
        if len(region):
            pts.append(lift(np.asarray(region, float)[:, : robot.dimension]))
    _, _, radii = swivel_parameters(robot)
    allp = np.concatenate(pts)
    allp = allp[np.all(np.isfinite(allp), axis=1)]
    lo, hi = allp.min(axis=0), allp.max(axis=0)
    pad = 0.06 * max(float((hi - lo).max()), 1e-9) + (float(np.max(radii)) if len(radii) else 0.0)
    span = np.maximum(hi - lo + 2 * pad, 0.04 * max(float((hi - lo).max()), 1e-9))
    mid = (lo + hi) / 2
    lo, hi = mid - span / 2, mid + span / 2
    ratio = span / span.max()
    axes = {
        f"{c}axis": dict(range=[float(lo[k]), float(hi[k])], title=f"{c} [m]", autorange=False)
        for k, c in enumerate("xyz")
    }
    scene: dict[str, Any] = axes | dict(aspectmode="manual", aspectratio=dict(x=ratio[0], y=ratio[1], z=ratio[2]))
    if robot.dimension == 2:
        scene["camera"] = dict(eye=dict(x=0.0, y=0.0, z=1.6), up=dict(x=0.0, y=1.0, z=0.0))
        scene["zaxis"]["visible"] = False
    return scene


def _tube(a: np.ndarray, b: np.ndarray, r: float, m: int = 14) -> tuple[np.ndarray, np.ndarray]:
    """Vertices and triangles of a closed cylinder of radius ``r`` from ``a`` to ``b``."""
    u = b - a
    n = float(np.linalg.norm(u))
    u = u / n if n > 0 else np.array([0.0, 0.0, 1.0])
    v = np.cross(u, [1.0, 0, 0] if abs(u[0]) < 0.9 else [0, 1.0, 0])
    v /= np.linalg.norm(v)
    w = np.cross(u, v)
    t = np.linspace(0, 2 * np.pi, m, endpoint=False)
    ring = r * (np.cos(t)[:, None] * v + np.sin(t)[:, None] * w)
    verts = np.vstack([a + ring, b + ring, a, b])
    k = np.arange(m)
    k1 = (k + 1) % m
    tri = np.vstack(
        [
            np.column_stack([k, k1, m + k]),
            np.column_stack([k1, m + k1, m + k]),
            np.column_stack([np.full(m, 2 * m), k1, k]),
            np.column_stack([np.full(m, 2 * m + 1), m + k, m + k1]),
        ]
    )
    return verts, tri


def _mesh(parts: Sequence[tuple[np.ndarray, np.ndarray]]) -> tuple[np.ndarray, np.ndarray]:
    verts, tris, offset = [], [], 0
    for v, t in parts:
        verts.append(v)
        tris.append(t + offset)
        offset += len(v)
    if not verts:
        return np.empty((0, 3)), np.empty((0, 3), int)
    return np.vstack(verts), np.vstack(tris)


def _fan(face: np.ndarray, offset: int) -> np.ndarray:
    k = np.arange(1, len(face) - 1)
    return np.column_stack([np.full(len(k), offset), offset + k, offset + k + 1])


def _bodies(robot: Robot, g: Poses, s: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Faces (vertices, triangles), edges and capsules (vertices, triangles) of the platform's
    bodies at pose ``s``."""
    b = g.anchors[s]
    faces: list[np.ndarray] = []
    joints: list[np.ndarray] = []
    if not robot.is_point_mass:
        shape = robot.platform.shape
        parents = {"platform": 0} | {bb.name: j for j, bb in enumerate(robot.platform.bodies, 1)}
        d = robot.dimension
        for k in range(g.origins.shape[1]):
            on_body = robot.cable_bodies == k
            if k == 0 and shape is not None and shape.polygon:
                faces.append(lift(_transform(shape.polygon, g.origins[s, 0, :d], g.rotations[s, 0])))
            elif on_body.any():
                faces += [f for f in _hull_faces_3d(b[on_body]) if len(f) >= 2]
            if k > 0:
                par = parents[robot.platform.bodies[k - 1].parent]
                joints.append(np.vstack([g.origins[s, par], g.origins[s, k]]))
    verts, tris, offset = [], [], 0
    for f in faces:
        if len(f) >= 3:
            verts.append(f)
            tris.append(_fan(f, offset))
            offset += len(f)
    v = np.vstack(verts) if verts else np.empty((0, 3))
    t = np.vstack(tris) if tris else np.empty((0, 3), int)
    edges = polylines([loop(f) if len(f) >= 3 else f for f in faces] + joints)
    caps = []
    d = robot.dimension
    for k, cap in robot.body_capsules:
        ends = lift(_transform([cap.a, cap.b], g.origins[s, k, :d], g.rotations[s, k]))
        caps.append(_tube(ends[0], ends[1], cap.radius))
    cv, ct = _mesh(caps)
    return v, t, edges, cv, ct


def _pulleys(robot: Robot, g: Poses, s: int) -> tuple[np.ndarray, dict[int, np.ndarray]]:
    """Outlines of the swivelling pulleys at pose ``s`` (each turned to face its anchor) and,
    per such cable, the arc it winds on its pulley from the exit point to the tangent point."""
    cables, axes, radii = swivel_parameters(robot)
    if not len(cables):
        return np.empty((0, 3)), {}
    wraps = swivel_paths(robot.exits[cables], axes, radii, g.anchors[s][None, cables, : robot.dimension]).wrap[0]
    circles, arcs = [], {}
    for j, i in enumerate(cables):
        a, e, r = lift(robot.exits[i]), lift(axes[j]), float(radii[j])
        off = g.anchors[s, i] - a
        w = off - (off @ e) * e
        nw = float(np.linalg.norm(w))
        if nw == 0:
            continue  # an anchor on the swivel axis: the pulley has no direction to face
        w /= nw
        centre = a + r * w
        circles.append(_circle(centre, r, w, e))
        # the exit point is at angle π on the pulley; the arc of angle β that ends at the
        # tangent point is the one the cable winds
        ends = [
            centre + r * (np.cos(np.pi + sgn * wraps[j]) * w + np.sin(np.pi + sgn * wraps[j]) * e) for sgn in (1, -1)
        ]
        sgn = 1 if np.linalg.norm(ends[0] - g.starts[s, i]) <= np.linalg.norm(ends[1] - g.starts[s, i]) else -1
        t = np.pi + sgn * np.linspace(0.0, wraps[j], 17)
        arcs[int(i)] = centre + r * (np.cos(t)[:, None] * w + np.sin(t)[:, None] * e)
    return polylines(circles), arcs


def tension_range(tensions: np.ndarray | None) -> tuple[float, float]:
    """The colour range of ``tensions``: their finite extremes, widened when equal."""
    if tensions is None or not np.isfinite(tensions).any():
        return 0.0, 1.0
    lo, hi = float(np.nanmin(tensions)), float(np.nanmax(tensions))
    return (lo, hi) if hi > lo else (lo - 0.5, hi + 0.5)


def _cable_colours(n: int) -> list[list[float | str]]:
    """A stepwise colour scale giving value ``i`` the colour of cable ``i``."""
    scale: list[list[float | str]] = []
    for k in range(n):
        c = CABLE_COLORS[k % len(CABLE_COLORS)]
        scale += [[k / n, c], [(k + 1) / n, c]]
    return scale


def pose_traces(
    robot: Robot,
    g: Poses,
    s: int,
    *,
    tensions: np.ndarray | None = None,
    slack: np.ndarray | None = None,
    paths: Sequence[np.ndarray] | None = None,
    lengths: np.ndarray | None = None,
    crange: tuple[float, float] = (0.0, 1.0),
    label: str = "",
    colorbar: bool = True,
    visible: bool = True,
    scene: str = "scene",
) -> list[BaseTraceType]:
    """The :data:`POSE_TRACES` of ``robot`` at pose ``s`` of ``g``.

    ``tensions`` ``(n,)`` colour the cables on the scale ``crange`` (without them each cable
    has its own colour); ``slack`` ``(n,)`` cables are dashed; ``paths`` are the wrapped
    paths ``(k, d)`` of the cables of a variable-structure robot (else straight, from the
    exit or pulley tangent point); ``lengths`` ``(n,)`` are shown in the hover (else the
    straight lengths); ``label`` heads every hover text."""
    go = graph_objects()
    n = robot.n_cables
    lengths = g.lengths[s] if lengths is None else lengths
    slack = np.zeros(n, bool) if slack is None else np.asarray(slack, bool)
    pulley_lines, arcs = _pulleys(robot, g, s)
    via_cables = robot.via_points[0]
    runs = []
    for i in range(n):
        if paths is not None:
            run = lift(paths[i])
        elif i in robot.routed_cables:
            run = np.vstack([lift(robot.exits[i])[None], g.vias[s, via_cables == i], g.anchors[s, i][None]])
        else:
            run = np.vstack([p for p in (arcs.get(i), g.starts[s, i][None], g.anchors[s, i][None]) if p is not None])
        runs.append(run)
    head = f"{label}<br>" if label else ""

    # the colour values as a list: plotly.js reads a typed array there as one colour, not one
    # per vertex; the hover's numbers go in a compact array, its words in one template
    def cable_lines(which: np.ndarray) -> tuple[np.ndarray, list[float], np.ndarray]:
        idx = np.flatnonzero(which)
        pts = polylines([runs[i] for i in idx])
        values: list[float] = []
        data: list[list[float]] = []
        for i in idx:
            k = len(runs[i]) + 1
            tau = float(tensions[i]) if tensions is not None else 0.0
            values += [tau if tensions is not None else float(i)] * k
            data += [[i + 1.0, float(lengths[i]), tau]] * k
        return pts, values, np.array(data, DRAWN).reshape(-1, 3)

    def template(what: str) -> str:
        tau = "" if tensions is None else "<br>tension %{customdata[2]:.4g} N"
        return f"{head}cable %{{customdata[0]}}{what}<br>length %{{customdata[1]:.4g}} m{tau}<extra></extra>"

    tight, tvals, thover = cable_lines(~slack)
    loose, _, lhover = cable_lines(slack)
    if tensions is not None:
        colour: dict[str, Any] = dict(color=tvals, colorscale=TENSION_SCALE, cmin=crange[0], cmax=crange[1])
        colour |= dict(showscale=colorbar, colorbar=dict(title="tension [N]", len=0.6, x=1.0))
    else:
        colour = dict(color=tvals, colorscale=_cable_colours(n), cmin=-0.5, cmax=n - 0.5, showscale=False)
    v, t, edges, cv, ct = _bodies(robot, g, s)
    b = g.anchors[s]
    p = lift(g.poses[s, : robot.dimension])
    marks = np.vstack([b, p[None]])
    common = dict(visible=visible, scene=scene)
    return [
        mesh(
            go,
            v,
            t,
            "platform",
            color=PLATFORM,
            opacity=0.35,
            hoverinfo="skip",
            flatshading=True,
            **common,
        ),
        _line(
            go, edges, "platform edges", line=dict(color="black", width=3), hoverinfo="skip", showlegend=False, **common
        ),
        mesh(
            go,
            cv,
            ct,
            "capsules",
            color=PLATFORM,
            opacity=0.3,
            hoverinfo="skip",
            **common,
        ),
        _line(go, pulley_lines, "pulleys", line=dict(color="#555555", width=3), hoverinfo="skip", **common),
        # no legend entry: plotly.js draws its symbol with the line's colour, which is an array here
        _line(
            go,
            tight,
            "cables",
            line=dict(width=6) | colour,
            customdata=thover,
            hovertemplate=template(""),
            showlegend=False,
            **common,
        ),
        _line(
            go,
            loose,
            "slack cables",
            line=dict(width=4, dash="dash", color="#888888"),
            customdata=lhover,
            hovertemplate=template(" (slack)"),
            **common,
        ),
        go.Scatter3d(
            x=marks[:, 0],
            y=marks[:, 1],
            z=marks[:, 2],
            mode="markers",
            name="anchors",
            marker=dict(
                size=[3] * n + [7 if robot.is_point_mass else 4],
                color=["black"] * n + [PLATFORM],
                symbol=["circle"] * n + ["diamond"],
            ),
            hovertext=[f"{head}anchor of cable {i + 1}" for i in range(n)]
            + [f"{head}" + ", ".join(f"{nm}={x:.4g}" for nm, x in zip(robot.pose_names, g.poses[s]))],
            hoverinfo="text",
            showlegend=False,
            **common,
        ),
    ]


def check_rows(what: str, array: npt.ArrayLike | None, rows: int, columns: int) -> np.ndarray | None:
    """``array`` as finite-or-NaN floats of shape ``(rows, columns)``; else an
    :class:`~taut.errors.ArgumentError` naming ``what``."""
    if array is None:
        return None
    a = np.asarray(array, float)
    if a.shape != (rows, columns):
        raise ArgumentError(f"{what}: expected shape ({rows}, {columns}), got {a.shape}")
    if np.isinf(a).any():
        raise ArgumentError(f"{what}: infinite values cannot be drawn")
    return a
