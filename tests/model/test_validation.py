"""Malformed robot files get one clear message naming the file, the field and what was expected."""

import json

import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import taut
from taut.model import robot_to_dict

GOOD = """
format: taut/1
name: test robot
dimension: 2
platform: {kind: point-mass, mass: 1.0}
cables:
  - {exit: [0, 0]}
  - {exit: [1, 0]}
  - {exit: [0.5, 1]}
"""


def _load(text, tmp_path, suffix=".yaml"):
    path = tmp_path / f"robot{suffix}"
    path.write_text(text)
    return taut.load_robot(path)


def test_good_file_loads(tmp_path):
    robot = _load(GOOD, tmp_path)
    assert robot.n_cables == 3 and robot.wrench_dim == 2 and robot.pose_size == 2


@pytest.mark.parametrize(
    "edit, field, words",
    [
        (lambda d: d.pop("dimension"), "dimension", "missing"),
        (lambda d: d["cables"][1].update(exit=[1, 0, 0]), "cables[2].exit", "expected 2 numbers"),
        (lambda d: d["cables"][0].update(exit=["a", 0]), "cables[1].exit[1]", "valid number"),
        (lambda d: d["cables"][2].update(exit=[0, 0]), "cables[3]", "duplicated cable"),
        (
            lambda d: d.update(obstacles=[{"kind": "circle", "center": [1, 1], "radius": -1}]),
            "obstacles[1].radius",
            "greater than or equal to 0",
        ),
        (lambda d: d["cables"][0].update(tension=[10, 1]), "cables[1].tension", "inverted"),
        (lambda d: d["cables"][0].update(length=[3, 2]), "cables[1].length", "inverted"),
        (lambda d: d["cables"][0].update(tension=[-1, 1]), "cables[1].tension", ">= 0"),
        (lambda d: d.update(colour="red"), "colour", "unknown key"),
        (lambda d: d["platform"].update(masss=1), "platform.masss", "unknown key"),
        (lambda d: d.update(dimension=4), "dimension", "2 or 3"),
        (lambda d: d.update(orientation="zyz"), "orientation", "unknown orientation convention"),
        (lambda d: d.update(cables=[]), "cables", "at least 1"),
        (lambda d: d["cables"][0].update(exit=[float("nan"), 0]), "cables[1].exit[1]", "finite"),
        (lambda d: d["cables"][0].update(anchor=[0.1, 0]), "cables[1].anchor", "point-mass"),
        (lambda d: d["platform"].update(wrench=[1, 2, 3]), "platform.wrench", "expected 2 numbers"),
        (lambda d: d.update(obstacles=[{"kind": "blob"}]), "obstacles[1]", "unknown kind"),
    ],
)
def test_each_problem_is_named(tmp_path, edit, field, words):
    data = yaml.safe_load(GOOD)
    edit(data)
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(data))
    with pytest.raises(taut.RobotFileError) as info:
        taut.load_robot(path)
    msg = str(info.value)
    assert msg.startswith(str(path)), msg
    assert f": {field}: " in msg, msg
    assert words in msg, msg


def test_unreadable_and_unparsable(tmp_path):
    with pytest.raises(taut.RobotFileError, match="no such file"):
        taut.load_robot(tmp_path / "missing.yaml")
    with pytest.raises(taut.RobotFileError, match="not valid YAML/JSON at line 2"):
        _load("name: x\n  - : [\n", tmp_path)
    with pytest.raises(taut.RobotFileError, match="not valid JSON at line 1"):
        _load("{name: x}", tmp_path, ".json")
    with pytest.raises(taut.RobotFileError, match="expected a mapping"):
        _load("- 1\n- 2\n", tmp_path)
    binary = tmp_path / "robot.yaml"
    binary.write_bytes(b"\xff\xfe\x00bad")
    with pytest.raises(taut.RobotFileError, match="cannot read"):
        taut.load_robot(binary)


def test_cli_reports_bad_file_with_status_2(tmp_path, cli):
    path = tmp_path / "bad.yaml"
    path.write_text(GOOD.replace("dimension: 2", "dimension: two"))
    assert cli.main(["ik", str(path), "--pose", "0.5,0.5"]) == 2
    err = cli.readouterr().err
    assert "dimension" in err and "Traceback" not in err


def test_json_round_trip_keeps_infinite_bounds(tmp_path):
    robot = _load(GOOD, tmp_path)
    taut.save_robot(robot, tmp_path / "r.json")
    assert json.loads((tmp_path / "r.json").read_text().replace("Infinity", "1e999"))["name"] == "test robot"
    again = taut.load_robot(tmp_path / "r.json")
    assert again.tension_bounds[1][0] == float("inf")
    assert robot_to_dict(again) == robot_to_dict(robot)


def test_shipped_schema_is_current():
    from taut.model._schema import schema_text, shipped_schema_text

    assert shipped_schema_text() == schema_text(), "run `taut schema > src/taut/schema/robot.schema.json`"


# --- hypothesis: random damage to a valid file never escapes as anything but RobotFileError ---

