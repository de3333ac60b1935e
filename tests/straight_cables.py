"""Which straight cables of a variable-structure robot meet its obstacles, by shapely: the
independent reference of the tests of taut.kinematics.obstacles_met and of the analyses that
refuse or exclude such poses (workspace, check, tensions, simulate)."""

from __future__ import annotations

import numpy as np
from shapely import LineString, Point
from shapely import Polygon as ShapelyPolygon

from taut.kinematics import anchors_at, as_poses

#: Round-off allowance [m]: a cable this close to an obstacle's boundary touches it, and
#: touching is not meeting (either verdict is right within it).
TOL = 1e-9


def contacts(robot, poses, *, tol=TOL):
    """``(N, n)`` int: the 0-based lowest-numbered obstacle each straight cable (exit → anchor)
    meets, ``-1`` where none; ``undecided`` ``(N, n)`` bool where a cable is within ``tol`` of
    an obstacle's boundary without entering it by more."""
    arr, _ = as_poses(robot, poses)
    b = anchors_at(robot, arr)
    N, n = b.shape[:2]
    met = np.full((N, n), -1)
    near = np.zeros((N, n), bool)
    for k in range(N):
        for i in range(n):
            line = LineString([robot.exits[i], b[k, i]])
            for j, o in enumerate(robot.obstacles):
                if o.kind == "circle":
                    depth = o.radius - line.distance(Point(o.center))
                else:  # how much of the cable runs through the polygon's interior
                    poly = ShapelyPolygon(o.vertices)
                    depth = line.intersection(poly).length if line.relate_pattern(poly, "T********") else 0.0
                if abs(depth) <= tol:
                    near[k, i] = True
                if depth > tol and met[k, i] < 0:
                    met[k, i] = j
    return met, near
