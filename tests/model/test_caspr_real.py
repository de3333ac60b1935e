"""CASPR's own models (``tests/model/fixtures/caspr/real``, copied unchanged from CASPR's
repository) through taut's reader: every stored (model, cable set) either loads, with the
platform, cables and joints recorded here, or is refused with the recorded one-line reason.
``docs/caspr-models.md`` is this catalogue as a table, checked against it below."""

from __future__ import annotations

import re
import subprocess
import sys
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest
from axis_rotations import rx, ry, rz

from taut.errors import TautError, UnsupportedRobotError
from taut.kinematics import inverse_kinematics, jointed_structure_matrix
from taut.model._caspr import cables_path, read_caspr

REAL = Path(__file__).parent / "fixtures" / "caspr" / "real"
DOC = Path(__file__).parents[2] / "docs" / "caspr-models.md"

# What stands in the way of a refused model: features taut's reader lacks (MISSING), a model
# taut has nothing to analyse in, and a number beyond the range taut takes.
GROUND = "chain jointed to the ground"
LINK_CABLE = "cable between two links"
SCREW_PULLEY = "screw_base_rotating_pulley"
VSD_CABLE = "variable-stiffness cable"
PASSIVE_SPRING = "passive spring"
FORCE_ERROR = "force_error property"
MOBILE_BASE = "actuated platform joint"
MISSING = (GROUND, LINK_CABLE, SCREW_PULLEY, VSD_CABLE, PASSIVE_SPRING, FORCE_ERROR, MOBILE_BASE)
NO_CABLES = "no cables"

#: CASPR's family of the models stored beside this catalogue's subdirectories, before them
ROOT_FAMILY = {"CoGiRo_bodies.xml": "SCDM", "KNTU_planar_bodies.xml": "SCDM", "SpiderBot_UR3_bodies.xml": "HCDM"}


@dataclass(frozen=True)
class Loads:
    kind: str
    cables: int
    joints: int


@dataclass(frozen=True)
class Refused:
    error: type[TautError]
    #: the message after the file's name, as ``taut`` prints it
    reason: str
    #: every construct that keeps the model out, the one the message names first
    blockers: tuple[str, ...]


def chain(links: str, joint: str) -> str:
    return (
        f"a chain of {len(links.split(', '))} links ({links}) jointed to the ground by {joint} is a multi-link "
        "robot; taut models a platform with a free joint"
    )


def link_cable(name: str, route: str) -> str:
    return f"cable {name!r} runs through links {route}; a taut cable runs from the base (link 0) to a body"


def cable_type(tag: str) -> str:
    return f"<{tag}> cables are not modelled by taut (only cable_ideal, cable_linear_spring)"


VSD = cable_type("cable_vsd_polynomial")
SPHERICAL = "link 1 has a S_EULER_XYZ joint; taut reads SPATIAL_EULER_XYZ"


def screw(name: str) -> str:
    return f"<screw_base_rotating_pulley> is not modelled by taut (cable {name!r}; only a first <base_rotating_pulley>)"


