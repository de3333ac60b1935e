"""Singular configurations (Lieskovský 2020, §2.3.1, after Diao & Ma 2007, 2008).

* **Jacobian singularity**: the inverse-kinematics Jacobian ``J`` (Eq. 2.3.1; Eq. 3.2.12 for
  the adjustable platform, :func:`taut.kinematics.actuator_jacobian`) loses rank.
  Decided from its singular values: singular iff ``σ_min ≤ tol · σ_max`` (``JACOBIAN_TOL``),
  which is also the case when ``J`` has fewer rows than columns (fewer actuators than
  degrees of freedom: under-constrained robots are Jacobian-singular everywhere).
* **Force-closure singularity**: the columns of the structure matrix ``W`` (Eq. 3.3.10) do
  not positively span the wrench space (Eqs. 2.3.2–2.3.3), so that some wrench cannot be
  resisted with positive tensions.  Two methods:

  - ``"fast"`` — the vectorised hyperplane test :func:`taut.statics.wrench_closure`
    (a Numba kernel over all poses: ``rank W = m`` and every facet normal of ``W·[0,1]^n``
    has columns strictly on both sides, relative margin ``1e-10``);
  - ``"lp"`` — the reference: the columns (scaled to unit length, which does not change
    positive spanning) positively span ``R^m`` iff ``rank W = m`` and some ``τ > 0`` has
    ``W τ = 0`` (Goldman & Tucker); one linear program per pose (HiGHS) maximises the
    smallest tension ``t`` subject to ``W τ = 0``, ``t ≤ τ_i ≤ 1``; closure iff
    ``t* > LP_TOL`` and ``σ_min(W) > RANK_TOL σ_max(W)``.

  Both count configurations on the boundary (a column exactly on a facet hyperplane, as at
  step 126 of simulation b, where four cables lie in one plane) as singular; the margins
  keep the verdicts stable under rounding.

References
----------
.. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, §2.3.1, Eqs. 2.3.1–2.3.3, Eqs.
   3.2.12 and 3.3.10. (docs/references.bib: lieskovsky2020)
.. [2] X. Diao, O. Ma, "A method of verifying force-closure condition for general cable
   manipulators with seven cables", Mechanism and Machine Theory 42, 2007.
   (docs/references.bib: diao2007)
.. [3] X. Diao, O. Ma, Q. Lu, "Singularity analysis of planar cable-driven parallel robots",
   2008. (docs/references.bib: diao2008)
"""

from __future__ import annotations

import numbers

import numpy as np
import numpy.typing as npt

from taut.errors import TautError
from taut.statics import wrench_closure

__all__ = ["force_closure_singular", "jacobian_singular", "positive_span_lp"]

#: ``σ_min(J) ≤ JACOBIAN_TOL · σ_max(J)``: Jacobian singular.
JACOBIAN_TOL = 1e-8
#: Smallest normalised tension of the LP below which the columns do not positively span.
LP_TOL = 1e-9
#: ``σ_min(W) ≤ RANK_TOL · σ_max(W)``: rank-deficient structure matrix.
RANK_TOL = 1e-10


def jacobian_singular(J: npt.ArrayLike, *, tol: float = JACOBIAN_TOL) -> tuple[np.ndarray, np.ndarray]:
    """Jacobian singularity: where the inverse-kinematics Jacobian loses rank.

    Singular iff ``σ_min ≤ tol · σ_max``, and always when ``J`` has fewer rows than columns
    (fewer actuators than degrees of freedom).

    Parameters
    ----------
    J : array_like, shape (N, rows, cols) or (rows, cols)
        Jacobians (:func:`taut.kinematics.actuator_jacobian`).
    tol : float, optional
        The ratio ``σ_min / σ_max`` at or below which ``J`` is singular, in ``[0, 1)``.

    Returns
    -------
    singular : ndarray of bool, shape (N,)
    ratio : ndarray, shape (N,)
        ``σ_min / σ_max`` (0 with fewer rows than columns).

    Raises
    ------
    TautError
        ``J`` not a finite matrix or array of matrices, a bad ``tol``.

    References
    ----------
    .. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, §2.3.1, Eq. 2.3.1.
       (docs/references.bib: lieskovsky2020)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.collision import jacobian_singular
    >>> jacobian_singular([np.eye(3), np.diag([1.0, 1.0, 1e-9])])
    (array([False,  True]), array([1.e+00, 1.e-09]))
    """
    J = _matrices(J, "J")
    if isinstance(tol, bool) or not isinstance(tol, numbers.Real) or not 0 <= tol < 1:
        raise TautError(f"tol must be a number in [0, 1) (a ratio of singular values), got {tol!r}")
    rows, cols = J.shape[1:]
    if rows < cols:
        return np.ones(J.shape[0], bool), np.zeros(J.shape[0])
    s = np.linalg.svd(J, compute_uv=False)
    ratio = s[:, -1] / np.maximum(s[:, 0], np.finfo(float).tiny)
    return ratio <= tol, ratio


