"""Tracking forward kinematics: the equilibrium that follows a known one when the cable
lengths change a little (Berti 2015, §4.1.2, "Forward kinematics" of the
real-time control routine and its "Remarks on the real-time procedure").

One update from the equilibrium ``x₀`` (reference points and scaled tensions of its taut
subset, :mod:`taut.dgp._formulation`) to the new lengths ``ρ₁``:

1. Newton on the same sub-problem's equations with the new lengths, from ``x₀``;
2. the Krawczyk test of :mod:`taut.interval._krawczyk` on the box centred at the Newton
   limit ``x₁`` whose half-width covers the step ``‖x₁ − x₀‖∞`` (the role of the source's
   Kantorovich test on the velocity-bounded box around ``Y₀``): ``K(X) ⊂ int X`` proves that
   ``X`` — which holds the previous equilibrium — holds exactly one equilibrium for ``ρ₁``,
   so the update cannot have jumped to another branch.  Anything else (no convergence, an
   empty or undecided test) raises :class:`~taut.errors.TrackingLostError`: the source stops
   the robot there;
3. taut-set changes (the source's sub-DGP switch): a taut cable whose tension came out
   negative is dropped, a slack cable whose anchor is now farther from its exit point than
   its length is added, and step 1–2 is redone from ``x₀`` on the new subset;
4. a step that cannot be certified is halved — tracked to the mid lengths, then on — up to
   :data:`MAX_HALVINGS` times: the certified box is only as large as the region where the
   Jacobian stays regular (§3.2.1), and near a platform's swinging modes a millimetre of
   cable moves the unknowns by more than that.  The source's control rate keeps its steps
   small instead.

The sub-problem of each taut subset is compiled once per robot (the lengths only enter the
constants ``ρ_i²`` of the length equations, which are patched per update), and steps 1–2
together with everything a solution reports — the frame, the tensions, the slack cables'
spans and the stability test of §3.2.2 — run in one compiled call (:func:`_update`): at a
few tens of microseconds per update, Python-side array code would cost more than the
arithmetic.  A single taut cable leaves the spin about the vertical free (a continuum,
§2.3): its Jacobian is singular and tracking it raises
:class:`~taut.errors.TrackingLostError`.  A planar platform (:mod:`taut.dgp._planar`) is
tracked on one to three taut cables (one cable fixes its angle), by the same Newton and
Krawczyk steps from Python.

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §4.1.2 (real-time forward kinematics), §3.2.
   (docs/references.bib: berti2015)
"""

from __future__ import annotations

import weakref
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt
from numba import njit

from taut._checks import as_array
from taut.dgp import _planar
from taut.dgp._formulation import Subproblem, build_subproblem, frame_from_points, load, refuse_unmodelled
from taut.dgp._inverse import IGPSolution
from taut.dgp._point_mass import PointMassTracker, pivot
from taut.dgp._pulleys import cable_spans, check_pulley_reach, pulley_update
from taut.dgp._solve import DGPSolution, check_lengths
from taut.dgp._stability import smallest_eigenvalue
from taut.errors import TautError, TrackingLostError
from taut.geometry import CONVENTIONS, matrix_angles
from taut.interval import CONST, SQR, certified_step, point_kernel
from taut.model import Robot

#: Relative floor of the Krawczyk box half-width (a zero step still needs a box).
BOX_FLOOR = 1e-8
#: The box half-width is this multiple of the step, so the previous equilibrium is inside.
BOX_MARGIN = 1.25
#: A step that fails is split in two at most this many times (2¹⁰ sub-steps).
MAX_HALVINGS = 10


#: What :func:`_update` returns: status, p, R, angles, tensions, spans, eigenvalue, box width.
Update = tuple[int, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, float, float]


@dataclass(frozen=True)
class _Compiled:
    """A sub-problem compiled once, and where its length constants sit in the tape."""

    sub: Subproblem
    nodes: np.ndarray  #: tape index of the CONST node ``ρ_i`` of each taut cable's length equation
    args: tuple  #: the leading arguments of :func:`_update` (tapes, geometry, taut indices)

    def update(self, lengths: np.ndarray, s: _State) -> Update:
        """:func:`_update` from ``s`` to ``lengths``: the length constants of the tape are
        patched in place first (one update at a time per process, as tracking runs)."""
        tape = self.sub.system.tape
        rho = lengths[list(self.sub.taut)]
        tape.clo[self.nodes] = rho
        tape.chi[self.nodes] = rho
        # numba's Dispatcher is typed as taking no arguments
        return _update(*self.args, lengths, s.p, s.R, s.tensions)  # type: ignore[call-arg]


