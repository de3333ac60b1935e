"""CASPR models in and out: every construct of the fixtures against an independent computation
from the files' raw numbers (parsed here with ElementTree, rotations built here from elementary
rotations, CASPR's semantics as its joint and attachment classes define them), the refusals,
and the round trip of every built-in example a CASPR model can hold."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
from axis_rotations import rx, ry, rz
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from taut.errors import RobotFileError, UnsupportedRobotError
from taut.kinematics import inverse_kinematics, jointed_structure_matrix
from taut.model import example, example_names, load_robot
from taut.model._caspr import read_caspr, write_caspr
from taut.statics import external_wrench

FIXTURES = Path(__file__).parent / "fixtures" / "caspr"
REAL = FIXTURES / "real"


def vec(el: ET.Element, path: str) -> np.ndarray:
    node = el.find(path)
    assert node is not None and node.text is not None
    return np.array([float(x) for x in node.text.split()])


def raw_model(bodies: Path, cable_set: str | None = None) -> tuple[list[dict], list[dict]]:
    """Links and cables as the files give them."""
    links = []
    for el in ET.parse(bodies).getroot().iter("link_rigid"):
        joint = el.find("joint")
        assert joint is not None
        links.append(
            {
                "joint": joint.get("type"),
                "location": vec(el, "parent/location"),
                "com": vec(el, "physical/com_location"),
                "mass": float(vec(el, "physical/mass")[0]),
                "inertia": {t.tag: float(t.text or "") for t in el.find("physical/inertia") or []},
                "inertia_ref": el.find("physical/inertia").get("ref"),  # type: ignore[union-attr]
            }
        )
    croot = ET.parse(str(bodies).replace("_bodies.xml", "_cables.xml")).getroot()
    wanted = cable_set or croot.get("default_cable_set")
    cables = []
    for cset in croot.iter("cable_set"):
        if cset.get("id") != wanted:
            continue
        for c in cset:
            atts = {int(a.findtext("link") or ""): vec(a, "location") for a in c.iter("attachment")}
            link = max(atts)
            r = atts[link] + (links[link - 1]["com"] if c.get("attachment_reference") == "com" else 0)
            k = c.find("properties/K")
            cables.append(
                {
                    "base": atts[0],
                    "r": r,
                    "force": (
                        float(c.findtext("properties/force_min") or ""),
                        float(c.findtext("properties/force_max") or ""),
                    ),
                    "K": None if k is None else float(k.text or ""),
                }
            )
    return links, cables


def caspr_frame(links: list[dict], q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """World position of the cable-carrying link's joint origin and its rotation, CASPR's
    joint definitions (SpatialEulerXYZ: Rx Ry Rz; SphericalFixedXYZ: Rz Ry Rx; PlanarXZ: Ry)."""
    origin = sum(link["location"] for link in links)
    kinds = [link["joint"] for link in links]
    if kinds == ["SPATIAL_EULER_XYZ"]:
        return origin + q[:3], rx(q[3]) @ ry(q[4]) @ rz(q[5])
    if kinds == ["T_XYZ", "S_EULER_XYZ"]:
        return origin + q[:3], rx(q[3]) @ ry(q[4]) @ rz(q[5])
    if kinds == ["T_XYZ", "S_FIXED_XYZ"]:
        return origin + q[:3], rz(q[5]) @ ry(q[4]) @ rx(q[3])
    if kinds == ["T_XYZ"]:
        return origin + q[:3], np.eye(3)
    plane = {"PLANAR_XY": (0, 1), "PLANAR_XZ": (0, 2), "PLANAR_YZ": (1, 2), "P_XY": (0, 1), "P_XZ": (0, 2)}[kinds[0]]
    t = np.zeros(3)
    t[list(plane)] = q[:2]
    R = {"PLANAR_XY": rz, "PLANAR_XZ": ry, "PLANAR_YZ": rx}.get(kinds[0], lambda _: np.eye(3))(
        q[2] if len(q) > 2 else 0
    )
    return origin + t, R


#: CASPR's q to taut's pose, and taut's plane axes (world vectors) for planar models.
def to_taut(kind: str, q: np.ndarray) -> np.ndarray:
    if kind == "PLANAR_XZ":
        return np.array([q[0], q[1], -q[2]])
    return q


PLANE_AXES = {
    "PLANAR_XY": (0, 1),
    "PLANAR_XZ": (0, 2),
    "PLANAR_YZ": (1, 2),
    "P_XY": (0, 1),
    "P_XZ": (0, 2),
}

MODELS = {
    FIXTURES / "spatial_euler_bodies.xml": 6,
    FIXTURES / "fixed_chain_bodies.xml": 6,
    FIXTURES / "euler_chain_bodies.xml": 6,
    FIXTURES / "point_spatial_bodies.xml": 3,
    FIXTURES / "planar_xz_bodies.xml": 3,
    FIXTURES / "planar_yz_bodies.xml": 3,
    FIXTURES / "planar_xy_bodies.xml": 3,
    FIXTURES / "point_xy_bodies.xml": 2,
    FIXTURES / "point_xz_bodies.xml": 2,
    REAL / "CoGiRo_bodies.xml": 6,
    REAL / "KNTU_planar_bodies.xml": 3,
}


def expected(bodies: Path, q: np.ndarray, cable_set: str | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Lengths and structure matrix at CASPR pose ``q``, from the raw numbers, in taut's frame."""
    links, cables = raw_model(bodies, cable_set)
    p, R = caspr_frame(links, q)
    kind = links[-1]["joint"] if len(links) == 1 else "spatial"
    rows, lengths = [], []
    for c in cables:
        b = p + R @ c["r"]
        d = c["base"] - b
        length = float(np.linalg.norm(d))
        u = d / length
        m = np.cross(R @ c["r"], u)
        lengths.append(length)
        if kind in PLANE_AXES:
            i, j = PLANE_AXES[kind]
            normal = np.cross(np.eye(3)[i], np.eye(3)[j])
            rows.append([u[i], u[j]] + ([] if kind.startswith("P_") else [float(m @ normal)]))
        elif kind == "T_XYZ":
            rows.append(list(u))
        else:
            rows.append(list(u) + list(m))
    return np.array(lengths), np.array(rows).T


