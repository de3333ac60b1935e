"""Executors: serial, local processes, dask.distributed — identical results."""

import sys

import numpy as np
import pytest

import taut
from taut.errors import TautError
from taut.parallel import DaskExecutor, ProcessExecutor, SerialExecutor, get_executor
from taut.workspace import evaluate_workspace

PLANAR = taut.example("planar-4cable")
SPATIAL = taut.example("spatial-8cable")


def _square(x):
    return x * x


def _fail(x):
    if x == 3:
        raise TautError("item 3 is bad")
    return x


@pytest.fixture(scope="module")
def reference():
    """The serial workspaces that every executor must reproduce."""
    return {
        "planar": evaluate_workspace(PLANAR, "wrench-feasible", resolution=40),
        "spatial": evaluate_workspace(SPATIAL, "static", resolution=9),
    }


@pytest.fixture(scope="module")
def cluster():
    """One local dask cluster of two worker processes for the module (it takes seconds to start)."""
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as c:
        yield c


def _run_all(executor):
    return {
        "planar": evaluate_workspace(PLANAR, "wrench-feasible", resolution=40, executor=executor, chunk=300),
        "spatial": evaluate_workspace(SPATIAL, "static", resolution=9, executor=executor, chunk=100),
    }


def _assert_same(got, ref):
    for key in ref:
        assert np.array_equal(got[key].inside, ref[key].inside)
        assert np.array_equal(got[key].poses, ref[key].poses)
        assert 0 < ref[key].count < ref[key].inside.size


def test_get_executor_kinds_and_errors():
    assert isinstance(get_executor(), SerialExecutor)
    assert isinstance(get_executor(workers=1), SerialExecutor)
    ex = get_executor(workers=3)
    assert isinstance(ex, ProcessExecutor) and ex.workers == 3
    ex.close()
    for bad in (0, -2, 1.5, "2", True):
        with pytest.raises(TautError):
            get_executor(workers=bad)
    with pytest.raises(TautError, match="not both"):
        get_executor(workers=2, scheduler="tcp://127.0.0.1:8786")
    with pytest.raises(TautError, match="executor"):
        evaluate_workspace(PLANAR, "static", resolution=3, executor=4)


def test_serial_map_order_callback_and_errors():
    seen = []
    assert SerialExecutor().map(_square, range(5), callback=seen.append) == [0, 1, 4, 9, 16]
    assert seen == [0, 1, 2, 3, 4]
    with pytest.raises(TautError, match="item 3"):
        SerialExecutor().map(_fail, range(5))


def test_missing_dask_extra_is_a_clear_error(monkeypatch):
    monkeypatch.setitem(sys.modules, "distributed", None)  # import distributed -> ImportError
    with pytest.raises(TautError, match=r"taut\[dist\]"):
        get_executor(scheduler="tcp://127.0.0.1:8786")


def test_unreachable_scheduler_is_a_clear_error():
    with pytest.raises(TautError, match="cannot reach"):
        get_executor(scheduler="tcp://127.0.0.1:9", timeout=1.0)


def test_processes_give_identical_results(reference):
    with get_executor(workers=2) as ex:
        seen = []
        assert ex.map(_square, range(6), callback=seen.append) == [0, 1, 4, 9, 16, 25]
        assert sorted(seen) == list(range(6))
        with pytest.raises(TautError, match="item 3"):
            ex.map(_fail, range(5))
        _assert_same(_run_all(ex), reference)


@pytest.mark.slow
def test_dask_local_cluster_gives_identical_results(reference, cluster):
    import distributed

    ex = get_executor(scheduler=cluster.scheduler_address)
    try:
        assert isinstance(ex, DaskExecutor)
        calls = []
        got = {
            "planar": evaluate_workspace(
                PLANAR,
                "wrench-feasible",
                resolution=40,
                executor=ex,
                chunk=300,
                progress=lambda d, t: calls.append((d, t)),
            ),
            "spatial": evaluate_workspace(SPATIAL, "static", resolution=9, executor=ex, chunk=100),
        }
        _assert_same(got, reference)
        assert calls[-1] == (1600, 1600) and len(calls) == 1 + 6
        with pytest.raises(TautError, match="item 3"):
            ex.map(_fail, range(5))
    finally:
        ex.close()
    with pytest.raises(TautError, match="closed"):
        ex.map(_square, [1])
    with distributed.Client(cluster) as client:  # an existing client is used as is
        ex2 = get_executor(scheduler=client)
        assert ex2.map(_square, [1, 2, 3]) == [1, 4, 9]
        ex2.close()
        assert client.status == "running"
        direct = evaluate_workspace(SPATIAL, "static", resolution=9, executor=client, chunk=250)
        assert np.array_equal(direct.inside, reference["spatial"].inside)


SUSPENDED = taut.example("suspended-3cable")


def _poses(res):
    return np.array([np.r_[s.position, s.orientation, s.tensions] for s in res.solutions])


def _assert_table_4_3(res):
    """Table 4.3 of Berti's thesis: six equilibria, all with the three cables taut, each at the
    reference lengths (independent inverse kinematics)."""
    from taut.kinematics import inverse_kinematics

    assert res.complete and len(res.solutions) == 6 and {s.taut for s in res.solutions} == {(0, 1, 2)}
    for s in res.solutions:
        lengths = inverse_kinematics(SUSPENDED, np.r_[s.position, s.orientation]).lengths
        assert np.allclose(lengths, SUSPENDED.reference.lengths, atol=1e-9)


@pytest.mark.slow
def test_dgp_serial_processes_and_dask_agree_bitwise(cluster):
    """solve_dgp takes the executors evaluate_workspace takes; the solution lists are the same
    to the bit and in the same order (canonical: taut set, then pose)."""
    import distributed

    from taut.dgp import solve_dgp

    calls = []
    serial = solve_dgp(SUSPENDED, progress=lambda d, t: calls.append((d, t)))
    _assert_table_4_3(serial)
    keys = [(s.taut, *s.position, *s.orientation) for s in serial.solutions]
    assert keys == sorted(keys)
    total = calls[-1][1]
    assert calls[0] == (0, total) and calls[-1] == (total, total) and total > serial.subproblems
    assert [d for d, _ in calls] == list(range(total + 1)) and {t for _, t in calls} == {total}
    with get_executor(workers=2) as ex:
        processes = solve_dgp(SUSPENDED, executor=ex)
    with distributed.Client(cluster) as client:
        on_dask = [
            solve_dgp(SUSPENDED, executor=client),  # a client as is, as evaluate_workspace takes it
            solve_dgp(SUSPENDED, executor=get_executor(scheduler=client)),
        ]
        assert client.status == "running"  # not closed by solve_dgp
    for res in (processes, *on_dask):
        assert [s.taut for s in res.solutions] == [s.taut for s in serial.solutions]
        assert np.array_equal(_poses(res), _poses(serial))
        assert [s.stable for s in res.solutions] == [s.stable for s in serial.solutions]
        assert (res.subproblems, res.boxes, res.undecided) == (serial.subproblems, serial.boxes, 0)


def test_dgp_refuses_what_is_not_an_executor():
    from taut.dgp import solve_dgp

    with pytest.raises(TautError, match="executor"):
        solve_dgp(SUSPENDED, max_taut=1, executor=4)
