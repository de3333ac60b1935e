"""Velocities at the via points of a multi-waypoint trajectory.

Three choices (``via=`` of :func:`taut.motion.trajectory_from_waypoints`):

- ``"stop"``: zero velocity (and acceleration) at every waypoint.  Each segment is then a
  straight line in pose coordinates with one time law for all coordinates, and the robot
  passes every waypoint exactly at rest: the right choice when the waypoints are poses to
  reach (CASPR's example trajectories give zero ``q_dot`` and ``q_ddot`` at every point).
- ``"average"`` (:func:`average_velocities`): the mean of the average velocities of the two
  segments that meet at the point, as CASPR's ``cubic_spline_average_velocity_trajectory``
  does; the velocity is continuous, the acceleration of a cubic jumps at the via points (a
  quintic takes zero acceleration there, so its acceleration is continuous too).  The robot
  does not stop, and the path bends smoothly near the via points instead of turning a corner.
- ``"spline"`` (:func:`spline_velocities`): the velocities of the cubic spline through all
  waypoints with continuous accelerations, at rest at both ends (Siciliano et al. 2009,
  §4.2.2): the smoothest of the three (C²), at the price of a global dependence (moving one
  waypoint changes every segment) and of overshoot between close waypoints.

References
----------
.. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning and
   Control", Springer, 2009, §4.2.2 (sequences of points: imposed velocities, continuous
   accelerations). (docs/references.bib: siciliano2009)
.. [2] D. Lau, J. Eden, Y. Tan, D. Oetomo, "CASPR: A comprehensive cable-robot analysis and
   simulation platform for the research of cable-driven parallel robots", IEEE/RSJ
   International Conference on Intelligent Robots and Systems (IROS), 2016.
   (docs/references.bib: lau2016)
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

__all__ = ["VIAS", "average_velocities", "spline_velocities"]

#: The choices of velocities at via points.
VIAS = ("stop", "average", "spline")


def average_velocities(
    times: np.ndarray, waypoints: np.ndarray, start: npt.ArrayLike = 0.0, end: npt.ArrayLike = 0.0
) -> np.ndarray:
    """Velocities ``(N, dof)`` at the waypoints ``(N, dof)`` reached at ``times (N,)``: at an
    interior point the mean of the average velocities of the segments before and after it
    (CASPR's ``cubic_spline_average_velocity_trajectory``); ``start`` and ``end`` at the ends."""
    slopes = np.diff(waypoints, axis=0) / np.diff(times)[:, None]
    v = np.empty_like(waypoints)
    v[0], v[-1] = start, end
    v[1:-1] = (slopes[:-1] + slopes[1:]) / 2
    return v


def spline_velocities(times: np.ndarray, waypoints: np.ndarray) -> np.ndarray:
    """Velocities ``(N, dof)`` at the waypoints of the cubic spline with continuous
    accelerations through them, at rest at both ends.

    Equating the accelerations of the two cubics that meet at point ``k`` gives
    ``h_k v_{k−1} + 2(h_{k−1} + h_k) v_k + h_{k−1} v_{k+1}
    = 3 (h_{k−1}/h_k Δ_k + h_k/h_{k−1} Δ_{k−1})`` with ``h_k`` and ``Δ_k`` the duration and
    displacement of segment ``k`` (Siciliano et al. 2009, §4.2.2)."""
    h = np.diff(times)
    d = np.diff(waypoints, axis=0)
    v = np.zeros_like(waypoints)
    m = len(waypoints) - 2
    if m == 0:
        return v
    A = np.zeros((m, m))
    k = np.arange(m)
    A[k, k] = 2 * (h[:-1] + h[1:])
    A[k[1:], k[:-1]] = h[2:]
    A[k[:-1], k[1:]] = h[:-2]
    b = 3 * ((h[:-1] / h[1:])[:, None] * d[1:] + (h[1:] / h[:-1])[:, None] * d[:-1])
    v[1:-1] = np.linalg.solve(A, b)
    return v