#: (bodies file under REAL, cable set) -> what the reader does with it
CATALOGUE: dict[tuple[str, str], Loads | Refused] = {
    ("CoGiRo_bodies.xml", "original"): Loads("rigid", 8, 0),
    ("KNTU_planar_bodies.xml", "original"): Loads("rigid", 4, 0),
    ("SpiderBot_UR3_bodies.xml", "CUcablerobot"): Loads("rigid", 8, 6),
    ("SpiderBot_UR3_bodies.xml", "set_1"): Loads("rigid", 8, 6),
    ("SpiderBot_UR3_bodies.xml", "set_IPAnema_inspired"): Loads("rigid", 8, 6),
    ("HCDM/SpiderBot_X52/SpiderBot_X52_bodies.xml", "original"): Loads("rigid", 8, 4),
    ("SCDM/2_DoF_VSD/2_DoF_VSD_bodies.xml", "basic_linear"): Loads("point-mass", 4, 0),
    ("SCDM/2_DoF_VSD/2_DoF_VSD_bodies.xml", "stiff"): Loads("point-mass", 4, 0),
    ("SCDM/ACROBOT/ACROBOT_bodies.xml", "original"): Loads("rigid", 8, 0),
    ("SCDM/CAROCA/CAROCA_bodies.xml", "original"): Loads("rigid", 8, 0),
    ("SCDM/CAROCA/CAROCA_bodies.xml", "with_rotating_pulleys"): Loads("rigid", 8, 0),
    ("SCDM/CAROCA/CAROCA_bodies.xml", "gazebo_sim"): Loads("rigid", 8, 0),
    ("SCDM/FAST/FAST_bodies.xml", "original"): Loads("rigid", 6, 0),
    ("SCDM/IPAnema_1/IPAnema_1_bodies.xml", "original"): Loads("rigid", 8, 0),
    ("SCDM/IPAnema_1/IPAnema_1_bodies.xml", "IROS_CASPR_2016"): Loads("rigid", 8, 0),
    ("SCDM/IPAnema_2/IPAnema_2_bodies.xml", "original"): Loads("rigid", 8, 0),
    ("SCDM/IPAnema_2/IPAnema_2_bodies.xml", "IROS_CASPR_2016"): Loads("rigid", 8, 0),
    ("SCDM/MACARM/MACARM_bodies.xml", "original"): Loads("rigid", 8, 0),
    ("SCDM/NIST_RoboCrane/NIST_RoboCrane_bodies.xml", "original"): Loads("rigid", 6, 0),
    ("SCDM/SEGESTA/SEGESTA_bodies.xml", "original"): Loads("rigid", 10, 0),
    ("SCDM/The_Cable_Robot_Simulator/The_Cable_Robot_Simulator_bodies.xml", "original"): Loads("rigid", 8, 0),
    ("SCDM/The_Cable_Robot_Simulator/The_Cable_Robot_Simulator_bodies.xml", "normal"): Loads("rigid", 8, 0),
    ("examples/Example_planar_XY/Example_planar_XY_bodies.xml", "basic"): Loads("rigid", 4, 0),
    ("examples/Example_planar_XY/Example_planar_XY_bodies.xml", "basic_notouch"): Loads("rigid", 4, 0),
    ("examples/Example_planar_XY/Example_planar_XY_bodies.xml", "basic_cross"): Loads("rigid", 4, 0),
    ("examples/Example_spatial/Example_spatial_bodies.xml", "basic_7_cables"): Loads("rigid", 7, 0),
    ("examples/Example_spatial/Example_spatial_bodies.xml", "basic_8_cables"): Loads("rigid", 8, 0),
    ("examples/Example_spatial/Example_spatial_bodies.xml", "cross_8_cables"): Loads("rigid", 8, 0),
    ("SCDM/2_DoF_VSD/2_DoF_VSD_bodies.xml", "basic"): Refused(
        UnsupportedRobotError, cable_type("cable_vsd_torsion_spring"), (VSD_CABLE,)
    ),
    ("SCDM/Passive_springs_planar/Passive_springs_planar_bodies.xml", "one_spring"): Refused(
        UnsupportedRobotError, cable_type("cable_passive_linear_spring"), (PASSIVE_SPRING,)
    ),
    ("SCDM/Passive_springs_planar/Passive_springs_planar_bodies.xml", "four_springs"): Refused(
        UnsupportedRobotError, cable_type("cable_passive_linear_spring"), (PASSIVE_SPRING,)
    ),
    ("SCDM/Myorob_shoulder/Myorob_shoulder_bodies.xml", "original"): Refused(
        UnsupportedRobotError,
        "<properties> <force_error>: taut models no error of the cable force",
        (FORCE_ERROR, GROUND),
    ),
    ("examples/Example_spatial/Example_spatial_bodies.xml", "alternative_7_cables"): Loads("rigid", 7, 0),
    ("examples/Example_spherical/Example_spherical_bodies.xml", "basic_4_cables"): Refused(
        UnsupportedRobotError, SPHERICAL, (GROUND,)
    ),
    ("examples/Example_spherical/Example_spherical_bodies.xml", "VSD_6_cables"): Refused(
        UnsupportedRobotError, cable_type("cable_vsd_flexure_linear"), (VSD_CABLE, GROUND)
    ),
    ("examples/Example_spherical/Example_spherical_bodies.xml", "VSD_6_cables_2"): Refused(
        UnsupportedRobotError, cable_type("cable_vsd_flexure_linear"), (VSD_CABLE, GROUND)
    ),
    ("HCDM/SpiderBot_UR3_Test/SpiderBot_UR3_Test_bodies.xml", "CUcablerobot"): Refused(
        UnsupportedRobotError, screw("X"), (SCREW_PULLEY,)
    ),
    ("HCDM/SpiderBot_UR3_Test/SpiderBot_UR3_Test_bodies.xml", "singleCableTest"): Refused(
        UnsupportedRobotError, screw("cable 1"), (SCREW_PULLEY,)
    ),
    ("HCDM/FASTKIT_Planar/FASTKIT_Planar_bodies.xml", "original"): Refused(
        UnsupportedRobotError, link_cable("cable1", "1 -> 3"), (LINK_CABLE, MOBILE_BASE)
    ),
    ("HCDM/PlanarSnakeArm/PlanarSnakeArm_bodies.xml", "Empty"): Refused(
        UnsupportedRobotError,
        "<cable_set id='Empty'>: the cable set holds no cables; taut models robots moved by cables",
        (NO_CABLES,),
    ),
    ("HCDM/PlanarSnakeArm/PlanarSnakeArm_bodies.xml", "PlaceHOlder"): Refused(
        UnsupportedRobotError, chain(", ".join(f"{k}:R_X" for k in range(1, 8)), "R_X"), (GROUND,)
    ),
    ("MCDM/8S_neck/8S_neck_bodies.xml", "opensim_vasavada"): Refused(
        UnsupportedRobotError, link_cable("deepmult-C4/5-C2 (right)", "3 -> 6"), (LINK_CABLE, GROUND)
    ),
    ("MCDM/4U_modular_units_arm/4U_modular_units_arm_bodies.xml", "basic"): Refused(
        UnsupportedRobotError, link_cable("M2_1", "1 -> 2"), (LINK_CABLE, GROUND)
    ),
    ("MCDM/4U_modular_units_arm/4U_modular_units_arm_bodies.xml", "co_shared_cable"): Refused(
        UnsupportedRobotError, link_cable("M2_1", "1 -> 2"), (LINK_CABLE, GROUND)
    ),
    ("MCDM/4U_modular_units_arm/4U_modular_units_arm_bodies.xml", "alternatively_co_shared_cables"): Refused(
        UnsupportedRobotError, link_cable("M2_2", "1 -> 2 -> 2 -> 3"), (LINK_CABLE, GROUND)
    ),
    ("MCDM/4U_modular_units_arm/4U_modular_units_arm_bodies.xml", "cable_set_4"): Refused(
        UnsupportedRobotError, chain("1:U_YZ, 2:U_YZ, 3:U_YZ, 4:U_YZ", "U_YZ"), (GROUND,)
    ),
    ("MCDM/4U_modular_units_arm/4U_modular_units_arm_bodies.xml", "cable_set_5"): Refused(
        UnsupportedRobotError, chain("1:U_YZ, 2:U_YZ, 3:U_YZ, 4:U_YZ", "U_YZ"), (GROUND,)
    ),
    ("MCDM/RoboyUpperBody/RoboyUpperBody_bodies.xml", "DEFAULT"): Refused(
        UnsupportedRobotError, link_cable("shoulder_left_motor0", "9 -> 16"), (LINK_CABLE, GROUND)
    ),
    ("MCDM/SJTUSnake/SJTUSnake_bodies.xml", "link to link cable connection"): Refused(
        UnsupportedRobotError, link_cable("cable 1 (link 2)", "2 -> 1"), (LINK_CABLE, GROUND)
    ),
    ("MCDM/SJTUSnake/SJTUSnake_bodies.xml", "base to link cable connection"): Refused(
        UnsupportedRobotError, chain(", ".join(f"{k}:U_XZ" for k in range(1, 13)), "U_XZ"), (GROUND,)
    ),
    ("MCDM/BMArm/BMArm_bodies.xml", "WORKING"): Refused(
        UnsupportedRobotError, chain("1:S_EULER_XYZ, 2:R_X", "S_EULER_XYZ"), (GROUND,)
    ),
    ("MCDM/BMArm/BMArm_bodies.xml", "vsd_test"): Refused(UnsupportedRobotError, VSD, (VSD_CABLE, GROUND)),
    ("MCDM/BMArm/BMArm_bodies.xml", "multi_link"): Refused(UnsupportedRobotError, VSD, (VSD_CABLE, GROUND)),
    ("MCDM/BioBiped/BioBiped_bodies.xml", "original"): Refused(
        UnsupportedRobotError, link_cable("1 (right)", "1 -> 2"), (LINK_CABLE,)
    ),
    ("MCDM/BioBiped_one_leg/BioBiped_one_leg_bodies.xml", "original"): Refused(
        UnsupportedRobotError, link_cable("1", "1 -> 3"), (LINK_CABLE,)
    ),
    ("MCDM/C-Leg/C-Leg_bodies.xml", "basic_4_cables"): Refused(
        UnsupportedRobotError, chain("1:R_Y, 2:R_Y, 3:R_Y", "R_Y"), (GROUND,)
    ),
    ("MCDM/CALEX/CALEX_bodies.xml", "original"): Refused(
        UnsupportedRobotError, chain("1:U_XY, 2:R_Y", "U_XY"), (GROUND,)
    ),
    ("MCDM/CAREX/CAREX_bodies.xml", "basic_6_cables"): Refused(
        UnsupportedRobotError, chain("1:S_EULER_XYZ, 2:R_Y", "S_EULER_XYZ"), (GROUND,)
    ),
    ("MCDM/RoboyLeftArm/RoboyLeftArm_bodies.xml", "DEFAULT"): Refused(
        UnsupportedRobotError, link_cable("motor10", "3 -> 4"), (LINK_CABLE, GROUND)
    ),
    ("examples/Example_2R_planar_XZ/Example_2R_planar_XZ_bodies.xml", "basic"): Refused(
        UnsupportedRobotError, chain("1:R_Y, 2:R_Y", "R_Y"), (GROUND,)
    ),
    ("examples/Example_2R_planar_XZ/Example_2R_planar_XZ_bodies.xml", "basic_multi_segment"): Refused(
        UnsupportedRobotError, chain("1:R_Y, 2:R_Y", "R_Y"), (GROUND,)
    ),
    ("examples/Example_2S/Example_2S_bodies.xml", "original"): Refused(
        UnsupportedRobotError, chain("1:S_EULER_XYZ, 2:S_EULER_XYZ", "S_EULER_XYZ"), (GROUND,)
    ),
}


