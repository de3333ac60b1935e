"""Calibration: a built robot's exits, encoder offsets and anchors, and the unknown poses of its
measurements, by nonlinear least squares over all of them at once.

The method is the self-calibration of Borgstrom et al. (2009) and the auto-calibration of
Miermeister & Pott (2012): the redundant cable lengths measured at poses that are unknown (or
measured by a tracker) determine the geometry and the encoder offsets together.  The problem is
solved as a bundle adjustment (Triggs et al. 2000): Levenberg–Marquardt on the analytic sparse
Jacobian of :mod:`taut.calibration._model`, each step solved exactly through the Schur
complement of the pose blocks (:mod:`taut.calibration._solve`), so that a step costs time
linear in the rows.

Start.  The nominal robot is the start of its parameters; the poses and offsets start from a
multi-start that needs no pose guess.  Every unknown pose is fitted to its own row on the nominal
geometry (Levenberg–Marquardt per row, batched, a weak prior holding the orientation near zero)
from each of :data:`START_POSES` poses — the exits' centroid and six points around it along the
axes — and keeps the best; the offsets of length changes then take the Gauss–Newton step of
offsets and poses together, the poses eliminated (the variable projection of Golub & Pereyra
1973), halved while it raises the residuals, and the two alternate up to :data:`START_ROUNDS`
times, rows that fit far worse than the others restarted from every start pose.  Where that
descent stops, every row is fitted afresh from every start pose and the descent goes on, up to
:data:`START_BRANCHES` times: rows fitted while the offsets were far off may sit in another
branch of their pose.  The offsets start from hypotheses — the medians of the changes measured
at the centroid, or one of the :data:`START_ROWS` most central rows measured there — each fitted
on a short budget; the best is fitted to convergence.  Then rows left in another branch of their
pose are restarted on the fitted geometry and everything refitted (:data:`RESEED_ROUNDS`).
Where two starts fit a row equally (a pose and its mirror image in the plane of coplanar exits),
the one lower along the platform's weight is kept: a suspended platform hangs below its exits.

The fit itself starts robust: even without ``robust``, each start is fitted first by the
:data:`BASIN_LOSS` loss at twice the residuals' robust deviation, re-seeded, and the plain
least-squares fit follows from its answer.  Rows the start left in another branch of their
pose fit the nominal geometry no worse than the others, so nothing marks them at first; plain
least squares lets them pull the exits into a false minimum, while the robust loss lets the
other rows set the geometry, on which the re-seeding then finds them.

Robust fit.  With ``robust``, a first fit with that loss (``soft_l1`` or ``huber``, scale
:data:`ROBUST_SCALE`), a second with the scale set to twice the residuals' robust standard
deviation (1.4826 × their median absolute value), then the rows with a residual beyond
:data:`OUTLIER_THRESHOLD` of those deviations are flagged as outliers and the others refitted
by plain least squares, which gives the estimate and its standard deviations.  Without it, the
same rows are flagged but kept.

Gauge.  With no measured pose, a rigid motion of the exits and every pose together (and, when
the anchors are estimated, a change of the platform frame) changes no length.  The rule: after
the fit, the estimated exits are moved by the proper rigid motion that best aligns them onto
the nominal ones in the least-squares sense (Kabsch 1976), and the poses with them — for a
point mass the motion may be improper: a configuration and its mirror image give the same
lengths, and the fit may land on either; estimated
anchors likewise onto the nominal anchors, the poses' frames changing to match.  The standard
deviations are those of that gauge: ``σ² Z (Zᵀ S Z)⁻¹ Zᵀ`` with ``S`` the information about
the parameters once the poses are eliminated and ``Z`` the directions that the alignment leaves
free (:mod:`taut.calibration._identify`), ``σ²`` the residual variance (sum of squares over
the degrees of freedom).

References
----------
.. [1] P. H. Borgstrom et al., "NIMS-PL: A Cable-Driven Robot With Self-Calibration
   Capabilities", IEEE Transactions on Robotics 25(5), 2009, the self-calibration section.
   (docs/references.bib: borgstrom2009)
.. [2] P. Miermeister, A. Pott, "Auto-Calibration Method for Overconstrained Cable-Driven
   Parallel Robots", IEEE ICRA 2012, the estimation of poses and length offsets.
   (docs/references.bib: miermeister2012)
.. [3] B. Triggs, P. F. McLauchlan, R. I. Hartley, A. W. Fitzgibbon, "Bundle Adjustment — A
   Modern Synthesis", Vision Algorithms: Theory and Practice, LNCS 1883, Springer, 2000, §6
   and §9. (docs/references.bib: triggs2000)
.. [4] W. Kabsch, "A solution for the best rotation to relate two sets of vectors", Acta
   Crystallographica A 32, 1976. (docs/references.bib: kabsch1976)
.. [5] G. H. Golub, V. Pereyra, "The differentiation of pseudo-inverses and nonlinear least
   squares problems whose variables separate", SIAM Journal on Numerical Analysis 10(2), 1973.
   (docs/references.bib: golub1973)
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Any

import numpy as np

from taut._checks import as_count, as_number
from taut._results import Result, jsonable
from taut.calibration._data import Measurements, refuse_unsupported
from taut.calibration._identify import MAX_CONDITION, Identifiability, common_axis, parse_estimate, report
from taut.calibration._model import Geometry, Layout, Problem, frames, partials
from taut.calibration._solve import levenberg_marquardt
from taut.errors import TautError
from taut.geometry import angles_from_matrix, rigid_alignment
from taut.model import Robot

#: Robust losses ``robust`` takes (``scipy.optimize.least_squares``'s names).
ROBUST_LOSSES = ("soft_l1", "huber")

#: The scale [m] of the first robust fit: residuals beyond it count as outliers' (a few mm of
#: noise, centimetres of nominal error fitted away in the same run).
ROBUST_SCALE = 0.01

#: A row is an outlier when one of its residuals, divided by ``√(1 − h)`` (``h`` its leverage in
#: its row's pose block), exceeds this many robust standard deviations of all of them (1.4826 ×
#: their median absolute value): under Gaussian noise one residual in 1.7 million goes that far.
OUTLIER_THRESHOLD = 5.0

#: Starting poses tried for every unknown pose: the exits' centroid and ± along each axis.
START_POSES = 7

#: Weight [m/rad] of the start's prior that keeps each row's orientation near zero: without it a
#: row fitted on the nominal geometry with wrong offsets can turn its platform half a turn.
START_PRIOR = 0.05

#: Central rows (their changes nearest the medians) that the start's offset hypotheses take as
#: measured at the exits' centroid.
START_ROWS = 2

#: Rows (at most) on which the start scores its offset hypotheses.
SCORE_ROWS = 200

#: Residual evaluations each start's fit may take before the best one is fitted to convergence.
START_EVALUATIONS = 30

#: The loss of the fits that find the basin when no robust loss is asked for: rows left in
#: another branch of their pose by the start (their residuals no larger than the others' on the
#: nominal geometry) would otherwise pull the exits into a false minimum, which plain least
#: squares cannot leave (measured: CoGiRo with pulleys, 12 of 60 rows 0.3–1.4 m away, residual
#: 4 mm against 0.3 mm of noise).
BASIN_LOSS = "soft_l1"

#: Rounds of re-seeding the poses after the fit (:func:`_reseed`), and the factor by which a
#: row's new pose must lower its squared residuals to be taken.
RESEED_ROUNDS = 3
RESEED_GAIN = 0.5

#: Hypotheses of the start fitted by least squares: the best one's fit is kept.
FITTED_STARTS = 3

#: The start's offsets have converged when a step moves none by more than this [m].
START_TOL = 1e-6

#: A row whose squared residuals exceed this many times the median row's is started afresh
#: from every start pose in the next step of the start.
RESTART_FACTOR = 4.0

#: Gauss–Newton steps of the start's offsets (each after a refit of the rows' poses).
START_ROUNDS = 40

#: Descents of the start's offsets, each from every row's pose fitted afresh, and the fraction
#: by which one must lower the residuals' rms for another to follow.
START_BRANCHES = 3
START_GAIN = 0.01

#: Iterations of the per-row Levenberg–Marquardt of the start.  A row stops sooner once it has
#: converged: its last step moved no coordinate by :data:`START_STEP` [m or rad], or its damping
#: exceeds :data:`START_DAMPING` (its steps no longer lower its residuals).
START_ITERATIONS = 30
START_DAMPING = 1e3
START_STEP = 1e-9

#: Budget of residual evaluations of a least-squares fit, per unknown (scipy's default is 100
#: per unknown for the dense solver).  The fits that converge take 1–6 per unknown; one that
#: spends more is crawling along the floor of a false valley (measured: 69,000 evaluations,
#: 160 s, for a cost 1 % lower), so it stops there and says it has not converged.
MAX_EVALUATIONS = 20

#: The rule that fixes the gauge, as the result and the CLI state it.
GAUGE_RULE = (
    "no pose measured: the estimated exits are aligned onto the nominal ones by the least-squares "
    "rigid motion (Kabsch; for a point mass, whose mirror image fits the same lengths, a reflection "
    "too), the poses moved with them"
)
GAUGE_RULE_ANCHORS = "; the estimated anchors likewise onto the nominal anchors (the platform frame)"
GAUGE_RULE_SWIVEL = (
    "; the swivel axes are fixed in the world, so the motion only translates, and turns about the axes' "
    "common direction if they share one"
)
GAUGE_MEASURED = "measured poses fix the frame"
GAUGE_FIXED_EXITS = "the nominal exits, not estimated, fix the frame"


@dataclass(frozen=True)
class CalibrationResult(Result):
    """The estimate of :func:`calibrate`.

    Attributes
    ----------
    robot_name : str
    estimate : tuple of str
        What was estimated (``exits``, ``offsets``, ``anchors``).
    exits, exits_std : ndarray, shape (n, d)
        Estimated exit points [m] (the nominal ones where not estimated) and their standard
        deviations (0 where not estimated, ``inf`` where the data do not determine them).
    offsets, offsets_std : ndarray, shape (n,)
        Encoder offsets [m]: the length at the encoder's zero of each cable measured by length
        changes (0 for the others), ``length = change + offset``.
    changes : ndarray of bool, shape (n,)
        The cables measured as length changes, whose offsets are estimated.
    anchors, anchors_std : ndarray, shape (n, d)
        Anchors in the platform frame [m] and their standard deviations.
    radii, radii_std : ndarray, shape (n,)
        Radii of the swivelling pulleys [m] (0 for a cable without one) and their standard
        deviations.
    poses : ndarray, shape (N, pose_size)
        The pose of every row: measured, or estimated.
    pose_known : ndarray of bool, shape (N,)
    residual_rms : ndarray, shape (n,)
        Root-mean-square residual of each cable over the rows used [m] (0 for a cable never
        measured).
    sigma : float
        Residual standard deviation [m] (sum of squares over the degrees of freedom; ``inf``
        with none).
    outliers : tuple of int
        0-based rows flagged as outliers (:data:`OUTLIER_THRESHOLD`); left out of the final
        fit when ``robust``.
    robust : str or None
    gauge : str
        The rule that fixed the frame.
    identifiability : Identifiability
    converged : bool
        The final least-squares fit met its tolerance within its budget.
    evaluations : int
        Residual evaluations of all fits.
    elapsed_s : float
    """

    robot_name: str
    estimate: tuple[str, ...]
    exits: np.ndarray
    exits_std: np.ndarray
    offsets: np.ndarray
    offsets_std: np.ndarray
    changes: np.ndarray
    anchors: np.ndarray
    anchors_std: np.ndarray
    radii: np.ndarray
    radii_std: np.ndarray
    poses: np.ndarray
    pose_known: np.ndarray
    residual_rms: np.ndarray
    sigma: float
    outliers: tuple[int, ...]
    robust: str | None
    gauge: str
    identifiability: Identifiability
    converged: bool
    evaluations: int
    elapsed_s: float

    @property
    def identifiable(self) -> bool:
        """Whether the data determine every estimated parameter (:class:`Identifiability`)."""
        return self.identifiability.identifiable

    def as_dict(self) -> dict[str, Any]:
        """The fields in JSON types, with ``identifiable`` and ``undetermined`` at the top level."""
        out = super().as_dict()
        out["identifiable"] = self.identifiability.identifiable
        out["undetermined"] = jsonable(self.identifiability.undetermined)
        return out

    def calibrated_robot(self, robot: Robot) -> Robot:
        """``robot`` (the nominal robot of the fit) with the estimated exits, anchors, pulley
        radii and encoder offsets (``cables[].length_offset``) written in and a description saying how it
        was calibrated.

        Parameters
        ----------
        robot : Robot

        Returns
        -------
        Robot

        Examples
        --------
        See :func:`calibrate`.
        """
        cables = []
        for i, c in enumerate(robot.cables):
            update: dict[str, Any] = {"exit": tuple(float(v) for v in self.exits[i])}
            if self.changes[i]:
                update["length_offset"] = float(self.offsets[i])
            if "anchors" in self.estimate:
                update["anchor"] = tuple(float(v) for v in self.anchors[i])
            if "radii" in self.estimate and c.swivel is not None:
                update["swivel"] = c.swivel.model_copy(update={"radius": float(self.radii[i])})
            cables.append(c.model_copy(update=update))
        rows = len(self.poses) - len(self.outliers) if self.robust else len(self.poses)
        note = (
            f"calibrated by taut calibrate: {', '.join(self.estimate)} from {rows} rows by least squares"
            f"{f' ({self.robust} loss)' if self.robust else ''}, residual {self.sigma * 1000:.3g} mm; "
            f"gauge: {self.gauge}; {'identifiable' if self.identifiable else 'NOT identifiable'}"
        )
        return robot.model_copy(update={"cables": tuple(cables), "description": note})


def _move_poses(robot: Robot, poses: np.ndarray, Q: np.ndarray, t: np.ndarray, body: bool) -> np.ndarray:
    """Poses after the world moves by ``x ↦ Q x + t`` (``body`` False), or after the platform
    frame changes so that anchors become ``Q r + t`` (``body`` True)."""
    d = robot.dimension
    p, R, _ = frames(robot, poses)
    out = poses.copy()
    if body:
        Rn = R @ Q.T
        out[:, :d] = p - Rn @ t
    else:
        Rn = Q @ R
        out[:, :d] = p @ Q.T + t
    if not robot.is_point_mass:
        if d == 2:
            out[:, 2] = poses[:, 2] + (-1.0 if body else 1.0) * np.arctan2(Q[1, 0], Q[0, 0])
        else:
            out[:, 3:6] = angles_from_matrix(Rn, robot.orientation)
    return out


def _start_prior(robot: Robot) -> np.ndarray:
    """The ``s × s`` information of the start's orientation prior (:data:`START_PRIOR`)."""
    s, d = robot.pose_size, robot.dimension
    prior = np.zeros((s, s))
    prior[d:, d:] = START_PRIOR**2 * np.eye(s - d)
    return prior


