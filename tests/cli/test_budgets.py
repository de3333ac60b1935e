"""Every long computation is bounded by its budget and every output by a memory cap (issue
26, HANGS and MEMORY): each command here used to run for minutes to hours or to grow past
gigabytes.  They run in real subprocesses with a time limit and an address-space limit, so
that a regression fails instead of hanging or exhausting the machine; every answer is
checked against an independent computation or the physics of the request."""

from __future__ import annotations

import json
import math
import resource
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest
import yaml
from scipy.optimize import linprog

#: Seconds a command may take here: each finishes in a few seconds to tens of seconds.
TIMEOUT = 60


@dataclass(frozen=True)
class Run:
    code: int
    out: str
    err: str

    def json(self) -> dict:
        assert self.code == 0, self.err
        return json.loads(self.out)

    def error_line(self) -> str:
        """The one stderr line of a refusal (exit 2, nothing on stdout)."""
        lines = [ln for ln in self.err.splitlines() if ln.strip()]
        assert self.code == 2 and self.out == "" and len(lines) == 1, (self.code, self.err)
        assert lines[0].startswith("taut: error: ")
        return lines[0]


def taut(*argv: str, memory_gib: float = 3.0) -> Run:
    """``python -m taut ARGV`` under :data:`TIMEOUT` and an address-space limit."""
    limit = int(memory_gib * 2**30)

    def cap() -> None:
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))

    proc = subprocess.run(
        [sys.executable, "-m", "taut", *argv], capture_output=True, text=True, timeout=TIMEOUT, preexec_fn=cap
    )
    return Run(proc.returncode, proc.stdout, proc.stderr)


# ---- HANGS ------------------------------------------------------------------------


@pytest.mark.slow
def test_static_atlas_of_an_under_constrained_robot_is_decided_in_closed_form():
    """One cable, two wrench components: every grid point of the 44 charts was an LP (1.4 M
    of them, six minutes).  The single-cable robot has no weight, so zero tension balances
    it at every point a cable reaches: the static workspace is the reachable area, to within
    the grid's cells along its border."""
    d = taut("atlas", "vscr-single-cable", "--condition", "static", "--json").json()
    assert d["charts"] == 44
    assert 0.99 * d["reachable_area"] <= d["workspace_area"] <= d["reachable_area"]


@pytest.mark.slow
def test_a_grid_beyond_the_pose_budget_is_refused_and_the_budget_can_be_raised():
    line = taut("workspace", "spatial-8cable", "--condition", "wrench-closure", "--grid=300", "--json").error_line()
    assert "27,000,000 poses" in line and "10,000,000" in line and "--max-poses" in line
    grid = ["workspace", "spatial-8cable", "--condition", "wrench-closure", "--grid=30", "--json"]
    assert "27,000 poses" in taut(*grid, "--max-poses=26999").error_line()
    d = taut(*grid, "--max-poses=27000").json()
    assert d["poses"] == 27_000 and 0 < d["inside"] < 27_000


def test_lengths_beyond_double_precision_are_refused():
    """Lengths of 1e9 m hang the platform 1e9 m below the exits, where doubles are 1.2e-7 m
    apart: the DGP's tol of 1e-7 m cannot be resolved there (hours of boxes that never
    certify)."""
    line = taut("fk", "suspended-3cable", "--lengths=1e9,1e9,1e9", "--json").error_line()
    assert f"{np.spacing(1e9):.2g} m apart" in line and "tol = 1e-07 m" in line


SLICE = "x=0,y=0,z=2,sigma=35deg"
RRT = ["plan", "robocrane", "--start", "q3", "--goal", "q4", "--fix", SLICE, "--planner=atlasrrt"]


def test_atlasrrt_refuses_a_step_too_small_for_its_charts():
    line = taut(*RRT, "--step=1e-12", "--max-nodes=100", "--json").error_line()
    assert "step 1e-12" in line and "0.0004" in line  # 1e-3 of the default radius 0.4


def test_atlasrrt_stops_at_its_node_budget_whatever_the_step():
    """The smallest step allowed, 4e-4: one extension toward a random sample is up to 2000
    steps, each a node; the walk stops where the budget does."""
    d = taut(*RRT, "--step=4e-4", "--max-nodes=100", "--json").json()
    assert not d["found"] and not d["no_path"] and d["nodes"] == 100 and d["path"] == []


@pytest.mark.slow
def test_astar_in_six_dimensions_needs_an_explicit_budget_and_stops_at_it():
    argv = ["plan", "robocrane", "--start", "q1", "--goal", "q2", "--planner=astar", "--json"]
    line = taut(*argv).error_line()
    assert "6 free coordinates" in line and "--fix" in line and "--max-charts" in line
    d = taut(*argv, "--max-charts=60").json()
    # the budget ends the search within an expansion: not found, not a proof
    assert d["charts"] == 60 and not d["found"] and not d["no_path"] and 0 < d["expanded"] < 60


