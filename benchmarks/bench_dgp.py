"""Time of the complete DGP of Table 4.3 (suspended 3-cable robot, 001_eb92e2f6589fc229.txt
§4.2.1) against the 25 s the source reports for its ALIAS C++ implementation.

    python benchmarks/bench_dgp.py [--max-taut K] [--repeat R] [--workers N]
"""

from _common import best_of  # first: it pins the thread pools to one core

import argparse

from taut.dgp import solve_dgp
from taut.model import load_robot
from taut.parallel import get_executor

SOURCE_SECONDS = 25.0  # Table 4.3, §4.2.1


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--max-taut", type=int, default=None)
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--workers", type=int, default=1)
    ns = ap.parse_args()
    robot = load_robot("suspended-3cable")
    solve_dgp(robot, max_taut=2)  # compile (or load) the Numba kernels outside the timing
    with get_executor(workers=ns.workers) as ex:
        t, res = best_of(lambda: solve_dgp(robot, max_taut=ns.max_taut, executor=ex), ns.repeat)
    stable = sum(s.stable for s in res.solutions)
    print(f"Table 4.3: {len(res.solutions)} solutions ({stable} stable), {res.subproblems} sub-problems, "
          f"{res.boxes} boxes, {res.undecided} undecided")
    if ns.max_taut is not None and ns.max_taut < robot.n_cables:
        # the source's 25 s cover every sub-problem: a partial run has no comparable ratio
        print(f"time: {t:.2f} s for sub-problems of at most {ns.max_taut} taut cables (partial run, no ratio to the source)")
    else:
        print(f"time: {t:.2f} s   source (ALIAS, 2015): {SOURCE_SECONDS:.0f} s   ratio source/taut: {SOURCE_SECONDS / t:.2f}x")


if __name__ == "__main__":
    main()
