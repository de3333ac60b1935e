"""The measurement model of calibration and its analytic Jacobian.

Row *k* measures cable *i* as ``y_ki = l_i(a_i, r_i, q_k) − o_i`` (``o_i = 0`` for an absolute
length, the unknown encoder offset for a length change), with ``l_i = ‖a_i − b_i‖``,
``b_i = p_k + R(q_k) r_i`` (``docs/architecture.md`` §2.4).  With ``u_i = (a_i − b_i)/l_i``, the
cable's unit vector from the platform to its exit, and ``m_i = (R r_i) × u_i`` its column of
the structure matrix's moment rows (Rushton 2022, Eqs. 2.8 and 2.10):

* ``∂l/∂a_i = u_i`` (the exit), ``∂l/∂o_i = −1`` for the residual of a length change;
* ``∂l/∂r_i = −Rᵀ u_i`` (the anchor, in the platform frame);
* ``∂l/∂p = −u_i`` and ``∂l/∂q = −m_iᵀ E(q)`` (``ω = E(q) q̇``): the pose derivatives are the
  transposed structure matrix, negated, its moment rows through the rate matrix.

A cable through a swivelling pulley (exit point ``a_i`` on the swivel axis ``k_i``, radius
``ρ_i``) has the length ``l_i = ρ_i β + l_f`` of :mod:`taut.kinematics` (Pott 2018): the wound arc
and the free length ``l_f`` from the tangent point ``C`` to the anchor.  Because ``C`` is the
point of tangency, ``∂l/∂b = −u_i`` with ``u_i = (C − b_i)/l_f``, and, the axis held, ``∂l/∂a_i = u_i``:
the same formulas with ``u_i`` through the tangent point.  In the pulley plane, with the
anchor at ``x = w − ρ`` from the pulley centre across the axis (``w`` its distance from the
axis) and ``h = k·(b − a)`` along it, ``ϱ² = x² + h²`` and ``l_f = √(ϱ² − ρ²)``, differentiating
``β = atan2(x, h) + atan2(ρ, l_f)`` gives

* ``∂l/∂ρ = β − (x l_f + ρ h)/ϱ²`` (``β − sin β`` as ``ρ → 0``).

Each residual touches one cable's parameters and one row's pose: the Jacobian is the sparse
block pattern of bundle adjustment (Triggs et al. 2000, §6, Fig. 3), which ``least_squares``
takes as a sparse matrix.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §2.1.1, Eqs. 2.1, 2.8 and 2.10. (docs/references.bib: rushton2022)
.. [2] A. Pott, "Cable-Driven Parallel Robots: Theory and Application", Springer Tracts in
   Advanced Robotics 120, Springer, 2018, pulley kinematics. (docs/references.bib: pott2018)
.. [3] B. Triggs, P. F. McLauchlan, R. I. Hartley, A. W. Fitzgibbon, "Bundle Adjustment — A
   Modern Synthesis", Vision Algorithms: Theory and Practice, LNCS 1883, Springer, 2000, §6
   (the sparse structure of the normal equations). (docs/references.bib: triggs2000)
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from taut.calibration._data import Measurements
from taut.geometry import planar_rotation, rate_matrix, rotation_matrix
from taut.model import Robot

#: A cable shorter than this [m] has no direction: its length is floored there, so that a
#: solver's trial step through an exit gives a large residual, not a division by zero.
FLOOR_LENGTH = 1e-9


@dataclass(frozen=True)
class Geometry:
    """What calibration may estimate of a robot's cables: exit points and platform anchors
    ``(n, d)``, and the radius of each cable's swivelling pulley ``(n,)`` (0 for a cable
    without one)."""

    exits: np.ndarray
    anchors: np.ndarray
    radii: np.ndarray

    @staticmethod
    def of(robot: Robot) -> Geometry:
        """The nominal geometry of ``robot``."""
        radii = np.zeros(robot.n_cables)
        for i, cable in enumerate(robot.cables):
            if cable.swivel is not None:
                radii[i] = cable.swivel.radius
        return Geometry(robot.exits, robot.anchors, radii)


def swivel_axes(robot: Robot) -> np.ndarray:
    """``(n, d)``: each cable's unit swivel axis (zeros for a cable without a swivelling pulley)."""
    axes = np.zeros((robot.n_cables, robot.dimension))
    for i, cable in enumerate(robot.cables):
        if cable.swivel is not None:
            axes[i] = np.asarray(cable.swivel.axis, float) / np.linalg.norm(cable.swivel.axis)
    return axes


