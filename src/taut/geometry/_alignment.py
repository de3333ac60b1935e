"""The proper rigid motion that best maps one set of points onto another (Kabsch 1976).

References
----------
.. [1] W. Kabsch, "A solution for the best rotation to relate two sets of vectors", Acta
   Crystallographica A 32, 1976. (docs/references.bib: kabsch1976)
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from taut.errors import TautError


def rigid_alignment(
    source: npt.ArrayLike, target: npt.ArrayLike, *, reflection: bool = False
) -> tuple[np.ndarray, np.ndarray]:
    """The proper rigid motion ``x ↦ Q x + t`` that maps ``source`` onto ``target`` best in the
    least-squares sense: the Kabsch rotation of the centred points (the SVD of their
    cross-covariance, its sign corrected so that ``det Q = +1``) and the centroids' offset.

    Parameters
    ----------
    source, target : array_like, shape (n, d)
        Corresponding points, ``d`` = 2 or 3.
    reflection : bool
        Allow an improper motion (``det Q = −1``, a rotation and a reflection) too, where it
        fits better.

    Returns
    -------
    Q : ndarray, shape (d, d)
        The rotation.
    t : ndarray, shape (d,)
        The translation.

    Raises
    ------
    TautError
        Point sets of different or unusable shapes, or not finite.

    References
    ----------
    .. [1] W. Kabsch, "A solution for the best rotation to relate two sets of vectors", Acta
       Crystallographica A 32, 1976. (docs/references.bib: kabsch1976)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.geometry import rigid_alignment
    >>> square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], float)
    >>> turned = square @ np.array([[0, -1], [1, 0]]).T + [2, 0]  # a quarter turn, then 2 along x
    >>> Q, t = rigid_alignment(square, turned)
    >>> Q.round(12) + 0.0, t.round(12) + 0.0
    (array([[ 0., -1.],
           [ 1.,  0.]]), array([2., 0.]))
    """
    src, dst = np.asarray(source, dtype=float), np.asarray(target, dtype=float)
    if src.ndim != 2 or src.shape != dst.shape or src.shape[1] not in (2, 3) or not len(src):
        raise TautError(
            f"rigid_alignment: expected two (n, 2) or (n, 3) point sets alike, got {src.shape} and {dst.shape}"
        )
    if not (np.isfinite(src).all() and np.isfinite(dst).all()):
        raise TautError("rigid_alignment: points must be finite")
    cs, ct = src.mean(axis=0), dst.mean(axis=0)
    U, _, Vt = np.linalg.svd((src - cs).T @ (dst - ct))
    D = np.eye(src.shape[1])
    if not reflection:
        D[-1, -1] = np.sign(np.linalg.det(Vt.T @ U.T)) or 1.0
    Q = Vt.T @ D @ U.T
    return Q, ct - Q @ cs
