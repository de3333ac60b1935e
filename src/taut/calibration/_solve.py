"""Levenberg–Marquardt for the calibration's bundle adjustment, each step solved exactly through
the Schur complement of the pose blocks.

The normal equations of a step ``(JᵀJ + λ D) δ = −Jᵀ r`` (``D`` the diagonal of ``JᵀJ``:
Marquardt's scaling) split into the parameters ``p`` and the unknown poses ``q``.  Every
residual touches one row's pose, so ``JqᵀJq`` is block diagonal, one ``s × s`` block ``A_k`` per
row: eliminating the poses leaves the reduced system of the parameters alone,
``(H − Σ B_kᵀ A_k⁻¹ B_k) δp = −(g_p − Σ B_kᵀ A_k⁻¹ g_k)`` with ``B_k = Jq_kᵀ Jp``, and each
pose's step follows by back-substitution, ``δq_k = −A_k⁻¹ (g_k + B_k δp)`` (Triggs et al.
2000, §6.1, "the reduced camera system").  The cost of a step is linear in the rows.  The
damping ``λ`` follows the gain ratio of the step (Nielsen's update; Madsen, Nielsen & Tingleff
2004, §3.2).  A robust loss rescales the residuals and the Jacobian's rows as
``scipy.optimize.least_squares`` does (Triggs et al. 2000, §4.3), so that the steps are
Gauss–Newton steps of the robust cost.

References
----------
.. [1] B. Triggs, P. F. McLauchlan, R. I. Hartley, A. W. Fitzgibbon, "Bundle Adjustment — A
   Modern Synthesis", Vision Algorithms: Theory and Practice, LNCS 1883, Springer, 2000, §4.3
   and §6.1. (docs/references.bib: triggs2000)
.. [2] K. Madsen, H. B. Nielsen, O. Tingleff, "Methods for Non-Linear Least Squares Problems",
   2nd ed., Technical University of Denmark, 2004, §3.2. (docs/references.bib: madsen2004)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from taut.calibration._model import Problem
from taut.errors import TautError

#: The smallest damping factor: keeps the steps along unseen directions (the gauge) at zero.
MIN_DAMPING = 1e-12

#: A diagonal entry of ``JᵀJ`` below this fraction of the largest is raised to it in ``D``, so
#: that a parameter no residual sees is held, not left singular.
DIAGONAL_FLOOR = 1e-14


@dataclass(frozen=True)
class Solution:
    """What :func:`levenberg_marquardt` returns, named as ``scipy.optimize.least_squares``'s
    result: ``x``, ``cost`` (half the sum of the loss of the squared residuals), ``nfev``
    (residual evaluations) and ``status`` (0: budget spent; 1: gradient, 2: cost, 3: step
    tolerance met)."""

    x: np.ndarray
    cost: float
    nfev: int
    status: int


def _loss(r: np.ndarray, loss: str, scale: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``ρ(z)``, ``ρ'(z)`` and ``ρ''(z)`` at ``z = (r / scale)²``, scaled to the residuals'
    units as scipy does (``scale² ρ``, ``ρ'``, ``ρ'' / scale²``)."""
    z = (r / scale) ** 2
    if loss == "linear":
        return z * scale**2, np.ones_like(z), np.zeros_like(z)
    if loss == "soft_l1":
        t = 1.0 + z
        return 2.0 * (np.sqrt(t) - 1.0) * scale**2, t**-0.5, -0.5 * t**-1.5 / scale**2
    if loss == "huber":
        big = z > 1.0
        zs = np.where(big, z, 1.0)
        rho0 = np.where(big, 2.0 * np.sqrt(zs) - 1.0, z)
        return rho0 * scale**2, np.where(big, zs**-0.5, 1.0), np.where(big, -0.5 * zs**-1.5, 0.0) / scale**2
    raise TautError(f"loss: unknown loss {loss!r}; expected linear, soft_l1 or huber")


