"""The pages taut writes, in headless Chromium with the network cut off: they load without a
console error, request nothing but their own files, every 3-D view draws, the slider moves the
robot through the lengths the CSV holds, and the selector switches the equilibria."""

from __future__ import annotations

import csv
import json
import os
import shutil
from pathlib import Path

import numpy as np
import pytest

pytestmark = pytest.mark.browser

ROOT = Path(__file__).resolve().parents[2]

#: The README's screenshot, rewritten by the suite when ``TAUT_SCREENSHOT=1``.
SCREENSHOT = ROOT / "docs" / "taut-view.png"

KINDS = ["robot", "solutions", "trajectory", "control", "workspace", "plan"]

#: The 3-D scenes of each kind of view.
SCENES = {"control": ["scene", "scene2"]}


def drawn(pixels: np.ndarray) -> int:
    """Pixels in colour (cables, platform, boxes): neither white nor the grey of the axes."""
    p = pixels.astype(int)
    return int(((p.max(axis=2) - p.min(axis=2)) > 40).sum())


def only_local(page, directory: Path) -> None:
    assert page.requests, "the page requested nothing, not even itself"
    for url in page.requests:
        assert url.startswith(directory.resolve().as_uri() + "/"), f"a request left the page's directory: {url}"


@pytest.mark.parametrize("kind", KINDS)
def test_view_loads_offline_without_errors_and_draws_every_scene(kind, open_page, pages):
    page = open_page(pages[kind])
    assert page.errors == []
    only_local(page, pages[kind].parent)
    assert page.plots() == 1
    for scene in SCENES.get(kind, ["scene"]):
        pixels = page.scene_pixels(0, scene)
        assert pixels.std() > 5, f"{kind}: the 3-D scene {scene} is uniform"
        assert drawn(pixels) > 300, f"{kind}: the 3-D scene {scene} shows nothing in colour"


def test_moving_the_slider_shows_the_lengths_of_the_csv(open_page, pages):
    page = open_page(pages["trajectory"])
    rows = list(csv.DictReader(pages["trajectory.csv"].open()))
    times = np.array([float(r["time"]) for r in rows])
    n = sum(1 for k in rows[0] if k.startswith("l") and k[1:].isdigit())

    # the lengths shown once the slider has settled: no frame queued, the marker at the
    # step's time (a click on the rail passes through the steps between)
    settled = (
        "([t0, f]) => { const gd = document.querySelector('.js-plotly-plot'), q = gd._transitionData || {};"
        " const m = gd._fullData.find(d => d.name === 'lengths now'), s = gd._fullLayout.sliders[0];"
        " const at = parseFloat(s.steps[s.active].label), x = m.x[0];"
        " if (Math.abs(s.active - Math.round(f * (s.steps.length - 1))) > 3) return null;"
        " if ((q._frameQueue || []).length || q._animationRaf || x === t0 || Math.abs(at - x) > 1e-3 * Math.max(1, x)) return null;"
        " return [x, Array.from(m.y)]; }"
    )

    def shown(t0: float | None = None, fraction: float = 0.0) -> tuple[float, np.ndarray]:
        x, y = page.page.wait_for_function(settled, arg=[t0, fraction], timeout=60_000).json_value()
        return x, np.array(y)

    t0, l0 = shown()
    rail = page.page.locator(".slider-rail-touch-rect").first
    box = rail.bounding_box()
    before = page.scene_pixels(0)
    for fraction in (0.37, 0.81):
        page.page.mouse.click(box["x"] + fraction * box["width"], box["y"] + box["height"] / 2)
        t, lengths = shown(t0, fraction)
        assert t > t0 and not np.allclose(lengths, l0)
        s = int(np.argmin(np.abs(times - t)))
        assert abs(times[s] - t) < 1e-9
        expected = np.array([float(rows[s][f"l{i + 1}"]) for i in range(n)])
        np.testing.assert_allclose(lengths, expected, atol=1e-8)
        t0, l0 = t, lengths
    assert not np.array_equal(page.scene_pixels(0), before), "the 3-D view did not move with the slider"
    assert page.errors == []


