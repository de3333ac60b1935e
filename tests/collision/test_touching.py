"""Touching cables (radius 0, crossing exactly) collide whatever the order of the cables or the
mirror image of the robot: the verdict against an exact rational segment distance."""

from fractions import Fraction

import numpy as np
from hypothesis import assume, example, given, settings
from hypothesis import strategies as st

from taut.collision import proximity
from taut.model import robot_from_dict


def exact_distance2(a1, b1, a2, b2):
    """Squared distance of two segments in rational arithmetic: the minimum of the convex
    quadratic ``‖r + s u − t v‖²`` over ``[0, 1]²`` is at its stationary point or on an edge
    of the square, and each edge is an end point against the other segment."""

    def dot(x, y):
        return sum(p * q for p, q in zip(x, y))

    def point_segment(p, a, v):
        vv = dot(v, v)
        t = min(Fraction(1), max(Fraction(0), dot([x - y for x, y in zip(p, a)], v) / vv)) if vv else Fraction(0)
        g = [y + t * w - x for x, y, w in zip(p, a, v)]
        return dot(g, g)

    u = [y - x for x, y in zip(a1, b1)]
    v = [y - x for x, y in zip(a2, b2)]
    r = [x - y for x, y in zip(a1, a2)]
    a, b, c, e, f = dot(u, u), dot(u, v), dot(u, r), dot(v, v), dot(v, r)
    best = min(point_segment(a1, a2, v), point_segment(b1, a2, v), point_segment(a2, a1, u), point_segment(b2, a1, u))
    denom = a * e - b * b
    if denom:
        s, t = (b * f - c * e) / denom, (a * f - b * c) / denom
        if 0 <= s <= 1 and 0 <= t <= 1:
            g = [x + s * p - t * q for x, p, q in zip(r, u, v)]
            best = min(best, dot(g, g))
    return best


def robot(exits, anchors):
    """A rigid 3-D platform at the origin (pose 0), one cable of radius 0 per exit and anchor."""
    cables = [{"exit": [float(x) for x in a], "anchor": [float(x) for x in b]} for a, b in zip(exits, anchors)]
    return robot_from_dict({"name": "touching", "dimension": 3, "platform": {"kind": "rigid"}, "cables": cables})


def verdicts(exits, anchors):
    """``{(i, j): colliding}`` over the cable pairs at pose 0."""
    res = proximity(robot(exits, anchors), np.zeros(6))
    return {tuple(int(x) for x in pair): bool(c) for pair, c in zip(res.model.pairs, res.colliding[0])}


tenth = st.integers(-30, 30).map(lambda k: Fraction(k, 10))
point = st.tuples(tenth, tenth, tenth)


@st.composite
def configurations(draw):
    """Exits and anchors in tenths (exact fractions); cable 1 is often made to cross cable 0
    at ``X = a_0 + (j / 10) (b_0 − a_0)`` (its anchor ``2 X − a_1``)."""
    n = draw(st.integers(2, 4))
    exits = [list(draw(point)) for _ in range(n)]
    anchors = [list(draw(point)) for _ in range(n)]
    if draw(st.booleans()):
        j = draw(st.integers(1, 9))
        X = [a + Fraction(j, 10) * (b - a) for a, b in zip(exits[0], anchors[0])]
        anchors[1] = [2 * x - a for x, a in zip(X, exits[1])]
    ends = [tuple(p) for p in exits + anchors]
    assume(len(set(ends)) == len(ends))  # no shared end, no cable of length 0
    return exits, anchors, draw(st.permutations(range(n)))


# cables 1 and 2 cross at (0.1, 0.3, 0.3), once computed 1.1e-16 apart (1.5e-16 with the
# cables swapped): reported free, and not colliding
CROSSING = (
    [[Fraction(-3, 10), Fraction(1, 10), Fraction(2, 10)], [Fraction(1, 10), Fraction(7, 10), Fraction(-1, 10)]],
    [[Fraction(5, 10), Fraction(5, 10), Fraction(4, 10)], [Fraction(1, 10), Fraction(-1, 10), Fraction(7, 10)]],
    [1, 0],
)


@settings(max_examples=60, deadline=None)
@given(configurations())
@example(CROSSING)
def test_touching_cables_collide_in_any_order_and_mirror_image(config):
    exits, anchors, perm = config
    n = len(exits)
    expected = {
        (i, j): exact_distance2(exits[i], anchors[i], exits[j], anchors[j]) == 0
        for i in range(n)
        for j in range(i + 1, n)
    }
    assert verdicts(exits, anchors) == expected
    mirror = [[-p[0], p[1], p[2]] for p in exits], [[-p[0], p[1], p[2]] for p in anchors]
    assert verdicts(*mirror) == expected
    got = verdicts([exits[k] for k in perm], [anchors[k] for k in perm])  # cable i is cable perm[i]
    assert {tuple(sorted((perm[i], perm[j]))): c for (i, j), c in got.items()} == expected