def _row_poses(
    robot: Robot,
    geometry: Geometry,
    offsets: np.ndarray,
    data: Measurements,
    rows: np.ndarray,
    start: np.ndarray,
) -> tuple[np.ndarray, np.ndarray]:
    """Each row's pose fitted to its own cables on the ``geometry``, from
    ``start (U, s)``: batched Levenberg–Marquardt with a weak prior holding the orientation near
    zero (:data:`START_PRIOR`); ``(poses (U, s), sum of squared residuals (U,))``."""
    n, s, d = robot.n_cables, robot.pose_size, robot.dimension
    U = rows.size
    mask = data.measured[rows]
    target = data.values[rows] + np.where(data.changes, offsets, 0.0)
    prior = _start_prior(robot)

    def evaluate(q: np.ndarray, k: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        part = partials(robot, geometry, q, np.repeat(np.arange(k.size), n), np.tile(np.arange(n), k.size))
        r = (part.length.reshape(k.size, n) - target[k]) * mask[k]
        cost = (r * r).sum(axis=1) + START_PRIOR**2 * (q[:, d:] ** 2).sum(axis=1)
        return r, part.pose.reshape(k.size, n, s) * mask[k][..., None], cost

    q = start.copy()
    r, J, cost = evaluate(q, np.arange(U))
    lam = np.full(U, 1e-3)
    # only the rows still moving are iterated: the others have converged
    k = np.arange(U)
    for _ in range(START_ITERATIONS):
        A = np.einsum("kis,kit->kst", J[k], J[k]) + prior
        g = np.einsum("kis,ki->ks", J[k], r[k])
        g[:, d:] += START_PRIOR**2 * q[k, d:]
        diag = np.einsum("kss->ks", A)
        A = A + (lam[k, None] * diag + 1e-12)[:, :, None] * np.eye(s)
        trial = q[k] - np.linalg.solve(A, g[..., None])[..., 0]
        step = np.abs(trial - q[k]).max(axis=1)
        r2, J2, cost2 = evaluate(trial, k)
        better = cost2 < cost[k]
        q[k[better]], r[k[better]], J[k[better]], cost[k[better]] = trial[better], r2[better], J2[better], cost2[better]
        lam[k] = np.where(better, lam[k] / 3, lam[k] * 4)
        k = k[(step >= START_STEP) & (lam[k] <= START_DAMPING)]
        if not k.size:
            break
    return q, (r * r).sum(axis=1)


def _starts(robot: Robot) -> np.ndarray:
    """The :data:`START_POSES` starting poses: the exits' centroid and ± along each axis, a
    third of the exits' largest extent away, zero orientation."""
    from taut.kinematics import default_guess

    centre = default_guess(robot)
    d = robot.dimension
    extent = float(np.ptp(robot.exits, axis=0).max()) or 1.0
    out = [centre]
    for k in range(d):
        for sign in (-1.0, 1.0):
            q = centre.copy()
            q[k] += sign * extent / 3
            out.append(q)
    return np.array(out)


def _multistart_poses(
    robot: Robot, geometry: Geometry, offsets: np.ndarray, data: Measurements, rows: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Each row's pose from the best of the :func:`_starts`; of two that fit equally (a pose and
    its mirror image in the plane of coplanar exits), the one lower along the weight."""
    weight = robot.weight[: robot.dimension]
    norm = float(np.linalg.norm(weight))
    down = weight / norm if norm > 0 else np.zeros(robot.dimension)
    starts = _starts(robot)
    k, U = len(starts), rows.size
    # one batch of every (start, row) pair: the per-row fits cost little beside their overhead
    q, costs = _row_poses(robot, geometry, offsets, data, np.tile(rows, k), np.repeat(starts, U, axis=0))
    q, costs = q.reshape(k, U, -1), costs.reshape(k, U)
    best = costs.min(axis=0)
    height = -(q[..., : robot.dimension] @ down)
    pick = np.argmin(np.where(costs <= best * 1.01 + 1e-12, height, np.inf), axis=0)
    return q[pick, np.arange(U)], costs[pick, np.arange(U)]


def _project(
    robot: Robot, data: Measurements, rows: np.ndarray, offsets: np.ndarray, used: np.ndarray
) -> tuple[np.ndarray, np.ndarray, float]:
    """Offsets by Gauss–Newton on the variable projection of the nominal-geometry problem: each
    step refits every row's pose, then moves the offsets by the Gauss–Newton step of offsets and
    poses together with the poses eliminated (Golub & Pereyra 1973), halved while it raises the
    residuals.  Where it stops, every row's pose is fitted afresh from each start
    pose and the descent goes on from the better of the two, up to :data:`START_BRANCHES`
    times: a row fitted on offsets far off may have been left in another branch of its pose.
    ``(poses (N, s), offsets (n,), rms over the rows used)``, the poses fitted to those
    offsets."""
    poses = np.where(data.pose_known[:, None], data.poses, 0.0)
    nominal = Geometry.of(robot)
    best: tuple[float, np.ndarray, np.ndarray] | None = None
    for _ in range(START_BRANCHES):
        if rows.size:
            fresh, cost = _multistart_poses(robot, nominal, offsets, data, rows)
            if best is not None:
                warm, warm_cost = _row_poses(robot, nominal, offsets, data, rows, best[2][rows])
                fresh = np.where((warm_cost <= cost)[:, None], warm, fresh)
            poses[rows] = fresh
        found = _descend_offsets(robot, nominal, data, rows, offsets, poses, used)
        if best is not None and found[0] >= best[0] * (1.0 - START_GAIN):
            break
        best = found
        if not (rows.size and data.changes.any()):
            # nothing to refit afresh, or no offsets to move: one descent is the answer
            break
        offsets, poses = found[1].copy(), found[2].copy()
    assert best is not None
    return best[2], best[1], best[0]


def _descend_offsets(
    robot: Robot,
    nominal: Geometry,
    data: Measurements,
    rows: np.ndarray,
    offsets: np.ndarray,
    poses: np.ndarray,
    used: np.ndarray,
) -> tuple[float, np.ndarray, np.ndarray]:
    """:func:`_project`'s descent from ``poses`` fitted to ``offsets``: ``(rms, offsets,
    poses)``, the poses fitted to those offsets."""
    n, s = robot.n_cables, robot.pose_size
    changed = np.flatnonzero(data.changes)
    unknown = np.isin(used, rows)
    P = unknown[:, None, None] * _start_prior(robot)
    rr = np.repeat(used, n)
    cc = np.tile(np.arange(n), used.size)
    mask = data.measured[used]
    poses = poses.copy()
    best: tuple[float, np.ndarray, np.ndarray] | None = None
    delta = np.zeros(changed.size)
    for step in range(START_ROUNDS):
        if rows.size and step > 0:
            poses[rows], cost = _row_poses(robot, nominal, offsets, data, rows, poses[rows])
            # rows that fit far worse than the others may sit in another branch: start them afresh
            stray = rows[cost > RESTART_FACTOR * np.median(cost)]
            if stray.size:
                fresh, fresh_cost = _multistart_poses(robot, nominal, offsets, data, stray)
                take = fresh_cost < cost[np.searchsorted(rows, stray)]
                poses[stray[take]] = fresh[take]
        part = partials(robot, nominal, poses, rr, cc)
        r = (part.length.reshape(-1, n) - np.where(data.changes, offsets, 0.0) - data.values[used]) * mask
        rms = float(np.sqrt((r * r).sum() / max(int(mask.sum()), 1)))
        if best is not None and rms >= best[0]:
            # the step overshot: go back and take half of it
            delta /= 2
            if np.abs(delta).max() < START_TOL:
                break
            offsets = best[1].copy()
            offsets[changed] -= delta
            continue
        best = (rms, offsets.copy(), poses.copy())
        if not changed.size:
            break
        # the Gauss–Newton step of offsets and poses together, the poses eliminated (their
        # orientation prior included, as the rows' fits have it)
        Jq = part.pose.reshape(-1, n, s) * (mask & unknown[:, None])[..., None]
        A = np.einsum("kis,kit->kst", Jq, Jq) + P + 1e-12 * np.eye(s)
        G = np.einsum("kis,ki->ks", Jq, r) + np.einsum("kst,kt->ks", P, poses[used])
        Jo = -(mask[:, :, None] & (np.arange(n)[:, None] == changed[None, :])[None]).astype(float)
        C = np.einsum("kic,kis->kcs", Jo, Jq)
        X = np.linalg.solve(A, np.concatenate([np.swapaxes(C, 1, 2), G[..., None]], axis=2))
        H = np.einsum("kic,kid->cd", Jo, Jo) - np.einsum("kcs,ksd->cd", C, X[..., :-1])
        g = np.einsum("kic,ki->c", Jo, r) - np.einsum("kcs,ks->c", C, X[..., -1])
        delta = np.linalg.lstsq(H, g, rcond=None)[0]
        if np.abs(delta).max() < START_TOL:
            break
        offsets = offsets.copy()
        offsets[changed] -= delta
    assert best is not None
    return best


def _start(robot: Robot, data: Measurements, rows: np.ndarray, keep: np.ndarray) -> list[tuple[np.ndarray, np.ndarray]]:
    """Start poses and offsets (module docstring): the best :data:`FITTED_STARTS` hypotheses
    (the best one alone when more than :data:`SCORE_ROWS` rows rank them), each
    ``(poses (N, s), offsets (n,))``."""
    used = np.flatnonzero(keep & data.measured.any(axis=1))
    changed = np.flatnonzero(data.changes)
    if not changed.size:
        poses, offsets, _ = _project(robot, data, rows, np.zeros(robot.n_cables), used)
        return [(poses, offsets)]
    from taut.kinematics import cable_lengths

    # hypotheses: the medians of the changes were measured at the centroid, or a central row was
    values = np.where(data.measured, data.values, np.nan)[used]
    median = np.nanmedian(values, axis=0)
    distance = np.nansum((np.nan_to_num(values - median, nan=0.0)) ** 2, axis=1)
    central = used[np.argsort(distance)[:START_ROWS]]
    sample = used[:: max(1, used.size // SCORE_ROWS)]
    sample_unknown = np.intersect1d(sample, rows)
    start = _starts(robot)[0]
    lengths = np.atleast_2d(cable_lengths(robot, start))[0]
    hypotheses = []
    for r in [-1, *central]:
        offsets = np.zeros(robot.n_cables)
        measured = data.measured[r] if r >= 0 else np.zeros(robot.n_cables, bool)
        offsets[changed] = np.where(
            measured[changed], lengths[changed] - data.values[r, changed], lengths[changed] - median[changed]
        )
        poses, offsets, rms = _project(robot, data, sample_unknown, offsets, sample)
        hypotheses.append((rms, offsets, poses))
    hypotheses.sort(key=lambda h: h[0])
    if sample.size == used.size:
        return [(poses, offsets) for _, offsets, poses in hypotheses[:FITTED_STARTS]]
    # more rows than the sample: the sample ranks the hypotheses, the best one starts the fit
    return [_project(robot, data, rows, hypotheses[0][1], used)[:2]]


def _reseed(
    problem: Problem,
    data: Measurements,
    fit: Any,
    x: np.ndarray,
    loss: tuple[str, float],
    dense: bool,
    budget: int | None = None,
) -> tuple[Any, np.ndarray, int]:
    """Refit every unknown pose from the :func:`_starts` on the fitted geometry; where one fits
    its row markedly better (a row left in another branch of its pose, which its few redundant
    cables fit almost as well), take it and fit everything again (on ``budget``), until no row
    moves or :data:`RESEED_ROUNDS` times.  ``(fit, x, evaluations)``."""
    L = problem.layout
    rows = L.unknown_rows
    evaluations = 0
    for _ in range(RESEED_ROUNDS if rows.size else 0):
        geometry, offsets, poses = problem.unpack(x)
        fresh, cost = _multistart_poses(L.robot, geometry, offsets, data, rows)
        r = problem.residuals(x)
        now = np.bincount(L.rows, r * r, minlength=len(L.known_poses))[rows]
        better = cost < RESEED_GAIN * now
        if not better.any():
            break
        poses[rows[better]] = fresh[better]
        trial = _fit(problem, L.pack(geometry, offsets, poses), loss[0], loss[1], dense, budget)
        evaluations += trial.nfev
        if trial.cost >= fit.cost:
            break
        fit, x = trial, trial.x
    return fit, x, evaluations


def _fit(problem: Problem, x0: np.ndarray, loss: str, scale: float, dense: bool, budget: int | None = None) -> Any:
    max_nfev = budget or MAX_EVALUATIONS * max(len(x0), 1)
    if not dense:
        return levenberg_marquardt(problem, x0, loss=loss, scale=scale, max_nfev=max_nfev)
    from scipy.optimize import least_squares

    return least_squares(
        problem.residuals,
        x0,
        jac=lambda x: problem.jacobian(x).toarray(),
        method="trf",
        tr_solver="exact",
        x_scale="jac",
        loss=loss,
        f_scale=scale,
        xtol=1e-12,
        ftol=1e-12,
        gtol=1e-10,
        max_nfev=max_nfev,
    )


def _descend(
    problem: Problem, data: Measurements, starts: list[np.ndarray], robust: str | None, scale: float, dense: bool
) -> tuple[Any, np.ndarray, tuple[str, float], int]:
    """The fit from the best of ``starts`` (module docstring): each fitted on a short budget by
    the ``robust`` loss at ``scale`` and then at twice the residuals' robust deviation (without
    ``robust``, by :data:`BASIN_LOSS` at that deviation alone), the best one re-seeded, fitted
    to convergence and re-seeded; without ``robust``, the least-squares fit follows from there,
    re-seeded again.  ``(fit, x, loss, evaluations)``."""
    evaluations = 0
    best = None
    for x in starts:
        budget = None if len(starts) == 1 else START_EVALUATIONS
        for f_scale in (scale, None) if robust else (None,):
            if f_scale is None:
                f_scale = max(2.0 * _robust_sigma(problem.residuals(x)), 1e-12)
            loss = (robust or BASIN_LOSS, f_scale)
            fit = _fit(problem, x, *loss, dense, budget)
            x, evaluations = fit.x, evaluations + fit.nfev
        if best is None or fit.cost < best[0].cost:
            best = (fit, x, loss)
    assert best is not None
    fit, x, loss = best
    if len(starts) > 1:
        # rows in another branch of their pose move before the fit to convergence, which
        # would otherwise crawl along the valley they make
        fit, x, spent = _reseed(problem, data, fit, x, loss, dense, START_EVALUATIONS)
        fit = _fit(problem, x, *loss, dense)
        x, evaluations = fit.x, evaluations + fit.nfev + spent
    fit, x, spent = _reseed(problem, data, fit, x, loss, dense)
    evaluations += spent
    if robust is None:
        loss = ("linear", 1.0)
        fit = _fit(problem, x, *loss, dense)
        evaluations += fit.nfev
        fit, x, spent = _reseed(problem, data, fit, fit.x, loss, dense)
        evaluations += spent
    return fit, x, loss, evaluations


def _standardized(problem: Problem, x: np.ndarray) -> np.ndarray:
    """Each residual over ``√(1 − h)``, ``h`` its leverage in its row's pose block: a row's few
    redundant cables leave its residuals far smaller than the noise, unequally.  0 for a
    residual that its row's pose fits exactly (no redundancy: no outlier can be seen there)."""
    L = problem.layout
    residual = problem.residuals(x)
    _, Jq, _ = problem.blocks(x)
    A = np.linalg.pinv(np.einsum("kis,kit->kst", Jq, Jq), rcond=1e-12, hermitian=True)
    h = np.einsum("kis,kst,kit->ki", Jq, A, Jq)[L.rows, L.cables]
    free = 1.0 - h
    return np.where(free > 1e-6, residual / np.sqrt(np.maximum(free, 1e-6)), 0.0)


