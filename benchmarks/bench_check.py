"""Collision + singularity check of ``adjustable-8cable`` (8 cables, 9 platform capsules, 84
capsule pairs, 9×7 Jacobian, 6×8 structure matrix) over many poses:
:func:`taut.collision.check_poses` against a straightforward per-pose Python implementation
written here as the baseline (segment distances by the textbook clamped projections, SVD
of the Jacobian, positive span by one LP per pose with ``scipy.optimize.linprog``).

Target: >= 20 000 poses/s on one core (first JIT compile excluded).

    python benchmarks/bench_check.py [--poses 200000] [--loop 300]
"""

import argparse
import time

import numpy as np
from _common import best_of  # first: it pins the thread pools to one core
from scipy.optimize import linprog

import taut
from taut.collision import capsule_model, capsule_segments, check_poses
from taut.kinematics import actuator_jacobian


def naive_distance(p1, q1, p2, q2):
    """Closest points by alternating clamped projections plus the four end points."""
    d1, d2, r = q1 - p1, q2 - p2, p1 - p2
    a, e, b, c, f = d1 @ d1, d2 @ d2, d1 @ d2, d1 @ r, d2 @ r
    den = a * e - b * b
    s = np.clip((b * f - c * e) / den, 0, 1) if den > 1e-14 * a * e else 0.0
    t = np.clip((b * s + f) / e, 0, 1)
    s = np.clip((b * t - c) / a, 0, 1)
    cands = [np.linalg.norm(p1 + s * d1 - p2 - t * d2)]
    for p, q, x in ((p2, q2, p1), (p2, q2, q1), (p1, q1, p2), (p1, q1, q2)):
        v = q - p
        u = np.clip((x - p) @ v / (v @ v), 0, 1)
        cands.append(np.linalg.norm(p + u * v - x))
    return min(cands)


def naive_check(robot, model, pose):
    """One pose: colliding pairs, Jacobian singular, force-closure singular, min clearance."""
    A, B = capsule_segments(robot, pose[None], model=model)
    clear = []
    for i, j in model.pairs:
        clear.append(naive_distance(A[0, i], B[0, i], A[0, j], B[0, j]) - model.radii[i] - model.radii[j])
    clear = np.array(clear)
    J = actuator_jacobian(robot, pose)
    s = np.linalg.svd(J, compute_uv=False)
    W = -J[:8, :6].T
    Wn = W / np.linalg.norm(W, axis=0)
    n = Wn.shape[1]
    res = linprog(
        np.r_[np.zeros(n), -1.0],
        A_ub=np.c_[-np.eye(n), np.ones(n)],
        b_ub=np.zeros(n),
        A_eq=np.c_[Wn, np.zeros(6)],
        b_eq=np.zeros(6),
        bounds=[(0, 1)] * n + [(None, None)],
        method="highs",
    )
    closure = res.status == 0 and -res.fun > 1e-9 and np.linalg.matrix_rank(W) == 6
    return clear <= 0, s[-1] <= 1e-8 * s[0], not closure, clear.min()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--poses", type=int, default=200_000)
    ap.add_argument("--loop", type=int, default=300)
    args = ap.parse_args()

    robot = taut.example("adjustable-8cable")
    model = capsule_model(robot)
    rng = np.random.default_rng(0)
    N = args.poses
    poses = np.column_stack(
        [rng.uniform(3, 7, (N, 2)), rng.uniform(1.5, 6, N), rng.uniform(-0.4, 0.4, (N, 3)), rng.uniform(0.5, 4.4, N)]
    )
    t = time.perf_counter()
    check_poses(robot, poses[:10])
    print(
        f"robot: {robot.name}; {len(model.pairs)} capsule pairs; first call (compile or cache load): {time.perf_counter() - t:.2f} s"
    )

    dt, res = best_of(lambda: check_poses(robot, poses, model=model))
    t = time.perf_counter()
    loop = [naive_check(robot, model, p) for p in poses[: args.loop]]
    dt_l = (time.perf_counter() - t) / args.loop

    k = args.loop
    diff = sum(
        (not np.array_equal(c, res.proximity.colliding[i]))
        or j != res.jacobian_singular[i]
        or f != res.force_closure_singular[i]
        for i, (c, j, f, _) in enumerate(loop)
    )
    err = max(abs(m - res.proximity.min_clearance[i]) for i, (*_, m) in enumerate(loop))
    print(f"{N} poses: self-collision (84 pairs) + Jacobian + force-closure singularity per pose, one core")
    print(f"  check_poses   : {N / dt:>10,.0f} poses/s  (target >= 20,000)")
    print(f"  per-pose loop : {1 / dt_l:>10,.0f} poses/s  ({k} poses, extrapolated)")
    print(f"  ratio         : {dt_l * N / dt:,.0f}x")
    print(
        f"  colliding {int(res.collides.sum())}, force-closure singular {int(res.force_closure_singular.sum())}, "
        f"Jacobian singular {int(res.jacobian_singular.sum())} of {N}"
    )
    print(f"  poses where the verdicts differ: {diff}; max |clearance difference| = {err:.1e}")
    if diff or err > 1e-9:
        raise SystemExit(1)


if __name__ == "__main__":
    main()
