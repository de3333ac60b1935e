"""The browser suite (marker ``browser``, ``make test-browser``): the pages taut writes, opened
in headless Chromium — Debian's own, driven by playwright (whose own browser download is not
used) — with the network cut off.

The pages are written once per session by the command line, in subprocesses: the demo report
and one ``taut view`` file per kind.  Without playwright or without Chromium every test skips
and says which is missing; ``make test-browser`` installs both where it can.
"""

from __future__ import annotations

import io
import os
import shutil
import time
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from conftest import run_taut

#: Where Chromium may be: ``TAUT_CHROMIUM``, then Debian's and others' names on the PATH.
CHROMIUM_NAMES = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")

#: Chromium's switches here: no sandbox (CI runs as root), WebGL on the CPU (no GPU).
CHROMIUM_ARGS = ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader"]


def chromium() -> str:
    path = os.environ.get("TAUT_CHROMIUM") or next(filter(None, map(shutil.which, CHROMIUM_NAMES)), None)
    if not path:
        pytest.skip("no Chromium on this machine (apt-get install chromium; make test-browser installs it as root)")
    return path


@pytest.fixture(scope="session")
def browser() -> Iterator[Any]:
    sync = pytest.importorskip(
        "playwright.sync_api", reason="playwright is not installed (pip install 'taut[browser]')"
    )
    path = chromium()
    with sync.sync_playwright() as p:
        b = p.chromium.launch(executable_path=path, args=CHROMIUM_ARGS)
        yield b
        b.close()


@dataclass
class Page:
    """A page opened offline: its playwright page, what it requested and what it logged."""

    page: Any
    requests: list[str] = field(default_factory=list)
    errors: list[str] = field(default_factory=list)
    open_s: float = 0.0

    def plots(self) -> int:
        return int(self.page.evaluate("document.querySelectorAll('.js-plotly-plot').length"))

    def data(self, div: int, name: str, key: str) -> list[Any]:
        """What the ``div``-th plot shows of its first trace named ``name`` (plotly.js's
        ``_fullData``, where the arrays are decoded), as numbers."""
        return list(
            self.page.evaluate(
                "([div, name, key]) => { const gd = document.querySelectorAll('.js-plotly-plot')[div];"
                " const t = gd._fullData.find(t => t.name === name); return Array.from(t[key]); }",
                [div, name, key],
            )
        )

    def scene_pixels(self, div: int, scene: str = "scene") -> np.ndarray:
        """A screenshot of one 3-D scene of the ``div``-th plot, as an RGB array."""
        from PIL import Image

        plot = self.page.locator(".js-plotly-plot").nth(div)
        plot.scroll_into_view_if_needed()
        box = plot.bounding_box()
        dom = self.page.evaluate(
            "([div, scene]) => { const L = document.querySelectorAll('.js-plotly-plot')[div]._fullLayout;"
            " const s = L[scene].domain, z = L._size;"
            " return [z.l + s.x[0] * z.w, z.t + (1 - s.y[1]) * z.h, (s.x[1] - s.x[0]) * z.w, (s.y[1] - s.y[0]) * z.h]; }",
            [div, scene],
        )
        clip = dict(x=box["x"] + dom[0], y=box["y"] + dom[1], width=dom[2], height=dom[3])
        png = self.page.screenshot(clip=clip)
        return np.asarray(Image.open(io.BytesIO(png)).convert("RGB"))


@pytest.fixture(scope="session")
def open_page(browser: Any) -> Iterator[Any]:
    """``open_page(path)``: the page at ``path`` in a context without network, once every
    plot on it is drawn; its requests, console errors and opening time recorded."""
    contexts = []

    def opener(path: Path, *, width: int = 1280, height: int = 1000) -> Page:
        ctx = browser.new_context(offline=True, viewport={"width": width, "height": height})
        contexts.append(ctx)
        page = Page(ctx.new_page())
        page.page.on("request", lambda r: page.requests.append(r.url))
        page.page.on("console", lambda m: page.errors.append(f"{m.text} ({m.location})") if m.type == "error" else None)
        page.page.on("pageerror", lambda e: page.errors.append(str(e)))
        start = time.perf_counter()
        page.page.goto(path.resolve().as_uri(), timeout=300_000)
        page.page.wait_for_function(
            "() => { const ds = document.querySelectorAll('.js-plotly-plot');"
            " return ds.length > 0 && Array.from(ds).every(d => d._fullLayout && d._fullLayout._size); }",
            polling=20,
            timeout=300_000,
        )
        page.open_s = time.perf_counter() - start
        return page

    yield opener
    for ctx in contexts:
        ctx.close()


@pytest.fixture(scope="session")
def pages(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    """One ``taut view`` page per kind, and the inputs they were drawn from, written by the
    command line; the motion views share plotly.js, as the issue measures them."""
    d = tmp_path_factory.mktemp("views")

    def taut(*argv: str) -> dict:
        return run_taut(*argv, "--json").json()

    out: dict[str, Path] = {}
    fk = d / "fk.json"
    fk.write_text(run_taut("fk", "suspended-3cable", "--json").out)
    out["fk.json"] = fk
    traj = d / "vscr-t-shaped.csv"
    taut("trajectory", "vscr-t-shaped", "--out", str(traj))
    out["trajectory.csv"] = traj
    sim = d / "sim.csv"
    taut("simulate", "spatial-8cable", "--waypoints=0,0,0;0.2,0.1,0.1", "--duration", "1", "--out", str(sim))
    boxes = d / "boxes.json"
    taut("workspace", "planar-4cable", "--condition", "static", "--certified", "--eps", "0.02", "--out", str(boxes))
    plan = d / "plan.csv"
    taut("plan", "robocrane", "--start", "q1", "--goal", "q2", "--fix", "x=0,y=0,z=2,sigma=35deg", "--out", str(plan))
    views = {
        "robot": ["adjustable-8cable"],
        "solutions": ["suspended-3cable", "--solutions", str(fk)],
        "trajectory": ["vscr-t-shaped", "--trajectory", str(traj)],
        "control": ["spatial-8cable", "--trajectory", str(sim)],
        "workspace": ["planar-4cable", "--workspace", str(boxes), "--pose", "0,0,0"],
        "plan": ["robocrane", "--plan", str(plan)],
    }
    for kind, argv in views.items():
        page = d / f"{kind}.html"
        taut("view", *argv, "--out", str(page), "--plotlyjs", "beside")
        out[kind] = page
    return out


@pytest.fixture(scope="session")
def report(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The demo report, written by ``taut demo`` (a few minutes)."""
    d = tmp_path_factory.mktemp("report")
    run_taut("demo", "--out", str(d), "--json", timeout=1800).json()
    return d / "index.html"
