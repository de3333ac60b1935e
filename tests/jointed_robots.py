"""Jointed robots shared by the MuJoCo-export and dynamics tests: built-in and real CASPR
models given link masses, a branching body tree and a planar slider with an arm."""

from pathlib import Path

import taut
from taut.model import load_robot, robot_from_dict, robot_to_dict

SPIDERBOT = Path(__file__).parent / "model" / "fixtures" / "caspr" / "real" / "SpiderBot_UR3_bodies.xml"
#: CASPR's universal, spherical and planar-translation joints: chains of one-DOF joints through
#: massless joint frames.
MULTIDOF = Path(__file__).parent / "model" / "fixtures" / "caspr" / "multidof_bodies.xml"


def adjustable():
    """The built-in adjustable-8cable, with its assumed masses (Lieskovský 2020 gives none): a
    20 kg lower body and an 8 kg upper body, their centres of mass off the joint axis, with
    products of inertia."""
    return taut.example("adjustable-8cable")


def branching():
    """adjustable() with two more bodies, so that the body tree branches and MuJoCo's joint
    order (depth first) differs from taut's: ``side`` turns on the platform about a tilted
    axis, ``tip`` slides along a tilted axis on ``upper``; cables 7 and 8 hang from them."""
    data = robot_to_dict(adjustable())
    data.pop("trajectories")
    data.pop("reference")
    data["platform"]["bodies"] += [
        {
            "name": "side",
            "joint": {"kind": "revolute", "axis": [1, 2, 2], "origin": [0.3, -0.2, 0.5], "limits": [-1.2, 2.0]},
            "mass": 3.0,
            "com": [0.4, 0.1, -0.2],
            "inertia": [0.5, 0.6, 0.7, 0.01, 0.02, -0.03],
        },
        {
            "name": "tip",
            "parent": "upper",
            "joint": {"kind": "prismatic", "axis": [0.2, -0.1, 1], "origin": [0.1, 0.0, 0.3], "limits": [-0.5, 0.8]},
            "mass": 1.5,
            "com": [0.0, 0.2, 0.1],
            "inertia": [0.2, 0.2, 0.3, 0.0, 0.0, 0.0],
        },
    ]
    data["cables"][6]["body"] = "side"
    data["cables"][7]["body"] = "tip"
    return robot_from_dict(data)


def planar():
    """planar-4cable carrying a slider and, on it, an arm turning in the plane; cables 3 and 4
    pull them."""
    data = robot_to_dict(taut.example("planar-4cable"))
    data.pop("reference")
    data["platform"]["bodies"] = [
        {
            "name": "slider",
            "joint": {"kind": "prismatic", "axis": [1, 1], "origin": [0.05, 0.0], "limits": [-0.1, 0.1]},
            "mass": 0.4,
            "com": [0.02, 0.01],
            "inertia": [0.002],
        },
        {
            "name": "arm",
            "parent": "slider",
            "joint": {"kind": "revolute", "axis": [1], "origin": [0.0, 0.04], "limits": [-2.5, 2.5]},
            "mass": 0.3,
            "com": [0.05, 0.0],
            "inertia": [0.001],
        },
    ]
    data["cables"][2]["body"] = "slider"
    data["cables"][3]["body"] = "arm"
    return robot_from_dict(data)


ROBOTS = {
    "adjustable-8cable": adjustable,
    "SpiderBot_UR3": lambda: load_robot(SPIDERBOT),
    "CASPR multi-DOF joints": lambda: load_robot(MULTIDOF),
    "branching tree": branching,
    "planar slider and arm": planar,
}
