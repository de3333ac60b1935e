"""Table 4.6 of 001_eb92e2f6589fc229.txt (teaching prototype, 6 cables, coplanar platform
anchors): the sub-problem with all 6 cables taut has exactly Conf. 1 and 2, both stable."""

import numpy as np
import pytest

from taut.dgp import solve_dgp
from taut.dgp.solve import _solve_subset
from taut.kinematics import inverse_kinematics
from taut.model import load_robot

ROBOT = load_robot("teaching-prototype")
LENGTHS = np.array(ROBOT.reference.lengths)
TABLE = [  # Conf. 1-2 (m = 6): pose, tensions
    ([0.346, 0.453, 0.066, -0.003, 0.005, -0.518], [0.153, 0.228, 0.156, 0.225, 0.163, 0.219]),
    ([0.348, 0.453, 0.088, -0.019, 0.004, 2.081], [0.231, 0.165, 0.233, 0.162, 0.239, 0.155]),
]


@pytest.mark.slow
def test_table_4_6_six_taut_cables():
    sols, undecided, boxes = _solve_subset((ROBOT, LENGTHS, tuple(range(6)), 1e-7))
    assert undecided == 0 and boxes > 0 and len(sols) == 2
    for pose, tensions in TABLE:
        match = [s for s in sols if np.allclose(s.position, pose[:3], atol=3e-3)]
        assert len(match) == 1
        s = match[0]
        assert np.allclose(s.orientation, pose[3:], atol=2e-2) and np.allclose(s.tensions, tensions, atol=8e-3)
        assert s.stable and s.uniqueness_radius > 0 and s.certificate_width < 1e-9
        lengths = inverse_kinematics(ROBOT, np.concatenate([s.position, s.orientation])).lengths
        assert np.allclose(lengths, LENGTHS, atol=1e-9)


def test_table_4_6_no_equilibrium_with_one_or_two_taut_cables():
    res = solve_dgp(ROBOT, max_taut=2)  # the table's rows all have 3 to 6 taut cables
    assert res.subproblems == 21 and res.undecided == 0 and res.solutions == []
