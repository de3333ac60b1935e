"""Start-up time of the ``taut`` command: whole processes, each command run once to warm
the Numba cache and then timed ``--runs`` times, against ``python -c pass`` timed the same
way in the same run (the baseline: what any Python command costs).

Targets (median wall time, warm cache): ``taut --help`` and ``taut examples`` <= 0.3 s;
``taut ik planar-4cable --pose 0.2,0.1,0`` and ``taut tensions planar-4cable --pose 0,0,0``
<= 0.8 s.  Which modules a command loads is checked without timing by
``tests/cli/test_startup.py``.

    python benchmarks/bench_cli.py [--runs 7]
"""

import argparse
import statistics
import subprocess
import sys
import time

#: The console script ``taut`` does exactly this: import the CLI and call its entry point.
TAUT = [sys.executable, "-c", "from taut.cli.main import entry; entry()"]

COMMANDS = [
    ("taut --help", ["--help"], 0.3),
    ("taut examples", ["examples"], 0.3),
    ("taut ik planar-4cable --pose 0.2,0.1,0", ["ik", "planar-4cable", "--pose", "0.2,0.1,0"], 0.8),
    ("taut tensions planar-4cable --pose 0,0,0", ["tensions", "planar-4cable", "--pose", "0,0,0"], 0.8),
]


def wall(cmd: list[str]) -> float:
    """Wall time of one process running ``cmd``; it must succeed."""
    t = time.perf_counter()
    out = subprocess.run(cmd, capture_output=True, text=True)
    dt = time.perf_counter() - t
    if out.returncode != 0:
        raise SystemExit(f"{' '.join(cmd)} failed ({out.returncode}): {out.stderr.strip()}")
    return dt


def median_wall(cmd: list[str], runs: int) -> float:
    wall(cmd)  # warm-up: the Numba cache and the OS file cache
    return statistics.median(wall(cmd) for _ in range(runs))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=7)
    args = ap.parse_args()

    base = median_wall([sys.executable, "-c", "pass"], args.runs)
    print(f"median wall time of {args.runs} processes after a warm-up run")
    print(f"  {'python -c pass':<42} {base:6.3f} s  (baseline)")
    met = []
    for label, argv, target in COMMANDS:
        dt = median_wall(TAUT + argv, args.runs)
        met.append(dt <= target)
        print(f"  {label:<42} {dt:6.3f} s  = {dt / base:5.1f}x baseline  (target <= {target} s)")
    print(f"targets met: {sum(met)} of {len(met)}")


if __name__ == "__main__":
    main()
