"""Cable tensions along a sequence of poses: :func:`plot_tensions`.

One line per cable (labelled with its 1-based number, in the cable's colour used by every
taut figure), the tension bounds ``τ_min``/``τ_max`` dashed, and the samples where no
feasible tension distribution exists shaded in red with a mark on the x axis.  The layout
follows the per-cable time plots of Rushton (2022) (Figs. 4.7, 4.10, 6.10:
one curve per cable over the trajectory, markers at events), with tensions in place of
lengths.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, Figs. 4.7, 4.10, 6.10. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from taut._checks import as_array
from taut.errors import ArgumentError
from taut.viz._style import DISALLOWED, axes_2d, cable_color

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = ["plot_tensions"]


def _runs(flags: np.ndarray) -> list[tuple[int, int]]:
    """Maximal runs ``[start, stop)`` of True in a boolean vector."""
    d = np.diff(np.concatenate([[0], flags.astype(np.int8), [0]]))
    return list(zip(np.flatnonzero(d == 1).tolist(), np.flatnonzero(d == -1).tolist()))


def plot_tensions(
    times_or_index: npt.ArrayLike | None,
    tensions: npt.ArrayLike,
    tmin: npt.ArrayLike,
    tmax: npt.ArrayLike,
    feasible: npt.ArrayLike | None = None,
    ax: Axes | None = None,
    *,
    mask_infeasible: bool = True,
) -> Axes:
    """Plot tensions ``(N, n)`` against ``times_or_index`` (``N`` times; ``None`` for the
    sample index) on 2-D axes ``ax`` (``None``: a new figure) and return that ``Axes``.
    3-D axes, arrays that are not numbers and sizes that do not match raise
    :class:`~taut.errors.ArgumentError`.

    ``tmin``/``tmax`` are scalars or one bound per cable (infinite bounds are not drawn);
    ``feasible (N,)`` marks the samples without a feasible distribution; their tensions
    (NaN, zeros or a best effort, depending on the method) are not drawn unless
    ``mask_infeasible=False``: the lines break there.  Cable lines have ``gid="tension-<i>"``; the
    infeasible marks are one line with ``gid="infeasible"`` whose x data are the
    infeasible samples."""
    T = as_array(tensions, "tensions", finite=False, error=ArgumentError)
    if T.ndim == 1:
        T = T[None, :]
    if T.ndim != 2:
        raise ArgumentError(f"tensions must be (N, n), got shape {np.shape(tensions)}")
    N, n = T.shape
    if times_or_index is None:
        x, xlabel = np.arange(N, dtype=float), "sample"
    else:
        x, xlabel = as_array(times_or_index, "times", finite=False, error=ArgumentError).ravel(), "time [s]"
        if x.size != N:
            raise ArgumentError(f"{x.size} times for {N} tension samples")
    ok = np.ones(N, bool) if feasible is None else np.asarray(feasible, bool).ravel()
    if ok.size != N:
        raise ArgumentError(f"{ok.size} feasibility flags for {N} tension samples")
    if mask_infeasible and not ok.all():
        T = np.where(ok[:, None], T, np.nan)
    lo, hi = (as_array(b, "tension bounds", finite=False, error=ArgumentError) for b in (tmin, tmax))
    if lo.size not in (1, n) or hi.size not in (1, n):
        raise ArgumentError(f"tension bounds are one number or one per cable ({n}), got {lo.size} and {hi.size}")
    lo, hi = np.broadcast_to(lo.ravel(), (n,)), np.broadcast_to(hi.ravel(), (n,))
    ax = axes_2d(ax, "a plot of tensions", figsize=(7.0, 4.0))

    for i in range(n):
        ax.plot(
            x,
            T[:, i],
            color=cable_color(i),
            lw=1.5,
            marker="." if N <= 40 else None,
            label=f"cable {i + 1}",
            gid=f"tension-{i + 1}",
        )
    for bounds, name in ((lo, "τ_min"), (hi, "τ_max")):
        finite = np.isfinite(bounds)
        if not finite.any():
            continue
        if np.all(bounds[finite] == bounds[finite][0]):
            ax.axhline(bounds[finite][0], color="black", ls="--", lw=1.0, label=name, gid="bound")
        else:
            drawn = np.flatnonzero(finite).tolist()
            for i in drawn:
                ax.axhline(
                    bounds[i],
                    color=cable_color(i),
                    ls="--",
                    lw=0.9,
                    alpha=0.8,
                    label=name if i == drawn[0] else None,
                    gid="bound",
                )
    bad = ~ok
    if bad.any():
        order = np.argsort(x, kind="stable")
        xs, bs = x[order], bad[order]
        half = np.diff(xs) / 2 if N > 1 else np.array([0.5])
        left = np.concatenate([[half[0]], half])
        right = np.concatenate([half, [half[-1]]])
        for k, (a, b) in enumerate(_runs(bs)):
            ax.axvspan(
                xs[a] - left[a],
                xs[b - 1] + right[b - 1],
                color=DISALLOWED,
                alpha=0.15,
                lw=0,
                label="infeasible" if k == 0 else None,
                gid="infeasible-span",
            )
        ax.plot(
            x[bad],
            np.zeros(int(bad.sum())),
            ls="none",
            marker="x",
            color=DISALLOWED,
            ms=6,
            clip_on=False,
            transform=ax.get_xaxis_transform(),
            gid="infeasible",
        )
    ax.set_xlabel(xlabel)
    ax.set_ylabel("tension [N]")
    ax.grid(True, lw=0.3, alpha=0.5)
    title = f"cable tensions: {int(ok.sum())} of {N} samples feasible"
    ax.set_title(title, fontsize=10)
    ax.legend(fontsize=8, ncol=1 + (n + 3) // 14, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    if N > 1 and np.ptp(x) > 0:
        ax.set_xlim(x.min(), x.max())
    return ax