@dataclass(frozen=True)
class Layout:
    """Where each unknown sits in the vector ``x`` of the least-squares problem, and the
    observations (row, cable, value) in row order.

    ``x`` is ``[exits (n·d) | offsets (one per cable measured by changes) | anchors (n·d) |
    radii (one per swivelling pulley) | poses of the rows without a measured pose (U·s)]``, each
    block present when estimated.
    """

    robot: Robot
    exits: bool
    anchors: bool
    radius_cables: np.ndarray
    offset_cables: np.ndarray
    unknown_rows: np.ndarray
    rows: np.ndarray
    cables: np.ndarray
    values: np.ndarray
    change: np.ndarray
    known_poses: np.ndarray

    @staticmethod
    def build(
        robot: Robot,
        data: Measurements,
        *,
        exits: bool,
        anchors: bool,
        radii: bool = False,
        keep: np.ndarray | None = None,
    ) -> Layout:
        """The layout of ``data`` (its rows where ``keep``), estimating the exits, anchors and
        pulley radii as asked and the offsets of every cable measured by changes."""
        measured = data.measured if keep is None else data.measured & keep[:, None]
        rows, cables = np.nonzero(measured)
        return Layout(
            robot,
            exits,
            anchors,
            np.array(robot.swivel_cables if radii else (), dtype=int),
            np.flatnonzero(data.changes),
            np.flatnonzero(~data.pose_known & measured.any(axis=1)),
            rows,
            cables,
            data.values[rows, cables],
            data.changes[cables],
            np.where(data.pose_known[:, None], data.poses, 0.0),
        )

    @property
    def n(self) -> int:
        return self.robot.n_cables

    @property
    def d(self) -> int:
        return self.robot.dimension

    @property
    def s(self) -> int:
        return self.robot.pose_size

    @property
    def n_params(self) -> int:
        """Unknowns other than the poses: exits, offsets, anchors, radii."""
        nd = self.n * self.d
        return (
            (nd if self.exits else 0) + self.offset_cables.size + (nd if self.anchors else 0) + self.radius_cables.size
        )

    @property
    def n_unknowns(self) -> int:
        return self.n_params + self.unknown_rows.size * self.s

    def pack(self, geometry: Geometry, offsets: np.ndarray, poses: np.ndarray) -> np.ndarray:
        """``x`` from full arrays: the geometry, offsets ``(n,)``, poses ``(N, s)``."""
        parts = [geometry.exits.ravel()] if self.exits else []
        parts.append(offsets[self.offset_cables])
        if self.anchors:
            parts.append(geometry.anchors.ravel())
        parts.append(geometry.radii[self.radius_cables])
        parts.append(poses[self.unknown_rows].ravel())
        return np.concatenate(parts)

    def unpack(self, x: np.ndarray, nominal: Geometry) -> tuple[Geometry, np.ndarray, np.ndarray]:
        """Full ``(geometry, offsets, poses)`` from ``x``: what is not estimated from the
        ``nominal`` geometry, the measured poses from the data."""
        n, d = self.n, self.d
        exits, anchors, radii = nominal.exits, nominal.anchors, nominal.radii
        at = 0
        if self.exits:
            exits = x[: n * d].reshape(n, d)
            at = n * d
        offsets = np.zeros(n)
        offsets[self.offset_cables] = x[at : at + self.offset_cables.size]
        at += self.offset_cables.size
        if self.anchors:
            anchors = x[at : at + n * d].reshape(n, d)
            at += n * d
        if self.radius_cables.size:
            radii = radii.copy()
            radii[self.radius_cables] = x[at : at + self.radius_cables.size]
            at += self.radius_cables.size
        poses = self.known_poses.copy()
        poses[self.unknown_rows] = x[at:].reshape(-1, self.s)
        return Geometry(exits, anchors, radii), offsets, poses

    def param_labels(self) -> list[str]:
        """A name per parameter of ``x`` (not the poses), cables numbered from 1."""
        axes = "xyz"[: self.d]
        out = [f"exit {i + 1} along {a}" for i in range(self.n) for a in axes] if self.exits else []
        out += [f"offset of cable {i + 1}" for i in self.offset_cables]
        if self.anchors:
            out += [f"anchor {i + 1} along the platform's {a}" for i in range(self.n) for a in axes]
        out += [f"pulley radius of cable {i + 1}" for i in self.radius_cables]
        return out


