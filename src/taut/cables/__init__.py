"""Sagging cables: Irvine's elastic catenary for one cable, vectorised over many (end
forces, unstrained lengths, shape and sag), and the statics of robots whose cables sag
(static inverse kinematics with the tension distribution iterated to consistency; static
forward kinematics by Newton continuation from the straight-cable pose, with stability)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports

if TYPE_CHECKING:
    from taut.cables._forward import SaggingFKResult, sagging_fk
    from taut.cables._inverse import MAX_SAG_STEPS, SAG_TOL, TAUT_WEIGHTS, SaggingIKResult, sagging_ik
    from taut.cables._sagging import (
        Catenary,
        catenary_forces,
        catenary_lengths,
        catenary_shape,
        catenary_tensions,
    )

#: Every name is imported on first use (PEP 562), so that importing the package loads nothing heavy.
_LAZY = {
    "SaggingFKResult": "taut.cables._forward",
    "sagging_fk": "taut.cables._forward",
    "MAX_SAG_STEPS": "taut.cables._inverse",
    "SAG_TOL": "taut.cables._inverse",
    "TAUT_WEIGHTS": "taut.cables._inverse",
    "SaggingIKResult": "taut.cables._inverse",
    "sagging_ik": "taut.cables._inverse",
    "Catenary": "taut.cables._sagging",
    "catenary_forces": "taut.cables._sagging",
    "catenary_lengths": "taut.cables._sagging",
    "catenary_shape": "taut.cables._sagging",
    "catenary_tensions": "taut.cables._sagging",
}

__all__ = [
    "Catenary",
    "MAX_SAG_STEPS",
    "SAG_TOL",
    "SaggingFKResult",
    "SaggingIKResult",
    "TAUT_WEIGHTS",
    "catenary_forces",
    "catenary_lengths",
    "catenary_shape",
    "catenary_tensions",
    "sagging_fk",
    "sagging_ik",
]

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
