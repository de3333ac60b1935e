"""docs/architecture.md §2.7 on the results of taut.dgp: frozen, read-only arrays, ``as_dict()``
in plain JSON types with 0-based cables, equal to the fields it is built from."""

import numpy as np
import pytest
from frozen_results import check_frozen

from taut.dgp import solve_dgp, solve_igp, track_path
from taut.model import load_robot
from taut.parallel import get_executor

ROBOT = load_robot("suspended-3cable")
SOLUTION_KEYS = {"taut", "position", "orientation", "tensions", "stable", "certificate_width", "uniqueness_radius"}


@pytest.fixture(scope="module")
def dgp():
    return solve_dgp(ROBOT)


def test_dgp_result_and_solutions(dgp):
    keys = {
        "solutions",
        "complete",
        "exhausted",
        "subproblems",
        "undecided_boxes",
        "undecided_enclosures",
        "boxes",
        "elapsed_s",
    }
    d = check_frozen(dgp, keys)
    assert d["complete"] is True and d["exhausted"] is False and d["undecided_enclosures"] == []
    assert (d["subproblems"], d["boxes"], d["elapsed_s"]) == (dgp.subproblems, dgp.boxes, dgp.elapsed_s)
    assert isinstance(dgp.solutions, tuple) and len(d["solutions"]) == len(dgp.solutions) == 6
    for s, ds in zip(dgp.solutions, d["solutions"]):
        # a single taut cable leaves a spin arc: the solution names it
        extra = {"continuum"} if s.continuum is not None else set()
        assert check_frozen(s, SOLUTION_KEYS | extra) == ds
        assert ds["taut"] == list(s.taut) and all(0 <= i < 3 for i in ds["taut"])
        assert np.array_equal(ds["position"], s.position) and np.array_equal(ds["tensions"], s.tensions)


def test_solutions_from_worker_processes_are_read_only_too():
    with get_executor(workers=2) as ex:
        res = solve_dgp(ROBOT, executor=ex)
    assert res.solutions
    for s in res.solutions:
        check_frozen(s, SOLUTION_KEYS | ({"continuum"} if s.continuum is not None else set()))


def test_igp_result_budget_and_undecided_boxes():
    res = solve_igp(ROBOT, (2, 0, 1), {"x": 2.7505, "y": 3.9798, "z": 5.5061}, max_boxes=2_000)
    keys = {"fixed", "solutions", "complete", "undecided_boxes", "undecided_enclosures", "boxes", "exhausted"}
    d = check_frozen(res, keys | {"elapsed_s"})
    assert d["fixed"] == {"x": 2.7505, "y": 3.9798, "z": 5.5061} and d["exhausted"] is True
    assert d["complete"] is False and d["undecided_boxes"] == len(res.undecided_enclosures) > 0
    for s, ds in zip(res.solutions, d["solutions"]):
        keys = SOLUTION_KEYS | {"lengths", "slack", "length_violations"}
        assert check_frozen(s, keys) == ds and ds["taut"] == [0, 1, 2]
    for box, db in zip(res.undecided_enclosures, d["undecided_enclosures"]):
        assert check_frozen(box, {"taut", "cause", "enclosure", "tensions"}) == db
        assert db["cause"] == "budget" and db["taut"] == [0, 1, 2]
        assert list(db["enclosure"]) == list(box.variables)


def test_tracked_solutions(dgp):
    start = next(s for s in dgp.solutions if s.stable and len(s.taut) == 3)
    (step,) = track_path(ROBOT, start, [np.array(ROBOT.reference.lengths) + 0.001])
    d = check_frozen(step, SOLUTION_KEYS)
    assert d["taut"] == [0, 1, 2] and np.allclose(d["position"], start.position, atol=0.01)
