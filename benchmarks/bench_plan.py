"""Wrench-feasible path planning on the NIST Robocrane (Bohigas et al. 2013, §5):
the queries q1 → q2 and q3 → q4 on the slice p = (0, 0, 2), σ = 35°, by A* over a growing
atlas (:func:`taut.planning.plan_path`), against the paper's 20 s and 280 s (C, 2.66 GHz
Core i7) and, measured in the same run, the uninformed baseline: the atlas grown
breadth-first (charts closed in creation order, Henderson's plain continuation) until a
chart reaches the goal.  q3, q4 are the wrench-feasible replacements of the file
(robocrane.yaml, reference.notes): the published τ_3, τ_4 are not feasible under our
reading of §5, so the 280 s ratio compares queries of the same kind, not the same query.

AtlasRRT (Jaillet & Porta 2013, :func:`taut.planning.plan_path` with ``method="atlasrrt"``, bidirectional, chart
radius ``--rrt-radius``, step ``--rrt-step``) on the same queries, ``--seeds`` seeds
(0, 1, ...), against the paper's times and, when the optional peer OMPL is installed
(``pip install ompl``, or ``pip install -e '.[bench]'``), RRTConnect on the same slice,
``--seeds`` trials (OMPL's one global seed 1), run alternately with AtlasRRT so that the
load of the machine falls on both.  Both use **the same validity checker**: a pose is valid
when the closed-form solution of the manifold's equations exists there inside its box (tensions
and lengths strictly inside their bounds with the box's margin: what AtlasRRT's projections
require of each tree node; ``--ompl-checker independent`` gives OMPL the independent test of
:mod:`taut.statics._feasibility` at one pose instead).  OMPL plans in SO(2) × [0, π] (φ
periodic, like the atlas; the half-turn identity (φ, θ) ≡ (φ + π, −θ) is not available to it),
its motions checked every ``--resolution`` rad, within ``--ompl-time`` s.  Every path of both
planners is checked by ``verify_path`` every ``--resolution`` rad; lengths are in (φ, θ).
Printed: both time and length distributions (min / median / max), the ratios of the medians,
and the paper's times with our ratio to them.  The straight line start → goal is checked too.
``--simplify`` shortens both planners' paths inside the timing (AtlasRRT's random shortcuts
on the manifold, OMPL's simplifySolution).  Then q5 → q6 without a slice (all six pose coordinates free) by AtlasRRT.

Last, planning in the pose space of redundant robots (``--pose-space``, on by default): the
8-cable spatial robot and CoGiRo (xyz-fixed angles), queries whose straight line is not
valid, by taut's RRT-Connect (``plan_path(robot, ..., method="rrtconnect")``, shortcuts
included) and OMPL's RRTConnect + simplifySolution in R³ × SO(2)³ with the same box, range
(step) and validity test (:func:`taut.planning.pose_validity`, one pose per call: OMPL
checks states one at a time; taut checks the poses of a segment in one batch), motions
checked every ``--resolution``, ``--pose-seeds`` seeds.  Every path is checked by
``verify_path`` every ``--pose-verify`` (pose coordinates, m and rad); lengths are in pose
coordinates with angles the short way.  Printed: the medians and the ratios OMPL / taut of
time and length.

    python benchmarks/bench_plan.py [--radius 0.2] [--repeat 3] [--max-charts 20000] [--no-astar]
                                    [--seeds 10] [--rrt-radius 0.4] [--rrt-step 0.1]
                                    [--no-peers] [--resolution 0.01] [--ompl-time 30]
                                    [--ompl-checker manifold|independent] [--simplify]
                                    [--no-pose-space] [--pose-seeds 10] [--pose-verify 0.001]
                                    [--pose-robots spatial-8cable,cogiro] [--no-manifold]
"""

import argparse
import gc
import time

import numpy as np
from _common import best_of  # first: it pins the thread pools to one core

import taut
from taut.planning import Atlas, WrenchFeasibleManifold, plan_path, pose_validity, verify_path

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


