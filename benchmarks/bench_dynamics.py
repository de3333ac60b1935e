"""Dynamics of ``spatial-8cable`` (with an inertia tensor): batched inverse dynamics and a
1 kHz control loop.

* Inverse dynamics of a sampled motion with the closed-form distribution
  (:func:`taut.dynamics.inverse_dynamics`, compiled kernel), against a per-sample loop of the
  same function and against the statics path (the required wrench, then
  :func:`taut.statics.solve_tensions`).  Target: >= 200,000 samples/s on one core.
* Computed-torque control at 1 kHz (:func:`taut.dynamics.simulate_control`: PD on the pose
  error plus feed-forward inverse dynamics with a controller model 10 % heavy, the
  closed-form distribution in the loop, a step disturbance, one RK4 step of the plant per
  period), against MuJoCo stepping the MJCF export of the same robot (RK4, 1 ms, the tensions
  held as controls, no controller) in the same run.  Target: >= 50x real time.

  How close taut comes, and why.  On the 2-core development machine shared with other jobs,
  taut ran 52-115x real time and MuJoCo's ``mj_step`` 45-90x (the load varied between runs;
  within a run the ratio is what counts), so the whole controlled simulation runs 1.1-1.5x as
  fast as MuJoCo stepping alone.  A control update costs about
  7 us in taut's compiled loop (:func:`taut.dynamics._kernels.control_updates`: the
  Newton-Euler wrench of the controller's model, a 6x6 Cholesky for the closed-form
  distribution, and four straight-cable acceleration evaluations of the plant, without
  forming a mass matrix); the rest of taut's time (about 40 %) is sampling the reference at
  the updates and mid-periods, tabulating the disturbance and the rotation errors afterwards.
  MuJoCo is general: each of its four RK4 stages runs its whole pipeline (spatial tendons
  through sites, actuators, the 6-DOF free joint's inertia factorization, contact and
  constraint stages), plus a Python call per step.  A controller written around MuJoCo would
  add its inverse dynamics and distribution on top of that.

    python benchmarks/bench_dynamics.py [--samples 200000] [--loop 300] [--seconds 5]
"""

import argparse
import time

import numpy as np
from _common import best_of  # first: it pins the thread pools to one core

import taut
from taut.dynamics import WrenchSteps, inverse_dynamics, loop_model, required_wrench, simulate_control, with_mass_error
from taut.kinematics import batch_structure_matrices
from taut.motion import trajectory_from_waypoints
from taut.statics import solve_tensions

INERTIA = (0.12, 0.2, 0.15, 0.01, -0.02, 0.005)


def sampled_motion(n, duration=10.0):
    """Samples of a smooth 6-DOF motion with exact rates and accelerations."""
    t = np.linspace(0, duration, n)[:, None]
    a = np.array([0.1, 0.05, 0.1, 0.05, 0.05, 0.1])
    w = np.array([1.0, 1.3, 0.7, 1.1, 0.9, 1.7])
    return t[:, 0], a * np.sin(w * t), a * w * np.cos(w * t), -a * w * w * np.sin(w * t)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--samples", type=int, default=200_000)
    ap.add_argument("--loop", type=int, default=300)
    ap.add_argument("--seconds", type=float, default=5.0)
    args = ap.parse_args()

    base = taut.example("spatial-8cable")
    robot = base.model_copy(update={"platform": base.platform.model_copy(update={"inertia": INERTIA})})
    t, q, qd, qdd = sampled_motion(args.samples)
    t0 = time.perf_counter()
    inverse_dynamics(robot, q[:10], qd[:10], qdd[:10], method="closed-form")
    print(
        f"robot: {robot.name} (inertia {INERTIA}); first call (compile or cache load): {time.perf_counter() - t0:.2f} s"
    )

    dt_b, res = best_of(lambda: inverse_dynamics(robot, q, qd, qdd, method="closed-form", times=t))
    m = min(args.loop, args.samples)
    t0 = time.perf_counter()
    for k in range(m):
        inverse_dynamics(robot, q[k], qd[k], qdd[k], method="closed-form")
    dt_l = (time.perf_counter() - t0) / m

    def statics_path():
        _, W, _ = batch_structure_matrices(robot, q)
        return solve_tensions(
            W, -required_wrench(robot, q, qd, qdd), tension_bounds=robot.tension_bounds, method="closed-form"
        )

    dt_s, ref = best_of(statics_path, repeat=1)
    n = args.samples
    same = bool(np.array_equal(res.feasible, ref.feasible)) and float(np.abs(res.tensions - ref.tensions).max()) < 1e-6
    print(f"inverse dynamics, {n} samples, closed-form distribution, one core")
    print(f"  compiled batch     : {n / dt_b:>12,.0f} samples/s  (target >= 200,000)")
    print(f"  statics path       : {n / dt_s:>12,.0f} samples/s  -> batch is {dt_s / dt_b:,.1f}x faster")
    print(f"  per-sample loop    : {1 / dt_l:>12,.0f} samples/s  -> batch is {dt_l * n / dt_b:,.1f}x faster")
    print(f"  all samples feasible: {bool(res.feasible.all())}; same tensions as the statics path: {same}")

    waypoints = [[0.0, 0, 0, 0, 0, 0], [0.3, 0.1, 0.2, 0.1, -0.05, 0.2], [-0.1, 0.2, 0.1, 0, 0, 0]]
    motion = trajectory_from_waypoints(robot, waypoints, duration=args.seconds, law="quintic")
    model = with_mass_error(robot, 0.1)
    step = WrenchSteps.step(args.seconds / 4, [5.0, -3.0, 0.0, 0.0, 0.2, 0.0])
    simulate_control(robot, trajectory_from_waypoints(robot, waypoints[:2], duration=0.1))
    dt_c, res = best_of(lambda: simulate_control(robot, motion, model=model, disturbance=step), repeat=3)
    print(
        f"computed-torque control at 1 kHz ({args.seconds:g} s quintic motion, controller model 10 % heavy, "
        "a step disturbance; closed-form distribution, RK4)"
    )
    print(f"  taut simulate_control: {args.seconds / dt_c:>10,.1f}x real time  (target >= 50x)")
    print(
        f"  max position error {1e3 * res.position_error.max():.2f} mm, rotation {1e3 * res.rotation_error.max():.2f} mrad; "
        f"min tension margin {res.min_tension_margin:.1f} N; every distribution admissible: {res.all_feasible}"
    )
    lm = loop_model(robot)
    try:
        import mujoco

        from taut.model import mjcf_text, pose_to_qpos
    except ImportError:
        print("  MuJoCo not installed: no comparison")
        return
    mj = mujoco.MjModel.from_xml_string(mjcf_text(robot))
    mj.opt.timestep = 1e-3
    mj.opt.integrator = mujoco.mjtIntegrator.mjINT_RK4
    data = mujoco.MjData(mj)
    data.qpos[:] = pose_to_qpos(robot, np.zeros(6))
    data.ctrl[:] = lm.tensions(np.zeros(6), np.zeros(6), np.zeros(6))[0]
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
