"""The ``taut`` command line (``docs/architecture.md`` §4): thin wrappers over the library.

Examples
--------
>>> from taut.cli import main
>>> main(["examples"]) == 0  # doctest: +ELLIPSIS
adjustable-8cable...planar-4cable...
True
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports

if TYPE_CHECKING:
    from taut.cli._main import entry, main

_LAZY = {"entry": "taut.cli._main", "main": "taut.cli._main"}

__all__ = ["entry", "main"]

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
