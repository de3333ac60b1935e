"""Sagging cables: Irvine's elastic catenary for one cable, vectorised over many (end
forces, unstrained lengths, shape and sag)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports

if TYPE_CHECKING:
    from taut.cables._sagging import Catenary, catenary_forces, catenary_lengths, catenary_shape

#: Every name is imported on first use (PEP 562), so that importing the package loads nothing heavy.
_LAZY = {
    "Catenary": "taut.cables._sagging",
    "catenary_forces": "taut.cables._sagging",
    "catenary_lengths": "taut.cables._sagging",
    "catenary_shape": "taut.cables._sagging",
}

__all__ = ["Catenary", "catenary_forces", "catenary_lengths", "catenary_shape"]

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
