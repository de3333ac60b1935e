"""A small self-contained HTML report: :class:`Report`.

A report is a title and a list of sections; each section may hold paragraphs of text,
figures (saved as PNG next to ``index.html`` and linked relatively), interactive views
(plotly figures of :mod:`taut.viz.interactive`, drawn in the page beside the PNGs, which stay
for print), a table (a list of dict rows) and a JSON block.  ``Report.write(out_dir)``
writes ``index.html`` (one file, its CSS inline, every text HTML-escaped), the PNGs and,
when there are views, plotly.js once beside them, so that the report opens offline.  Figures
are rendered to PNG (dpi 110) and closed as soon as they are added, so that a long report does
not keep them open.
No figure of the sources is imitated here.
"""

from __future__ import annotations

import html
import io
import json
import math
import os
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING
from urllib.parse import quote

import numpy as np

from taut.errors import ArgumentError
from taut.viz.interactive import PLOTLY_JS

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure, SubFigure
    from plotly.graph_objects import Figure as PlotlyFigure

__all__ = ["Report"]

DPI = 110

_CSS = """
body { font-family: system-ui, -apple-system, "Segoe UI", Helvetica, Arial, sans-serif; margin: 0 auto;
       max-width: 1100px; padding: 1.5em 2em 3em; color: #222; line-height: 1.45; }
h1 { font-size: 1.7em; margin-bottom: 0.2em; }
h2 { font-size: 1.25em; margin-top: 2em; border-bottom: 1px solid #ddd; padding-bottom: 0.2em; }
.meta { color: #777; font-size: 0.9em; margin-top: 0; }
nav ol { padding-left: 1.4em; } nav a { text-decoration: none; }
.figures { display: flex; flex-wrap: wrap; gap: 1.2em; align-items: flex-start; }
figure { margin: 0; max-width: 100%; }
figure img { max-width: 100%; max-height: 560px; border: 1px solid #eee; }
figcaption { font-size: 0.9em; color: #555; text-align: center; }
figure.view { width: 100%; border: 1px solid #eee; }
table { border-collapse: collapse; font-size: 0.92em; margin: 0.8em 0; }
th, td { border: 1px solid #ddd; padding: 0.25em 0.6em; }
th { background: #f4f4f4; text-align: left; } td.num { text-align: right; font-variant-numeric: tabular-nums; }
pre { background: #f7f7f7; border: 1px solid #e5e5e5; padding: 0.7em; overflow-x: auto; font-size: 0.85em; }
"""


@dataclass
class _Figure:
    filename: str
    caption: str
    png: bytes


@dataclass
class _Section:
    title: str
    text: str | None = None
    figures: list[_Figure] = field(default_factory=list)
    table: list[dict[str, object]] | None = None
    json: object = None
    views: list[tuple[str, str]] = field(default_factory=list)  #: (HTML of the figure, caption)


def _jsonable(obj: object) -> object:
    """JSON form of the values ``json.dumps`` does not take (NumPy, paths, sets); ``repr`` else."""
    if isinstance(obj, np.ndarray):
        return obj.tolist()
    if isinstance(obj, np.generic):
        return obj.item()
    if isinstance(obj, Path):
        return str(obj)
    if isinstance(obj, (set, frozenset)):
        return sorted(obj, key=str)
    return repr(obj)


def _cell(v: object) -> tuple[str, bool]:
    """(escaped text, is_number) of a table cell."""
    if isinstance(v, np.generic):
        v = v.item()
    if v is None:
        return "", False
    if isinstance(v, bool):
        return ("yes" if v else "no"), False
    if isinstance(v, int):
        return str(v), True
    if isinstance(v, float):
        return (f"{v:.4g}" if math.isfinite(v) else str(v)), True
    return html.escape(str(v)), False


def _png(drawing: Figure | SubFigure | Axes) -> bytes:
    """PNG of a figure (of a sub-figure or an ``Axes``: of the whole figure it is in), which
    is then closed."""
    import matplotlib.pyplot as plt
    from matplotlib.axes import Axes
    from matplotlib.figure import SubFigure

    placed = drawing.figure if isinstance(drawing, Axes) else drawing
    fig = placed.figure if isinstance(placed, SubFigure) else placed  # a sub-figure's figure is the root one
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=DPI, bbox_inches="tight")
    plt.close(fig)
    return buf.getvalue()


def _slug(text: str, used: set[str]) -> str:
    base = re.sub(r"[^a-z0-9]+", "-", text.lower()).strip("-") or "section"
    slug, k = base, 2
    while slug in used:
        slug, k = f"{base}-{k}", k + 1
    used.add(slug)
    return slug


