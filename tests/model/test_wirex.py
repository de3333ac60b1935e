"""WireX ``.wcrfx`` files: the reader against WireX's own reference values and against an
independent computation from the files' raw numbers, the writer by round trips, and bad files.

The independent computation parses the XML here with ElementTree and builds rotations from
elementary rotations written here; it follows WireX's standard model (``CKinematics::
doInverseKinematics``, ``CStructureMatrix::getStructureMatrix``): ``l_i = ‖r + R b_i − a_i‖``,
``u_i = (a_i − r − R b_i)/l_i``, columns ``[u_i; R b_i × u_i]``, planar patterns keeping x, y
and the z moment.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import taut
from taut.errors import RobotFileError, UnsupportedRobotError
from taut.kinematics import inverse_kinematics
from taut.model import load_robot
from taut.model._wirex import read_wirex, write_wirex
from taut.statics import external_wrench

FIXTURES = Path(__file__).parent / "fixtures" / "wirex"
REAL = ["IPAnema.wcrfx", "CoGiRo.wcrfx", "CableMasterRobot.wcrfx"]
OWN = ["spatial_3r3t.wcrfx", "planar_1r2t.wcrfx", "point_2t.wcrfx", "point_3t.wcrfx"]


def raw(name: str) -> ET.Element:
    return ET.parse(FIXTURES / name).getroot().find("robot")


def raw_chains(name: str) -> tuple[np.ndarray, np.ndarray]:
    """Base and platform points ``(n, 3)`` as the file prints them."""
    chains = raw(name).find("geometry").findall("chain")
    base = np.array([[float(c.find("base").get(k)) for k in "xyz"] for c in chains])
    plat = np.array([[float(c.find("platform").get(k)) for k in "xyz"] for c in chains])
    return base, plat


def rx(t: float) -> np.ndarray:
    return np.array([[1, 0, 0], [0, math.cos(t), -math.sin(t)], [0, math.sin(t), math.cos(t)]])


def ry(t: float) -> np.ndarray:
    return np.array([[math.cos(t), 0, math.sin(t)], [0, 1, 0], [-math.sin(t), 0, math.cos(t)]])


def rz(t: float) -> np.ndarray:
    return np.array([[math.cos(t), -math.sin(t), 0], [math.sin(t), math.cos(t), 0], [0, 0, 1]])


def wirex_standard_model(name: str, r: np.ndarray, R: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Lengths ``(n,)`` and the 6 x n structure matrix of WireX's standard model."""
    base, plat = raw_chains(name)
    P = plat @ R.T
    v = base - r - P
    lengths = np.linalg.norm(v, axis=1)
    u = v / lengths[:, None]
    return lengths, np.vstack([u.T, np.cross(P, u).T])


def read(name: str) -> taut.Robot:
    return read_wirex(FIXTURES / name, pulleys="points")


# ---- WireX's own reference values ----------------------------------------------------------

#: Structure matrix ``A^T`` (rows = cables) of WireX's unit test ``test_Ikin_structureMatrix_compliance644``
#: (``Scripts/wcUnitTest.py``) for the IPAnema 1 design at r = (0.1, 0.2, 1), R = I.
WIREX_AT = [
    [-0.7881678136715315, 0.4790823965454407, 0.3863567714076135, 0.023181406284456807, 0.023181406284456807, 0.018545125027565453],
    [0.7560310364971451, 0.5094991767698152, 0.4108864328788832, 0.024653185972732992, -0.024653185972732992, -0.014791911583639798],
    [0.6917488766649749, -0.6165587813753037, 0.37595047644835594, -0.022557028586901357, -0.022557028586901357, 0.004511405717380269],
    [-0.728051577325381, -0.5852963660851102, 0.35688802810067694, -0.021413281686040616, 0.021413281686040616, -0.00856531267441625],
    [-0.7881678136715315, 0.4790823965454407, -0.3863567714076135, -0.023181406284456807, -0.023181406284456807, 0.018545125027565453],
    [0.7560310364971451, 0.5094991767698152, -0.4108864328788832, -0.024653185972732992, 0.024653185972732992, -0.014791911583639798],
    [0.6917488766649749, -0.6165587813753037, -0.37595047644835594, 0.022557028586901357, 0.022557028586901357, 0.004511405717380269],
    [-0.728051577325381, -0.5852963660851102, -0.35688802810067694, 0.021413281686040616, -0.021413281686040616, -0.00856531267441625],
]  # fmt: skip
#: ``test_Ikin_inversekinematics_compliance644``: lengths at r = (0.1, 0.2, 1).
WIREX_LENGTHS = [2.5882812830138846, 2.433762519228201, 2.659924810967408, 2.8019992862240346] * 2
#: ``test_Ikin_inversekinematics``: lengths at r = (0, 0, 1).
WIREX_LENGTHS_CENTRE = [2.6148040079516472] * 8


def test_ipanema_file_is_wirex_ipanema1_design():
    """WireX's unit tests use its built-in IPAnema1Design (frame 4 x 3 x 2 m, platform
    0.12 x 0.12 m, GeometryGenerator.cpp); IPAnema.wcrfx holds the same geometry."""
    base, plat = raw_chains("IPAnema.wcrfx")
    sx, sy = [-1, 1, 1, -1] * 2, [1, 1, -1, -1] * 2
    assert np.array_equal(base, np.c_[np.multiply(sx, 2.0), np.multiply(sy, 1.5), [2.0] * 4 + [0.0] * 4])
    assert np.array_equal(plat, np.c_[np.multiply(sx, 0.06), np.multiply(sy, 0.06), np.zeros(8)])


