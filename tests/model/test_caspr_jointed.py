"""CASPR jointed platforms (a free platform link carrying links on one-DOF joints) in and
out: lengths, structure matrices with joint rows, link weights in the statics, against an
independent forward model built here from the files' raw numbers as CASPR's
``SystemModelBodies.update`` composes link frames; the refusals of every construct taut
cannot represent; the round trip; the command line in real subprocesses."""

from __future__ import annotations

import json
import math
import xml.etree.ElementTree as ET
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from axis_rotations import rx, ry, rz
from hypothesis import given, settings
from hypothesis import strategies as st

from taut.errors import RobotFileError, UnsupportedRobotError
from taut.kinematics import inverse_kinematics, joint_forces, jointed_structure_matrix
from taut.model import Robot, example, load_robot
from taut.model._caspr import read_caspr, write_caspr
from taut.statics import distribute_tensions, external_wrench

FIXTURES = Path(__file__).parent / "fixtures" / "caspr"
ARM = FIXTURES / "jointed_arm_bodies.xml"
CHAIN = FIXTURES / "jointed_chain_bodies.xml"
SPIDER = FIXTURES / "real" / "SpiderBot_UR3_bodies.xml"
MULTIDOF = FIXTURES / "multidof_bodies.xml"
G = 9.81  # CASPR's gravity, along -z

#: (bodies file, cable set, platform position offset) of the models checked at random poses;
#: SpiderBot's default set has swivelling pulleys (checked in test_caspr.py), set_1 has none.
MODELS = {
    "arm": (ARM, None, np.array([0.0, 0.0, 1.0])),
    "chain": (CHAIN, None, np.array([0.0, 0.0, 1.0])),
    "spiderbot": (SPIDER, "set_1", np.zeros(3)),
    "multidof": (MULTIDOF, None, np.array([0.0, 0.0, 1.0])),
}


# ---- an independent model of CASPR's multi-link kinematics, from the raw XML -------------


def about(axis: np.ndarray, t: float) -> np.ndarray:
    """CASPR's ``RevoluteAxis.RelRotationMatrix``: ``I + sin t A + (1 − cos t) A²``."""
    a = axis / np.linalg.norm(axis)
    A = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(t) * A + (1 - math.cos(t)) * A @ A


def numbers(text: str | None) -> np.ndarray:
    return np.array([float(x) for x in (text or "").split()])


def raw_links(bodies: Path) -> list[dict]:
    links = []
    for el in ET.parse(bodies).getroot().iter("link_rigid"):
        joint = el.find("joint")
        inertia = el.find("physical/inertia")
        assert joint is not None and inertia is not None
        I = {t.tag: float(t.text or "") for t in inertia}
        tensor = np.array(
            [[I["Ixx"], I["Ixy"], I["Ixz"]], [I["Ixy"], I["Iyy"], I["Iyz"]], [I["Ixz"], I["Iyz"], I["Izz"]]]
        )
        mass = float(el.findtext("physical/mass") or "")
        com = numbers(el.findtext("physical/com_location"))
        if inertia.get("ref") == "joint":  # parallel axes, to the centre of mass
            tensor = tensor - mass * (com @ com * np.eye(3) - np.outer(com, com))
        links.append(
            {
                "name": el.get("name"),
                "type": joint.get("type"),
                "axis": numbers(joint.get("axis")),
                "q_min": joint.get("q_min"),
                "q_max": joint.get("q_max"),
                "parent": int(el.findtext("parent/num") or ""),
                "location": numbers(el.findtext("parent/location")),
                "mass": mass,
                "com": com,
                "inertia": tensor,
            }
        )
    return links


def raw_cables(bodies: Path, cable_set: str | None) -> list[dict]:
    root = ET.parse(str(bodies).replace("_bodies.xml", "_cables.xml")).getroot()
    wanted = cable_set or root.get("default_cable_set")
    links = raw_links(bodies)
    out = []
    for cset in root.iter("cable_set"):
        if cset.get("id") != wanted:
            continue
        for c in cset:
            atts = {int(a.findtext("link") or ""): numbers(a.findtext("location")) for a in c.iter("attachment")}
            link = max(atts)
            r = atts[link] + (links[link - 1]["com"] if c.get("attachment_reference") == "com" else 0.0)
            out.append({"base": atts[0], "link": link, "r": r})
    return out


DOFS = {"SPATIAL_EULER_XYZ": 6, "T_XYZ": 3, "S_EULER_XYZ": 3, "S_FIXED_XYZ": 3}
DOFS |= {"PLANAR_XY": 3, "PLANAR_XZ": 3, "PLANAR_YZ": 3}
DOFS |= {"U_XY": 2, "U_YZ": 2, "U_XZ": 2, "P_XY": 2, "P_XZ": 2}


