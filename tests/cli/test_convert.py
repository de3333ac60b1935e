"""CASPR models through the command line (real subprocesses): every robot command reads a
``*_bodies.xml``, ``--cable-set`` picks a set, ``taut convert`` writes the format OUT's name
selects; bad files exit 2 with one line."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import yaml

FIXTURES = Path(__file__).resolve().parents[1] / "model" / "fixtures" / "caspr"
COGIRO = FIXTURES / "real" / "CoGiRo_bodies.xml"
KNTU = FIXTURES / "real" / "KNTU_planar_bodies.xml"
SPIDERBOT = FIXTURES / "real" / "SpiderBot_UR3_bodies.xml"


def rot(axis: int, t: float) -> np.ndarray:
    """The elementary rotation by ``t`` about the x (0), y (1) or z (2) axis."""
    c, s = math.cos(t), math.sin(t)
    return [
        np.array([[1, 0, 0], [0, c, -s], [0, s, c]]),
        np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]]),
        np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]]),
    ][axis]


def raw_lengths(bodies: Path, position: np.ndarray, R: np.ndarray) -> np.ndarray:
    """Cable lengths from the cables file's raw numbers (CASPR: attachments about the joint
    or the centre of mass)."""
    com = np.array(ET.parse(bodies).getroot().findtext(".//com_location", "").split(), dtype=float)
    out = []
    for cable in ET.parse(str(bodies).replace("_bodies", "_cables")).getroot().iter("cable_ideal"):
        base, anchor = (np.array(a.findtext("location", "").split(), dtype=float) for a in cable.iter("attachment"))
        if cable.get("attachment_reference") == "com":
            anchor = anchor + com
        out.append(np.linalg.norm(base - position - R @ anchor))
    return np.array(out)


def test_ik_of_a_real_spatial_caspr_model(taut_cli: Callable[..., Any]) -> None:
    q = [0.3, -0.2, 2.1, 0.1, -0.15, 0.25]
    data = taut_cli("ik", str(COGIRO), "--pose", ",".join(map(str, q)), "--json").json()
    R = rot(0, q[3]) @ rot(1, q[4]) @ rot(2, q[5])  # SPATIAL_EULER_XYZ: Rx(α) Ry(β) Rz(γ)
    np.testing.assert_allclose(data["lengths"], raw_lengths(COGIRO, np.array(q[:3]), R), rtol=1e-12)


def test_ik_of_a_real_planar_caspr_model(taut_cli: Callable[..., Any]) -> None:
    data = taut_cli("ik", str(KNTU), "--pose=-0.2,0.1,0.3", "--json").json()
    expected = raw_lengths(KNTU, np.array([-0.2, 0.1, 0.0]), rot(2, 0.3))  # PLANAR_XY: Rz(θ)
    np.testing.assert_allclose(data["lengths"], expected, rtol=1e-12)
    assert np.array(data["structure_matrix"]).shape == (3, 4)


def test_cable_set_and_convert_to_taut(taut_cli: Callable[..., Any], tmp_path: Path) -> None:
    out = tmp_path / "springs.yaml"
    bodies = str(FIXTURES / "spatial_euler_bodies.xml")
    data = taut_cli("convert", bodies, str(out), "--cable-set", "springs", "--json").json()
    assert data == {"in": bodies, "out": str(out), "format": "taut", "robot": "spatial_euler"}
    robot = yaml.safe_load(out.read_text())
    assert [c["stiffness"] for c in robot["cables"]] == [2.5e4 + 100 * i for i in range(8)]
    default = taut_cli("ik", bodies, "--pose", "0,0,1,0,0,0", "--json").json()
    again = taut_cli("ik", str(out), "--pose", "0,0,1,0,0,0", "--json").json()
    assert default["lengths"] != again["lengths"]  # the springs set attaches its cables elsewhere
    springs = taut_cli("ik", bodies, "--cable-set", "springs", "--pose", "0,0,1,0,0,0", "--json").json()
    assert springs["lengths"] == again["lengths"]


@pytest.mark.slow
def test_convert_an_example_to_caspr_and_back(taut_cli: Callable[..., Any], tmp_path: Path) -> None:
    out = tmp_path / "cogiro_bodies.xml"
    data = taut_cli("convert", "cogiro", str(out), "--json").json()
    assert data["format"] == "caspr" and (tmp_path / "cogiro_cables.xml").is_file()
    pose = "0.2,-0.1,1.5,0.1,0.2,-0.1"
    a = taut_cli("ik", "cogiro", "--pose", pose, "--json").json()
    b = taut_cli("ik", str(out), "--pose", pose, "--json").json()
    np.testing.assert_allclose(b["lengths"], a["lengths"], rtol=1e-14)
    ta = taut_cli("tensions", "cogiro", "--pose", pose, "--json").json()
    tb = taut_cli("tensions", str(out), "--pose", pose, "--json").json()
    assert ta["feasible"] == tb["feasible"]


def test_convert_an_example_to_wirex_and_back(taut_cli: Callable[..., Any], tmp_path: Path) -> None:
    out = tmp_path / "cogiro.wcrfx"
    assert taut_cli("convert", "cogiro", str(out), "--json").json()["format"] == "wirex"
    pose = "0.2,-0.1,1.5,0.1,0.2,-0.1"
    a = taut_cli("ik", "cogiro", "--pose", pose, "--json").json()
    b = taut_cli("ik", str(out), "--pose", pose, "--json").json()
    np.testing.assert_allclose(b["lengths"], a["lengths"], rtol=1e-14)
    np.testing.assert_allclose(b["structure_matrix"], a["structure_matrix"], rtol=1e-12, atol=1e-15)


def test_convert_to_mujoco(taut_cli: Callable[..., Any], tmp_path: Path) -> None:
    """A robot file with mass and inertia becomes an MJCF model MuJoCo loads, with one
    tendon and one actuator per cable; its tendon lengths at the zero pose are taut's."""
    mujoco = pytest.importorskip("mujoco")
    taut_cli("convert", "spatial-8cable", str(tmp_path / "r.yaml"), "--json")
    data = yaml.safe_load((tmp_path / "r.yaml").read_text())
    data["platform"]["inertia"] = [0.05, 0.06, 0.07, 0.0, 0.0, 0.0]
    (tmp_path / "r.yaml").write_text(yaml.safe_dump(data))
    out = tmp_path / "r.mjcf.xml"
    assert taut_cli("convert", str(tmp_path / "r.yaml"), str(out), "--json").json()["format"] == "mujoco"
    model = mujoco.MjModel.from_xml_path(str(out))
    assert model.ntendon == model.nu == len(data["cables"])
    sim = mujoco.MjData(model)
    mujoco.mj_forward(model, sim)
    ik = taut_cli("ik", str(tmp_path / "r.yaml"), "--pose", "0,0,0,0,0,0", "--json").json()
    np.testing.assert_allclose(sim.ten_length, ik["lengths"], atol=1e-12)


