"""Cutting a sub-problem's domain into pieces for parallel jobs (taut.dgp._solve): the
pieces lie in the domain, do not overlap, and every equilibrium of Table 4.3 of
Berti (2015) lies in one of them."""

import numpy as np
import pytest

from taut.dgp import solve_dgp
from taut.dgp._formulation import build_subproblem
from taut.dgp._solve import PREPARED_SIZE, domain_pieces, prepared_subproblem, solve_piece
from taut.errors import TautError
from taut.geometry import rotation_matrix
from taut.interval import MAX_BOXES, Certificate, certify, same_solution
from taut.model import load_robot

ROBOT = load_robot("suspended-3cable")
LENGTHS = np.array(ROBOT.reference.lengths)
TABLE_4_3 = [  # poses and tensions of Conf. 1-6 (see test_table_4_3.py)
    ([2.7505, 3.9798, 5.5061, 3.0064, 0.3417, 0.1089], [0.526, 0.512, 0.581]),
    ([1.700, 3.687, 5.809, 0.339, -1.036, -2.596], [0.676, 0.251, 0.486]),
    ([3.020, 4.757, 3.879, -0.038, 0.027, 0.776], [0.590, 0.783, 0.956]),
    ([1.846, 4.074, 5.322, 2.146, -0.708, 2.423], [0.684, 0.305, 0.614]),
    ([2.138, 4.287, 6.030, -0.482, -0.360, -2.211], [0.546, 0.325, 0.550]),
    ([3.499, 5.369, 4.709, -2.908, -0.174, -2.659], [0.289, 0.787, 0.912]),
]


def test_pieces_hold_every_solution_and_do_not_overlap():
    sp = build_subproblem(ROBOT, LENGTHS, (0, 1, 2))
    pieces = domain_pieces(sp, 3)
    assert len(pieces) == 8
    for i, (alo, ahi) in enumerate(pieces):
        assert np.all(alo >= sp.lo) and np.all(ahi <= sp.hi)
        for blo, bhi in pieces[i + 1 :]:  # interiors are disjoint
            assert np.any(np.minimum(ahi, bhi)[sp.primary] <= np.maximum(alo, blo)[sp.primary])
    for pose, tensions in TABLE_4_3:
        R = rotation_matrix(np.array(pose[3:]), "xyz-fixed")
        x = certify(sp.system, sp.unknowns(pose[:3], R, np.array(tensions) / LENGTHS)).x
        assert sum(bool(np.all(x >= lo) and np.all(x <= hi)) for lo, hi in pieces) >= 1


def test_lengths_no_pose_fits_give_no_piece():
    sp = build_subproblem(ROBOT, np.array([1.0, 1.0, 1.0]), (0, 1, 2))  # exits 10 m apart
    assert domain_pieces(sp, 3) == []


def test_a_process_builds_each_sub_problem_once_for_all_its_pieces():
    sp, pieces = prepared_subproblem(ROBOT, LENGTHS, (0, 1, 2), 3)
    assert prepared_subproblem(ROBOT, LENGTHS, (0, 1, 2), 3)[0] is sp
    assert len(pieces) == 8
    other = prepared_subproblem(ROBOT, LENGTHS * 1.01, (0, 1, 2), 3)[0]  # other lengths: another system
    assert other is not sp and not np.array_equal(other.system.tape.bhi, sp.system.tape.bhi)
    for k in range(PREPARED_SIZE):  # the cache stays bounded: the oldest entries go
        prepared_subproblem(ROBOT, LENGTHS * (1.0 + 1e-3 * k), (0, 1), 0)
    assert prepared_subproblem(ROBOT, LENGTHS, (0, 1, 2), 3)[0] is not sp


def test_same_solution_by_certified_box_or_uniqueness_radius():
    x = np.array([1.0, 2.0])
    a = Certificate(x, x - 1e-12, x + 1e-12, 1e-6)
    assert same_solution(a, Certificate(x + 1e-13, x - 1e-12, x + 1e-12, 0.0))
    assert same_solution(a, Certificate(x + 5e-7, x, x + 1e-6, 0.0))
    assert not same_solution(a, Certificate(x + 1e-3, x, x + 2e-3, 1e-6))


def test_split_out_of_range_is_refused():
    for bad in (-1, 11):
        with pytest.raises(TautError, match="split"):
            solve_dgp(ROBOT, max_taut=2, split=bad)


def test_a_box_that_reached_eps_beside_a_solution_certified_later_is_not_undecided():
    """Teaching prototype, cables 2, 5, 6, piece 14 of 16: depth first, a box hugging the
    solution (1.5e-8 from it, not holding it) reaches eps before the solution is certified;
    it lies in the solution's uniqueness box, so it holds no other solution."""
    robot = load_robot("teaching-prototype")
    job = (robot, np.array(robot.reference.lengths), (1, 4, 5), 1e-7, 4, 14, MAX_BOXES, True)
    sols, certs, undecided, boxes = solve_piece(job)
    assert undecided == [] and len(certs) <= 1 and boxes > 0