def frames(links: list[dict], q: np.ndarray) -> list[tuple[np.ndarray, np.ndarray]]:
    """World position of each link's joint origin and its rotation at taut's pose ``q``: ``R_0k =
    R_0p R_pe(q_k)``, ``p_k = p_p + R_0p (location_k + r_rel(q_k))``.  taut's pose is CASPR's
    ``q``, but for a further link's S_FIXED_XYZ joint, whose chain taut turns γ first: its
    coordinates come as (γ, β, α) (the module docstring of ``taut.model._caspr``)."""
    out: list[tuple[np.ndarray, np.ndarray]] = []
    i = 0
    first = platform_index(links)
    for k, link in enumerate(links):
        t = link["type"]
        n = DOFS.get(t, 1)
        qk = q[i : i + n]
        i += n
        r_rel, R_pe = np.zeros(3), np.eye(3)
        if t == "SPATIAL_EULER_XYZ":
            r_rel, R_pe = qk[:3], rx(qk[3]) @ ry(qk[4]) @ rz(qk[5])
        elif t == "T_XYZ":
            r_rel = qk
        elif t == "S_EULER_XYZ":
            R_pe = rx(qk[0]) @ ry(qk[1]) @ rz(qk[2])
        elif t == "S_FIXED_XYZ":
            a, b, g = qk if k <= first else qk[::-1]
            R_pe = rz(g) @ ry(b) @ rx(a)
        elif t in ("U_XY", "U_YZ", "U_XZ"):
            first_axis, second_axis = {"U_XY": (rx, ry), "U_YZ": (ry, rz), "U_XZ": (rx, rz)}[t]
            R_pe = first_axis(qk[0]) @ second_axis(qk[1])
        elif t == "P_XY":
            r_rel = np.array([qk[0], qk[1], 0.0])
        elif t == "P_XZ":
            r_rel = np.array([qk[0], 0.0, qk[1]])
        elif t == "PLANAR_XY":
            r_rel, R_pe = np.array([qk[0], qk[1], 0.0]), rz(qk[2])
        elif t == "PLANAR_XZ":
            r_rel, R_pe = np.array([qk[0], 0.0, qk[1]]), ry(qk[2])
        elif t == "PLANAR_YZ":
            r_rel, R_pe = np.array([0.0, qk[0], qk[1]]), rx(qk[2])
        elif t in ("R_X", "R_Y", "R_Z"):
            R_pe = {"R_X": rx, "R_Y": ry, "R_Z": rz}[t](qk[0])
        elif t == "R_AXIS":
            R_pe = about(link["axis"], qk[0])
        elif t == "P_X":
            r_rel = np.array([qk[0], 0.0, 0.0])
        elif t == "P_AXIS":
            r_rel = qk[0] * link["axis"] / np.linalg.norm(link["axis"])
        else:
            raise AssertionError(t)
        if link["parent"] == 0:
            out.append((link["location"] + r_rel, R_pe))
        else:
            pp, Rp = out[link["parent"] - 1]
            out.append((pp + Rp @ (link["location"] + r_rel), Rp @ R_pe))
    assert i == len(q)
    return out


def platform_index(links: list[dict]) -> int:
    """0-based index of the platform link (after a T_XYZ carrier)."""
    return 1 if links[0]["type"] == "T_XYZ" else 0


def anchors(bodies: Path, cable_set: str | None, q: np.ndarray) -> np.ndarray:
    links = raw_links(bodies)
    F = frames(links, q)
    return np.array([F[c["link"] - 1][0] + F[c["link"] - 1][1] @ c["r"] for c in raw_cables(bodies, cable_set)])


def potential(bodies: Path, q: np.ndarray) -> float:
    """Gravitational potential energy ``Σ m_k g z_k`` of all links."""
    links = raw_links(bodies)
    F = frames(links, q)
    return sum(link["mass"] * G * (p + R @ link["com"])[2] for link, (p, R) in zip(links, F))


def derivative(f: Callable[[np.ndarray], np.ndarray], q: np.ndarray, j: int, h: float = 1e-6) -> np.ndarray:
    dq = np.zeros_like(q)
    dq[j] = h
    return (np.asarray(f(q + dq)) - np.asarray(f(q - dq))) / (2 * h)


def draw_pose(data: st.DataObject, robot: Robot, offset: np.ndarray) -> np.ndarray:
    floats = st.floats(-0.3, 0.3)
    q = np.array(data.draw(st.lists(floats, min_size=6, max_size=6)), dtype=float)
    q[:3] += offset
    lo = np.maximum(robot.joint_limits[:, 0], -1.0)
    hi = np.minimum(robot.joint_limits[:, 1], 1.0)
    u = np.array(data.draw(st.lists(st.floats(0, 1), min_size=len(lo), max_size=len(lo))), dtype=float)
    return np.concatenate([q, lo + u * (hi - lo)])


# ---- kinematics and statics against the independent model --------------------------------


