"""What a calibration data set determines: the gauge, the information about the parameters
once the poses are eliminated, and the undetermined combinations in words.

With unknown poses only, a rigid motion of the exits and of every pose (3 degrees of freedom in
the plane, 6 in space) leaves every length as it was, and so does a change of the platform
frame when the anchors are estimated: these are gauge freedoms (Triggs et al. 2000, §9), fixed
after the fit by aligning the estimate onto the nominal robot (:mod:`taut.calibration._fit`).
Their directions ``G`` are removed: the gauge-fixed parameter space is ``Z``, an orthonormal
basis of ``Gᵀ δ = 0`` (the linearised alignment).

The poses are eliminated by the Schur complement of the normal equations (Triggs et al. 2000,
§6.1, the reduced camera system): each row ``k`` with an unknown pose adds
``S_k = J_pᵀ J_p − J_pᵀ J_q (J_qᵀ J_q)⁺ J_qᵀ J_p`` to the information ``S`` about the parameters
(a measured pose adds ``J_pᵀ J_p``).  The identifiability report is then the rank and condition
number of ``Zᵀ S Z`` (as a Jacobian: the square roots of its eigenvalues), the eigenvectors of
its small eigenvalues named by parameter, the rows whose pose their own cables do not fix, and
the recognisable degenerate designs: a single pose, all rows identical, fewer measurements than
unknowns, a cable whose anchor stays on one line (its exit turns about it) or in one plane (its
exit mirrored in that plane fits equally) — poses that Borgstrom et al. (2009) require the
self-calibration of NIMS-PL to avoid.

References
----------
.. [1] B. Triggs, P. F. McLauchlan, R. I. Hartley, A. W. Fitzgibbon, "Bundle Adjustment — A
   Modern Synthesis", Vision Algorithms: Theory and Practice, LNCS 1883, Springer, 2000, §6.1
   and §9. (docs/references.bib: triggs2000)
.. [2] P. H. Borgstrom et al., "NIMS-PL: A Cable-Driven Robot With Self-Calibration
   Capabilities", IEEE Transactions on Robotics 25(5), 2009, the self-calibration section
   (the poses that leave it degenerate). (docs/references.bib: borgstrom2009)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from taut._results import Result
from taut.calibration._data import Measurements, measurements
from taut.calibration._model import Geometry, Layout, Problem, swivel_axes
from taut.errors import TautError, UnsupportedRobotError
from taut.model import Robot

#: Largest condition number of the gauge-fixed, pose-eliminated Jacobian for which the data
#: count as determining the parameters: beyond it, a millimetre of noise moves a combination
#: of parameters by a kilometre.
MAX_CONDITION = 1e6

#: Singular values below this fraction of the largest are zero (rank).
RANK_RTOL = 1e-9

#: A cable's anchor points count as on one line (in one plane) when their spread across it is
#: below this fraction of their spread along it.  With unknown poses the fit bends points that
#: were measured on a line by about the noise over the exits' errors (a few per cent): a design
#: that close to degenerate leaves exits undetermined by decimetres.
FLAT_RTOL = 0.05

#: Swivel axes count as parallel when their unit vectors differ by less than this.
AXIS_RTOL = 1e-9

#: What ``estimate`` may name.
ESTIMATES = ("exits", "offsets", "anchors", "radii")


@dataclass(frozen=True)
class Identifiability(Result):
    """What a data set determines (module docstring).

    Attributes
    ----------
    identifiable : bool
        Every estimated parameter and every unknown pose is determined (full rank, condition
        number at most :data:`MAX_CONDITION`, no degenerate design recognised).
    rank : int
        Rank of the gauge-fixed Jacobian: of the parameters after the poses are eliminated,
        plus each unknown pose's own.
    unknowns : int
        Its columns: the parameters and unknown pose coordinates, less the gauge freedoms.
    condition : float
        Condition number of the gauge-fixed Jacobian of the parameters with the poses
        eliminated (``inf`` where it is singular).
    gauge : int
        Gauge freedoms removed (rigid motions of everything, of the platform frame).
    observations : int
        Measured lengths.
    undetermined : tuple of str
        The combinations the data do not determine, in words.
    ambiguities : tuple of str
        Discrete ambiguities: other solutions that fit the data equally.
    """

    identifiable: bool
    rank: int
    unknowns: int
    condition: float
    gauge: int
    observations: int
    undetermined: tuple[str, ...]
    ambiguities: tuple[str, ...]


def common_axis(robot: Robot) -> np.ndarray | None:
    """The unit direction that every swivel axis of ``robot`` shares (up to sign), or None when
    they differ; None too for a robot without swivelling pulleys."""
    axes = swivel_axes(robot)[list(robot.swivel_cables)]
    if not len(axes):
        return None
    k = axes[0]
    if np.abs(np.cross(axes, k) if robot.dimension == 3 else axes[:, 0] * k[1] - axes[:, 1] * k[0]).max() > AXIS_RTOL:
        return None
    return k


def _rigid_directions(points: np.ndarray, robot: Robot, *, frame: bool) -> np.ndarray:
    """``(n·d, g)``: the infinitesimal rigid motions of ``points (n, d)`` that no length sees —
    translations, then rotations about their centroid.  For the exits (``frame`` False) of a
    robot with swivelling pulleys, whose axes are fixed in the world, only the rotations that
    keep every axis: about their common axis in space, none otherwise."""
    n, d = points.shape
    c = points - points.mean(axis=0)
    cols = [np.tile(np.eye(d)[k], n) for k in range(d)]
    if not frame and robot.swivel_cables:
        axis = common_axis(robot)
        if axis is not None and d == 3:
            cols.append(np.cross(axis, c).ravel())
    elif d == 2:
        cols.append(np.column_stack([-c[:, 1], c[:, 0]]).ravel())
    else:
        for k in range(3):
            cols.append(np.cross(np.eye(3)[k], c).ravel())
    return np.column_stack(cols)


def gauge_directions(layout: Layout, geometry: Geometry) -> np.ndarray:
    """``(P, g)``: the parameter directions that a change of frame leaves unseen — the rigid
    motions of the exits when they are estimated, and of the anchors (the platform frame) when
    they are, if no row has a measured pose."""
    P = layout.n_params
    cols = []
    if not (~np.isin(np.arange(len(layout.known_poses)), layout.unknown_rows)).any() and layout.unknown_rows.size:
        nd = layout.n * layout.d
        if layout.exits:
            moves = _rigid_directions(geometry.exits, layout.robot, frame=False)
            g = np.zeros((P, moves.shape[1]))
            g[:nd] = moves
            cols.append(g)
        if layout.anchors:
            start = (nd if layout.exits else 0) + layout.offset_cables.size
            moves = _rigid_directions(geometry.anchors, layout.robot, frame=True)
            g = np.zeros((P, moves.shape[1]))
            g[start : start + nd] = moves
            cols.append(g)
    return np.concatenate(cols, axis=1) if cols else np.zeros((P, 0))


def row_information(problem: Problem, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per row, the information ``S_k (N, P, P)`` about the parameters with its pose eliminated
    (module docstring), and the rank of its pose block (``s`` where the pose is measured)."""
    Jp, Jq, _ = problem.blocks(x)
    L = problem.layout
    S = np.einsum("kip,kiq->kpq", Jp, Jp)
    ranks = np.full(len(Jp), L.s)
    if L.unknown_rows.size:
        u = L.unknown_rows
        A = np.einsum("kis,kit->kst", Jq[u], Jq[u])
        B = np.einsum("kis,kip->ksp", Jq[u], Jp[u])
        Ainv = np.linalg.pinv(A, rcond=RANK_RTOL**2, hermitian=True)
        S[u] -= np.einsum("ksp,kst,ktq->kpq", B, Ainv, B)
        sv = np.sqrt(np.clip(np.linalg.eigvalsh(A), 0.0, None))
        ranks[u] = (sv > RANK_RTOL * np.maximum(sv.max(axis=1, keepdims=True), 1e-300)).sum(axis=1)
    return S, ranks


