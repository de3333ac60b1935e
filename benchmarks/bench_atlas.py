"""Structure atlas of the T-shaped VSCR (Alg. 5.1, ``taut.atlas``): construction time, and
atlas-based direct inverse kinematics (Alg. 5.3) in queries per second against a naive
from-scratch IK per point (the shortest taut admissible state of every cable,
``CableStateTree.shortest_taut_state``, then Eq. 4.9).  The lengths of both agree where
the point's chart is the shortest routing.  Targets (issue 5): atlas <= 2 s, IK >= 100 000
queries/s."""

import argparse

import numpy as np
import shapely
from _common import best_of  # first: it pins the thread pools to one core

from taut.atlas import build_atlas, direct_ik
from taut.model import example


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--queries", type=int, default=200_000, help="random IK query points")
    ap.add_argument("--naive", type=int, default=200, help="query points of the naive baseline")
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    robot = example("vscr-t-shaped")
    start = robot.reference.poses["initial"]
    build_atlas(robot, start)  # compile / warm caches
    sec_build, atlas = best_of(lambda: build_atlas(robot, start), repeat=args.repeat)
    print(
        f"T-shaped atlas: {len(atlas.charts)} charts, {atlas.n_edges} adjacent pairs, "
        f"reachable area {atlas.reachable_area().area:.6f} m² built in {sec_build:.3f} s (target <= 2 s)"
    )
    reach = atlas.reachable_area()
    rng = np.random.default_rng(0)
    Q = rng.uniform(*np.array(atlas.space.bounds).reshape(2, 2), size=(4 * args.queries, 2))
    Q = Q[shapely.contains_xy(reach, Q[:, 0], Q[:, 1])][: args.queries]
    sec_ik, res = best_of(lambda: direct_ik(atlas, Q), repeat=args.repeat)
    rate = len(Q) / sec_ik
    sub = Q[: args.naive]

    def naive():
        out = np.empty((len(sub), len(atlas.trees)))
        for j, p in enumerate(sub):
            for i, tree in enumerate(atlas.trees):
                out[j, i] = tree.length(tree.shortest_taut_state(p), p)
        return out

    sec_naive, ref = best_of(naive, repeat=1)
    agree = np.isclose(ref, res.lengths[: len(sub)], atol=1e-9).all(axis=1).mean()
    naive_rate = len(sub) / sec_naive
    print(f"direct IK: {rate:,.0f} queries per second (target >= 100,000), all found: {bool(res.found.all())}")
    print(
        f"naive from-scratch IK: {naive_rate:,.0f} per second; ratio {rate / naive_rate:,.0f}x "
        f"(same lengths at {100 * agree:.0f} % of the points: elsewhere the first chart is another routing)"
    )


if __name__ == "__main__":
    main()