@dataclass(frozen=True)
class _PlanarCompiled:
    """A planar platform's sub-problem compiled once (:class:`taut.dgp._planar.Tracker`)."""

    tracker: _planar.Tracker

    def update(self, lengths: np.ndarray, s: _State) -> Update:
        return self.tracker.update(lengths, s.p, s.R, s.tensions)


@dataclass
class _RobotCache:
    load_point: np.ndarray  #: body-frame point where the external wrench acts
    convention: int  #: index of the robot's orientation convention in ``CONVENTIONS``
    subsets: dict = field(default_factory=dict)  #: taut subset → :class:`_Compiled`


_CACHE: dict[int, _RobotCache] = {}


def _cache(robot: Robot) -> _RobotCache:
    key = id(robot)
    rc = _CACHE.get(key)
    if rc is None:
        rc = _CACHE[key] = _RobotCache(load(robot)[2], CONVENTIONS.index(robot.orientation))
        weakref.finalize(robot, _CACHE.pop, key, None)
    return rc


def _compiled(robot: Robot, taut: tuple[int, ...]) -> _Compiled | _PlanarCompiled | PointMassTracker:
    if robot.is_point_mass:
        return PointMassTracker(robot, taut, BOX_MARGIN, BOX_FLOOR)
    rc = _cache(robot)
    per_robot = rc.subsets
    c = per_robot.get(taut)
    if c is None and robot.dimension == 2:
        c = per_robot[taut] = _PlanarCompiled(_planar.Tracker(robot, taut, BOX_MARGIN, BOX_FLOOR))
    if c is None:
        # placeholder lengths, patched per update: distinct, so that the tape's hash-consing
        # cannot merge two cables' ρ (or a ρ with another constant) into one node
        marks = 1.0 + np.sqrt(2.0) / 7.0 + np.arange(robot.n_cables)
        sub = build_subproblem(robot, marks, taut, normal=False)
        tape = sub.system.tape
        nodes = []
        for j, i in enumerate(taut):  # length equations follow the 3 rigidity relations
            root = tape.end[3 + j] - 1  # dist² − ρ²: SUB(dist², SQR(CONST ρ))
            sq = tape.b[root]
            k = tape.a[sq]
            assert tape.op[sq] == SQR and tape.op[k] == CONST and tape.clo[k] == marks[i]
            assert tape.parents(k) == 1, "a length constant is shared: it cannot be patched per update"
            nodes.append(k)
        system, statics = sub.system, sub.statics.tape
        args = (
            *system.tape.arrays[:7],
            system.n_equations,
            *system.jacobian.arrays[:7],
            system.rows,
            system.cols,
            *statics.arrays[:7],
            sub.body_refs,
            robot.anchors,
            robot.exits,
            rc.load_point,
            np.array(taut, np.int64),
            rc.convention,
        )
        c = per_robot[taut] = _Compiled(sub, np.array(nodes, np.int64), args)
    return c


@dataclass(frozen=True)
class _State:
    taut: tuple[int, ...]  #: 0-based
    lengths: np.ndarray
    p: np.ndarray
    R: np.ndarray
    tensions: np.ndarray  #: all n cables
    angles: np.ndarray | None = None  #: orientation in the robot's convention (not kept for a start state)
    stable: bool = False


