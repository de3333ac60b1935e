"""Constants of the DGP equations (Berti 2015, §2.3) are the exact ones of the
robot's data, enclosed outwards: the interval system holds the true system."""

from fractions import Fraction

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from taut.dgp._formulation import build_subproblem, exact_cross, rational_constant, secondary_coordinates
from taut.geometry import rotation_matrix
from taut.interval import CONST, evaluate_point
from taut.model import load_robot

coord = st.floats(-10.0, 10.0, allow_nan=False, allow_infinity=False)
point = st.tuples(coord, coord, coord)


@settings(max_examples=200, deadline=None)
@given(st.fractions(min_value=-1e6, max_value=1e6, max_denominator=10**12))
def test_enclosure_holds_the_rational_and_is_at_most_two_ulps(x):
    e = rational_constant(x)
    assert e.op == CONST
    assert Fraction(e.lo) <= x <= Fraction(e.hi)
    assert e.hi <= np.nextafter(np.nextafter(e.lo, np.inf), np.inf)


@settings(max_examples=200, deadline=None)
@given(point, point, point, point)
def test_secondary_point_coordinates_are_exact(r0, r1, r2, body):
    refs = np.array([r0, r1, r2])
    e1, e2 = refs[1] - refs[0], refs[2] - refs[0]
    if np.linalg.norm(np.cross(e1, e2)) < 1e-3:
        return  # collinear reference points are refused before this is called
    beta = secondary_coordinates(refs, np.array(body))
    R = [[Fraction(float(c)) for c in p] for p in (r0, r1, r2)]
    c1 = [R[1][k] - R[0][k] for k in range(3)]
    c2 = [R[2][k] - R[0][k] for k in range(3)]
    c3 = exact_cross(c1, c2)
    rebuilt = [R[0][k] + beta[0] * c1[k] + beta[1] * c2[k] + beta[2] * c3[k] for k in range(3)]
    assert rebuilt == [Fraction(float(c)) for c in body]


def test_coplanar_anchors_have_no_normal_component():
    robot = load_robot("teaching-prototype")  # all platform anchors at z' = 0.025
    refs = robot.anchors[:3]
    for body in robot.anchors[3:]:
        assert secondary_coordinates(refs, body)[2] == 0


def test_every_constant_node_encloses_a_float_or_two_neighbours():
    robot = load_robot("cogiro")
    sp = build_subproblem(robot, np.array(robot.reference.lengths), (0, 2, 4, 6))
    tape = sp.system.tape
    consts = tape.op == CONST
    lo, hi = tape.clo[consts], tape.chi[consts]
    assert np.all(lo <= hi)
    assert np.all((lo == hi) | (np.nextafter(np.nextafter(lo, np.inf), np.inf) == hi))
    assert np.any(lo < hi)  # derived constants that are not floats are intervals


@settings(max_examples=60, deadline=None)
@given(
    st.tuples(*[st.floats(-1.0, 1.0)] * 3),
    st.tuples(*[st.floats(-np.pi, np.pi)] * 3),
    st.lists(st.floats(0.0, 0.5), min_size=8, max_size=8),
    st.sets(st.integers(0, 7), min_size=2, max_size=6),
)
def test_every_pose_the_lengths_allow_meets_the_geometric_filter_constraints(p, angles, slack, taut):
    """The inequalities of the filter — slack cables no longer than their length (Eq. 3.7)
    and the sphere bounds of Eq. 3.6 on the reference points — hold at every pose whose
    taut cables have exactly their length and whose slack cables are shorter."""
    robot = load_robot("cogiro")
    taut = tuple(sorted(taut))
    R = rotation_matrix(np.array(angles), robot.orientation)
    pos = np.array([0.0, 0.0, 2.0]) + np.array(p)
    b = pos + robot.anchors @ R.T
    span = np.linalg.norm(b - robot.exits, axis=1)
    lengths = np.array([span[i] if i in taut else span[i] + slack[i] for i in range(8)])
    sp = build_subproblem(robot, lengths, taut)
    x = sp.unknowns(pos, R, np.ones(sp.system.n - sp.pose_unknowns))
    tape, h = sp.system.tape, sp.system.n_equations
    v = evaluate_point(tape, x)
    inequality = tape.blo < tape.bhi
    inequality[:h] = False
    assert inequality.sum() >= 3 * 7  # Eq. 3.6 for each reference point and every other cable
    tol = 1e-9 * (1.0 + np.abs(v))
    assert np.all(v[inequality] >= tape.blo[inequality] - tol[inequality])
    assert np.all(v[inequality] <= tape.bhi[inequality] + tol[inequality])