def gauge_basis(G: np.ndarray, P: int) -> np.ndarray:
    """``Z (P, P − g)``: an orthonormal basis of ``Gᵀ δ = 0``."""
    if G.shape[1] == 0:
        return np.eye(P)
    from scipy.linalg import null_space

    return null_space(G.T)


def _flatness(points: np.ndarray) -> np.ndarray:
    """Singular values of the centred ``points``, largest first (their spread per direction)."""
    if len(points) < 2:
        return np.zeros(points.shape[1])
    return np.linalg.svd(points - points.mean(axis=0), compute_uv=False)


def _designs(problem: Problem, x: np.ndarray, data: Measurements, keep: np.ndarray) -> tuple[list[str], list[str]]:
    """The degenerate designs recognised in the data (module docstring): ``(undetermined,
    ambiguities)``, in words."""
    L = problem.layout
    robot = L.robot
    geometry, _, poses = problem.unpack(x)
    anchors = geometry.anchors
    undetermined: list[str] = []
    ambiguities: list[str] = []
    used = np.flatnonzero(keep & data.measured.any(axis=1))
    distinct = np.unique(
        np.column_stack([np.where(data.measured, data.values, np.nan), data.poses, data.pose_known])[used], axis=0
    )
    if len(used) == 1:
        undetermined.append("a single pose")
    elif len(distinct) == 1:
        undetermined.append("all rows identical: the data hold a single pose")
    gauge = gauge_directions(L, geometry).shape[1]
    free = L.n_unknowns - gauge
    if L.rows.size < free:
        undetermined.append(
            f"fewer measurements than unknowns: {L.rows.size} lengths for {free} unknowns "
            f"({L.n_params} parameters and {L.unknown_rows.size} poses of {L.s} coordinates, less {gauge} of gauge)"
        )
    if not L.exits or len(used) < 2 or robot.swivel_cables:
        # a swivel axis fixed in the world breaks the symmetries of these designs: the
        # Jacobian's rank and condition judge them
        return undetermined, ambiguities
    d = robot.dimension
    p = poses[:, :d]
    if robot.is_point_mass:
        spread = _flatness(p[used])
        groups: list[tuple[str, np.ndarray, int]] = [("all poses", spread, -1)]
    else:
        from taut.calibration._model import frames

        _, R, _ = frames(robot, poses)
        groups = []
        for i in range(L.n):
            rows = used[data.measured[used, i]]
            b = p[rows] + R[rows] @ anchors[i]
            groups.append((f"cable {i + 1}'s anchor", _flatness(b), i))
    line = [g for g in groups if g[1][0] > 0 and g[1][1] <= FLAT_RTOL * g[1][0]]
    plane = [
        g for g in groups if d == 3 and g[1][0] > 0 and g[1][1] > FLAT_RTOL * g[1][0] and g[1][2] <= FLAT_RTOL * g[1][0]
    ]
    if robot.is_point_mass:
        if line and d == 3:
            undetermined.append("all poses on one line: each exit can turn about that line")
        elif line:
            ambiguities.append("all poses on one line: each exit mirrored in that line fits equally")
        elif plane:
            ambiguities.append("all poses in one plane: each exit mirrored in that plane fits equally")
    else:
        for what, _, i in line:
            if d == 3:
                undetermined.append(f"{what} stayed on one line: exit {i + 1} can turn about that line")
            else:
                ambiguities.append(f"{what} stayed on one line: exit {i + 1} mirrored in that line fits equally")
        for what, _, i in plane:
            ambiguities.append(f"{what} stayed in one plane: exit {i + 1} mirrored in that plane fits equally")
    return undetermined, ambiguities


