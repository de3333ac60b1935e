"""Joint actuators beside the cables in the tension distribution.

A jointed platform's joint may have a motor (``joint.actuator``) exerting a force or torque
``ζ_j`` within its bounds, which may be negative or infinite.  Its generalized force is the
unit column of the joint's coordinate, so the distribution solves ``[A  E] [τ; ζ] = w`` with
``E`` those unit columns (Lau, Oetomo & Halgamuge 2013: cables and joint actuators together in
the joint-space equations of motion of a multilink cable robot).  The compiled closed form
(:mod:`taut.dynamics._kernels`) takes such columns as they are; the distributions of
:mod:`taut.statics` accept non-negative lower bounds only, so for them each actuator becomes a
pushing and a pulling column, ``ζ = ζ⁺ − ζ⁻`` with ``ζ⁺ ∈ [max(ζ_min, 0), max(ζ_max, 0)]`` and
``ζ⁻ ∈ [max(−ζ_max, 0), max(−ζ_min, 0)]``: the two sets of ``ζ`` are the same, and the least
sum or 2-norm of the split is reached with one of ``ζ⁺``, ``ζ⁻`` at zero (where the bounds
allow), so that ``lp`` and ``qp`` minimise ``|ζ|`` and ``ζ²`` beside the tensions.

References
----------
.. [1] D. Lau, D. Oetomo, S. K. Halgamuge, "Generalized modeling of multilink cable-driven
   manipulators with arbitrary routing using the cable-routing matrix", IEEE Transactions on
   Robotics 29(5), 2013 (cables and joint actuators in the joint-space equations of motion).
   (docs/references.bib: lau2013)
"""

from __future__ import annotations

import numpy as np

from taut.model import Robot

__all__ = ["input_bounds", "solve_inputs"]


def input_bounds(robot: Robot, cables: tuple[np.ndarray, np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    """The bounds of the inputs: the cables' ``cables = (tmin, tmax)`` then the joint
    actuators' (:attr:`taut.model.Robot.actuator_bounds`), each ``(n + n_actuators,)``."""
    lo, hi = robot.actuator_bounds
    return np.concatenate([cables[0], lo]), np.concatenate([cables[1], hi])


def solve_inputs(
    W: np.ndarray, wrench: np.ndarray, lo: np.ndarray, hi: np.ndarray, n_cables: int, method: str
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Tensions and actuator forces ``x`` with ``W x = wrench`` and ``lo ≤ x ≤ hi`` by the
    distribution ``method`` of :mod:`taut.statics`, the actuators (the columns after the first
    ``n_cables``) split as the module docstring says.

    ``W`` is ``(..., m, n)`` and ``wrench`` ``(..., m)``; returns ``x (..., n)`` (zeros where
    not admissible), whether it is admissible and the distribution's status (``(...)`` each)."""
    from taut.statics import solve_tensions

    n = W.shape[-1]
    if n == n_cables:
        res = solve_tensions(W, -wrench, tension_bounds=(lo, hi), method=method)
        return np.array(res.tensions), np.asarray(res.feasible), np.asarray(res.status)
    act = slice(n_cables, n)
    split = np.concatenate([W, -W[..., act]], axis=-1)
    zero = np.zeros(n - n_cables)
    low = np.concatenate([lo[:n_cables], np.maximum(lo[act], zero), np.maximum(-hi[act], zero)])
    high = np.concatenate([hi[:n_cables], np.maximum(hi[act], zero), np.maximum(-lo[act], zero)])
    res = solve_tensions(split, -wrench, tension_bounds=(low, high), method=method)
    x = np.array(res.tensions[..., :n])
    x[..., act] -= res.tensions[..., n:]
    return x, np.asarray(res.feasible), np.asarray(res.status)