def test_ipanema_reproduces_wirex_reference_values():
    """WireX's reference lengths and structure matrix (its standard model, ``inverseKinematics2``
    and ``getStructureMatrix``: no pulley kinematics), so the point model compares exactly."""
    robot = read("IPAnema.wcrfx")
    ik = inverse_kinematics(robot, [[0.1, 0.2, 1.0, 0, 0, 0], [0, 0, 1.0, 0, 0, 0]])
    assert np.allclose(ik.lengths[0], WIREX_LENGTHS, rtol=0, atol=1e-14)
    assert np.allclose(ik.lengths[1], WIREX_LENGTHS_CENTRE, rtol=0, atol=1e-14)
    assert np.allclose(ik.structure_matrix[0].T, WIREX_AT, rtol=0, atol=1e-14)


def test_pulleys_are_swivels_by_default():
    robot = read_wirex(FIXTURES / "IPAnema.wcrfx")
    base, _ = raw_chains("IPAnema.wcrfx")
    assert np.array_equal(robot.exits, base)
    assert all(c.swivel is not None and c.swivel.axis == (0, 0, 1) and c.swivel.radius == 0.1 for c in robot.cables)
    assert "APPROXIMATION" not in robot.description


def test_planar_pulleys_about_an_axis_out_of_the_plane_are_refused():
    """WireX's default winch frame is the identity: its z axis, the swivel axis, is normal to
    the plane of a planar pattern, and the cable would leave the plane over the pulley."""
    with pytest.raises(
        UnsupportedRobotError,
        match=r'no_radius_2t\.wcrfx: <chain id="1"> <base>: the swivelling pulley \(radius 0\.1 m\) turns about',
    ) as err:
        read_wirex(FIXTURES / "no_radius_2t.wcrfx")
    assert "(0, 0, 1), which leaves the xy plane of motion of 2T" in str(err.value)
    assert "pulleys='points'" in str(err.value) and "\n" not in str(err.value)


def test_point_pulleys_say_so_in_the_description():
    robot = read("CableMasterRobot.wcrfx")
    assert "APPROXIMATION" in robot.description and "radius 0.025 m" in robot.description
    assert "APPROXIMATION" not in read("spatial_3r3t.wcrfx").description


def test_point_pulleys_are_the_fixed_points():
    """Pulleys of radius 0.05 taken as points give the robot whose file says radius 0."""
    swivels = read_wirex(FIXTURES / "pulleys_3r3t.wcrfx")
    assert [c.swivel.radius for c in swivels.cables] == [0.05] * 8
    points, plain = read("pulleys_3r3t.wcrfx"), read("spatial_3r3t.wcrfx")
    assert np.array_equal(points.exits, plain.exits) and np.array_equal(points.anchors, plain.anchors)
    assert "radius 0.05 m" in points.description


def test_missing_radius_is_wirex_default_pulley():
    """WireX assumes a 0.1 m pulley where <base> gives no radius (CRobotData::getXmlNode)."""
    with pytest.raises(UnsupportedRobotError, match="radius 0.1 m"):
        read_wirex(FIXTURES / "no_radius_2t.wcrfx")
    assert read("no_radius_2t.wcrfx").n_cables == 3


# ---- pulleys: WireX's own pulley kinematics -----------------------------------------------------


def raw_winches(root: ET.Element) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Base points ``(n, 3)``, winch frames ``(n, 3, 3)`` (``aRC`` is row R, column C),
    pulley radii ``(n,)`` (0.1 where absent) and platform points ``(n, 3)`` of a ``<robot>``."""
    chains = root.find("geometry").findall("chain")
    bases = [c.find("base") for c in chains]
    points = np.array([[float(b.get(k)) for k in "xyz"] for b in bases])
    frames = np.array(
        [[[float(b.get(f"a{i}{j}", float(i == j))) for j in (1, 2, 3)] for i in (1, 2, 3)] for b in bases]
    )
    radii = np.array([float(b.get("radius", 0.1)) for b in bases])
    plat = np.array([[float(c.find("platform").get(k)) for k in "xyz"] for c in chains])
    return points, frames, radii, plat


def wirex_pulley_lengths(root: ET.Element, r: np.ndarray, R: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Cable lengths ``(n,)`` of WireX's pulley kinematics, as ``CKinematics::doInverseKinematicsPulleyEx``
    (``WireLib/Kinematics.cpp``) computes them, and each anchor's distance from its swivel axis.

    The platform point minus the base point, expressed in the winch frame, has the distance
    ``bxy`` from the frame's z axis and the height ``bz`` along it; the distance from the pulley
    centre (``r_p`` off the axis) is ``BM = √((bxy − r_p)² + bz²)``, the free length
    ``l_f = √(BM² − r_p²)``, the wrap angle ``acos(l_f/BM) + acos(bz/BM)``, the length
    ``wrap · r_p + l_f``."""
    base, frames, rp, plat = raw_winches(root)
    ap = r + plat @ R.T - base
    local = np.einsum("nji,nj->ni", frames, ap)
    bxy, bz = np.hypot(local[:, 0], local[:, 1]), local[:, 2]
    bm = np.hypot(bxy - rp, bz)
    lf = np.sqrt(bz**2 + (bxy - rp) ** 2 - rp**2)
    wrap = np.arccos(lf / bm) + np.arccos(bz / bm)
    return wrap * rp + lf, bxy / rp