def ompl_rrtconnect(valid_pose, start, goal, step, budget, simplify=False):
    """One RRTConnect trial in SO(2) × [0, π] with the state validity test ``valid_pose(pose)``
    (then OMPL's path simplification when ``simplify``, timed with it); ``None`` when OMPL is
    absent, else ``(solved, seconds, validity calls, poses)`` with φ unwrapped along the path."""
    try:
        from ompl import base as ob
        from ompl import geometric as og
        from ompl import util as ou
    except ImportError:
        return None
    ou.setLogLevel(ou.LogLevel.LOG_WARN)
    if not _SEEDED:  # OMPL takes one global seed, before its first random number
        ou.RNG.setSeed(1)
        _SEEDED.append(1)
    theta = ob.RealVectorStateSpace(1)
    bounds = ob.RealVectorBounds(1)
    bounds.setLow(0, 0.0)
    bounds.setHigh(0, np.pi)
    theta.setBounds(bounds)
    space = ob.CompoundStateSpace()
    space.addSubspace(ob.SO2StateSpace(), 1.0)
    space.addSubspace(theta, 1.0)
    counter = [0]

    def pose(phi, th):
        q = start.copy()
        q[list(FREE)] = phi, th
        return q

    def valid(s):
        counter[0] += 1
        return valid_pose(pose(s[0].value, s[1][0]))

    ss = og.SimpleSetup(space)
    ss.setStateValidityChecker(valid)
    si = ss.getSpaceInformation()
    si.setStateValidityCheckingResolution(step / space.getMaximumExtent())
    ss.setPlanner(og.RRTConnect(si))
    a, b = space.allocState(), space.allocState()
    a[0].value, a[1][0] = start[FREE[0]], start[FREE[1]]
    b[0].value, b[1][0] = goal[FREE[0]], goal[FREE[1]]
    ss.setStartAndGoalStates(a, b)
    t = time.perf_counter()
    solved = bool(ss.solve(budget))
    if solved and simplify:
        ss.simplifySolution()
    dt = time.perf_counter() - t
    exact = solved and ss.haveExactSolutionPath()
    poses = None
    if exact:
        poses = np.array([pose(s[0].value, s[1][0]) for s in ss.getSolutionPath().getStates()])
        poses[:, FREE[0]] = np.unwrap(poses[:, FREE[0]])
    calls = counter[0]
    del ss, si, a, b
    gc.collect()
    return exact, dt, calls, poses


def spread(values):
    v = np.asarray(values, float)
    if v.size == 0:
        return "none"
    return f"min {v.min():.3f} / median {np.median(v):.3f} / max {v.max():.3f}"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radius", type=float, default=0.2)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--max-charts", type=int, default=20000)
    ap.add_argument("--astar", action=argparse.BooleanOptionalAction, default=True, help="run A* and breadth-first")
    ap.add_argument("--seeds", type=int, default=10, help="AtlasRRT seeds and OMPL trials per query")
    ap.add_argument("--rrt-radius", type=float, default=0.4)
    ap.add_argument("--rrt-step", type=float, default=0.1)
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
    ap.add_argument("--ompl-checker", choices=("manifold", "independent"), default="manifold")
    ap.add_argument(
        "--simplify",
        action="store_true",
        help="shorten both planners' paths (AtlasRRT shorten=True, OMPL simplifySolution), inside the timing",
    )
    ap.add_argument("--pose-space", action=argparse.BooleanOptionalAction, default=True)
    ap.add_argument("--pose-seeds", type=int, default=10, help="seeds per pose-space query")
    ap.add_argument("--pose-robots", default="spatial-8cable,cogiro", help="robots of the pose-space queries")
    ap.add_argument("--pose-verify", type=float, default=0.001, help="verify_path step on pose-space paths")
    ap.add_argument("--manifold", action=argparse.BooleanOptionalAction, default=True, help="the Robocrane part")
    ns = ap.parse_args()
    if ns.manifold:
        robocrane(ns)
    if ns.pose_space:
        pose_space(ns)