def _sphere_robot(n: int) -> dict:
    """``n`` cables from a Fibonacci sphere of radius 1 to anchors on one of radius 0.1
    (a shuffled copy of the exits: the moments span every direction)."""
    i = np.arange(n) + 0.5
    polar, azimuth = np.arccos(1 - 2 * i / n), np.pi * (1 + math.sqrt(5)) * i
    exits = np.column_stack([np.cos(azimuth) * np.sin(polar), np.sin(azimuth) * np.sin(polar), np.cos(polar)])
    anchors = 0.1 * exits[np.random.default_rng(0).permutation(n)]
    return {
        "format": "taut/1",
        "name": f"sphere of {n} cables",
        "dimension": 3,
        "platform": {"kind": "rigid", "mass": 1.0, "gravity": [0, 0, -9.81]},
        "cables": [{"exit": e.tolist(), "anchor": a.tolist(), "tension": [1, 100]} for e, a in zip(exits, anchors)],
    }


@pytest.mark.slow
def test_the_workspace_of_two_thousand_cables(tmp_path: Path):
    """C(2000, 5) = 2.6e14 facet normals per pose for the facet test: LPs decide instead.
    Oracle: the structure matrix from the file's numbers (``u = (a − p − r)/‖…‖``, moment
    ``r × u``), a positive null vector by scipy's linprog."""
    spec = _sphere_robot(2000)
    path = tmp_path / "sphere.yaml"
    path.write_text(yaml.safe_dump(spec))
    out = tmp_path / "ws.npz"
    d = taut("workspace", str(path), "--condition", "wrench-closure", "--grid=3", "--out", str(out), "--json").json()
    assert d["poses"] == 27
    with np.load(out) as f:
        inside, axes = f["inside"], [f[f"axis_{k}"] for k in range(3)]
    exits = np.array([c["exit"] for c in spec["cables"]])
    anchors = np.array([c["anchor"] for c in spec["cables"]])
    expected = []
    for p in np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3):
        u = exits - p - anchors
        u /= np.linalg.norm(u, axis=1)[:, None]
        W = np.vstack([u.T, np.cross(anchors, u).T])
        res = linprog(np.zeros(2000), A_eq=W, b_eq=np.zeros(6), bounds=[(1, None)] * 2000, method="highs")
        expected.append(np.linalg.matrix_rank(W) == 6 and res.status == 0)
    assert inside.tolist() == expected
    assert expected[13]  # the centre
    assert d["inside"] == sum(expected)


# ---- MEMORY -----------------------------------------------------------------------

WAYPOINTS = "0,0,0;0.3,0.1,0.2"


def test_a_simulation_whose_samples_exceed_the_memory_cap_is_refused():
    """9999 s at 1 kHz kept at 100 Hz: 999,901 samples of 377 bytes (time, six pose-sized
    rows, eight tensions, two errors, a flag), 360 MiB; the way out is a lower rate."""
    line = taut("simulate", "spatial-8cable", "--waypoints", WAYPOINTS, "--duration=9999", "--json").error_line()
    assert "999,901 samples of 377 bytes" in line and "64 MiB" in line and "--sample-rate at most" in line


@pytest.mark.slow
def test_a_fast_control_rate_streams_in_bounded_memory():
    """A million control updates under a 1 GiB address space (the full arrays took 1.2 GB):
    only the 101 samples at 100 Hz are kept, and the statistics cover every update."""
    d = taut(
        "simulate", "spatial-8cable", "--waypoints", WAYPOINTS, "--duration=1", "--rate=1e6", "--json", memory_gib=1.0
    ).json()
    assert d["updates"] == 1_000_001 and d["samples"] == len(d["time"]) == 101
    np.testing.assert_allclose(d["time"], np.linspace(0.0, 1.0, 101), atol=1e-12)
    # the path ends where it was asked to, and the error of a 1 MHz loop is tiny
    np.testing.assert_allclose(d["reference"][-1], [0.3, 0.1, 0.2, 0, 0, 0], atol=1e-12)
    assert max(d["tracking_error_max"]) < 1e-6 and d["feasible"]


def test_the_independent_check_of_a_path_is_bounded():
    base = ["plan", "robocrane", "--start", "q1", "--goal", "q2", "--fix", SLICE, "--json"]
    assert "--subdivide 1000000" in taut(*base, "--subdivide=1000000").error_line()
    # a path of several steps at 100,000 poses a step: more than the million checked
    line = taut(*base, "--subdivide=100000").error_line()
    steps = int(line.split("the path's ")[1].split(" steps")[0])
    assert f"{steps * 100_000 + 1:,} poses" in line and f"at most {999_999 // steps}" in line
