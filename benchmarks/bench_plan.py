"""Wrench-feasible path planning on the NIST Robocrane (Bohigas et al. 2013, §5):
the queries q1 → q2 and q3 → q4 on the slice p = (0, 0, 2), σ = 35°, by A* over a growing
atlas (:func:`taut.planning.plan_path`), against the paper's 20 s and 280 s (C, 2.66 GHz
Core i7) and, measured in the same run, the uninformed baseline: the atlas grown
breadth-first (charts closed in creation order, Henderson's plain continuation) until a
chart reaches the goal.  q3, q4 are the wrench-feasible replacements of the file
(robocrane.yaml, reference.notes): the published τ_3, τ_4 are not feasible under our
reading of §5, so the 280 s ratio compares queries of the same kind, not the same query.

Peers on the same queries (``--no-peers`` skips them): the straight line start → goal in
pose space, checked by :func:`~taut.planning.verify.verify_path` every ``--resolution``
rad; and, when the optional peer OMPL is installed (``pip install ompl``, or
``pip install -e '.[bench]'``), RRTConnect in the (φ, θ) square [−π, π] × [0, π] of the
slice, its state validity checker the same independent test at one pose, its motion
checked every ``--resolution`` rad, within ``--ompl-time`` s; ``--repeat`` trials (seed 1),
each path then checked by ``verify_path`` every ``--resolution`` rad.

    python benchmarks/bench_plan.py [--radius 0.2] [--repeat 3] [--max-charts 20000]
                                    [--no-peers] [--resolution 0.01] [--ompl-time 30]
"""

import argparse
import gc
import time

import numpy as np
from _common import best_of  # first: it pins the thread pools to one core

import taut
from taut.planning import Atlas, plan_path
from taut.planning.manifold import WrenchFeasibleManifold
from taut.planning.verify import verify_path

PAPER_S = {("q1", "q2"): 20.0, ("q3", "q4"): 280.0}
FREE = (3, 4)  # φ, θ in a pose [x, y, z, φ, θ, σ]


def densify(poses, step):
    """The polyline ``poses`` ``(M, 6)`` with every segment cut into pieces of at most ``step``."""
    poses = np.asarray(poses, float)
    out = [poses[:1]]
    for a, b in zip(poses[:-1], poses[1:]):
        n = max(1, int(np.ceil(np.linalg.norm(b - a) / step)))
        out.append(a + np.linspace(0.0, 1.0, n + 1)[1:, None] * (b - a))
    return np.vstack(out)


def straight_line(robot, start, goal, step):
    t = time.perf_counter()
    check = verify_path(robot, densify([start, goal], step), subdivide=1)
    return time.perf_counter() - t, check


_SEEDED = []


