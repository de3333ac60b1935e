"""docs/architecture.md §2.7: results are frozen, their arrays read-only, ``as_dict()`` plain JSON."""

import dataclasses
import functools
import json
import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from taut._results import Result, freeze, jsonable
from taut.errors import TautError


@dataclasses.dataclass(frozen=True)
class Sample(Result):
    values: np.ndarray
    cables: tuple[int, ...]
    parts: tuple[np.ndarray, ...] = ()
    label: str = "x"
    count: int = 0


def test_arrays_are_read_only_and_the_callers_array_is_untouched():
    own = np.arange(3.0)
    r = Sample(own, (0, 2), parts=(np.ones(2), np.zeros(1)))
    with pytest.raises(ValueError):
        r.values[0] = 5.0
    with pytest.raises(ValueError):
        r.parts[0][0] = 5.0
    with pytest.raises(dataclasses.FrozenInstanceError):
        r.values = np.zeros(3)  # type: ignore[misc]
    own[0] = 7.0  # the caller's array stays writeable
    assert own.flags.writeable


def test_freeze_on_a_plain_dataclass():
    @dataclasses.dataclass
    class Plain:
        a: np.ndarray
        b: list

    p = Plain(np.zeros(2), [(np.zeros(1), np.ones(1)), (np.ones(1), np.ones(2))])
    freeze(p)
    assert not p.a.flags.writeable
    assert isinstance(p.b, tuple) and not any(x.flags.writeable for box in p.b for x in box)


def test_as_dict_types():
    r = Sample(np.array([[1.0, np.nan], [np.inf, -2.5]]), (1, 3), label="lp", count=np.int64(4))
    d = r.as_dict()
    assert d == {"values": [[1.0, None], [None, -2.5]], "cables": [1, 3], "parts": [], "label": "lp", "count": 4}
    assert type(d["count"]) is int
    json.dumps(d, allow_nan=False)


def test_nested_results_use_their_as_dict():
    @dataclasses.dataclass(frozen=True)
    class Outer(Result):
        inner: Sample
        flags: np.ndarray

    o = Outer(Sample(np.zeros(1), ()), np.array([True, False]))
    assert o.as_dict() == {
        "inner": {"values": [0.0], "cables": [], "parts": [], "label": "x", "count": 0},
        "flags": [True, False],
    }


def test_no_json_form_is_a_taut_error():
    with pytest.raises(TautError, match="function"):
        jsonable({"f": lambda: 0})


@given(arrays(np.float64, st.integers(0, 6)))
def test_round_trip(values):
    d = Sample(values, (0,)).as_dict()
    back = json.loads(json.dumps(d, allow_nan=False))["values"]
    expected = [float(v) if math.isfinite(v) else None for v in values]
    assert back == expected


# ---- every exported result ---------------------------------------------------------------

#: Exported frozen dataclasses that are not results: what a caller builds and passes in (a
#: problem, a model, a set of wrenches), not what a computation returns.
NOT_RESULTS = {
    "dynamics.LoopModel",  # the closed-loop model simulate_control integrates
    "interval.System",  # a compiled system of equations, the input of the solvers
    "interval.Tape",  # the compiled expressions of a system
    "planning.ImplicitManifold",  # the manifold a planner searches (callables)
    "planning.Symmetry",  # a manifold's symmetry (callables)
    "planning.ManifoldChart",  # a chart of the atlas a planner grows in place
    "planning.WrenchFeasibleManifold",  # the planning problem of a robot
    "statics.SingleWrench",
    "statics.BoxWrenchSet",
    "statics.PolytopeWrenchSet",
    "statics.EllipsoidWrenchSet",
}

#: Results of work a budget or a failure can cut short: each says how long it took and
#: whether it is whole.
PARTIAL = {
    "atlas.StructureAtlas",
    "dgp.DGPResult",
    "dgp.IGPResult",
    "dynamics.ControlResult",
    "dynamics.ForwardDynamicsResult",
    "interval.BranchAndPruneResult",
    "planning.PathResult",
    "workspace.CertifiedWorkspace",
    "workspace.WorkspaceResult",
}


