"""Table 4.3 of Berti (2015): the suspended 3-cable robot has 6 equilibria, all
with 3 taut cables, only Conf. 1 stable; no 1- or 2-cable equilibria."""

import json

import numpy as np
import pytest

from taut.dgp import is_stable, solve_dgp
from taut.dgp._formulation import build_subproblem
from taut.geometry import rotation_matrix
from taut.interval import certify
from taut.kinematics import inverse_kinematics
from taut.model import load_robot
from taut.parallel import get_executor

ROBOT = load_robot("suspended-3cable")
LENGTHS = np.array(ROBOT.reference.lengths)
# Conf. 1 as corrected in the example's notes (row 1 is misprinted), Conf. 2-6 as printed.
TABLE = [
    ([2.7505, 3.9798, 5.5061, 3.0064, 0.3417, 0.1089], [0.526, 0.512, 0.581], True),
    ([1.700, 3.687, 5.809, 0.339, -1.036, -2.596], [0.676, 0.251, 0.486], False),
    ([3.020, 4.757, 3.879, -0.038, 0.027, 0.776], [0.590, 0.783, 0.956], False),
    ([1.846, 4.074, 5.322, 2.146, -0.708, 2.423], [0.684, 0.305, 0.614], False),
    ([2.138, 4.287, 6.030, -0.482, -0.360, -2.211], [0.546, 0.325, 0.550], False),
    ([3.499, 5.369, 4.709, -2.908, -0.174, -2.659], [0.289, 0.787, 0.912], False),
]


def _refs(pose):
    R = rotation_matrix(np.array(pose[3:]), "xyz-fixed")
    return np.array(pose[:3]) + ROBOT.anchors @ R.T, np.array(pose[:3]) + R @ np.array(ROBOT.platform.wrench_point)


@pytest.mark.parametrize("pose, tensions, stable", TABLE)
def test_each_row_is_certified_from_the_printed_values_with_its_stability(pose, tensions, stable):
    sp = build_subproblem(ROBOT, LENGTHS, (0, 1, 2))
    cert = certify(
        sp.system, sp.unknowns(pose[:3], rotation_matrix(np.array(pose[3:]), "xyz-fixed"), np.array(tensions) / LENGTHS)
    )
    assert cert is not None and cert.width < 1e-9 and cert.radius > 0
    p, ang, R = sp.pose(cert.x, "xyz-fixed")
    assert np.allclose(p, pose[:3], atol=6e-3) and np.allclose(ang, pose[3:], atol=7e-3)
    assert np.allclose(inverse_kinematics(ROBOT, np.concatenate([p, ang])).lengths, LENGTHS, atol=1e-9)
    tau = sp.tensions(cert.x, LENGTHS, 3)
    assert np.allclose(tau, tensions, atol=2e-3)
    b, g = _refs(np.concatenate([p, ang]))
    assert is_stable(ROBOT.exits, b, g, tau, LENGTHS) is stable


def test_no_equilibrium_with_one_or_two_taut_cables():
    res = solve_dgp(ROBOT, max_taut=2)
    assert res.subproblems == 6 and res.solutions == () and res.undecided == 0


@pytest.mark.slow
@pytest.mark.parametrize("workers, split", [(1, 0), (2, None), (1, 3)])
def test_table_4_3_complete_solution_set(workers, split):
    with get_executor(workers=workers) as ex:  # split None: the 3-taut domain in 2**SPLIT pieces
        res = solve_dgp(ROBOT, executor=ex, split=split)
    assert res.subproblems == 7 and res.undecided == 0
    assert len(res.solutions) == 6 and all(s.taut == (0, 1, 2) for s in res.solutions)
    assert sum(s.stable for s in res.solutions) == 1
    for pose, tensions, stable in TABLE:
        match = [s for s in res.solutions if np.allclose(s.position, pose[:3], atol=6e-3)]
        assert len(match) == 1
        s = match[0]
        assert np.allclose(s.orientation, pose[3:], atol=7e-3) and np.allclose(s.tensions, tensions, atol=2e-3)
        assert s.stable is stable
        lengths = inverse_kinematics(ROBOT, np.concatenate([s.position, s.orientation])).lengths
        assert np.allclose(lengths, LENGTHS, atol=1e-9)


@pytest.mark.slow
def test_cli_fk_json_plot_and_bad_input(tmp_path, cli):
    out = tmp_path / "fk.png"
    assert cli.main(["fk", "suspended-3cable", "--max-taut", "2", "--plot", str(out), "--json"]) == 0
    data = json.loads(cli.readouterr().out)
    assert data["solutions"] == [] and data["subproblems"] == 6 and data["elapsed_s"] >= 0
    assert data["plot"] == str(out) and out.stat().st_size > 1000
    for bad in ("1,2", "1,0,3", "1,inf,3", "a,b,c"):
        assert cli.main(["fk", "suspended-3cable", f"--lengths={bad}"]) == 2
    assert cli.main(["fk", "suspended-3cable", "--max-taut", "0"]) == 2
