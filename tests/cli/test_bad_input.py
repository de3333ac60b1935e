"""Bad input, found by fuzzing the command line through subprocesses: every case ends with
exit status 2, exactly one line ``taut: error: ...`` on stderr (argparse's refusals and a
robot file with many bad fields included), no traceback, no warning, and nothing on
stdout — within a time limit (a hang fails) and a 4 GiB address space (a runaway
allocation fails)."""

from __future__ import annotations

import http.server
import json
import os
import threading
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import taut
from taut.model import robot_to_dict

#: Seconds one case may take: far beyond the few seconds of a refusal, far below a hang.
TIMEOUT = 120


def assert_refused(run, *words: str) -> None:
    assert run.code == 2, (run.code, run.out[:300], run.err[-2000:])
    assert run.out == ""
    assert "internal error" not in run.err
    lines = run.err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("taut: error: "), run.err
    for w in words:
        assert w in run.err, (w, run.err)


def _robot_file(tmp: Path, name: str, edit: Callable[[dict], None]) -> str:
    data = json.loads(json.dumps(robot_to_dict(taut.example("suspended-3cable")), default=float))
    edit(data)
    path = tmp / name
    path.write_text(yaml.safe_dump(data))
    return str(path)


def _files(tmp: Path) -> dict[str, str]:
    """Bad input files, by name."""
    (tmp / "deep.json").write_text("[" * 1000 + "]" * 1000)
    (tmp / "bigint.json").write_text('{"format": "taut/1", "name": ' + "7" * 5000 + "}")
    os.mkfifo(tmp / "fifo.yaml")
    (tmp / "evil.yaml").write_text("!!python/object/apply:os.system ['echo hi']\n")
    (tmp / "waypoints.txt").write_text("0.5 1\nnan 1\n")
    return {
        "deep": str(tmp / "deep.json"),
        "bigint": str(tmp / "bigint.json"),
        "fifo": str(tmp / "fifo.yaml"),
        "evil": str(tmp / "evil.yaml"),
        "nan-waypoints": str(tmp / "waypoints.txt"),
        "mass": _robot_file(tmp, "mass.yaml", lambda d: d["platform"].update(mass=1e300, gravity=[0, 0, -9.81])),
        "coincide": _robot_file(
            tmp, "coincide.yaml", lambda d: [c.update(anchor=[0.0, 0.0, 0.0]) for c in d["cables"]]
        ),
        "tmp": str(tmp),
    }


