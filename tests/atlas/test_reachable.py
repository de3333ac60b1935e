"""Cable-reachable areas (§5.1.2) against a brute-force reference: dense sampled end
points, each tested with the CST's admissibility test (``CableStateTree.is_taut``)."""

import numpy as np
import pytest
import shapely
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from shapely.geometry import Polygon

from taut.atlas import cable_reachable_area
from taut.model import example
from taut.wrapping import CableStateTree, wrapped_inverse_kinematics

CASES = [
    ("vscr-t-shaped", [0.8128, -0.2032]),
    ("vscr-single-cable", [0.0, 2.0]),
    ("vscr-four-cable", [0.75, -0.5]),
    ("vscr-rehabilitation", [0.0, 0.254]),
]
#: Points this close to the CRA boundary are not judged (chords of the arcs).
BOUNDARY = 1e-4


def _states(name, start, per_cable=3):
    robot = example(name)
    ik = wrapped_inverse_kinematics(robot, [start])
    for i, tree in enumerate(ik.trees):
        node = int(ik.nodes[0, i])
        kids = [int(c) for c in tree.children(node)]
        deeper = [int(g) for c in kids[:1] for g in tree.children(c)][:1]
        for n in [node, *kids[:per_cable], *deeper]:
            yield robot, tree, n


@pytest.mark.slow
@pytest.mark.parametrize("name, start", CASES)
def test_cra_matches_brute_force(name, start):
    rng = np.random.default_rng(7)
    checked = 0
    for robot, tree, node in _states(name, start):
        space = robot.installation_space
        A = cable_reachable_area(tree, node, installation_space=space)
        x0, y0, x1, y1 = Polygon(space).bounds if space else A.bounds
        P = rng.uniform([x0, y0], [x1, y1], (600, 2))
        if space:
            P = P[shapely.contains_xy(Polygon(space), P[:, 0], P[:, 1])]
        ref = np.array([tree.is_taut(node, p) for p in P])
        got = shapely.contains_xy(A, P[:, 0], P[:, 1])
        far = shapely.distance(A.boundary, shapely.points(P)) > BOUNDARY
        assert np.array_equal(ref[far], got[far]), (name, tree.contacts(node), P[far & (ref != got)][:3])
        assert ref.any() and (~ref).any() or space is None
        checked += 1
    assert checked >= 4


def test_cra_of_free_cable_is_whole_space():
    """A cable in the open (no object, no region) reaches the whole installation space."""
    robot = example("vscr-t-shaped")
    ik = wrapped_inverse_kinematics(robot, [[0.8128, -0.2032]])
    tree = ik.trees[0]
    tree.circles[:-1, 2] = 0.0  # shrink the idlers to points: nothing blocks
    tree.disallowed = []
    A = cable_reachable_area(tree, 0, installation_space=robot.installation_space)
    full = Polygon(robot.installation_space).difference(shapely.Point(robot.cables[0].exit).buffer(0.025, 256))
    assert A.symmetric_difference(full).area < 1e-6


def test_cra_wrapped_state_is_bounded_by_unwrap_ray():
    """In a wrapped state the CRA lies on the wrapping side of the incoming segment's line."""
    robot = example("vscr-single-cable")
    ik = wrapped_inverse_kinematics(robot, [[0.0, 2.0]])
    tree = ik.trees[0]
    node = int(tree.children(0)[0])
    A = cable_reachable_area(tree, node)
    e, u, d = tree.F[node, 2:4], tree.F[node, 4:6], tree.F[node, 9]
    xy = np.asarray(A.exterior.coords)
    side = d * (u[0] * (xy[:, 1] - e[1]) - u[1] * (xy[:, 0] - e[0]))
    beyond = (xy - e) @ u > 1e-9
    assert (side[beyond] >= -1e-9).all()


@pytest.mark.slow
@settings(max_examples=12, deadline=None)
@given(
    st.lists(st.tuples(st.floats(-0.8, 0.8), st.floats(0.2, 1.6), st.floats(0.03, 0.2)), min_size=1, max_size=3),
    st.floats(0.0, 0.05),
    st.sampled_from([1, -1]),
)
def test_cra_random_circles(objects, pulley, direction):
    """Random disjoint circles above a winch at the origin: every state of depth ≤ 2 has
    the CRA that sampling with the CST's test gives."""
    C = np.array(objects, float)
    for i in range(len(C)):
        assume(np.hypot(*C[i, :2]) > C[i, 2] + pulley + 0.02)
        for j in range(i):
            assume(np.hypot(*(C[i, :2] - C[j, :2])) > C[i, 2] + C[j, 2] + 0.02)
    tree = CableStateTree(np.vstack([C, [[0.0, 0.0, pulley]]]), direction)
    space = [[-1.5, -0.5], [1.5, -0.5], [1.5, 2.0], [-1.5, 2.0]]
    P = np.random.default_rng(1).uniform([-1.5, -0.5], [1.5, 2.0], (500, 2))
    nodes = [0] + [int(c) for c in tree.children(0)]
    nodes += [int(g) for c in nodes[1:3] for g in tree.children(c)][:2]
    for node in nodes:
        A = cable_reachable_area(tree, node, installation_space=space)
        ref = np.array([tree.is_taut(node, p) for p in P])
        got = shapely.contains_xy(A, P[:, 0], P[:, 1])
        far = shapely.distance(A.boundary, shapely.points(P)) > BOUNDARY
        assert np.array_equal(ref[far], got[far]), (tree.contacts(node), P[far & (ref != got)][:3])