@pytest.mark.parametrize("name", list(MODELS))
@settings(max_examples=25, deadline=None)
@given(data=st.data())
def test_lengths_and_structure_matrix_with_joint_rows(name: str, data: st.DataObject) -> None:
    bodies, cable_set, offset = MODELS[name]
    robot = load_robot(bodies, cable_set=cable_set)
    q = draw_pose(data, robot, offset)
    links, cables = raw_links(bodies), raw_cables(bodies, cable_set)
    p = frames(links, q)[platform_index(links)][0]
    b = anchors(bodies, cable_set, q)
    base = np.array([c["base"] for c in cables])
    lengths = np.linalg.norm(base - b, axis=1)
    u = (base - b) / lengths[:, None]
    np.testing.assert_allclose(inverse_kinematics(robot, q).lengths, lengths, rtol=1e-12, atol=1e-12)
    A = jointed_structure_matrix(robot, q)
    n, nj = robot.n_cables, robot.n_joints
    np.testing.assert_allclose(A[:3, :n], u.T, atol=1e-12)
    np.testing.assert_allclose(A[3:6, :n], np.cross(b - p, u).T, atol=1e-12)
    # joint rows by virtual work: u_i · ∂b_i/∂q_j, the derivative by central differences
    for j in range(nj):
        db = derivative(lambda x: anchors(bodies, cable_set, x), q, 6 + j)
        np.testing.assert_allclose(A[6 + j, :n], np.einsum("id,id->i", u, db), atol=1e-7)
    np.testing.assert_array_equal(A[6:, n:], np.eye(nj))
    np.testing.assert_array_equal(A[:6, n:], 0)


@pytest.mark.parametrize("name", list(MODELS))
@settings(max_examples=15, deadline=None)
@given(data=st.data())
def test_link_weights_in_the_external_wrench_and_the_joint_forces(name: str, data: st.DataObject) -> None:
    """The weights of all links act on the platform (force, moment about its origin) and on
    the joints: with tensions τ, ζ_j = −Σ τ_i u_i·∂b_i/∂q_j + ∂V/∂q_j (V the potential energy)."""
    bodies, cable_set, offset = MODELS[name]
    robot = load_robot(bodies, cable_set=cable_set)
    q = draw_pose(data, robot, offset)
    links = raw_links(bodies)
    F = frames(links, q)
    p = F[platform_index(links)][0]
    force, moment = np.zeros(3), np.zeros(3)
    for link, (pk, Rk) in zip(links, F):
        weight = np.array([0.0, 0.0, -G * link["mass"]])
        force += weight
        moment += np.cross(pk + Rk @ link["com"] - p, weight)
    np.testing.assert_allclose(external_wrench(robot, q), np.concatenate([force, moment]), rtol=1e-12, atol=1e-12)
    tau = np.array(data.draw(st.lists(st.floats(0, 100), min_size=robot.n_cables, max_size=robot.n_cables)))
    cables = raw_cables(bodies, cable_set)
    b = anchors(bodies, cable_set, q)
    base = np.array([c["base"] for c in cables])
    u = (base - b) / np.linalg.norm(base - b, axis=1)[:, None]
    expected = []
    for j in range(robot.n_joints):
        db = derivative(lambda x: anchors(bodies, cable_set, x), q, 6 + j)
        expected.append(-tau @ np.einsum("id,id->i", u, db) + derivative(lambda x: potential(bodies, x), q, 6 + j))
    np.testing.assert_allclose(joint_forces(robot, q, tau), expected, rtol=1e-6, atol=1e-6)


def test_spiderbot_tensions_hold_the_whole_arm() -> None:
    """The tension distribution of the real SpiderBot balances the weight of the platform and
    of all six arm links (18.63 kg, not the platform's 10 kg alone) and their moments about
    the platform origin, each link's weight at its centre of mass."""
    cable_set = "set_IPAnema_inspired"
    robot = load_robot(SPIDER, cable_set=cable_set)
    q = np.array([0.05, -0.1, 0.3, 0.05, -0.05, 0.1, 0.3, -0.4, 0.8, 0.2, -1.5708, 0.1])
    res = distribute_tensions(robot, q)
    assert res.feasible
    links = raw_links(SPIDER)
    F = frames(links, q)
    b = anchors(SPIDER, cable_set, q)
    base = np.array([c["base"] for c in raw_cables(SPIDER, cable_set)])
    u = (base - b) / np.linalg.norm(base - b, axis=1)[:, None]
    total = sum(link["mass"] for link in links)
    assert total == pytest.approx(18.63)
    np.testing.assert_allclose(res.tensions @ u, [0.0, 0.0, G * total], atol=1e-6)
    p = F[0][0]
    weights = sum(
        np.cross(pk + Rk @ link["com"] - p, [0.0, 0.0, -G * link["mass"]]) for link, (pk, Rk) in zip(links, F)
    )
    np.testing.assert_allclose(res.tensions @ np.cross(b - p, u) + weights, 0.0, atol=1e-6)


def test_bodies_mass_centre_of_mass_inertia_joints() -> None:
    for bodies in (ARM, CHAIN, SPIDER):
        links = raw_links(bodies)
        robot = load_robot(bodies)
        first = platform_index(links) + 1
        assert robot.n_joints == len(links) - first
        for body, link in zip(robot.platform.bodies, links[first:]):
            assert body.joint.kind == ("prismatic" if link["type"].startswith("P_") else "revolute")
            np.testing.assert_array_equal(body.joint.origin, link["location"])
            if link["mass"] == 0:
                assert (body.mass, body.com, body.inertia) == (None, None, None)
                continue
            assert body.mass == link["mass"]
            np.testing.assert_array_equal(body.com or np.zeros(3), link["com"])
            t = link["inertia"]
            expected = [t[0, 0], t[1, 1], t[2, 2], t[0, 1], t[0, 2], t[1, 2]]
            np.testing.assert_allclose(body.inertia or np.zeros(6), expected, rtol=1e-14, atol=1e-15)


