"""External wrenches and wrench sets.

The external wrench on the platform (Rushton 2022, Eq. 2.11 writes
equilibrium as ``W τ = −w_ext``) is the robot's constant wrench plus its weight, both
applied at ``platform.wrench_point``, with moments taken about the platform reference
point ``p``, plus the weights of the jointed bodies at their centres of mass (Lieskovský
2020, Eqs. 3.3.7–3.3.10: the platform rows of the jointed equilibrium).

A wrench set is described by its support function ``h(n) = max_{w ∈ set} n·w``; every
convex set below (a single wrench, a box, a polytope given by its vertices, and the
ellipsoid ``{c + L v : ‖v‖ ≤ 1}`` of Bohigas et al. (2013), §2) provides it, which is
all the wrench-feasibility tests of :mod:`taut.statics._feasibility` need.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, Eq. 2.11. (docs/references.bib: rushton2022)
.. [2] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of Cable-Driven
   Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots, Mechanisms and
   Machine Science 12, Springer, 2013, §2. (docs/references.bib: bohigas2013)
.. [3] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, §3.3, Eqs. 3.3.7–3.3.12.
   (docs/references.bib: lieskovsky2020)
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from taut._checks import as_array
from taut.errors import TautError
from taut.geometry import cross
from taut.kinematics import as_poses, body_frames, platform_frame
from taut.model import Robot


def bounds_pair(tension_bounds: object) -> tuple[npt.ArrayLike, npt.ArrayLike]:
    """``(tmin, tmax)`` of the ``tension_bounds`` argument, which must be a pair."""
    if not isinstance(tension_bounds, (tuple, list)) or len(tension_bounds) != 2:
        raise TautError(f"tension_bounds must be a pair (tmin, tmax), got {tension_bounds!r}")
    return tension_bounds[0], tension_bounds[1]


def as_floats(value: object, what: str) -> np.ndarray:
    """``value`` as a float array; :class:`TautError` naming ``what`` when it holds no numbers."""
    return as_array(value, what, finite=False)


def external_wrench(robot: Robot, poses: npt.ArrayLike) -> np.ndarray:
    """The external wrench ``w_ext`` on the platform at each pose: the platform's constant
    ``wrench`` plus its weight, both at ``platform.wrench_point``, plus the weights of the
    jointed bodies, with moments about the platform's reference point.

    Parameters
    ----------
    robot : Robot
        The robot.
    poses : array_like, shape (N, pose_size) or (pose_size,)
        Poses, one or a batch.

    Returns
    -------
    ndarray, shape (N, m) or (m,)
        Forces [N] then moments [N m] in the fixed frame (``m = robot.wrench_dim``).

    Raises
    ------
    PoseError
        For poses of the wrong size or not finite.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
       Waterloo, 2022, Eq. 2.11. (docs/references.bib: rushton2022)
    .. [2] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, §3.3, Eqs. 3.3.7–3.3.10.
       (docs/references.bib: lieskovsky2020)

    Examples
    --------
    The 1 kg platform of the planar 4-cable robot under standard gravity:

    >>> from taut.model import example
    >>> external_wrench(example("planar-4cable"), [0.2, 0.1, 0.3])
    array([ 0.  , -9.81,  0.  ])
    """
    arr, single = as_poses(robot, poses)
    d, m = robot.dimension, robot.wrench_dim
    plat = robot.platform
    wrench = np.zeros(m)
    if plat.wrench is not None:
        wrench += np.asarray(plat.wrench, float)
    wrench[:d] += robot.weight
    out = np.broadcast_to(wrench, (arr.shape[0], m)).copy()
    if not robot.is_point_mass and plat.wrench_point is not None:
        _, R = platform_frame(robot, arr)
        arm = R @ np.asarray(plat.wrench_point, float)
        moment = cross(arm, out[:, :d])
        out[:, d:] += moment[:, None] if moment.ndim == 1 else moment
    if np.any(robot.body_weights != 0):
        out += _body_weights(robot, arr)
    return out[0] if single else out


def _body_weights(robot: Robot, poses: np.ndarray) -> np.ndarray:
    """The weights of the jointed bodies as a wrench on the platform ``(N, m)``: the platform
    rows of the jointed equilibrium balance the whole robot (the joints' reactions are
    internal), so each weight ``F_k`` adds its force and its moment ``(c_k − p) × F_k`` about
    the reference point ``p``, ``c_k`` the body's centre of mass in the fixed frame (the rows
    of ``A`` for the platform twist, Lieskovský 2020, Eqs. 3.3.7–3.3.10); the joints' own rows
    are in :func:`taut.statics.equilibrium_equations`."""
    pos, rot = body_frames(robot, poses)
    d = robot.dimension
    out = np.zeros((poses.shape[0], robot.wrench_dim))
    for k, (force, com) in enumerate(zip(robot.body_weights, robot.body_coms), 1):
        arm = pos[:, k] - pos[:, 0] + rot[:, k] @ com
        out[:, :d] += force
        moment = cross(arm, np.broadcast_to(force, arm.shape))
        out[:, d:] += moment[:, None] if moment.ndim == 1 else moment
    return out


class WrenchSet(ABC):
    """A convex set of wrenches, known through its support function ``h(n) = max_{w ∈ set} n·w``.

    The wrench-feasibility test (:func:`wrench_feasible`) needs only the support; a
    subclass sets ``dim`` and implements :meth:`support`.  The built-in sets are
    :class:`SingleWrench`, :class:`BoxWrenchSet`, :class:`PolytopeWrenchSet` and
    :class:`EllipsoidWrenchSet`.

    Attributes
    ----------
    dim : int
        Number of wrench components.

    Examples
    --------
    >>> isinstance(SingleWrench([0.0, -9.81, 0.0]), WrenchSet)
    True
    """

    dim: int  #: number of wrench components

    @abstractmethod
    def support(self, normals: np.ndarray) -> np.ndarray:
        """The support ``h(n) = max_{w ∈ set} n·w``.

        Parameters
        ----------
        normals : array_like, shape (..., dim)
            Directions (any length).

        Returns
        -------
        ndarray, shape (...)
            The support in each direction.

        Raises
        ------
        TautError
            For normals that are not numbers or not of size ``dim``.

        Examples
        --------
        >>> BoxWrenchSet([-1.0, 0.0], [1.0, 2.0]).support([[1.0, 0.0], [0.0, -1.0]])
        array([1., 0.])
        """


def _normals(normals: npt.ArrayLike, dim: int) -> np.ndarray:
    """The ``normals`` argument of a ``support`` as an array ``(..., dim)``."""
    n = as_floats(normals, "normals")
    if n.ndim == 0 or n.shape[-1] != dim:
        raise TautError(f"normals of a {dim}-dimensional wrench set must have shape (..., {dim}), got {n.shape}")
    return n


def _vector(x: npt.ArrayLike, what: str) -> np.ndarray:
    arr = as_floats(x, what)
    if arr.ndim != 1 or arr.size == 0 or not np.all(np.isfinite(arr)):
        raise TautError(f"{what} must be a finite vector, got {x!r}")
    return arr


@dataclass(frozen=True)
class SingleWrench(WrenchSet):
    """The set of one wrench ``w``.

    Parameters
    ----------
    wrench : array_like, shape (dim,)
        The wrench [N, N m].

    Attributes
    ----------
    wrench : ndarray, shape (dim,)
    dim : int

    Raises
    ------
    TautError
        For a wrench that is not a finite non-empty vector.

    Examples
    --------
    >>> SingleWrench([0.0, -9.81, 0.0]).support([0.0, -1.0, 0.0])
    np.float64(9.81)
    """

    wrench: np.ndarray
    dim: int = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "wrench", _vector(self.wrench, "wrench"))
        object.__setattr__(self, "dim", self.wrench.size)

    def support(self, normals: npt.ArrayLike) -> np.ndarray:
        return _normals(normals, self.dim) @ self.wrench


@dataclass(frozen=True)
class BoxWrenchSet(WrenchSet):
    """The box ``lower ≤ w ≤ upper`` (componentwise) of wrenches.

    Parameters
    ----------
    lower, upper : array_like, shape (dim,)
        Its corners [N, N m].

    Attributes
    ----------
    lower, upper : ndarray, shape (dim,)
    dim : int

    Raises
    ------
    TautError
        For corners that are not finite vectors, of different sizes, or inverted.

    Examples
    --------
    >>> box = BoxWrenchSet.around([0.0, -9.81, 0.0], [1.0, 1.0, 0.1])
    >>> box.lower, box.upper
    (array([ -1.  , -10.81,  -0.1 ]), array([ 1.  , -8.81,  0.1 ]))
    >>> len(box.vertices())
    8
    """

    lower: np.ndarray
    upper: np.ndarray
    dim: int = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        lo, hi = _vector(self.lower, "box lower corner"), _vector(self.upper, "box upper corner")
        if lo.shape != hi.shape:
            raise TautError(f"box corners have different sizes: {lo.size} and {hi.size}")
        if np.any(lo > hi):
            raise TautError(f"box wrench set is inverted: lower {lo.tolist()} > upper {hi.tolist()}")
        object.__setattr__(self, "lower", lo)
        object.__setattr__(self, "upper", hi)
        object.__setattr__(self, "dim", lo.size)

    @classmethod
    def around(cls, center: npt.ArrayLike, half_widths: npt.ArrayLike) -> BoxWrenchSet:
        """The box ``center ± half_widths``.

        Parameters
        ----------
        center : array_like, shape (dim,)
            Its centre [N, N m].
        half_widths : array_like, shape (dim,)
            Half its side lengths (their absolute values).

        Returns
        -------
        BoxWrenchSet

        Examples
        --------
        >>> BoxWrenchSet.around([0.0, 5.0], [1.0, 1.0]).upper
        array([1., 6.])
        """
        c, r = _vector(center, "box center"), np.abs(_vector(half_widths, "box half-widths"))
        return cls(c - r, c + r)

    def support(self, normals: npt.ArrayLike) -> np.ndarray:
        n = _normals(normals, self.dim)
        c, r = (self.lower + self.upper) / 2, (self.upper - self.lower) / 2
        return n @ c + np.abs(n) @ r

    def vertices(self) -> np.ndarray:
        """The ``2^dim`` corners of the box.

        Returns
        -------
        ndarray, shape (2**dim, dim)

        Examples
        --------
        >>> BoxWrenchSet([0.0, 0.0], [1.0, 2.0]).vertices()
        array([[0., 0.],
               [1., 0.],
               [0., 2.],
               [1., 2.]])
        """
        bits = (np.arange(2**self.dim)[:, None] >> np.arange(self.dim)) & 1
        return np.where(bits, self.upper, self.lower)


@dataclass(frozen=True)
class PolytopeWrenchSet(WrenchSet):
    """The convex hull of wrenches ``vertices``.

    Parameters
    ----------
    vertices : array_like, shape (k, dim)
        The polytope's vertices (points inside it do no harm).

    Attributes
    ----------
    vertices : ndarray, shape (k, dim)
    dim : int

    Raises
    ------
    TautError
        For vertices that are not a finite ``(k, dim)`` array with ``k ≥ 1``.

    Examples
    --------
    >>> triangle = PolytopeWrenchSet([[0.0, 0.0], [2.0, 0.0], [0.0, 1.0]])
    >>> triangle.support([[1.0, 1.0], [-1.0, 0.0]])
    array([2., 0.])
    """

    vertices: np.ndarray
    dim: int = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        v = as_floats(self.vertices, "polytope vertices")
        if v.ndim != 2 or v.shape[0] == 0 or not np.all(np.isfinite(v)):
            raise TautError("a polytope wrench set needs a (k, dim) array of finite vertices")
        object.__setattr__(self, "vertices", v)
        object.__setattr__(self, "dim", v.shape[1])

    def support(self, normals: npt.ArrayLike) -> np.ndarray:
        return (_normals(normals, self.dim) @ self.vertices.T).max(axis=-1)


@dataclass(frozen=True)
class EllipsoidWrenchSet(WrenchSet):
    """The ellipsoid ``{c + L v : ‖v‖ ≤ 1}`` of wrenches, with ``shape = L Lᵀ`` positive
    semi-definite: the wrench uncertainty ``(w − w0)ᵀ E⁻¹ (w − w0) ≤ 1``, ``E = shape``, of
    Bohigas et al. (2013), §2.

    Parameters
    ----------
    center_wrench : array_like, shape (dim,)
        Its centre ``c`` (``w0``) [N, N m].
    shape : array_like, shape (dim, dim)
        The symmetric positive semi-definite matrix ``E``.

    Attributes
    ----------
    center_wrench : ndarray, shape (dim,)
    shape : ndarray, shape (dim, dim)
    dim : int

    Raises
    ------
    TautError
        For a centre or shape that is not finite, of the wrong size, not symmetric or not
        positive semi-definite.

    References
    ----------
    .. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of Cable-Driven
       Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots, Mechanisms and
       Machine Science 12, Springer, 2013, §2. (docs/references.bib: bohigas2013)

    Examples
    --------
    Semi-axes 3 and 2 along the coordinate axes:

    >>> ellipse = EllipsoidWrenchSet([1.0, 0.0], [[9.0, 0.0], [0.0, 4.0]])
    >>> ellipse.support([[1.0, 0.0], [0.0, 1.0]])
    array([4., 2.])
    """

    center_wrench: np.ndarray
    shape: np.ndarray
    dim: int = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        c = _vector(self.center_wrench, "ellipsoid center")
        S = as_floats(self.shape, "ellipsoid shape")
        if S.shape != (c.size, c.size) or not np.all(np.isfinite(S)):
            raise TautError(f"ellipsoid shape must be a finite {c.size}x{c.size} matrix")
        if not np.allclose(S, S.T) or np.linalg.eigvalsh(S).min() < -1e-12 * max(1.0, np.abs(S).max()):
            raise TautError("ellipsoid shape must be symmetric positive semi-definite")
        object.__setattr__(self, "center_wrench", c)
        object.__setattr__(self, "shape", S)
        object.__setattr__(self, "dim", c.size)

    def support(self, normals: npt.ArrayLike) -> np.ndarray:
        n = _normals(normals, self.dim)
        q = np.einsum("...i,ij,...j->...", n, self.shape, n)
        return n @ self.center_wrench + np.sqrt(np.maximum(q, 0.0))
