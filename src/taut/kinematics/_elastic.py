"""Elastic cables: the linear spring model of Eq. (2.15) of Rushton (2022),
``τ = EA (l − l0) / l0``, solved for the unstretched length ``l0 = EA l / (EA + τ)``.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §2.1.6, Eq. 2.15. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from taut.errors import TautError
from taut.model import Robot


def unstretched_length(lengths: npt.ArrayLike, tensions: npt.ArrayLike, stiffness: npt.ArrayLike) -> np.ndarray:
    """The unstretched length ``l0 = EA l / (EA + τ)`` that stretches to ``l`` under ``τ``.

    Parameters
    ----------
    lengths : array_like
        Stretched lengths ``l`` [m].
    tensions : array_like
        Tensions ``τ`` [N], non-negative.
    stiffness : array_like
        Axial stiffness ``EA`` [N], positive.  The three arrays broadcast together.

    Returns
    -------
    ndarray
        ``l0`` [m], of the broadcast shape.

    Raises
    ------
    TautError
        Values that are not finite numbers, a negative tension, a non-positive stiffness, or
        arrays that do not broadcast.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, Eq. 2.15. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> from taut.kinematics import unstretched_length
    >>> float(unstretched_length(2.0, 100.0, 1e4))  # 2 m / 1.01
    1.9801980198019802
    """
    l, t, ea = _arrays((lengths, "lengths"), (tensions, "tensions"), (stiffness, "stiffness"))
    if np.any(t < 0):
        raise TautError("cable tensions must be non-negative")
    return l / (1.0 + t / ea)


def tension_from_stretch(lengths: npt.ArrayLike, unstretched: npt.ArrayLike, stiffness: npt.ArrayLike) -> np.ndarray:
    """The tension ``τ = EA (l − l0) / l0`` of a cable stretched from ``l0`` to ``l``.

    A cable shorter than ``l0`` is slack: its tension is 0.

    Parameters
    ----------
    lengths : array_like
        Lengths ``l`` [m].
    unstretched : array_like
        Unstretched lengths ``l0`` [m], positive.
    stiffness : array_like
        Axial stiffness ``EA`` [N], positive.  The three arrays broadcast together.

    Returns
    -------
    ndarray
        Tensions [N], of the broadcast shape.

    Raises
    ------
    TautError
        Values that are not finite numbers, a non-positive ``l0`` or stiffness, or arrays that
        do not broadcast.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, Eq. 2.15. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> from taut.kinematics import tension_from_stretch
    >>> tension_from_stretch([2.0, 1.9], 1.98, 1e4).round(2)  # the second cable is slack
    array([101.01,   0.  ])
    """
    l, l0, ea = _arrays((lengths, "lengths"), (unstretched, "unstretched lengths"), (stiffness, "stiffness"))
    if np.any(l0 <= 0):
        raise TautError("unstretched lengths must be positive")
    return np.maximum(ea * (l - l0) / l0, 0.0)


def _arrays(*named: tuple[npt.ArrayLike, str]) -> list[np.ndarray]:
    """The arrays of ``named`` (value, name), finite and broadcast together; the last is the
    axial stiffness, which must be positive."""
    out = []
    for value, what in named:
        try:
            arr = np.asarray(value, dtype=float)
        except (TypeError, ValueError):
            raise TautError(f"{what} must be numbers, got {value!r}") from None
        if not np.all(np.isfinite(arr)):
            raise TautError(f"{what} must be finite, got {arr.tolist()}")
        out.append(arr)
    if np.any(out[-1] <= 0):
        raise TautError("axial stiffness EA must be positive and finite")
    try:
        return list(np.broadcast_arrays(*out))
    except ValueError:
        shapes = ", ".join(f"{what} {np.shape(a)}" for a, (_, what) in zip(out, named))
        raise TautError(f"the arrays do not broadcast together: {shapes}") from None


def robot_stiffness(robot: Robot) -> np.ndarray:
    """The axial stiffness ``EA`` of every cable of a robot (``cables[].stiffness``).

    Parameters
    ----------
    robot : Robot

    Returns
    -------
    ndarray, shape (n,)
        ``EA`` [N] of each cable.

    Raises
    ------
    TautError
        A cable without a stiffness (named by its 1-based number).

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.kinematics import robot_stiffness
    >>> robot = example("planar-4cable")
    >>> robot = robot.model_copy(update={"cables": tuple(c.model_copy(update={"stiffness": 2e4}) for c in robot.cables)})
    >>> robot_stiffness(robot)
    array([20000., 20000., 20000., 20000.])
    """
    missing = [i for i, c in enumerate(robot.cables, 1) if c.stiffness is None]
    if missing:
        raise TautError(f"{robot.name}: cables {missing} have no axial stiffness (field `stiffness`, EA in N)")
    return np.array([c.stiffness for c in robot.cables], dtype=float)