def wirex_pulley_ex(root: ET.Element, r: np.ndarray, R: np.ndarray) -> dict[str, np.ndarray]:
    """Everything ``CKinematics::doInverseKinematicsPulleyEx`` (``WireLib/Kinematics.cpp``)
    computes at the pose ``(r, R)``, for every chain, transcribed: the lengths ``l``, the
    swivel angles ``gamma = atan2(b_y, b_x)`` and wrap angles ``beta`` of the pulleys, the
    tangent points ``C = a + A R_z(gamma)((r_p, 0, 0) + R_y(beta)(−r_p, 0, 0))``, the cable
    vectors ``U = C − R b − r``, WireX's validity flag (it refuses ``BM < 2 r_p`` and anchors
    within 1e-6 of the axis) and ``off_axis`` = ``bxy / r_p`` (the two-``arccos`` wrap angle
    holds for ``bxy ≥ r_p``); and the structure matrix of ``CStructureMatrix::getStructureMatrix``
    with ``usePulley`` (``3R3T``): columns ``[U/‖U‖; R b × U/‖U‖]``."""
    base, frames, rp, plat = raw_winches(root)
    P = plat @ R.T
    ap = r + P - base
    local = np.einsum("nji,nj->ni", frames, ap)
    bxy, bz = np.hypot(local[:, 0], local[:, 1]), local[:, 2]
    bm = np.hypot(bxy - rp, bz)
    gamma = np.arctan2(local[:, 1], local[:, 0])
    lf = np.sqrt(bz**2 + (bxy - rp) ** 2 - rp**2)
    beta = np.arccos(lf / bm) + np.arccos(bz / bm)
    C = np.array(
        [
            a + A @ rz(g) @ (np.array([p, 0, 0]) + ry(b) @ np.array([-p, 0, 0]))
            for a, A, g, b, p in zip(base, frames, gamma, beta, rp, strict=True)
        ]
    )
    U = C - P - r
    u = U / np.linalg.norm(U, axis=1, keepdims=True)
    return {
        "l": beta * rp + lf,
        "gamma": gamma,
        "beta": beta,
        "C": C,
        "W": np.vstack([u.T, np.cross(P, u).T]),
        "valid": ~((bm < 2 * rp) | (bxy < 1e-6)),
        "off_axis": bxy / np.where(rp > 0, rp, 1.0),
    }


def angle_gap(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``|a − b|`` as angles, wrapped into ``[0, π]``."""
    return np.abs(np.angle(np.exp(1j * (np.asarray(a) - np.asarray(b)))))


@pytest.mark.parametrize("name", REAL)
def test_real_robots_swivel_angles_tangents_and_structure_matrix_are_wirexs(name):
    """At 1,200 random poses of each real WireX robot, where WireX's formulas are valid (its own
    validity test, and anchors at least ``r_p`` from the swivel axis for the two-``arccos``
    wrap angle), taut's lengths, swivel angles, tangent points and structure matrix are those
    of WireX's pulley kinematics and its pulley-corrected structure matrix."""
    from taut.kinematics import swivel_angles

    root, robot = raw(name), read_wirex(FIXTURES / name)
    assert robot.swivel_cables == tuple(range(robot.n_cables))
    base = raw_winches(root)[0]
    lo, hi = base.min(axis=0), base.max(axis=0)
    rng = np.random.default_rng(2018)
    N = 1200
    positions = lo + (hi - lo) * rng.uniform(0.3, 0.7, (N, 3))
    angles = rng.uniform(-0.25, 0.25, (N, 3))
    poses = np.hstack([positions, angles])
    ik = inverse_kinematics(robot, poses)
    gamma = swivel_angles(robot, poses)
    used = 0
    for k, (position, (a, b, c)) in enumerate(zip(positions, angles, strict=True)):
        wx = wirex_pulley_ex(root, position, rz(c) @ ry(b) @ rx(a))
        if not (wx["valid"].all() and (wx["off_axis"] >= 1.0).all()):
            continue
        used += 1
        assert np.allclose(ik.lengths[k], wx["l"], rtol=0, atol=1e-12)
        assert angle_gap(gamma[k], wx["gamma"]).max() < 1e-12
        assert np.allclose(ik.exit_points[k], wx["C"], rtol=0, atol=1e-12)
        assert np.allclose(ik.structure_matrix[k], wx["W"], rtol=0, atol=1e-12)
    assert used >= 1000


PLANAR_PULLEYS = ["planar_pulleys_1r2t.wcrfx", "planar_pulleys_2t.wcrfx"]


