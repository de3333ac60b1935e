"""Time of a complete DGP of Berti (2015), §4.2 against the single-core time the
source reports for its ALIAS C++ implementation: Table 4.3 (suspended 3-cable robot, 25 s) by
default, or with ``--robot`` Table 4.6 (teaching-prototype, 187 s), 4.5 (marionet-vr, 702 s)
or 4.4 (cogiro, 1343 s); the count of solutions per number of taut cables is printed next to
the table's.

With ``--peer``, also the sub-problem with all three cables taut against the peer ``bertini2``
(``pip install bertini2``): its zero-dimensional solve (the start system it infers, total degree
2^12 = 4096 paths, one thread) of the same 12 polynomial equations in the same 12 unknowns as
``taut.dgp.formulation.build_subproblem``, against taut's certified branch-and-prune on that
sub-problem alone.  bertini2 needs minutes here; its count is of the real endpoints with
non-negative tensions.

    python benchmarks/bench_dgp.py [--robot NAME] [--max-taut K] [--repeat R] [--workers N]
                                   [--peer] [--peer-mptype double|adaptive]
"""

import argparse
import time
from collections import Counter
from fractions import Fraction

import numpy as np
from _common import best_of  # first: it pins the thread pools to one core

from taut.dgp import solve_dgp
from taut.dgp.formulation import _reference_choice, load
from taut.dgp.solve import _solve_subset
from taut.geometry.rotation import rotation_matrix
from taut.model import load_robot
from taut.parallel import get_executor

#: robot → (table, the source's single-core seconds, printed solutions per number of taut cables), §4.2
SOURCES = {
    "suspended-3cable": ("Table 4.3", 25.0, {3: 6}),
    "teaching-prototype": ("Table 4.6", 187.0, {6: 2, 5: 11, 4: 12, 3: 9}),
    "marionet-vr": ("Table 4.5", 702.0, {6: 3, 5: 1, 4: 7, 3: 4, 2: 2}),
    "cogiro": ("Table 4.4", 1343.0, {6: 6, 5: 16, 4: 15, 3: 4, 2: 5}),
}
ALL_TAUT = (0, 1, 2)
EPS = 1e-7  # solve_dgp's default box width
REAL_TOL = 1e-8  # |imaginary part| per unknown, relative to max(1, |value|)
MATCH_TOL = 1e-5  # reference points and tensions agreeing with taut's solution
SEED = 1  # bertini2's random gamma and start system: the same paths every run


def _cross(u, v):
    return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]


def bertini_system(bertini, robot, lengths, taut):
    """The equations of ``build_subproblem(robot, lengths, taut)`` as a ``bertini.System``:
    unknowns ``q_1, q_2, q_3`` (fixed-frame reference points) then the scaled tensions
    ``t_i = τ_i/ρ_i``; 3 rigidity relations, ``m`` cable lengths, 3 forces and 3 moments about
    the exit point of the first taut cable.  Every coefficient is the exact value of taut's
    double, so both tools solve the same system."""

    def c(x):
        return bertini.coefficient(Fraction(float(x)))

    a, r = robot.exits, robot.anchors
    f, mext, gp = load(robot)
    labels, refs = _reference_choice(robot, taut, gp)
    qv = [bertini.Variable(f"q{s}{k}") for s in range(3) for k in range(3)]
    tv = [bertini.Variable(f"t{i}") for i in taut]
    q = [qv[0:3], qv[3:6], qv[6:9]]
    t = dict(zip(taut, tv))
    e1 = [q[1][k] - q[0][k] for k in range(3)]
    e2 = [q[2][k] - q[0][k] for k in range(3)]
    n12 = _cross(e1, e2)
    Eb = np.column_stack([refs[1] - refs[0], refs[2] - refs[0], np.cross(refs[1] - refs[0], refs[2] - refs[0])])

    def point(label, body):
        if label in labels:
            return q[labels.index(label)]
        beta = np.linalg.solve(Eb, body - refs[0])
        beta = np.where(np.abs(beta) < 1e-14, 0.0, beta)
        return [q[0][k] + c(beta[0]) * e1[k] + c(beta[1]) * e2[k] + c(beta[2]) * n12[k] for k in range(3)]

    b = {i: point(i, r[i]) for i in taut}
    g = point("G", gp)
    pole = a[taut[0]]
    eqs = []
    for i, j in ((0, 1), (0, 2), (1, 2)):
        d = float(np.linalg.norm(refs[i] - refs[j]))
        eqs.append(sum((q[i][k] - q[j][k]) ** 2 for k in range(3)) - c(d) ** 2)
    for i in taut:
        eqs.append(sum((b[i][k] - c(a[i][k])) ** 2 for k in range(3)) - c(lengths[i]) ** 2)
    for k in range(3):
        eqs.append(sum(t[i] * (c(a[i][k]) - b[i][k]) for i in taut) + c(f[k]))
    for k in range(3):
        k1, k2 = (k + 1) % 3, (k + 2) % 3
        acc = (g[k1] - c(pole[k1])) * c(f[k2]) - (g[k2] - c(pole[k2])) * c(f[k1]) + c(mext[k])
        for i in taut:
            arm = a[i] - pole
            acc = acc + t[i] * ((b[i][k1] - c(pole[k1])) * c(arm[k2]) - (b[i][k2] - c(pole[k2])) * c(arm[k1]))
        eqs.append(acc)
    system = bertini.System()
    system.add_variable_group(bertini.VariableGroup(qv + tv))
    for e in eqs:
        system.add_function(e)
    return system


def run_bertini(bertini, robot, lengths, mptype):
    """``(seconds, admissible endpoints (k, 9 + m) real, finite endpoints, paths)``."""
    bertini.recording(False)  # no records directory written into the working directory
    bertini.random.set_random_seed(SEED)
    system = bertini_system(bertini, robot, lengths, ALL_TAUT)
    solver = bertini.nag_algorithm.ZeroDimSolver(system, mptype=mptype, num_threads=1)
    t0 = time.perf_counter()
    finite = solver.solve(show_progress=False)
    seconds = time.perf_counter() - t0
    x = np.array([[complex(v) for v in p] for p in finite]).reshape(len(finite), 9 + len(ALL_TAUT))
    real = np.all(np.abs(x.imag) <= REAL_TOL * np.maximum(1.0, np.abs(x)), axis=1)
    admissible = real & np.all(x.real[:, 9:] >= 0.0, axis=1)
    return seconds, x[admissible].real, len(finite), solver.num_paths()


def matching(robot, lengths, taut_solutions, endpoints):
    """How many of taut's solutions one of the peer's endpoints reproduces (reference points
    and scaled tensions within ``MATCH_TOL``)."""
    _, _, gp = load(robot)
    _, refs = _reference_choice(robot, ALL_TAUT, gp)
    idx = list(ALL_TAUT)
    xs = [
        np.concatenate(
            [
                (s.position + refs @ rotation_matrix(s.orientation, robot.orientation).T).ravel(),
                s.tensions[idx] / lengths[idx],
            ]
        )
        for s in taut_solutions
    ]
    return sum(any(np.abs(e - x).max() <= MATCH_TOL for e in endpoints) for x in xs)


def peer(robot, repeat, mptype):
    try:
        import bertini
    except ImportError as e:
        print(
            "bertini2: not installed (pip install bertini2)"
            if e.name == "bertini"
            else f"bertini2: not available ({e})"
        )
        return
    lengths = np.asarray(robot.reference.lengths, float)
    t_taut, (sols, _, _) = best_of(lambda: _solve_subset((robot, lengths, ALL_TAUT, EPS)), repeat)
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
