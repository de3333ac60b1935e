"""One taut cable (§2.3.3): the platform hangs along the load with G below (stable) or above."""

import numpy as np

from taut.dgp import solve_dgp
from taut.kinematics import inverse_kinematics
from taut.model import load_robot


def test_one_cable_families_when_the_other_cables_are_long():
    robot = load_robot("suspended-3cable")
    lengths = np.array([5.0, 30.0, 30.0])  # cables 2 and 3 long enough to stay slack
    res = solve_dgp(robot, lengths, max_taut=1)
    sols = [s for s in res.solutions if s.taut == (0,)]
    assert len(sols) == 2 and sorted(s.stable for s in sols) == [False, True]
    for s in sols:
        ik = inverse_kinematics(robot, np.concatenate([s.position, s.orientation]))
        assert abs(ik.lengths[0] - 5.0) < 1e-12 and np.all(ik.lengths[1:] <= 30.0)
        assert np.allclose(s.tensions, [1.0, 0.0, 0.0])
        assert ik.directions[0] @ np.array([0.0, 0.0, -1.0]) > 1 - 1e-12  # the cable is vertical