def _robust_sigma(r: np.ndarray) -> float:
    return float(1.4826 * np.median(np.abs(r))) if r.size else 0.0


def calibrate(
    robot: Robot,
    data: Measurements,
    *,
    estimate: tuple[str, ...] = ("exits", "offsets"),
    robust: str | None = None,
    scale: float = ROBUST_SCALE,
    dense: bool = False,
) -> CalibrationResult:
    """Estimate a built robot's geometry from its own cable measurements (module docstring).

    Parameters
    ----------
    robot : Robot
        The nominal robot: the start of the estimated parameters and the value of the others.
    data : Measurements
        Rows of lengths or length changes, with measured poses where known
        (:func:`read_measurements`, :func:`measurements`, :func:`simulate_measurements`).
    estimate : sequence of str
        From ``exits``, ``offsets`` (of the cables measured as changes: required with them),
        ``anchors``, ``radii`` (of the swivelling pulleys).
    robust : {None, "soft_l1", "huber"}
        Robust loss of the outlier-resistant first fits.
    scale : float
        The first robust fit's residual scale [m].
    dense : bool
        Solve with ``scipy.optimize.least_squares`` on the dense Jacobian (trust region
        reflective; the benchmark's baseline).

    Returns
    -------
    CalibrationResult

    Raises
    ------
    UnsupportedRobotError
        A robot with jointed bodies, obstacles, sagging or routed cables; ``radii`` without
        swivelling pulleys; anchors of a point mass.
    TautError
        An unknown estimate or loss; changes measured without estimating their offsets.

    References
    ----------
    .. [1] P. H. Borgstrom et al., "NIMS-PL: A Cable-Driven Robot With Self-Calibration
       Capabilities", IEEE Transactions on Robotics 25(5), 2009, the self-calibration section.
       (docs/references.bib: borgstrom2009)
    .. [2] P. Miermeister, A. Pott, "Auto-Calibration Method for Overconstrained Cable-Driven
       Parallel Robots", IEEE ICRA 2012. (docs/references.bib: miermeister2012)
    .. [3] B. Triggs, P. F. McLauchlan, R. I. Hartley, A. W. Fitzgibbon, "Bundle Adjustment —
       A Modern Synthesis", LNCS 1883, Springer, 2000, §6 and §9.
       (docs/references.bib: triggs2000)

    Examples
    --------
    Exits 2 cm off, encoders counting from an unknown zero, 40 unknown poses:

    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.calibration import calibrate, plan_poses, simulate_measurements
    >>> nominal = example("printer-5cable")
    >>> rng = np.random.default_rng(1)
    >>> exits = nominal.exits + rng.uniform(-0.02, 0.02, nominal.exits.shape)
    >>> built = nominal.model_copy(update={"cables": tuple(
    ...     c.model_copy(update={"exit": tuple(e)}) for c, e in zip(nominal.cables, exits))})
    >>> poses = plan_poses(nominal, 40, seed=0).poses
    >>> data = simulate_measurements(built, poses, offsets=[2.0] * 5, sigma=1e-4, seed=2)
    >>> res = calibrate(nominal, data)
    >>> res.identifiable, bool(np.all(res.exits_std < 0.01)), res.offsets.round(2).tolist()
    (True, True, [2.0, 2.0, 2.0, 2.0, 2.0])
    """
    began = time.perf_counter()
    refuse_unsupported(robot)
    if not isinstance(data, Measurements) or data.values.shape[1:] != (robot.n_cables,):
        raise TautError(f"data: expected Measurements of {robot.name}'s {robot.n_cables} cables")
    if data.poses.shape[1] != robot.pose_size:
        raise TautError(f"data: its poses have {data.poses.shape[1]} coordinates, {robot.name}'s {robot.pose_size}")
    exits_on, anchors_on, radii_on = parse_estimate(robot, estimate, data)
    names = tuple(e for e in ("exits", "offsets", "anchors", "radii") if e in estimate)
    if robust is not None and robust not in ROBUST_LOSSES:
        raise TautError(f"robust: unknown loss {robust!r}; expected None or one of {', '.join(ROBUST_LOSSES)}")
    scale = as_number(scale, "scale", positive=True)
    as_count(data.rows, "data rows")
    keep = np.ones(data.rows, bool)
    layout = Layout.build(robot, data, exits=exits_on, anchors=anchors_on, radii=radii_on)
    problem = Problem(layout)
    nominal = problem.nominal
    starts = [layout.pack(nominal, offsets, poses) for poses, offsets in _start(robot, data, layout.unknown_rows, keep)]
    evaluations = 0
    if radii_on:
        # the radii, weakly seen beside the exits, wander off while the poses are still far
        # from their own: the fit with the nominal radii starts the one that frees them
        fixed = Problem(Layout.build(robot, data, exits=exits_on, anchors=anchors_on))
        staged = [fixed.layout.pack(*problem.unpack(x)) for x in starts]
        _, x, _, evaluations = _descend(fixed, data, staged, robust, scale, dense)
        starts = [layout.pack(*fixed.unpack(x))]
    fit, x, loss, spent = _descend(problem, data, starts, robust, scale, dense)
    evaluations += spent
    scaled = _standardized(problem, x)
    noise = _robust_sigma(scaled)
    bad = np.abs(scaled) > OUTLIER_THRESHOLD * noise if noise > 0 else np.zeros(scaled.size, bool)
    outliers = np.unique(layout.rows[bad])
    if robust is not None:
        keep[outliers] = False
        geometry, offsets, poses = problem.unpack(x)
        layout = Layout.build(robot, data, exits=exits_on, anchors=anchors_on, radii=radii_on, keep=keep)
        problem = Problem(layout)
        fit = _fit(problem, layout.pack(geometry, offsets, poses), "linear", 1.0, dense)
        x, evaluations = fit.x, evaluations + fit.nfev
        full_poses = poses
    geometry, offsets, poses = problem.unpack(x)
    if robust is not None:
        poses[~keep] = full_poses[~keep]
    gauge = _gauge(layout)
    exits, anchors = geometry.exits, geometry.anchors
    if gauge.startswith(GAUGE_RULE):
        if anchors_on:
            Q, t = rigid_alignment(anchors, robot.anchors)
            anchors = anchors @ Q.T + t
            poses = _move_poses(robot, poses, Q, t, body=True)
        if exits_on:
            Q, t = _align_exits(robot, exits)
            exits = exits @ Q.T + t
            poses = _move_poses(robot, poses, Q, t, body=False)
        geometry = Geometry(exits, anchors, geometry.radii)
        x = layout.pack(geometry, offsets, poses)
    residual = problem.residuals(x)
    rep = report(problem, x, data, keep)
    std = _std(layout, residual, rep)
    sigma = _sigma(layout, residual, rep)
    n, d = robot.n_cables, robot.dimension
    exits_std = np.zeros((n, d))
    offsets_std = np.zeros(n)
    anchors_std = np.zeros((n, d))
    radii_std = np.zeros(n)
    at = 0
    if exits_on:
        exits_std = std[: n * d].reshape(n, d)
        at = n * d
    offsets_std[layout.offset_cables] = std[at : at + layout.offset_cables.size]
    at += layout.offset_cables.size
    if anchors_on:
        anchors_std = std[at : at + n * d].reshape(n, d)
        at += n * d
    radii_std[layout.radius_cables] = std[at : at + layout.radius_cables.size]
    sq = np.bincount(layout.cables, residual**2, minlength=n)
    count = np.bincount(layout.cables, minlength=n)
    return CalibrationResult(
        robot_name=robot.name,
        estimate=names,
        exits=exits,
        exits_std=exits_std,
        offsets=offsets,
        offsets_std=offsets_std,
        changes=data.changes.copy(),
        anchors=anchors,
        anchors_std=anchors_std,
        radii=geometry.radii.copy(),
        radii_std=radii_std,
        poses=poses,
        pose_known=data.pose_known.copy(),
        residual_rms=np.sqrt(sq / np.maximum(count, 1)),
        sigma=sigma,
        outliers=tuple(int(k) for k in outliers),
        robust=robust,
        gauge=gauge,
        identifiability=rep.result,
        converged=bool(fit.status > 0),
        evaluations=int(evaluations),
        elapsed_s=time.perf_counter() - began,
    )


