"""Typed exceptions.  Every error caused by the caller's input derives from
:class:`TautError`; the command line turns those into one message and exit status 2."""


class TautError(Exception):
    """Bad input to taut: a malformed file, an impossible pose, unreachable lengths."""


class RobotFileError(TautError):
    """A robot description that cannot be read or does not validate."""


class PoseError(TautError):
    """A pose of the wrong size, non-finite, or outside joint limits."""


class InfeasiblePoseError(PoseError):
    """A pose at which the requested quantity does not exist (e.g. a zero-length cable)."""


class CableSetError(TautError):
    """A set of cable numbers out of range, duplicated, or of a size the analysis does not take."""


class UnsupportedRobotError(TautError):
    """A robot the requested analysis does not handle (e.g. a planar or point-mass platform
    for the spatial geometrico-static problems)."""


class SingularConfigurationError(TautError):
    """A configuration at which the structure matrix or a Jacobian is singular."""


class UnreachableLengthsError(TautError):
    """Cable lengths that no pose of the robot fits."""


class TrackingLostError(TautError):
    """Tracking forward kinematics could not certify the equilibrium that follows the
    previous one (no convergence, or no unique solution proven around the step)."""


class GridSizeError(TautError):
    """A grid of more poses than taut evaluates in memory, or an array of its poses larger
    than it materialises at once."""


class TrajectoryError(TautError):
    """A trajectory that cannot be built or sampled: fewer than two waypoints, waypoints of the
    wrong size or not finite, non-increasing times, a non-positive duration or rate, an
    unknown time law, a sample time outside the trajectory."""


class TautWarning(UserWarning):
    """Something the caller should know that is not an error: a part of a file taut leaves
    out (a CASPR trajectory of a kind it does not read) while reading the rest."""