def ompl_rrtconnect(robot, start, goal, step, budget, trials, seed=1):
    """RRTConnect in the (φ, θ) square; ``None`` when OMPL is absent, else one
    ``(solved, exact, seconds, validity calls, waypoints, check)`` per trial."""
    try:
        from ompl import base as ob
        from ompl import geometric as og
        from ompl import util as ou
    except ImportError:
        return None
    ou.setLogLevel(ou.LogLevel.LOG_WARN)
    bounds = ob.RealVectorBounds(2)
    for i, (lo, hi) in enumerate([(-np.pi, np.pi), (0.0, np.pi)]):
        bounds.setLow(i, lo)
        bounds.setHigh(i, hi)
    space = ob.RealVectorStateSpace(2)
    space.setBounds(bounds)
    counter = [0]

    def pose(phi, theta):
        q = start.copy()
        q[list(FREE)] = phi, theta
        return q

    def valid(s):
        counter[0] += 1
        return bool(verify_path(robot, pose(s[0], s[1])[None], subdivide=1).feasible[0])

    if not _SEEDED:  # OMPL takes one global seed, before its first random number
        ou.RNG.setSeed(seed)
        _SEEDED.append(seed)
    runs = []
    for _ in range(trials):
        ss = og.SimpleSetup(space)
        ss.setStateValidityChecker(valid)
        si = ss.getSpaceInformation()
        si.setStateValidityCheckingResolution(step / space.getMaximumExtent())
        ss.setPlanner(og.RRTConnect(si))
        a, b = space.allocState(), space.allocState()
        a[0], a[1] = start[FREE[0]], start[FREE[1]]
        b[0], b[1] = goal[FREE[0]], goal[FREE[1]]
        ss.setStartAndGoalStates(a, b)
        counter[0] = 0
        t = time.perf_counter()
        solved = bool(ss.solve(budget))
        dt = time.perf_counter() - t
        exact = ss.haveExactSolutionPath()
        poses = np.array([pose(s[0], s[1]) for s in ss.getSolutionPath().getStates()]) if solved else None
        check = verify_path(robot, densify(poses, step), subdivide=1) if exact else None
        runs.append((solved, exact, dt, counter[0], poses, check))
        del ss, si, a, b
        gc.collect()
    return runs


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radius", type=float, default=0.2)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--max-charts", type=int, default=20000)
    ap.add_argument(
        "--peers",
        action=argparse.BooleanOptionalAction,
        default=True,
        help="also run the straight-line check and OMPL RRTConnect (if installed)",
    )
    ap.add_argument(
        "--resolution", type=float, default=0.01, help="rad between checked poses on straight lines and OMPL motions"
    )
    ap.add_argument("--ompl-time", type=float, default=30.0, help="OMPL time budget per trial, s")
    ns = ap.parse_args()
    robot = taut.load_robot("robocrane")
    P = {k: np.array(v) for k, v in robot.reference.poses.items()}
    M = WrenchFeasibleManifold.from_robot(robot, fixed=dict(x=0.0, y=0.0, z=2.0, sigma=7 * np.pi / 36))
    mf = M.implicit()
    for (a, b), paper_s in PAPER_S.items():
        y1, y2 = M.lift(P[a]), M.lift(P[b])
        t_astar, res = best_of(
            lambda: plan_path(mf, y1, y2, ns.radius, metric=M.pose_metric, max_charts=ns.max_charts),  # noqa: B023
            ns.repeat,
        )
        check = verify_path(robot, M.pose(res.path), subdivide=10) if res.found else None

        def breadth_first(y1=y1, y2=y2):
            atlas = Atlas(mf, y1, ns.radius, metric=M.pose_metric)
            i = 0
            while i < len(atlas.charts) and len(atlas.charts) < ns.max_charts:
                if atlas.reaches(i, y2):
                    return atlas, True
                atlas.grow(i)
                i += 1
            return atlas, False

        t_full, (atlas, done) = best_of(breadth_first, 1)
        print(f"robocrane {a} -> {b}, chart radius {ns.radius}")
        print(
            f"  A*: found {res.found}, {res.charts} charts ({res.expanded} closed), path length "
            f"{res.length:.3f} rad, {t_astar:.3f} s"
        )
        if check is not None:
            print(
                f"  independent check at {check.poses.shape[0]} interpolated poses: all feasible {check.all_feasible}"
            )
        print(
            f"  breadth-first atlas: reached {b} {done}, {len(atlas.charts)} charts, {t_full:.3f} s "
            f"(A* speed-up {t_full / t_astar:.1f}x)"
        )
        print(f"  paper (C): {paper_s:.0f} s; ratio paper / taut A*: {paper_s / t_astar:.1f}x")
        if not ns.peers:
            continue
        t_line, line = straight_line(robot, P[a], P[b], ns.resolution)
        bad = int((~line.feasible).sum())
        print(
            f"  straight line: feasible {line.all_feasible} ({bad} of {line.poses.shape[0]} points "
            f"infeasible), {t_line:.3f} s"
        )
        runs = ompl_rrtconnect(robot, P[a], P[b], ns.resolution, ns.ompl_time, ns.repeat)
        if runs is None:
            print("  OMPL not installed (optional peer: pip install ompl)")
            continue
        for trial, (_solved, exact, dt, calls, poses, ck) in enumerate(runs, 1):
            line = (
                f"  OMPL RRTConnect (trial {trial}, budget {ns.ompl_time:.0f} s): solved {exact}, "
                f"{dt:.3f} s, {calls} validity checks"
            )
            if ck is not None:
                length = np.linalg.norm(np.diff(poses[:, FREE], axis=0), axis=1).sum()
                line += (
                    f", {poses.shape[0]} waypoints, length {length:.3f} rad; check at "
                    f"{ck.poses.shape[0]} poses: {int(ck.feasible.sum())} feasible "
                    f"(path valid {ck.all_feasible}); time taut A* / OMPL: {t_astar / dt:.1f}x"
                )
            print(line)


if __name__ == "__main__":
    main()
