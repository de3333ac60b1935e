"""Table 4.6 of Berti (2015) (teaching prototype, 6 cables, coplanar platform
anchors): the sub-problem with all 6 cables taut has exactly Conf. 1 and 2, both stable; the
six with 5 taut cables, exactly Conf. 3–13 (3–5 stable); the fifteen with 4, Conf. 14–25 and
two more; the twenty with 3, Conf. 26–29 and 32–34. The printed data have 3 digits and the
robot is nearly a 3-3 one (exit points and anchors in pairs 2–4 mm apart), so the printed
angles are met to 0.05 rad and the tensions to 0.015, and two printed 3-taut equilibria,
Conf. 30–31 (cables 2, 4, 6), do not solve the equations with these data: next to them, the
sub-problems (2,3,4,6) and (2,4,5,6) each hold an equilibrium whose fourth tension is nearly
0 (0.003 and 0.001) — the same configurations, moved across the boundary between the subsets
by the rounding."""

import numpy as np
import pytest

from taut.dgp import solve_dgp
from taut.dgp._solve import solve_subset
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
    sols, undecided, boxes = solve_subset((ROBOT, LENGTHS, tuple(range(6)), 1e-7))
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
    assert res.subproblems == 21 and res.undecided == 0 and res.solutions == ()


#: the tolerances of the module docstring
TOLERANCES = {"pos_tol": 3e-3, "ang_tol": 5e-2, "tau_tol": 1.5e-2}


@pytest.mark.slow
def test_table_4_6_five_taut_cables(solve_subsets, match_rows):
    res = solve_subsets(ROBOT, 5)
    assert sum(und for _, und in res.values()) == 0
    printed = [  # Conf. 3-13: x, y, z, phi_x, phi_y, phi_z, tau_1..tau_6; stable
        ([0.363, 0.454, 0.122, -2.420, 0.406, -1.341, 0.202, 0.333, 0.105, 0.362, 0, 0.151], True),
        ([0.341, 0.437, 0.122, 2.419, 0.345, 0.449, 0.100, 0.362, 0, 0.159, 0.204, 0.327], True),
        ([0.335, 0.464, 0.122, -3.124, -0.823, 2.636, 0, 0.149, 0.210, 0.326, 0.116, 0.352], True),
        ([0.366, 0.401, 0.098, -0.384, 0.623, 1.265, 0.445, 0.026, 0.382, 0.005, 0.334, 0], False),
        ([0.341, 0.539, 0.118, -1.401, -0.157, 3.104, 0.066, 0.237, 0.180, 0.483, 0, 0.206], False),
        ([0.356, 0.436, 0.130, 3.119, 0.448, -0.087, 0.023, 0.336, 0.045, 0.373, 0, 0.392], False),
        ([0.294, 0.463, 0.099, 0.710, -0.028, 1.369, 0.384, 0.002, 0.333, 0, 0.459, 0.013], False),
        ([0.424, 0.416, 0.117, 1.019, 1.163, -2.600, 0.173, 0.480, 0, 0.216, 0.072, 0.232], False),
        ([0.332, 0.456, 0.131, 2.809, -0.256, 2.131, 0.022, 0.381, 0, 0.409, 0.019, 0.338], False),
        ([0.356, 0.470, 0.131, -2.731, -0.202, -2.250, 0, 0.388, 0.037, 0.327, 0.058, 0.360], False),
        ([0.277, 0.404, 0.116, 1.217, -0.877, 2.383, 0, 0.223, 0.067, 0.252, 0.165, 0.469], False),
    ]
    assert match_rows([s for found, _ in res.values() for s in found], printed, **TOLERANCES) == []