def test_planar_pulleys_are_in_plane_swivels():
    robot = read_wirex(FIXTURES / "planar_pulleys_1r2t.wcrfx")
    _, frames, radii, _ = raw_winches(raw("planar_pulleys_1r2t.wcrfx"))
    assert robot.swivel_cables == (0, 1, 2, 4)
    assert [c.swivel.axis for c in robot.cables if c.swivel] == [tuple(f[:2, 2]) for f in frames[[0, 1, 2, 4]]]
    assert [c.swivel.radius for c in robot.cables if c.swivel] == radii[[0, 1, 2, 4]].tolist()
    point = read_wirex(FIXTURES / "planar_pulleys_2t.wcrfx")
    assert (point.dimension, point.platform.kind, point.swivel_cables) == (2, "point-mass", (0, 1, 2))


@settings(max_examples=200, deadline=None)
@given(st.floats(-0.5, 0.5), st.floats(-0.5, 0.5), st.floats(-0.5, 0.5), st.sampled_from(PLANAR_PULLEYS))
def test_planar_pulleys_are_wirex_pulley_kinematics(x, y, theta, name):
    """The planar patterns with in-plane pulleys: lengths, swivel angles (0 or π) and tangent
    points of WireX's pulley kinematics (the pattern does not change them: WireX's
    ``doInverseKinematicsPulleyEx`` takes the pose ``(r, R)`` of any pattern, here ``r_z = 0``
    and ``R = R_z(θ)``), and the rows ``f_x, f_y`` (and ``m_z`` for ``1R2T``) of WireX's
    pulley-corrected structure matrix, the rows the planar patterns keep
    (``getStructureMatrix``)."""
    from taut.kinematics import swivel_angles

    robot, root = read_wirex(FIXTURES / name), raw(name)
    rigid = robot.platform.kind == "rigid"
    if rigid:
        r, R, pose = np.array([x, y, 0.0]), rz(theta), [x, y, theta]
    else:
        r, R, pose = np.array([x + 1.0, y + 1.0, 0.0]), np.eye(3), [x + 1.0, y + 1.0]
    wx = wirex_pulley_ex(root, r, R)
    assume(wx["valid"].all() and (wx["off_axis"][list(robot.swivel_cables)] >= 1.0).all())
    ik = inverse_kinematics(robot, pose)
    assert np.allclose(ik.lengths, wx["l"], rtol=0, atol=1e-9)
    # a point mass carries its anchor offsets in its exits: its tangent points move with them
    offsets = 0.0 if rigid else raw_winches(root)[3][:, :2]
    assert np.allclose(ik.exit_points, wx["C"][:, :2] - offsets, rtol=0, atol=1e-9)
    assert np.allclose(wx["C"][:, 2], raw_winches(root)[0][:, 2], rtol=0, atol=1e-12), "the cables stay in the plane"
    rows = [0, 1, 5] if rigid else [0, 1]
    assert np.allclose(ik.structure_matrix, wx["W"][rows], rtol=0, atol=1e-9)
    gamma = swivel_angles(robot, pose)
    assert angle_gap(gamma, wx["gamma"][list(robot.swivel_cables)]).max() < 1e-12
    assert set(np.round(np.abs(gamma), 12)) <= {0.0, round(math.pi, 12)}


@pytest.mark.parametrize("name", PLANAR_PULLEYS)
def test_planar_pulleys_round_trip(tmp_path, name):
    robot = read_wirex(FIXTURES / name)
    write_wirex(robot, tmp_path / name)
    back = read_wirex(tmp_path / name)
    assert [c.swivel for c in back.cables] == [c.swivel for c in robot.cables]
    assert_same_robot(robot, back)


positions = st.tuples(st.floats(-1.6, 1.6), st.floats(-1.1, 1.1), st.floats(0.2, 1.8))
turns = st.tuples(*[st.floats(-0.6, 0.6)] * 3)


@settings(max_examples=60, deadline=None)
@given(positions, turns)
def test_ipanema_swivels_are_wirex_pulley_kinematics(position, abc):
    """taut's lengths with the imported swivels equal WireX's pulley kinematics on the real
    IPAnema file.  WireX's two-``arccos`` wrap angle is right only for anchors at least the
    pulley radius from the swivel axis (and WireX itself refuses anchors within ``2 r_p`` of
    the pulley centre): the poses are restricted to that domain."""
    a, b, c = abc
    root = raw("IPAnema.wcrfx")
    expected, off_axis = wirex_pulley_lengths(root, np.array(position), rz(c) @ ry(b) @ rx(a))
    assume(np.all(off_axis >= 1.0))
    ik = inverse_kinematics(read_wirex(FIXTURES / "IPAnema.wcrfx"), [*position, a, b, c])
    assert np.allclose(ik.lengths, expected, rtol=0, atol=1e-9)
    # the pulleys lengthen the cables: the standard model's lengths differ
    assert not np.allclose(
        ik.lengths, wirex_standard_model("IPAnema.wcrfx", np.array(position), rz(c) @ ry(b) @ rx(a))[0]
    )


