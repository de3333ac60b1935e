"""A cable sweeping around the corners of a square polygon obstacle (zero-radius circles at
the vertices plus a disallowed interior): the tracked contacts must be the physical ones.

Regression: right after unwrapping a zero-radius corner, the cable lies on the line of the
corner's opposite-direction sibling (same point, same tangent line), and the inclusive
collision test re-wrapped the corner the other way at the same instant (decided by
round-off): ``[unwrap A ccw, wrap A cw]``, a cable bent away from the obstacle."""

import numpy as np
import pytest

from taut.geometry import segment_enters_polygon
from taut.wrapping._tree import DIR, EX, EY, OBJ, PARENT, UX, UY, CableStateTree
from taut.wrapping._update import track_cable_state

SQUARE = np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]])  # A, B, C, D (ccw)
A, B = 0, 1
WINCH = (-3.0, 0.0)


def _tree():
    circles = np.vstack([np.column_stack([SQUARE, np.zeros(4)]), [[*WINCH, 0.0]]])
    return CableStateTree(circles, 1, disallowed=[SQUARE])


def _cross(u, v):
    return u[0] * v[1] - u[1] * v[0]


def _check_physical(tree, P, tr, n0):
    """Contacts bend round the obstacle, wraps/unwraps happen when the cable is straight
    across the corner, lengths are 1-Lipschitz, and the state is the taut one."""
    centre = SQUARE.mean(axis=0)
    dirs = {}
    node = n0
    for j, tau, kind, n in tr.events:
        j, kind, n = int(j), int(kind), int(n)
        b = P[j - 1] + tau * (P[j] - P[j - 1])
        k, d = int(tree.I[n, OBJ]), int(tree.F[n, DIR])
        assert dirs.setdefault(k, d) == d, f"corner {k} wrapped both ways: {tr.events}"
        V = tree.F[n, [EX, EY]]
        u_in = tree.F[n, [UX, UY]]
        # the event happens when b is on the forward extension of the segment onto V
        assert abs(_cross(u_in, b - V)) <= 1e-9 and np.dot(u_in, b - V) >= -1e-9
        # the obstacle is on the inside of the bend: a wrap direction that holds the cable
        assert d * _cross(u_in, centre - V) > 0
        if kind == 1:
            assert int(tree.I[n, PARENT]) == node
            node = n
        else:
            assert n == node
            # after the unwrap the wrap angle is negative: b is on the outside of the bend
            assert d * _cross(u_in, P[j] - V) < 0
            node = int(tree.I[n, PARENT])
    assert node == tr.nodes[-1]
    db = np.linalg.norm(np.diff(P, axis=0), axis=-1)
    assert (np.abs(np.diff(tr.lengths)) <= db + 1e-9).all()
    for s, b in enumerate(P):
        n = int(tr.nodes[s])
        assert tree.is_taut(n, b)
        for _, d in tree.contacts(n):
            assert d == 1  # the winch is to the left: every corner is wrapped ccw below the square
        x, u, _, _ = tree.active_segment(n, b)
        assert not segment_enters_polygon(x, b, SQUARE, tol=1e-9)
        assert tree.contacts(n) == tree.contacts(tree.shortest_taut_state(b))


@pytest.mark.parametrize("samples", [2, 3, 17, 200])
def test_unwrapping_a_corner_does_not_rewrap_it_the_other_way(samples):
    # the cable wraps corner A ccw; b moves straight down across the extension of winch→A
    tree = _tree()
    P = np.linspace([2.5, -1.3], [2.0, -5.0], samples)
    n0 = tree.shortest_taut_state(P[0])
    assert tree.contacts(n0) == ((A, 1),)
    tr = track_cable_state(tree, P, node=n0)
    assert tr.events[:, 2].tolist() == [2]  # one unwrap, nothing else
    assert tree.contacts(int(tr.nodes[-1])) == ()
    _check_physical(tree, P, tr, n0)
    back = track_cable_state(tree, P[::-1], node=int(tr.nodes[-1]))
    assert back.nodes[-1] == n0
    assert back.events[:, 2].tolist() == [1]
    np.testing.assert_allclose(back.lengths, tr.lengths[::-1], atol=1e-9)


@pytest.mark.parametrize("samples", [2, 5, 40])
def test_sweep_around_two_corners_and_back(samples):
    tree = _tree()
    P = np.linspace([-0.5, -3.0], [3.0, -0.3], samples)
    n0 = tree.shortest_taut_state(P[0])
    assert tree.contacts(n0) == ()
    tr = track_cable_state(tree, P, node=n0)
    assert [(int(k), tree.contacts(int(n))[-1]) for _, _, k, n in tr.events] == [(1, (A, 1)), (1, (B, 1))]
    assert tree.contacts(int(tr.nodes[-1])) == ((A, 1), (B, 1))
    _check_physical(tree, P, tr, n0)
    back = track_cable_state(tree, P[::-1], node=int(tr.nodes[-1]))
    assert [(int(k), tree.contacts(int(n))[-1]) for _, _, k, n in back.events] == [(2, (B, 1)), (2, (A, 1))]
    assert back.nodes[-1] == n0
    _check_physical(tree, P[::-1], back, int(tr.nodes[-1]))
    np.testing.assert_allclose(back.lengths, tr.lengths[::-1], atol=1e-9)


def test_random_straight_moves_below_the_square():
    # every straight move in the region where the cable runs below the square (y < 0,
    # outside the obstacle), forth and back: tracked state == taut state, consistent wraps
    rng = np.random.default_rng(7)
    done = 0
    while done < 60:
        b0 = np.array([rng.uniform(-2.0, 4.0), rng.uniform(-4.0, -0.05)])
        b1 = np.array([rng.uniform(-2.0, 4.0), rng.uniform(-4.0, -0.05)])
        if segment_enters_polygon(b0, b1, SQUARE + np.sign(SQUARE) * 0.05, tol=0.0):
            continue
        tree = _tree()
        P = np.linspace(b0, b1, int(rng.integers(2, 30)))
        n0 = tree.shortest_taut_state(P[0])
        tr = track_cable_state(tree, P, node=n0)
        _check_physical(tree, P, tr, n0)
        back = track_cable_state(tree, P[::-1], node=int(tr.nodes[-1]))
        assert back.nodes[-1] == n0
        done += 1
