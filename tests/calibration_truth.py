"""Synthetic calibration trials for the tests: a nominal robot perturbed into a "built" one, its
cable lengths at random poses computed here with plain NumPy norms (never through taut's
kinematics), and the truth expressed in the gauge of the estimate (an SVD alignment written
here)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from axis_rotations import rx, ry, rz

from taut.calibration import calibrate, measurements
from taut.model import Robot

#: Perturbations of the issue: exits up to 5 cm, offsets up to 10 cm around 1 m.
EXIT_ERROR = 0.05
OFFSET_ERROR = 0.10
NOMINAL_OFFSET = 1.0


def rotation(robot: Robot, pose: np.ndarray) -> np.ndarray:
    """The platform rotation of ``pose`` (xyz-fixed, or the planar angle)."""
    if robot.is_point_mass:
        return np.eye(robot.dimension)
    if robot.dimension == 2:
        c, s = math.cos(pose[2]), math.sin(pose[2])
        return np.array([[c, -s], [s, c]])
    assert robot.orientation == "xyz-fixed"
    a, b, c = pose[3:6]
    return rz(c) @ ry(b) @ rx(a)


def lengths(robot: Robot, exits: np.ndarray, anchors: np.ndarray, poses: np.ndarray) -> np.ndarray:
    """``‖a_i − (p + R r_i)‖`` for every pose and cable."""
    d = robot.dimension
    out = np.empty((len(poses), robot.n_cables))
    for k, q in enumerate(poses):
        R = rotation(robot, q)
        for i in range(robot.n_cables):
            out[k, i] = np.linalg.norm(exits[i] - q[:d] - R @ anchors[i])
    return out


def align(source: np.ndarray, target: np.ndarray) -> np.ndarray:
    """``source`` moved by the proper rigid motion that best fits it onto ``target``."""
    cs, ct = source.mean(axis=0), target.mean(axis=0)
    H = (source - cs).T @ (target - ct)
    U, _, Vt = np.linalg.svd(H)
    D = np.eye(len(H))
    D[-1, -1] = np.sign(np.linalg.det(Vt.T @ U.T))
    Q = Vt.T @ D @ U.T
    return (source - cs) @ Q.T + ct


def random_poses(robot: Robot, rows: int, rng: np.random.Generator, box: np.ndarray, angle: float = 0.2) -> np.ndarray:
    d = robot.dimension
    poses = np.zeros((rows, robot.pose_size))
    poses[:, :d] = rng.uniform(box[:, 0], box[:, 1], (rows, d))
    poses[:, d:] = rng.uniform(-angle, angle, (rows, robot.pose_size - d))
    return poses


@dataclass
class Trial:
    z: np.ndarray  #: (estimate − truth) / std of every estimated parameter
    error: np.ndarray  #: estimate − truth
    result: object
    corrupted: np.ndarray  #: rows given an outlier


def trial(
    robot: Robot,
    seed: int,
    box: np.ndarray,
    *,
    rows: int = 40,
    sigma: float = 5e-4,
    known_poses: bool = False,
    outliers: float = 0.0,
    robust: str | None = None,
) -> Trial:
    """One synthetic calibration of ``robot`` perturbed with ``seed``: length changes (offsets
    unknown) at ``rows`` random poses in ``box``, Gaussian noise ``sigma``, a fraction
    ``outliers`` of the rows corrupted by 10 cm on one cable."""
    rng = np.random.default_rng(seed)
    n = robot.n_cables
    exits = robot.exits + rng.uniform(-EXIT_ERROR, EXIT_ERROR, robot.exits.shape)
    offsets = NOMINAL_OFFSET + rng.uniform(-OFFSET_ERROR, OFFSET_ERROR, n)
    poses = random_poses(robot, rows, rng, box)
    dl = lengths(robot, exits, robot.anchors, poses) - offsets + rng.normal(0.0, sigma, (rows, n))
    corrupted = rng.choice(rows, int(round(outliers * rows)), replace=False) if outliers else np.zeros(0, int)
    for k in corrupted:
        dl[k, rng.integers(n)] += 0.1
    data = measurements(robot, changes=dl, poses=poses if known_poses else None)
    res = calibrate(robot, data, robust=robust)
    truth = exits if known_poses else align(exits, robot.exits)
    error = np.concatenate([(res.exits - truth).ravel(), res.offsets - offsets])
    std = np.concatenate([res.exits_std.ravel(), res.offsets_std])
    return Trial(error / std, error, res, np.sort(corrupted))