@settings(max_examples=40, deadline=None)
@given(
    positions,
    turns,
    st.lists(
        st.tuples(st.floats(-math.pi, math.pi), st.floats(-2.5, 2.5), st.floats(-math.pi, math.pi)),
        min_size=8,
        max_size=8,
    ),
)
def test_tilted_winch_frames_are_wirex_pulley_kinematics(tmp_path_factory, position, abc, tilts):
    """IPAnema with every winch frame turned (``R_z R_x R_z``): the swivel axis is the frame's
    z axis, and the lengths, tangent points and pulley-corrected structure matrix stay WireX's
    (same domain as above).  The swivel angle is WireX's up to the constant angle between the
    file frame's x axis and that of :func:`taut.geometry.axis_frames`, about the same axis."""
    from taut.geometry import axis_frames
    from taut.kinematics import swivel_angles

    root = raw("IPAnema.wcrfx")
    for chain, (t1, t2, t3) in zip(root.find("geometry").findall("chain"), tilts, strict=True):
        frame = rz(t1) @ rx(t2) @ rz(t3)
        chain.find("base").attrib.update(
            {f"a{i + 1}{j + 1}": repr(float(frame[i, j])) for i in range(3) for j in range(3)}
        )
    path = tmp_path_factory.mktemp("wcrfx") / "tilted.wcrfx"
    models = ET.Element("models")
    models.append(root)
    ET.ElementTree(models).write(path)
    a, b, c = abc
    expected, off_axis = wirex_pulley_lengths(root, np.array(position), rz(c) @ ry(b) @ rx(a))
    assume(np.all(off_axis >= 1.0))
    wx = wirex_pulley_ex(root, np.array(position), rz(c) @ ry(b) @ rx(a))
    assume(wx["valid"].all())
    robot = read_wirex(path)
    frames = raw_winches(root)[1]
    assert np.array_equal([c.swivel.axis for c in robot.cables], frames[:, :, 2])
    ik = inverse_kinematics(robot, [*position, a, b, c])
    assert np.allclose(ik.lengths, expected, rtol=0, atol=1e-9)
    assert np.allclose(ik.exit_points, wx["C"], rtol=0, atol=1e-9)
    assert np.allclose(ik.structure_matrix, wx["W"], rtol=0, atol=1e-9)
    own_x = axis_frames(np.array([f[:, 2] for f in frames]))[:, :, 0]
    offset = np.arctan2(np.einsum("ni,ni->n", frames[:, :, 1], own_x), np.einsum("ni,ni->n", frames[:, :, 0], own_x))
    assert angle_gap(swivel_angles(robot, [*position, a, b, c]) + offset, wx["gamma"]).max() < 1e-9


# ---- independent computation from the raw numbers -------------------------------------------

angles = st.floats(-0.6, 0.6)


@settings(max_examples=30, deadline=None)
@given(st.tuples(st.floats(-0.8, 0.8), st.floats(-0.5, 0.5), st.floats(0.5, 1.5)), st.tuples(angles, angles, angles))
@pytest.mark.parametrize("name", ["spatial_3r3t.wcrfx", *REAL])
def test_spatial_lengths_and_structure_matrix(name, position, abc):
    a, b, c = abc
    robot = read(name)
    assert robot.orientation == "xyz-fixed"
    ik = inverse_kinematics(robot, [*position, a, b, c])
    lengths, W = wirex_standard_model(name, np.array(position), rz(c) @ ry(b) @ rx(a))
    assert np.allclose(ik.lengths, lengths, rtol=0, atol=1e-12)
    assert np.allclose(ik.structure_matrix, W, rtol=0, atol=1e-12)


@settings(max_examples=30, deadline=None)
@given(st.floats(-0.5, 0.5), st.floats(-0.5, 0.5), angles)
def test_planar_1r2t(x, y, theta):
    robot = read("planar_1r2t.wcrfx")
    assert (robot.dimension, robot.platform.kind) == (2, "rigid")
    ik = inverse_kinematics(robot, [x, y, theta])
    lengths, W = wirex_standard_model("planar_1r2t.wcrfx", np.array([x, y, 0.0]), rz(theta))
    assert np.allclose(ik.lengths, lengths, rtol=0, atol=1e-12)
    assert np.allclose(ik.structure_matrix, W[[0, 1, 5]], rtol=0, atol=1e-12)


@settings(max_examples=30, deadline=None)
@given(st.floats(0.3, 1.7), st.floats(0.3, 1.7), st.floats(0.2, 1.5))
@pytest.mark.parametrize("name", ["point_2t.wcrfx", "point_3t.wcrfx"])
def test_translating_patterns(name, x, y, z):
    """2T and 3T: a point mass whose exits absorb the anchor offsets, exactly WireX's lengths."""
    robot = read(name)
    d = robot.dimension
    assert robot.platform.kind == "point-mass" and d == (2 if name == "point_2t.wcrfx" else 3)
    r = np.array([x, y, z if d == 3 else 0.0])
    ik = inverse_kinematics(robot, r[:d])
    lengths, W = wirex_standard_model(name, r, np.eye(3))
    assert np.allclose(ik.lengths, lengths, rtol=0, atol=1e-12)
    assert np.allclose(ik.structure_matrix, W[:d], rtol=0, atol=1e-12)


# ---- mass properties, bounds, names ----------------------------------------------------------