def cable_sets(bodies: Path) -> list[str]:
    return [str(s.get("id")) for s in ET.parse(cables_path(bodies)).getroot().iter("cable_set")]


def initial_pose(bodies: Path) -> np.ndarray:
    """CASPR's ``q_initial``, the links' in order: taut's pose of the models that load (none of
    them has a coordinate taut negates or reorders)."""
    return np.array(
        [float(x) for j in ET.parse(bodies).getroot().iter("joint") for x in j.get("q_initial", "").split()]
    )


def test_the_catalogue_holds_every_stored_model_and_cable_set() -> None:
    stored = {(str(b.relative_to(REAL)), s) for b in REAL.rglob("*_bodies.xml") for s in cable_sets(b)}
    assert stored == set(CATALOGUE)


@pytest.mark.parametrize(("bodies", "cable_set"), list(CATALOGUE), ids=[f"{Path(b).stem}-{s}" for b, s in CATALOGUE])
def test_each_model_loads_or_is_refused_as_recorded(bodies: str, cable_set: str) -> None:
    path = REAL / bodies
    outcome = CATALOGUE[bodies, cable_set]
    if isinstance(outcome, Refused):
        with pytest.raises(TautError) as info:
            read_caspr(path, cable_set=cable_set)
        assert type(info.value) is outcome.error
        message = str(info.value)
        assert "\n" not in message
        assert outcome.reason in message
        return
    robot = read_caspr(path, cable_set=cable_set)
    assert (robot.platform.kind, robot.n_cables, robot.n_joints) == (outcome.kind, outcome.cables, outcome.joints)
    q = initial_pose(path)
    assert q.shape == (robot.pose_size,)
    assert np.all(np.isfinite(inverse_kinematics(robot, q).lengths))
    size = robot.wrench_dim + robot.n_joints, robot.n_cables + robot.n_joints
    assert jointed_structure_matrix(robot, q).shape == size


