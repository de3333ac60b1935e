"""docs/architecture.md §2.7 on the results of taut.wrapping: frozen, read-only arrays,
``as_dict()`` in plain JSON types with 0-based cables and objects, equal to the fields."""

import numpy as np
from frozen_results import check_frozen

from taut.model import example
from taut.wrapping import builtin_trajectory, rebuild_path, run_trajectory, track_cable_state

ROBOT = example("vscr-single-cable")
TIMES, POSES = builtin_trajectory(ROBOT, dt=0.05)
RESULT = run_trajectory(ROBOT, TIMES, POSES)


def test_trajectory_result_is_what_the_cli_prints():
    keys = {"samples", "duration", "lengths", "transitions", "tension_feasible", "infeasible_samples"}
    d = check_frozen(RESULT, keys | {"times", "length_controlled"})
    assert d["samples"] == len(TIMES) and d["times"] == TIMES.tolist()
    np.testing.assert_array_equal(d["lengths"], RESULT.lengths)
    assert d["length_controlled"] == RESULT.controlled.tolist()
    assert d["tension_feasible"] == bool(RESULT.feasible.all())
    assert isinstance(RESULT.transitions, tuple) and len(d["transitions"]) == len(RESULT.transitions) > 0
    for e in d["transitions"]:
        assert e["cable"] == 0 and 0 <= e["object"] < len(ROBOT.obstacles) and e["kind"] in ("wrap", "unwrap")


def test_wrapped_ik():
    ik = RESULT.ik
    keys = {"poses", "anchors", "lengths", "directions", "exit_points", "structure_matrix", "states", "transitions"}
    d = check_frozen(ik, keys)
    assert isinstance(ik.trees, tuple) and isinstance(ik.events, tuple)
    assert not any(ev.flags.writeable for ev in ik.events)
    np.testing.assert_array_equal(d["structure_matrix"], ik.structure_matrix)
    assert [len(row) for row in d["states"]] == [ROBOT.n_cables] * len(TIMES)
    s = len(TIMES) // 2
    assert d["states"][s][0] == [list(c) for c in ik.contacts(s, 0)]
    # the transitions with sample numbers as times
    assert [e["sample"] for e in d["transitions"]] == [e["sample"] for e in RESULT.transitions]


def test_tracking_cable_state_and_path():
    ik = RESULT.ik
    tree = ik.trees[0]
    back = track_cable_state(tree, ik.anchors[::-1, 0], node=int(ik.nodes[-1, 0]))
    d = check_frozen(back, {"nodes", "lengths", "directions", "events"})
    np.testing.assert_allclose(d["lengths"], ik.lengths[::-1, 0], atol=1e-9)  # the same lengths backwards
    assert len(d["events"]) == len(ik.events[0])
    state = tree.state(int(ik.nodes[-1, 0]))
    d = check_frozen(state, {"contacts", "reference_angle"})
    assert d["contacts"] == [list(c) for c in state.contacts]
    path = rebuild_path(tree.circles, tree.winch_direction, state, ik.anchors[-1, 0])
    d = check_frozen(path, {"segments", "arcs", "length"})
    assert d["length"] == path.length and np.isclose(path.length, ik.lengths[-1, 0], atol=1e-9)
