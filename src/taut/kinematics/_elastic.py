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
    l, t, ea = (np.asarray(x, dtype=float) for x in (lengths, tensions, stiffness))
    if np.any(ea <= 0) or not np.all(np.isfinite(ea)):
        raise TautError("axial stiffness EA must be positive and finite")
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
    l, l0, ea = (np.asarray(x, dtype=float) for x in (lengths, unstretched, stiffness))
    return np.maximum(ea * (l - l0) / l0, 0.0)


def robot_stiffness(robot: Robot) -> np.ndarray:
    """The ``EA`` of every cable of ``robot``; a clear error if one is missing."""
    missing = [i for i, c in enumerate(robot.cables, 1) if c.stiffness is None]
    if missing:
        raise TautError(f"{robot.name}: cables {missing} have no axial stiffness (field `stiffness`, EA in N)")
    return np.array([c.stiffness for c in robot.cables], dtype=float)