def test_the_selector_switches_equilibria(open_page, pages):
    page = open_page(pages["solutions"])
    solutions = json.loads(pages["fk.json"].read_text())["solutions"]
    assert len(solutions) > 1

    def platform() -> np.ndarray:
        """The reference point of the visible solution (the last marker of its anchors)."""
        xyz = page.page.evaluate(
            "() => { const gd = document.querySelector('.js-plotly-plot');"
            " const t = gd._fullData.filter(t => t.name === 'anchors' && t.visible === true);"
            " return t.map(t => [t.x[t.x.length - 1], t.y[t.y.length - 1], t.z[t.z.length - 1]]); }"
        )
        assert len(xyz) == 1, "one solution shown at a time"
        return np.array(xyz[0])

    np.testing.assert_allclose(platform(), solutions[0]["position"], atol=1e-9)
    before = page.scene_pixels(0)
    for k in (1, len(solutions) - 1):
        page.page.locator(".updatemenu-header").first.click()
        page.page.locator(".updatemenu-dropdown-button").nth(k).click()
        page.page.wait_for_function(
            "k => document.querySelector('.js-plotly-plot').layout.title.text.startsWith('#' + (k + 1) + ':')", arg=k
        )
        np.testing.assert_allclose(platform(), solutions[k]["position"], atol=1e-9)
        taut = ",".join(str(i) for i in solutions[k]["taut"])
        title = page.page.evaluate("() => document.querySelector('.js-plotly-plot').layout.title.text")
        assert title.startswith(f"#{k + 1}: cables {taut} taut")
        # the hover of the shown solution's anchors: its taut set, stability and tensions
        hover = page.page.evaluate(
            "() => document.querySelector('.js-plotly-plot')._fullData"
            ".filter(t => t.name === 'anchors' && t.visible === true).map(t => t.hovertext[0])"
        )
        stability = "stable" if solutions[k]["stable"] else "unstable"
        tensions = ", ".join(f"{t:.4g}" for t in solutions[k]["tensions"])
        assert hover == [f"#{k + 1}: cables {taut} taut, {stability}<br>τ = {tensions}<br>anchor of cable 1"]
    assert not np.array_equal(page.scene_pixels(0), before)
    assert page.errors == []


def test_a_4700_sample_trajectory_opens_within_the_issue_figure(open_page, pages):
    html = pages["trajectory"]
    samples = len(pages["trajectory.csv"].read_text().splitlines()) - 1
    size = html.stat().st_size
    assert size <= 10 << 20, f"{size:,} bytes"
    # the floor in the same run: plotly.js and one empty 3-D scene (WebGL, in software here)
    import plotly.graph_objects as go
    import plotly.io as pio

    floor_html = html.parent / "empty-scene.html"
    pio.write_html(go.Figure(go.Scatter3d(x=[0], y=[0], z=[0])), floor_html, include_plotlyjs="directory")
    floor = open_page(floor_html)
    page = open_page(html)
    # the page's own clock: from navigation to every plot laid out and drawn
    ms = page.page.evaluate("performance.now()")
    print(
        f"\nvscr-t-shaped trajectory view: {samples} samples, {size / 1e6:.2f} MB of HTML (+ plotly.js "
        f"{(html.parent / 'plotly.min.js').stat().st_size / 1e6:.2f} MB shared); opened in {page.open_s:.2f} s "
        f"(page clock {ms / 1000:.2f} s; the issue asks for 2 s); plotly.js with an empty 3-D scene "
        f"{floor.open_s:.2f} s: {page.open_s / floor.open_s:.2f}x that floor"
    )
    assert samples > 4000 and page.errors == [] and floor.errors == []


def test_the_demo_report_loads_offline_and_draws_its_views(open_page, report):
    page = open_page(report, height=1200)
    assert page.errors == []
    only_local(page, report.parent)
    text = report.read_text()
    assert '<script src="plotly.min.js"' in text and (report.parent / "plotly.min.js").is_file()
    assert page.plots() == 4
    titles = page.page.evaluate(
        "() => Array.from(document.querySelectorAll('.js-plotly-plot')).map(d => d.layout.title.text)"
    )
    for words in ("taut", "wrapping trajectory", "simulation c", "q1 → q2"):
        assert any(words in t for t in titles), (words, titles)
    for div in range(4):
        pixels = page.scene_pixels(div)
        assert pixels.std() > 5 and drawn(pixels) > 300, f"view {div + 1} of the report draws nothing"
    pngs = [p.name for p in report.parent.glob("*.png")]
    assert "dgp-equilibria.png" in pngs and "adjustable-8cable-check.png" in pngs


@pytest.mark.skipif(os.environ.get("TAUT_SCREENSHOT") != "1", reason="TAUT_SCREENSHOT=1 rewrites docs/taut-view.png")
def test_readme_screenshot(open_page, pages, tmp_path):
    page = open_page(pages["robot"], width=1000, height=720)
    shot = tmp_path / "shot.png"
    page.page.locator(".js-plotly-plot").first.screenshot(path=str(shot))
    shutil.copyfile(shot, SCREENSHOT)
    assert SCREENSHOT.stat().st_size > 10_000
