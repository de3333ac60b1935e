"""Simulated calibration data: the cable lengths a built robot would measure at given poses,
with Gaussian noise, as lengths or as changes from an encoder zero."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from taut._checks import as_array, as_number, as_rng
from taut.calibration._data import Measurements, measurements
from taut.model import Robot


def simulate_measurements(
    robot: Robot,
    poses: npt.ArrayLike,
    *,
    sigma: float = 0.0,
    offsets: npt.ArrayLike | None = None,
    known_poses: bool = False,
    seed: int | np.random.Generator | None = None,
) -> Measurements:
    """The measurements ``robot`` (the built robot, whose geometry a calibration should find)
    gives at ``poses``: each cable's length plus Gaussian noise of standard deviation ``sigma``,
    or, with ``offsets``, its change ``l − o_i`` from an encoder zero at length ``o_i``.

    Parameters
    ----------
    robot : Robot
    poses : array_like, shape (N, pose_size)
    sigma : float
        Standard deviation of the length noise [m], ``≥ 0``.
    offsets : array_like, shape (n,), optional
        Each cable's length at its encoder's zero [m]: the data are then changes (``dl``
        columns) and a calibration estimates the offsets.
    known_poses : bool
        Record the poses too (a tracker measured them).
    seed : int or numpy.random.Generator, optional

    Returns
    -------
    Measurements

    Raises
    ------
    PoseError
        Poses that :func:`taut.kinematics.as_poses` refuses, or where a cable has no length.
    UnsupportedRobotError
        A robot with jointed bodies, obstacles, sagging or routed cables.

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.calibration import simulate_measurements
    >>> robot = example("planar-4cable")
    >>> data = simulate_measurements(robot, [[0.0, 0.0, 0.0]], offsets=[1.0] * 4)
    >>> data.values.round(4).tolist()
    [[0.3086, 0.3086, 0.3086, 0.3086]]
    """
    from taut.kinematics import as_poses, cable_lengths

    arr, _ = as_poses(robot, poses)
    lengths = np.atleast_2d(cable_lengths(robot, arr))
    if sigma != 0.0:
        sigma = as_number(sigma, "sigma", positive=True)
        lengths = lengths + as_rng(seed).normal(0.0, sigma, lengths.shape)
    pose_arr = arr if known_poses else None
    if offsets is None:
        return measurements(robot, lengths, poses=pose_arr)
    o = as_array(offsets, "offsets", shape=(robot.n_cables,))
    return measurements(robot, changes=lengths - o, poses=pose_arr)