def robocrane(ns):
    robot = taut.load_robot("robocrane")
    P = {k: np.array(v) for k, v in robot.reference.poses.items()}
    M = WrenchFeasibleManifold.from_robot(robot, fixed=dict(x=0.0, y=0.0, z=2.0, sigma=7 * np.pi / 36))
    mf = M.implicit()
    free = M.pose_metric

    def valid_manifold(q):
        y = mf.graph(q[list(FREE)])
        return y is not None and mf.in_box(y)

    def valid_independent(q):
        return bool(verify_path(robot, q[None], subdivide=1).feasible[0])

    valid_pose = valid_manifold if ns.ompl_checker == "manifold" else valid_independent
    assert free.tolist() == [0, 1]  # (φ, θ) are the free vector's first two coordinates
    for (a, b), paper_s in PAPER_S.items():
        y1, y2 = M.lift(P[a]), M.lift(P[b])
        print(f"robocrane {a} -> {b}")
        if ns.astar:
            t_astar, res = best_of(
                lambda: plan_path(mf, y1, y2, radius=ns.radius, metric=M.pose_metric, max_charts=ns.max_charts),  # noqa: B023
                ns.repeat,
            )
            check = verify_path(robot, M.pose(res.path), subdivide=10) if res.found else None

            def breadth_first(y1=y1, y2=y2):
                atlas = Atlas(mf, y1, radius=ns.radius, metric=M.pose_metric)
                i = 0
                while i < len(atlas.charts) and len(atlas.charts) < ns.max_charts:
                    if atlas.reaches(i, y2):
                        return atlas, True
                    atlas.grow(i)
                    i += 1
                return atlas, False

            t_full, (atlas, done) = best_of(breadth_first, 1)
            print(
                f"  A* (chart radius {ns.radius}): found {res.found}, {res.charts} charts ({res.expanded} closed), "
                f"path length {res.length:.3f} rad, {t_astar:.3f} s"
            )
            if check is not None:
                print(
                    f"  A* independent check at {check.poses.shape[0]} interpolated poses: "
                    f"all feasible {check.all_feasible}"
                )
            print(
                f"  breadth-first atlas: reached {b} {done}, {len(atlas.charts)} charts, {t_full:.3f} s "
                f"(A* speed-up {t_full / t_astar:.1f}x)"
            )
            print(f"  paper (C): {paper_s:.0f} s; ratio paper / taut A*: {paper_s / t_astar:.1f}x")
        if ns.peers:
            t_line, line = straight_line(robot, P[a], P[b], ns.resolution)
            bad = int((~line.feasible).sum())
            print(
                f"  straight line: feasible {line.all_feasible} ({bad} of {line.poses.shape[0]} points "
                f"infeasible), {t_line:.3f} s"
            )
        rrt = {"t": [], "len": [], "ok": []}
        peer = {"t": [], "len": [], "ok": [], "calls": []}
        have_ompl = ns.peers
        for seed in range(ns.seeds):
            t = time.perf_counter()
            r = plan_path(
                mf,
                y1,
                y2,
                method="atlasrrt",
                radius=ns.rrt_radius,
                step=ns.rrt_step,
                metric=M.pose_metric,
                seed=seed,
                shorten=ns.simplify,
            )
            dt = time.perf_counter() - t
            if r.found:
                ck = verify_path(robot, densify(M.pose(r.path), ns.resolution), subdivide=1)
                rrt["t"].append(dt)
                rrt["len"].append(r.length)
                rrt["ok"].append(ck.all_feasible)
            if not have_ompl:
                continue
            run = ompl_rrtconnect(valid_pose, P[a], P[b], ns.resolution, ns.ompl_time, ns.simplify)
            if run is None:
                have_ompl = False
                print("  OMPL not installed (optional peer: pip install ompl)")
                continue
            exact, dt, calls, poses = run
            if exact:
                ck = verify_path(robot, densify(poses, ns.resolution), subdivide=1)
                peer["t"].append(dt)
                peer["len"].append(float(np.linalg.norm(np.diff(poses[:, FREE], axis=0), axis=1).sum()))
                peer["ok"].append(ck.all_feasible)
                peer["calls"].append(calls)
        print(
            f"  AtlasRRT (bidirectional, radius {ns.rrt_radius}, step {ns.rrt_step}"
            f"{', shortened' if ns.simplify else ''}; {ns.seeds} seeds): "
            f"solved {len(rrt['t'])}, paths valid by the independent check at {ns.resolution} rad: "
            f"{sum(rrt['ok'])} of {len(rrt['ok'])}; all feasible {all(rrt['ok']) and len(rrt['ok']) == ns.seeds}"
        )
        print(f"    time, s:        {spread(rrt['t'])}")
        print(f"    path length, rad: {spread(rrt['len'])}")
        if rrt["t"]:
            med = float(np.median(rrt["t"]))
            print(f"  paper (C): {paper_s:.0f} s; ratio paper / taut AtlasRRT median: {paper_s / med:.0f}x")
        if have_ompl and ns.seeds:
            print(
                f"  OMPL RRTConnect{' + simplifySolution' if ns.simplify else ''} ({ns.ompl_checker} validity "
                f"checker, motions every {ns.resolution} rad, "
                f"budget {ns.ompl_time:.0f} s; {ns.seeds} trials): solved {len(peer['t'])}, paths valid "
                f"{sum(peer['ok'])} of {len(peer['ok'])}, validity checks median "
                f"{np.median(peer['calls']) if peer['calls'] else float('nan'):.0f}"
            )
            print(f"    time, s:        {spread(peer['t'])}")
            print(f"    path length, rad: {spread(peer['len'])}")
            if rrt["t"] and peer["t"]:
                rt = np.median(peer["t"]) / np.median(rrt["t"])
                rl = np.median(peer["len"]) / np.median(rrt["len"])
                print(
                    f"  ratio of medians OMPL / AtlasRRT: time {rt:.2f}x "
                    f"({'AtlasRRT faster' if rt > 1 else 'OMPL faster'}), path length {rl:.2f}x "
                    f"({'AtlasRRT shorter' if rl > 1 else 'OMPL shorter'})"
                )
    six_d(robot, P, ns)


