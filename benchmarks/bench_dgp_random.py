"""The complete DGP (``taut.dgp.solve_dgp``) on a suite of seeded random suspended robots
(``taut.model.random_suspended_robot``) that nobody tuned the solver to: per
robot the equilibria, the undecided boxes and the time; per cable count the median, 90th
percentile and worst time; for the 3-cable suite the worst/median ratio (target ≤ 5).

By default 20 robots of 3 cables (seeds 0–19) and 10 of 4 cables (seeds 0–9), every taut
subset, and 2 of 6 and 2 of 8 cables with sub-problems of at most ``--max-taut`` (default 2)
taut cables; then planar platforms (``taut.model.random_planar_robot``, pose ``x, y, θ``):
``--planar`` robots (default 10) each of 2, 3 and 4 cables, every taut subset (up to three
cables), summarised apart so that the spatial figures stay what they were.  With ``--peer``, the sub-problem with all three cables taut of every 3-cable
robot is also solved by ``bertini2`` (see ``_bertini.py``; 4096 paths, 10–20 minutes per robot
on a shared core: pick a few robots, e.g. ``--three 3 --four 0 --six 0 --eight 0 --peer``):
both counts of real equilibria with non-negative tensions are printed, and any disagreement.

Point masses (``taut.model.random_point_mass_robot``, ``--point-mass N``, default 10 of each
kind): N spatial robots of 2–8 cables and N planar ones of 2–6, their lengths perturbed by
2, 10, 30 or 60 % (some admit no equilibrium); per kind the median and worst time, the
undecided boxes, and against the least-squares fit of all the lengths that cable-printer
firmware computes (``DGPResult.least_squares``, timed alone as the baseline) how often that fit
is more than 1 mm from the certified equilibrium or has none to be near.

Pulleys (``random_suspended_robot(..., pulley_radius=PULLEY_RADIUS)``, ``--pulleys N``, default
5): the 3-cable robots of seeds ``--first`` on, their cables through swivelling pulleys of 5 cm,
every taut subset; per robot the equilibria, each one's lengths recomputed by the pulley
inverse kinematics (``taut.kinematics.cable_lengths``, the largest residual printed), and the
same seed's point-exit robot solved as the baseline; summarised apart, with the median ratio
of the two times.

With ``--fold``, a suite robot at a fold (seed 0, 3 cables, cable 1 lengthened by
:data:`FOLD_SIDE`, 7e-11 past the length where two equilibria appear): solved in double
precision alone, which leaves boxes too narrow to split around the nearly double pair, and
with the boxes searched again in multi-precision (python-flint, ``taut[precise]``).

    python benchmarks/bench_dgp_random.py [--three N] [--four N] [--six N] [--eight N]
                                          [--planar N] [--max-taut K] [--first SEED]
                                          [--point-mass N] [--pulleys N] [--peer] [--fold]
"""

import argparse
import time

import _common  # noqa: F401  (pins the thread pools to one core)
import numpy as np
from _bertini import ALL_TAUT, import_bertini, matching, run_bertini
from scipy.optimize import least_squares

from taut.dgp import solve_dgp, solve_subset
from taut.kinematics import cable_lengths
from taut.model import random_planar_robot, random_point_mass_robot, random_suspended_robot

EPS = 1e-7  # solve_dgp's default box width
RATIO_TARGET = 5.0  # worst / median time of the 3-cable suite (issue 21)
FOLD_SIDE = 1.0353778044866666  # the factor of tests/fold_robot.py


def suite(ns):
    """``(cables, seed, max_taut)`` of every robot of the run."""
    first = ns.first
    cases = [(3, s, None) for s in range(first, first + ns.three)]
    cases += [(4, s, None) for s in range(first, first + ns.four)]
    cases += [(6, s, ns.max_taut) for s in range(first, first + ns.six)]
    cases += [(8, s, ns.max_taut) for s in range(first, first + ns.eight)]
    return cases


#: Cable counts of the planar robots of the run.
PLANAR_CABLES = (2, 3, 4)


def planar(ns):
    """The planar robots: their equilibria by taut-set size, undecided boxes and times."""
    times: dict[int, list[float]] = {}
    undecided = 0
    for n in PLANAR_CABLES:
        for seed in range(ns.first, ns.first + ns.planar):
            robot, lengths = random_planar_robot(n, seed=seed)
            t0 = time.perf_counter()
            res = solve_dgp(robot, lengths)
            t = time.perf_counter() - t0
            times.setdefault(n, []).append(t)
            undecided += res.undecided
            per_m = {}
            for s in res.solutions:
                per_m[len(s.taut)] = per_m.get(len(s.taut), 0) + 1
            print(
                f"planar {n} cables seed {seed:3d}: {len(res.solutions)} equilibria "
                f"{dict(sorted(per_m.items(), reverse=True))}, {res.undecided} undecided, {res.boxes} boxes, {t:.2f} s",
                flush=True,
            )
    for n in sorted(times):
        summary(f"planar {n} cables", times[n])
    return undecided


