"""Cable-state updates per second (Alg. 4.4, ``taut.wrapping._update``) on the four-cable VSCR
example (Eq. 4.13 driven back and forth), against a naive re-computation of every state
from scratch (shortest taut admissible path at each sample, ``shortest_taut_state``).
Target (issue 4): >= 100 000 updates per second per cable."""

import argparse

import numpy as np
from _common import best_of  # first: it pins the thread pools to one core

from taut.model import example
from taut.wrapping import CableStateTree, collidable_objects, track_cable_state


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--samples", type=int, default=100_001, help="samples of one sweep (driven there and back)")
    args = ap.parse_args()
    robot = example("vscr-four-cable")
    circles, polys = collidable_objects(robot)
    t = np.linspace(0.0, 5.0, args.samples)
    P = np.column_stack([0.75 * np.cos(np.pi * t / 5), -0.5 + 0.75 * np.sin(np.pi * t / 5)])
    P = np.vstack([P, P[::-1]])
    trees = [CableStateTree(np.vstack([circles, [[*c.exit, 0.0]]]), 1, disallowed=polys) for c in robot.cables]
    starts = [tr.shortest_taut_state(P[0]) for tr in trees]
    for tr, s in zip(trees, starts):
        track_cable_state(tr, P[:10], node=s)  # compile / expand
    rates = []
    for tr, s in zip(trees, starts):
        sec, _ = best_of(lambda: track_cable_state(tr, P, node=s))  # noqa: B023 — called at once
        rates.append(len(P) / sec)
    sub = P[:: max(1, len(P) // 200)]
    naive_sec, _ = best_of(lambda: [trees[0].shortest_taut_state(b) for b in sub], repeat=1)
    naive = len(sub) / naive_sec
    print(f"state updates per second per cable: min {min(rates):,.0f}, mean {np.mean(rates):,.0f} (target >= 100,000)")
    print(f"naive from-scratch state computation: {naive:,.0f} per second; ratio {np.mean(rates) / naive:,.0f}x")


if __name__ == "__main__":
    main()