def six_d(robot, P, ns):
    """q5 → q6 without a slice: all six pose coordinates free (target: at most 60 s)."""
    M = WrenchFeasibleManifold.from_robot(robot)
    mf = M.implicit()
    y1, y2 = M.lift(P["q5"]), M.lift(P["q6"])
    times, lengths, charts, ok = [], [], [], []
    for seed in range(ns.seeds):
        t = time.perf_counter()
        r = plan_path(
            mf, y1, y2, method="atlasrrt", radius=ns.rrt_radius, step=ns.rrt_step, metric=M.pose_metric, seed=seed
        )
        times.append(time.perf_counter() - t)
        if r.found:
            lengths.append(r.length)
            charts.append(r.charts)
            ok.append(verify_path(robot, M.pose(r.path), subdivide=10).all_feasible)
    print("robocrane q5 -> q6 in six dimensions (no slice)")
    print(
        f"  AtlasRRT ({ns.seeds} seeds): solved {len(ok)}, paths valid {sum(ok)} of {len(ok)}; "
        f"all feasible {all(ok) and len(ok) == ns.seeds}; charts median {np.median(charts) if charts else 0:.0f}"
    )
    print(f"    time, s:        {spread(times)}  (target 60 s: {60 / max(times):.0f}x under it at the slowest)")
    print(f"    path length (pose coordinates, m and rad): {spread(lengths)}")