def frames(robot: Robot, poses: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
    """Position ``p (N, d)``, rotation ``R (N, d, d)`` and, for a spatial rigid platform, the
    rate matrix ``E (N, 3, 3)`` of each pose."""
    d = robot.dimension
    p = poses[:, :d]
    if robot.is_point_mass:
        return p, np.broadcast_to(np.eye(d), (len(poses), d, d)), None
    if d == 2:
        return p, planar_rotation(poses[:, 2]), None
    angles = poses[:, 3:6]
    return p, rotation_matrix(angles, robot.orientation), rate_matrix(angles, robot.orientation)


@dataclass(frozen=True)
class Partials:
    """Lengths of ``m`` observed cables and their derivatives (module docstring)."""

    length: np.ndarray  #: ``(m,)``
    exit: np.ndarray  #: ``(m, d)``: ``∂l/∂a``, the unit vector ``u`` from the anchor
    anchor: np.ndarray  #: ``(m, d)``: ``∂l/∂r`` in the platform frame
    radius: np.ndarray  #: ``(m,)``: ``∂l/∂ρ`` (0 for a cable without a swivelling pulley)
    pose: np.ndarray  #: ``(m, s)``: ``∂l/∂q``


def partials(
    robot: Robot,
    geometry: Geometry,
    poses: np.ndarray,
    rows: np.ndarray,
    cables: np.ndarray,
) -> Partials:
    """Length of cable ``cables[j]`` at pose ``rows[j]`` and its derivatives (module docstring)."""
    d = robot.dimension
    p, R, E = frames(robot, poses)
    Rj = R[rows]
    Rr = np.einsum("mij,mj->mi", Rj, geometry.anchors[cables])
    b = p[rows] + Rr
    v = geometry.exits[cables] - b
    length = np.sqrt(np.einsum("mi,mi->m", v, v))
    u = v / np.maximum(length, FLOOR_LENGTH)[:, None]
    dradius = np.zeros(len(rows))
    if robot.swivel_cables:
        on = np.isin(cables, robot.swivel_cables)
        length[on], u[on], dradius[on] = _swivel(geometry, swivel_axes(robot), cables[on], b[on])
    dpose = np.empty((len(rows), robot.pose_size))
    dpose[:, :d] = -u
    if not robot.is_point_mass:
        if d == 2:
            dpose[:, 2] = -(Rr[:, 0] * u[:, 1] - Rr[:, 1] * u[:, 0])
        else:
            m = np.cross(Rr, u)
            dpose[:, 3:6] = -np.einsum("mi,mij->mj", m, E[rows])  # type: ignore[index]
    danchor = -np.einsum("mji,mj->mi", Rj, u)
    return Partials(length, u, danchor, dradius, dpose)


def _swivel(
    geometry: Geometry, axes: np.ndarray, cables: np.ndarray, b: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Length, unit vector ``u = (C − b)/l_f`` from the anchor to the tangent point, and
    ``∂l/∂ρ`` of the cables ``cables`` through swivelling pulleys, anchors at ``b (m, d)``
    (module docstring)."""
    from taut.kinematics import swivel_paths

    a, k, r = geometry.exits[cables], axes[cables], geometry.radii[cables]
    paths = swivel_paths(a, k, r, b[None])
    length, tangent, wrap = paths.lengths[0], paths.tangent_points[0], paths.wrap[0]
    free = length - r * wrap
    h = np.einsum("mi,mi->m", b - a, k)
    x = np.linalg.norm(b - a - h[:, None] * k, axis=1) - r
    # normalised rather than divided by l_f: a trial step can put the anchor inside the pulley
    # circle, where there is no tangent and ‖C − b‖ = l_f = 0; the exit's direction stands in
    v = tangent - b
    span = np.linalg.norm(v, axis=1)
    lost = span < FLOOR_LENGTH
    v[lost] = (a - b)[lost]
    u = v / np.maximum(np.linalg.norm(v, axis=1), FLOOR_LENGTH)[:, None]
    dradius = wrap - (x * free + r * h) / np.maximum(x * x + h * h, FLOOR_LENGTH**2)
    return length, u, dradius


class Problem:
    """Residuals and their sparse Jacobian for ``scipy.optimize.least_squares``.

    Parameters
    ----------
    layout : Layout
        Its robot's geometry is the nominal one, used for what is not estimated.
    """

    def __init__(self, layout: Layout) -> None:
        self.layout = layout
        self.nominal = Geometry.of(layout.robot)
        L = layout
        n, d, s = L.n, L.d, L.s
        m = L.rows.size
        cols: list[np.ndarray] = []
        at = 0
        if L.exits:
            cols.append(L.cables[:, None] * d + np.arange(d))
            at = n * d
        offset_col = np.full(n, -1)
        offset_col[L.offset_cables] = at + np.arange(L.offset_cables.size)
        self._has_offset = offset_col[L.cables] >= 0
        self._offset_cols = offset_col[L.cables][self._has_offset]
        at += L.offset_cables.size
        if L.anchors:
            cols.append(at + L.cables[:, None] * d + np.arange(d))
            at += n * d
        radius_col = np.full(n, -1)
        radius_col[L.radius_cables] = at + np.arange(L.radius_cables.size)
        self._has_radius = radius_col[L.cables] >= 0
        self._radius_cols = radius_col[L.cables][self._has_radius]
        at += L.radius_cables.size
        pose_col = np.full(len(L.known_poses), -1)
        pose_col[L.unknown_rows] = at + np.arange(L.unknown_rows.size) * s
        self._has_pose = pose_col[L.rows] >= 0
        self._pose_cols = pose_col[L.rows][self._has_pose][:, None] + np.arange(s)
        fixed = np.concatenate(cols, axis=1) if cols else np.zeros((m, 0), int)
        obs = np.arange(m)
        self._rows = np.concatenate(
            [
                np.repeat(obs, fixed.shape[1]),
                obs[self._has_offset],
                obs[self._has_radius],
                np.repeat(obs[self._has_pose], s),
            ]
        )
        self._cols = np.concatenate([fixed.ravel(), self._offset_cols, self._radius_cols, self._pose_cols.ravel()])
        self.shape = (m, L.n_unknowns)

    def unpack(self, x: np.ndarray) -> tuple[Geometry, np.ndarray, np.ndarray]:
        return self.layout.unpack(x, self.nominal)

    def evaluate(self, x: np.ndarray) -> tuple[np.ndarray, Partials]:
        L = self.layout
        geometry, offsets, poses = self.unpack(x)
        part = partials(L.robot, geometry, poses, L.rows, L.cables)
        residual = part.length - np.where(L.change, offsets[L.cables], 0.0) - L.values
        return residual, part

    def residuals(self, x: np.ndarray) -> np.ndarray:
        """Model minus measurement per observation [m]."""
        return self.evaluate(x)[0]

    def jacobian(self, x: np.ndarray) -> Any:
        """The sparse Jacobian of :meth:`residuals`: one cable's exit, offset, anchor and pulley
        radius and one row's pose per residual."""
        from scipy.sparse import coo_matrix

        _, part = self.evaluate(x)
        parts = []
        if self.layout.exits:
            parts.append(part.exit)
        if self.layout.anchors:
            parts.append(part.anchor)
        fixed = np.concatenate(parts, axis=1) if parts else np.zeros((len(part.length), 0))
        data = np.concatenate(
            [
                fixed.ravel(),
                -np.ones(self._offset_cols.size),
                part.radius[self._has_radius],
                part.pose[self._has_pose].ravel(),
            ]
        )
        return coo_matrix((data, (self._rows, self._cols)), shape=self.shape).tocsr()

    def blocks(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Per row, the dense Jacobian blocks of its observations: ``Jp (N, n, P)`` over the
        parameters, ``Jq (N, n, s)`` over its pose (zero for a measured pose), and the mask
        ``(N, n)`` of observed cells."""
        L = self.layout
        N = len(L.known_poses)
        J = self.jacobian(x).tocsr()
        P = L.n_params
        Jp = np.zeros((N, L.n, P))
        Jq = np.zeros((N, L.n, L.s))
        seen = np.zeros((N, L.n), bool)
        Jp[L.rows, L.cables] = J[:, :P].toarray()
        rows, cables = L.rows[self._has_pose], L.cables[self._has_pose]
        _, part = self.evaluate(x)
        Jq[rows, cables] = part.pose[self._has_pose]
        seen[L.rows, L.cables] = True
        return Jp, Jq, seen