@njit(cache=True)
def _update(
    op: np.ndarray,
    a: np.ndarray,
    b: np.ndarray,
    clo: np.ndarray,
    chi: np.ndarray,
    start: np.ndarray,
    end: np.ndarray,
    h: int,
    jop: np.ndarray,
    ja: np.ndarray,
    jb: np.ndarray,
    jclo: np.ndarray,
    jchi: np.ndarray,
    jstart: np.ndarray,
    jend: np.ndarray,
    rows: np.ndarray,
    cols: np.ndarray,
    sop: np.ndarray,
    sa: np.ndarray,
    sb: np.ndarray,
    sclo: np.ndarray,
    schi: np.ndarray,
    sstart: np.ndarray,
    send: np.ndarray,
    refs: np.ndarray,
    anchors: np.ndarray,
    exits: np.ndarray,
    gp: np.ndarray,
    idx: np.ndarray,
    convention: int,
    lengths: np.ndarray,
    p0: np.ndarray,
    R0: np.ndarray,
    tau0: np.ndarray,
) -> Update:
    """Steps 1–2 of the module docstring and the solution's data, in one compiled call.

    The unknowns of the pose ``(p0, R0)`` and tensions ``tau0`` (the three ``refs``
    reference points, then ``τ/ρ`` unless six cables are taut) start
    :func:`~taut.interval.certified_step`; from its limit come the frame (:func:`~taut.dgp._formulation.frame_from_points`), the tensions
    (for six taut cables the square statics of the ``s*`` tape, §3.1.3), every cable's
    span ``‖b_i − a_i‖`` and the smallest eigenvalue of the reduced Hessian (§3.2.2).
    Returns ``(status, p, R, angles, tensions, spans, eigenvalue, box width)``; status as
    :func:`certified_step` (1: certified)."""
    n, m, pose = anchors.shape[0], idx.size, 9
    x0 = np.empty(h)
    for s in range(3):
        x0[3 * s : 3 * s + 3] = p0 + R0 @ refs[s]
    for j in range(h - pose):
        x0[pose + j] = tau0[idx[j]] / lengths[idx[j]]
    status, x, lo, hi = certified_step(
        op,
        a,
        b,
        clo,
        chi,
        start,
        end,
        h,
        jop,
        ja,
        jb,
        jclo,
        jchi,
        jstart,
        jend,
        rows,
        cols,
        x0,
        BOX_MARGIN,
        BOX_FLOOR,
        1e-13,
        30,
        10,
    )
    width = np.max(hi - lo)
    tau, spans = np.zeros(n), np.zeros(n)
    if status != 1:
        return status, p0, R0, np.zeros(3), tau, spans, 0.0, width
    p, R = frame_from_points(np.ascontiguousarray(x[:9]).reshape(3, 3), refs)
    if h > pose:
        for j in range(m):
            tau[idx[j]] = x[pose + j] * lengths[idx[j]]
    else:
        vals = np.empty(sstart.size)
        point_kernel(sop, sa, sb, sclo, schi, sstart, send, x, vals)
        t = np.linalg.solve(np.ascontiguousarray(vals[: 6 * m]).reshape(6, m), vals[6 * m :])
        for j in range(m):
            tau[idx[j]] = t[j] * lengths[idx[j]]
    for i in range(n):
        spans[i] = np.sqrt(np.sum((p + R @ anchors[i] - exits[i]) ** 2))
    at, bt, taut_tau, rho = np.empty((m, 3)), np.empty((m, 3)), np.empty(m), np.empty(m)
    for j in range(m):
        at[j], bt[j] = exits[idx[j]], p + R @ anchors[idx[j]]
        taut_tau[j], rho[j] = tau[idx[j]], lengths[idx[j]]
    eig = smallest_eigenvalue(at, bt, p + R @ gp, taut_tau, rho)
    ang = matrix_angles(R.reshape(1, 3, 3), convention)[0]
    return status, p, R, ang, tau, spans, eig, width


def _attempt(
    robot: Robot, s: _State, taut: tuple[int, ...], lengths: np.ndarray
) -> str | tuple[_State, float, np.ndarray]:
    """Newton + Krawczyk on subset ``taut``; ``(state, box width)`` or a reason string."""
    least: int
    most: int
    if robot.is_point_mass:
        least, most = 1, robot.dimension
    else:
        least, most = (1, _planar.MAX_TAUT) if robot.dimension == 2 else (2, 6)
    if not least <= len(taut) <= most:
        return f"a taut set of {len(taut)} cable(s) has no isolated equilibrium to track"
    if robot.swivel_cables:
        status, p, R, ang, tau, spans, eig, width = pulley_update(
            robot, taut, lengths, s.p, s.R, s.tensions, BOX_MARGIN, BOX_FLOOR
        )
    else:
        status, p, R, ang, tau, spans, eig, width = _compiled(robot, taut).update(lengths, s)
    if status == -1:
        return "Newton did not converge"
    if status != 1:
        kind = "holds no equilibrium" if status == 2 else "was not proven to hold a unique equilibrium"
        return f"the Krawczyk box of half-width {0.5 * width:.3g} around the step {kind}"
    return _State(taut, lengths, p, R, tau, ang, bool(eig > 0.0)), float(width), spans