def positive_span_lp(W: npt.ArrayLike) -> np.ndarray:
    """The reference positive-span test: one linear program (HiGHS) per matrix.

    The columns (scaled to unit length) positively span ``R^m`` iff ``rank W = m`` and some
    ``τ > 0`` has ``W τ = 0`` (Goldman & Tucker): the LP maximises the smallest tension ``t``
    subject to ``W τ = 0``, ``t ≤ τ_i ≤ 1``.

    Parameters
    ----------
    W : array_like, shape (N, m, n) or (m, n)
        Structure matrices.

    Returns
    -------
    ndarray of bool, shape (N,)
        True where the columns positively span ``R^m`` (``t* > LP_TOL`` and
        ``σ_min(W) > RANK_TOL σ_max(W)``).

    Raises
    ------
    TautError
        ``W`` not a finite matrix or array of matrices.

    References
    ----------
    .. [1] X. Diao, O. Ma, "A method of verifying force-closure condition for general cable
       manipulators with seven cables", Mechanism and Machine Theory 42, 2007.
       (docs/references.bib: diao2007)

    Examples
    --------
    At the centre of the planar robot the cables positively span the plane's wrenches; near
    an exit they do not:

    >>> from taut.model import example
    >>> from taut.kinematics import structure_matrix
    >>> from taut.collision import positive_span_lp
    >>> positive_span_lp(structure_matrix(example("planar-4cable"), [[0, 0, 0], [0.9, 0.9, 0]]))
    array([ True, False])
    """
    import highspy

    W = _matrices(W, "W")
    N, m, n = W.shape
    out = np.zeros(N, bool)
    from taut.statics import QuietHighs

    h = QuietHighs()
    inf = highspy.kHighsInf
    for k in range(N):
        norms = np.linalg.norm(W[k], axis=0)
        if n <= m or np.any(norms == 0):
            continue  # m + 1 non-zero columns at least are needed
        s = np.linalg.svd(W[k], compute_uv=False)
        if s[-1] <= RANK_TOL * s[0] or len(s) < m:
            continue
        Wn = W[k] / norms
        # variables τ_1..τ_n, t;  maximise t
        lp = highspy.HighsLp()
        lp.num_col_, lp.num_row_ = n + 1, m + n
        lp.col_cost_ = np.r_[np.zeros(n), -1.0]
        lp.col_lower_ = np.r_[np.zeros(n), -inf]
        lp.col_upper_ = np.r_[np.ones(n), inf]
        rows = np.zeros((m + n, n + 1))
        rows[:m, :n] = Wn
        rows[m:, :n] = np.eye(n)
        rows[m:, n] = -1.0  # τ_i − t ≥ 0
        lp.row_lower_ = np.r_[np.zeros(m), np.zeros(n)]
        lp.row_upper_ = np.r_[np.zeros(m), np.full(n, inf)]
        csc = rows.T  # column-wise storage
        starts, index, value = [0], [], []
        for col in csc:
            nz = np.flatnonzero(col)
            index += nz.tolist()
            value += col[nz].tolist()
            starts.append(len(index))
        lp.a_matrix_.format_ = highspy.MatrixFormat.kColwise
        lp.a_matrix_.start_ = starts
        lp.a_matrix_.index_ = index
        lp.a_matrix_.value_ = value
        h.passModel(lp)
        h.run()
        if h.getModelStatus() == highspy.HighsModelStatus.kOptimal:
            out[k] = -h.getInfo().objective_function_value > LP_TOL
    return out


def force_closure_singular(W: npt.ArrayLike, *, method: str = "fast") -> np.ndarray:
    """Force-closure singularity: where the cables do not positively span the wrench space.

    Parameters
    ----------
    W : array_like, shape (N, m, n) or (m, n)
        Structure matrices.
    method : {"fast", "lp"}, optional
        ``"fast"``: the vectorised hyperplane test :func:`taut.statics.wrench_closure` (for
        grids); ``"lp"``: the reference, :func:`positive_span_lp`.

    Returns
    -------
    ndarray of bool, shape (N,)
        True where the columns do not positively span ``R^m`` (configurations on the
        boundary count as singular).

    Raises
    ------
    TautError
        ``W`` not a finite matrix or array of matrices, an unknown method.

    References
    ----------
    .. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, §2.3.1, Eqs. 2.3.2–2.3.3.
       (docs/references.bib: lieskovsky2020)
    .. [2] X. Diao, O. Ma, "A method of verifying force-closure condition for general cable
       manipulators with seven cables", Mechanism and Machine Theory 42, 2007.
       (docs/references.bib: diao2007)

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.kinematics import structure_matrix
    >>> from taut.collision import force_closure_singular
    >>> force_closure_singular(structure_matrix(example("planar-4cable"), [[0, 0, 0], [0.9, 0.9, 0]]))
    array([False,  True])
    """
    check_method(method)
    if method == "lp":
        return ~positive_span_lp(W)
    return ~wrench_closure(_matrices(W, "W"))


#: The methods of :func:`force_closure_singular`.
METHODS = ("fast", "lp")


def check_method(method: object) -> None:
    """Raise :class:`TautError` unless ``method`` is one of :data:`METHODS`."""
    if not isinstance(method, str) or method not in METHODS:
        raise TautError(f"unknown force-closure method {method!r}; expected 'fast' or 'lp'")


def _matrices(X: npt.ArrayLike, what: str) -> np.ndarray:
    """``X`` as a finite float array ``(N, rows, cols)`` (one matrix gets the batch axis)."""
    try:
        arr = np.asarray(X, dtype=float)
    except (TypeError, ValueError):
        raise TautError(f"{what} must be a matrix or an array of matrices of numbers") from None
    if arr.ndim == 2:
        arr = arr[None]
    if arr.ndim != 3 or not np.isfinite(arr).all():
        raise TautError(f"{what} must be finite, of shape (rows, cols) or (N, rows, cols), got shape {arr.shape}")
    return arr