def _align_exits(robot: Robot, exits: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The motion ``x ↦ Q x + t`` of the gauge rule that best aligns the estimated ``exits`` onto
    the nominal ones: rigid (Kabsch), for a point mass improper too — its mirror image fits the
    same lengths; with swivelling pulleys only what keeps their axes, fixed in the world: a turn
    about their common axis (and, for a point mass, a mirror in a plane through it), or a
    translation alone when the axes differ."""
    nominal = robot.exits
    mirror = robot.is_point_mass
    if not robot.swivel_cables:
        return rigid_alignment(exits, nominal, reflection=mirror)
    d = robot.dimension
    Q = np.eye(d)
    k = common_axis(robot)
    if k is not None:
        from scipy.linalg import null_space

        B = null_space(k[None])
        src = (exits - exits.mean(axis=0)) @ B
        dst = (nominal - nominal.mean(axis=0)) @ B
        if d == 3:
            turn = rigid_alignment(src, dst, reflection=mirror)[0]
        else:
            turn = -np.eye(1) if mirror and float(src[:, 0] @ dst[:, 0]) < 0 else np.eye(1)
        Q = B @ turn @ B.T + np.outer(k, k)
    return Q, nominal.mean(axis=0) - exits.mean(axis=0) @ Q.T


def _gauge(layout: Layout) -> str:
    """The gauge rule that applies to ``layout``."""
    if layout.unknown_rows.size < len(layout.known_poses) or not layout.unknown_rows.size:
        return GAUGE_MEASURED
    if not layout.exits and not layout.anchors:
        return GAUGE_FIXED_EXITS
    if not layout.exits:
        return GAUGE_FIXED_EXITS + "; the estimated anchors are aligned onto the nominal ones (the platform frame)"
    swivel = GAUGE_RULE_SWIVEL if layout.robot.swivel_cables else ""
    return GAUGE_RULE + swivel + (GAUGE_RULE_ANCHORS if layout.anchors else "")


def _sigma(layout: Layout, residual: np.ndarray, rep: Any) -> float:
    dof = residual.size - rep.result.unknowns
    return float(np.sqrt(residual @ residual / dof)) if dof > 0 else float("inf")


def _std(layout: Layout, residual: np.ndarray, rep: Any) -> np.ndarray:
    """Standard deviation of each parameter in the gauge of the result (module docstring);
    ``inf`` for a parameter that an undetermined direction moves."""
    P = layout.n_params
    sigma = _sigma(layout, residual, rep)
    if not np.isfinite(sigma) or rep.M.size == 0:
        return np.full(P, np.inf if not np.isfinite(sigma) else 0.0)
    w, V = np.linalg.eigh(rep.M)
    # the directions the report calls undetermined (condition beyond MAX_CONDITION) get no variance
    sv = np.sqrt(np.clip(w, 0.0, None))
    good = sv > sv.max() / MAX_CONDITION if sv.max() > 0 else np.zeros(w.size, bool)
    ZV = rep.Z @ V
    cov_diag = (ZV[:, good] ** 2 / w[good]).sum(axis=1) * sigma**2
    std = np.sqrt(cov_diag)
    if (~good).any():
        moved = (np.abs(ZV[:, ~good]) > 1e-6).any(axis=1)
        std[moved] = np.inf
    return std
