"""Names a package re-exports but imports on first use (PEP 562), so that importing the
package does not load the heavy libraries (pydantic, Numba, HiGHS) behind them: every
``taut`` command starts without paying for what it does not use."""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterable, Mapping
from importlib import import_module


def lazy_exports(
    package: str, sources: Mapping[str, str], public: Iterable[str]
) -> tuple[Callable[[str], object], Callable[[], list[str]]]:
    """The module-level ``__getattr__`` and ``__dir__`` of ``package``: a name of
    ``sources`` is imported from the module ``sources[name]`` on first access and kept in
    the package's namespace; ``dir()`` lists the loaded names and ``public``."""
    namespace = vars(sys.modules[package])
    listed = set(public)

    def getattr_(name: str) -> object:
        if name not in sources:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        value = getattr(import_module(sources[name]), name)
        namespace[name] = value
        return value

    def dir_() -> list[str]:
        return sorted(set(namespace) | listed)

    return getattr_, dir_