#: (id, argv with {name} standing for a file of :func:`_files`, words the message must hold).
CASES: list[tuple[str, list[str], tuple[str, ...]]] = [
    ("unknown-robot", ["ik", "no-such-robot"], ("no such file",)),
    ("unknown-command", ["frobnicate"], ()),
    ("nested-1000", ["ik", "{deep}"], ("nested",)),
    ("int-5000-digits", ["ik", "{bigint}"], ("digits",)),
    ("fifo", ["ik", "{fifo}"], ("not a regular file",)),
    ("dev-zero", ["ik", "/dev/zero"], ("not a regular file",)),
    ("mass-1e300", ["tensions", "{mass}"], ("platform.mass", "out of range")),
    ("lengths-1e308", ["fk", "suspended-3cable", "--lengths=1e308,1e308,1e308"], ("--lengths", "out of range")),
    ("coinciding-anchors", ["fk", "{coincide}"], ("collinear",)),
    ("empty-pose", ["ik", "planar-4cable", "--pose="], ("--pose",)),
    # argparse reads ``--opt=--`` as an empty list (found by the hypothesis test below)
    ("double-dash-value", ["ik", "planar-4cable", "--plot=--"], ("--plot", "expected one value")),
    ("empty-lengths", ["fk", "suspended-3cable", "--lengths="], ("--lengths",)),
    ("pose-size", ["ik", "planar-4cable", "--pose", "1,2"], ("--pose", "3 coordinates")),
    ("pose-nan", ["ik", "planar-4cable", "--pose", "nan,0,0"], ("--pose",)),
    ("wrench-size", ["tensions", "planar-4cable", "--wrench", "1,2"], ("--wrench",)),
    ("unknown-method", ["tensions", "planar-4cable", "--method", "simplex"], ("simplex",)),
    ("unknown-condition", ["workspace", "planar-4cable", "--condition", "nice"], ("nice",)),
    ("negative-box", ["workspace", "planar-4cable", "--condition", "wrench-feasible", "--box=-1,-1,-1"], ("--box",)),
    ("absurd-grid", ["workspace", "planar-4cable", "--condition", "static", "--grid", "10000000"], ("poses",)),
    (
        "absurd-grid-ranges",
        ["workspace", "planar-4cable", "--condition", "static", "--grid", "0:1:99999;0:1:99999"]
        + ["--orientation", "0"],
        ("poses",),
    ),
    ("zero-grid", ["workspace", "planar-4cable", "--condition", "static", "--grid", "0"], ("--grid",)),
    (
        "scheduler-garbage",
        ["workspace", "planar-4cable", "--condition", "static", "--scheduler", "garbage"],
        ("tcp://HOST:PORT",),
    ),
    ("speed-0", ["trajectory", "vscr-single-cable", "--speed", "0"], ("--speed",)),
    ("dt-inf", ["trajectory", "vscr-single-cable", "--dt", "inf"], ("--dt",)),
    ("dt-1e-7", ["trajectory", "vscr-single-cable", "--dt", "1e-7"], ("samples",)),
    ("dwell-negative", ["trajectory", "vscr-single-cable", "--dwell=-1"], ("--dwell",)),
    ("waypoints-python-tag", ["trajectory", "vscr-single-cable", "--waypoints", "{evil}"], ("--waypoints",)),
    ("waypoints-nan", ["trajectory", "vscr-single-cable", "--waypoints", "{nan-waypoints}"], ("--waypoints",)),
    ("plot-directory", ["ik", "planar-4cable", "--plot", "{tmp}"], ("--plot",)),
    ("plot-no-suffix", ["ik", "planar-4cable", "--plot", "{tmp}/x"], ("--plot",)),
    ("plot-unknown-suffix", ["ik", "planar-4cable", "--plot", "{tmp}/x.xyz"], ("--plot",)),
    ("plot-missing-directory", ["ik", "planar-4cable", "--plot", "{tmp}/no/x.png"], ("does not exist",)),
    ("plot-proc", ["ik", "planar-4cable", "--plot", "/proc/x.png"], ("cannot write",)),
    ("out-npz-suffix", ["workspace", "planar-4cable", "--condition", "static", "--out", "{tmp}/x.xyz"], (".npz",)),
    ("trajectory-out-missing-dir", ["trajectory", "vscr-single-cable", "--out", "{tmp}/no/t.csv"], ("--out",)),
    ("trajectory-plot-proc", ["trajectory", "vscr-single-cable", "--plot", "/proc/t.png"], ("--plot",)),
    ("plan-fix-commas", ["plan", "robocrane", "--start", "q1", "--goal", "q2", "--fix=,,,"], ("--fix",)),
    ("plan-radius-tiny", ["plan", "robocrane", "--start", "q1", "--goal", "q2", "--radius", "1e-9"], ("--radius",)),
    ("plan-out-directory", ["plan", "robocrane", "--start", "q1", "--goal", "q2", "--out", "{tmp}"], ("--out",)),
    ("atlas-out-missing-dir", ["atlas", "vscr-single-cable", "--out", "{tmp}/no/a.json"], ("--out",)),
    ("check-plot-suffix", ["check", "adjustable-8cable", "--trajectory", "sim-d", "--plot", "{tmp}/c"], ("--plot",)),
    ("fk-plot-proc", ["fk", "suspended-3cable", "--plot", "/proc/f.png"], ("--plot",)),
    ("igp-cables", ["igp", "suspended-3cable", "--taut", "1,x", "--fix", "x=1"], ("--taut",)),
    ("demo-out-file", ["demo", "--out", "/dev/null"], ("--out",)),
    *(
        (f"simulate-{name}", ["simulate", robot, "--waypoints", w, "--duration", t, *more], words)
        for name, robot, w, t, more, words in (
            ("pose-size", "spatial-8cable", "0,0,0;0,0,0,0", "1", [], ("--waypoints", "waypoint 2")),
            ("one-waypoint", "spatial-8cable", "0,0,0", "1", [], ("--waypoints", "two")),
            ("duration-0", "spatial-8cable", "0,0,0;0.1,0,0", "0", [], ("--duration",)),
            ("duration-negative", "spatial-8cable", "0,0,0;0.1,0,0", "-1", [], ("--duration",)),
            ("disturbance-syntax", "spatial-8cable", "0,0,0;0.1,0,0", "1", ["--disturbance", "5,0,0"], ("T0:W",)),
            ("disturbance-size", "spatial-8cable", "0,0,0;0.1,0,0", "1", ["--disturbance", "0:5,0"], ("6 components",)),
            (
                "disturbance-times",
                "spatial-8cable",
                "0,0,0;0.1,0,0",
                "1",
                ["--disturbance", "2:1:1,0,0,0,0,0"],
                ("T0",),
            ),
            ("no-mass", "robocrane", "0,0,2;0.1,0,2", "1", [], ("mass",)),
            ("mass-error", "spatial-8cable", "0,0,0;0.1,0,0", "1", ["--mass-error", "-1"], ("--mass-error",)),
            ("kp-size", "spatial-8cable", "0,0,0;0.1,0,0", "1", ["--kp", "1,2"], ("--kp",)),
            ("law", "spatial-8cable", "0,0,0;0.1,0,0", "1", ["--law", "septic"], ("septic",)),
            ("rate-0", "spatial-8cable", "0,0,0;0.1,0,0", "1", ["--rate", "0"], ("--rate",)),
            # feed-forward with a model 5 % heavy: the platform climbs out of the frame
            (
                "diverges",
                "spatial-8cable",
                "0,0,0;0.3,0.1,0.2",
                "2",
                ["--controller", "none", "--mass-error", "0.05"],
                ("diverged",),
            ),
        )
    ),
]