def _step(robot: Robot, s: _State, lengths: np.ndarray, halvings: int = MAX_HALVINGS) -> tuple[_State, float]:
    """The certified state at ``lengths`` from ``s``, halving the step when it fails."""
    try:
        return _advance(robot, s, lengths)
    except TrackingLostError:
        if halvings == 0:
            raise
    mid, _ = _step(robot, s, 0.5 * (s.lengths + lengths), halvings - 1)
    return _step(robot, mid, lengths, halvings - 1)


def _advance(robot: Robot, s: _State, lengths: np.ndarray) -> tuple[_State, float]:
    taut, tried = s.taut, []
    while True:
        tried.append(taut)
        out = _attempt(robot, s, taut, lengths)
        if isinstance(out, str):
            raise TrackingLostError(
                f"tracking lost with taut cables {[i + 1 for i in taut]} at lengths {lengths.tolist()}: {out}"
            )
        new, width, dist = out
        negative = [i for i in taut if new.tensions[i] < 0.0]
        stretched = [k for k in range(robot.n_cables) if k not in taut and dist[k] > lengths[k]]
        if not negative and not stretched:
            return new, width
        if negative:  # drop the most negative tension first, then re-check
            drop = min(negative, key=lambda i: new.tensions[i])
            nxt = tuple(i for i in taut if i != drop)
        else:  # add the most stretched slack cable (starting tension 0)
            add = max(stretched, key=lambda k: dist[k] - lengths[k])
            nxt = tuple(sorted(taut + (add,)))
            if robot.is_point_mass and len(nxt) > robot.dimension:
                # a point hangs on at most d cables: the added one takes the place of one of them
                nxt = pivot(robot, new.p, new.tensions, lengths, taut, add)
        if nxt in tried:
            raise TrackingLostError(
                f"tracking lost at lengths {lengths.tolist()}: the taut set cycles through "
                f"{[[i + 1 for i in t] for t in tried]}"
            )
        taut = nxt


def _state(robot: Robot, sol: DGPSolution | IGPSolution, lengths: np.ndarray) -> _State:
    """The state of ``sol``, about to move to ``lengths``: the lengths it holds are its
    taut cables' spans (a solution does not carry them) and, for its slack cables, the new
    ``lengths`` (they enter no equation)."""
    refuse_unmodelled(robot, "tracking")
    if not isinstance(sol, (DGPSolution, IGPSolution)):
        raise TautError(f"tracking starts from a DGPSolution or an IGPSolution, got a {type(sol).__name__}")
    check_pulley_reach(robot, lengths)
    tau = np.asarray(sol.tensions, float)
    if tau.shape != (robot.n_cables,):
        raise TautError(f"{robot.name} has {robot.n_cables} cables, the solution has {tau.size} tensions")
    taut = tuple(sorted(int(i) for i in sol.taut))
    p = np.asarray(sol.position, float)
    if p.shape != (robot.dimension,):
        raise TautError(f"{robot.name} is {robot.dimension}-D, the solution's position has {p.size} coordinates")
    R = np.eye(p.size) if robot.is_point_mass else _planar.rotation(robot, np.asarray(sol.orientation, float))
    held = lengths.copy()
    if robot.swivel_cables:
        held[list(taut)] = cable_spans(robot, p + robot.anchors @ R.T)[list(taut)]
    else:
        held[list(taut)] = np.linalg.norm(p + robot.anchors[list(taut)] @ R.T - robot.exits[list(taut)], axis=1)
    return _State(taut, held, p, R, tau)


def _solution(s: _State, width: float) -> DGPSolution:
    assert s.angles is not None, "a certified step sets the angles"
    return DGPSolution(tuple(s.taut), s.p, s.angles, s.tensions, s.stable, width, 0.0)


