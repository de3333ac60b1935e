"""Sagging cables: the static inverse kinematics of ``spatial-8cable`` with heavy elastic
cables (:func:`taut.cables.sagging_ik`, the tension distribution iterated to consistency with
Irvine's elastic catenaries) and its sag-aware static workspace grid (``sagging-static``),
each against the straight-cable computation in the same run.

Stated cables: 0.5 N/m (about a 3 mm steel rope) and EA = 1e5 N on the robot's 3 m x 2 m x
2 m frame, tensions 5 N to 500 N.  Targets: >= 20 000 poses/s for the IK, >= 2 000 poses/s
for the grid, on one core.

    python benchmarks/bench_sag.py [--poses 100000] [--resolution 21]
"""

import argparse
import collections

import numpy as np
from _common import best_of  # first: it pins the thread pools to one core

import taut
from taut.cables import sagging_ik
from taut.statics import distribute_tensions
from taut.workspace import evaluate_workspace

WEIGHT = 0.5
STIFFNESS = 1e5


def heavy(robot, weight=WEIGHT, stiffness=STIFFNESS):
    return robot.model_copy(
        update={"cables": tuple(c.model_copy(update={"weight": weight, "stiffness": stiffness}) for c in robot.cables)}
    )


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--poses", type=int, default=100_000)
    ap.add_argument("--resolution", type=int, default=21)
    ap.add_argument("--method", default="improved-closed-form")
    args = ap.parse_args()

    straight = taut.example("spatial-8cable")
    robot = heavy(straight)
    rng = np.random.default_rng(0)
    n = args.poses
    poses = np.concatenate(
        [rng.uniform([-0.6, -0.4, -0.4], [0.6, 0.4, 0.4], (n, 3)), rng.uniform(-0.1, 0.1, (n, 3))], axis=1
    )
    sagging_ik(robot, poses[:10], method=args.method)
    print(f"robot: {robot.name}, cables {WEIGHT} N/m, EA {STIFFNESS:g} N; tension distribution {args.method}")

    dt_s, res = best_of(lambda: sagging_ik(robot, poses, method=args.method), repeat=2)
    dt_0, ref = best_of(lambda: distribute_tensions(straight, poses, method=args.method), repeat=2)
    ok = res.feasible
    residual = np.abs(np.einsum("kij,kj->ki", res.structure_matrix[ok], res.platform_tensions[ok]))
    residual = (residual + taut.statics.external_wrench(robot, poses[ok])).__abs__().max()
    print(f"{n} poses, static IK with sagging cables (8 cables), one core")
    print(f"  sagging_ik          : {n / dt_s:>10,.0f} poses/s  (target >= 20,000)")
    print(f"  straight tensions   : {n / dt_0:>10,.0f} poses/s  (distribute_tensions, the same method)")
    print(f"  sag / straight time : {dt_s / dt_0:.1f}x")
    print(f"  statuses: {dict(collections.Counter(res.status.tolist()))}; steps: median {int(np.median(res.steps))}")
    print(f"  largest sag {res.sag.max():.4f} m, largest equilibrium residual {residual:.2e} N")

    r = args.resolution
    grid = [(-1.44, 1.44, r), (-0.96, 0.96, r), (-0.96, 0.96, r)]
    evaluate_workspace(robot, "sagging-static", grid=[(0, 0, 1)] * 3)
    dt_w, ws = best_of(lambda: evaluate_workspace(robot, "sagging-static", grid=grid), repeat=1)
    dt_w0, ws0 = best_of(lambda: evaluate_workspace(straight, "static", grid=grid), repeat=1)
    print(f"sag-aware static workspace grid {r}^3 = {ws.size} poses, one core")
    print(f"  sagging-static      : {ws.size / dt_w:>10,.0f} poses/s  (target >= 2,000); {ws.count} inside")
    print(f"  static (straight)   : {ws.size / dt_w0:>10,.0f} poses/s; {ws0.count} inside")
    print(f"  sag / straight time : {dt_w / dt_w0:.1f}x")
    light = heavy(straight, weight=1e-12, stiffness=None)
    small = [(-1.44, 1.44, 5), (-0.96, 0.96, 5), (-0.96, 0.96, 5)]
    a = evaluate_workspace(light, "sagging-static", grid=small).inside
    b = evaluate_workspace(straight, "static", grid=small).inside
    print(
        f"weight 1e-12 N/m against straight cables, {a.size} poses: poses where the verdicts differ: {int((a != b).sum())}"
    )


if __name__ == "__main__":
    main()
