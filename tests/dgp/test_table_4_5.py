"""Table 4.5 of Berti (2015) (MARIONET-VR, 6 cables, platform anchors not
coplanar): the sub-problems with 6, 4, 3 and 2 taut cables hold exactly Conf. 1–3 (stable),
5–11, 12–15 and 16–17 (unstable); the six with 5 taut cables hold no admissible equilibrium
— the printed Conf. 4 stretches its slack cable (last test). The OCR lost z of Conf. 1–2 and
τ4 of Conf. 1, τ2 of Conf. 2–3 (None below): the equations give them (z = 0.778 and 0.338;
τ4 = 0.078; τ2 = 0.291 and 0.271)."""

import numpy as np
import pytest

from taut.dgp import solve_dgp
from taut.dgp._formulation import build_subproblem
from taut.dgp._solve import solve_subset
from taut.geometry import rotation_matrix
from taut.interval import certify, file_certificate
from taut.kinematics import inverse_kinematics
from taut.model import load_robot

ROBOT = load_robot("marionet-vr")
LENGTHS = np.array(ROBOT.reference.lengths)
TABLE = [  # Conf. 1-3 (m = 6): x, y, z, phi_x, phi_y, phi_z; tau_1..tau_6
    ([-0.270, 0.235, None, 2.554, 0.124, 0.080], [0.398, 0.226, 0.248, None, 0.244, 0.268]),
    ([0.253, -0.520, None, 0.960, -0.105, -3.077], [0.262, None, 0.293, 0.278, 0.314, 0.283]),
    ([-0.278, -1.470, 0.549, -0.670, 0.014, -0.043], [0.374, None, 0.156, 0.004, 0.376, 0.220]),
]


def _close(values, printed, atol):
    pairs = [(v, p) for v, p in zip(values, printed) if p is not None]
    return all(abs(v - p) <= atol for v, p in pairs)


@pytest.mark.slow
def test_table_4_5_six_taut_cables():
    sols, undecided, boxes = solve_subset((ROBOT, LENGTHS, tuple(range(6)), 1e-7))
    assert undecided == 0 and boxes > 0 and len(sols) == 3
    for pose, tensions in TABLE:
        match = [s for s in sols if _close(np.r_[s.position, s.orientation], pose, 2e-3)]
        assert len(match) == 1, pose
        s = match[0]
        assert _close(s.tensions, tensions, 2e-3)
        assert s.stable and s.uniqueness_radius > 0 and s.certificate_width < 1e-9
        lengths = inverse_kinematics(ROBOT, np.concatenate([s.position, s.orientation])).lengths
        assert np.allclose(lengths, LENGTHS, atol=1e-9)


def test_table_4_5_two_taut_cables(match_rows):
    res = solve_dgp(ROBOT, max_taut=2)  # Conf. 16-17, and no single-cable equilibrium
    assert res.undecided == 0
    printed = [
        [-0.218, -1.192, 1.499, 1.220, 0.379, 1.539, 0, 1.569, 1.612, 0, 0, 0],
        [0.342, -0.676, 1.244, 1.194, -0.403, -1.458, 0, 0, 0, 1.691, 1.681, 0],
    ]
    assert match_rows(res.solutions, [(r, False) for r in printed], 2e-3, 2e-3, 2e-3) == []


@pytest.mark.slow
def test_table_4_5_three_taut_cables(solve_subsets, match_rows):
    res = solve_subsets(ROBOT, 3)
    assert sum(und for _, und in res.values()) == 0
    sols = [s for found, _ in res.values() for s in found]
    printed = [  # Conf. 12-15: x, y, z, phi_x, phi_y, phi_z, tau_1..tau_6
        [0.132, -0.597, 2.425, -2.065, 0.376, 3.057, 0, 1.355, 0, 0.471, 0, 1.419],
        [0.386, -0.364, 2.294, -1.703, -0.087, -3.059, 1.393, 0, 0, 0, 1.256, 0.480],
        [0.552, -0.525, 2.211, -2.131, -0.431, -2.963, 1.421, 0, 0.546, 0, 1.374, 0],
        [0.332, -0.383, 2.328, -1.700, 0.073, 3.132, 0.442, 1.229, 0, 0, 0, 1.373],
    ]
    assert match_rows(sols, [(r, False) for r in printed], 3e-3, 3e-3, 3e-3) == []


@pytest.mark.slow
def test_table_4_5_four_taut_cables(solve_subsets, match_rows):
    res = solve_subsets(ROBOT, 4)
    sols = [s for found, _ in res.values() for s in found]
    assert sum(und for _, und in res.values()) == 0
    printed = [  # Conf. 5-11: x, y, z, phi_x, phi_y, phi_z, tau_1..tau_6
        [-0.502, -0.452, 0.351, 0.817, -0.913, -2.873, 0, 0.300, 0, 0.492, 0.243, 0.679],
        [-0.289, -0.592, 0.553, 0.940, 0.069, 0.008, 0, 0.395, 0.496, 0.464, 0.432, 0],
        [0.530, -0.505, 2.234, -1.986, -0.324, -3.011, 1.403, 0, 0.353, 0, 1.332, 0.134],
        [-0.217, 0.025, 1.237, -2.420, 0.068, 0.058, 0.545, 0.082, 0, 0, 0.177, 0.506],
        [0.334, -0.380, 2.325, -1.695, 0.067, 3.134, 0.464, 1.200, 0, 0, 0.031, 1.352],
        [0.151, -0.579, 2.411, -2.009, 0.333, 3.075, 0.054, 1.337, 0, 0.395, 0, 1.409],
        [0.879, -0.455, 0.751, 0.862, 0.757, 3.036, 0.658, 0.229, 0.524, 0, 0.339, 0],
    ]
    assert match_rows(sols, [(r, False) for r in printed], 3e-3, 3e-3, 3e-3) == []


@pytest.mark.slow
def test_table_4_5_five_taut_cables(solve_subsets):
    res = solve_subsets(ROBOT, 5)
    assert len(res) == 6 and sum(und for _, und in res.values()) == 0
    assert [s for found, _ in res.values() for s in found] == []


def test_table_4_5_conf_4_stretches_its_slack_cable():
    """Conf. 4 (cables 1,2,3,5,6 taut, 0.002 from Conf. 3 where τ4 = 0.004) solves the
    5-taut equations, but cable 4 would then span 1.26 mm more than its length: with the
    printed data it is not an admissible equilibrium, and the DGP does not report it."""
    taut = (0, 1, 2, 4, 5)
    sp = build_subproblem(ROBOT, LENGTHS, taut)
    pose = np.array([-0.279, -1.470, 0.549, -0.669, 0.016, -0.046])
    tau = np.array([0.381, 0.267, 0.161, 0.380, 0.213])
    cert = certify(sp.system, sp.unknowns(pose[:3], rotation_matrix(pose[3:], "xyz-fixed"), tau / LENGTHS[list(taut)]))
    assert cert is not None and cert.width < 1e-9
    p, ang, _ = sp.pose(cert.x, "xyz-fixed")
    assert np.allclose(np.r_[p, ang], pose, atol=2e-3)
    span = inverse_kinematics(ROBOT, np.r_[p, ang]).lengths
    assert span[3] - LENGTHS[3] == pytest.approx(1.26e-3, abs=1e-5)
    assert file_certificate(sp.system, cert, sp.lo, sp.hi) is None
