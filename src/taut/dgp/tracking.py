"""Tracking forward kinematics: the equilibrium that follows a known one when the cable
lengths change a little (``001_eb92e2f6589fc229.txt`` §4.1.2, "Forward kinematics" of the
real-time control routine and its "Remarks on the real-time procedure").

One update from the equilibrium ``x₀`` (reference points and scaled tensions of its taut
subset, :mod:`taut.dgp.formulation`) to the new lengths ``ρ₁``:

1. Newton on the same sub-problem's equations with the new lengths, from ``x₀``;
2. the Krawczyk test of :mod:`taut.interval.krawczyk` on the box centred at the Newton
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
constants ``ρ_i²`` of the length equations, which are patched per update).  A single taut
cable leaves the spin about the vertical free (a continuum, §2.3): its Jacobian is
singular and tracking it raises :class:`~taut.errors.TrackingLostError`.
"""

from __future__ import annotations

import weakref
from dataclasses import dataclass, field

import numpy as np

from taut.dgp.formulation import Subproblem, build_subproblem, load
from taut.dgp.solve import DGPSolution, check_lengths
from taut.dgp.stability import is_stable
from taut.errors import TautError, TrackingLostError
from taut.geometry.rotation import angles_from_matrix, rotation_matrix
from taut.interval.expression import CONST, SQR
from taut.interval.krawczyk import certified_step
from taut.model.robot import Robot

#: Relative floor of the Krawczyk box half-width (a zero step still needs a box).
BOX_FLOOR = 1e-8
#: The box half-width is this multiple of the step, so the previous equilibrium is inside.
BOX_MARGIN = 1.25
#: A step that fails is split in two at most this many times (2¹⁰ sub-steps).
MAX_HALVINGS = 10


@dataclass(frozen=True)
class _Compiled:
    """A sub-problem compiled once, and where its length constants sit in the tape."""

    sub: Subproblem
    nodes: np.ndarray  #: tape index of the CONST node ``ρ_i`` of each taut cable's length equation

    def system(self, lengths: np.ndarray):
        """The square system with the lengths ``lengths``: its length constants are
        patched in place (one update at a time per process, as tracking runs)."""
        tape = self.sub.system.tape
        rho = lengths[list(self.sub.taut)]
        tape.clo[self.nodes] = rho
        tape.chi[self.nodes] = rho
        return self.sub.system


@dataclass
class _RobotCache:
    load_point: np.ndarray  #: body-frame point where the external wrench acts
    subsets: dict = field(default_factory=dict)  #: taut subset → :class:`_Compiled`


_CACHE: dict[int, _RobotCache] = {}


def _cache(robot: Robot) -> _RobotCache:
    key = id(robot)
    rc = _CACHE.get(key)
    if rc is None:
        rc = _CACHE[key] = _RobotCache(load(robot)[2])
        weakref.finalize(robot, _CACHE.pop, key, None)
    return rc


def _compiled(robot: Robot, taut: tuple[int, ...]) -> _Compiled:
    per_robot = _cache(robot).subsets
    c = per_robot.get(taut)
    if c is None:
        ones = np.ones(robot.n_cables)  # placeholder lengths, patched per update
        sub = build_subproblem(robot, ones, taut)
        tape = sub.system.tape
        nodes = []
        for j in range(len(taut)):  # length equations follow the 3 rigidity relations
            root = tape.end[3 + j] - 1  # dist² − ρ²: SUB(dist², SQR(CONST ρ))
            sq = tape.b[root]
            assert tape.op[sq] == SQR and tape.op[tape.a[sq]] == CONST and tape.clo[tape.a[sq]] == 1.0
            nodes.append(tape.a[sq])
        c = per_robot[taut] = _Compiled(sub, np.array(nodes, np.int64))
    return c


@dataclass(frozen=True)
class _State:
    taut: tuple[int, ...]  #: 0-based
    lengths: np.ndarray
    p: np.ndarray
    R: np.ndarray
    tensions: np.ndarray  #: all n cables


def _unknowns(c: _Compiled, s: _State, lengths: np.ndarray) -> np.ndarray:
    """The sub-problem's unknowns (reference points, ``τ/ρ``) of a pose and tensions."""
    q = s.p + c.sub.body_refs @ s.R.T
    if not c.sub.tension_unknowns:
        return q.ravel()
    idx = list(c.sub.taut)
    return np.concatenate([q.ravel(), s.tensions[idx] / lengths[idx]])


