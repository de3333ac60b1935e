"""docs/architecture.md §2.7, errors: ``TautError`` is a ``ValueError``; no function raises a
bare ``ValueError`` or ``TypeError`` for bad input (the pure math of ``geometry`` and
``interval`` and the drawing of ``viz`` raise ``ArgumentError``); shared limits are defined
once; the command line tells bad input (exit 2) from bugs (exit 1), although a
``TautError`` is a ``ValueError``."""

from __future__ import annotations

import ast
import inspect
import re
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

import taut  # noqa: E402
import taut.errors  # noqa: E402
from taut.dynamics import IntegrationError  # noqa: E402
from taut.errors import ArgumentError, PoseError, TautError  # noqa: E402
from taut.geometry import (  # noqa: E402
    angles_from_matrix,
    angular_acceleration,
    angular_velocity,
    planar_rotation,
    rate_matrix,
    rotation_matrix,
    segment_distance,
)
from taut.interval import Interval, branch_and_prune, compile_system, variables  # noqa: E402
from taut.viz import Report, draw_robot, plot_equilibria, plot_tensions, plot_tracking, plot_workspace  # noqa: E402

SRC = Path(__file__).parents[1] / "src" / "taut"
FILES = sorted(SRC.rglob("*.py"))


def test_taut_error_is_a_value_error():
    assert issubclass(TautError, ValueError)
    errors = [
        c
        for _, c in inspect.getmembers(taut.errors, inspect.isclass)
        if issubclass(c, Exception) and not issubclass(c, Warning)
    ]
    assert ArgumentError in errors and len(errors) > 5
    for cls in [*errors, IntegrationError]:
        assert issubclass(cls, TautError) and issubclass(cls, ValueError), cls
    with pytest.raises(ValueError, match="unknown orientation convention"):
        rotation_matrix([0.0, 0.0, 0.0], "zyz")


def _bare_raises(source: str) -> list[int]:
    """Lines of ``raise ValueError(...)`` / ``raise TypeError`` (called or not)."""
    out = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Raise) and node.exc is not None:
            exc = node.exc.func if isinstance(node.exc, ast.Call) else node.exc
            if isinstance(exc, ast.Name) and exc.id in ("ValueError", "TypeError"):
                out.append(node.lineno)
    return out


def test_bare_raise_is_detected():
    source = (
        "raise ValueError('x')\nraise TypeError\nraise TautError('y')\ntry:\n    f()\nexcept ValueError:\n    raise\n"
    )
    assert _bare_raises(source) == [1, 2]


@pytest.mark.parametrize("path", FILES, ids=[str(p.relative_to(SRC)) for p in FILES])
def test_no_bare_value_or_type_error_is_raised(path):
    lines = _bare_raises(path.read_text())
    assert not lines, f"{path.relative_to(SRC)} raises a bare ValueError/TypeError at lines {lines}"


# ---- the limits shared by several modules are defined once -------------------------------
LIMIT = re.compile(r"^(MAX|MIN)_[A-Z0-9_]+$")


def _limits(source: str) -> set[str]:
    """Module-level ``MAX_…`` / ``MIN_…`` constants assigned in ``source``."""
    names = set()
    for node in ast.parse(source).body:
        targets = (
            node.targets if isinstance(node, ast.Assign) else [node.target] if isinstance(node, ast.AnnAssign) else []
        )
        names |= {t.id for t in targets if isinstance(t, ast.Name) and LIMIT.match(t.id)}
    return names


def test_limits_are_defined_once():
    where: dict[str, list[str]] = {}
    for path in FILES:
        for name in _limits(path.read_text()):
            where.setdefault(name, []).append(str(path.relative_to(SRC)))
    twice = {n: w for n, w in where.items() if len(w) > 1}
    assert not twice, f"limits defined in more than one module: {twice}"
    assert {"MAX_GRID_POSES", "MIN_LENGTH", "MAX_MAGNITUDE"} <= set(where)
    assert _limits("MAX_A = 1\nMIN_B: float = 2.0\ndef f():\n    MAX_C = 3\nOTHER = 4\n") == {"MAX_A", "MIN_B"}


