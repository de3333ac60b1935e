import json

import pytest


@pytest.mark.slow
def test_trajectory_json_csv_plot(tmp_path, cli):
    out, png = tmp_path / "t.csv", tmp_path / "t.png"
    assert (
        cli.main(["trajectory", "vscr-four-cable", "--dt", "0.05", "--json", "--out", str(out), "--plot", str(png)])
        == 0
    )
    d = json.loads(cli.readouterr().out)
    assert d["samples"] == 101 and len(d["lengths"]) == 101 and len(d["lengths"][0]) == 4
    assert {e["kind"] for e in d["transitions"]} == {"wrap"} and d["tension_feasible"] is True
    assert {e["cable"] for e in d["transitions"]} == {1, 2, 3, 4}
    assert out.read_text().count("\n") == 102 and png.stat().st_size > 10_000


def test_trajectory_bad_input(tmp_path, cli):
    w = tmp_path / "w.txt"
    w.write_text("0.75,-0.5\n0,-0.3333\n")  # second waypoint inside object 1
    assert cli.main(["trajectory", "vscr-four-cable", "--waypoints", str(w)]) == 2
    assert "inside object 1" in cli.readouterr().err
    assert cli.main(["trajectory", "vscr-four-cable", "--waypoints", str(tmp_path / "nope.txt")]) == 2
    assert cli.main(["trajectory", "vscr-four-cable", "--dt", "0"]) == 2