CASES += [
    *(
        (f"plan-radius-{r}", ["plan", "robocrane", "--start", "q1", "--goal", "q2", "--radius", r], ("--radius",))
        for r in ("nan", "inf", "-1")
    ),
    ("lengths-huge-finite", ["fk", "suspended-3cable", "--lengths=1e13,1,1"], ("out of range",)),
    ("wrench-huge", ["tensions", "planar-4cable", "--wrench", "0,1e300,0"], ("--wrench",)),
    ("max-taut-0", ["fk", "suspended-3cable", "--max-taut", "0"], ("--max-taut",)),
    ("fk-max-boxes-0", ["fk", "suspended-3cable", "--max-boxes", "0"], ("--max-boxes",)),
    (
        "igp-max-boxes-0",
        ["igp", "suspended-3cable", "--taut", "1,2,3", "--fix", "x=1,y=1,z=1", "--max-boxes", "0"],
        ("--max-boxes",),
    ),
    ("scheduler-refused", ["fk", "suspended-3cable", "--scheduler", "tcp://127.0.0.1:1"], ("scheduler",)),
]


@pytest.fixture
def files(tmp_path: Path) -> dict[str, str]:
    return _files(tmp_path)


def _run_case(taut_cli, files: dict[str, str], argv: list[str], words: tuple[str, ...]) -> None:
    run = taut_cli(*(a.format(**files) for a in argv), "--json", timeout=TIMEOUT)
    assert_refused(run, *words)
    assert not any(Path(files["tmp"]).glob("x*")), "nothing is written for refused input"


#: One case of each kind for the quick suite (each is a process start of a few seconds);
#: the slow suite runs them all.
QUICK = {
    "nested-1000",
    "fifo",
    "mass-1e300",
    "empty-pose",
    "double-dash-value",
    "dt-1e-7",
    "plot-directory",
    "plan-fix-commas",
    "simulate-pose-size",
    "simulate-disturbance-syntax",
    "simulate-no-mass",
}


@pytest.mark.parametrize(
    ("argv", "words"),
    [pytest.param(a, w, id=i, marks=() if i in QUICK else pytest.mark.slow) for i, a, w in CASES],
)
def test_refused(argv, words, taut_cli, files):
    _run_case(taut_cli, files, argv, words)


@pytest.fixture
def http_server() -> Iterator[str]:
    """A real HTTP server on a free localhost port: it accepts the connection and then says
    nothing, where a dask scheduler would send its handshake."""
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), http.server.SimpleHTTPRequestHandler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"tcp://127.0.0.1:{server.server_address[1]}"
    finally:
        server.shutdown()
        server.server_close()


@pytest.mark.slow
def test_scheduler_that_is_an_http_server(http_server, taut_cli):
    run = taut_cli(
        "workspace",
        "planar-4cable",
        "--condition",
        "static",
        "--grid",
        "3",
        "--scheduler",
        http_server,
        "--json",
        timeout=TIMEOUT,
    )
    assert_refused(run, "dask scheduler")


@pytest.mark.slow
def test_fk_lengths_beyond_what_tol_resolves_are_refused(taut_cli):
    """Lengths of a thousand kilometres put the platform where neighbouring doubles are
    wider apart than ``tol`` allows to certify: no box could be decided there, so the
    command refuses them in one line (exit 2) before searching, instead of a search that
    ends with every box undecided; a length the solver resolves is still answered."""
    run = taut_cli("fk", "suspended-3cable", "--lengths=1e6,1e6,1e6", "--json", timeout=600)
    assert run.code == 2 and run.out == ""
    lines = run.err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("taut: error: ") and "cannot resolve" in lines[0]
    ok = taut_cli("fk", "suspended-3cable", "--lengths=7.5,10,9.5", "--json", timeout=600)
    assert ok.code == 0 and json.loads(ok.out)["complete"] is True


@pytest.mark.slow
@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(
    text=st.one_of(
        st.text(alphabet="0123456789.,-+eE naifINpid/*", max_size=20),
        st.lists(
            st.sampled_from(["nan", "inf", "-inf", "1e400", "1e13", "", "pi/0", "--"]), min_size=1, max_size=4
        ).map(",".join),
    )
)
def test_any_pose_text_is_a_result_or_a_refusal(text, taut_cli):
    """Whatever ``--pose`` holds, the answer is JSON with finite lengths (exit 0) or a
    one-line refusal (exit 2)."""
    run = taut_cli("ik", "planar-4cable", f"--pose={text}", "--json", timeout=TIMEOUT)
    if run.code == 0:
        d = json.loads(run.out)
        assert all(isinstance(v, float) for v in d["lengths"])
    else:
        assert_refused(run)