def test_limits_names_and_cable_bodies() -> None:
    arm = load_robot(ARM)
    assert [b.name for b in arm.platform.bodies] == ["elbow", "wrist", "slider", "rail"]
    assert [b.parent for b in arm.platform.bodies] == ["platform", "elbow", "platform", "slider"]
    # given, CASPR's revolute default ±π, given, unbounded prismatic → ±1e9 (the same poses)
    np.testing.assert_array_equal(arm.joint_limits, [[-1.5, 1.5], [-math.pi, math.pi], [-0.3, 0.3], [-1e9, 1e9]])
    assert [c.body for c in arm.cables] == [None] * 4 + ["elbow", "wrist", "slider", "rail"]
    assert arm.platform.bodies[1].joint.axis == (0.0, 1.0, 1.0)
    chain = load_robot(CHAIN)
    # an unnamed link and a link named like the platform get unique names
    assert [b.name for b in chain.platform.bodies] == ["link 3", "platform (link 4)"]
    assert chain.orientation == "xyz-fixed"
    spider = load_robot(SPIDER)
    assert spider.swivel_cables == tuple(range(8))
    assert spider.pose_size == 12
    assert spider.platform.mass == 10.0


# ---- refusals -----------------------------------------------------------------------------


def edited(tmp_path: Path, bodies: Path, edit_bodies: Callable[[str], str], edit_cables: Callable[[str], str]) -> Path:
    stem = bodies.name[: -len("_bodies.xml")]
    out = tmp_path / bodies.name
    text = bodies.read_text()
    cables = (bodies.parent / f"{stem}_cables.xml").read_text()
    # the edit applies (or there is none: the fixture itself is refused)
    assert (edit_bodies(text), edit_cables(cables)) != (text, cables) or edit_bodies is edit_cables is same
    out.write_text(edit_bodies(text))
    (tmp_path / f"{stem}_cables.xml").write_text(edit_cables(cables))
    return out


def same(s: str) -> str:
    return s


REFUSED = [
    (
        ARM,
        lambda s: s.replace('type="R_Y"', 'type="SPHERICAL"'),
        same,
        UnsupportedRobotError,
        r"link 2 \('elbow'\) has a SPHERICAL joint, whose coordinates are a quaternion",
    ),
    (
        ARM,
        lambda s: s.replace('type="R_Y"', 'type="PLANAR_XZ"'),
        same,
        UnsupportedRobotError,
        r"link 2 \('elbow'\) has a PLANAR_XZ joint, which taut reads for the platform link only",
    ),
    (ARM, lambda s: s.replace('type="R_Y"', 'type="R_W"'), same, RobotFileError, "unknown joint type 'R_W'"),
    (
        ARM,
        lambda s: s.replace('type="R_Y"', 'type="U_XY"'),
        same,
        RobotFileError,
        r"U_XY joint's q_min/q_max \(one number per degree of freedom\): expected 2 numbers",
    ),
    (
        ARM,
        lambda s: s.replace("<num>1</num><location>-0.2 0 0</location>", "<num>0</num><location>-0.2 0 0</location>"),
        same,
        UnsupportedRobotError,
        r"link 4 \('slider'\) is jointed to the ground \(link 0\)",
    ),
    (
        ARM,
        lambda s: s.replace('"SPATIAL_EULER_XYZ"', '"SPATIAL_EULER_XYZ" actuated="true"'),
        same,
        UnsupportedRobotError,
        "platform's SPATIAL_EULER_XYZ joint is actuated",
    ),
    (
        ARM,
        lambda s: s.replace('"SPATIAL_EULER_XYZ"', '"PLANAR_XZ"'),
        same,
        UnsupportedRobotError,
        r"link 3 \('wrist'\): its R_AXIS joint turns about \[0.0, 1.0, 1.0\]; taut's planar joints turn about the plane's normal",
    ),
    (ARM, lambda s: s.replace('"SPATIAL_EULER_XYZ"', '"T_XYZ"'), same, UnsupportedRobotError, "jointed to a T_XYZ"),
    (
        ARM,
        same,
        lambda s: s.replace(
            "<attachment><link>0</link><location>2 -2 0</location></attachment><attachment><link>2</link>",
            "<attachment><link>3</link><location>0 0 0</location></attachment><attachment><link>2</link>",
        ),
        UnsupportedRobotError,
        r"runs through links 3 -> 2; a taut cable runs from the base \(link 0\) to a body",
    ),
    (ARM, lambda s: s.replace(' axis="0 1 1"', ""), same, RobotFileError, "R_AXIS joint needs an axis"),
    (ARM, lambda s: s.replace('axis="0 1 1"', 'axis="0 0 0"'), same, RobotFileError, "non-zero"),
    (ARM, lambda s: s.replace('type="R_Y"', 'type="R_Y" axis="1 0 0"'), same, RobotFileError, "R_AXIS / P_AXIS"),
    (ARM, lambda s: s.replace('q_min="-0.3" q_max="0.3"', 'q_min="0.3" q_max="-0.3"'), same, RobotFileError, "q_min"),
    (ARM, lambda s: s.replace('q_max="1.5"', 'q_max="NaN"'), same, RobotFileError, "finite"),
    (
        CHAIN,
        lambda s: s.replace("<num>2</num><location>0 0 -0.2</location>", "<num>1</num><location>0 0 -0.2</location>"),
        same,
        UnsupportedRobotError,
        r"is jointed to link 1 \(T_XYZ\)",
    ),
    (
        CHAIN,
        same,
        lambda s: s.replace("<link>4</link><location>0 0.1 0", "<link>1</link><location>0 0.1 0"),
        UnsupportedRobotError,
        "link 1, which carries no cables",
    ),
    (
        FIXTURES / "multilink_bodies.xml",
        same,
        same,
        UnsupportedRobotError,
        "jointed to the ground by R_Z is a multi-link robot",
    ),
]


