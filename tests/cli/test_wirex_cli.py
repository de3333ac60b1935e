"""WireX ``.wcrfx`` files on the command line: ``taut ik`` and ``taut workspace`` read them
like taut's own files, and a bad or unsupported file exits 2 with one line."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

FIXTURES = Path(__file__).parents[1] / "model" / "fixtures" / "wirex"


def test_ik_of_a_wcrfx_file(taut_cli):
    """Lengths against the file's raw points at a pose with rotation Rz(0) Ry(0) Rx(0.3)."""
    path = FIXTURES / "spatial_3r3t.wcrfx"
    result = taut_cli("ik", str(path), "--pose", "0.1,0.2,1,0.3,0,0", "--json").json()
    chains = ET.parse(path).getroot().findall("robot/geometry/chain")
    base = np.array([[float(c.find("base").get(k)) for k in "xyz"] for c in chains])
    plat = np.array([[float(c.find("platform").get(k)) for k in "xyz"] for c in chains])
    c, s = math.cos(0.3), math.sin(0.3)
    R = np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
    expected = np.linalg.norm(base - [0.1, 0.2, 1.0] - plat @ R.T, axis=1)
    assert result["robot"] == "spatial fixture"
    assert np.allclose(result["lengths"], expected, rtol=0, atol=1e-12)


def test_workspace_of_a_wcrfx_file(taut_cli):
    result = taut_cli(
        "workspace",
        str(FIXTURES / "point_2t.wcrfx"),
        "--condition",
        "wrench-closure",
        "--grid",
        "0.2:1.8:5;0.2:1.8:5",
        "--json",
    ).json()
    assert result["robot"] == "planar point fixture" and result["poses"] == 25
    assert 0 < result["inside"] < 25  # the triangle of exit points holds some grid points, not all


def test_ik_of_wcrfx_pulleys(taut_cli):
    """IPAnema's pulleys are read as swivels: at (0, 0, 1) each cable's length is WireX's
    pulley length (``CKinematics::doInverseKinematicsPulleyEx``: the anchor at ``bxy`` from
    the winch z axis and ``bz`` along it, ``BM = ‖(bxy − r, bz)‖``, ``l_f = √(BM² − r²)``,
    ``l = r (acos(l_f/BM) + acos(bz/BM)) + l_f``), with r = 0.1."""
    path = FIXTURES / "IPAnema.wcrfx"
    result = taut_cli("ik", str(path), "--pose", "0,0,1,0,0,0", "--json").json()
    chains = ET.parse(path).getroot().findall("robot/geometry/chain")
    base = np.array([[float(c.find("base").get(k)) for k in "xyz"] for c in chains])
    plat = np.array([[float(c.find("platform").get(k)) for k in "xyz"] for c in chains])
    ap = plat + [0, 0, 1] - base
    bxy, bz, r = np.hypot(ap[:, 0], ap[:, 1]), ap[:, 2], 0.1
    bm = np.hypot(bxy - r, bz)
    lf = np.sqrt(bm**2 - r**2)
    assert np.allclose(result["lengths"], r * (np.arccos(lf / bm) + np.arccos(bz / bm)) + lf, rtol=0, atol=1e-12)


@pytest.mark.slow
def test_ik_and_workspace_of_planar_wcrfx_pulleys(taut_cli):
    """In-plane pulleys of a 2T file: WireX's pulley lengths with the swivel axis ``k`` (the
    winch frame's z axis, in the plane): ``bz = k·(r + b − a)``, ``bxy`` the rest."""
    path = FIXTURES / "planar_pulleys_2t.wcrfx"
    result = taut_cli("ik", str(path), "--pose", "1.1,0.9", "--json").json()
    chains = ET.parse(path).getroot().findall("robot/geometry/chain")
    base = np.array([[float(c.find("base").get(k)) for k in "xyz"] for c in chains])
    plat = np.array([[float(c.find("platform").get(k)) for k in "xyz"] for c in chains])
    axes = np.array([[float(c.find("base").get(f"a{i}3")) for i in (1, 2, 3)] for c in chains])
    r = np.array([float(c.find("base").get("radius")) for c in chains])
    ap = plat + [1.1, 0.9, 0] - base
    bz = np.einsum("ij,ij->i", ap, axes)
    bxy = np.linalg.norm(ap - bz[:, None] * axes, axis=1)
    bm = np.hypot(bxy - r, bz)
    lf = np.sqrt(bm**2 - r**2)
    assert np.allclose(result["lengths"], r * (np.arccos(lf / bm) + np.arccos(bz / bm)) + lf, rtol=0, atol=1e-12)
    space = taut_cli(
        "workspace", str(path), "--condition", "wrench-closure", "--grid", "0.3:1.7:5;0.3:1.7:5", "--json"
    ).json()
    assert space["poses"] == 25 and 0 < space["inside"] < 25


def test_workspace_of_wcrfx_pulleys(taut_cli):
    result = taut_cli(
        "workspace",
        str(FIXTURES / "IPAnema.wcrfx"),
        "--condition",
        "wrench-closure",
        "--grid",
        "4",
        "--orientation",
        "0,0,0",
        "--json",
    ).json()
    assert result["robot"] == "IPAnema" and result["poses"] == 64
    assert 0 < result["inside"] < 64


@pytest.mark.parametrize(
    "name, words",
    [
        (
            "no_radius_2t.wcrfx",
            "turns about the winch frame's z axis (0, 0, 1), which leaves the xy plane of motion of 2T",
        ),
        ("line_1t.wcrfx", "motion pattern 1T (a point moving on a line) has no taut platform"),
        ("five_dof_2r3t.wcrfx", "motion pattern 2R3T"),
    ],
)
def test_unsupported_files_exit_2(taut_cli, name, words):
    run = taut_cli("ik", str(FIXTURES / name), "--pose", "0,0,1,0,0,0")
    assert run.code == 2 and run.out == ""
    assert run.err.startswith("taut: error: ") and words in run.err and run.err.count("\n") == 1


def test_malformed_file_exits_2(taut_cli, tmp_path):
    path = tmp_path / "broken.wcrfx"
    path.write_text((FIXTURES / "spatial_3r3t.wcrfx").read_text().replace('z="2.0" a11="0.6"', 'z="nan" a11="0.6"'))
    run = taut_cli("workspace", str(path), "--condition", "wrench-closure", "--grid", "3", "--json")
    assert run.code == 2 and run.out == ""
    assert run.err == f"taut: error: {path}: <chain id=\"2\"> <base> z: expected a finite number, got 'nan'\n"
