"""Typed exceptions (``docs/architecture.md`` §2.7).

Every error caused by the caller's input derives from :class:`TautError`, and
:class:`TautError` derives from :class:`ValueError`, as scikit-learn's errors do: a caller
who catches ``ValueError`` catches taut's bad-input errors too.  No public function raises a
bare ``ValueError`` or ``TypeError`` for bad input.  The command line turns a
:class:`TautError` into one message and exit status 2; any other exception (a bare
``ValueError`` from a library included) is a bug, exit status 1.

The subclasses name what is wrong with the input: a robot file, a pose, a set of cables, a
robot the analysis does not take, a grid or a trajectory; :class:`ArgumentError` is the error
of the functions that take no robot (pure math and drawing: ``taut.geometry``,
``taut.interval``, ``taut.viz``), whose arguments can only be of the wrong shape, kind or
value.  Some packages add their own (``taut.dynamics.IntegrationError``).
"""

__all__ = [
    "ArgumentError",
    "CableSetError",
    "GridSizeError",
    "InfeasiblePoseError",
    "PoseError",
    "RobotFileError",
    "SingularConfigurationError",
    "TautError",
    "TrackingLostError",
    "TrajectoryError",
    "UnreachableLengthsError",
    "UnsupportedRobotError",
    "WrappedCableError",
]


class TautError(ValueError):
    """Bad input to taut: a malformed file, an impossible pose, unreachable lengths.

    A :class:`ValueError`, so that ``except ValueError`` catches it too.

    Examples
    --------
    >>> import taut
    >>> issubclass(taut.TautError, ValueError)
    True
    """


class RobotFileError(TautError):
    """A robot description that cannot be read or does not validate."""


class PoseError(TautError):
    """A pose of the wrong size, non-finite, or outside joint limits."""


class InfeasiblePoseError(PoseError):
    """A pose at which the requested quantity does not exist (e.g. a zero-length cable)."""


class WrappedCableError(InfeasiblePoseError):
    """A pose at which a cable of a variable-structure robot, taken as a straight line from its
    exit, meets one of the robot's obstacles: the cable wraps around it there, and its wrapped
    length and direction depend on the motion that led to the pose (``taut.wrapping`` follows
    them along a trajectory), so that no single-pose analysis answers."""


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


class ArgumentError(TautError):
    """An argument that a function taking no robot (pure math and drawing: ``taut.geometry``,
    ``taut.interval``, ``taut.viz``) does not take: an array of the wrong shape or of a size
    that does not match another, an unknown option value (a method, a bisection rule, an
    orientation convention), a count out of range, axes of the wrong kind (2-D for a 3-D
    drawing or the reverse) or a figure that is not empty."""


class TautWarning(UserWarning):
    """Something the caller should know that is not an error: a part of a file taut leaves
    out (a CASPR trajectory of a kind it does not read) while reading the rest."""
