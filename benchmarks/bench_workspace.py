"""Wrench-feasible workspace of ``spatial-8cable`` (box wrench set): hyperplane shifting
(:mod:`taut.statics._feasibility`) against a loop of ``scipy.optimize.linprog(method="highs")``.

Prints poses/s of the whole evaluation on one core (IK + external wrench + facet test,
first JIT compile excluded; target >= 100 000 poses/s), the facet test alone, and the
ratio against the LP loop (one LP per box vertex, stopping at the first infeasible vertex)
run over every pose of a coarser grid (the LP loop needs about a minute for 12^3 poses),
with the number of those poses where the verdicts differ (must be 0).

    python benchmarks/bench_workspace.py [--resolution 60] [--check-resolution 12]
"""

import argparse
import time

import numpy as np
from _common import best_of  # first: it pins the thread pools to one core
from scipy.optimize import linprog

import taut
from taut.kinematics import batch_structure_matrices, structure_matrix
from taut.statics import external_wrench, wrench_feasible
from taut.workspace import default_wrench_set, evaluate_workspace


def lp_verdict(W, tmin, tmax, w, vertices) -> bool:
    bounds = [(lo, None if np.isinf(hi) else hi) for lo, hi in zip(tmin, tmax)]
    for v in vertices:
        res = linprog(np.zeros(W.shape[1]), A_eq=W, b_eq=-(w + v), bounds=bounds, method="highs")
        if res.status != 0:
            return False
    return True


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--resolution", type=int, default=60)
    ap.add_argument("--check-resolution", type=int, default=12)
    args = ap.parse_args()

    robot = taut.example("spatial-8cable")
    box = default_wrench_set(robot)
    print(f"robot: {robot.name} ({robot.n_cables} cables, m = {robot.wrench_dim})")
    print(f"wrench set: box around the external wrench, half-widths {np.round(box.upper, 4).tolist()}")

    t = time.perf_counter()
    evaluate_workspace(robot, "wrench-feasible", resolution=3)  # JIT compile / cache load
    print(f"first call (compile or cache load): {time.perf_counter() - t:.2f} s")

    dt, res = best_of(lambda: evaluate_workspace(robot, "wrench-feasible", resolution=args.resolution))
    N = res.inside.size
    rate = N / dt
    print(f"\nworkspace: {N} poses ({args.resolution}^3 grid), {res.count} inside ({100 * res.fraction:.1f} %)")
    print(f"  evaluate_workspace, one core: {dt:.3f} s = {rate:,.0f} poses/s (target >= 100,000)")

    poses = res.poses
    _, W, ok = batch_structure_matrices(robot, poses)
    w = external_wrench(robot, poses)
    tmin, tmax = robot.tension_bounds
    dt_k, _ = best_of(lambda: wrench_feasible(W, box, tension_bounds=(tmin, tmax), wrench=w))
    dt_ik, _ = best_of(lambda: batch_structure_matrices(robot, poses))
    dt_w, _ = best_of(lambda: external_wrench(robot, poses))
    print(
        f"  parts: facet test {N / dt_k:,.0f} poses/s, batch IK {N / dt_ik:,.0f} poses/s, external wrench {N / dt_w:,.0f} poses/s"
    )

    check = evaluate_workspace(robot, "wrench-feasible", resolution=args.check_resolution)
    Ws = structure_matrix(robot, check.poses)
    ws = external_wrench(robot, check.poses)
    vertices = box.vertices()
    t = time.perf_counter()
    lp = np.array([lp_verdict(Ws[k], tmin, tmax, ws[k], vertices) for k in range(len(Ws))])
    dt_lp = time.perf_counter() - t
    per_pose_lp = dt_lp / len(Ws)
    differ = int(np.count_nonzero(lp != check.inside))
    print(f"\nbaseline: linprog(method='highs') over the {len(vertices)} box vertices (stop at the first infeasible)")
    print(
        f"  every pose of the {args.check_resolution}^3 grid: {len(Ws)} poses ({int(lp.sum())} feasible) "
        f"in {dt_lp:.2f} s = {1 / per_pose_lp:,.1f} poses/s"
    )
    print(f"  extrapolated to the {args.resolution}^3 grid: {per_pose_lp * N:,.0f} s vs {dt:.3f} s")
    print(f"  speed-up of evaluate_workspace over the LP loop: {per_pose_lp * rate:,.0f}x")
    print(f"  poses where the verdicts differ: {differ} of {len(Ws)} (must be 0)")
    if differ:
        raise SystemExit(1)


if __name__ == "__main__":
    main()
