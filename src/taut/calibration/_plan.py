"""Where to measure: poses inside the wrench-feasible workspace that make the calibration best
conditioned — an exact D-optimal design over the identification Jacobian, by greedy
construction then exchange.

Candidates.  Random poses in the box of the exits (below them, for a loaded robot whose exits
lie nearly level: a suspended robot hangs under them), kept where the workspace condition
holds: ``wrench-feasible`` where any candidate is, else ``static`` (a suspended robot balances
its weight, not a box of wrenches about it).  A robot with fewer cables than pose coordinates
has no such poses but a set of measure zero: its equilibria.  Each random pose then only gives
the lengths; the platform is let hang at them — the potential energy of its load is minimised
subject to ``l_i(q) ≤ L_i`` (the geometrico-static problem as Carricato & Merlet 2013 pose it,
whose constrained minima are the stable equilibria), by SLSQP — and the equilibria with every
cable taut within its tension bounds are the candidates.  Or the caller gives the candidates:
poses known to be reachable.

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
.. [2] M. Carricato, J.-P. Merlet, "Stability Analysis of Underconstrained Cable-Driven
   Parallel Robots", IEEE Transactions on Robotics 29(1), 2013, §II (equilibrium as a
   constrained minimum of the potential energy). (docs/references.bib: carricato2013)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

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

#: Equilibria computed per planned pose for a robot with fewer cables than pose coordinates (at
#: least :data:`MIN_EQUILIBRIA`): each is a constrained minimisation, not a test.
EQUILIBRIA_PER_POSE = 5
MIN_EQUILIBRIA = 100

#: The workspace conditions tried in turn when none is given (the second for a loaded robot).
DEFAULT_CONDITIONS = ("wrench-feasible", "static")

#: A weighted robot whose exits span less than this fraction of their largest extent along its
#: weight hangs below them: its candidates are drawn there, down to one largest extent.
LEVEL_EXITS = 0.25

#: An equilibrium's cable counts as taut when its length is within this fraction of the
#: commanded one.
TAUT_RTOL = 1e-6

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
        Candidate poses the design was chosen from.
    condition : str
        Where the candidates came from: the workspace condition they meet, the equilibria of an
        under-constrained robot, or the caller's.
    identifiability : Identifiability
        What measuring every cable at these poses would determine.
    """

    poses: np.ndarray
    pose_names: tuple[str, ...]
    log_det: float
    candidates: int
    condition: str
    identifiability: Identifiability


def candidate_box(robot: Robot) -> np.ndarray:
    """``(d, 2)``: the box random candidates are drawn from — the exits' box a tenth in from
    each side (:func:`taut.workspace.default_bounds`), or, for a loaded robot whose exits lie
    nearly level across its load (weight and constant force), the space below them along the
    load (:data:`LEVEL_EXITS`)."""
    from taut.workspace import default_bounds

    box = default_bounds(robot, shrink=0.1)
    weight = _load(robot)
    k = int(np.argmax(np.abs(weight)))
    if not weight.any() or abs(weight[k]) < 0.999 * float(np.linalg.norm(weight)):
        return box
    lo, hi = robot.exits.min(axis=0), robot.exits.max(axis=0)
    big = float((hi - lo).max()) or 2.0
    if hi[k] - lo[k] >= LEVEL_EXITS * big:
        return box
    box[k] = [lo[k] - big, lo[k] - 0.05 * big] if weight[k] < 0 else [hi[k] + 0.05 * big, hi[k] + big]
    return box


def candidate_poses(
    robot: Robot, count: int, *, condition: str, orientation: float, rng: np.random.Generator
) -> np.ndarray:
    """``count`` random poses in :func:`candidate_box`, angles uniform within
    ``±orientation``, kept where ``condition`` holds."""
    from taut.workspace import evaluate_workspace

    poses = _random_poses(robot, count, orientation, rng)
    return poses[evaluate_workspace(robot, condition, poses=poses).inside]


