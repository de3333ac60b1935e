"""Cable state, CST, state update and VSCR IK (§4.1–4.3 of Rushton 2022)."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from taut.errors import TautError
from taut.geometry import segment_enters_polygon, segment_meets_circle
from taut.model import example
from taut.wrapping._state import CableState, rebuild_path
from taut.wrapping._trajectory import builtin_trajectory, run_trajectory
from taut.wrapping._tree import CableStateTree
from taut.wrapping._update import track_cable_state, update_state

VSCR = ["vscr-single-cable", "vscr-four-cable", "vscr-agriculture", "vscr-rehabilitation", "vscr-t-shaped"]


@pytest.fixture(scope="module")
def runs():
    out = {}
    for name in VSCR:
        r = example(name)
        t, P = builtin_trajectory(r, dt=0.02)
        out[name] = (r, t, P, run_trajectory(r, t, P))
    return out


def _single_tree():
    r = example("vscr-single-cable")
    circ = np.array([[*o.center, o.radius] for o in r.obstacles] + [[0.0, 0.0, 0.0]])
    return CableStateTree(circ, 1)


@pytest.mark.slow
@pytest.mark.parametrize("name", VSCR)
def test_lengths_are_continuous_across_transitions(runs, name):
    # a taut cable's length is 1-Lipschitz in its platform end: no jump at any wrap/unwrap
    r, t, P, res = runs[name]
    db = np.linalg.norm(np.diff(res.ik.anchors, axis=0), axis=-1)
    dl = np.abs(np.diff(res.lengths, axis=0))
    assert (dl <= db + 1e-9).all()
    assert len(res.transitions) > 0


@pytest.mark.parametrize("name", VSCR)
def test_paths_are_taut_and_lengths_match_eq_4_9(runs, name):
    r, t, P, res = runs[name]
    for s in range(0, len(t), 7):
        for i in range(r.n_cables):
            tree = res.ik.trees[i]
            path = res.ik.path(s, i)
            assert path.length == pytest.approx(res.lengths[s, i], abs=1e-9)
            chain = [(tree.n_objects, tree.winch_direction)] + list(res.ik.contacts(s, i))
            for j, (a, b) in enumerate(path.segments):
                u = (b - a) / max(np.linalg.norm(b - a), 1e-300)
                for end, (k, d) in ((a, chain[j]),) + (((b, chain[j + 1]),) if j + 1 < len(chain) else ()):
                    c, rad = tree.circles[k, :2], tree.circles[k, 2]
                    assert np.linalg.norm(end - c) == pytest.approx(rad, abs=1e-9)
                    if rad > 0:
                        assert np.dot(end - c, u) == pytest.approx(0, abs=1e-9)  # tangent
                        assert np.sign(u[0] * (c - end)[1] - u[1] * (c - end)[0]) == d  # recorded direction
                assert not segment_meets_circle(a, b, tree.circles[:, :2], tree.circles[:, 2], tol=1e-7).any()
            assert (path.arcs[1:, 4] >= -1e-9).all()  # non-negative wrap angles
            if not res.ik.contacts(s, i) and tree.circles[-1, 2] == 0:
                assert path.length == pytest.approx(np.linalg.norm(res.ik.anchors[s, i] - tree.circles[-1, :2]))


@pytest.mark.parametrize("name", ["vscr-t-shaped", "vscr-agriculture", "vscr-rehabilitation"])
def test_idlers_keep_cables_out_of_the_protected_regions(runs, name):
    r, t, P, res = runs[name]
    assert r.disallowed
    # every straight piece of every cable at every sample, tested against each region at once
    owner = [(s, i) for s in range(len(t)) for i in range(r.n_cables)]
    pieces = [res.ik.path(s, i).segments for s, i in owner]
    seg = np.concatenate(pieces)
    which = np.repeat(np.arange(len(owner)), [len(p) for p in pieces])
    for poly in r.disallowed:
        inside = segment_enters_polygon(seg[:, 0], seg[:, 1], np.asarray(poly), tol=1e-9)
        assert not inside.any(), [owner[k] for k in np.unique(which[inside])]


@pytest.mark.parametrize("name", VSCR)
def test_reversing_the_trajectory_returns_every_cable_to_its_initial_state(runs, name):
    r, t, P, res = runs[name]
    for i, tree in enumerate(res.ik.trees):
        back = track_cable_state(tree, res.ik.anchors[::-1, i], node=int(res.ik.nodes[-1, i]))
        assert back.nodes[-1] == res.ik.nodes[0, i]
        assert np.allclose(back.lengths[::-1], res.lengths[:, i], atol=1e-12)
        assert np.array_equal(back.nodes[::-1], res.ik.nodes[:, i])


def test_single_cable_wraps_the_three_objects_in_turn():
    # Fig. 4.8: the free end passes over objects 1, 2, 3 and the cable wraps each
    tree = _single_tree()
    t = np.linspace(0, 4, 401)
    P = np.column_stack([t, 1 + np.cos(2 * np.pi * t / 3)])
    tr = track_cable_state(tree, P, node=tree.shortest_taut_state(P[0]))
    assert tree.contacts(int(tr.nodes[0])) == ()
    assert tree.contacts(int(tr.nodes[-1])) == ((0, -1), (1, 1), (2, -1))
    assert tr.events[:, 2].tolist() == [1, 1, 1]


def test_a_large_step_does_not_jump_over_a_collision():
    tree = _single_tree()
    start = tree.shortest_taut_state([0, 2])
    # one straight step from above object 1 to far beyond and below it
    node = update_state(tree, start, [0.0, 2.0], [1.5, 0.3])
    assert tree.contacts(node) == ((0, -1),)
    # and back in one step: unwrapped again
    assert update_state(tree, node, [1.5, 0.3], [0.0, 2.0]) == start


def test_several_transitions_in_one_step_and_tie_rule_of_fig_4_5():
    # point objects at (1, 0) and (2, 0) collinear with the winch at the origin: sweeping
    # the cable down across them wraps the farther one (largest magnitude, Fig. 4.5)
    circ = np.array([[1.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 0.0, 0.0]])
    tree = CableStateTree(circ, 1)
    node = update_state(tree, 0, [3.0, 1.0], [3.0, -1.0])
    assert tree.contacts(node) == ((1, -1),)
    # two separate objects hit in one step: winch -> object 1 -> object 2
    circ = np.array([[1.0, 0.5, 0.1], [2.0, -0.5, 0.1], [0.0, 0.0, 0.0]])
    tree = CableStateTree(circ, 1)
    node = update_state(tree, 0, [3.0, 2.0], [2.5, -3.0])
    assert tree.contacts(node) == ((0, -1), (1, -1))
    back = update_state(tree, node, [2.5, -3.0], [3.0, 2.0])
    assert back == 0


def test_lazy_expansion_matches_the_full_tree():
    full, lazy = _single_tree(), _single_tree()
    n = full.build()
    assert n > 10
    t = np.linspace(0, 4, 201)
    P = np.column_stack([t, 1 + np.cos(2 * np.pi * t / 3)])
    a = track_cable_state(full, P, node=0)
    b = track_cable_state(lazy, P, node=0)
    assert lazy.size < n
    assert [full.contacts(int(k)) for k in a.nodes] == [lazy.contacts(int(k)) for k in b.nodes]
    assert np.allclose(a.lengths, b.lengths)


def test_tree_rejects_blocked_and_disallowed_segments():
    # object 2 sits on the line from the winch to object 1: no direct segment onto object 1
    circ = np.array([[2.0, 0.0, 0.1], [1.0, 0.0, 0.1], [0.0, 0.0, 0.0]])
    tree = CableStateTree(circ, 1)
    assert {int(tree.I[c, 1]) for c in tree.children(0)} == {1}
    poly = np.array([[0.4, -0.5], [0.6, -0.5], [0.6, 0.5], [0.4, 0.5]])
    assert tree.children(0).size == 2
    assert CableStateTree(circ, 1, disallowed=[poly]).children(0).size == 0


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.floats(0.2, 4), st.floats(1.25, 3)), min_size=2, max_size=12))
def test_random_walks_stay_continuous_and_reversible(points):
    # free ends above the objects, so that the cable never has to cross itself (not modelled)
    tree = _single_tree()
    P = np.array([[0.0, 2.0]] + [list(p) for p in points])
    through = segment_meets_circle(
        P[:-1, None], P[1:, None], tree.circles[None, :3, :2], tree.circles[None, :3, 2] + 0.01, tol=0.0
    )
    if through.any():  # the platform end may not pass through an object
        return
    tr = track_cable_state(tree, P, node=0)
    db = np.linalg.norm(np.diff(P, axis=0), axis=1)
    assert (np.abs(np.diff(tr.lengths)) <= db + 1e-9).all()
    back = track_cable_state(tree, P[::-1], node=int(tr.nodes[-1]))
    assert back.nodes[-1] == 0
    for k in tr.nodes:
        path = rebuild_path(tree.circles, 1, CableState(tree.contacts(int(k))), P[0])
        assert np.isfinite(path.length)


def test_bad_input():
    r = example("vscr-four-cable")
    with pytest.raises(TautError, match="inside object"):
        run_trajectory(r, [0, 1], [[0.75, -0.5], [0.0, -0.3333]])
    with pytest.raises(TautError, match="not taut"):
        run_trajectory(r, [0, 1], [[0.75, -0.5], [0.7, -0.5]], initial={0: [(1, -1)]})
    bad = r.model_copy(update={"obstacles": (*r.obstacles, r.obstacles[0].model_copy(update={"center": [0.1, -0.3]}))})
    with pytest.raises(TautError, match="overlap"):
        run_trajectory(bad, [0, 1], [[0.75, -0.5], [0.7, -0.5]])


def test_rehabilitation_starts_wrapped_as_its_notes_say(runs):
    r, t, P, res = runs["vscr-rehabilitation"]
    assert res.ik.contacts(0, 3) == ((1, -1),) and res.ik.contacts(0, 4) == ((2, 1),)
    assert res.feasible.all()
    assert res.controlled.sum(axis=1).tolist() == [2] * len(t)
