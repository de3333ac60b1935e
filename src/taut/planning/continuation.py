"""Higher-dimensional continuation: an atlas of a k-manifold ``F(x) = 0`` in ``R^n``.

Henderson's multiple-chart method (Henderson 2002, ref. [14] of
Bohigas et al. (2013); §4 of that paper):

* a **chart** ``C_i`` is a centre ``x_i`` on the manifold, an orthonormal basis ``Ψ_i`` of
  the tangent space ``T_{x_i}M`` (the null space of the Jacobian ``F_x``), a radius ``r``
  and a polytope ``P_i ⊂ R^k`` of tangent coordinates, initially a cube ``[−1.05 r, 1.05 r]^k``
  enclosing the ball ``B_i``;
* the chart maps ``u ∈ P_i`` to the manifold by **Newton projection**: the point ``x`` with
  ``F(x) = 0`` and ``Ψ_iᵀ (x − x_i − Ψ_i u) = 0``, started at ``x_i + Ψ_i u``;
* **expansion**: a vertex ``s`` of ``P_i`` outside ``B_i`` gives ``u = α s/‖s‖`` (``α = r``);
  the projection ``x_j`` is accepted as a new chart centre when Newton converges,
  ``‖x_j − (x_i + Ψ_i u)‖ ≤ ε`` and the tangent spaces agree, ``σ_min(Ψ_iᵀ Ψ_j) ≥ 1 − ε``;
  otherwise ``α`` shrinks, which **adapts the step to the local curvature**;
* **cropping**: each pair of overlapping charts cuts both polytopes with the radical
  (power) plane of their balls, ``2 u·u_j ≤ ‖u_j‖² + r_i² − r_j²`` with
  ``u_j = Ψ_iᵀ (x_j − x_i)``.  A chart whose polytope lies inside its ball is *closed*;
  when every chart is closed, the connected component of the start point is covered;
* **frontier** charts, whose centre leaves the box ``lower ≤ x ≤ upper`` (the upper
  bounds on the slack variables of §4), are kept but never expanded, so that the
  atlas of an unbounded manifold stays finite.

The polytopes are kept as vertex lists with, for each vertex, the set of its ``k``
active constraints (cube faces and cutting planes); two vertices share an edge when
they share ``k − 1`` of them, which is all the cutting step needs.

References
----------
.. [1] M. E. Henderson, "Multiple parameter continuation: Computing implicitly defined
   k-manifolds", International Journal of Bifurcation and Chaos 12(3), 2002.
   (docs/references.bib: henderson2002)
.. [2] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of Cable-Driven
   Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots, Mechanisms and
   Machine Science 12, Springer, 2013, §4. (docs/references.bib: bohigas2013)
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from taut.errors import TautError

__all__ = ["Atlas", "Chart", "ImplicitManifold", "Polytope", "project", "tangent_basis"]


@dataclass(frozen=True)
class ImplicitManifold:
    """The solution set of ``F(x) = 0`` with ``F: R^n → R^(n−k)``, inside a box."""

    function: Callable[[np.ndarray], np.ndarray]  #: ``F(x)``, shape ``(n − k,)``
    jacobian: Callable[[np.ndarray], np.ndarray]  #: ``F_x(x)``, shape ``(n − k, n)``
    dim: int  #: ``k``
    lower: np.ndarray | None = None  #: box bounds, ``(n,)`` (``−∞`` for none)
    upper: np.ndarray | None = None

    def in_box(self, x: np.ndarray) -> bool:
        lo = -np.inf if self.lower is None else self.lower
        hi = np.inf if self.upper is None else self.upper
        return bool(np.all(x >= lo) and np.all(x <= hi))


def tangent_basis(jac: np.ndarray, k: int) -> np.ndarray:
    """Orthonormal basis ``(n, k)`` of the null space of ``jac`` (complete QR of ``jacᵀ``)."""
    q, _ = np.linalg.qr(jac.T, mode="complete")
    return q[:, q.shape[1] - k :]


def project(
    manifold: ImplicitManifold,
    guess: np.ndarray,
    basis: np.ndarray,
    tol: float = 1e-10,
    max_iter: int = 25,
    max_step: float = np.inf,
) -> np.ndarray | None:
    """Newton on ``[F(x); Ψᵀ (x − guess)] = 0`` from ``guess``; ``None`` if it fails.

    ``max_step`` rejects solutions farther than that from ``guess`` (a jump to another
    sheet of the manifold).
    """
    x = np.array(guess, dtype=float)
    n = x.size
    for _ in range(max_iter):
        f = manifold.function(x)
        g = np.concatenate([f, basis.T @ (x - guess)])
        if not np.all(np.isfinite(g)):
            return None
        if np.linalg.norm(f) <= tol * (1.0 + np.linalg.norm(x)):
            break
        A = np.vstack([manifold.jacobian(x), basis.T])
        try:
            dx = np.linalg.solve(A, -g)
        except np.linalg.LinAlgError:
            return None
        x = x + dx
        if not np.all(np.isfinite(x)) or np.linalg.norm(x - guess) > max_step:
            return None
    else:
        return None
    if x.size != n or np.linalg.norm(x - guess) > max_step:
        return None
    return x


class Polytope:
    """A convex polytope of ``R^k`` by its vertices and their active constraints."""

    def __init__(self, k: int, half_side: float):
        corners = np.array(np.meshgrid(*[[-1.0, 1.0]] * k, indexing="ij")).reshape(k, -1).T
        self.k = k
        self.vertices = corners * half_side
        # cube face of dimension d: lower = 2d, upper = 2d + 1; cutting planes get ids ≥ 2k
        self.active = [frozenset(2 * d + int(c[d] > 0) for d in range(k)) for c in corners]
        self.scale = half_side

    def cut(self, normal: np.ndarray, offset: float, ident: int) -> bool:
        """Keep ``{u : normal·u ≤ offset}``; ``True`` if some vertex was removed."""
        nn = np.linalg.norm(normal)
        if nn == 0.0:
            return False
        a, b = normal / nn, offset / nn
        s = self.vertices @ a - b
        tol = 1e-10 * self.scale
        while np.any(np.abs(s) <= tol):  # keep the polytope simple: nudge the plane outwards
            b += 10 * tol
            s = self.vertices @ a - b
        out = s > 0
        if not out.any():
            return False
        edges: dict[frozenset, list[int]] = {}
        for v, act in enumerate(self.active):
            for c in act:
                edges.setdefault(act - {c}, []).append(v)
        new_v, new_a = [], []
        for key, vs in edges.items():
            if len(vs) != 2 or out[vs[0]] == out[vs[1]]:
                continue
            i, o = (vs[0], vs[1]) if not out[vs[0]] else (vs[1], vs[0])
            t = s[i] / (s[i] - s[o])
            new_v.append(self.vertices[i] + t * (self.vertices[o] - self.vertices[i]))
            new_a.append(key | {ident})
        keep = ~out
        self.vertices = np.vstack([self.vertices[keep]] + ([np.array(new_v)] if new_v else []))
        self.active = [a_ for a_, kp in zip(self.active, keep) if kp] + new_a
        return True

    def exterior(self, radius: float) -> np.ndarray:
        """Indices of the vertices outside the ball of ``radius``, farthest first."""
        d = np.linalg.norm(self.vertices, axis=1)
        idx = np.flatnonzero(d > radius * (1 + 1e-9))
        return idx[np.argsort(-d[idx])]


@dataclass
class Chart:
    centre: np.ndarray
    basis: np.ndarray
    radius: float
    polytope: Polytope
    frontier: bool = False  #: centre outside the box, or the projection failed: never expanded
    neighbours: dict[int, float] = field(default_factory=dict)  #: chart index → edge cost
    expanded: bool = False

    def coordinates(self, x: np.ndarray) -> np.ndarray:
        return self.basis.T @ (x - self.centre)

    @property
    def closed(self) -> bool:
        return self.frontier or self.polytope.exterior(self.radius).size == 0


class Atlas:
    """A growing atlas of ``manifold`` started at ``x0`` (Henderson's method, see module doc).

    ``epsilon`` bounds both the distance between a tangent point and its projection and
    the tangent-space change ``1 − σ_min(Ψ_iᵀ Ψ_j)`` between a chart and its child;
    ``min_step`` is the fraction of ``radius`` below which a direction is abandoned
    (the chart becomes a frontier chart).  ``metric`` selects the coordinates in which
    edge costs are measured (all of them by default).

    References
    ----------
    .. [1] M. E. Henderson, "Multiple parameter continuation: Computing implicitly defined
       k-manifolds", International Journal of Bifurcation and Chaos 12(3), 2002.
       (docs/references.bib: henderson2002)
    .. [2] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of
       Cable-Driven Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots,
       Mechanisms and Machine Science 12, Springer, 2013, §4. (docs/references.bib: bohigas2013)
    """

    def __init__(
        self,
        manifold: ImplicitManifold,
        x0: npt.ArrayLike,
        radius: float,
        epsilon: float = 0.1,
        min_step: float = 0.05,
        metric: np.ndarray | None = None,
    ) -> None:
        x0 = np.asarray(x0, dtype=float)
        if radius <= 0 or not 0 < epsilon < 1:
            raise TautError(f"atlas needs radius > 0 and 0 < epsilon < 1, got {radius}, {epsilon}")
        self.manifold = manifold
        self.radius = float(radius)
        self.epsilon = float(epsilon)
        self.min_step = float(min_step)
        self.metric = np.arange(x0.size) if metric is None else np.asarray(metric)
        self.charts: list[Chart] = []
        self._centres = np.empty((0, x0.size))
        if np.linalg.norm(manifold.function(x0)) > 1e-6 * (1 + np.linalg.norm(x0)):
            raise TautError("the start point is not on the manifold (|F(x0)| too large)")
        self.add_chart(x0)

    # -- construction ---------------------------------------------------------------

    def _basis(self, x: np.ndarray) -> np.ndarray:
        return tangent_basis(self.manifold.jacobian(x), self.manifold.dim)

    def cost(self, x: np.ndarray, y: np.ndarray) -> float:
        return float(np.linalg.norm((x - y)[self.metric]))

    def add_chart(self, x: np.ndarray, basis: np.ndarray | None = None) -> int:
        """Add the chart centred at ``x`` and crop it against its overlapping charts."""
        basis = self._basis(x) if basis is None else basis
        k = self.manifold.dim
        # the cube strictly encloses the ball, also for k = 1
        chart = Chart(x, basis, self.radius, Polytope(k, 1.05 * self.radius), frontier=not self.manifold.in_box(x))
        j = len(self.charts)
        if j:
            d = np.linalg.norm(self._centres - x, axis=1)
            for i in np.flatnonzero(d < 2 * self.radius):
                self._crop_pair(int(i), chart, j)
        self.charts.append(chart)
        self._centres = np.vstack([self._centres, x])
        return j

    def _crop_pair(self, i: int, new: Chart, j: int) -> None:
        old = self.charts[i]
        if np.linalg.svd(old.basis.T @ new.basis, compute_uv=False).min() < 1 - 2 * self.epsilon:
            return  # another sheet of the manifold passing nearby
        k2 = 2 * self.manifold.dim
        cut = False
        for a, b, ident in ((old, new, k2 + j), (new, old, k2 + i)):
            u = a.coordinates(b.centre)
            cut |= a.polytope.cut(2 * u, u @ u + a.radius**2 - b.radius**2, ident)
        if cut:
            c = self.cost(old.centre, new.centre)
            old.neighbours[j] = c
            new.neighbours[i] = c

    def grow(self, i: int) -> list[int]:
        """Close chart ``i``: create new charts at its exterior vertices.  Returns them."""
        chart = self.charts[i]
        created: list[int] = []
        chart.expanded = True
        if chart.frontier:
            return created
        while True:
            ext = chart.polytope.exterior(chart.radius)
            if ext.size == 0:
                return created
            s = chart.polytope.vertices[ext[0]]
            j = self._step(i, s / np.linalg.norm(s))
            if j is None:
                chart.frontier = True  # no way forward in that direction: a boundary chart
                return created
            created.append(j)

    def _step(self, i: int, direction: np.ndarray) -> int | None:
        chart = self.charts[i]
        alpha = chart.radius
        while alpha >= self.min_step * chart.radius:
            u = alpha * direction
            guess = chart.centre + chart.basis @ u
            x = project(self.manifold, guess, chart.basis, max_step=self.epsilon)
            if x is not None:
                basis = self._basis(x)
                if np.linalg.svd(chart.basis.T @ basis, compute_uv=False).min() >= 1 - self.epsilon:
                    j = self.add_chart(x, basis)
                    if j not in chart.neighbours:  # no cut happened (should not): force one
                        chart.polytope.cut(2 * u, float(u @ u), 2 * self.manifold.dim + j)
                        c = self.cost(chart.centre, x)
                        chart.neighbours[j] = c
                        self.charts[j].neighbours[i] = c
                    return j
            alpha *= 0.5
        return None

    def complete(self, max_charts: int = 100_000) -> bool:
        """Expand every chart until all are closed; ``False`` if ``max_charts`` was hit."""
        i = 0
        while i < len(self.charts):
            if len(self.charts) >= max_charts:
                return False
            if not self.charts[i].expanded:
                self.grow(i)
            i += 1
        return True

    # -- queries --------------------------------------------------------------------

    @property
    def centres(self) -> np.ndarray:
        return self._centres

    def chart_map(self, i: int, u: np.ndarray) -> np.ndarray | None:
        """The manifold point of tangent coordinates ``u`` in chart ``i``."""
        c = self.charts[i]
        return project(
            self.manifold, c.centre + c.basis @ u, c.basis, max_step=max(self.epsilon, 2 * float(np.linalg.norm(u)))
        )

    def reaches(self, i: int, x: np.ndarray, tol: float = 1e-6) -> bool:
        """Whether the map of chart ``i`` reaches the manifold point ``x`` within its ball."""
        c = self.charts[i]
        u = c.coordinates(x)
        if np.linalg.norm(u) > c.radius or np.linalg.norm(x - c.centre) > 2 * c.radius:
            return False
        y = self.chart_map(i, u)
        return y is not None and np.linalg.norm(y - x) <= tol * (1 + np.linalg.norm(x))

    def covering_chart(self, x: np.ndarray) -> int | None:
        """A chart whose map reaches ``x`` (a manifold point) within its ball, if any."""
        d = np.linalg.norm(self._centres - x, axis=1)
        for i in np.argsort(d):
            if d[i] > 2 * self.radius:
                break
            if self.reaches(int(i), x):
                return int(i)
        return None
