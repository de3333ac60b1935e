"""Figures and the HTML report.  ``viz`` only draws (``docs/architecture.md`` §1): its
functions take a robot and the results computed by the other packages and return figures;
they never run a solver, a planner, a simulation or an atlas builder.  At run time a ``viz``
module imports from taut only ``errors``, ``geometry``, ``model``, ``kinematics`` and
``viz``; the classes of the results it draws are imported for annotations only
(``tests/test_layers.py``).  The demo (:mod:`taut.demo`) and the command line run the
analyses and pass their results here.

- :func:`draw_robot` — a robot at one pose (planar: 2-D axes; spatial: 3-D axes);
- :func:`plot_workspace` — a grid workspace result (planar mask image, spatial scatter);
- :func:`plot_tensions` — cable tensions along a sequence of poses;
- :class:`Report` — a self-contained ``index.html`` with PNG figures, tables and JSON.

A function that draws on one set of axes takes ``ax: matplotlib.axes.Axes | None = None``
and returns the ``Axes`` it drew on: the given one, or with ``ax=None`` the axes of a new
figure (made through pyplot).  These are :func:`draw_robot`, :func:`plot_workspace`,
:func:`plot_tensions`, :func:`taut.viz._robot.draw_scene_2d`,
:func:`taut.viz._robot.draw_scene_3d` and :func:`taut.viz._trajectory.draw_wrapped_cables`.
A 3-D plot (a spatial robot or scene, a full spatial workspace) needs an
``mpl_toolkits.mplot3d.axes3d.Axes3D`` (``projection="3d"``), a 2-D plot a plain ``Axes``;
axes of the other kind raise :class:`~taut.errors.ArgumentError`, as does every other
argument a figure cannot be drawn from (``docs/architecture.md`` §2.7).

A function that draws several panels takes ``fig: matplotlib.figure.Figure | None = None``
instead and returns that ``Figure``: the given one, which must be empty (a figure that
already has axes raises :class:`~taut.errors.ArgumentError`), or a new one.  These are
:func:`taut.viz._atlas.plot_atlas`, :func:`taut.viz._calibration.plot_calibration`,
:func:`taut.viz._check.plot_check`,
:func:`taut.viz._dgp.plot_equilibria`, :func:`taut.viz._dgp.plot_tracking`,
:func:`taut.viz._plan.plot_plan`, :func:`taut.viz._sag.plot_sag` and :func:`taut.viz._trajectory.plot_trajectory`.

Cable *i* has the same colour in every figure and is labelled with its 1-based number.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports

if TYPE_CHECKING:
    from taut.viz._atlas import plot_atlas
    from taut.viz._calibration import plot_calibration
    from taut.viz._certified import plot_certified
    from taut.viz._check import plot_check
    from taut.viz._dgp import plot_equilibria, plot_tracking
    from taut.viz._dynamics import plot_control, plot_motion_tensions
    from taut.viz._plan import plot_plan
    from taut.viz._report import Report
    from taut.viz._robot import draw_robot
    from taut.viz._sag import plot_sag
    from taut.viz._tensions import plot_tensions
    from taut.viz._trajectory import plot_trajectory
    from taut.viz._workspace import plot_workspace

#: Every name is imported on first use (PEP 562), so that importing the package loads nothing heavy.
_LAZY = {
    "plot_atlas": "taut.viz._atlas",
    "plot_calibration": "taut.viz._calibration",
    "plot_certified": "taut.viz._certified",
    "plot_check": "taut.viz._check",
    "plot_equilibria": "taut.viz._dgp",
    "plot_tracking": "taut.viz._dgp",
    "plot_control": "taut.viz._dynamics",
    "plot_motion_tensions": "taut.viz._dynamics",
    "plot_plan": "taut.viz._plan",
    "Report": "taut.viz._report",
    "draw_robot": "taut.viz._robot",
    "plot_sag": "taut.viz._sag",
    "plot_tensions": "taut.viz._tensions",
    "plot_trajectory": "taut.viz._trajectory",
    "plot_workspace": "taut.viz._workspace",
}

__all__ = [
    "Report",
    "draw_robot",
    "plot_atlas",
    "plot_calibration",
    "plot_certified",
    "plot_check",
    "plot_control",
    "plot_equilibria",
    "plot_motion_tensions",
    "plot_plan",
    "plot_sag",
    "plot_tensions",
    "plot_tracking",
    "plot_trajectory",
    "plot_workspace",
]

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
