"""Static forward kinematics with sagging cables: it inverts the static IK, reduces to the
straight elastic equilibrium (solved here with scipy) as the weight goes to 0, says "no
equilibrium" as an answer, and reports stability."""

from __future__ import annotations

import json

import numpy as np
import pytest
from scipy.optimize import root

from taut.cables import sagging_fk, sagging_ik
from taut.errors import TautError, UnreachableLengthsError, UnsupportedRobotError
from taut.kinematics import inverse_kinematics
from taut.model import example
from taut.statics import external_wrench

COGIRO = example("cogiro-sagging")


def _with(robot, **update):
    return robot.model_copy(update={"cables": tuple(c.model_copy(update=update) for c in robot.cables)})


@pytest.mark.parametrize("pose", [[0.5, 0.2, 2.0, 0.0, 0.0, 0.0], [-2.0, 1.5, 1.0, 0.05, -0.04, 0.1]])
def test_fk_inverts_the_ik(pose):
    ik = sagging_ik(COGIRO, pose, method="qp")
    assert ik.feasible
    fk = sagging_fk(COGIRO, ik.unstrained_lengths)
    assert fk.found and fk.stable and fk.within_bounds
    assert np.allclose(fk.pose, pose, rtol=0, atol=1e-9)
    assert np.allclose(fk.platform_tensions, ik.platform_tensions, rtol=1e-7)
    assert np.allclose(fk.exit_tensions, ik.exit_tensions, rtol=1e-7)
    assert np.all(fk.stiffness_eigenvalues > 0)


def _straight_equilibrium(robot, L0, start):
    """The platform on weightless elastic cables, ``τ = EA (l − L0)/L0``, balanced by scipy."""
    ea = np.array([c.stiffness for c in robot.cables])

    def net(q):
        ik = inverse_kinematics(robot, q)
        tau = ea * (ik.lengths - L0) / L0  # every cable is taut at the solution (asserted)
        return ik.structure_matrix @ tau + external_wrench(robot, q)

    sol = root(net, start, method="hybr", options={"xtol": 1e-13})
    assert np.abs(net(sol.x)).max() < 1e-9
    return sol.x


def test_weightless_limit_is_the_straight_elastic_equilibrium():
    straight = _with(example("spatial-8cable"), stiffness=2e4)
    built = [0.1, -0.05, 0.08, 0.05, 0.0, -0.03]
    L0 = inverse_kinematics(straight, built).lengths * 0.98  # 2 % pretension, 400 N against 49 N of weight
    expected = _straight_equilibrium(straight, L0, built)
    assert np.all(inverse_kinematics(straight, expected).lengths > L0)  # every cable taut
    light = _with(straight, weight=1e-12)
    fk = sagging_fk(light, L0, guess=built)
    assert fk.found
    assert np.allclose(fk.pose, expected, rtol=1e-9, atol=1e-12)
    # the stiffness is the Hessian of the potential energy of the springs and the weight,
    # differenced here: this pretensioned equilibrium is unstable about one direction
    ea = 2e4

    def energy(q):
        return np.sum(ea / (2 * L0) * (inverse_kinematics(straight, q).lengths - L0) ** 2) + 5.0 * 9.81 * q[2]

    h, eye = 1e-4, np.eye(6)
    hessian = np.array(
        [
            [
                (
                    energy(fk.pose + h * eye[i] + h * eye[j])
                    - energy(fk.pose + h * eye[i] - h * eye[j])
                    - energy(fk.pose - h * eye[i] + h * eye[j])
                    + energy(fk.pose - h * eye[i] - h * eye[j])
                )
                / (4 * h * h)
                for j in range(6)
            ]
            for i in range(6)
        ]
    )
    assert np.allclose(fk.stiffness_eigenvalues, np.linalg.eigvalsh(hessian), rtol=1e-4, atol=1e-2)
    assert fk.stable == (np.linalg.eigvalsh(hessian).min() > 0)


def test_inextensible_limit():
    """EA → ∞: the pose tends to the inextensible cables' at the rate 1/EA (the stretch); the
    inextensible FK inverts the inextensible IK to 1e-9."""
    pose = [0.5, 0.2, 2.0, 0.0, 0.0, 0.0]
    rigid = _with(COGIRO, stiffness=None)
    L0 = sagging_ik(rigid, pose, method="qp").unstrained_lengths
    exact = sagging_fk(rigid, L0)
    assert exact.found and np.allclose(exact.pose, pose, rtol=0, atol=1e-9)
    gaps = []
    for ea in (1e6, 1e8):
        fk = sagging_fk(_with(COGIRO, stiffness=ea), L0, guess=pose)
        assert fk.found
        gaps.append(np.abs(fk.pose - exact.pose).max())
    assert gaps[1] < 2e-2 * gaps[0]