def _random_poses(robot: Robot, count: int, orientation: float, rng: np.random.Generator) -> np.ndarray:
    box = candidate_box(robot)
    d = robot.dimension
    poses = np.zeros((count, robot.pose_size))
    poses[:, :d] = rng.uniform(box[:, 0], box[:, 1], (count, d))
    poses[:, d:] = rng.uniform(-orientation, orientation, (count, robot.pose_size - d))
    return poses


def _load(robot: Robot) -> np.ndarray:
    """The constant force on the platform [N]: its weight and the force of ``platform.wrench``."""
    force = robot.weight.copy()
    if robot.platform.wrench is not None:
        force += np.asarray(robot.platform.wrench, float)[: robot.dimension]
    return force


def hanging_poses(robot: Robot, poses: np.ndarray) -> np.ndarray:
    """The stable equilibria the platform hangs in at the cable lengths of ``poses``, those with
    every cable taut and tensions within bounds (module docstring): the potential energy of the
    platform's load ``−F·(p + R c)`` (weight and constant force ``F`` at the wrench point ``c``)
    minimised subject to ``l_i(q) ≤ L_i`` by SLSQP from each pose, then the lengths and the
    balance ``W τ + w = 0`` solved together by Newton's method (Powell's hybrid) from there."""
    from scipy.optimize import minimize, root

    from taut.calibration._model import Geometry, frames, partials
    from taut.workspace import evaluate_workspace

    d, n = robot.dimension, robot.n_cables
    force = _load(robot)
    point = np.zeros(d) if robot.platform.wrench_point is None else np.asarray(robot.platform.wrench_point, float)
    rows, cables = np.zeros(n, int), np.arange(n)
    nominal = Geometry.of(robot)

    def lengths(q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        part = partials(robot, nominal, q[None], rows, cables)
        return part.length, part.pose

    def energy(q: np.ndarray) -> float:
        p, R, _ = frames(robot, q[None])
        return -float(force @ (p[0] + R[0] @ point))

    from taut.kinematics import structure_matrix
    from taut.statics import external_wrench

    def balance(z: np.ndarray, target: np.ndarray) -> np.ndarray:
        q, tau = z[:-n], z[-n:]
        return np.concatenate([lengths(q)[0] - target, structure_matrix(robot, q) @ tau + external_wrench(robot, q)])

    found = []
    for q0 in poses:
        target = lengths(q0)[0]
        res = minimize(
            energy,
            q0,
            method="SLSQP",
            constraints=[
                {"type": "ineq", "fun": lambda q, L=target: L - lengths(q)[0], "jac": lambda q: -lengths(q)[1]}
            ],
            options={"ftol": 1e-12, "maxiter": 200},
        )
        if not res.success or np.any(np.abs(lengths(res.x)[0] - target) > TAUT_RTOL * target.max()):
            continue
        # SLSQP stops within ~1e-8 of the balance; Newton on lengths and balance together
        # (square: pose and tensions) makes it exact, from the tensions that balance it best
        tau = np.linalg.lstsq(structure_matrix(robot, res.x), -external_wrench(robot, res.x), rcond=None)[0]
        exact = root(balance, np.concatenate([res.x, tau]), args=(target,), method="hybr")
        if exact.success:
            found.append(exact.x[:-n])
    out = np.array(found).reshape(-1, robot.pose_size)
    return out[evaluate_workspace(robot, "static", poses=out).inside] if len(out) else out


def _candidates(
    robot: Robot, n: int, condition: str | None, orientation: float, rng: np.random.Generator
) -> tuple[np.ndarray, str]:
    """The candidate poses of :func:`plan_poses` and where they came from."""
    if condition is None and robot.n_cables < robot.pose_size and _load(robot).any():
        count = max(MIN_EQUILIBRIA, EQUILIBRIA_PER_POSE * n)
        pool = hanging_poses(robot, _random_poses(robot, count, 0.0, rng))
        if len(pool) < n:
            raise TautError(
                f"{robot.name}: at the lengths of {count} random poses it hangs with every cable taut in "
                f"{len(pool)} stable equilibria, fewer than the {n} asked; give candidate poses it can reach"
            )
        return pool, "stable equilibria with every cable taut (fewer cables than pose coordinates)"
    count = max(MIN_CANDIDATES, CANDIDATES_PER_POSE * n)
    tried = []
    # with no load every pose is static on zero tensions: the condition says nothing there
    names = (
        (condition,) if condition is not None else DEFAULT_CONDITIONS if _load(robot).any() else DEFAULT_CONDITIONS[:1]
    )
    for name in names:
        pool = candidate_poses(robot, count, condition=name, orientation=orientation, rng=rng)
        tried.append(f"{len(pool)} meet {name}")
        if len(pool) >= n:
            return pool, name
    why = (
        ""
        if _load(robot).any()
        else " (its platform carries no load, neither mass nor wrench: a suspended robot's cables then balance nothing)"
    )
    raise TautError(
        f"{robot.name}: of {count} random candidate poses {', '.join(tried)}, fewer than the {n} asked{why}; "
        "give candidate poses it can reach"
    )


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
    condition: str | None = None,
    candidates: npt.ArrayLike | None = None,
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
    condition : str, optional
        The workspace condition candidates must meet (:data:`taut.workspace.CONDITIONS`);
        default: :data:`DEFAULT_CONDITIONS` in turn, or the equilibria of a robot with fewer
        cables than pose coordinates.
    candidates : array_like, shape (M, pose_size), optional
        Poses the robot can reach, to choose from in place of random ones.
    orientation : float
        Random candidates' angles are drawn within ``±orientation`` [rad] (rigid platforms).
    seed : int or numpy.random.Generator, optional

    Returns
    -------
    PosePlan

    Raises
    ------
    UnsupportedRobotError
        A robot with jointed bodies, obstacles, sagging or routed cables.
    PoseError
        ``candidates`` that are not poses of the robot.
    TautError
        Fewer than ``n`` candidates.

    References
    ----------
    .. [1] A. C. Atkinson, A. N. Donev, R. D. Tobias, "Optimum Experimental Designs, with SAS",
       Oxford University Press, 2007, Ch. 11 and Ch. 12. (docs/references.bib: atkinson2007)
    .. [2] M. Carricato, J.-P. Merlet, "Stability Analysis of Underconstrained Cable-Driven
       Parallel Robots", IEEE Transactions on Robotics 29(1), 2013, §II.
       (docs/references.bib: carricato2013)

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.calibration import plan_poses
    >>> plan = plan_poses(example("printer-5cable"), 30)
    >>> plan.poses.shape, plan.condition, plan.identifiability.identifiable
    ((30, 3), 'wrench-feasible', True)

    A suspended platform on two cables hangs where they hold it:

    >>> plan = plan_poses(example("planar-2cable"), 5, known_poses=True)
    >>> plan.condition
    'stable equilibria with every cable taut (fewer cables than pose coordinates)'
    """
    refuse_unsupported(robot)
    n = as_count(n, "n")
    if n > MAX_PLANNED:
        raise TautError(f"n: at most {MAX_PLANNED} poses, got {n}")
    orientation = as_number(orientation, "orientation")
    rng = as_rng(seed)
    parse_estimate(robot, estimate)
    if candidates is not None:
        from taut.kinematics import as_poses

        pool, source = as_poses(robot, candidates)[0], "given candidates"
        if len(pool) < n:
            raise TautError(f"candidates: {len(pool)} poses, fewer than the {n} asked")
    else:
        pool, source = _candidates(robot, n, condition, orientation, rng)
    problem, x, _ = design(robot, pool, estimate=estimate, changes=changes, known_poses=known_poses)
    layout = problem.layout
    S, _ = row_information(problem, x)
    Z = gauge_basis(gauge_directions(layout, problem.nominal), layout.n_params)
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
        condition=source,
        identifiability=identifiability(robot, poses, estimate=estimate, changes=changes, known_poses=known_poses),
    )