@pytest.mark.slow
def test_table_4_6_four_taut_cables(solve_subsets, match_rows):
    res = solve_subsets(ROBOT, 4)
    assert sum(und for _, und in res.values()) == 0
    printed = [  # Conf. 14-25, all unstable
        ([0.349, 0.467, 0.117, -1.979, 0.416, -1.395, 0.331, 0.232, 0.196, 0.387, 0, 0], False),
        ([0.347, 0.463, 0.137, -1.899, 0.370, 1.567, 0.384, 0.134, 0.234, 0.429, 0, 0], False),
        ([0.414, 0.396, 0.121, 0.399, 1.451, 2.627, 0.424, 0.461, 0, 0.142, 0.134, 0], False),
        ([0.370, 0.440, 0.138, 3.034, 0.894, 2.441, 0.397, 0.439, 0, 0.160, 0.173, 0], False),
        ([0.361, 0.443, 0.117, 2.019, 0.578, 0.036, 0.201, 0.386, 0, 0, 0.341, 0.215], False),
        ([0.354, 0.449, 0.138, 1.951, 0.612, 2.940, 0.234, 0.426, 0, 0, 0.401, 0.120], False),
        ([0.363, 0.539, 0.122, -1.466, -0.471, 2.666, 0.127, 0, 0.433, 0.466, 0, 0.135], False),
        ([0.347, 0.480, 0.138, -2.262, -0.341, 0.231, 0.167, 0, 0.409, 0.442, 0, 0.152], False),
        ([0.324, 0.440, 0.139, 2.339, -0.467, -1.519, 0, 0.159, 0.172, 0, 0.414, 0.426], False),
        ([0.264, 0.424, 0.122, 1.437, -0.567, 1.751, 0, 0.142, 0.133, 0, 0.437, 0.448], False),
        ([0.339, 0.448, 0.137, 2.837, -1.247, -0.602, 0, 0, 0.396, 0.141, 0.228, 0.417], False),
        ([0.330, 0.445, 0.117, 2.891, -1.187, 2.648, 0, 0, 0.336, 0.223, 0.210, 0.376], False),
    ]
    extra = match_rows([s for found, _ in res.values() for s in found], printed, **TOLERANCES)
    # Conf. 31 and 30 (cables 2, 4, 6), each with a nearly-zero fourth tension
    assert sorted(tuple(i + 1 for i in s.taut) for s in extra) == [(2, 3, 4, 6), (2, 4, 5, 6)]
    near = {(2, 3, 4, 6): ([0.295, 0.444, 0.108], 2), (2, 4, 5, 6): ([0.378, 0.429, 0.106], 4)}
    for s in extra:
        position, cable = near[tuple(i + 1 for i in s.taut)]
        assert np.allclose(s.position, position, atol=2.5e-2) and 0 < s.tensions[cable] < 5e-3 and not s.stable


@pytest.mark.slow
def test_table_4_6_three_taut_cables(solve_subsets, match_rows):
    res = solve_subsets(ROBOT, 3)
    assert sum(und for _, und in res.values()) == 0
    printed = [  # Conf. 26-29 and 32-34, all unstable (Conf. 30-31: see the module docstring)
        ([0.367, 0.476, 0.142, -1.991, 0.768, 2.158, 0.364, 0.413, 0, 0.406, 0, 0], False),
        ([0.349, 0.440, 0.139, 2.006, 0.809, 2.651, 0.376, 0.417, 0, 0, 0.387, 0], False),
        ([0.359, 0.462, 0.138, -1.864, 0.152, 1.207, 0.371, 0, 0.390, 0.420, 0, 0], False),
        ([0.355, 0.425, 0.142, 1.877, 0.215, -2.738, 0, 0.404, 0, 0, 0.381, 0.398], False),
        ([0.319, 0.459, 0.142, -2.344, -1.141, -1.026, 0, 0, 0.378, 0.412, 0, 0.394], False),
        ([0.334, 0.459, 0.139, 2.297, -1.121, -0.474, 0, 0, 0.381, 0, 0.395, 0.406], False),
    ]
    rest = match_rows([s for found, _ in res.values() for s in found], printed, **TOLERANCES)
    # Conf. 29 (cables 1, 3, 5) is the most ill-conditioned row: 1e-2 in position, 0.12 in φy
    conf_29 = [0.311, 0.462, 0.096, 0.472, -0.036, 1.353, 0.392, 0, 0.358, 0, 0.445, 0]
    assert [s.taut for s in rest] == [(0, 2, 4)]
    assert match_rows(rest, [(conf_29, False)], **{**TOLERANCES, "pos_tol": 1e-2, "ang_tol": 0.12}) == []