def summary(label, times):
    t = np.asarray(times)
    med = float(np.median(t))
    print(
        f"{label}: {t.size} robots   median {med:.2f} s   90th percentile {np.percentile(t, 90):.2f} s   "
        f"worst {t.max():.2f} s   worst/median {t.max() / med:.1f}x"
    )
    return float(t.max() / med)


def peer(cases, mptype):
    bertini = import_bertini()
    if bertini is None:
        return
    disagreements = 0
    for n, seed, _ in cases:
        if n != 3:
            continue
        robot, lengths = random_suspended_robot(n, seed=seed)
        sols, undecided, _ = solve_subset((robot, lengths, ALL_TAUT, EPS))
        t_peer, endpoints, n_finite, n_paths = run_bertini(bertini, robot, lengths, mptype)
        found = matching(robot, lengths, sols, endpoints)
        agree = len(endpoints) == len(sols) == found and undecided == 0
        disagreements += not agree
        print(
            f"  3 cables seed {seed}: taut {len(sols)}  bertini2 {len(endpoints)} (of {n_finite} finite endpoints, "
            f"{n_paths} paths, {t_peer:.0f} s)  taut's found by bertini2: {found}, taut undecided: {undecided}"
            + ("" if agree else "  DISAGREE")
        )
    print(f"bertini2 {bertini.__version__} ({mptype} precision): {disagreements} disagreement(s)")


def firmware_fit(robot, lengths):
    """The least-squares fit of all the lengths, as ``DGPResult.least_squares`` computes it:
    timed alone, the baseline of the point-mass suite."""
    a = robot.exits
    f = robot.weight / np.linalg.norm(robot.weight)
    start = a.mean(axis=0) + float(np.mean(lengths)) * f / 2.0
    return least_squares(
        lambda p: np.linalg.norm(p - a, axis=1) - lengths, start, method="trf", xtol=1e-15, ftol=1e-15, gtol=1e-15
    ).x


def point_masses(ns):
    """The point-mass suite: per kind the times, undecided boxes and firmware's misses."""
    for dimension, low, high in ((3, 2, 8), (2, 2, 6)):
        times, fits, undecided, off = [], [], 0, 0
        for k, seed in enumerate(range(ns.first, ns.first + ns.point_mass)):
            n = low + k % (high - low + 1)
            perturbation = (0.02, 0.1, 0.3, 0.6)[k % 4]
            robot, lengths = random_point_mass_robot(n, dimension=dimension, seed=seed, perturbation=perturbation)
            t0 = time.perf_counter()
            res = solve_dgp(robot, lengths)
            times.append(time.perf_counter() - t0)
            t0 = time.perf_counter()
            fit = firmware_fit(robot, lengths)
            fits.append(time.perf_counter() - t0)
            undecided += res.undecided
            near = [np.linalg.norm(fit - s.position) <= 1e-3 for s in res.solutions]
            off += not any(near)
            print(
                f"point mass {dimension}-D {n} cables seed {seed:3d} (lengths ±{perturbation:g}): "
                f"{len(res.solutions)} equilibria {[list(s.taut) for s in res.solutions]}, {res.undecided} undecided, "
                f"{res.boxes} boxes, {times[-1]:.3f} s; least-squares fit "
                f"{'at the equilibrium' if any(near) else 'off (no equilibrium within 1 mm)'}",
                flush=True,
            )
        summary(f"point mass {dimension}-D", times)
        print(
            f"point mass {dimension}-D: certified DGP / least-squares fit time {np.median(times) / np.median(fits):.0f}x "
            f"(median); least-squares fit off the equilibrium in {off} of {len(times)}; undecided boxes {undecided}"
        )


#: Radius [m] of the swivelling pulleys of the pulley suite.
PULLEY_RADIUS = 0.05


def by_size(res):
    """The equilibria counted by taut-set size, largest first."""
    per_m = {}
    for s in res.solutions:
        per_m[len(s.taut)] = per_m.get(len(s.taut), 0) + 1
    return dict(sorted(per_m.items(), reverse=True))