class Report:
    """An HTML report under construction: ``add_section`` then ``write``."""

    def __init__(self, title: str) -> None:
        self.title = str(title)
        self.sections: list[_Section] = []
        self._files: set[str] = set()
        self._views = 0

    def add_section(
        self,
        title: str,
        text: str | None = None,
        figures: Iterable[tuple[Figure | SubFigure | Axes, str] | tuple[Figure | SubFigure | Axes, str, str | None]]
        | None = None,
        table: Iterable[Mapping[str, object]] | None = None,
        json: object = None,
        views: Iterable[tuple[PlotlyFigure, str]] | None = None,
    ) -> None:
        """Append a section.

        ``text``: paragraphs separated by blank lines (plain text, escaped).  ``figures``:
        ``(Figure, filename, caption)`` tuples (caption optional; a sub-figure or an ``Axes``
        stands for its whole figure); each figure is rendered to
        PNG and closed now; ``filename`` is a plain file name (``.png`` added if missing),
        unique in the report.  ``table``: a list of dict rows (columns in order of first
        appearance).  ``json``: any JSON-serialisable value (NumPy values accepted).
        ``views``: ``(plotly Figure, caption)`` pairs, interactive views drawn in the page
        (the ``view`` extra).
        A figure item of another length or a file name that is not plain or is used twice
        raises :class:`~taut.errors.ArgumentError`."""
        figs = []
        for item in figures or []:
            if not isinstance(item, (tuple, list)) or len(item) not in (2, 3):
                raise ArgumentError("a report figure is (figure, filename) or (figure, filename, caption)")
            fig, name = item[0], str(item[1])
            caption = str(item[2]) if len(item) == 3 and item[2] is not None else ""
            if not name or Path(name).name != name or name.startswith(".") or "\\" in name:
                raise ArgumentError(f"report figure file name must be a plain file name, got {name!r}")
            if not name.lower().endswith(".png"):
                name += ".png"
            if name in self._files or name == "index.html":
                raise ArgumentError(f"report figure file name {name!r} is used twice")
            self._files.add(name)
            figs.append(_Figure(name, caption, _png(fig)))
        rows = None
        if table is not None:
            rows = [dict(r) for r in table]
        shown = []
        for view, caption in views or []:
            from taut.viz.interactive import html_fragment

            self._views += 1
            shown.append((html_fragment(view, div_id=f"view-{self._views}"), str(caption)))
        self.sections.append(_Section(str(title), None if text is None else str(text), figs, rows, json, shown))

    # ---- rendering -----------------------------------------------------------------
    def _section_html(self, s: _Section, slug: str) -> str:
        out = [f'<section id="{slug}">', f"<h2>{html.escape(s.title)}</h2>"]
        if s.text:
            for para in re.split(r"\n\s*\n", s.text.strip()):
                out.append(f"<p>{html.escape(para)}</p>")
        if s.figures:
            out.append('<div class="figures">')
            for f in s.figures:
                src = html.escape(quote(f.filename))
                alt = html.escape(f.caption or f.filename)
                out.append(f'<figure><a href="{src}"><img src="{src}" alt="{alt}"></a>')
                if f.caption:
                    out.append(f"<figcaption>{html.escape(f.caption)}</figcaption>")
                out.append("</figure>")
            out.append("</div>")
        for view, caption in s.views:
            out.append(f'<figure class="view">{view}<figcaption>{html.escape(caption)}</figcaption></figure>')
        if s.table:
            cols: list[str] = []
            for r in s.table:
                cols += [str(k) for k in r if str(k) not in cols]
            out.append(
                "<table><thead><tr>" + "".join(f"<th>{html.escape(c)}</th>" for c in cols) + "</tr></thead><tbody>"
            )
            for r in s.table:
                cells = {str(k): v for k, v in r.items()}
                tds = []
                for c in cols:
                    text, num = _cell(cells.get(c))
                    tds.append(f'<td class="num">{text}</td>' if num else f"<td>{text}</td>")
                out.append("<tr>" + "".join(tds) + "</tr>")
            out.append("</tbody></table>")
        if s.json is not None:
            text = json.dumps(s.json, indent=2, default=_jsonable)
            out.append(f'<pre><code class="json">{html.escape(text)}</code></pre>')
        out.append("</section>")
        return "\n".join(out)

    def html(self) -> str:
        """The text of ``index.html``."""
        from taut import __version__

        used: set[str] = set()
        slugs = [_slug(s.title, used) for s in self.sections]
        nav = "".join(f'<li><a href="#{g}">{html.escape(s.title)}</a></li>' for s, g in zip(self.sections, slugs))
        body = "\n".join(self._section_html(s, g) for s, g in zip(self.sections, slugs))
        title = html.escape(self.title)
        return (
            '<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n'
            '<meta name="viewport" content="width=device-width, initial-scale=1">\n'
            f"<title>{title}</title>\n<style>{_CSS}</style>\n"
            + (f'<script src="{PLOTLY_JS}" charset="utf-8"></script>\n' if self._views else "")
            + "</head>\n<body>\n"
            f'<header><h1>{title}</h1><p class="meta">written by taut {html.escape(__version__)}</p></header>\n'
            + (f"<nav><ol>{nav}</ol></nav>\n" if len(self.sections) > 1 else "")
            + body
            + "\n</body>\n</html>\n"
        )

    def write(self, out_dir: str | os.PathLike[str]) -> Path:
        """Write ``index.html`` and the PNGs into ``out_dir`` (created if needed); return
        the path of ``index.html``."""
        out = Path(out_dir)
        out.mkdir(parents=True, exist_ok=True)
        for s in self.sections:
            for f in s.figures:
                (out / f.filename).write_bytes(f.png)
        if self._views:
            from taut.viz.interactive import write_plotly_js

            write_plotly_js(out)
        index = out / "index.html"
        index.write_text(self.html(), encoding="utf-8")
        return index
