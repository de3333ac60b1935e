"""plotly, imported where a view is built: ``import taut`` loads no third-party module, and
without the ``view`` extra the first view says what to install."""

from __future__ import annotations

from types import ModuleType

from taut.errors import TautError

#: The message of a missing plotly, one line, naming the extra.
MISSING = "interactive views need plotly, which is not installed; install the extra: pip install 'taut[view]'"


def graph_objects() -> ModuleType:
    """``plotly.graph_objects``, or a :class:`~taut.errors.TautError` naming the extra to install."""
    try:
        import plotly.graph_objects as go
    except ImportError:
        raise TautError(MISSING) from None
    return go


def plotly_js() -> str:
    """The text of the plotly.js bundle that the installed plotly ships (no CDN is ever named)."""
    graph_objects()
    from plotly.offline import get_plotlyjs

    return str(get_plotlyjs())
