"""Views to HTML that opens offline: :func:`write_html` (a page of figures, plotly.js embedded
in it or written once beside it as :data:`PLOTLY_JS`) and :func:`html_fragment` (a figure's
``<div>`` and script, for a page that loads plotly.js itself, as the demo report does).
No CDN is named: the page requests nothing beyond its own directory."""

from __future__ import annotations

import html
import os
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from taut.errors import ArgumentError
from taut.viz.interactive._plotly import plotly_js

if TYPE_CHECKING:
    from plotly.graph_objects import Figure

__all__ = ["PLOTLY_JS", "html_fragment", "write_html", "write_plotly_js"]

#: The file name of plotly.js written beside a page that shares it.
PLOTLY_JS = "plotly.min.js"

#: plotly's configuration of every view: no plotly logo, the figure fills its page's width.
CONFIG = {"displaylogo": False, "responsive": True}


def html_fragment(fig: Figure, *, div_id: str | None = None) -> str:
    """The ``<div>`` of ``fig`` and the script drawing it, without plotly.js.

    Parameters
    ----------
    fig : plotly.graph_objects.Figure
    div_id : str, optional
        The ``id`` of the ``<div>`` (default: a random one).

    Returns
    -------
    str

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.viz.interactive import html_fragment, view_robot
    >>> text = html_fragment(view_robot(example("planar-4cable")), div_id="robot")
    >>> 'id="robot"' in text, "Plotly.newPlot" in text, "http" in text
    (True, True, False)
    """
    # no auto-play: plotly would otherwise run through every frame as the page opens
    return str(fig.to_html(full_html=False, include_plotlyjs=False, div_id=div_id, config=CONFIG, auto_play=False))


def write_plotly_js(directory: str | os.PathLike[str]) -> Path:
    """Write :data:`PLOTLY_JS` into ``directory`` unless the same file is already there.

    Parameters
    ----------
    directory : str or os.PathLike
        An existing directory.

    Returns
    -------
    Path
        The path of the file.

    Examples
    --------
    >>> import tempfile
    >>> from taut.viz.interactive import write_plotly_js
    >>> with tempfile.TemporaryDirectory() as d:
    ...     write_plotly_js(d).stat().st_size > 1_000_000
    True
    """
    path = Path(directory) / PLOTLY_JS
    text = plotly_js().encode("utf-8")
    if not (path.is_file() and path.stat().st_size == len(text) and path.read_bytes() == text):
        path.write_bytes(text)
    return path


def write_html(
    figures: Figure | Sequence[Figure],
    path: str | os.PathLike[str],
    *,
    title: str = "taut",
    plotlyjs: str = "embed",
) -> Path:
    """Write ``figures`` into one HTML page at ``path`` that opens offline.

    Parameters
    ----------
    figures : Figure or sequence of Figure
        Drawn one below the other.
    path : str or os.PathLike
        The page; its directory must exist.
    title : str, default "taut"
    plotlyjs : {"embed", "beside"}, default "embed"
        ``"embed"``: plotly.js inside the page (one file, about 5 MB more);
        ``"beside"``: :data:`PLOTLY_JS` written once into the page's directory and loaded from
        there, shared by every page of the directory.

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    ArgumentError
        Another ``plotlyjs``, no figure, or a directory that does not exist.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> from taut.model import example
    >>> from taut.viz.interactive import view_robot, write_html
    >>> with tempfile.TemporaryDirectory() as d:
    ...     page = write_html(view_robot(example("spatial-8cable")), pathlib.Path(d) / "robot.html", plotlyjs="beside")
    ...     sorted(p.name for p in page.parent.iterdir())
    ['plotly.min.js', 'robot.html']
    """
    if plotlyjs not in ("embed", "beside"):
        raise ArgumentError(f"plotlyjs must be 'embed' or 'beside', got {plotlyjs!r}")
    figs = [figures] if not isinstance(figures, Sequence) else list(figures)
    if not figs:
        raise ArgumentError("write_html needs at least one figure")
    out = Path(path)
    if not out.parent.is_dir():
        raise ArgumentError(f"write_html: the directory {str(out.parent)!r} does not exist")
    if plotlyjs == "beside":
        write_plotly_js(out.parent)
        script = f'<script src="{PLOTLY_JS}" charset="utf-8"></script>'
    else:
        script = f'<script type="text/javascript">{plotly_js()}</script>'
    body = "\n".join(html_fragment(f) for f in figs)
    page = (
        '<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n'
        f"<title>{html.escape(title)}</title>\n{script}\n</head>\n<body>\n{body}\n</body>\n</html>\n"
    )
    out.write_text(page, encoding="utf-8")
    return out
