"""Shortening of pose-space paths (``taut.planning._posespace.simplify``): in a space whose
valid set is known exactly — the plane of a planar platform's position without an open disc,
every orientation valid — the shortest path is known in closed form (two tangents and an arc,
the orientation turning in proportion to the arc length), and a segment's clearance is a
point-to-segment distance.  Shortening on robots: tests/planning/test_pose_space.py."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from taut.model import example
from taut.planning._posespace import PoseSpace, _shortcuts, _shortest, simplify

#: The disc of invalid positions: centred at the origin, this radius.
RADIUS = 0.5
#: Start and goal positions, either side of the disc.
END = 0.9
RESOLUTION = 0.01


def _disc_space() -> PoseSpace:
    """A planar platform's pose space ``(x, y, θ)`` whose valid poses are those with the
    position outside the open disc."""

    def check(poses):
        return np.hypot(poses[:, 0], poses[:, 1]) > RADIUS, None

    lower, upper = np.array([-1.5, -1.5, -np.pi]), np.array([1.5, 1.5, np.pi])
    return PoseSpace(example("planar-4cable"), lower, upper, np.array([2]), check, lambda **_: check, np.eye(3))


SPACE = _disc_space()


def _length(path) -> float:
    return float(np.linalg.norm(np.diff(path, axis=0), axis=1).sum())


def _geodesic(turn: float) -> float:
    """Length of the shortest path from ``(−END, 0)`` to ``(END, 0)`` around the disc with
    the orientation turning by ``turn``: the planar one (two tangents and the arc between
    them) and the turn as the legs of a right triangle."""
    planar = 2 * np.sqrt(END**2 - RADIUS**2) + RADIUS * (np.pi - 2 * np.arccos(RADIUS / END))
    return float(np.hypot(planar, turn))


def _clearance(path) -> float:
    """The least distance from the disc's centre to the path's positions (exact per segment)."""
    a, b = path[:-1, :2], path[1:, :2]
    d = b - a
    t = np.clip(-np.einsum("ij,ij->i", a, d) / np.maximum(np.einsum("ij,ij->i", d, d), 1e-300), 0.0, 1.0)
    return float(np.linalg.norm(a + t[:, None] * d, axis=1).min())


def _zigzag() -> np.ndarray:
    """Over the disc on a circle of radius 0.75, the orientation swinging at each vertex."""
    angles = np.linspace(np.pi, 0.0, 9)
    inner = np.column_stack([0.75 * np.cos(angles), 0.75 * np.sin(angles), np.where(np.arange(9) % 2, 0.4, -0.2)])
    return np.vstack([[-END, 0.0, 0.0], inner, [END, 0.0, 0.6]])


def test_the_fixture_path_is_valid_and_long():
    path = _zigzag()
    assert _clearance(path) > RADIUS
    assert _length(path) > 2.5 * _geodesic(0.6)


def test_partial_shortcuts_straighten_what_full_shortcuts_cannot():
    # Full shortcuts that would skip the orientation's swings cross the disc; straightening
    # the orientation alone (Geraerts & Overmars 2007) keeps the positions clear of it.
    path = _zigzag()
    full, _ = _shortcuts(SPACE, path, RESOLUTION, np.random.default_rng(0), np.inf, 2000, partial=False)
    partial, _ = _shortcuts(SPACE, path, RESOLUTION, np.random.default_rng(0), np.inf, 2000, partial=True)
    assert _length(partial) < _length(full) < _length(path)
    assert _length(partial) < 1.01 * _geodesic(0.6)
    for p in (full, partial):
        assert _clearance(p) > RADIUS - 1e-4  # a chord between checked poses 0.01 apart dips ≤ 2.5e-5
        assert np.array_equal(p[0], path[0]) and np.array_equal(p[-1], path[-1])


@settings(max_examples=10, deadline=None)
@given(
    data=st.data(),
    n=st.integers(2, 10),
    seed=st.integers(0, 2**32 - 1),
    ends=st.tuples(st.floats(-1.4, 1.4), st.floats(-1.4, 1.4)),
)
def test_shortening_never_lengthens_keeps_the_path_valid_and_nears_the_shortest(data, n, seed, ends):
    angles = np.sort(data.draw(st.lists(st.floats(0.05, np.pi - 0.05), min_size=n, max_size=n)))[::-1]
    radii = np.array(data.draw(st.lists(st.floats(0.6, 1.3), min_size=n, max_size=n)))
    turns = np.array(data.draw(st.lists(st.floats(-1.4, 1.4), min_size=n, max_size=n)))
    path = np.vstack(
        [
            [-END, 0.0, ends[0]],
            np.column_stack([radii * np.cos(angles), radii * np.sin(angles), turns]),
            [END, 0.0, ends[1]],
        ]
    )
    if _clearance(path) <= RADIUS + 1e-3:  # a drawn polyline that crosses the disc is no path
        return
    short = simplify(SPACE, path, RESOLUTION, np.random.default_rng(seed), np.inf)
    assert np.array_equal(short[0], path[0]) and np.array_equal(short[-1], path[-1])
    assert _length(short) <= _length(path) + 1e-12
    assert _clearance(short) > RADIUS - 1e-4
    assert np.all(np.abs(np.diff(short[:, 2])) < np.pi)  # each step turns the short way
    # Validity is checked at poses ``RESOLUTION`` apart, so vertices end up on the disc's
    # rim with chords between them that dip inside unseen; moving such a stretch samples
    # other poses of it, which may fall inside, and the path can stay a little long.  Over
    # 400 random paths: median 0.3 % above the shortest, 99th percentile 1.3 %, worst 3.6 %.
    shortest = _geodesic(ends[1] - ends[0])
    assert shortest * (1 - 1e-4) <= _length(short) <= 1.05 * shortest


def test_the_path_that_shortens_best_is_chosen():
    # Two paths over the disc: a long zigzag that shortens to the shortest path, and a shorter
    # one that turns the orientation the long way round (by 0.6 − 2π), which no shortcut
    # changes (each step turns by less than π): it stays longer than 2π − 0.6.
    over = _zigzag()
    round_ = np.array([[-END, 0.0, 0.0], [-0.53, 0.53, -1.9], [0.53, 0.53, -3.8], [END, 0.0, 0.6 - 2 * np.pi]])
    assert _clearance(round_) > RADIUS and _length(round_) < _length(over)
    raw, short = _shortest(SPACE, [round_, over], RESOLUTION, np.random.default_rng(0), np.inf)
    assert raw is over and np.array_equal(short[[0, -1]], over[[0, -1]])
    assert _length(short) < 2 * np.pi - 0.6 < _length(over)