_values = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(-5, 5),
    st.floats(allow_nan=True, allow_infinity=True),
    st.text(max_size=5),
    st.lists(st.floats(-3, 3), max_size=4),
    st.dictionaries(st.text(max_size=3), st.integers(), max_size=2),
)


def _paths(obj, prefix=()):
    yield prefix
    if isinstance(obj, dict):
        for k, v in obj.items():
            yield from _paths(v, prefix + (k,))
    elif isinstance(obj, list):
        for i, v in enumerate(obj):
            yield from _paths(v, prefix + (i,))


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_damaged_files_fail_cleanly(data, tmp_path_factory):
    base = robot_to_dict(taut.example("planar-4cable"))
    paths = [p for p in _paths(base) if p]
    target = data.draw(st.sampled_from(paths))
    value = data.draw(_values)
    obj = base
    for key in target[:-1]:
        obj = obj[key]
    obj[target[-1]] = value
    path = tmp_path_factory.mktemp("bad") / "robot.json"
    path.write_text(json.dumps(base))
    try:
        robot = taut.load_robot(path)
    except taut.RobotFileError as exc:
        assert str(exc).startswith(str(path)) and "\n\n" not in str(exc)
        return
    # accepted: then it is a coherent robot whose kinematics run or fail with a typed error
    from taut.kinematics import inverse_kinematics

    try:
        ik = inverse_kinematics(robot, [0.0] * robot.pose_size)
    except taut.TautError:
        return
    assert ik.lengths.shape == (robot.n_cables,)


@pytest.mark.parametrize(
    "call",
    [
        lambda: taut.model.parse_robot(3),
        lambda: taut.model.format_of("robot.yaml", kind="append"),
        lambda: taut.model.random_suspended_robot("3", seed=0),
        lambda: taut.model.random_suspended_robot(3, seed="x"),
        lambda: taut.model.random_suspended_robot(3, seed=-1),
        lambda: taut.model.random_suspended_robot(3, seed=0, perturbation="x"),
        lambda: taut.model.pose_to_qpos(taut.example("spatial-8cable"), "ab"),
        lambda: taut.model.read_text("/nonexistent/robot.yaml"),
    ],
)
def test_bad_arguments_are_taut_errors(call):
    """docs/architecture.md §2.7: bad input raises a TautError subclass, never a bare
    ValueError, TypeError or AttributeError."""
    with pytest.raises(taut.TautError):
        call()


@pytest.mark.parametrize(
    "write, name",
    [
        (taut.model.save_robot, "robot.yaml"),
        (taut.model.write_robot, "robot.json"),
        (taut.model.write_mjcf, "robot.mjcf.xml"),
        (taut.model.write_caspr, "robot_bodies.xml"),
    ],
)
def test_writing_into_a_missing_directory_is_a_robot_file_error(write, name, tmp_path):
    robot = taut.example("planar-4cable")
    with pytest.raises(taut.RobotFileError, match="cannot write the file|does not exist"):
        write(robot, tmp_path / "missing" / name)


@pytest.mark.parametrize(
    "build, prefix",
    [
        (lambda m: m.Robot(name="r", dimension=4, cables=(m.Cable(exit=(0.0, 1.0)),)), "Robot: dimension: "),
        (lambda m: m.Robot(name="r", dimension=2, cables=()), "Robot: cables: "),
        (
            lambda m: m.Robot(
                name="r", dimension=2, platform=m.Platform(kind="point-mass"), cables=(m.Cable(exit=(0.0, 1.0, 2.0)),)
            ),
            "Robot: cables[1].exit: expected 2 numbers",
        ),
        (lambda m: m.Cable(exit=(0.0, "a")), "Cable: exit[2]: "),
        (lambda m: m.Cable(exit=(0.0, 1.0), tension=(5.0, 1.0)), "Cable: tension: "),
        (lambda m: m.Platform(kind="blob"), "Platform: kind: "),
        (lambda m: m.Robot(name="r", dimension=2, cables=(m.Cable(exit=(0.0, 1.0)),), colour="red"), "Robot: colour: "),
    ],
)
def test_calling_the_classes_with_bad_fields_raises_one_robot_file_error(build, prefix):
    """Pydantic's ValidationError is no TautError: the classes raise RobotFileError (a
    ValueError) with one line naming the class and the field."""
    with pytest.raises(taut.RobotFileError) as info:
        build(taut.model)
    assert isinstance(info.value, ValueError)
    msg = str(info.value)
    assert msg.startswith(prefix) and "\n" not in msg, msg


def test_calling_the_classes_with_good_fields_builds_the_robot_a_file_describes():
    m = taut.model
    built = m.Robot(
        name="test robot",
        dimension=2,
        platform=m.Platform(kind="point-mass", mass=1.0),
        cables=(m.Cable(exit=(0.0, 0.0)), m.Cable(exit=(1.0, 0.0)), m.Cable(exit=(0.5, 1.0))),
    )
    assert built == taut.model.parse_robot(GOOD)
