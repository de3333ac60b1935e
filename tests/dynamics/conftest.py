"""Robots with full inertial data for the dynamics tests (the built-in examples give a mass
and a diagonal inertia), and one without inertia, built with ``model_copy(update=...)`` so
that they are validated."""

import numpy as np
import pytest

import taut

#: A spatial inertia about the centre of mass with products of inertia (Ixx, Iyy, Izz, Ixy, Ixz, Iyz).
SPATIAL_INERTIA = (0.12, 0.2, 0.15, 0.01, -0.02, 0.005)


def with_platform(robot, **fields):
    """``robot`` with the platform fields ``fields`` replaced."""
    return robot.model_copy(update={"platform": robot.platform.model_copy(update=fields)})


@pytest.fixture(scope="session")
def spatial():
    """spatial-8cable with an inertia tensor and the centre of mass off the reference point."""
    return with_platform(taut.example("spatial-8cable"), inertia=SPATIAL_INERTIA, wrench_point=(0.02, -0.01, 0.03))


@pytest.fixture(scope="session")
def no_inertia():
    """spatial-8cable with a mass but no inertia tensor: the rigid-body dynamics refuses it."""
    return with_platform(taut.example("spatial-8cable"), inertia=None)


@pytest.fixture(scope="session")
def spatial_centred():
    """spatial-8cable with an inertia tensor, centre of mass at the reference point."""
    return with_platform(taut.example("spatial-8cable"), inertia=SPATIAL_INERTIA)


@pytest.fixture(scope="session")
def loaded():
    """spatial-8cable with an inertia, an offset centre of mass and a constant external
    wrench (``platform.wrench``: a force at the centre of mass and a moment)."""
    return with_platform(
        taut.example("spatial-8cable"),
        inertia=SPATIAL_INERTIA,
        wrench_point=(0.02, -0.01, 0.03),
        wrench=(1.0, -2.0, 3.0, 0.1, 0.2, -0.3),
    )


@pytest.fixture(scope="session")
def planar():
    """planar-4cable with Izz and the centre of mass off the reference point."""
    return with_platform(taut.example("planar-4cable"), inertia=(0.004,), wrench_point=(0.01, -0.02))


@pytest.fixture(scope="session")
def planar_centred():
    return with_platform(taut.example("planar-4cable"), inertia=(0.004,))


@pytest.fixture(scope="session")
def point_mass():
    """A spatial point mass on 4 cables (suspended, like a camera crane)."""
    data = {
        "format": "taut/1",
        "name": "point mass",
        "dimension": 3,
        "platform": {"kind": "point-mass", "mass": 2.0},
        "cables": [
            {"exit": [x, y, 1.0], "anchor": [0, 0, 0], "tension": [0, 200]}
            for x, y in ((-1, -1), (1, -1), (1, 1), (-1, 1))
        ],
    }
    return taut.model.robot_from_dict(data)


@pytest.fixture(scope="session")
def planar_point():
    """A planar point mass on 3 cables, with a gravity that is not along an axis."""
    data = {
        "format": "taut/1",
        "name": "planar point mass",
        "dimension": 2,
        "platform": {"kind": "point-mass", "mass": 0.5, "gravity": [1.0, -9.0]},
        "cables": [{"exit": e, "tension": [0, 100]} for e in ([-1.0, 1.0], [1.0, 1.0], [0.0, -1.0])],
    }
    return taut.model.robot_from_dict(data)


@pytest.fixture
def rng():
    return np.random.default_rng(20261202)


@pytest.fixture
def random_state(rng):
    """``random_state(robot)``: a pose near the middle of the frame, away from the gimbal
    lock, and random pose rates and accelerations."""

    def make(robot, scale=0.2):
        n = robot.pose_size
        return rng.uniform(-scale, scale, n), rng.normal(0, 1, n), rng.normal(0, 1, n)

    return make