def _exported_classes() -> dict[str, type]:
    import importlib
    import inspect
    import pkgutil

    import taut

    out = {}
    for info in pkgutil.iter_modules(taut.__path__):
        if info.name.startswith("_"):
            continue
        module = importlib.import_module(f"taut.{info.name}")
        for name in getattr(module, "__all__", ()):
            obj = getattr(module, name)
            if inspect.isclass(obj):
                out[f"{info.name}.{name}"] = obj
    return out


EXPORTED = _exported_classes()
RESULTS = sorted(k for k, c in EXPORTED.items() if issubclass(c, Result))


def test_every_exported_dataclass_is_a_frozen_result():
    """A result class that does not derive Result would escape the conventions unnoticed."""
    for key, cls in EXPORTED.items():
        if dataclasses.is_dataclass(cls) and key not in NOT_RESULTS or key.endswith("Result"):
            assert issubclass(cls, Result), f"{key} does not derive taut._results.Result"
        if issubclass(cls, Result):
            assert dataclasses.is_dataclass(cls) and cls.__dataclass_params__.frozen, f"{key} is not frozen"
    assert NOT_RESULTS <= EXPORTED.keys(), NOT_RESULTS - EXPORTED.keys()


@pytest.mark.parametrize("key", sorted(PARTIAL))
def test_partial_work_reports_elapsed_s_and_complete(key):
    cls = EXPORTED[key]
    names = {f.name for f in dataclasses.fields(cls)} | {n for n in dir(cls) if isinstance(getattr(cls, n), property)}
    assert {"elapsed_s", "complete"} <= names, key


@functools.cache
def _atlas():
    from taut.atlas import build_atlas
    from taut.model import example

    robot = example("vscr-t-shaped")
    return build_atlas(robot, robot.reference.poses["initial"])


@functools.cache
def _dgp():
    from taut.dgp import solve_dgp
    from taut.model import example

    return solve_dgp(example("suspended-3cable"), max_boxes=3000)


@functools.cache
def _igp():
    from taut.dgp import solve_igp
    from taut.model import example

    return solve_igp(example("suspended-3cable"), [0, 1, 2], {"x": 2.7505, "y": 3.9798, "z": 5.5061})


def _caspr(tmp_path):
    from taut.model import example, write_caspr
    from taut.motion import read_caspr_trajectories

    write_caspr(example("planar-4cable"), tmp_path / "planar_bodies.xml")
    (tmp_path / "planar_trajectories.xml").write_text(
        '<trajectories><joint_trajectories><linear_spline_trajectory id="move" time_definition="relative" '
        'time_step="0.5"><points><point><q>0 0 0</q></point><point time="2"><q>0.2 0.1 0</q></point></points>'
        "</linear_spline_trajectory></joint_trajectories></trajectories>"
    )
    return read_caspr_trajectories(tmp_path / "planar_trajectories.xml")[1]["move"]


def _motion():
    from taut.model import example
    from taut.motion import trajectory_from_waypoints

    return trajectory_from_waypoints(example("planar-4cable"), [[0, 0, 0], [0.2, 0.1, 0]], durations=[2.0])


def _tree():
    from taut.wrapping import CableStateTree

    return CableStateTree([[0.0, 1.0, 0.2], [0.0, 0.0, 0.0]])


def _point_mass_fit():
    from taut.dgp import solve_dgp
    from taut.model import example

    return solve_dgp(example("camera-4cable")).least_squares


def _example(name):
    from taut.model import example

    return example(name)