def test_spatial_mass_properties_and_loads():
    robot = read("spatial_3r3t.wcrfx")
    tensor = raw("spatial_3r3t.wcrfx").find("platform/inertiatensor")
    I = np.array([[float(tensor.get(f"I{r}{c}")) for c in "xyz"] for r in "xyz"])
    assert robot.platform.mass == 4.5
    assert np.array_equal(robot.inertia, I)
    assert robot.platform.wrench_point == (0.01, -0.02, 0.03)
    assert np.array_equal(robot.weight, [0, 0, -4.5 * 9.81])  # WireX: 9.81 along -z
    assert all(c.tension == (5.0, 500.0) for c in robot.cables)
    assert [c.name for c in robot.cables] == [f"chain {i}" for i in range(1, 9)]
    assert robot.name == "spatial fixture" and "by taut tests" in robot.source


def test_planar_mass_properties():
    robot = read("planar_1r2t.wcrfx")
    assert robot.platform.inertia == (0.0125,) and robot.platform.wrench_point == (0.02, -0.01)
    assert np.array_equal(robot.weight, [0.0, 0.0]), "WireX's gravity is normal to the xy plane"
    assert robot.exits.tolist()[0] == [-1.0, -1.0] and robot.anchors.tolist()[0] == [-0.1, -0.05]
    assert "no in-plane weight" in robot.description


def test_incomplete_tensor_and_missing_loads_are_stated():
    robot = read("IPAnema.wcrfx")
    assert robot.platform.mass == 25.0 and robot.platform.inertia is None
    assert "Inertia tensor not imported" in robot.description and "gives Ixx" in robot.description
    assert "no <application> cable loads" in robot.description
    assert all(c.tension == (0.0, math.inf) for c in robot.cables)
    assert all(c.tension == (40.0, 1000.0) for c in read("CableMasterRobot.wcrfx").cables)


@pytest.mark.parametrize(
    "name, words",
    [
        ("line_1t.wcrfx", "motion pattern 1T (a point moving on a line) has no taut platform"),
        ("five_dof_2r3t.wcrfx", "motion pattern 2R3T (5 degrees of freedom"),
        ("beam_2r3t.wcrfx", "motion pattern 2R3T (5 degrees of freedom"),
    ],
)
def test_unrepresentable_motion_patterns(name, words):
    with pytest.raises(UnsupportedRobotError) as err:
        read_wirex(FIXTURES / name, pulleys="points")
    message = str(err.value)
    assert words in message and "\n" not in message
    assert ("across the line" in message) if "1T" in words else ("wrench-closure" in message)


def test_a_2r3t_beam_read_as_3r3t_is_not_the_2r3t_robot():
    """Why 2R3T is refused: the beam's file read as taut's 6-DOF platform has WireX's lengths,
    unchanged by the rotation ``a`` about the beam (the body x axis: ``R = Rz(c) Ry(b) Rx(a)``),
    but its structure matrix has rank 5, the moment about the beam zero in every column, so no
    pose of it is wrench-closed in six dimensions, whatever the cables."""
    import dataclasses

    from taut.model._wirex import parse_wirex, wirex_robot

    model = parse_wirex((FIXTURES / "beam_2r3t.wcrfx").read_bytes())
    robot = wirex_robot(dataclasses.replace(model, motion_pattern="3R3T"), pulleys="points")
    rng = np.random.default_rng(5)
    for _ in range(50):
        position, (a, b, c) = rng.uniform([-0.5, -0.4, 0.6], [0.5, 0.4, 1.4]), rng.uniform(-0.5, 0.5, 3)
        lengths, W = wirex_standard_model("beam_2r3t.wcrfx", position, rz(c) @ ry(b) @ rx(a))
        turned = inverse_kinematics(robot, [[*position, a, b, c], [*position, a + 1.0, b, c]])
        assert np.allclose(turned.lengths, lengths, rtol=0, atol=1e-12)
        assert np.allclose(turned.structure_matrix[0], W, rtol=0, atol=1e-12)
        axis = rz(c) @ ry(b) @ rx(a) @ [1.0, 0.0, 0.0]
        assert np.allclose(axis @ W[3:], 0.0, atol=1e-12)
        assert np.linalg.matrix_rank(W) == 5


def test_load_robot_reads_wcrfx():
    assert load_robot(FIXTURES / "spatial_3r3t.wcrfx") == read_wirex(FIXTURES / "spatial_3r3t.wcrfx")
    cogiro = load_robot(FIXTURES / "CoGiRo.wcrfx")
    assert cogiro == read_wirex(FIXTURES / "CoGiRo.wcrfx") and cogiro.swivel_cables == tuple(range(8))
    with pytest.raises(UnsupportedRobotError, match="leaves the xy plane"):
        load_robot(FIXTURES / "no_radius_2t.wcrfx")


# ---- bad files ---------------------------------------------------------------------------------

SPATIAL = (FIXTURES / "spatial_3r3t.wcrfx").read_text()
PLANAR = (FIXTURES / "planar_1r2t.wcrfx").read_text()
CHAIN1 = '<chain id="1"><base x="-1.5" y="-1.0" z="2.0" a11="0" a12="-1" a13="0" a21="1" a22="0" a23="0" a31="0" a32="0" a33="1" radius="0"/><platform x="-0.2" y="-0.1" z="0.05"/></chain>'


def changed(old: str, new: str, text: str = SPATIAL) -> str:
    assert old in text
    return text.replace(old, new, 1)


