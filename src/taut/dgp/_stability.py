"""Stability of an equilibrium by the reduced Hessian (Berti (2015)
§3.2.2, Eqs. 3.41–3.43, after Carricato & Merlet 2013).

``H = Σ τ_i/ρ_i [[I, −(b̃_i − g̃)], [(b̃_i − g̃), ½((b̃_i − g̃)(g̃ − ã_i) + (g̃ − ã_i)(b̃_i − g̃))]]``
(moments about ``G``), ``N`` spans the null space of ``Jᵀ`` (rows
``[(b_i − a_i)ᵀ, ((b_i − g) × (b_i − a_i))ᵀ]/ρ_i``: the motions that keep the taut lengths),
and the equilibrium is stable when ``H_r = Nᵀ H N`` is positive definite.

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §3.2.2, Eqs. 3.41–3.43. (docs/references.bib: berti2015)
.. [2] M. Carricato, J.-P. Merlet, "Stability Analysis of Underconstrained Cable-Driven Parallel
   Robots", IEEE Transactions on Robotics 29(1), 2013. (docs/references.bib: carricato2013)
"""

from __future__ import annotations

import numpy as np
from numba import njit

from taut.dgp._planar import planar_reduced_hessian


@njit(cache=True)
def reduced_hessian(a: np.ndarray, b: np.ndarray, g: np.ndarray, tau: np.ndarray, rho: np.ndarray) -> np.ndarray:
    """The reduced Hessian ``H_r = Nᵀ H N`` of an equilibrium (module docstring).  Compiled:
    the tracking update calls it once per step.

    Parameters
    ----------
    a : ndarray, shape (m, 3)
        Exit points [m] of the taut cables.
    b : ndarray, shape (m, 3)
        Their platform anchors [m] at the equilibrium, fixed frame.
    g : ndarray, shape (3,)
        Load point [m], fixed frame.
    tau : ndarray, shape (m,)
        Tensions [N].
    rho : ndarray, shape (m,)
        Cable lengths [m].

    Returns
    -------
    ndarray, shape (k, k)
        ``k = 6 − rank J``: the motions that keep the taut lengths.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §3.2.2, Eqs. 3.41–3.43. (docs/references.bib: berti2015)
    .. [2] M. Carricato, J.-P. Merlet, "Stability Analysis of Underconstrained Cable-Driven
       Parallel Robots", IEEE Transactions on Robotics 29(1), 2013.
       (docs/references.bib: carricato2013)

    Examples
    --------
    The stable pose of Table 4.3 of Berti (2015): three taut cables leave three motions.

    >>> import numpy as np
    >>> from taut.dgp import is_stable, load, reduced_hessian, solve_igp
    >>> from taut.geometry import rotation_matrix
    >>> from taut.model import example
    >>> robot = example("suspended-3cable")
    >>> s = solve_igp(robot, [0, 1, 2], {"x": 2.7505, "y": 3.9798, "z": 5.5061}).solutions[0]
    >>> R = rotation_matrix(s.orientation, robot.orientation)
    >>> b = s.position + robot.anchors @ R.T
    >>> g = s.position + R @ load(robot)[2]
    >>> H = reduced_hessian(robot.exits, b, g, s.tensions, s.lengths)
    >>> H.shape, bool(np.linalg.eigvalsh(0.5 * (H + H.T)).min() > 0)
    ((3, 3), True)
    """
    H = np.zeros((6, 6))
    Jt = np.zeros((tau.size, 6))
    for i in range(tau.size):
        w = tau[i] / rho[i]
        bg = b[i] - g
        ga = g - a[i]
        Bg = np.array([[0.0, -bg[2], bg[1]], [bg[2], 0.0, -bg[0]], [-bg[1], bg[0], 0.0]])  # b̃_i − g̃
        Ga = np.array([[0.0, -ga[2], ga[1]], [ga[2], 0.0, -ga[0]], [-ga[1], ga[0], 0.0]])  # g̃ − ã_i
        S = 0.5 * (Bg @ Ga + Ga @ Bg)
        for r in range(3):
            H[r, r] += w
            for c in range(3):
                H[r, 3 + c] -= w * Bg[r, c]
                H[3 + r, c] += w * Bg[r, c]
                H[3 + r, 3 + c] += w * S[r, c]
        d = b[i] - a[i]
        Jt[i, :3] = d / rho[i]
        Jt[i, 3:] = np.cross(bg, d) / rho[i]
    _, s, vt = np.linalg.svd(Jt)
    top = max(1.0, s[0]) if s.size else 1.0
    rank = 0
    for v in s:
        if v > 1e-10 * top:
            rank += 1
    N = np.ascontiguousarray(vt[rank:].T)
    return N.T @ H @ N


@njit(cache=True)
def smallest_eigenvalue(a: np.ndarray, b: np.ndarray, g: np.ndarray, tau: np.ndarray, rho: np.ndarray) -> float:
    """Smallest eigenvalue of the (symmetrised) reduced Hessian of :func:`reduced_hessian`,
    ``inf`` when the null space is empty; the equilibrium is stable when it is positive.
    Compiled, for callers that are compiled too (the tracking update); arrays contiguous."""
    Hr = reduced_hessian(a, b, g, tau, rho)
    if Hr.size == 0:
        return np.inf
    return np.linalg.eigvalsh(0.5 * (Hr + Hr.T))[0]


def is_stable(a: np.ndarray, b: np.ndarray, g: np.ndarray, tau: np.ndarray, rho: np.ndarray) -> bool:
    """Whether an equilibrium is stable: its reduced Hessian is positive definite (the
    sufficient condition of §3.2.2); a fully constrained equilibrium (empty null space) is.
    Planar arrays (shape ``(m, 2)``) are tested on the planar twists ``(v_x, v_y, ω)``.

    Parameters
    ----------
    a : ndarray, shape (m, 3)
        Exit points [m] of the taut cables.
    b : ndarray, shape (m, 3)
        Their platform anchors [m] at the equilibrium, fixed frame.
    g : ndarray, shape (3,)
        Load point [m], fixed frame.
    tau : ndarray, shape (m,)
        Tensions [N].
    rho : ndarray, shape (m,)
        Cable lengths [m].

    Returns
    -------
    bool

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §3.2.2. (docs/references.bib: berti2015)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.dgp import is_stable, load, reduced_hessian, solve_igp
    >>> from taut.geometry import rotation_matrix
    >>> from taut.model import example
    >>> robot = example("suspended-3cable")
    >>> s = solve_igp(robot, [0, 1, 2], {"x": 2.7505, "y": 3.9798, "z": 5.5061}).solutions[0]
    >>> R = rotation_matrix(s.orientation, robot.orientation)
    >>> b = s.position + robot.anchors @ R.T
    >>> g = s.position + R @ load(robot)[2]
    >>> is_stable(robot.exits, b, g, s.tensions, s.lengths)
    True
    """
    if np.shape(a)[-1] == 2:
        Hr = planar_reduced_hessian(*(np.asarray(v, dtype=float) for v in (a, b, g, tau, rho)))
        return bool(Hr.size == 0 or np.linalg.eigvalsh(0.5 * (Hr + Hr.T))[0] > 0.0)
    return bool(smallest_eigenvalue(*(np.ascontiguousarray(v, dtype=float) for v in (a, b, g, tau, rho))) > 0.0)
