"""Time of a complete DGP of Berti (2015), §4.2 against the single-core time the
source reports for its ALIAS C++ implementation: Table 4.3 (suspended 3-cable robot, 25 s) by
default, or with ``--robot`` Table 4.6 (teaching-prototype, 187 s), 4.5 (marionet-vr, 702 s)
or 4.4 (cogiro, 1343 s); the count of solutions per number of taut cables is printed next to
the table's.

With ``--peer``, also the sub-problem with all three cables taut against the peer ``bertini2``
(``pip install bertini2``): its zero-dimensional solve (the start system it infers, total degree
2^12 = 4096 paths, one thread) of the same 12 polynomial equations in the same 12 unknowns as
``taut.dgp.build_subproblem``, against taut's certified branch-and-prune on that
sub-problem alone.  bertini2 needs minutes here; its count is of the real endpoints with
non-negative tensions.

    python benchmarks/bench_dgp.py [--robot NAME] [--max-taut K] [--repeat R] [--workers N]
                                   [--peer] [--peer-mptype double|adaptive]
"""

import argparse
from collections import Counter

import numpy as np
from _bertini import ALL_TAUT, import_bertini, matching, run_bertini
from _common import best_of  # pins the thread pools to one core

from taut.dgp import solve_dgp, solve_subset
from taut.model import load_robot
from taut.parallel import get_executor

#: robot → (table, the source's single-core seconds, printed solutions per number of taut cables), §4.2
SOURCES = {
    "suspended-3cable": ("Table 4.3", 25.0, {3: 6}),
    "teaching-prototype": ("Table 4.6", 187.0, {6: 2, 5: 11, 4: 12, 3: 9}),
    "marionet-vr": ("Table 4.5", 702.0, {6: 3, 5: 1, 4: 7, 3: 4, 2: 2}),
    "cogiro": ("Table 4.4", 1343.0, {6: 6, 5: 16, 4: 15, 3: 4, 2: 5}),
}
EPS = 1e-7  # solve_dgp's default box width


def peer(robot, repeat, mptype):
    bertini = import_bertini()
    if bertini is None:
        return
    lengths = np.asarray(robot.reference.lengths, float)
    t_taut, (sols, _, _) = best_of(lambda: solve_subset((robot, lengths, ALL_TAUT, EPS)), repeat)
    t_peer, endpoints, n_finite, n_paths = run_bertini(bertini, robot, lengths, mptype)
    print(
        f"bertini2: {len(endpoints)} real solutions with non-negative tensions (of {n_finite} finite endpoints; "
        f"{matching(robot, lengths, sols, endpoints)} of taut's {len(sols)} among them) in {t_peer:.1f} s "
        f"(bertini2 {bertini.__version__}, {n_paths} paths, {mptype} precision, 1 thread)   "
        f"taut 3-taut sub-problem: {len(sols)} in {t_taut:.2f} s   ratio bertini2/taut: {t_peer / t_taut:.1f}x"
    )


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--robot", choices=sorted(SOURCES), default="suspended-3cable")
    ap.add_argument("--max-taut", type=int, default=None)
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--workers", type=int, default=1)
    ap.add_argument("--peer", action="store_true", help="also time bertini2 on the 3-taut sub-problem (minutes)")
    ap.add_argument(
        "--peer-mptype",
        choices=("double", "adaptive"),
        default="double",
        help="bertini2's precision model (adaptive: a few times slower)",
    )
    ns = ap.parse_args()
    robot = load_robot(ns.robot)
    table, source_seconds, printed = SOURCES[ns.robot]
    with get_executor(workers=ns.workers) as ex:
        # start the workers and load the Numba kernels in each of them outside the timing
        solve_dgp(robot, max_taut=2, executor=ex)
        t, res = best_of(lambda: solve_dgp(robot, max_taut=ns.max_taut, executor=ex), ns.repeat)
    stable = sum(s.stable for s in res.solutions)
    per_m = dict(sorted(Counter(len(s.taut) for s in res.solutions).items(), reverse=True))
    print(
        f"{table}: {len(res.solutions)} solutions ({stable} stable), {res.subproblems} sub-problems, "
        f"{res.boxes} boxes, {res.undecided} undecided"
    )
    print(f"solutions per number of taut cables: {per_m}   printed: {printed}")
    top = min(robot.n_cables, 6)
    if ns.max_taut is not None and ns.max_taut < top:
        # the source's time covers every sub-problem: a partial run has no comparable ratio
        print(
            f"time: {t:.2f} s for sub-problems of at most {ns.max_taut} taut cables (partial run, no ratio to the source)"
        )
    else:
        print(
            f"time: {t:.2f} s on {ns.workers} worker(s)   source (ALIAS, 2015, one core): {source_seconds:.0f} s   "
            f"ratio source/taut: {source_seconds / t:.2f}x"
        )
    if ns.peer:
        if ns.robot != "suspended-3cable":
            print("bertini2: the peer runs on Table 4.3 only (--robot suspended-3cable)")
        else:
            peer(robot, ns.repeat, ns.peer_mptype)


if __name__ == "__main__":
    main()