def pulleys(ns):
    """The pulley suite: per robot the equilibria, their pulley-IK residual and the time, with
    the same seed's point-exit robot as the baseline."""
    solve_dgp(*random_suspended_robot(3, seed=0, pulley_radius=PULLEY_RADIUS), max_taut=2)
    times, ratios, undecided, worst = [], [], 0, 0.0
    for seed in range(ns.first, ns.first + ns.pulleys):
        robot, lengths = random_suspended_robot(3, seed=seed, pulley_radius=PULLEY_RADIUS)
        t0 = time.perf_counter()
        res = solve_dgp(robot, lengths)
        times.append(time.perf_counter() - t0)
        point = random_suspended_robot(3, seed=seed)
        t0 = time.perf_counter()
        base = solve_dgp(*point)
        ratios.append(times[-1] / (time.perf_counter() - t0))
        undecided += res.undecided
        residual = max(
            (
                float(np.abs(cable_lengths(robot, [*s.position, *s.orientation]) - lengths)[list(s.taut)].max())
                for s in res.solutions
            ),
            default=0.0,
        )
        worst = max(worst, residual)
        print(
            f"pulleys 3 cables seed {seed:3d}: {len(res.solutions)} equilibria {by_size(res)}, {res.undecided} "
            f"undecided, {res.boxes} boxes, {times[-1]:.2f} s, pulley IK residual {residual:.1e} m; point exits "
            f"{len(base.solutions)} equilibria {by_size(base)}, {times[-1] / ratios[-1]:.2f} s",
            flush=True,
        )
    summary(f"pulleys 3 cables (radius {PULLEY_RADIUS:g} m)", times)
    print(
        f"pulleys 3 cables: pulley / point-exit DGP time {np.median(ratios):.1f}x (median); largest pulley IK "
        f"residual {worst:.1e} m (within 1e-9: {worst <= 1e-9}); undecided boxes {undecided}"
    )


def fold():
    robot, lengths = random_suspended_robot(3, seed=0)
    lengths = lengths.copy()
    lengths[0] *= FOLD_SIDE
    times = []
    for label, multiprecision in (("double precision alone", False), ("with multi-precision", True)):
        t0 = time.perf_counter()
        res = solve_dgp(robot, lengths, max_taut=3, multiprecision=multiprecision)
        times.append(time.perf_counter() - t0)
        full = sum(len(s.taut) == 3 for s in res.solutions)
        print(
            f"fold robot, {label}: {full} all-taut equilibria of {len(res.solutions)}, "
            f"{res.undecided} undecided ({'complete' if res.complete else 'incomplete'}), {times[-1]:.2f} s"
        )
    print(f"fold robot, time with multi-precision / double precision alone: {times[1] / times[0]:.2f}x")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--three", type=int, default=20, help="3-cable robots")
    ap.add_argument("--four", type=int, default=10, help="4-cable robots")
    ap.add_argument("--six", type=int, default=2, help="6-cable robots (with --max-taut)")
    ap.add_argument("--eight", type=int, default=2, help="8-cable robots (with --max-taut)")
    ap.add_argument("--planar", type=int, default=10, help="planar robots of each of 2, 3 and 4 cables")
    ap.add_argument("--max-taut", type=int, default=2, help="largest taut subset of the 6- and 8-cable robots")
    ap.add_argument("--first", type=int, default=0, help="first seed")
    ap.add_argument("--point-mass", type=int, default=10, help="point-mass robots of each kind (spatial, planar)")
    ap.add_argument("--pulleys", type=int, default=5, help="3-cable robots with swivelling pulleys")
    ap.add_argument("--peer", action="store_true", help="also bertini2 on each 3-cable all-taut sub-problem")
    ap.add_argument("--peer-mptype", choices=("double", "adaptive"), default="double")
    ap.add_argument(
        "--fold", action="store_true", help="also the suite robot at a fold, with and without multi-precision"
    )
    ns = ap.parse_args()
    cases = suite(ns)
    # load the Numba kernels outside the timing
    solve_dgp(*random_suspended_robot(3, seed=0), max_taut=2)
    times: dict[int, list[float]] = {}
    total_undecided = 0
    for n, seed, max_taut in cases:
        robot, lengths = random_suspended_robot(n, seed=seed)
        t0 = time.perf_counter()
        res = solve_dgp(robot, lengths, max_taut=max_taut)
        t = time.perf_counter() - t0
        times.setdefault(n, []).append(t)
        total_undecided += res.undecided
        per_m = {}
        for s in res.solutions:
            per_m[len(s.taut)] = per_m.get(len(s.taut), 0) + 1
        print(
            f"{n} cables seed {seed:3d}{'' if max_taut is None else f' (max taut {max_taut})'}: "
            f"{len(res.solutions)} equilibria {dict(sorted(per_m.items(), reverse=True))}, "
            f"{res.undecided} undecided, {res.boxes} boxes, {t:.2f} s",
            flush=True,
        )
    ratio = None
    for n in sorted(times):
        r = summary(f"{n} cables", times[n])
        if n == 3:
            ratio = r
    if ns.planar:
        total_undecided += planar(ns)
    print(f"undecided boxes over the suite: {total_undecided}")
    if ratio is not None:
        print(f"3-cable worst/median: {ratio:.1f}x (target <= {RATIO_TARGET:g}x)")
    if ns.point_mass:
        point_masses(ns)
    if ns.pulleys:
        pulleys(ns)
    if ns.peer:
        peer(cases, ns.peer_mptype)
    if ns.fold:
        fold()


if __name__ == "__main__":
    started = time.perf_counter()
    main()
    print(f"suite time: {time.perf_counter() - started:.1f} s")