@pytest.mark.parametrize(("bodies", "edit_bodies", "edit_cables", "error", "message"), REFUSED)
def test_unrepresentable_constructs_are_refused_by_name(
    tmp_path: Path,
    bodies: Path,
    edit_bodies,
    edit_cables,
    error: type,
    message: str,  # noqa: ANN001
) -> None:
    path = edited(tmp_path, bodies, edit_bodies, edit_cables)
    with pytest.raises(error, match=message) as info:
        load_robot(path)
    assert "\n" not in str(info.value)
    assert str(path) in str(info.value) or path.name[: -len("_bodies.xml")] in str(info.value)


def test_body_mass_properties_are_validated() -> None:
    arm = load_robot(ARM)
    elbow = arm.platform.bodies[0]

    def with_elbow(**update: object) -> Robot:
        body = elbow.model_copy(update=update)
        return arm.model_copy(
            update={"platform": arm.platform.model_copy(update={"bodies": (body, *arm.platform.bodies[1:])})}
        )

    for update, message in [
        ({"mass": -1.0}, "greater than 0"),
        ({"com": (0.1, 0.2)}, r"bodies\[1\].com: expected 3 numbers"),
        ({"inertia": (1.0, 1.0, 1.0)}, r"bodies\[1\].inertia: expected 6 numbers"),
        ({"inertia": (1.0, 1.0, 1.0, 5.0, 0.0, 0.0)}, "not a positive semi-definite"),
    ]:
        with pytest.raises(RobotFileError, match=message):
            with_elbow(**update)
    with pytest.raises(RobotFileError, match=r"bodies\[1\]: com or inertia is given without mass"):
        with_elbow(mass=None, inertia=None)
    # gravity may be given when only bodies carry a mass; it acts on them
    light = arm.platform.model_copy(
        update={"mass": None, "wrench_point": None, "inertia": None, "gravity": (0.0, 0.0, -1.62)}
    )
    moon = arm.model_copy(update={"platform": light})
    np.testing.assert_allclose(
        moon.body_weights[:, 2], [-1.62 * b.mass if b.mass else 0.0 for b in arm.platform.bodies]
    )
    np.testing.assert_array_equal(moon.weight, 0.0)


# ---- planar jointed platforms ------------------------------------------------------------

XZ = FIXTURES / "jointed_planar_xz_bodies.xml"
XY = FIXTURES / "jointed_planar_xy_bodies.xml"
YZ = FIXTURES / "jointed_planar_yz_bodies.xml"
#: plane axes, sign of each taut pose coordinate against CASPR's q (XZ: θ and the R_Y joint
#: turn against taut's planar angles; R_AXIS about −y turns with them), platform centre
PLANAR = {
    "xz": (XZ, (0, 2), np.array([1, 1, -1, -1, 1, 1]), np.array([0.0, 1.0])),
    "xy": (XY, (0, 1), np.ones(5), np.zeros(2)),
    "yz": (YZ, (1, 2), np.ones(5), np.array([0.0, 1.0])),
}


