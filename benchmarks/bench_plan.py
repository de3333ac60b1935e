"""Wrench-feasible path planning on the NIST Robocrane (``002_19d5d688a3999fb0.txt`` §5):
the queries q1 → q2 and q3 → q4 on the slice p = (0, 0, 2), σ = 35°, by A* over a growing
atlas (:func:`taut.planning.plan_path`), against the paper's 20 s and 280 s (C, 2.66 GHz
Core i7) and, measured in the same run, the uninformed baseline: the atlas grown
breadth-first (charts closed in creation order, Henderson's plain continuation) until a
chart reaches the goal.  q3, q4 are the wrench-feasible replacements of the file
(robocrane.yaml, reference.notes): the published τ_3, τ_4 are not feasible under our
reading of §5, so the 280 s ratio compares queries of the same kind, not the same query.

    python benchmarks/bench_plan.py [--radius 0.2] [--repeat 3] [--max-charts 20000]
"""

from _common import best_of  # first: it pins the thread pools to one core

import argparse

import numpy as np

import taut
from taut.planning import Atlas, plan_path
from taut.planning.manifold import WrenchFeasibleManifold
from taut.planning.verify import verify_path

PAPER_S = {("q1", "q2"): 20.0, ("q3", "q4"): 280.0}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radius", type=float, default=0.2)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--max-charts", type=int, default=20000)
    ns = ap.parse_args()
    robot = taut.load_robot("robocrane")
    P = {k: np.array(v) for k, v in robot.reference.poses.items()}
    M = WrenchFeasibleManifold.from_robot(robot, fixed=dict(x=0.0, y=0.0, z=2.0, sigma=7 * np.pi / 36))
    mf = M.implicit()
    for (a, b), paper_s in PAPER_S.items():
        y1, y2 = M.lift(P[a]), M.lift(P[b])
        t_astar, res = best_of(lambda: plan_path(mf, y1, y2, ns.radius, metric=M.pose_metric,
                                                 max_charts=ns.max_charts), ns.repeat)
        check = verify_path(robot, M.pose(res.path), subdivide=10) if res.found else None

        def breadth_first():
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
        print(f"  A*: found {res.found}, {res.charts} charts ({res.expanded} closed), path length "
              f"{res.length:.3f} rad, {t_astar:.3f} s")
        if check is not None:
            print(f"  independent check at {check.poses.shape[0]} interpolated poses: all feasible "
                  f"{check.all_feasible}")
        print(f"  breadth-first atlas: reached {b} {done}, {len(atlas.charts)} charts, {t_full:.3f} s "
              f"(A* speed-up {t_full / t_astar:.1f}x)")
        print(f"  paper (C): {paper_s:.0f} s; ratio paper / taut A*: {paper_s / t_astar:.1f}x")


if __name__ == "__main__":
    main()
