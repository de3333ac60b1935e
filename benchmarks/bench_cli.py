"""Start-up time of the ``taut`` command: whole processes, each command run once to warm
the Numba cache and then timed ``--runs`` times, against ``python -c pass`` timed the same
way in the same run (the baseline: what any Python command costs).  The CPU time of the
processes (user + system) is printed beside the wall time: on a busy machine it stays near
what the wall time would be on an idle one.

Targets (median wall time, warm cache): ``taut --help`` and ``taut examples`` <= 0.3 s;
``taut ik planar-4cable --pose 0.2,0.1,0`` and ``taut tensions planar-4cable --pose 0,0,0``
<= 0.8 s.  Which modules a command loads is checked without timing by
``tests/cli/test_startup.py``.

    python benchmarks/bench_cli.py [--runs 7]
"""

import argparse
import resource
import statistics
import subprocess
import sys
import time

#: The console script ``taut`` does exactly this: import the CLI and call its entry point.
TAUT = [sys.executable, "-c", "from taut.cli._main import entry; entry()"]

COMMANDS = [
    ("taut --help", ["--help"], 0.3),
    ("taut examples", ["examples"], 0.3),
    ("taut ik planar-4cable --pose 0.2,0.1,0", ["ik", "planar-4cable", "--pose", "0.2,0.1,0"], 0.8),
    ("taut tensions planar-4cable --pose 0,0,0", ["tensions", "planar-4cable", "--pose", "0,0,0"], 0.8),
]


def _children_cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def timed(cmd: list[str]) -> tuple[float, float]:
    """Wall and CPU time of one process running ``cmd``; it must succeed."""
    cpu, t = _children_cpu(), time.perf_counter()
    out = subprocess.run(cmd, capture_output=True, text=True)
    dt, dcpu = time.perf_counter() - t, _children_cpu() - cpu
    if out.returncode != 0:
        raise SystemExit(f"{' '.join(cmd)} failed ({out.returncode}): {out.stderr.strip()}")
    return dt, dcpu


def medians(cmd: list[str], runs: int) -> tuple[float, float]:
    """Median wall and CPU time of ``runs`` processes after a warm-up run (the Numba cache
    and the OS file cache)."""
    timed(cmd)
    walls, cpus = zip(*(timed(cmd) for _ in range(runs)))
    return statistics.median(walls), statistics.median(cpus)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=7)
    args = ap.parse_args()

    base, base_cpu = medians([sys.executable, "-c", "pass"], args.runs)
    print(f"median wall (and CPU) time of {args.runs} processes after a warm-up run")
    print(f"  {'python -c pass':<42} {base:6.3f} s  (cpu {base_cpu:5.3f} s)  baseline")
    met = []
    for label, argv, target in COMMANDS:
        dt, cpu = medians(TAUT + argv, args.runs)
        met.append(dt <= target)
        print(
            f"  {label:<42} {dt:6.3f} s  (cpu {cpu:5.3f} s)  = {dt / base:5.1f}x baseline  (target <= {target} s wall)"
        )
    print(f"targets met: {sum(met)} of {len(met)}")


if __name__ == "__main__":
    main()