def _attempt(robot: Robot, s: _State, taut: tuple[int, ...], lengths: np.ndarray):
    """Newton + Krawczyk on subset ``taut``; ``(state, box width)`` or a reason string."""
    if not 2 <= len(taut) <= 6:
        return f"a taut set of {len(taut)} cable(s) has no isolated equilibrium to track"
    c = _compiled(robot, taut)
    system = c.system(lengths)
    status, x, lo, hi = certified_step(system, _unknowns(c, s, lengths), margin=BOX_MARGIN, floor=BOX_FLOOR)
    if status == "newton-failed":
        return "Newton did not converge"
    if status != "unique":
        kind = "holds no equilibrium" if status == "empty" else "was not proven to hold a unique equilibrium"
        return f"the Krawczyk box of half-width {0.5 * np.max(hi - lo):.3g} around the step {kind}"
    p, R = c.sub.frame(x)
    n = robot.n_cables
    return _State(taut, lengths, p, R, c.sub.tensions(x, lengths, n)), float(np.max(hi - lo))


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
    a, r = robot.exits, robot.anchors
    taut, tried = s.taut, []
    while True:
        tried.append(taut)
        out = _attempt(robot, s, taut, lengths)
        if isinstance(out, str):
            raise TrackingLostError(f"tracking lost with taut cables {[i + 1 for i in taut]} "
                                    f"at lengths {lengths.tolist()}: {out}")
        new, width = out
        negative = [i for i in taut if new.tensions[i] < 0.0]
        slack = [k for k in range(robot.n_cables) if k not in taut]
        dist = np.zeros(robot.n_cables)
        if slack:
            dist[slack] = np.linalg.norm(new.p + r[slack] @ new.R.T - a[slack], axis=1)
        stretched = [k for k in slack if dist[k] > lengths[k]]
        if not negative and not stretched:
            return new, width
        if negative:  # drop the most negative tension first, then re-check
            drop = min(negative, key=lambda i: new.tensions[i])
            nxt = tuple(i for i in taut if i != drop)
        else:  # add the most stretched slack cable (starting tension 0)
            add = max(stretched, key=lambda k: dist[k] - lengths[k])
            nxt = tuple(sorted(taut + (add,)))
        if nxt in tried:
            raise TrackingLostError(f"tracking lost at lengths {lengths.tolist()}: the taut set cycles through "
                                    f"{[[i + 1 for i in t] for t in tried]}")
        taut = nxt


def _state(robot: Robot, sol: DGPSolution, lengths: np.ndarray) -> _State:
    """The state of ``sol``, about to move to ``lengths``: the lengths it holds are its
    taut cables' spans (a solution does not carry them) and, for its slack cables, the new
    ``lengths`` (they enter no equation)."""
    if robot.dimension != 3 or robot.is_point_mass or robot.n_joints:
        raise TautError("tracking handles spatial rigid platforms without joints")
    tau = np.asarray(sol.tensions, float)
    if tau.shape != (robot.n_cables,):
        raise TautError(f"{robot.name} has {robot.n_cables} cables, the solution has {tau.size} tensions")
    taut = tuple(sorted(int(i) - 1 for i in sol.taut))
    p = np.asarray(sol.position, float)
    R = rotation_matrix(np.asarray(sol.orientation, float), robot.orientation)
    held = lengths.copy()
    held[list(taut)] = np.linalg.norm(p + robot.anchors[list(taut)] @ R.T - robot.exits[list(taut)], axis=1)
    return _State(taut, held, p, R, tau)


def _solution(robot: Robot, s: _State, lengths: np.ndarray, width: float) -> DGPSolution:
    idx = list(s.taut)
    gp = _cache(robot).load_point
    b = s.p + robot.anchors @ s.R.T
    stable = is_stable(robot.exits[idx], b[idx], s.p + s.R @ gp, s.tensions[idx], lengths[idx])
    return DGPSolution(tuple(i + 1 for i in s.taut), s.p, angles_from_matrix(s.R, robot.orientation),
                       s.tensions, stable, width, 0.0)


def track(robot: Robot, previous_solution, lengths) -> DGPSolution:
    """The equilibrium that continues ``previous_solution`` (a :class:`DGPSolution` or an
    :class:`~taut.dgp.inverse.IGPSolution`) at the new cable ``lengths`` (see the module
    docstring); raises :class:`~taut.errors.TrackingLostError` when it
    cannot be certified.  ``certificate_width`` is the width of the Krawczyk enclosure;
    ``uniqueness_radius`` is not computed (0)."""
    lengths = check_lengths(robot, lengths)
    s, width = _step(robot, _state(robot, previous_solution, lengths), lengths)
    return _solution(robot, s, lengths, width)


def track_path(robot: Robot, start_solution, lengths_sequence) -> list[DGPSolution]:
    """:func:`track` along a sequence of cable lengths (one solution per row)."""
    try:
        rows = np.asarray(lengths_sequence, dtype=float)
    except ValueError as e:
        raise TautError(f"the lengths sequence is not a table of numbers: {e}") from None
    if rows.size == 0:
        return []
    if rows.ndim != 2 or rows.shape[1] != robot.n_cables:
        raise TautError(f"{robot.name} has {robot.n_cables} cables: give one row of {robot.n_cables} lengths "
                        f"per update, got an array of shape {rows.shape}")
    for row in rows[~np.all(np.isfinite(rows) & (rows > 0), axis=1)][:1]:
        check_lengths(robot, row)  # raises, naming what is wrong
    out, s = [], None
    for lengths in rows:
        s = _state(robot, start_solution, lengths) if s is None else s
        s, width = _step(robot, s, lengths)
        out.append(_solution(robot, s, lengths, width))
    return out
