"""Calibration of an 8-cable robot (:func:`taut.calibration.calibrate`): exits and encoder offsets
with every pose unknown, by the sparse bundle adjustment against the same fit with a dense
Jacobian (``least_squares`` with the dense trust-region solver) as the baseline, for the
random point-mass robot and the rigid spatial 8-cable robot; the growth of
the time with the rows; and the parameter errors after planned (D-optimal,
:func:`taut.calibration.plan_poses`) and random feasible poses.

Targets: 8 cables, 100 unknown poses, exits and offsets in <= 1 s; 10 000 rows in <= 30 s,
growing linearly.

    python benchmarks/bench_calibrate.py [--rows 1000,3000,10000] [--trials 10] [--dense-poses 100]
"""

import argparse

import numpy as np
from _common import best_of  # first: it pins the thread pools to one core

from taut.calibration import calibrate, measurements, plan_poses, simulate_measurements
from taut.model import example, random_point_mass_robot
from taut.workspace import default_bounds, evaluate_workspace


def built(robot, rng, exit_error=0.05):
    return robot.exits + rng.uniform(-exit_error, exit_error, robot.exits.shape)


def lengths(exits, robot, poses):
    """Point-mass lengths by plain norms (the bench's own model)."""
    return np.linalg.norm(exits[None] - poses[:, None, : robot.dimension], axis=2)


def aligned(source, target):
    cs, ct = source.mean(0), target.mean(0)
    U, _, Vt = np.linalg.svd((source - cs).T @ (target - ct))
    D = np.eye(len(U))
    D[-1, -1] = np.sign(np.linalg.det(Vt.T @ U.T))
    return (source - cs) @ (Vt.T @ D @ U.T).T + ct


def random_feasible(robot, n, rng):
    box = default_bounds(robot, shrink=0.1)
    out = np.zeros((0, robot.pose_size))
    while len(out) < n:
        poses = rng.uniform(box[:, 0], box[:, 1], (4 * n, robot.dimension))
        out = np.vstack([out, poses[evaluate_workspace(robot, "wrench-feasible", poses=poses).inside]])
    return out[:n]


def dataset(robot, poses, rng, sigma=5e-4):
    exits = built(robot, rng)
    offsets = 1.0 + rng.uniform(-0.1, 0.1, robot.n_cables)
    dl = lengths(exits, robot, poses) - offsets + rng.normal(0, sigma, (len(poses), robot.n_cables))
    return measurements(robot, changes=dl), exits, offsets


def error(robot, res, exits, offsets):
    """RMS error of exits (in the estimate's gauge) and offsets [m]."""
    e = np.concatenate([(res.exits - aligned(exits, robot.exits)).ravel(), res.offsets - offsets])
    return float(np.sqrt(np.mean(e**2)))


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--rows", default="1000,3000,10000", help="row counts of the growth test")
    ap.add_argument("--trials", type=int, default=10, help="trials of planned vs random poses")
    ap.add_argument("--plan", type=int, default=30, help="poses planned / drawn per trial")
    ap.add_argument("--dense-poses", type=int, default=100)
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    robot, _ = random_point_mass_robot(8, seed=4)
    rng = np.random.default_rng(0)

    poses = random_feasible(robot, args.dense_poses, rng)
    data, exits, offsets = dataset(robot, poses, rng)
    calibrate(robot, data)  # warm the imports
    t_sparse, res = best_of(lambda: calibrate(robot, data), args.repeat)
    t_dense, dense = best_of(lambda: calibrate(robot, data, dense=True), 1)
    print(
        f"{robot.name}: 8 cables, {len(poses)} unknown poses, exits and offsets ({res.identifiability.unknowns} unknowns)"
    )
    print(f"  sparse Jacobian: {t_sparse:.3f} s, parameter error {error(robot, res, exits, offsets) * 1000:.3f} mm")
    print(f"  dense Jacobian:  {t_dense:.3f} s, parameter error {error(robot, dense, exits, offsets) * 1000:.3f} mm")
    print(
        f"  dense / sparse time: {t_dense / t_sparse:.1f}x; same estimate within {np.abs(res.exits - dense.exits).max() * 1000:.2g} mm"
    )

    rigid = example("spatial-8cable")
    box = np.array([[-0.6, 0.6], [-0.4, 0.4], [-0.4, 0.4]])
    rposes = np.zeros((args.dense_poses, 6))
    rposes[:, :3] = rng.uniform(box[:, 0], box[:, 1], (args.dense_poses, 3))
    rexits = built(rigid, rng)
    rtrue = rigid.model_copy(
        update={"cables": tuple(c.model_copy(update={"exit": tuple(e)}) for c, e in zip(rigid.cables, rexits))}
    )
    rdata = simulate_measurements(rtrue, rposes, offsets=1.0 + rng.uniform(-0.1, 0.1, 8), sigma=5e-4, seed=1)
    t_rigid, rres = best_of(lambda: calibrate(rigid, rdata), 1)
    t_rdense, rdense = best_of(lambda: calibrate(rigid, rdata, dense=True), 1)
    print(f"{rigid.name} (rigid, 6 pose coordinates): 8 cables, {len(rposes)} unknown poses, exits and offsets")
    print(f"  sparse Jacobian: {t_rigid:.3f} s, residual {rres.sigma * 1000:.3f} mm")
    print(f"  dense Jacobian:  {t_rdense:.3f} s, residual {rdense.sigma * 1000:.3f} mm")
    print(f"  dense / sparse time: {t_rdense / t_rigid:.1f}x")

    print("growth with the rows (sparse Jacobian):")
    per_row = []
    for n_rows in [int(v) for v in args.rows.split(",")]:
        p = random_feasible(robot, n_rows, rng)
        d, ex, off = dataset(robot, p, rng)
        t, r = best_of(lambda d=d: calibrate(robot, d), 1)
        per_row.append(t / n_rows)
        print(
            f"  {n_rows:6d} rows: {t:7.2f} s ({t / n_rows * 1e3:.2f} ms per row), parameter error {error(robot, r, ex, off) * 1000:.3f} mm"
        )
    print(f"  time per row, last over first: {per_row[-1] / per_row[0]:.2f} (1 = linear)")

    planned_err, random_err = [], []
    plan = plan_poses(robot, args.plan, seed=0).poses
    for trial in range(args.trials):
        trng = np.random.default_rng(100 + trial)
        d, ex, off = dataset(robot, plan, trng)
        planned_err.append(error(robot, calibrate(robot, d), ex, off))
        rp = random_feasible(robot, args.plan, trng)
        d, ex, off = dataset(robot, rp, np.random.default_rng(100 + trial))
        random_err.append(error(robot, calibrate(robot, d), ex, off))
    print(
        f"{args.plan} planned poses: parameter error {np.mean(planned_err) * 1000:.3f} mm; "
        f"{args.plan} random feasible poses: {np.mean(random_err) * 1000:.3f} mm "
        f"(mean of {args.trials} trials; random / planned {np.mean(random_err) / np.mean(planned_err):.2f})"
    )


if __name__ == "__main__":
    main()