def _named(v: np.ndarray, labels: list[str]) -> str:
    """A null direction in words: its largest components, with their signed weights."""
    v = v / np.abs(v).max()
    top = np.argsort(-np.abs(v))
    parts = [f"{labels[j]} ({v[j]:+.2f})" for j in top[:6] if abs(v[j]) >= 0.3]
    more = int((np.abs(v) >= 0.3).sum()) - len(parts)
    return "together: " + ", ".join(parts) + (f" and {more} more" if more > 0 else "")


@dataclass(frozen=True)
class Report:
    """The identifiability report and what the covariance needs: ``Z``, the reduced information
    ``M = Zᵀ S Z`` and its eigen-decomposition."""

    result: Identifiability
    Z: np.ndarray
    M: np.ndarray
    null: np.ndarray


def report(problem: Problem, x: np.ndarray, data: Measurements, keep: np.ndarray) -> Report:
    """The identifiability of the estimate ``x`` of ``problem`` (module docstring)."""
    L = problem.layout
    geometry, _, _ = problem.unpack(x)
    S_rows, ranks = row_information(problem, x)
    S = S_rows.sum(axis=0)
    G = gauge_directions(L, geometry)
    Z = gauge_basis(G, L.n_params)
    M = Z.T @ S @ Z
    w, V = np.linalg.eigh(M) if M.size else (np.zeros(0), np.zeros((0, 0)))
    sv = np.sqrt(np.clip(w, 0.0, None))
    top = sv.max() if sv.size else 0.0
    rank_params = int((sv > RANK_RTOL * top).sum()) if top > 0 else 0
    condition = float(top / sv.min()) if sv.size and sv.min() > 0 else (1.0 if not sv.size else np.inf)
    weak = sv <= top / MAX_CONDITION if top > 0 else np.ones(sv.size, bool)
    undetermined, ambiguities = _designs(problem, x, data, keep)
    labels = L.param_labels()
    for j in np.flatnonzero(weak):
        undetermined.append(_named(Z @ V[:, j], labels))
    rows = L.unknown_rows
    for k in rows[ranks[rows] < L.s][:10]:
        cables = int(data.measured[k].sum())
        undetermined.append(f"the pose of row {k + 1}: its {cables} measured cable{'s' * (cables != 1)} do not fix it")
    short = int((ranks[rows] < L.s).sum()) - 10
    if short > 0:
        undetermined.append(f"the poses of {short} more rows")
    unknowns = Z.shape[1] + rows.size * L.s
    result = Identifiability(
        identifiable=not undetermined,
        rank=rank_params + int(ranks[rows].sum()),
        unknowns=unknowns,
        condition=condition,
        gauge=G.shape[1],
        observations=int(L.rows.size),
        undetermined=tuple(undetermined),
        ambiguities=tuple(ambiguities),
    )
    return Report(result, Z, M, V[:, weak] if M.size else np.zeros((0, 0)))