@pytest.mark.parametrize("name", list(PLANAR))
@settings(max_examples=25, deadline=None)
@given(data=st.data())
def test_planar_jointed_platforms(name: str, data: st.DataObject) -> None:
    bodies, (i, j), signs, centre = PLANAR[name]
    robot = load_robot(bodies)
    pose = np.concatenate(
        [
            centre + np.array(data.draw(st.lists(st.floats(-0.3, 0.3), min_size=2, max_size=2))),
            [data.draw(st.floats(-0.3, 0.3))],
            [data.draw(st.floats(lo, hi)) for lo, hi in robot.joint_limits.clip(-1, 1)],
        ]
    )
    q = signs * pose  # CASPR's coordinates
    links, cables = raw_links(bodies), raw_cables(bodies, None)
    F = frames(links, q)
    p = F[0][0]
    b = anchors(bodies, None, q)
    base = np.array([c["base"] for c in cables])
    lengths = np.linalg.norm(base - b, axis=1)
    u = (base - b) / lengths[:, None]
    normal = np.cross(np.eye(3)[i], np.eye(3)[j])
    np.testing.assert_allclose(inverse_kinematics(robot, pose).lengths, lengths, rtol=1e-12, atol=1e-12)
    A = jointed_structure_matrix(robot, pose)
    n = robot.n_cables
    np.testing.assert_allclose(A[:2, :n], u[:, [i, j]].T, atol=1e-12)
    np.testing.assert_allclose(A[2, :n], np.cross(b - p, u) @ normal, atol=1e-12)
    for k in range(robot.n_joints):
        db = derivative(lambda x: anchors(bodies, None, x), q, 3 + k)
        np.testing.assert_allclose(A[3 + k, :n], signs[3 + k] * np.einsum("id,id->i", u, db), atol=1e-7)
    # weights: CASPR's gravity along -z, projected on the plane (nothing in the XY plane)
    force, moment = np.zeros(3), np.zeros(3)
    for link, (pk, Rk) in zip(links, F):
        weight = np.array([0.0, 0.0, -G * link["mass"]])
        force += weight
        moment += np.cross(pk + Rk @ link["com"] - p, weight)
    np.testing.assert_allclose(external_wrench(robot, pose), [force[i], force[j], moment @ normal], atol=1e-12)
    tau = np.linspace(5.0, 50.0, n)
    expected = [
        signs[3 + k]
        * (
            -tau @ np.einsum("id,id->i", u, derivative(lambda x: anchors(bodies, None, x), q, 3 + k))
            + derivative(lambda x: potential(bodies, x), q, 3 + k)
        )
        for k in range(robot.n_joints)
    ]
    np.testing.assert_allclose(joint_forces(robot, pose, tau), expected, rtol=1e-6, atol=1e-6)


def test_planar_mapping() -> None:
    xz = load_robot(XZ)
    assert [b.joint.limits for b in xz.platform.bodies] == [(-1.2, 1.0), (-math.pi, math.pi), (-0.2, 0.2)]
    assert "joint coordinates negated (-q of CASPR): arm" in (xz.description or "")
    assert xz.platform.gravity is None and xz.gravity.tolist() == [0.0, -9.81]
    assert xz.platform.bodies[0].inertia == pytest.approx((0.02 - 1.0 * 0.1**2,), rel=1e-14)  # Iyy, about the COM
    xy = load_robot(XY)
    assert xy.platform.gravity == (0.0, 0.0)  # CASPR's gravity is normal to the XY plane
    np.testing.assert_array_equal(xy.body_weights, 0.0)


def test_written_planar_pair_means_the_same_in_caspr(tmp_path: Path) -> None:
    """The written XZ model, read by the independent model: the platform angle is −θ (the
    plane's mapping), the revolute joints are written as R_AXIS about −y, so their CASPR
    coordinates are taut's."""
    robot = load_robot(XZ)
    out = tmp_path / "xz_bodies.xml"
    write_caspr(robot, out)
    assert out.read_text().count('type="R_AXIS"') == 2
    base = np.array([c["base"] for c in raw_cables(out, None)])
    for pose in random_poses(robot, np.array([0.0, 1.0]), 10):
        q = np.array([1, 1, -1, 1, 1, 1]) * pose
        np.testing.assert_allclose(
            inverse_kinematics(robot, pose).lengths, np.linalg.norm(base - anchors(out, None, q), axis=1), rtol=1e-12
        )


PLANAR_REFUSED = [
    (XZ, lambda s: s.replace('type="R_Y"', 'type="R_X"'), same, r"R_X joint turns about \[1.0, 0.0, 0.0\]"),
    (XZ, lambda s: s.replace('axis="1 0 1"', 'axis="1 0.5 1"'), same, "P_AXIS joint moves out of the plane"),
    # the arm's frame is 0.01 off the platform's along y: its cable's exit must be too
    (XZ, same, lambda s: s.replace("2 0.03 -1", "2 0.02 -1"), "cable 3 .* leaves the XZ plane"),
    (XY, lambda s: s.replace('type="R_Z"', 'type="R_Y"'), same, "R_Y joint turns about"),
]


@pytest.mark.parametrize(("bodies", "edit_bodies", "edit_cables", "message"), PLANAR_REFUSED)
def test_planar_refusals(tmp_path: Path, bodies: Path, edit_bodies, edit_cables, message: str) -> None:  # noqa: ANN001
    with pytest.raises(UnsupportedRobotError, match=message):
        load_robot(edited(tmp_path, bodies, edit_bodies, edit_cables))


# ---- writing ------------------------------------------------------------------------------