#: Pose-space queries: robot, start, goal (straight line not valid).
POSE_QUERIES = [
    ("spatial-8cable", [0, 0, 0, 0, 0, 0], [0, 0, 0, 0, 0, 2.5]),
    ("spatial-8cable", [0, 0, 0, 0, 0, 0], [0, 0, 0, 2.5, 0, 0]),
    # near the exits' plane, turning the platform by 3 rad: the straight line leaves the valid
    # set for most of its length.  (Elsewhere the valid set of CoGiRo, whose tensions have no
    # upper bound, is cut only by thin sheets of singular poses, which a sampling planner
    # checking poses a resolution apart can step over.)
    ("cogiro", [-2, 0, 5.3, 0, 0, 1.5], [2, 0, 5.3, 0, 0, -1.5]),
    ("cogiro", [0, 0, 5.35, 0, 0, 1.5], [0, 0, 5.35, 0, 0, -1.5]),
]


def pose_box(robot, start, goal):
    """The default box of ``plan_path``'s pose-space planners: the exits, start and goal,
    widened to a cube about its centre."""
    pts = np.vstack([robot.exits, np.asarray(start)[None, :3], np.asarray(goal)[None, :3]])
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    half, centre = 0.5 * (hi - lo).max(), 0.5 * (lo + hi)
    return np.minimum(lo, centre - half), np.maximum(hi, centre + half)


def short_length(poses):
    d = np.diff(np.asarray(poses, float), axis=0)
    d[:, 3:] = np.mod(d[:, 3:] + np.pi, 2 * np.pi) - np.pi
    return float(np.linalg.norm(d, axis=1).sum())


def fine_check(robot, poses, step):
    """``verify_path`` with every segment cut at most ``step`` apart."""
    d = np.diff(np.asarray(poses, float), axis=0)
    d[:, 3:] = np.mod(d[:, 3:] + np.pi, 2 * np.pi) - np.pi
    seg = float(np.linalg.norm(d, axis=1).max())
    return verify_path(robot, poses, subdivide=max(1, int(np.ceil(seg / step)))).all_feasible


def ompl_pose_rrtconnect(valid, box, start, goal, step, resolution, budget):
    """OMPL RRTConnect + simplifySolution in R³ × SO(2)³; ``None`` without OMPL, else
    ``(solved, seconds, validity calls, poses)``."""
    try:
        from ompl import base as ob
        from ompl import geometric as og
        from ompl import util as ou
    except ImportError:
        return None
    ou.setLogLevel(ou.LogLevel.LOG_WARN)
    if not _SEEDED:
        ou.RNG.setSeed(1)
        _SEEDED.append(1)
    pos = ob.RealVectorStateSpace(3)
    bounds = ob.RealVectorBounds(3)
    for i in range(3):
        bounds.setLow(i, float(box[0][i]))
        bounds.setHigh(i, float(box[1][i]))
    pos.setBounds(bounds)
    space = ob.CompoundStateSpace()
    space.addSubspace(pos, 1.0)
    for _ in range(3):
        space.addSubspace(ob.SO2StateSpace(), 1.0)
    counter = [0]

    def pose(s):
        return np.array([s[0][0], s[0][1], s[0][2], s[1].value, s[2].value, s[3].value])

    def is_valid(s):
        counter[0] += 1
        return bool(valid(pose(s)[None])[0][0])

    ss = og.SimpleSetup(space)
    ss.setStateValidityChecker(is_valid)
    si = ss.getSpaceInformation()
    si.setStateValidityCheckingResolution(resolution / space.getMaximumExtent())
    planner = og.RRTConnect(si)
    planner.setRange(step)
    ss.setPlanner(planner)
    a, b = space.allocState(), space.allocState()
    for st, q in ((a, start), (b, goal)):
        for i in range(3):
            st[0][i] = float(q[i])
        for i in range(3):
            st[1 + i].value = float(q[3 + i])
    ss.setStartAndGoalStates(a, b)
    t = time.perf_counter()
    solved = bool(ss.solve(budget))
    if solved:
        ss.simplifySolution()
    dt = time.perf_counter() - t
    exact = solved and ss.haveExactSolutionPath()
    poses = np.array([pose(s) for s in ss.getSolutionPath().getStates()]) if exact else None
    calls = counter[0]
    del ss, si, a, b, planner
    gc.collect()
    return exact, dt, calls, poses


