"""Sagging cables in the control loop: quasi-static elastic catenaries.

A sagging cable (``cables[].weight``) is taken to be in static equilibrium at every instant
(its own inertia and its mass's share of the platform's inertia neglected): Irvine's elastic
catenary through its exit point and its anchor, whose tension at the platform end is the
tension the loop commands for it.  It pulls the platform with that tension along its tangent
at the anchor, not along its chord (:func:`taut.cables.catenary_tensions`).  The controller
distributes the tensions with the structure matrix of those tangents, iterated to
consistency with the catenaries as :func:`taut.cables.sagging_ik` does (Kozak, Zhou & Wang
2006, §III; with Anderson's acceleration), both ends of every cable within its tension bounds; the plant recomputes each
catenary, from the last one, at every stage of its Runge–Kutta steps.

References
----------
.. [1] H. M. Irvine, "Cable Structures", MIT Press, 1981, Ch. 1, §1.3 (the elastic catenary).
   (docs/references.bib: irvine1981)
.. [2] K. Kozak, Q. Zhou, J. Wang, "Static analysis of cable-driven manipulators with
   non-negligible cable mass", IEEE Transactions on Robotics 22(3), 2006, §III.
   (docs/references.bib: kozak2006)
.. [3] H. F. Walker, P. Ni, "Anderson acceleration for fixed-point iterations", SIAM Journal on
   Numerical Analysis 49(4), 2011. (docs/references.bib: walker2011)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from taut.errors import UnsupportedRobotError
from taut.model import Robot

if TYPE_CHECKING:
    from taut.cables import Catenary

__all__ = ["ANDERSON_DEPTH", "CABLE_MODELS", "LEAST_RTOL", "Anderson", "SaggingCables", "cable_model"]

#: What :func:`cable_model` calls the two ways the loop models cables.
CABLE_MODELS = ("straight", "quasi-static elastic catenary")


#: A tension within this fraction (at least this many newtons) of its least counts as at it.
LEAST_RTOL = 1e-6
#: Steps of the iteration whose differences Anderson's acceleration combines.
ANDERSON_DEPTH = 3


class Anderson:
    """Anderson's acceleration of a fixed-point iteration ``x ← G(x)`` of one state, from the
    last :data:`ANDERSON_DEPTH` steps (Walker & Ni 2011, Eq. 2.1 with ``β = 1``): the
    distribution iterated with tangents alone oscillates where a small turn of a tangent moves
    the tensions much (a redundant robot far from its bounds' middle)."""

    def __init__(self) -> None:
        self.x: list[np.ndarray] = []
        self.g: list[np.ndarray] = []

    def step(self, x: np.ndarray, g: np.ndarray) -> np.ndarray:
        """The next iterate, the map having taken ``x`` to ``g``."""
        self.x, self.g = [*self.x[-ANDERSON_DEPTH:], x], [*self.g[-ANDERSON_DEPTH:], g]
        if len(self.x) < 2:
            return g
        G = np.array(self.g)
        F = G - np.array(self.x)
        dF, dG = np.diff(F, axis=0), np.diff(G, axis=0)
        A = dF @ dF.T
        A += (1e-10 * np.trace(A) + 1e-300) * np.eye(A.shape[0])
        gamma = np.linalg.solve(A, dF @ F[-1])
        out: np.ndarray = g - gamma @ dG
        return out


def cable_model(robot: Robot) -> str:
    """The name of the loop's cable model of ``robot``: :data:`CABLE_MODELS`."""
    return CABLE_MODELS[bool(robot.sagging_cables)]


class SaggingCables:
    """The sagging cables of one robot and the last catenaries of the controller (with the
    cables that were at their least tension) and of the plant, from which the next ones are
    solved (mutable: a loop's state, not a result)."""

    def __init__(self, robot: Robot) -> None:
        if robot.n_joints:
            raise UnsupportedRobotError(f"{robot.name}: the sagging-cable dynamics handle platforms without joints")
        if robot.routed_cables:
            raise UnsupportedRobotError(
                f"{robot.name}: the sagging-cable dynamics handle robots without cables routed through via points"
            )
        self.robot = robot
        self.which = np.array(robot.sagging_cables, dtype=np.int64)
        self.weights = robot.cable_weights[self.which]
        self.stiffness = robot.axial_stiffness[self.which]
        self.exits = robot.exits[self.which]
        self.up = -robot.gravity / np.linalg.norm(robot.gravity)
        self.controller: Catenary | None = None
        self.least = np.zeros(self.which.size, dtype=bool)
        self.plant: Catenary | None = None

    def geometry(self, q: np.ndarray) -> tuple[np.ndarray, ...]:
        """At the pose ``q``: the arms ``b_i − p``, the spans, rises, chord lengths and the unit
        horizontal directions from the anchors towards the exits of the sagging cables."""
        from taut.kinematics import anchors_at

        d = self.robot.dimension
        anchors = anchors_at(self.robot, q[None])[0][self.which]
        chord = self.exits - anchors
        rise = chord @ self.up
        level = chord - rise[:, None] * self.up
        span = np.linalg.norm(level, axis=1)
        # a cable hanging vertically (span 0) has no catenary: catenary_tensions names it
        level /= np.where(span > 0, span, 1.0)[:, None]
        return anchors - q[:d], span, rise, np.linalg.norm(chord, axis=1), level

    def columns(self, arms: np.ndarray, directions: np.ndarray) -> np.ndarray:
        """The structure matrix's columns ``[u_i ; (b_i − p) × u_i]`` of the cables, ``(m, k)``."""
        from taut.geometry import cross

        if self.robot.is_point_mass:
            return directions.T
        moments = cross(arms, directions)
        return np.vstack([directions.T, moments[None] if moments.ndim == 1 else moments.T])

    def tangents(self, catenary: Catenary, level: np.ndarray) -> np.ndarray:
        """Unit tangents at the platform ends, towards the exits, ``(k, d)``."""
        T = catenary.platform_tensions[:, None]
        return (catenary.horizontal_forces[:, None] * level + catenary.vertical_forces[:, None] * self.up) / T

    def pull(self, q: np.ndarray, tensions: np.ndarray) -> np.ndarray:
        """The wrench ``Σ τ_i [u_i ; (b_i − p) × u_i]`` of the sagging cables at the plant's pose
        ``q`` with platform-end tensions ``τ`` (from the plant's last catenaries).

        Raises ArgumentError where no catenary has that tension through the ends (too slack)."""
        from taut.cables import catenary_tensions

        arms, span, rise, _, level = self.geometry(q)
        self.plant = catenary_tensions(span, rise, tensions, self.weights, self.stiffness, start=self.plant)
        wrench: np.ndarray = self.columns(arms, self.tangents(self.plant, level)) @ tensions
        return wrench

    def pull_lengths(self, q: np.ndarray, lengths: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The wrench of the sagging cables at the pose ``q`` with unstrained lengths ``L0``
        (:func:`taut.cables.catenary_forces`), and their tensions at the platform.

        Raises UnreachableLengthsError where an inextensible cable is not longer than its
        chord, ArgumentError where no catenary is found."""
        from taut.cables import catenary_forces

        arms, span, rise, _, level = self.geometry(q)
        catenary = catenary_forces(span, rise, lengths, self.weights, self.stiffness)
        tensions = catenary.platform_tensions
        wrench: np.ndarray = self.columns(arms, self.tangents(catenary, level)) @ tensions
        return wrench, tensions