def test_convert_a_jointed_caspr_model_to_mujoco(taut_cli: Callable[..., Any], tmp_path: Path) -> None:
    """CASPR's SpiderBot (a platform on 8 cables over swivelling pulleys, carrying a 6-joint
    UR3 arm) becomes an MJCF model MuJoCo loads: the arm's links are hinged bodies with
    CASPR's masses and a drive each; at a pose its tendon lengths are ``taut ik``'s, and at
    rest without tensions the arm's drives must hold the links' weights, taut's joint forces."""
    mujoco = pytest.importorskip("mujoco")
    from taut.kinematics import joint_forces
    from taut.model import load_robot, pose_to_qpos

    out = tmp_path / "spiderbot.mjcf.xml"
    assert taut_cli("convert", str(SPIDERBOT), str(out), "--json").json()["format"] == "mujoco"
    model = mujoco.MjModel.from_xml_path(str(out))
    assert (model.ntendon, model.nu, model.njnt) == (8, 8 + 6, 1 + 6 + 8)
    assert [model.jnt_type[model.joint(f"joint{k}").id] for k in range(1, 7)] == [mujoco.mjtJoint.mjJNT_HINGE] * 6
    np.testing.assert_allclose(
        [model.body(f"body{k}").mass[0] for k in range(1, 7)], [2.0, 3.42, 1.26, 0.8, 0.8, 0.35], rtol=1e-15
    )
    pose = [1.1, 1.0, 0.9, 0.1, -0.2, 0.3, 0.5, -1.0, 1.2, 0.3, -0.4, 2.0]
    robot = load_robot(SPIDERBOT)
    sim = mujoco.MjData(model)
    sim.qpos[:] = pose_to_qpos(robot, pose)
    mujoco.mj_inverse(model, sim)
    ik = taut_cli("ik", str(SPIDERBOT), "--pose", ",".join(map(str, pose)), "--json").json()
    np.testing.assert_allclose(sim.ten_length, ik["lengths"], atol=1e-12)
    arm = [model.jnt_dofadr[model.joint(f"joint{k}").id] for k in range(1, 7)]
    zeta = joint_forces(robot, pose, np.zeros(8))
    assert np.abs(zeta).max() > 1
    np.testing.assert_allclose(sim.qfrc_inverse[arm], zeta, rtol=0, atol=1e-12 * np.abs(zeta).max())


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["convert", "cogiro", "cogiro.mjcf.xml"], "no platform.mass"),
        (["ik", str(FIXTURES / "multilink_bodies.xml")], "multi-link"),
        (["ik", str(COGIRO), "--cable-set", "nope"], "no cable set 'nope'"),
        (["ik", "planar-4cable", "--cable-set", "x"], "--cable-set"),
        (["convert", "cogiro", "robot.txt"], "supported: *_bodies.xml"),
        (["convert", "robocrane", "robocrane_bodies.xml"], "a CASPR model cannot hold"),
    ],
)
def test_bad_input_exits_2_with_one_line(taut_cli: Callable[..., Any], argv: list[str], message: str) -> None:
    run = taut_cli(*argv)
    assert run.code == 2
    assert run.err.count("\n") == 1 and run.err.startswith("taut: error: ")
    assert message in run.err
    assert run.out == ""


def test_missing_cables_file(taut_cli: Callable[..., Any], tmp_path: Path) -> None:
    bodies = tmp_path / "alone_bodies.xml"
    bodies.write_text(COGIRO.read_text())
    run = taut_cli("workspace", str(bodies), "--condition", "wrench-closure", "--grid", "3")
    assert run.code == 2 and "alone_cables.xml is missing" in run.err and run.err.count("\n") == 1


def test_a_jointed_body_without_a_mass_is_refused_by_name(taut_cli: Callable[..., Any], tmp_path: Path) -> None:
    """adjustable-8cable with its platform's mass and inertia but none for its upper body: one
    line naming the body, exit 2, no file written."""
    taut_cli("convert", "adjustable-8cable", str(tmp_path / "r.yaml"), "--json")
    data = yaml.safe_load((tmp_path / "r.yaml").read_text())
    for field in ("mass", "com", "inertia"):
        data["platform"]["bodies"][0].pop(field)
    (tmp_path / "r.yaml").write_text(yaml.safe_dump(data))
    out = tmp_path / "r.mjcf.xml"
    run = taut_cli("convert", str(tmp_path / "r.yaml"), str(out))
    assert run.code == 2 and run.err.count("\n") == 1 and run.out == ""
    assert "platform.bodies[1] (upper) has no mass" in run.err
    assert not out.exists()