def pose_space(ns):
    """RRT-Connect in the pose space of redundant robots, against OMPL's (module docstring)."""
    have_ompl = True
    for name, start, goal in POSE_QUERIES:
        if name not in ns.pose_robots.split(","):
            continue
        robot = taut.load_robot(name)
        start, goal = np.asarray(start, float), np.asarray(goal, float)
        box = pose_box(robot, start, goal)
        diag = float(np.linalg.norm(np.r_[box[1] - box[0], np.full(3, 2 * np.pi)]))
        step = diag / 20  # plan_path's default step
        valid = pose_validity(robot)
        line = fine_check(robot, [start, goal], ns.resolution)
        print(f"{name} {start.tolist()} -> {goal.tolist()}: straight line valid {line}")
        ours = {"t": [], "len": [], "ok": [], "ok_res": []}
        peer = {"t": [], "len": [], "ok": [], "ok_res": [], "calls": []}
        for seed in range(ns.pose_seeds):
            t = time.perf_counter()
            r = plan_path(robot, start, goal, method="rrtconnect", seed=seed, bounds=box, resolution=ns.resolution)
            dt = time.perf_counter() - t
            if r.found:
                ours["t"].append(dt)
                ours["len"].append(r.length)
                ours["ok"].append(fine_check(robot, r.path, ns.pose_verify))
                ours["ok_res"].append(fine_check(robot, r.path, ns.resolution))
            if not have_ompl:
                continue
            run = ompl_pose_rrtconnect(valid, box, start, goal, step, ns.resolution, ns.ompl_time)
            if run is None:
                have_ompl = False
                print("  OMPL not installed (optional peer: pip install 'ompl>=2'): its comparison is skipped")
                continue
            exact, dt, calls, poses = run
            if exact:
                peer["t"].append(dt)
                peer["len"].append(short_length(poses))
                peer["ok"].append(fine_check(robot, poses, ns.pose_verify))
                peer["ok_res"].append(fine_check(robot, poses, ns.resolution))
                peer["calls"].append(calls)
        print(
            f"  taut RRT-Connect + shortcuts ({ns.pose_seeds} seeds, step {step:.3f}, checks every {ns.resolution}): "
            f"solved {len(ours['t'])}, verified every {ns.resolution}: {sum(ours['ok_res'])}, every {ns.pose_verify}: "
            f"{sum(ours['ok'])} of {len(ours['ok'])}"
        )
        print(f"    time, s:     {spread(ours['t'])}")
        print(f"    path length: {spread(ours['len'])}")
        if have_ompl:
            print(
                f"  OMPL RRTConnect + simplifySolution (same box, range, validity test; budget {ns.ompl_time:.0f} s): "
                f"solved {len(peer['t'])}, verified every {ns.resolution}: {sum(peer['ok_res'])}, every {ns.pose_verify}: "
                f"{sum(peer['ok'])} of {len(peer['ok'])}, validity calls median "
                f"{np.median(peer['calls']) if peer['calls'] else float('nan'):.0f}"
            )
            print(f"    time, s:     {spread(peer['t'])}")
            print(f"    path length: {spread(peer['len'])}")
            if ours["t"] and peer["t"]:
                rt = np.median(peer["t"]) / np.median(ours["t"])
                rl = np.median(peer["len"]) / np.median(ours["len"])
                print(
                    f"  ratio of medians OMPL / taut: time {rt:.2f}x ({'taut faster' if rt > 1 else 'OMPL faster'}), "
                    f"path length {rl:.2f}x ({'taut shorter' if rl > 1 else 'OMPL shorter or equal'})"
                )


if __name__ == "__main__":
    main()
