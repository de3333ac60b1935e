"""Dynamics of ``spatial-8cable`` (with an inertia tensor), of ``adjustable-8cable`` (jointed) and
of ``spatial-8cable`` with swivelling pulleys: batched inverse dynamics and a 1 kHz control loop.

* Inverse dynamics of a sampled motion with the closed-form distribution
  (:func:`taut.dynamics.inverse_dynamics`, compiled kernel), against a per-sample loop of the
  same function and against the statics path (the required wrench, then
  :func:`taut.statics.solve_tensions`).  Target: >= 200,000 samples/s on one core.
* Computed-torque control at 1 kHz (:func:`taut.dynamics.simulate_control`: PD on the pose
  error plus feed-forward inverse dynamics with a controller model 10 % heavy, the
  closed-form distribution in the loop, a step disturbance, one RK4 step of the plant per
  period), against MuJoCo stepping the MJCF export of the same robot (RK4, 1 ms, the tensions
  held as controls, no controller) in the same run.  Target: >= 50x real time.
* The same for ``adjustable-8cable`` with its assumed masses (the
  source gives none; a 20 kg platform, an 8 kg upper body on a passive prismatic joint):
  inverse dynamics through the compiled body tree (:mod:`taut.dynamics._tree`) against the
  NumPy equations of motion and jointed structure matrix, target >= 100,000 samples/s; 1 kHz
  computed-torque control, target >= 20x real time, against MuJoCo stepping the exported
  model (RK4, 1 ms, the tensions held, the joint's motor at zero).  Measured on the 2-core
  machine: 220,000-300,000 samples/s (12x the NumPy path), 45x real time, MuJoCo 58x: the
  whole controlled jointed simulation runs at 0.8x MuJoCo's stepping alone (each state forms
  the 7x7 mass matrix from the bodies' Jacobians and factorizes it, where the platform alone
  needs no matrix).
* spatial-8cable with 3 cm swivelling pulleys in the same control run (the tangent point and
  the wound arc in every kernel), target >= 50x real time, against the fixed exit points'
  run: measured 80x, 1.5x the cost of straight cables.

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


def control_run(robot, seconds):
    """``(best wall time, result)`` of 1 kHz computed-torque control along a quintic motion
    through three waypoints, the controller's model 10 % heavy, a step disturbance at a
    quarter of the run (compiled outside the timing)."""
    waypoints = [[0.0, 0, 0, 0, 0, 0], [0.3, 0.1, 0.2, 0.1, -0.05, 0.2], [-0.1, 0.2, 0.1, 0, 0, 0]]
    motion = trajectory_from_waypoints(robot, waypoints, duration=seconds, law="quintic")
    model = with_mass_error(robot, 0.1)
    step = WrenchSteps.step(seconds / 4, [5.0, -3.0, 0.0, 0.0, 0.2, 0.0])
    simulate_control(robot, trajectory_from_waypoints(robot, waypoints[:2], duration=0.1))
    return best_of(lambda: simulate_control(robot, motion, model=model, disturbance=step), repeat=3)


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

    dt_c, res = control_run(robot, args.seconds)
    print(
        f"computed-torque control at 1 kHz ({args.seconds:g} s quintic motion, controller model 10 % heavy, "
        "a step disturbance; closed-form distribution, RK4)"
    )
    print(f"  taut simulate_control: {args.seconds / dt_c:>10,.1f}x real time  (target >= 50x)")
    print(
        f"  max position error {1e3 * res.position_error.max():.2f} mm, rotation {1e3 * res.rotation_error.max():.2f} mrad; "
        f"min tension margin {res.min_tension_margin:.1f} N; every distribution admissible: {res.all_feasible}"
    )
    dt_m = mujoco_seconds(
        robot, np.zeros(6), loop_model(robot).tensions(np.zeros(6), np.zeros(6), np.zeros(6))[0], args.seconds
    )
    if dt_m is None:
        print("  MuJoCo not installed: no comparison")
    else:
        print(
            f"  MuJoCo mj_step     : {args.seconds / dt_m:>10,.1f}x real time  (RK4 step only, tensions held, no controller)"
        )
        print(f"  taut with its controller and distribution vs MuJoCo stepping alone: {dt_m / dt_c:,.2f}x")
    jointed(args)
    pulleys(args, robot, dt_c)


def mujoco_seconds(robot, q0, tensions, seconds):
    """Wall time of MuJoCo stepping the MJCF export of ``robot`` (RK4, 1 ms) for ``seconds``
    with ``tensions`` held as controls (joint motors at zero), or None without MuJoCo."""
    try:
        import mujoco

        from taut.model import mjcf_text, pose_to_qpos
    except ImportError:
        return None
    mj = mujoco.MjModel.from_xml_string(mjcf_text(robot))
    mj.opt.timestep = 1e-3
    mj.opt.integrator = mujoco.mjtIntegrator.mjINT_RK4
    data = mujoco.MjData(mj)
    data.qpos[:] = pose_to_qpos(robot, q0)
    data.ctrl[:] = 0.0
    data.ctrl[: robot.n_cables] = tensions
    steps = int(round(seconds / 1e-3))

    def run():
        for _ in range(steps):
            mujoco.mj_step(mj, data)

    return best_of(run, repeat=1)[0]


def jointed(args):
    """adjustable-8cable with assumed masses (its passive joint moved by the cables)."""
    from taut.dynamics import bias_forces, mass_matrix, velocity_jacobian
    from taut.kinematics import jointed_structure_matrix

    robot = taut.example("adjustable-8cable")
    n = args.samples
    t = np.linspace(0, 10, n)[:, None]
    centre = np.array([5, 5, 1.5, 0, 0, 0, 1.5])
    a = np.array([0.2, 0.2, 0.2, 0.05, 0.05, 0.1, 0.3])
    w = np.array([1.0, 1.3, 0.7, 1.1, 0.9, 1.7, 0.8])
    q, qd, qdd = centre + a * np.sin(w * t), a * w * np.cos(w * t), -a * w * w * np.sin(w * t)
    inverse_dynamics(robot, q[:10], qd[:10], qdd[:10], method="closed-form")
    dt_b, res = best_of(lambda: inverse_dynamics(robot, q, qd, qdd, method="closed-form"))

    def numpy_path():
        # the equations of motion and the jointed structure matrix in NumPy, then the statics
        need = np.einsum("kij,kj->ki", mass_matrix(robot, q), qdd) + bias_forces(robot, q, qd)
        wrench = np.linalg.solve(np.swapaxes(velocity_jacobian(robot, q), 1, 2), need[..., None])[..., 0]
        A = jointed_structure_matrix(robot, q)[..., : robot.n_cables]
        return solve_tensions(A, -wrench, tension_bounds=robot.tension_bounds, method="closed-form")

    dt_s, ref = best_of(numpy_path, repeat=1)
    same = bool(np.array_equal(res.feasible, ref.feasible)) and float(np.abs(res.tensions - ref.tensions).max()) < 1e-6
    print(f"{robot.name} (20 kg platform, 8 kg upper body on a passive prismatic joint, masses assumed)")
    print(f"inverse dynamics, {n} samples of a 7-coordinate motion, closed-form distribution, one core")
    print(f"  compiled batch     : {n / dt_b:>12,.0f} samples/s  (target >= 100,000)")
    print(f"  NumPy path         : {n / dt_s:>12,.0f} samples/s  -> batch is {dt_s / dt_b:,.1f}x faster")
    print(f"  feasible samples: {res.feasible.mean():.0%}; same tensions as the NumPy path: {same}")
    waypoints = [[5, 5, 1.5, 0, 0, 0, 1.5], [5.3, 5.2, 1.2, 0.05, 0, 0.1, 2.0], [4.8, 5.1, 1.4, 0, 0.05, -0.1, 1.2]]
    # at least 5 s: faster, the motion asks for more than the cables across the joint can give
    seconds = max(args.seconds, 5.0)
    motion = trajectory_from_waypoints(robot, waypoints, duration=seconds, law="quintic")
    model = with_mass_error(robot, 0.1)
    simulate_control(robot, trajectory_from_waypoints(robot, waypoints[:2], duration=2.0))
    dt_c, run = best_of(lambda: simulate_control(robot, motion, model=model), repeat=3)
    print(
        f"computed-torque control at 1 kHz ({seconds:g} s quintic motion, controller model 10 % heavy, bodies too; "
        "closed-form distribution, RK4)"
    )
    print(f"  taut simulate_control: {seconds / dt_c:>10,.1f}x real time  (target >= 20x)")
    print(
        f"  max errors: {np.abs(run.tracking_error_max).max() * 1e3:.2f} mm/mrad (s23 {run.tracking_error_max[6] * 1e3:.2f} mm); "
        f"min tension margin {run.min_tension_margin:.1f} N; every distribution admissible: {run.all_feasible}"
    )
    hold = inverse_dynamics(robot, centre, np.zeros(7), np.zeros(7), method="qp").tensions
    dt_m = mujoco_seconds(robot, centre, hold, seconds)
    if dt_m is None:
        print("  MuJoCo not installed: no comparison")
        return
    print(f"  MuJoCo mj_step     : {seconds / dt_m:>10,.1f}x real time  (the exported model, tensions held)")
    print(f"  taut with its controller and distribution vs MuJoCo stepping alone: {dt_m / dt_c:,.2f}x")


def pulleys(args, straight, dt_straight):
    """spatial-8cable with 3 cm swivelling pulleys at its exits in the compiled loop, against
    the same robot with fixed exit points (``dt_straight``, measured above)."""
    robot = straight.model_copy(
        update={
            "cables": tuple(
                c.model_copy(update={"swivel": {"axis": (0, 0, 1), "radius": 0.03}}) for c in straight.cables
            )
        }
    )
    dt_p, run = control_run(robot, args.seconds)
    print(f"{robot.name} with 3 cm swivelling pulleys, the same control run")
    print(f"  taut simulate_control: {args.seconds / dt_p:>10,.1f}x real time  (target >= 50x)")
    print(f"  pulleys cost {dt_p / dt_straight:,.2f}x the fixed exit points' run; admissible: {run.all_feasible}")


if __name__ == "__main__":
    main()
