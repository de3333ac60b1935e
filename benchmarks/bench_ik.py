"""Inverse kinematics + structure matrix of ``spatial-8cable`` over many poses: the Numba
batch kernel (:mod:`taut.kinematics._batch`) and the full
:func:`taut.kinematics.inverse_kinematics` (lengths, directions, anchors, W) against a
straightforward per-pose NumPy loop written here as the baseline.

Target: >= 1 000 000 poses/s on one core (first JIT compile excluded).

    python benchmarks/bench_ik.py [--poses 1000000] [--loop 5000]
"""

import argparse
import time

import numpy as np
from _common import best_of  # first: it pins the thread pools to one core

import taut
from taut.kinematics import batch_structure_matrices, inverse_kinematics


def naive_structure_matrix(robot, pose):
    """The textbook computation, one pose at a time (the baseline)."""
    from taut.geometry import rotation_matrix

    p, R = pose[:3], rotation_matrix(pose[3:], robot.orientation)
    cols = []
    for a, r in zip(robot.exits, robot.anchors):
        arm = R @ r
        v = a - (p + arm)
        u = v / np.linalg.norm(v)
        cols.append(np.concatenate([u, np.cross(arm, u)]))
    return np.array(cols).T


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--poses", type=int, default=1_000_000)
    ap.add_argument("--loop", type=int, default=5000)
    args = ap.parse_args()

    robot = taut.example("spatial-8cable")
    rng = np.random.default_rng(0)
    poses = np.concatenate([rng.uniform(-0.6, 0.6, (args.poses, 3)), rng.uniform(-0.3, 0.3, (args.poses, 3))], axis=1)
    t = time.perf_counter()
    batch_structure_matrices(robot, poses[:10])
    print(f"robot: {robot.name}; first call (compile or cache load): {time.perf_counter() - t:.2f} s")

    dt_b, (lengths, W, ok) = best_of(lambda: batch_structure_matrices(robot, poses))
    dt_n, ik = best_of(lambda: inverse_kinematics(robot, poses))
    t = time.perf_counter()
    loop = [naive_structure_matrix(robot, p) for p in poses[: args.loop]]
    dt_l = (time.perf_counter() - t) / args.loop
    err = float(np.abs(W - ik.structure_matrix).max())
    err_loop = float(np.abs(W[: args.loop] - np.array(loop)).max())

    n = len(poses)
    print(f"{n} poses, lengths + structure matrix (6 x 8) per pose, one core")
    print(f"  Numba batch kernel : {n / dt_b:>12,.0f} poses/s  (target >= 1,000,000)")
    print(f"  inverse_kinematics : {n / dt_n:>12,.0f} poses/s  (lengths, directions, anchors, W)")
    print(f"  per-pose loop      : {1 / dt_l:>12,.0f} poses/s  ({args.loop} poses, extrapolated)")
    print(f"  ratio batch / loop : {dt_l * n / dt_b:,.0f}x;  batch / inverse_kinematics: {dt_n / dt_b:.1f}x")
    print(
        f"  max |W_batch - W_inverse_kinematics| = {err:.1e}, vs loop {err_loop:.1e}; all poses valid: {bool(ok.all())}"
    )
    if err > 1e-12 or err_loop > 1e-12:
        raise SystemExit(1)


if __name__ == "__main__":
    main()
