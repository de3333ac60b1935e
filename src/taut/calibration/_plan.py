"""Where to measure: poses inside the wrench-feasible workspace that make the calibration best
conditioned — an exact D-optimal design over the identification Jacobian, by greedy
construction then exchange.

Each candidate pose ``k`` adds the information ``T_k = Zᵀ S_k Z`` about the gauge-fixed
parameters, its own pose eliminated (:mod:`taut.calibration._identify`); a design's information
is the sum.  The design maximises ``log det Σ T_k``: the greedy sequential construction adds,
one at a time, the candidate that raises it most; the exchange then swaps a chosen pose for a
candidate while that raises it (Fedorov's exchange in its one-pair-at-a-time form; Atkinson,
Donev & Tobias 2007, Ch. 12).

References
----------
.. [1] A. C. Atkinson, A. N. Donev, R. D. Tobias, "Optimum Experimental Designs, with SAS",
   Oxford University Press, 2007, Ch. 11 (D-optimality) and Ch. 12 (exchange algorithms).
   (docs/references.bib: atkinson2007)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from taut._checks import as_count, as_number, as_rng
from taut._results import Result
from taut.calibration._data import refuse_unsupported
from taut.calibration._identify import (
    Identifiability,
    design,
    gauge_basis,
    gauge_directions,
    identifiability,
    parse_estimate,
    row_information,
)
from taut.errors import TautError
from taut.model import Robot

#: Candidate poses drawn per planned pose (at least :data:`MIN_CANDIDATES`).
CANDIDATES_PER_POSE = 25
MIN_CANDIDATES = 500

#: Most exchange passes over the design.
MAX_PASSES = 20

#: Largest number of poses planned.
MAX_PLANNED = 10_000


@dataclass(frozen=True)
class PosePlan(Result):
    """Poses to measure (:func:`plan_poses`).

    Attributes
    ----------
    poses : ndarray, shape (N, pose_size)
    pose_names : tuple of str
    log_det : float
        ``log det`` of the design's gauge-fixed information (the D-criterion; larger is better).
    candidates : int
        Wrench-feasible candidates the design was chosen from.
    identifiability : Identifiability
        What measuring every cable at these poses would determine.
    """

    poses: np.ndarray
    pose_names: tuple[str, ...]
    log_det: float
    candidates: int
    identifiability: Identifiability


def candidate_poses(
    robot: Robot, count: int, *, condition: str, orientation: float, rng: np.random.Generator
) -> np.ndarray:
    """``count`` random poses in the box of the exits (:func:`taut.workspace.default_bounds`,
    a tenth cut per side), angles uniform within ``±orientation``, kept where ``condition``
    holds."""
    from taut.workspace import default_bounds, evaluate_workspace

    box = default_bounds(robot, shrink=0.1)
    d = robot.dimension
    poses = np.zeros((count, robot.pose_size))
    poses[:, :d] = rng.uniform(box[:, 0], box[:, 1], (count, d))
    poses[:, d:] = rng.uniform(-orientation, orientation, (count, robot.pose_size - d))
    inside = evaluate_workspace(robot, condition, poses=poses).inside
    return poses[inside]


def _logdet(M: np.ndarray) -> np.ndarray:
    sign, value = np.linalg.slogdet(M)
    return np.where(sign > 0, value, -np.inf)


def plan_poses(
    robot: Robot,
    n: int,
    *,
    estimate: tuple[str, ...] = ("exits", "offsets"),
    changes: bool = True,
    known_poses: bool = False,
    condition: str = "wrench-feasible",
    orientation: float = 0.2,
    seed: int | np.random.Generator | None = 0,
) -> PosePlan:
    """``n`` poses inside the workspace whose measurement best determines the calibration
    (module docstring).

    Parameters
    ----------
    robot : Robot
        The nominal robot.
    n : int
        Poses to plan, 1 to :data:`MAX_PLANNED`.
    estimate : sequence of str
        What the calibration will estimate (:func:`calibrate`).
    changes : bool
        The cables will be measured as changes from an encoder zero (offsets unknown).
    known_poses : bool
        The poses will be measured too.
    condition : str
        The workspace condition candidates must meet (:data:`taut.workspace.CONDITIONS`).
    orientation : float
        Candidate angles are drawn within ``±orientation`` [rad] (rigid platforms).
    seed : int or numpy.random.Generator, optional

    Returns
    -------
    PosePlan

    Raises
    ------
    UnsupportedRobotError
        A robot with swivelling pulleys, jointed bodies or obstacles.
    TautError
        Too few candidates meet the condition.

    References
    ----------
    .. [1] A. C. Atkinson, A. N. Donev, R. D. Tobias, "Optimum Experimental Designs, with SAS",
       Oxford University Press, 2007, Ch. 11 and Ch. 12. (docs/references.bib: atkinson2007)

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.calibration import plan_poses
    >>> plan = plan_poses(example("printer-5cable"), 30)
    >>> plan.poses.shape, plan.identifiability.identifiable
    ((30, 3), True)
    """
    refuse_unsupported(robot)
    n = as_count(n, "n")
    if n > MAX_PLANNED:
        raise TautError(f"n: at most {MAX_PLANNED} poses, got {n}")
    orientation = as_number(orientation, "orientation")
    rng = as_rng(seed)
    parse_estimate(robot, estimate)
    pool = candidate_poses(
        robot, max(MIN_CANDIDATES, CANDIDATES_PER_POSE * n), condition=condition, orientation=orientation, rng=rng
    )
    if len(pool) < n:
        raise TautError(
            f"{robot.name}: {len(pool)} of the random candidate poses meet {condition}; fewer than the {n} asked"
        )
    problem, x, _ = design(robot, pool, estimate=estimate, changes=changes, known_poses=known_poses)
    layout = problem.layout
    S, _ = row_information(problem, x)
    Z = gauge_basis(gauge_directions(layout, robot.exits, robot.anchors), layout.n_params)
    T = np.einsum("pa,kpq,qb->kab", Z, S, Z)
    p = T.shape[1]
    ridge = 1e-9 * float(np.einsum("kaa->", T)) / max(len(T) * p, 1) * np.eye(p)
    chosen: list[int] = []
    free = np.ones(len(T), bool)
    M = ridge.copy()
    for _ in range(n):
        score = np.where(free, _logdet(M + T), -np.inf)
        j = int(np.argmax(score))
        chosen.append(j)
        free[j] = False
        M = M + T[j]
    best = float(_logdet(M))
    for _ in range(MAX_PASSES):
        swapped = False
        for slot in range(n):
            out = M - T[chosen[slot]]
            score = np.where(free, _logdet(out + T), -np.inf)
            j = int(np.argmax(score))
            if score[j] > best + 1e-9:
                free[chosen[slot]], free[j] = True, False
                chosen[slot] = j
                M, best = out + T[j], float(score[j])
                swapped = True
        if not swapped:
            break
    poses = pool[chosen]
    return PosePlan(
        poses=poses,
        pose_names=tuple(robot.pose_names),
        log_det=best,
        candidates=len(pool),
        identifiability=identifiability(robot, poses, estimate=estimate, changes=changes, known_poses=known_poses),
    )