def levenberg_marquardt(
    problem: Problem,
    x0: np.ndarray,
    *,
    loss: str = "linear",
    scale: float = 1.0,
    max_nfev: int = 1000,
    xtol: float = 1e-12,
    ftol: float = 1e-12,
    gtol: float = 1e-10,
) -> Solution:
    """Minimise the (robust) cost of ``problem``'s residuals from ``x0`` (module docstring).

    Parameters
    ----------
    problem : Problem
    x0 : ndarray
        The start: parameters, then the unknown poses (:class:`Layout`).
    loss : {"linear", "soft_l1", "huber"}
    scale : float
        The robust loss's residual scale [m].
    max_nfev : int
        Residual evaluations allowed.
    xtol, ftol, gtol : float
        Stop when a step moves ``x`` by less than ``xtol (xtol + ‖x‖)``, lowers the cost by less
        than ``ftol`` of it, or the scaled gradient's largest entry is below ``gtol``.

    Returns
    -------
    Solution

    References
    ----------
    .. [1] B. Triggs, P. F. McLauchlan, R. I. Hartley, A. W. Fitzgibbon, "Bundle Adjustment —
       A Modern Synthesis", LNCS 1883, Springer, 2000, §6.1. (docs/references.bib: triggs2000)
    .. [2] K. Madsen, H. B. Nielsen, O. Tingleff, "Methods for Non-Linear Least Squares
       Problems", Technical University of Denmark, 2004, §3.2. (docs/references.bib: madsen2004)
    """
    L = problem.layout
    P, s, U = L.n_params, L.s, L.unknown_rows.size
    has_pose = problem._has_pose
    block = (problem._pose_cols[:, 0] - P) // s if U else np.zeros(0, int)
    x = np.asarray(x0, dtype=float).copy()

    def evaluate(x: np.ndarray) -> tuple[np.ndarray, float]:
        r = problem.residuals(x)
        rho = _loss(r, loss, scale)
        return r, 0.5 * float(rho[0].sum())

    r, cost = evaluate(x)
    nfev = 1
    lam, nu = 1e-3, 2.0
    status = 0
    while nfev < max_nfev:
        J = problem.jacobian(x)
        rho = _loss(r, loss, scale)
        # the robust cost's Gauss–Newton model, as scipy scales it
        weight = np.sqrt(np.maximum(rho[1] + 2.0 * rho[2] * r**2, np.finfo(float).eps))
        f = r * rho[1] / weight
        J = J.multiply(weight[:, None]).tocsr()
        Jp = J[:, :P].toarray()
        Jq = J[:, P:]
        gp = Jp.T @ f
        H = Jp.T @ Jp
        A = np.zeros((U, s, s))
        gq = np.zeros((U, s))
        B = np.zeros((U, s, P))
        if U:
            # the s × s pose blocks A_k of JqᵀJq and the pose gradients, one bincount per entry
            obs = np.flatnonzero(has_pose)
            vals = problem.evaluate(x)[1].pose[obs] * weight[obs, None]
            for a in range(s):
                gq[:, a] = np.bincount(block, vals[:, a] * f[obs], minlength=U)
                for b in range(a, s):
                    A[:, a, b] = A[:, b, a] = np.bincount(block, vals[:, a] * vals[:, b], minlength=U)
            B = np.asarray(Jq.T @ Jp).reshape(U, s, P)
        grad = np.concatenate([gp, gq.ravel()])
        diag = np.concatenate([np.diag(H), np.einsum("kii->ki", A).ravel()])
        diag = np.maximum(diag, DIAGONAL_FLOOR * max(float(diag.max(initial=0.0)), 1e-300))
        if np.abs(grad / np.sqrt(diag)).max(initial=0.0) < gtol:
            status = 1
            break
        while nfev < max_nfev:
            dp_diag, dq_diag = diag[:P], diag[P:].reshape(U, s)
            Ad = A + lam * dq_diag[:, :, None] * np.eye(s)
            Ainv = np.linalg.inv(Ad) if U else A
            C = Ainv @ B
            S = H + lam * np.diag(dp_diag) - B.reshape(-1, P).T @ C.reshape(-1, P)
            rhs = -(gp - np.einsum("ksp,ks->p", C, gq))
            try:
                step_p = np.linalg.solve(S, rhs) if P else np.zeros(0)
            except np.linalg.LinAlgError:
                step_p = np.linalg.lstsq(S, rhs, rcond=None)[0]
            step_q = -np.einsum("kst,kt->ks", Ainv, gq + B @ step_p) if U else np.zeros((0, s))
            step = np.concatenate([step_p, step_q.ravel()])
            trial = x + step
            r_new, cost_new = evaluate(trial)
            nfev += 1
            Jd = J @ step
            predicted = -(f @ Jd + 0.5 * Jd @ Jd)
            if predicted <= ftol * cost:
                # the model promises nothing more: a minimum to the tolerance (rounding may
                # even refuse the step)
                if cost_new < cost:
                    x, r, cost = trial, r_new, cost_new
                status = 2
                break
            gain = (cost - cost_new) / predicted if predicted > 0 else -1.0
            if gain > 0:
                small_step = np.linalg.norm(step) < xtol * (xtol + np.linalg.norm(x))
                # as scipy's test: a small drop that the model predicted well
                small_drop = cost - cost_new < ftol * cost and gain > 0.25
                x, r, cost = trial, r_new, cost_new
                lam = max(lam * max(1.0 / 3.0, 1.0 - (2.0 * gain - 1.0) ** 3), MIN_DAMPING)
                nu = 2.0
                if small_drop:
                    status = 2
                elif small_step:
                    status = 3
                break
            lam *= nu
            nu *= 2.0
            if np.linalg.norm(step) < xtol * (xtol + np.linalg.norm(x)):
                status = 3
                break
        if status:
            break
    return Solution(x=x, cost=cost, nfev=nfev, status=status)