def parse_estimate(robot: Robot, estimate: object, data: Measurements | None = None) -> tuple[bool, bool, bool]:
    """``(exits, anchors, radii)`` from ``estimate``, a sequence of :data:`ESTIMATES`; raises
    for an unknown name, for ``radii`` of a robot without swivelling pulleys, for anchors of a
    point mass and for changes without ``offsets``."""
    try:
        names: tuple[object, ...] = (estimate,) if isinstance(estimate, str) else tuple(estimate)  # type: ignore[arg-type]
    except TypeError:
        raise TautError(f"estimate: expected names from {', '.join(ESTIMATES)}, got {estimate!r}") from None
    for name in names:
        if name not in ESTIMATES:
            raise TautError(f"estimate: unknown {name!r}; expected names from {', '.join(ESTIMATES)}")
    if not names:
        raise TautError(f"estimate: expected at least one of {', '.join(ESTIMATES)}")
    if "radii" in names and not robot.swivel_cables:
        raise UnsupportedRobotError(
            f"{robot.name}: no cable leaves through a swivelling pulley (cables[].swivel): no radius to estimate"
        )
    if "anchors" in names and robot.is_point_mass:
        raise UnsupportedRobotError(f"{robot.name}: a point mass has no anchors to estimate")
    if data is not None and data.changes.any() and "offsets" not in names:
        raise TautError("the data give length changes (dl columns): their offsets are unknown; estimate offsets too")
    return "exits" in names, "anchors" in names, "radii" in names


def identifiability(
    robot: Robot,
    poses: npt.ArrayLike,
    *,
    estimate: tuple[str, ...] = ("exits", "offsets"),
    changes: bool = True,
    known_poses: bool = False,
) -> Identifiability:
    """What measuring every cable at ``poses`` would determine about the robot.

    Parameters
    ----------
    robot : Robot
        The nominal robot, at which the Jacobian is evaluated.
    poses : array_like, shape (N, pose_size)
        The poses to be measured.
    estimate : sequence of str
        Names from :data:`ESTIMATES`: ``exits``, ``offsets``, ``anchors``, ``radii`` (of the
        swivelling pulleys).
    changes : bool
        The cables are measured as length changes from an encoder zero (offsets unknown).
    known_poses : bool
        The poses are measured too (a tracker): no gauge, no pose unknowns.

    Returns
    -------
    Identifiability

    Raises
    ------
    PoseError
        Poses that :func:`taut.kinematics.as_poses` refuses.
    UnsupportedRobotError
        A robot with jointed bodies, obstacles, sagging or routed cables; ``radii`` without
        swivelling pulleys; anchors of a point mass.

    References
    ----------
    .. [1] B. Triggs, P. F. McLauchlan, R. I. Hartley, A. W. Fitzgibbon, "Bundle Adjustment — A
       Modern Synthesis", Vision Algorithms: Theory and Practice, LNCS 1883, Springer, 2000,
       §6.1 and §9. (docs/references.bib: triggs2000)

    Examples
    --------
    Poses on one line leave each exit free to turn about it:

    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.calibration import identifiability
    >>> robot = example("printer-5cable")
    >>> line = np.column_stack([np.linspace(-0.5, 0.5, 20), np.zeros(20), np.full(20, 1.0)])
    >>> rep = identifiability(robot, line)
    >>> rep.identifiable, rep.undetermined[0]
    (False, 'all poses on one line: each exit can turn about that line')
    """
    from taut.kinematics import as_poses

    arr, _ = as_poses(robot, poses)
    problem, x, data = design(robot, arr, estimate=estimate, changes=changes, known_poses=known_poses)
    return report(problem, x, data, np.ones(data.rows, bool)).result


def design(
    robot: Robot, poses: np.ndarray, *, estimate: object, changes: bool, known_poses: bool
) -> tuple[Problem, np.ndarray, Measurements]:
    """The calibration problem of measuring every cable of the nominal ``robot`` at checked
    ``poses``, and its point ``x`` at the nominal robot (zero residuals)."""
    from taut.kinematics import cable_lengths

    lengths = np.atleast_2d(cable_lengths(robot, poses))
    data = measurements(
        robot,
        None if changes else lengths,
        changes=lengths if changes else None,
        poses=poses if known_poses else None,
    )
    exits_on, anchors_on, radii_on = parse_estimate(robot, estimate, data)
    layout = Layout.build(robot, data, exits=exits_on, anchors=anchors_on, radii=radii_on)
    problem = Problem(layout)
    return problem, layout.pack(problem.nominal, np.zeros(robot.n_cables), poses), data
