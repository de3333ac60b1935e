from taut.viz import Report
from taut.viz.atlas import atlas_section


def test_atlas_section(tmp_path):
    report = Report("atlas")
    atlas_section(report)
    out = report.write(tmp_path)
    html = out.read_text() if out.is_file() else (out / "index.html").read_text()
    assert "structure atlas" in html and "queries/s" in html