def assert_same_robot(back: Robot, robot: Robot, poses: np.ndarray) -> None:
    assert [(b.name, b.parent) for b in back.platform.bodies] == [(b.name, b.parent) for b in robot.platform.bodies]
    for a, b in zip(back.platform.bodies, robot.platform.bodies):
        assert (a.joint.kind, a.joint.axis, a.joint.limits) == (b.joint.kind, b.joint.axis, b.joint.limits)
        assert a.joint.origin == (b.joint.origin or (0.0,) * robot.dimension)
        assert (a.mass, a.com, a.inertia) == (b.mass, b.com, b.inertia)
        assert a.joint.actuator == b.joint.actuator
    assert [c.body for c in back.cables] == [c.body for c in robot.cables]
    np.testing.assert_array_equal(back.exits, robot.exits)
    np.testing.assert_array_equal(back.anchors, robot.anchors)
    np.testing.assert_allclose(
        inverse_kinematics(back, poses).lengths, inverse_kinematics(robot, poses).lengths, rtol=1e-14
    )
    np.testing.assert_allclose(
        jointed_structure_matrix(back, poses), jointed_structure_matrix(robot, poses), rtol=1e-12, atol=1e-14
    )
    np.testing.assert_allclose(external_wrench(back, poses), external_wrench(robot, poses), rtol=1e-14, atol=1e-12)
    tau = np.linspace(1.0, 50.0, robot.n_cables)
    np.testing.assert_allclose(joint_forces(back, poses, tau), joint_forces(robot, poses, tau), rtol=1e-12, atol=1e-12)


def random_poses(robot: Robot, centre: np.ndarray, n: int = 50) -> np.ndarray:
    rng = np.random.default_rng(3)
    lo, hi = np.maximum(robot.joint_limits[:, 0], -1.0), np.minimum(robot.joint_limits[:, 1], 1.0)
    d = robot.dimension
    return np.concatenate(
        [
            centre + rng.uniform(-0.3, 0.3, (n, d)),
            rng.uniform(-0.3, 0.3, (n, robot.wrench_dim - d)),
            lo + rng.uniform(0, 1, (n, robot.n_joints)) * (hi - lo),
        ],
        axis=1,
    )


@pytest.mark.parametrize(
    ("bodies", "cable_set", "centre"),
    [
        (ARM, None, (0, 0, 1)),
        (CHAIN, None, (0, 0, 1)),
        (SPIDER, None, (1.1, 1.1, 1.0)),
        (SPIDER, "set_1", (0, 0, 0)),
        (SPIDER, "set_IPAnema_inspired", (0, 0, 0.3)),
        (MULTIDOF, None, (0, 0, 1)),
        (XZ, None, (0, 1)),
        (XY, None, (0, 0)),
        (YZ, None, (0, 1)),
    ],
)
def test_round_trip_of_jointed_fixtures(tmp_path: Path, bodies: Path, cable_set: str | None, centre: tuple) -> None:
    robot = load_robot(bodies, cable_set=cable_set)
    out = tmp_path / "again_bodies.xml"
    write_caspr(robot, out)
    back = read_caspr(out)
    assert (back.orientation, back.platform.mass, back.platform.wrench_point) == (
        robot.orientation,
        robot.platform.mass,
        robot.platform.wrench_point,
    )
    assert [c.swivel for c in back.cables] == [c.swivel for c in robot.cables]
    assert_same_robot(back, robot, random_poses(robot, np.array(centre, float)))


def without_cable_radii(robot: Robot) -> Robot:
    return robot.model_copy(update={"cables": tuple(c.model_copy(update={"radius": 0.0}) for c in robot.cables)})


def test_adjustable_platform_round_trip(tmp_path: Path) -> None:
    """The adjustable 8-cable robot (a prismatic joint) as a CASPR pair: its cable radii (the
    collision model) have no place in CASPR and are refused; without them it round-trips, and
    the written files mean in CASPR's semantics what the robot means in taut."""
    robot = example("adjustable-8cable")
    with pytest.raises(UnsupportedRobotError, match="the radius of cable 1"):
        write_caspr(robot, tmp_path / "adjustable_bodies.xml")
    robot = without_cable_radii(robot)
    out = tmp_path / "adjustable_bodies.xml"
    write_caspr(robot, out)
    assert '<joint type="P_AXIS" actuated="false"' in out.read_text()  # a passive joint: no actuator
    back = read_caspr(out)
    poses = random_poses(robot, np.array([5.0, 5.0, 4.0]))
    assert_same_robot(back, robot, poses)
    for q in poses[:10]:
        np.testing.assert_allclose(
            inverse_kinematics(robot, q).lengths,
            np.linalg.norm(np.array([c["base"] for c in raw_cables(out, None)]) - anchors(out, None, q), axis=1),
            rtol=1e-12,
        )


def test_writer_refusals(tmp_path: Path) -> None:
    arm = load_robot(ARM)
    moon = arm.model_copy(update={"platform": arm.platform.model_copy(update={"gravity": (0.0, 0.0, -1.62)})})
    with pytest.raises(UnsupportedRobotError, match="gravity"):
        write_caspr(moon, tmp_path / "moon_bodies.xml")


# ---- the command line, in real subprocesses -------------------------------------------------


