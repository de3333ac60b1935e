"""Commands that model cables as straight lines say so, in one warning line on stderr, when
the robot's cables sag (``cables[].weight``); their answer on stdout stays one JSON document."""

import json

import pytest

#: Commands whose answer is the straight model's, and words of their warning.
COMMANDS = [
    (["view", "cogiro-sagging", "--out", "{tmp}/v.html"], "the view"),
    (["workspace", "cogiro-sagging", "--condition", "static", "--grid", "3", "--json"], "the static condition"),
    (["workspace", "cogiro-sagging", "--condition", "sagging-static", "--grid", "2", "--json"], None),
]


@pytest.mark.parametrize(("argv", "words"), COMMANDS)
def test_straight_models_warn_of_sagging_cables(taut_cli, tmp_path, argv, words):
    run = taut_cli(*(a.format(tmp=tmp_path) for a in argv))
    assert run.code == 0, run.err
    lines = run.err.splitlines()
    if words is None:
        assert lines == []
    else:
        assert len(lines) == 1 and lines[0].startswith("taut: warning: ")
        assert "cables 1, 2, 3, 4, 5, 6, 7, 8 sag" in lines[0] and f"{words} takes them as straight lines" in lines[0]
    if "--json" in argv:
        json.loads(run.out)