def _calibration():
    from taut.calibration import calibrate, simulate_measurements
    from taut.model import example

    robot = example("printer-5cable")
    poses = [
        [x, y, z]
        for x, y, z in zip(
            [-0.5, 0.4, 0.0, 0.3, -0.3, 0.5], [-0.4, 0.3, 0.5, -0.5, 0.1, 0.0], [0.5, 1.5, 1.0, 0.8, 1.3, 0.6]
        )
    ]
    return calibrate(robot, simulate_measurements(robot, poses, offsets=[1.0] * 5, sigma=1e-4, seed=0))


def _result(key, tmp_path):
    """A small instance of the exported result class ``key``, from a public function."""
    import taut.atlas as atlas
    import taut.cables as cables
    import taut.calibration as calibration
    import taut.collision as collision
    import taut.dynamics as dynamics
    import taut.interval as interval
    import taut.kinematics as kinematics
    import taut.motion as motion
    import taut.planning as planning
    import taut.statics as statics
    import taut.workspace as workspace
    import taut.wrapping as wrapping

    planar, adjustable, crane = (_example(n) for n in ("planar-4cable", "adjustable-8cable", "robocrane"))
    sim_b = collision.trajectory_poses(adjustable, "sim-b")[120:130]
    x, y = interval.variables(2)
    factories = {
        "atlas.AtlasIK": lambda: atlas.direct_ik(_atlas(), [_atlas().start]),
        "atlas.AtlasWorkspace": lambda: atlas.atlas_workspace(_atlas(), "static", step=0.1),
        "atlas.Edge": lambda: _atlas().edges[0],
        "atlas.StructureAtlas": _atlas,
        "atlas.StructureChart": lambda: _atlas().charts[0],
        "cables.Catenary": lambda: cables.catenary_forces([10.0, 8.0], [0.0, 2.0], [10.05, 8.5], 10.0, 2e5),
        "cables.SaggingFKResult": lambda: cables.sagging_fk(
            _example("cogiro-sagging"),
            cables.sagging_ik(
                _example("cogiro-sagging"), [0.0, 0.0, 2.0, 0.0, 0.0, 0.0], method="qp"
            ).unstrained_lengths,
        ),
        "cables.SaggingIKResult": lambda: cables.sagging_ik(
            _example("cogiro-sagging"), [[0.0, 0.0, 2.0, 0.0, 0.0, 0.0], [6.5, 4.5, 5.0, 0.0, 0.0, 0.0]]
        ),
        "calibration.CalibrationResult": _calibration,
        "calibration.Identifiability": lambda: _calibration().identifiability,
        "calibration.Measurements": lambda: calibration.measurements(
            _example("planar-4cable"), [[1.0, None, 1.2, 1.3]]
        ),
        "calibration.PosePlan": lambda: calibration.plan_poses(_example("printer-5cable"), 10),
        "collision.CapsuleModel": lambda: collision.capsule_model(adjustable),
        "collision.CheckResult": lambda: collision.check_poses(adjustable, sim_b),
        "collision.ProximityResult": lambda: collision.proximity(adjustable, sim_b),
        "dgp.DGPResult": _dgp,
        "dgp.DGPSolution": lambda: _dgp().solutions[0],
        "dgp.IGPResult": _igp,
        "dgp.LeastSquaresFit": _point_mass_fit,
        "dgp.IGPSolution": lambda: _igp().solutions[0],
        "dgp.UndecidedBox": lambda: _dgp().undecided_enclosures[0],
        "dynamics.ControlResult": lambda: dynamics.simulate_control(planar, _motion(), rate_hz=20),
        "dynamics.ForwardDynamicsResult": lambda: dynamics.forward_dynamics(
            planar, np.zeros(3), np.zeros(3), 0.1, tensions=lambda t: np.zeros(4), method="RK4", step=0.05
        ),
        "dynamics.InverseDynamicsResult": lambda: dynamics.inverse_dynamics(
            planar, np.zeros(3), np.zeros(3), [0.0, 400.0, 0.0], method="qp"
        ),
        "dynamics.PlatformDynamics": lambda: dynamics.platform_dynamics(planar),
        "dynamics.WrenchSteps": lambda: dynamics.WrenchSteps.step(1.0, [5.0, 0.0, 0.0], end=2.0),
        "interval.BranchAndPruneResult": lambda: interval.branch_and_prune(
            interval.compile_system(1, [x**2 - 2]), [0.0], [2.0]
        ),
        "interval.Certificate": lambda: interval.certify(
            interval.compile_system(2, [x**2 + y**2 - 1, (x - 1) ** 2 + y**2 - 1]), [0.4, 0.8]
        ),
        "kinematics.FKResult": lambda: kinematics.forward_kinematics(
            planar, kinematics.cable_lengths(planar, [0.1, -0.05, 0.1])
        ),
        "kinematics.IKResult": lambda: kinematics.inverse_kinematics(planar, [[0.0, 0.0, 0.0], [0.1, 0.0, 0.2]]),
        "kinematics.SwivelPaths": lambda: kinematics.swivel_paths([[0, 0, 0]], [[0, 0, 1]], [0.1], [[[1.0, 0, 0]]]),
        "motion.CasprTrajectory": lambda: _caspr(tmp_path),
        "motion.Motion": _motion,
        "motion.MotionSamples": lambda: _motion().at([0.0, 1.0, 2.0]),
        "motion.RobotTrajectory": lambda: motion.robot_trajectory(adjustable, "sim-a"),
        "planning.PathCheck": lambda: planning.verify_path(
            crane, list(crane.reference.poses.values())[:2], subdivide=3
        ),
        "planning.PathResult": lambda: planning.plan_path(
            planning.ImplicitManifold(lambda p: np.array([p @ p - 1]), lambda p: 2 * p[None, :], 2),
            [1.0, 0, 0],
            [0, 1.0, 0],
            radius=0.3,
        ),
        "planning.SliceMap": lambda: planning.slice_map(
            planning.WrenchFeasibleManifold.from_robot(crane), crane.reference.poses["q1"], resolution=(4, 3)
        ),
        "statics.TensionResult": lambda: statics.distribute_tensions(planar, [[0.0, 0.0, 0.0], [0.99, 0.99, 0.0]]),
        "workspace.SagMap": lambda: workspace.sag_map(
            _example("cogiro-sagging"), grid=[(-1.0, 1.0, 2), (0.0, 0.0, 1), (2.0, 7.0, 2)], method="qp"
        ),
        "workspace.PoseGrid": lambda: workspace.position_grid(planar, resolution=5),
        "workspace.WorkspaceResult": lambda: workspace.evaluate_workspace(planar, "static", resolution=5),
        "workspace.CertifiedWorkspace": lambda: workspace.certified(planar, "static", eps=0.2),
        "wrapping.CablePath": lambda: wrapping.rebuild_path(
            [[0.0, 1.0, 0.2], [0.0, 0.0, 0.0]], 1, wrapping.CableState(((0, 1),)), [0.0, 2.0]
        ),
        "wrapping.CableState": lambda: wrapping.CableState(((0, 1), (2, -1))),
        "wrapping.Tracking": lambda: wrapping.track_cable_state(_tree(), [[1.0, 2.0], [-1.0, 2.0]]),
        "wrapping.TrajectoryResult": lambda: wrapping.run_trajectory(
            _example("vscr-single-cable"), *wrapping.builtin_trajectory(_example("vscr-single-cable"), dt=0.5)
        ),
        "wrapping.WrappedIK": lambda: wrapping.wrapped_inverse_kinematics(
            _example("vscr-single-cable"), [[0.0, 2.0], [4.0, 0.5]]
        ),
    }
    assert factories.keys() == set(RESULTS), "a result class without an instance here goes unchecked"
    return factories[key]()


@pytest.mark.parametrize("key", RESULTS)
def test_every_exported_result_is_frozen_read_only_and_json(key, tmp_path):
    from result_checks import check_result

    result = _result(key, tmp_path)
    assert type(result) is EXPORTED[key]
    check_result(result)