@pytest.mark.parametrize("bodies", list(MODELS), ids=[p.stem for p in MODELS])
@settings(max_examples=25, deadline=None)
@given(data=st.data())
def test_lengths_and_structure_matrix_match_caspr_semantics(bodies: Path, data: st.DataObject) -> None:
    size = MODELS[bodies]
    q = np.array(data.draw(st.lists(st.floats(-0.3, 0.3), min_size=size, max_size=size)), dtype=float)
    if size == 6:
        q[2] += 1.0
    links, _ = raw_model(bodies)
    robot = load_robot(bodies)
    pose = to_taut(links[-1]["joint"], q)
    ik = inverse_kinematics(robot, pose)
    lengths, W = expected(bodies, q)
    np.testing.assert_allclose(ik.lengths, lengths, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(ik.structure_matrix, W, rtol=1e-10, atol=1e-12)


@pytest.mark.parametrize("bodies", list(MODELS), ids=[p.stem for p in MODELS])
def test_mass_centre_of_mass_inertia_and_bounds(bodies: Path) -> None:
    links, cables = raw_model(bodies)
    robot = load_robot(bodies)
    body = links[-1]
    kind = body["joint"]
    m = body["mass"]
    weight = np.array([0.0, 0.0, -9.81 * m])  # CASPR: g = 9.81 m/s² along -z
    if kind in PLANE_AXES:
        weight = weight[list(PLANE_AXES[kind])]
    np.testing.assert_allclose(robot.weight, weight, rtol=1e-15)
    np.testing.assert_array_equal(robot.tension_bounds[0], [c["force"][0] for c in cables])
    np.testing.assert_array_equal(robot.tension_bounds[1], [c["force"][1] for c in cables])
    assert [c.stiffness for c in robot.cables] == [c["K"] for c in cables]
    if robot.is_point_mass:
        assert robot.platform.inertia is None
        return
    c = body["com"]
    I = body["inertia"]
    tensor = np.array([[I["Ixx"], I["Ixy"], I["Ixz"]], [I["Ixy"], I["Iyy"], I["Iyz"]], [I["Ixz"], I["Iyz"], I["Izz"]]])
    if body["inertia_ref"] == "joint":  # parallel axes: about the joint -> about the COM
        tensor = tensor - m * (np.dot(c, c) * np.eye(3) - np.outer(c, c))
    if kind in PLANE_AXES:
        i, j = PLANE_AXES[kind]
        n = 3 - i - j
        np.testing.assert_allclose(robot.platform.wrench_point, c[[i, j]])
        np.testing.assert_allclose(robot.inertia, [[tensor[n, n]]])
    else:
        np.testing.assert_allclose(robot.platform.wrench_point, c)
        np.testing.assert_allclose(robot.inertia, tensor, rtol=1e-14, atol=1e-14)


def test_inertia_about_the_joint_is_shifted_to_the_centre_of_mass() -> None:
    robot = load_robot(FIXTURES / "spatial_euler_bodies.xml")
    # Ixx about the COM = 0.9 - 12.5 (cy² + cz²) with c = (0.02, -0.03, 0.05); Ixy = 0.01 + 12.5 cx cy
    assert robot.inertia is not None
    assert robot.inertia[0, 0] == pytest.approx(0.9 - 12.5 * (0.03**2 + 0.05**2), rel=1e-14)
    assert robot.inertia[0, 1] == pytest.approx(0.01 + 12.5 * 0.02 * -0.03, rel=1e-13)


def test_orientation_conventions() -> None:
    assert load_robot(FIXTURES / "spatial_euler_bodies.xml").orientation == "xyz-moving"
    assert load_robot(FIXTURES / "euler_chain_bodies.xml").orientation == "xyz-moving"
    assert load_robot(FIXTURES / "fixed_chain_bodies.xml").orientation == "xyz-fixed"
    xz = load_robot(FIXTURES / "planar_xz_bodies.xml")
    assert "CASPR (x, z, -theta)" in (xz.description or "")


@settings(max_examples=25, deadline=None)
@given(q=st.lists(st.floats(-0.3, 0.3), min_size=6, max_size=6))
def test_cable_sets_and_linear_springs(q: list[float]) -> None:
    bodies = FIXTURES / "spatial_euler_bodies.xml"
    robot = load_robot(bodies, cable_set="springs")
    qq = np.array(q) + [0, 0, 1, 0, 0, 0]
    lengths, W = expected(bodies, qq, "springs")
    ik = inverse_kinematics(robot, qq)
    np.testing.assert_allclose(ik.lengths, lengths, rtol=1e-12)
    np.testing.assert_allclose(ik.structure_matrix, W, rtol=1e-10, atol=1e-12)
    # <K> is the axial rigidity EA [N]; CASPR's spring rate is K / length
    assert [c.stiffness for c in robot.cables] == [2.5e4 + 100 * i for i in range(8)]
    assert robot.tension_bounds[1].tolist() == [math.inf] * 8


def caspr_pulley_lengths(cables: Path, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Cable lengths ``(n,)`` of the ``base_rotating_pulley`` cables at the pose ``q`` of a
    ``SPATIAL_EULER_XYZ`` link at the origin, as CASPR computes them
    (``BaseRotatingPulleyAttachment.ComputePulleyLeavingLocation``, ``src/Model/Cables/
    CableAttachments/BaseRotatingPulleyAttachment/``; the cable length is the segment from the
    leaving point plus the first attachment's ``length_offset``, ``CableSegmentModel``), and
    whether each pose is in the domain of CASPR's formula.

    With the entry point ``F``, the entry direction ``v``, the anchor ``B``: the plane normal
    ``n = v × (B − F)``, the centre ``C = F + R (n × v)/‖n × v‖``, ``ρ = R/‖B − C‖``, the
    leaving point ``A = C + ρ² (B − C) − ρ √(1 − ρ²) n̂ × (B − C)`` and the arc
    ``R acos(((F − C)/‖F − C‖)·((A − C)/‖A − C‖))``: a single ``acos``, right while the
    cable wraps at most half a turn, i.e. while ``A`` is not behind the centre along ``v``."""
    R = rx(q[3]) @ ry(q[4]) @ rz(q[5])
    lengths, valid = [], []
    for el in ET.parse(cables).getroot().iter("cable_ideal"):
        F = vec(el, "attachments/base_rotating_pulley/fixed_location")
        radius = float(vec(el, "attachments/base_rotating_pulley/pulley_radius")[0])
        v = vec(el, "attachments/base_rotating_pulley/cable_entry_vector")
        B = q[:3] + R @ vec(el, "attachments/attachment/location")
        n = np.cross(v, B - F)
        n_hat = n / np.linalg.norm(n)
        towards = np.cross(n, v)
        C = F + radius * towards / np.linalg.norm(towards)
        rho = radius / np.linalg.norm(B - C)
        A = C + rho**2 * (B - C) - rho * math.sqrt(1 - rho**2) * np.cross(n_hat, B - C)
        n1, n2 = (F - C) / np.linalg.norm(F - C), (A - C) / np.linalg.norm(A - C)
        lengths.append(np.linalg.norm(B - A) + radius * math.acos(float(n1 @ n2)))
        valid.append(float((A - C) @ v) > 1e-9 * radius and np.linalg.norm(n) > 1e-6)
    return np.array(lengths), np.array(valid)


@settings(max_examples=60, deadline=None)
@given(
    st.tuples(st.floats(-0.8, 0.8), st.floats(-0.5, 0.5), st.floats(0.4, 1.6)),
    st.tuples(*[st.floats(-0.4, 0.4)] * 3),
)
def test_base_rotating_pulleys_are_casprs_lengths(position: tuple, angles: tuple) -> None:
    """``base_rotating_pulley`` cables read as swivels have CASPR's lengths (to 1e-9) at
    random poses where CASPR's single-``acos`` arc is valid (wraps up to half a turn)."""
    q = np.array([*position, *angles])
    expected, valid = caspr_pulley_lengths(FIXTURES / "pulley_cables.xml", q)
    assume(bool(valid.all()))
    robot = load_robot(FIXTURES / "pulley_bodies.xml")
    assert robot.swivel_cables == tuple(range(8))
    np.testing.assert_allclose(inverse_kinematics(robot, q).lengths, expected, rtol=0, atol=1e-9)


def test_base_rotating_pulleys_round_trip(tmp_path: Path) -> None:
    robot = load_robot(FIXTURES / "pulley_bodies.xml")
    write_caspr(robot, tmp_path / "back_bodies.xml")
    assert (tmp_path / "back_cables.xml").read_text().count("<base_rotating_pulley>") == 8
    back = read_caspr(tmp_path / "back_bodies.xml")
    assert [c.swivel for c in back.cables] == [c.swivel for c in robot.cables]
    assert np.array_equal(back.exits, robot.exits) and np.array_equal(back.anchors, robot.anchors)
    q = np.array([[0.1, -0.2, 0.9, 0.1, -0.2, 0.3], [0, 0, 1, 0, 0, 0]])
    np.testing.assert_allclose(
        inverse_kinematics(back, q).lengths, inverse_kinematics(robot, q).lengths, rtol=0, atol=0
    )


def test_refused_constructs(tmp_path: Path) -> None:
    screw = copy_model(
        tmp_path, "pulley", edit_cables=lambda s: s.replace("base_rotating_pulley", "screw_base_rotating_pulley")
    )
    with pytest.raises(UnsupportedRobotError, match=r"<screw_base_rotating_pulley> is not modelled by taut"):
        load_robot(screw)
    planar = copy_model(
        tmp_path,
        "planar_xz",
        edit_cables=lambda s: s.replace(
            "<attachment><link>0</link><location>-1 0.3 1</location></attachment>",
            "<base_rotating_pulley><fixed_location>-1 0.3 1</fixed_location><pulley_radius>0.05</pulley_radius>"
            "<cable_entry_vector>0 1 0</cable_entry_vector></base_rotating_pulley>",
        ),
    )
    with pytest.raises(
        UnsupportedRobotError, match=r"cable 1 \('c1'\) leaves through a base_rotating_pulley .* leaves the XZ plane"
    ):
        load_robot(planar)
    with pytest.raises(UnsupportedRobotError, match="multi-link"):
        load_robot(FIXTURES / "multilink_bodies.xml")


def copy_model(tmp_path: Path, name: str, edit_bodies=lambda s: s, edit_cables=lambda s: s) -> Path:  # noqa: ANN001
    src = FIXTURES / f"{name}_bodies.xml"
    bodies = tmp_path / f"{name}_bodies.xml"
    bodies.write_text(edit_bodies(src.read_text()))
    (tmp_path / f"{name}_cables.xml").write_text(edit_cables((FIXTURES / f"{name}_cables.xml").read_text()))
    return bodies


@pytest.mark.parametrize(
    ("edit_bodies", "edit_cables", "error", "message"),
    [
        (lambda s: s.replace("<mass>12.5", "<mass>NaN"), None, RobotFileError, "mass.*finite"),
        (lambda s: s.replace('num="1"', 'num="2"'), None, RobotFileError, "out of order"),
        (None, lambda s: s.replace("<link>1</link>", "<link>3</link>", 1), RobotFileError, "links 1..1"),
        (
            None,
            lambda s: s.replace('default_cable_set="ideal"', 'default_cable_set="nope"'),
            RobotFileError,
            "no cable set 'nope'",
        ),
        (None, lambda s: s.replace('id="springs"', 'id="ideal"'), RobotFileError, "given twice"),
        (lambda s: s.replace('ref="joint"', 'ref="centre"'), None, RobotFileError, "ref must be"),
        (
            lambda s: s.replace('<inertia ref="joint">', '<inertia ref="joint" units="mm">'),
            None,
            RobotFileError,
            "unknown attribute 'units'",
        ),
        (
            None,
            lambda s: s.replace('attachment_reference="com"', 'attachment_reference="tip"', 1),
            RobotFileError,
            "attachment_reference",
        ),
        (
            None,
            lambda s: s.replace("cable_ideal", "cable_vsd_flexure_linear"),
            UnsupportedRobotError,
            "cable_vsd_flexure_linear",
        ),
        (
            lambda s: s.replace('"SPATIAL_EULER_XYZ"', '"SPATIAL_EULER_XYZ" actuated="true"'),
            None,
            UnsupportedRobotError,
            "actuated",
        ),
        (
            lambda s: s.replace('"SPATIAL_EULER_XYZ"', '"SPATIAL_QUATERNION"'),
            None,
            UnsupportedRobotError,
            "SPATIAL_QUATERNION",
        ),
        (
            lambda s: s.replace("<bodies_system>", '<!DOCTYPE b [<!ENTITY x "xx">]>\n<bodies_system>'),
            None,
            RobotFileError,
            "ENTITY",
        ),
        (lambda s: s.replace("</links>", ""), None, RobotFileError, "not valid XML"),
    ],
)
def test_bad_files_one_clear_line(tmp_path: Path, edit_bodies, edit_cables, error, message) -> None:  # noqa: ANN001
    bodies = copy_model(tmp_path, "spatial_euler", edit_bodies or (lambda s: s), edit_cables or (lambda s: s))
    with pytest.raises(error, match=message) as info:
        load_robot(bodies)
    assert "\n" not in str(info.value)
    assert "spatial_euler" in str(info.value)


def test_missing_cables_file_cable_set_on_a_taut_file_unknown_extension(tmp_path: Path) -> None:
    unknown = tmp_path / "robot.txt"
    unknown.write_text("name: x\n")
    bodies = tmp_path / "lonely_bodies.xml"
    bodies.write_text((FIXTURES / "spatial_euler_bodies.xml").read_text())
    with pytest.raises(RobotFileError, match="lonely_cables.xml is missing"):
        read_caspr(bodies)
    with pytest.raises(RobotFileError, match="cable-set"):
        load_robot("planar-4cable", cable_set="x")
    with pytest.raises(RobotFileError, match=r"supported: \*_bodies.xml"):
        load_robot(unknown)


def test_planar_cable_leaving_the_plane_is_refused(tmp_path: Path) -> None:
    bodies = copy_model(tmp_path, "planar_xz", edit_cables=lambda s: s.replace("-1 0.3 1", "-1 0.4 1"))
    with pytest.raises(UnsupportedRobotError, match="leaves the XZ plane"):
        load_robot(bodies)


# ---- round trip ---------------------------------------------------------------------------

#: The built-in examples a CASPR model can hold; the others are refused with a reason.
WRITABLE = {
    "camera-4cable",
    "cogiro",
    "marionet-vr",
    "planar-4cable",
    "printer-5cable",
    "spatial-8cable",
    "teaching-prototype",
}
#: Examples refused only for their cable radii (the collision model), written without them.
WITHOUT_RADII = {"adjustable-8cable"}


@pytest.mark.parametrize("name", example_names())
def test_round_trip_of_every_example(tmp_path: Path, name: str) -> None:
    robot = example(name)
    out = tmp_path / f"{name}_bodies.xml"
    if name in WITHOUT_RADII:
        with pytest.raises(UnsupportedRobotError, match="a CASPR model cannot hold the radius of cable 1"):
            write_caspr(robot, out)
        robot = robot.model_copy(update={"cables": tuple(c.model_copy(update={"radius": 0.0}) for c in robot.cables)})
    elif name not in WRITABLE:
        with pytest.raises(UnsupportedRobotError, match="a CASPR model cannot hold"):
            write_caspr(robot, out)
        return
    write_caspr(robot, out)
    back = read_caspr(out)
    assert (back.dimension, back.platform.kind, back.orientation) == (
        robot.dimension,
        robot.platform.kind,
        robot.orientation,
    )
    np.testing.assert_array_equal(back.exits, robot.exits)
    np.testing.assert_array_equal(back.anchors, robot.anchors)
    np.testing.assert_array_equal(back.tension_bounds, robot.tension_bounds)
    assert [c.stiffness for c in back.cables] == [c.stiffness for c in robot.cables]
    if robot.platform.wrench is None:
        np.testing.assert_allclose(back.weight, robot.weight, rtol=1e-15, atol=0)
    if np.any(back.weight != 0):
        np.testing.assert_array_equal(back.platform.wrench_point or 0, robot.platform.wrench_point or 0)
    if robot.inertia is not None:
        np.testing.assert_array_equal(back.inertia, robot.inertia)
    rng = np.random.default_rng(7)
    centre = robot.exits.mean(axis=0)
    n = 200
    poses = np.zeros((n, robot.pose_size))
    poses[:, : robot.dimension] = centre + rng.uniform(-0.2, 0.2, (n, robot.dimension)) * np.ptp(robot.exits, axis=0)
    poses[:, robot.dimension : robot.wrench_dim] = rng.uniform(-0.4, 0.4, (n, robot.wrench_dim - robot.dimension))
    lo, hi = robot.joint_limits.T
    poses[:, robot.wrench_dim :] = lo + rng.uniform(0, 1, (n, robot.n_joints)) * (hi - lo)
    a, b = inverse_kinematics(robot, poses), inverse_kinematics(back, poses)
    np.testing.assert_allclose(b.lengths, a.lengths, rtol=1e-14)
    np.testing.assert_allclose(b.structure_matrix, a.structure_matrix, rtol=1e-12, atol=1e-14)
    assert [(k.name, k.parent, k.joint.kind, k.joint.axis, k.joint.limits) for k in back.platform.bodies] == [
        (k.name, k.parent, k.joint.kind, k.joint.axis, k.joint.limits) for k in robot.platform.bodies
    ]
    np.testing.assert_allclose(
        jointed_structure_matrix(back, poses), jointed_structure_matrix(robot, poses), rtol=1e-12, atol=1e-14
    )
    # a constant downward wrench is written as the mass whose weight it is: same wrench at every pose
    np.testing.assert_allclose(external_wrench(back, poses), external_wrench(robot, poses), rtol=1e-14, atol=1e-15)


def test_written_pair_is_read_by_the_independent_parser(tmp_path: Path) -> None:
    """The writer's output means in CASPR what the robot means in taut: lengths from the
    written file's raw numbers (CASPR's semantics) equal taut's."""
    robot = example("cogiro")
    out = tmp_path / "cogiro_bodies.xml"
    write_caspr(robot, out)
    q = np.array([0.1, -0.2, 1.0, 0.1, -0.05, 0.2])
    lengths, W = expected(out, q)
    ik = inverse_kinematics(robot, q)
    np.testing.assert_allclose(ik.lengths, lengths, rtol=1e-12)
    np.testing.assert_allclose(ik.structure_matrix, W, rtol=1e-10, atol=1e-12)


@pytest.mark.parametrize("bodies", list(MODELS), ids=[p.stem for p in MODELS])
def test_round_trip_of_every_fixture(tmp_path: Path, bodies: Path) -> None:
    """Read, write, read again: the same robot (a horizontal plane stays horizontal, a YZ
    model comes back in the XZ plane with the same taut coordinates)."""
    robot = load_robot(bodies)
    out = tmp_path / "again_bodies.xml"
    write_caspr(robot, out)
    back = read_caspr(out)
    assert (back.dimension, back.platform.kind, back.orientation) == (
        robot.dimension,
        robot.platform.kind,
        robot.orientation,
    )
    for field in ("exits", "anchors", "tension_bounds", "weight", "inertia"):
        np.testing.assert_array_equal(getattr(back, field), getattr(robot, field), err_msg=field)
    assert back.platform.wrench_point == robot.platform.wrench_point
    assert [c.stiffness for c in back.cables] == [c.stiffness for c in robot.cables]
    assert [c.name for c in back.cables] == [c.name for c in robot.cables]