@pytest.mark.parametrize(
    "text, kind, words",
    [
        (SPATIAL[:-40], RobotFileError, "not well-formed XML at line"),
        ("", RobotFileError, "not well-formed XML"),
        ('<?xml version="1.0"?><!DOCTYPE m [<!ENTITY a "aaaa">]><models/>', RobotFileError, "document type"),
        ("<robot/>", RobotFileError, "root element is <robot>"),
        ("<models/>", RobotFileError, "<models>: element <robot> is missing"),
        (
            changed('<base x="1.5" y="1.0" z="2.0"', '<base x="nan" y="1.0" z="2.0"'),
            RobotFileError,
            'chain id="3"> <base> x: expected a finite number',
        ),
        (changed('<base x="1.5" y="1.0" z="2.0"', '<base x="1e400" y="1.0" z="2.0"'), RobotFileError, "finite number"),
        (
            changed('<base x="1.5" y="1.0" z="2.0"', '<base x="one" y="1.0" z="2.0"'),
            RobotFileError,
            "expected a number, got 'one'",
        ),
        (
            changed(' y="1.0" z="2.0" radius="0"/>', ' z="2.0" radius="0"/>'),
            RobotFileError,
            'chain id="3"> <base>: attribute y is missing',
        ),
        (
            changed('<platform x="0.2" y="0.1" z="-0.05"/>', ""),
            RobotFileError,
            'chain id="7">: element <platform> is missing',
        ),
        (changed('<chain id="2">', '<chain id="1">'), RobotFileError, 'chain id="1"> appears twice'),
        (changed('<chain id="2">', '<chain id="two">'), RobotFileError, "id must be an integer"),
        (changed('a11="0.6"', 'a11="0.7"'), RobotFileError, "not a rotation matrix"),
        (changed(' a13="0" a21="0.8"', ' a21="0.8"'), RobotFileError, "frame entries a13 are missing"),
        (changed('radius="0"', 'radius="-0.1"'), RobotFileError, "radius must be >= 0"),
        (changed('motionpattern="3R3T"', 'motionpattern="6DOF"'), RobotFileError, "unknown motion pattern '6DOF'"),
        (changed('mass="4.5"', 'mass="-1"'), RobotFileError, "mass: expected a mass >= 0"),
        (changed('Iyx="-0.01"', 'Iyx="0.01"'), RobotFileError, "inertiatensor>: not symmetric"),
        (changed('Iyy="0.25"', 'Iyy="-2"'), RobotFileError, "positive semi-definite"),
        (
            changed('min_cable_load="5"', 'min_cable_load="600"'),
            RobotFileError,
            "min_cable_load 600.0 > max_cable_load 500.0",
        ),
        (changed('min_cable_load="5"', 'min_cable_load="-5"'), RobotFileError, "min_cable_load: expected a load >= 0"),
        (
            changed("<geometry>", "<geometry><!-- no chains -->").split("<chain")[0] + "</geometry></robot></models>",
            RobotFileError,
            "no <chain> elements",
        ),
        (changed(CHAIN1, CHAIN1 + CHAIN1.replace('id="1"', 'id="9"')), RobotFileError, "same exit point and anchor"),
        (
            changed('<base x="1.0" y="-1.0" z="0.5"', '<base x="1.0" y="-1.0" z="0.7"', PLANAR),
            UnsupportedRobotError,
            'chain id="2">: motion pattern 1R2T moves in the xy plane',
        ),
    ],
)
def test_bad_files(tmp_path, text, kind, words):
    path = tmp_path / "bad.wcrfx"
    path.write_text(text)
    with pytest.raises(kind) as err:
        read_wirex(path, pulleys="points")
    message = str(err.value)
    assert words in message and message.startswith(str(path)) and "\n" not in message


def test_entity_in_another_encoding_is_refused(tmp_path):
    """The refusal looks at the parsed document, not the bytes: UTF-16 does not slip through."""
    path = tmp_path / "wide.wcrfx"
    path.write_text(
        '<?xml version="1.0" encoding="UTF-16"?><!DOCTYPE m [<!ENTITY a "a">]><models>&a;</models>', encoding="utf-16"
    )
    with pytest.raises(RobotFileError, match="document type"):
        read_wirex(path)


def test_not_a_regular_file(tmp_path):
    (tmp_path / "dir.wcrfx").mkdir()
    with pytest.raises(RobotFileError, match="not a regular file"):
        read_wirex(tmp_path / "dir.wcrfx")


# ---- writer: round trips ------------------------------------------------------------------------

#: The built-in examples a WireX file holds; the others have jointed platforms, obstacles,
#: pulleys, shapes, length bounds, other angle conventions or upward loads.
WRITABLE = {"camera-4cable", "cogiro", "marionet-vr", "printer-5cable", "teaching-prototype"}


def random_poses(robot: taut.Robot, count: int = 50) -> np.ndarray:
    rng = np.random.default_rng(7)
    centre = robot.exits.mean(axis=0)
    spread = 0.2 * np.ptp(robot.exits, axis=0)
    positions = centre + rng.uniform(-1, 1, (count, robot.dimension)) * spread
    angles = rng.uniform(-0.3, 0.3, (count, robot.wrench_dim - robot.dimension))
    return np.hstack([positions, angles])