def test_spiderbot_x52_lengths_from_the_raw_attachments() -> None:
    """SpiderBot X52's cables all end on its base link, a ``SPATIAL_EULER_XYZ`` joint at the
    origin with ``R = Rx(α) Ry(β) Rz(γ)`` and joint-referenced attachments: each length is
    ``|a − (p + R r)|``, whatever the arm's four joints do."""
    bodies = REAL / "HCDM" / "SpiderBot_X52" / "SpiderBot_X52_bodies.xml"
    q = np.array([2.1, 1.2, 0.9, 0.1, -0.2, 0.3, 0.4, -0.3, 0.2, 0.1])
    rotation = rx(q[3]) @ ry(q[4]) @ rz(q[5])
    expected = []
    for cable in ET.parse(cables_path(bodies)).getroot().iter("cable_ideal"):
        assert cable.get("attachment_reference") == "joint"
        (base, on_link), (anchor, _) = [
            (np.array([float(x) for x in (a.findtext("location") or "").split()]), a.findtext("link"))
            for a in cable.iter("attachment")
        ]
        assert on_link == "0"
        expected.append(np.linalg.norm(base - (q[:3] + rotation @ anchor)))
    lengths = inverse_kinematics(read_caspr(bodies), q).lengths
    np.testing.assert_allclose(lengths, expected, rtol=1e-12)