def test_cli_ik_of_a_jointed_caspr_model(taut_cli) -> None:  # noqa: ANN001
    q = np.array([0.1, -0.1, 0.9, 0.1, 0.05, -0.2, 0.4, -0.3, 0.1, 0.25])
    run = taut_cli("ik", str(ARM), "--pose=" + ",".join(repr(float(x)) for x in q), "--json")
    assert run.code == 0, run.err
    data = json.loads(run.out)
    base = np.array([c["base"] for c in raw_cables(ARM, None)])
    np.testing.assert_allclose(data["lengths"], np.linalg.norm(base - anchors(ARM, None, q), axis=1), rtol=1e-12)
    spider = taut_cli(
        "ik", str(SPIDER), "--cable-set", "set_1", "--pose=0,0,0,0,0,0,0.3,-0.4,0.8,0.2,-1.5,0.1", "--json"
    )
    q = np.array([0, 0, 0, 0, 0, 0, 0.3, -0.4, 0.8, 0.2, -1.5, 0.1])
    base = np.array([c["base"] for c in raw_cables(SPIDER, "set_1")])
    np.testing.assert_allclose(
        spider.json()["lengths"], np.linalg.norm(base - anchors(SPIDER, "set_1", q), axis=1), rtol=1e-12
    )


@pytest.mark.parametrize(
    ("edit", "words"),
    [
        (lambda s: s.replace('type="R_Y"', 'type="U_XY"'), ("U_XY", "expected 2 numbers")),
        (lambda s: s.replace('type="R_Y"', 'type="R_W"'), ("link 2", "unknown joint type 'R_W'")),
        (lambda s: s.replace('type="R_Y"', 'type="SPHERICAL"'), ("SPHERICAL", "quaternion")),
        (lambda s: s.replace(' axis="0 1 1"', ""), ("R_AXIS", "axis")),
    ],
)
@pytest.mark.parametrize("command", ["ik", "convert", "check"])
def test_cli_bad_jointed_files_one_line_exit_2(
    tmp_path: Path,
    taut_cli,  # noqa: ANN001
    edit,  # noqa: ANN001
    words: tuple[str, ...],
    command: str,
) -> None:
    path = edited(tmp_path, ARM, edit, same)
    options = {
        "ik": ["--pose=0,0,1,0,0,0,0,0,0,0"],
        "convert": [str(tmp_path / "out.yaml")],
        "check": ["--trajectory", "any"],
    }[command]
    run = taut_cli(command, str(path), *options)
    assert run.code == 2
    assert run.err.count("\n") == 1 and run.err.startswith("taut: error: ")
    assert all(w in run.err for w in words), run.err
    assert "Traceback" not in run.err
    assert not (tmp_path / "out.yaml").exists()


def test_cli_convert_jointed(tmp_path: Path, taut_cli) -> None:  # noqa: ANN001
    out = tmp_path / "arm_bodies.xml"
    run = taut_cli("convert", str(ARM), str(out), "--json")
    assert run.json()["format"] == "caspr"
    robot = load_robot(ARM)
    assert_same_robot(read_caspr(out), robot, random_poses(robot, np.array([0.0, 0.0, 1.0]), 10))
    refused = taut_cli("convert", "adjustable-8cable", str(tmp_path / "adjustable_bodies.xml"))
    assert refused.code == 2 and refused.err.count("\n") == 1
    assert "the radius of cable 1" in refused.err


def test_cli_tensions_hold_the_links_and_yaml_keeps_their_masses(tmp_path: Path, taut_cli) -> None:  # noqa: ANN001
    """``taut tensions`` on the real SpiderBot balances the weight of all seven links; the
    link masses survive a conversion to taut YAML."""
    cable_set = "set_IPAnema_inspired"
    q = np.array([0.05, -0.1, 0.3, 0.05, -0.05, 0.1, 0.3, -0.4, 0.8, 0.2, -1.5708, 0.1])
    run = taut_cli(
        "tensions", str(SPIDER), "--cable-set", cable_set, "--pose=" + ",".join(repr(float(x)) for x in q), "--json"
    )
    data = run.json()
    assert data["feasible"]
    b = anchors(SPIDER, cable_set, q)
    base = np.array([c["base"] for c in raw_cables(SPIDER, cable_set)])
    u = (base - b) / np.linalg.norm(base - b, axis=1)[:, None]
    np.testing.assert_allclose(np.array(data["tensions"]) @ u, [0.0, 0.0, G * 18.63], atol=1e-6)
    out = tmp_path / "spider.yaml"
    assert taut_cli("convert", str(SPIDER), str(out), "--json").code == 0
    assert load_robot(out) == load_robot(SPIDER)


def test_default_wrench_set_is_sized_by_all_link_weights() -> None:
    """The default box of wrench-feasibility is 10 % of the force of the external wrench: of
    all seven SpiderBot links (18.63 kg), not of the platform's 10 kg."""
    from taut.workspace import default_wrench_set

    box = default_wrench_set(load_robot(SPIDER))
    np.testing.assert_allclose(box.upper[:3], 0.1 * G * 18.63, rtol=1e-12)
