"""The slice map of a wrench-feasible manifold (Fig. 5 of Bohigas et al. 2013):
``taut.planning.slice_map``."""

import numpy as np
import pytest

from taut.errors import PoseError, TautError
from taut.model import load_robot
from taut.planning import SliceMap, slice_map
from taut.planning._manifold import WrenchFeasibleManifold

ROBOT = load_robot("robocrane")
Q1 = np.array(ROBOT.reference.poses["q1"])


def test_slice_map_classifies_like_the_manifold():
    M = WrenchFeasibleManifold.from_robot(ROBOT)
    grid = slice_map(M, Q1, resolution=(24, 12))
    assert grid.axes == ("phi", "theta")
    u, v, cls = grid.u, grid.v, grid.classes
    assert cls.shape == (24, 12) and u[0] == -np.pi and v[-1] == np.pi
    for i, j in np.ndindex(cls.shape):
        q = Q1.copy()
        q[3], q[4] = u[i], v[j]
        try:
            M.lift(q)
            ok = True
        except Exception:
            ok = False
        assert ok == (cls[i, j] == SliceMap.FEASIBLE)
    assert (cls == SliceMap.FEASIBLE).any() and (cls != SliceMap.FEASIBLE).any()
    # lengths: at z = 4.9 cables are longer than 5a = 5 somewhere
    far = slice_map(M, np.r_[0, 0, 4.9, Q1[3:]], resolution=(8, 6)).classes
    assert (far == SliceMap.LENGTH_OUT).any()


def test_slice_map_is_a_read_only_result_with_a_plain_dict():
    M = WrenchFeasibleManifold.from_robot(ROBOT)
    grid = slice_map(M, Q1, axes=("theta", "phi"), resolution=(3, 4))
    assert grid.classes.shape == (3, 4) and not grid.classes.flags.writeable
    d = grid.as_dict()
    assert d["axes"] == ["theta", "phi"] and np.array_equal(d["classes"], grid.classes)
    assert d["u"] == pytest.approx(np.linspace(0.0, np.pi, 3).tolist())


def test_position_axes_take_their_default_limits_from_span():
    M = WrenchFeasibleManifold.from_robot(ROBOT)
    span = np.array([np.r_[0.0, 0.0, 2.0, Q1[3:]], np.r_[0.5, 0.0, 2.0, Q1[3:]]])
    with pytest.raises(TautError, match="limits for x"):
        slice_map(M, Q1, axes=("x", "phi"), resolution=(2, 2))
    grid = slice_map(M, Q1, axes=("x", "phi"), span=span, resolution=(2, 2))
    assert (grid.u[0], grid.u[-1]) == pytest.approx((-0.1, 0.6))  # padded by a tenth, at least 0.1


def test_bad_axes_and_poses_are_refused():
    M = WrenchFeasibleManifold.from_robot(ROBOT)
    for axes in (("phi",), ("phi", "phi"), ("phi", "psi")):
        with pytest.raises(PoseError, match="two distinct pose coordinates"):
            slice_map(M, Q1, axes=axes)
    with pytest.raises(PoseError, match="a pose is"):
        slice_map(M, Q1[:5])