# ---- bad input to geometry, interval and viz ---------------------------------------------
def _system():
    x, y = variables(2)
    return compile_system(2, [x * x + y * y - 1.0, x - y])


@dataclass
class _Grid:
    condition: str
    inside: np.ndarray
    axes: tuple
    grid_shape: tuple


def _figure_with_axes():
    fig = plt.figure()
    fig.add_subplot()
    return fig


PLANAR = taut.example("planar-4cable")
SPATIAL = taut.example("spatial-8cable")

#: name → call that gets bad input
BAD_INPUT: dict[str, Callable[[], object]] = {
    # geometry
    "rotation: unknown convention": lambda: rotation_matrix([0, 0, 0], "zyz"),
    "rotation: two angles": lambda: rotation_matrix([0.1, 0.2]),
    "rotation: scalar": lambda: rotation_matrix(0.3),
    "rotation: not numbers": lambda: rotation_matrix(["a", "b", "c"]),
    "angles: 2x2 matrix": lambda: angles_from_matrix(np.eye(2)),
    "angles: unknown convention": lambda: angles_from_matrix(np.eye(3), "zxz"),
    "planar rotation: not numbers": lambda: planar_rotation("x"),
    "rates: unknown convention": lambda: rate_matrix([0, 0, 0], "zyz"),
    "rates: four angles": lambda: rate_matrix([0, 0, 0, 0]),
    "angular velocity: two rates": lambda: angular_velocity([0, 0, 0], [1.0, 2.0]),
    "angular velocity: batches": lambda: angular_velocity(np.zeros((2, 3)), np.zeros((3, 3))),
    "angular acceleration: not numbers": lambda: angular_acceleration([0, 0, 0], [0, 0, 0], "abc"),
    "segments: 4-D points": lambda: segment_distance(np.zeros(4), np.ones(4), np.zeros(4), np.ones(4)),
    "segments: shapes": lambda: segment_distance(np.zeros((2, 3)), np.ones((3, 3)), np.zeros(3), np.ones(3)),
    "segments: scalars": lambda: segment_distance(0.0, 1.0, 0.0, 1.0),
    # interval
    "interval: shapes": lambda: Interval([1.0, 2.0], [1.0, 2.0, 3.0]),
    "interval: not numbers": lambda: Interval("a"),
    "interval: negative power": lambda: Interval(1.0, 2.0) ** -1,
    "interval: fractional power": lambda: Interval(1.0, 2.0) ** 0.5,
    "expression: negative power": lambda: variables(1)[0] ** -2,
    "system: not square": lambda: compile_system(2, variables(2)[:1]),
    "branch and prune: method": lambda: branch_and_prune(_system(), [-2, -2], [2, 2], method="fast"),
    "branch and prune: bisection": lambda: branch_and_prune(_system(), [-2, -2], [2, 2], bisection="longest"),
    "branch and prune: box size": lambda: branch_and_prune(_system(), [-2, -2, -2], [2, 2, 2]),
    "branch and prune: NaN box": lambda: branch_and_prune(_system(), [-2, np.nan], [2, 2]),
    "branch and prune: primary": lambda: branch_and_prune(_system(), [-2, -2], [2, 2], primary=[True]),
    "branch and prune: tube": lambda: branch_and_prune(_system(), [-2, -2], [2, 2], tube=5),
    "branch and prune: domain": lambda: branch_and_prune(_system(), [-2, -2], [2, 2], domain=([-1, -1], [1, 1])),
    # viz
    "draw robot: 2-D axes for 3-D": lambda: draw_robot(SPATIAL, None, ax=plt.figure().add_subplot()),
    "draw robot: 3-D axes for 2-D": lambda: draw_robot(PLANAR, None, ax=plt.figure().add_subplot(projection="3d")),
    "tensions: 3-D array": lambda: plot_tensions(None, np.ones((2, 2, 2)), 0.0, 1.0),
    "tensions: not numbers": lambda: plot_tensions(None, "abc", 0.0, 1.0),
    "tensions: times": lambda: plot_tensions([0.0, 1.0, 2.0], np.ones((2, 3)), 0.0, 1.0),
    "tensions: flags": lambda: plot_tensions(None, np.ones((2, 3)), 0.0, 1.0, [True]),
    "tensions: bounds": lambda: plot_tensions(None, np.ones((2, 3)), [0.0, 0.0], 1.0),
    "workspace: inside": lambda: plot_workspace(_Grid("x", np.ones(3, bool), (np.arange(2.0), np.arange(2.0)), (2, 2))),
    "workspace: one axis": lambda: plot_workspace(_Grid("x", np.ones(2, bool), (np.arange(2.0),), (2,))),
    "workspace: axes not numbers": lambda: plot_workspace(_Grid("x", np.ones(4, bool), ("ab", "cd"), (2, 2))),
    "equilibria: columns": lambda: plot_equilibria(SPATIAL, [], columns=0),
    "equilibria: figure with axes": lambda: plot_equilibria(SPATIAL, [], fig=_figure_with_axes()),
    "tracking: no solution": lambda: plot_tracking([]),
    "report: not a tuple": lambda: Report("r").add_section("s", figures=[plt.figure()]),
    "report: path": lambda: Report("r").add_section("s", figures=[(plt.figure(), "../x.png")]),
}