def assert_same_robot(a: taut.Robot, b: taut.Robot) -> None:
    assert (a.dimension, a.platform.kind, a.name) == (b.dimension, b.platform.kind, b.name)
    assert np.array_equal(a.exits, b.exits) and np.array_equal(a.anchors, b.anchors)
    assert all(np.array_equal(x, y) for x, y in zip(a.tension_bounds, b.tension_bounds, strict=True))
    poses = random_poses(a)
    assert np.allclose(inverse_kinematics(a, poses).lengths, inverse_kinematics(b, poses).lengths, rtol=0, atol=1e-12)
    assert np.allclose(external_wrench(a, poses), external_wrench(b, poses), rtol=1e-15, atol=1e-15)


@pytest.mark.parametrize("name", taut.example_names())
def test_round_trip_of_examples(tmp_path, name):
    robot = taut.example(name)
    path = tmp_path / f"{name}.wcrfx"
    if name not in WRITABLE:
        with pytest.raises(UnsupportedRobotError, match=f"write_wirex: {robot.name}: .* has no WireX equivalent"):
            write_wirex(robot, path)
        assert not path.exists()
        return
    write_wirex(robot, path)
    back = read_wirex(path)
    assert_same_robot(robot, back)
    assert back.platform.wrench_point == robot.platform.wrench_point
    if robot.platform.wrench is None:  # the point masses: their mass under standard gravity
        assert back.platform.mass == robot.platform.mass
        return
    # the unit downward load becomes the weight of F / 9.81 kg at the same point
    assert back.platform.mass == pytest.approx(-robot.platform.wrench[2] / 9.81, rel=1e-15)


@pytest.mark.parametrize("name", OWN)
def test_round_trip_of_fixtures(tmp_path, name):
    robot = read(name)
    write_wirex(robot, tmp_path / name)
    back = read_wirex(tmp_path / name)
    assert_same_robot(robot, back)
    for field in ("mass", "wrench_point", "inertia", "gravity"):
        assert getattr(back.platform, field) == getattr(robot.platform, field)


@pytest.mark.parametrize("name", [*REAL, "pulleys_3r3t.wcrfx"])
def test_round_trip_keeps_swivels(tmp_path, name):
    """Swivels are written as winch frames with z = the unit axis and the pulley radius."""
    robot = read_wirex(FIXTURES / name)
    write_wirex(robot, tmp_path / name)
    back = read_wirex(tmp_path / name)
    assert_same_robot(robot, back)
    for a, b in zip(robot.cables, back.cables, strict=True):
        assert a.swivel.radius == b.swivel.radius
        axis = np.array(a.swivel.axis) / np.linalg.norm(a.swivel.axis)
        assert np.allclose(b.swivel.axis, axis, rtol=0, atol=1e-15)


def test_writer_refusals(tmp_path):
    planar = taut.example("planar-4cable").model_copy(update={"platform": {"kind": "rigid", "mass": 1.0}})
    with pytest.raises(UnsupportedRobotError, match="a weight in the plane"):
        write_wirex(planar, tmp_path / "p.wcrfx")
    cogiro = taut.example("cogiro")
    with pytest.raises(UnsupportedRobotError, match="orientation xyz-moving"):
        write_wirex(cogiro.model_copy(update={"orientation": "xyz-moving"}), tmp_path / "c.wcrfx")
    mixed = cogiro.model_copy(
        update={"cables": [*cogiro.cables[:-1], cogiro.cables[-1].model_copy(update={"tension": (1.0, 2.0)})]}
    )
    with pytest.raises(UnsupportedRobotError, match="different tension bounds"):
        write_wirex(mixed, tmp_path / "m.wcrfx")


coordinates = st.floats(-50, 50, allow_subnormal=False)


@settings(max_examples=40, deadline=None)
@given(
    st.lists(st.tuples(*[coordinates] * 6), min_size=1, max_size=9, unique_by=lambda t: t[:3]),
    st.floats(0.01, 100),
    st.lists(st.floats(-1, 1), min_size=9, max_size=9),
    st.tuples(*[coordinates] * 3),
    st.tuples(st.floats(0, 10), st.floats(10, 1e4)),
)
def test_round_trip_of_any_spatial_robot(tmp_path_factory, rows, mass, entries, center, tension):
    """Every number comes back bit for bit (the writer prints ``repr`` of each float)."""
    A = np.array(entries).reshape(3, 3)
    I = A @ A.T
    robot = taut.Robot.model_validate(
        {
            "name": "random",
            "dimension": 3,
            "platform": {
                "mass": mass,
                "wrench_point": center,
                "inertia": [I[0, 0], I[1, 1], I[2, 2], I[0, 1], I[0, 2], I[1, 2]],
            },
            "cables": [{"exit": r[:3], "anchor": r[3:], "tension": tension} for r in rows],
        }
    )
    path = tmp_path_factory.mktemp("wcrfx") / "random.wcrfx"
    write_wirex(robot, path)
    back = read_wirex(path)
    assert np.array_equal(back.exits, robot.exits) and np.array_equal(back.anchors, robot.anchors)
    assert back.platform.mass == mass and back.platform.wrench_point == robot.platform.wrench_point
    assert np.array_equal(back.inertia, robot.inertia)
    assert all(c.tension == tension for c in back.cables)