def track_equilibrium(robot: Robot, solution: DGPSolution | IGPSolution, lengths: npt.ArrayLike) -> DGPSolution:
    """The equilibrium that continues ``solution`` at new cable lengths (module docstring).

    Parameters
    ----------
    robot : Robot
        A platform without joints: rigid, spatial or planar, or a point mass, spatial or
        planar (Newton and Krawczyk on the system of :mod:`taut.dgp._point_mass`; a single
        taut cable is then an isolated equilibrium, tracked too).  The cables of a spatial
        rigid platform may leave through swivelling pulleys (each update then builds the
        pulley sub-problem of :mod:`taut.dgp._pulleys` afresh, in milliseconds rather than
        microseconds).
    solution : DGPSolution or IGPSolution
        The equilibrium before the change.
    lengths : array_like, shape (n,)
        The new cable lengths [m].

    Returns
    -------
    DGPSolution
        Certified: ``certificate_width`` is the width of the Krawczyk enclosure;
        ``uniqueness_radius`` is not computed (0).

    Raises
    ------
    TrackingLostError
        The new equilibrium cannot be certified (it left the branch, or one taut cable of a
        rigid platform is left: a continuum).
    TautError
        A jointed robot, lengths that are not ``n`` positive numbers, a pulley radius not
        smaller than its cable's length, or a ``solution`` that is not one.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §4.1.2. (docs/references.bib: berti2015)

    Examples
    --------
    The stable pose of Table 4.3 of Berti (2015), with cable 1 paid out by 1 cm.

    >>> import numpy as np
    >>> from taut.dgp import solve_igp, track_equilibrium, track_path
    >>> from taut.model import example
    >>> robot = example("suspended-3cable")
    >>> start = solve_igp(robot, [0, 1, 2], {"x": 2.7505, "y": 3.9798, "z": 5.5061}).solutions[0]
    >>> moved = track_equilibrium(robot, start, np.array(robot.reference.lengths) + [0.01, 0, 0])
    >>> moved.taut, np.round(moved.position, 3), moved.stable
    ((0, 1, 2), array([2.753, 3.984, 5.511]), True)
    """
    lengths = check_lengths(robot, lengths)
    s, width = _step(robot, _state(robot, solution, lengths), lengths)
    return _solution(s, width)


def track_path(robot: Robot, solution: DGPSolution | IGPSolution, lengths: npt.ArrayLike) -> list[DGPSolution]:
    """:func:`track_equilibrium` from ``solution`` along a sequence of cable lengths.

    Parameters
    ----------
    robot : Robot
    solution : DGPSolution or IGPSolution
        The equilibrium at the start.
    lengths : array_like, shape (T, n)
        One row of cable lengths [m] per update.

    Returns
    -------
    list of DGPSolution
        One per row.

    Raises
    ------
    TrackingLostError
        An update cannot be certified.
    TautError
        Lengths that are not rows of ``n`` positive numbers.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §4.1.2. (docs/references.bib: berti2015)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.dgp import solve_igp, track_equilibrium, track_path
    >>> from taut.model import example
    >>> robot = example("suspended-3cable")
    >>> start = solve_igp(robot, [0, 1, 2], {"x": 2.7505, "y": 3.9798, "z": 5.5061}).solutions[0]
    >>> rows = np.array(robot.reference.lengths) + np.linspace(0, 0.02, 5)[:, None] * [1, 0, 0]
    >>> path = track_path(robot, start, rows)
    >>> len(path), np.round(path[-1].position, 3)
    (5, array([2.756, 3.988, 5.515]))
    """
    rows = as_array(lengths, "the lengths sequence", finite=False)
    if rows.size == 0:
        return []
    if rows.ndim != 2 or rows.shape[1] != robot.n_cables:
        raise TautError(
            f"{robot.name} has {robot.n_cables} cables: give one row of {robot.n_cables} lengths "
            f"per update, got an array of shape {rows.shape}"
        )
    for row in rows[~np.all(np.isfinite(rows) & (rows > 0), axis=1)][:1]:
        check_lengths(robot, row)  # raises, naming what is wrong
    out, s = [], None
    for step in rows:
        s = _state(robot, solution, step) if s is None else s
        s, width = _step(robot, s, step)
        out.append(_solution(s, width))
    return out
