import json
import re

import pytest

import taut


@pytest.mark.slow
def test_atlas_json_out_plot(tmp_path, cli):
    out, png = tmp_path / "a.json", tmp_path / "a.png"
    assert cli.main(["atlas", "vscr-t-shaped", "--json", "--out", str(out), "--plot", str(png)]) == 0
    d = json.loads(cli.readouterr().out)
    assert d["charts"] >= 10 and d["edges"] >= d["charts"] - 1
    assert 0.89 < d["reachable_area"] < 0.9084 and 0 < d["workspace_area"] <= d["reachable_area"]
    full = json.loads(out.read_text())
    assert len(full["chart_list"]) == d["charts"] and full["chart_list"][0]["structure"] == [[]] * 6
    assert png.stat().st_size > 10_000


@pytest.mark.slow
def test_atlas_human_and_options(cli):
    assert cli.main(["atlas", "vscr-agriculture", "--start", "0,0.991", "--condition", "static", "--theta", "0"]) == 0
    out = cli.readouterr().out
    head = re.search(
        r"(\d+) charts, (\d+) adjacent pairs, reachable area ([\d.]+) m².*static workspace ([\d.]+) m²", out, re.S
    )
    charts, pairs, reachable, static = int(head[1]), int(head[2]), float(head[3]), float(head[4])
    areas = [float(a) for a in re.findall(r"chart +\d+ +area +([\d.]+)", out)]
    # one line per chart; a connected atlas has at least charts - 1 adjacent pairs; the charts
    # cover the reachable area (they overlap) and the static workspace lies inside it
    assert len(areas) == charts > 1 and pairs >= charts - 1
    assert all(0 < a <= reachable for a in areas) and sum(areas) >= reachable
    assert 0 < static <= reachable


@pytest.mark.slow
def test_atlas_bad_input(cli):
    assert cli.main(["atlas", "vscr-t-shaped", "--start", "5,5"]) == 2
    assert "outside the installation space" in cli.readouterr().err
    assert cli.main(["atlas", "vscr-t-shaped", "--start", "1"]) == 2
    assert cli.main(["atlas", "vscr-t-shaped", "--theta", "0.3"]) == 2
    assert cli.main(["atlas", "spatial-8cable"]) == 2
    assert cli.main(["atlas", "vscr-rigid-t-shaped", "--theta", "x"]) == 2
    assert cli.main(["atlas", "vscr-t-shaped", "--condition", "nope"]) == 2


@pytest.mark.slow
def test_atlas_rigid_page(cli):
    """A rigid platform: one atlas page per orientation (§5.2)."""
    assert cli.main(["atlas", "vscr-rigid-t-shaped", "--json"]) == 0
    d0 = json.loads(cli.readouterr().out)
    assert (
        cli.main(["atlas", "vscr-rigid-t-shaped", "--theta", "15deg", "--condition", "wrench-closure", "--json"]) == 0
    )
    d1 = json.loads(cli.readouterr().out)
    assert d0["theta"] == 0.0 and abs(d1["theta"] - 0.2617993877991494) < 1e-12
    assert d0["charts"] >= 10 and d1["charts"] >= 10
    # the platform must stay in the T, off the idlers and its cables: less than the point mass's 0.9
    assert 0.5 < d1["reachable_area"] < d0["reachable_area"] < 0.8
    assert cli.main(["atlas", "vscr-rigid-t-shaped", "--theta", "0.1"]) == 0
    assert "page θ = 0.1 rad" in cli.readouterr().out


@pytest.mark.slow
@pytest.mark.parametrize("name", [n for n in taut.example_names() if n.startswith("vscr-") and n != "vscr-t-shaped"])
def test_atlas_with_plot_on_every_planar_vscr_example(name, tmp_path, cli):
    """Also the examples whose wrench-feasible workspace is empty (no weight is printed for
    them): the plot shows the charts and an empty workspace panel (vscr-t-shaped:
    test_atlas_json_out_plot)."""
    png = tmp_path / "atlas.png"
    assert cli.main(["atlas", name, "--json", "--plot", str(png)]) == 0
    data = json.loads(cli.readouterr().out)
    assert data["charts"] >= 1 and 0 <= data["workspace_area"] <= data["reachable_area"] + 1e-9
    assert png.stat().st_size > 10_000
