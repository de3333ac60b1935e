import json

import pytest

from taut.cli.main import main


def test_atlas_json_out_plot(tmp_path, capsys):
    out, png = tmp_path / "a.json", tmp_path / "a.png"
    assert main(["atlas", "vscr-t-shaped", "--json", "--out", str(out), "--plot", str(png)]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["charts"] >= 10 and d["edges"] >= d["charts"] - 1
    assert 0.89 < d["reachable_area"] < 0.9084 and 0 < d["workspace_area"] <= d["reachable_area"]
    full = json.loads(out.read_text())
    assert len(full["chart_list"]) == d["charts"] and full["chart_list"][0]["structure"] == [[]] * 6
    assert png.stat().st_size > 10_000


def test_atlas_human_and_options(capsys):
    assert main(["atlas", "vscr-agriculture", "--start", "0,0.991", "--condition", "static", "--theta", "0"]) == 0
    assert "charts" in capsys.readouterr().out


def test_atlas_bad_input(capsys):
    assert main(["atlas", "vscr-t-shaped", "--start", "5,5"]) == 2
    assert "outside the installation space" in capsys.readouterr().err
    assert main(["atlas", "vscr-t-shaped", "--start", "1"]) == 2
    assert main(["atlas", "vscr-t-shaped", "--theta", "0.3"]) == 2
    assert main(["atlas", "planar-4cable"]) == 2
    with pytest.raises(SystemExit) as exc:
        main(["atlas", "vscr-t-shaped", "--condition", "nope"])
    assert exc.value.code == 2
