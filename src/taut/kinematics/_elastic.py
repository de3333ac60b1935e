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
    """Unstretched length ``l0`` that stretches to ``lengths`` under ``tensions`` with axial
    stiffness ``stiffness = EA`` (arrays broadcast).

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, Eq. 2.15. (docs/references.bib: rushton2022)
    """
    l, t, ea = _arrays((lengths, "lengths"), (tensions, "tensions"), (stiffness, "stiffness"))
    if np.any(t < 0):
        raise TautError("cable tensions must be non-negative")
    return l / (1.0 + t / ea)


def tension_from_stretch(lengths: npt.ArrayLike, unstretched: npt.ArrayLike, stiffness: npt.ArrayLike) -> np.ndarray:
    """Eq. (2.15): tension of a cable of unstretched length ``l0`` stretched to ``l``;
    a cable shorter than ``l0`` is slack (tension 0).

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, Eq. 2.15. (docs/references.bib: rushton2022)
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
    """The ``EA`` of every cable of ``robot``; a clear error if one is missing."""
    missing = [i for i, c in enumerate(robot.cables, 1) if c.stiffness is None]
    if missing:
        raise TautError(f"{robot.name}: cables {missing} have no axial stiffness (field `stiffness`, EA in N)")
    return np.array([c.stiffness for c in robot.cables], dtype=float)
