"""Trajectories in pose space (joint space included for jointed platforms): point-to-point and
multi-waypoint, with cubic, quintic, trapezoidal or linear time laws, sampled at any rate with
velocity, acceleration and angular rates (``docs/architecture.md`` §1, layer 2)."""

from taut.motion.caspr import CasprTrajectories, CasprTrajectory, read_caspr_trajectories
from taut.motion.laws import LAWS
from taut.motion.named import RobotTrajectory, robot_trajectory
from taut.motion.trajectory import ROTATIONS, Motion, MotionSamples, trajectory_from_robot, trajectory_from_waypoints
from taut.motion.vias import VIAS
from taut.motion.waypoints import complete_waypoints, unwrap_angles

__all__ = [
    "LAWS",
    "ROTATIONS",
    "VIAS",
    "CasprTrajectories",
    "CasprTrajectory",
    "Motion",
    "MotionSamples",
    "RobotTrajectory",
    "complete_waypoints",
    "read_caspr_trajectories",
    "robot_trajectory",
    "trajectory_from_robot",
    "trajectory_from_waypoints",
    "unwrap_angles",
]