def test_example_planar_xy_lengths_from_the_raw_attachments() -> None:
    """CASPR's planar example turns its ``PLANAR_XY`` link about +z and takes the anchors from
    its centre of mass, which is the joint: each length is ``|a − (p + R(θ) r)|`` in the plane."""
    bodies = REAL / "examples" / "Example_planar_XY" / "Example_planar_XY_bodies.xml"
    q = np.array([0.4, 0.55, 0.3])
    rotation = rz(q[2])[:2, :2]
    cable_set = ET.parse(cables_path(bodies)).getroot().find("cable_set[@id='basic_notouch']")
    assert cable_set is not None
    expected = []
    for cable in cable_set:
        base, anchor = [
            np.array([float(x) for x in (a.findtext("location") or "").split()])[:2] for a in cable.iter("attachment")
        ]
        expected.append(np.linalg.norm(base - (q[:2] + rotation @ anchor)))
    lengths = inverse_kinematics(read_caspr(bodies, cable_set="basic_notouch"), q).lengths
    assert len(expected) == 4
    np.testing.assert_allclose(lengths, expected, rtol=1e-12)


def test_the_doc_table_is_the_catalogue() -> None:
    rows = re.findall(r"^\| (\w+) \| `([^`]+)` \| `([^`]+)` \| (loads|refused) \|", DOC.read_text(), re.M)
    table = {(family, model, cable_set): result for family, model, cable_set, result in rows}
    expected = {}
    for (bodies, cable_set), outcome in CATALOGUE.items():
        family = Path(bodies).parts[0] if "/" in bodies else ROOT_FAMILY[bodies]
        model = Path(bodies).name.removesuffix("_bodies.xml")
        expected[family, model, cable_set] = "loads" if isinstance(outcome, Loads) else "refused"
    assert table == expected
    refused = [o for o in CATALOGUE.values() if isinstance(o, Refused)]
    models = {bodies for bodies, _ in CATALOGUE}
    summary = f"{len(CATALOGUE)} (model, cable set) pairs of {len(models)} models, {len(table) - len(refused)} load and {len(refused)} are refused"
    assert summary in DOC.read_text()
    for blocker in {*MISSING, NO_CABLES}:
        first = sum(o.blockers[0] == blocker for o in refused)
        assert (f"| {blocker} | {first} |" in DOC.read_text()) == bool(first), blocker


def test_every_blocker_is_named() -> None:
    for outcome in CATALOGUE.values():
        if isinstance(outcome, Refused):
            assert outcome.blockers and set(outcome.blockers) <= {*MISSING, NO_CABLES}


@pytest.mark.parametrize(
    ("bodies", "code"),
    [("HCDM/SpiderBot_X52/SpiderBot_X52_bodies.xml", 0), ("MCDM/C-Leg/C-Leg_bodies.xml", 2)],
)
def test_convert_on_the_command_line(tmp_path: Path, bodies: str, code: int) -> None:
    run = subprocess.run(
        [sys.executable, "-m", "taut", "convert", str(REAL / bodies), "out.yaml"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=600,
    )
    assert run.returncode == code, run.stderr
    if code == 0:
        assert (tmp_path / "out.yaml").is_file()
        return
    outcome = CATALOGUE[bodies, "basic_4_cables"]
    assert isinstance(outcome, Refused)
    assert run.stderr.startswith("taut: error: ") and run.stderr.count("\n") == 1
    assert outcome.reason in run.stderr
    assert not (tmp_path / "out.yaml").exists()