@pytest.mark.parametrize("name", BAD_INPUT)
def test_bad_input_raises_argument_error(name):
    with pytest.raises(ArgumentError):
        BAD_INPUT[name]()
    plt.close("all")


def test_several_poses_for_one_drawing_raise_pose_error():
    with pytest.raises(PoseError, match="one pose"):
        draw_robot(PLANAR, np.zeros((2, PLANAR.pose_size)))
    plt.close("all")


@settings(max_examples=60, deadline=None)
@given(st.lists(st.integers(0, 4), min_size=0, max_size=3))
def test_rotations_take_three_angles_or_raise_argument_error(shape):
    angles = np.zeros(shape)
    if shape and shape[-1] == 3:
        assert rotation_matrix(angles).shape == (*shape, 3)
        assert angles_from_matrix(rotation_matrix(angles)).shape == tuple(shape)
    else:
        with pytest.raises(ArgumentError, match="three angles"):
            rotation_matrix(angles)
        with pytest.raises(ArgumentError):
            rate_matrix(angles)


@settings(max_examples=60, deadline=None)
@given(st.integers(1, 4), st.integers(1, 4), st.integers(1, 4))
def test_interval_end_points_broadcast_or_raise_argument_error(a, b, n):
    lo, hi = np.zeros((a, n)), np.ones((b, n))
    if a == b or 1 in (a, b):
        assert Interval(lo, hi).shape == (max(a, b), n)
    else:
        with pytest.raises(ArgumentError, match="broadcast"):
            Interval(lo, hi)


# ---- the command line: TautError → exit 2, anything else → exit 1 ------------------------
def test_cli_catches_taut_error_before_any_broader_handler():
    """``main`` handles ``TautError`` (exit 2) before any clause that would also catch a
    ``ValueError`` (``Exception``: a bug in taut or a library, exit 1)."""
    tree = ast.parse((SRC / "cli" / "_main.py").read_text())
    (main,) = [n for n in tree.body if isinstance(n, ast.FunctionDef) and n.name == "main"]
    (handlers,) = [n.handlers for n in ast.walk(main) if isinstance(n, ast.Try)]
    caught = [ast.unparse(h.type) if h.type is not None else "" for h in handlers]
    broad = [k for k, c in enumerate(caught) if re.search(r"\b(ValueError|Exception|BaseException)\b|^$", c)]
    assert caught[0] == "TautError" and broad and min(broad) > 0, caught
    returns = [
        [ast.unparse(r.value) for r in ast.walk(h) if isinstance(r, ast.Return) and r.value is not None]
        for h in handlers
    ]
    assert returns[0] in (["2"], ["BAD_INPUT"]) and returns[min(broad)] == ["1"], returns