def test_no_equilibrium_is_an_answer():
    """8.5 m inextensible cables reach across the frame pairwise (no triangle inequality
    refuses them) but leave no pose where every one is longer than its chord."""
    rigid = _with(COGIRO, stiffness=None)
    fk = sagging_fk(rigid, [8.5] * 8)
    assert not fk.found
    d = fk.as_dict()
    assert d["pose"] is None and d["found"] is False
    json.dumps(d, allow_nan=False)


def test_bad_input():
    with pytest.raises(TautError, match="unstrained_lengths"):
        sagging_fk(COGIRO, [10.0] * 7)
    with pytest.raises(TautError, match="unstrained_lengths"):
        sagging_fk(COGIRO, [10.0] * 7 + [-1.0])
    with pytest.raises(UnsupportedRobotError, match="no sagging cables"):
        sagging_fk(example("spatial-8cable"), [2.0] * 8)
    cables = list(COGIRO.cables)
    cables[0] = cables[0].model_copy(update={"weight": None, "stiffness": None})
    mixed = COGIRO.model_copy(update={"cables": tuple(cables)})
    with pytest.raises(UnsupportedRobotError, match="straight and inextensible"):
        sagging_fk(mixed, [10.0] * 8)


def test_cli_fk_on_a_sagging_robot(taut_cli):
    ik = sagging_ik(COGIRO, [0.5, 0.2, 2.0, 0.0, 0.0, 0.0], method="qp")
    lengths = ",".join(repr(float(x)) for x in ik.unstrained_lengths)
    d = taut_cli("fk", "cogiro-sagging", "--lengths", lengths, "--json").json()
    assert d["found"] and d["stable"]
    assert np.allclose(d["pose"], [0.5, 0.2, 2.0, 0.0, 0.0, 0.0], atol=1e-9)
    assert "catenary" in d["model"]


@pytest.mark.slow
def test_cli_fk_needs_lengths(taut_cli):
    missing = taut_cli("fk", "cogiro-sagging")
    assert missing.code == 2 and missing.err.count("\n") == 1 and "--lengths" in missing.err


@pytest.mark.slow
def test_cli_no_equilibrium_is_an_answer(taut_cli, tmp_path):
    from taut.model import save_robot

    save_robot(_with(COGIRO, stiffness=None), tmp_path / "rigid.yaml")
    d = taut_cli("fk", str(tmp_path / "rigid.yaml"), "--lengths", "8.5,8.5,8.5,8.5,8.5,8.5,8.5,8.5", "--json").json()
    assert d["found"] is False and d["pose"] is None


def test_lengths_no_pose_fits_are_refused_by_the_triangle_inequality():
    """Two inextensible cables whose lengths and anchors' distance fall short of their exits'
    distance: each cannot be longer than its chord at any pose.  A hair longer, they pass."""
    rigid = _with(COGIRO, stiffness=None)
    reach = np.linalg.norm(rigid.exits[2] - rigid.exits[7]) - np.linalg.norm(rigid.anchors[2] - rigid.anchors[7])
    for margin, refused in ((-1e-6, True), (1e-6, False)):
        L = np.full(8, 30.0)
        L[[2, 7]] = (reach + margin) / 2
        if refused:
            with pytest.raises(UnreachableLengthsError, match="cables 3 and 8 .* shorter than its chord"):
                sagging_fk(rigid, L)
        else:  # an answer, found or not
            assert sagging_fk(rigid, L).as_dict()["found"] in (True, False)


def test_cli_fk_lengths_no_pose_fits_exit_2(taut_cli, tmp_path):
    from taut.model import save_robot

    save_robot(_with(COGIRO, stiffness=None), tmp_path / "rigid.yaml")
    run = taut_cli("fk", str(tmp_path / "rigid.yaml"), "--lengths", "5,5,5,5,5,5,5,5", "--json")
    assert run.code == 2 and run.out == "" and run.err.count("\n") == 1
    assert run.err.startswith("taut: error: ") and "no pose fits the lengths" in run.err and "cables 3 and 8" in run.err
