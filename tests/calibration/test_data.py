"""The measurement file: columns, empty cells, and every kind of bad input as one line."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from taut.calibration import MeasurementError, measurements, parse_measurements, read_measurements
from taut.errors import UnsupportedRobotError
from taut.model import example

PLANAR = example("planar-4cable")


def test_columns_in_any_order_with_poses_and_empty_cells():
    text = "theta,l3,dl1,x,y,l2,dl4\n0.1,1.5,0.2,0.3,0.4,,-0.1\n,1.4,0.1,,,1.2,0.0\n"
    data = parse_measurements(PLANAR, text)
    assert data.changes.tolist() == [True, False, False, True]
    assert data.measured.tolist() == [[True, False, True, True], [True, True, True, True]]
    assert data.values[0].tolist() == [0.2, 0.0, 1.5, -0.1]
    assert data.pose_known.tolist() == [True, False]
    assert data.poses[0].tolist() == [0.3, 0.4, 0.1]


def test_named_cables():
    robot = example("camera-4cable")
    data = parse_measurements(robot, "dl_NE,l_SW,l_SE\n0.5,10,11\n")
    assert data.measured.tolist() == [[True, True, True, False]]
    assert data.changes.tolist() == [False, False, True, False]
    assert data.values[0, :3].tolist() == [10.0, 11.0, 0.5]


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("l1,l2,q9\n1,1,1\n", "unknown name 'q9'"),
        ("l1,l2,l2\n1,1,1\n", "duplicate header 'l2'"),
        ("l1,dl1\n1,1\n", "cable 1 has two columns"),
        ("l1,l5\n1,1\n", "has cables 1..4"),
        ("l1,l2\n1,nan\n", "'nan' is not a finite number"),
        ("l1,l2\n1,abc\n", "'abc' is not a number"),
        ("l1,l2\n1,2,3\n", "3 cells, the header has 2"),
        ("l1,l2,x,y\n1,1,0,0\n", "theta missing"),
        ("l1,l2,x,y,theta\n1,1,0,,0\n", "measured in part"),
        ("l1,l2,x,y,theta\n,,0,0,0\n", "measures no cable"),
        ("l1,l2\n-1,1\n", "must be positive"),
        ("l1,l2\n", "no rows"),
        ("", "empty file"),
        ("x,y,theta\n0,0,0\n", "no cable column"),
    ],
)
def test_bad_files_are_one_line(text, message):
    with pytest.raises(MeasurementError, match=message) as info:
        parse_measurements(PLANAR, text, source="data.csv")
    assert "\n" not in str(info.value) and str(info.value).startswith("data.csv: ")


def test_unsupported_robots():
    with pytest.raises(UnsupportedRobotError, match="jointed bodies"):
        parse_measurements(example("adjustable-8cable"), "l1\n1\n")
    with pytest.raises(UnsupportedRobotError, match="obstacles"):
        parse_measurements(example("vscr-four-cable"), "l1\n1\n")


def test_read_refuses_a_directory(tmp_path):
    with pytest.raises(MeasurementError, match="not a regular file"):
        read_measurements(PLANAR, tmp_path)


cells = st.one_of(st.none(), st.floats(min_value=0.01, max_value=100, allow_nan=False))


@settings(max_examples=40, deadline=None)
@given(st.lists(st.lists(cells, min_size=4, max_size=4), min_size=1, max_size=6), st.booleans())
def test_csv_round_trip(rows, changes):
    """to_csv then parse gives the same cells, the same measured mask."""
    rows = [r if any(v is not None for v in r) else [1.0, *r[1:]] for r in rows]
    arr = np.array([[np.nan if v is None else v for v in r] for r in rows])
    data = measurements(PLANAR, None if changes else arr, changes=arr if changes else None)
    back = parse_measurements(PLANAR, data.to_csv(PLANAR))
    assert np.array_equal(back.measured, ~np.isnan(arr))
    assert np.array_equal(back.values, np.nan_to_num(arr))
    assert back.changes[back.measured.any(axis=0)].all() == changes or not changes
