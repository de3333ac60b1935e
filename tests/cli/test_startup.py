"""Start-up cost without timing: the light commands load none of the heavy libraries
(``--help`` and ``examples`` not even NumPy or pydantic).

Each case runs in a fresh interpreter (a real subprocess), does what the ``taut`` console
script does, and prints which heavy top-level packages ended up in ``sys.modules``.
``benchmarks/bench_cli.py`` measures the times themselves."""

import json
import subprocess
import sys

import pytest

HEAVY = {"numba", "scipy", "matplotlib", "shapely", "highspy", "dask", "distributed", "numpy", "pydantic"}
#: what computing anything with a robot needs
ROBOT = {"numpy", "pydantic"}

PROBE = """
import json, sys
{statement}
print(json.dumps(sorted({{m.split(".")[0] for m in sys.modules}} & {heavy})))
"""

CLI = """
from taut.cli._main import main
try:
    code = main({argv!r})
except SystemExit as exc:
    code = exc.code
assert code == 0, code
"""


def loaded(statement: str) -> tuple[set[str], str]:
    """The heavy packages loaded by ``statement`` in a fresh interpreter, and its stdout."""
    code = PROBE.format(statement=statement, heavy=set(HEAVY))
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    *lines, last = out.stdout.strip().splitlines()
    return set(json.loads(last)), "\n".join(lines)


@pytest.mark.parametrize(
    "statement, allowed",
    [
        ("import taut", set()),
        ("import taut.cli._main", set()),
        # every package re-exports lazily (docs/architecture.md §2.7): importing one loads nothing
        ("import taut.model, taut.statics, taut.kinematics, taut.dgp, taut.dynamics", set()),
        ("from taut.model import example; example('planar-4cable')", ROBOT),
    ],
)
def test_imports_load_no_heavy_library(statement, allowed):
    assert loaded(statement)[0] == allowed


@pytest.mark.parametrize(
    "argv, allowed, expect",
    [
        (["--help"], set(), "usage: taut"),
        (["examples", "--json"], set(), '"name": "planar-4cable"'),
        (["ik", "planar-4cable", "--pose", "0.2,0.1,0", "--json"], ROBOT, '"lengths"'),
        (["ik", "vscr-four-cable", "--json"], ROBOT, '"lengths"'),
        (["ik", "spatial-8cable", "--pose", "0.1,0,0.2,0.1,-0.1,0.2", "--json"], ROBOT, '"lengths"'),
        (["ik", "robocrane", "--json"], ROBOT, '"lengths"'),
        # the default method is an LP solved by HiGHS: that one it needs
        (["tensions", "planar-4cable", "--pose", "0,0,0", "--json"], ROBOT | {"highspy"}, '"feasible": true'),
    ],
)
def test_light_commands_load_no_heavy_library(argv, allowed, expect):
    heavy, stdout = loaded(CLI.format(argv=argv))
    assert expect in stdout
    assert heavy <= allowed, f"taut {' '.join(argv)} loaded {sorted(heavy - allowed)}"
