"""Dynamics of ``spatial-8cable`` (with an inertia tensor): batched inverse dynamics and a
1 kHz control loop.

* Inverse dynamics of a sampled motion with the closed-form distribution
  (:func:`taut.dynamics.inverse_dynamics`, compiled kernel), against a per-sample loop of the
  same function and against the statics path (the required wrench, then
  :func:`taut.statics.tension.solve_tensions`).  Target: >= 200,000 samples/s on one core.
* A 1 kHz loop of PD plus feed-forward inverse dynamics with the closed-form distribution in
  the loop and one RK4 step per period (:class:`taut.dynamics.LoopModel`), against MuJoCo
  stepping the MJCF export of the same robot (RK4, 1 ms, the tensions as controls) in the same
  run.  Target: >= 50x real time.

    python benchmarks/bench_dynamics.py [--samples 200000] [--loop 300] [--seconds 5]
"""

import argparse
import time

import numpy as np
from _common import best_of  # first: it pins the thread pools to one core

import taut
from taut.dynamics import inverse_dynamics, loop_model, required_wrench
from taut.kinematics.batch import batch_structure_matrices
from taut.statics.tension import solve_tensions

INERTIA = (0.12, 0.2, 0.15, 0.01, -0.02, 0.005)


def motion(n, duration=10.0):
    """Samples of a smooth 6-DOF motion with exact rates and accelerations."""
    t = np.linspace(0, duration, n)[:, None]
    a = np.array([0.1, 0.05, 0.1, 0.05, 0.05, 0.1])
    w = np.array([1.0, 1.3, 0.7, 1.1, 0.9, 1.7])
    return t[:, 0], a * np.sin(w * t), a * w * np.cos(w * t), -a * w * w * np.sin(w * t)


def control_loop(model, q_goal, seconds, dt=1e-3):
    """PD on the pose error plus feed-forward inverse dynamics at 1/dt Hz; returns the
    final pose error and whether every distribution was admissible."""
    x, v = np.zeros(6), np.zeros(6)
    ok_all = True
    for _ in range(int(round(seconds / dt))):
        tau, ok = model.tensions(x, v, -40.0 * (x - q_goal) - 12.0 * v)
        ok_all &= ok
        x, v = model.step(x, v, tau, dt)
    return float(np.abs(x - q_goal).max()), ok_all


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--samples", type=int, default=200_000)
    ap.add_argument("--loop", type=int, default=300)
    ap.add_argument("--seconds", type=float, default=5.0)
    args = ap.parse_args()

    base = taut.example("spatial-8cable")
    robot = base.model_copy(update={"platform": base.platform.model_copy(update={"inertia": INERTIA})})
    t, q, qd, qdd = motion(args.samples)
    t0 = time.perf_counter()
    inverse_dynamics(robot, q[:10], qd[:10], qdd[:10], method="closed-form")
    print(
        f"robot: {robot.name} (inertia {INERTIA}); first call (compile or cache load): {time.perf_counter() - t0:.2f} s"
    )

    dt_b, res = best_of(lambda: inverse_dynamics(robot, q, qd, qdd, method="closed-form", time=t))
    m = min(args.loop, args.samples)
    t0 = time.perf_counter()
    for k in range(m):
        inverse_dynamics(robot, q[k], qd[k], qdd[k], method="closed-form")
    dt_l = (time.perf_counter() - t0) / m

    def statics_path():
        _, W, _ = batch_structure_matrices(robot, q)
        lo, hi = robot.tension_bounds
        return solve_tensions(W, -required_wrench(robot, q, qd, qdd), lo, hi, "closed-form")

    dt_s, ref = best_of(statics_path, repeat=1)
    n = args.samples
    same = bool(np.array_equal(res.feasible, ref.feasible)) and float(np.abs(res.tensions - ref.tensions).max()) < 1e-6
    print(f"inverse dynamics, {n} samples, closed-form distribution, one core")
    print(f"  compiled batch     : {n / dt_b:>12,.0f} samples/s  (target >= 200,000)")
    print(f"  statics path       : {n / dt_s:>12,.0f} samples/s  -> batch is {dt_s / dt_b:,.1f}x faster")
    print(f"  per-sample loop    : {1 / dt_l:>12,.0f} samples/s  -> batch is {dt_l * n / dt_b:,.1f}x faster")
    print(f"  all samples feasible: {bool(res.feasible.all())}; same tensions as the statics path: {same}")

    model = loop_model(robot)
    goal = np.array([0.1, -0.05, 0.08, 0.05, -0.03, 0.1])
    control_loop(model, goal, 0.01)
    dt_c, (err, ok) = best_of(lambda: control_loop(model, goal, args.seconds), repeat=1)
    print(f"control at 1 kHz (PD + feed-forward, closed-form distribution, RK4), {args.seconds:g} s simulated")
    print(f"  taut LoopModel     : {args.seconds / dt_c:>10,.1f}x real time  (target >= 50x)")
    print(f"  final pose error {err:.2e}; every distribution admissible: {ok}")
    try:
        import mujoco

        from taut.model.mjcf import mjcf_text, pose_to_qpos
    except ImportError:
        print("  MuJoCo not installed: no comparison")
        return
    mj = mujoco.MjModel.from_xml_string(mjcf_text(robot))
    mj.opt.timestep = 1e-3
    mj.opt.integrator = mujoco.mjtIntegrator.mjINT_RK4
    data = mujoco.MjData(mj)
    data.qpos[:] = pose_to_qpos(robot, np.zeros(6))
    data.ctrl[:] = model.tensions(np.zeros(6), np.zeros(6), np.zeros(6))[0]
    steps = int(round(args.seconds / 1e-3))

    def mj_run():
        for _ in range(steps):
            mujoco.mj_step(mj, data)

    dt_m, _ = best_of(mj_run, repeat=1)
    print(
        f"  MuJoCo mj_step     : {args.seconds / dt_m:>10,.1f}x real time  (RK4 step only, tensions held, no controller)"
    )
    print(f"  taut with its controller and distribution vs MuJoCo stepping alone: {dt_m / dt_c:,.2f}x")


if __name__ == "__main__":
    main()
