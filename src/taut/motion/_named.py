"""The named trajectories of a robot file (``trajectories:``), read once for every user.

A robot file names trajectories by waypoints (positions or full poses) with, optionally, the
increments of each straight move (``steps``: pose sequences, Lieskovský 2020, §4.2) or a
``speed`` and a ``dwell`` at each waypoint (waypoint sequences, Rushton 2022, §6.2).
:func:`robot_trajectory` reads one into a :class:`RobotTrajectory`, its waypoints completed
to poses (:func:`~taut.motion._waypoints.complete_waypoints`); the timed motion
(:func:`~taut.motion._trajectory.trajectory_from_robot`), the pose sequences of the collision
checks (:func:`taut.collision.trajectory_poses`) and the sampled moves of the wrapping cables
(:func:`taut.wrapping.builtin_trajectory`) start from it.

References
----------
.. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, §4.2.
   (docs/references.bib: lieskovsky2020)
.. [2] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §6.2. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from taut._results import Result
from taut.errors import TrajectoryError
from taut.model import Robot
from taut.motion._waypoints import complete_waypoints

__all__ = ["RobotTrajectory", "robot_trajectory"]


@dataclass(frozen=True)
class RobotTrajectory(Result):
    """A named trajectory of a robot file (:func:`robot_trajectory`).

    Attributes
    ----------
    name : str
    waypoints : ndarray, shape (N, pose_size)
        Read-only; positions completed to poses.
    steps : tuple of int or None
        The increments of each of the ``N − 1`` moves.
    speed : float or None
        [m/s].
    dwell : float
        [s] at each waypoint.
    description : str or None
        The file's description.

    Examples
    --------
    >>> import taut
    >>> from taut.motion import robot_trajectory
    >>> tr = robot_trajectory(taut.example("adjustable-8cable"), "sim-a")
    >>> tr.waypoints.flags.writeable, tr.as_dict()["steps"]
    (False, [100, 100])
    """

    name: str
    waypoints: np.ndarray
    steps: tuple[int, ...] | None
    speed: float | None
    dwell: float
    description: str | None

    def __post_init__(self) -> None:
        object.__setattr__(self, "waypoints", np.asarray(self.waypoints, dtype=float))
        super().__post_init__()


def robot_trajectory(robot: Robot, name: str | None = None) -> RobotTrajectory:
    """The trajectory ``name`` of ``robot``'s file (its first one when None).

    Parameters
    ----------
    robot : Robot
        The robot; its ``trajectories`` are validated with it (waypoint widths, one step count
        per move).
    name : str, optional
        The trajectory's name.

    Returns
    -------
    RobotTrajectory
        Its waypoints as poses, steps, speed, dwell and description.

    Raises
    ------
    TrajectoryError
        The robot has no trajectory of that name (the message lists those it has), or none.

    Examples
    --------
    >>> import taut
    >>> from taut.motion import robot_trajectory
    >>> tr = robot_trajectory(taut.example("adjustable-8cable"), "sim-a")
    >>> tr.waypoints.shape, tr.steps
    ((3, 7), (100, 100))
    """
    if not robot.trajectories:
        raise TrajectoryError(
            f"{robot.name}: no trajectory {name!r} (it has none)" if name else f"{robot.name} has no trajectories"
        )
    if name is None:
        name = next(iter(robot.trajectories))
    if name not in robot.trajectories:
        raise TrajectoryError(f"{robot.name}: no trajectory {name!r} (it has: {', '.join(robot.trajectories)})")
    tr = robot.trajectories[name]
    waypoints = complete_waypoints(robot, tr.waypoints, what=f"trajectory {name}")
    return RobotTrajectory(
        name=name,
        waypoints=waypoints,
        steps=tr.steps,
        speed=None if tr.speed is None else float(tr.speed),
        dwell=float(tr.dwell),
        description=tr.description,
    )
