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
:func:`plot_tensions`, :func:`taut.viz.robot.draw_scene_2d`,
:func:`taut.viz.robot.draw_scene_3d` and :func:`taut.viz.trajectory.draw_wrapped_cables`.
A 3-D plot (a spatial robot or scene, a full spatial workspace) needs an
``mpl_toolkits.mplot3d.axes3d.Axes3D`` (``projection="3d"``), a 2-D plot a plain ``Axes``;
axes of the other kind raise :class:`~taut.errors.ArgumentError`, as does every other
argument a figure cannot be drawn from (``docs/architecture.md`` §2.7).

A function that draws several panels takes ``fig: matplotlib.figure.Figure | None = None``
instead and returns that ``Figure``: the given one, which must be empty (a figure that
already has axes raises :class:`~taut.errors.ArgumentError`), or a new one.  These are
:func:`taut.viz.atlas.plot_atlas`, :func:`taut.viz.check.plot_check`,
:func:`taut.viz.dgp.plot_equilibria`, :func:`taut.viz.dgp.plot_tracking`,
:func:`taut.viz.plan.plot_plan` and :func:`taut.viz.trajectory.plot_trajectory`.

Cable *i* has the same colour in every figure and is labelled with its 1-based number.
"""

from taut.viz.report import Report
from taut.viz.robot import draw_robot
from taut.viz.tensions import plot_tensions
from taut.viz.workspace import plot_workspace

__all__ = ["Report", "draw_robot", "plot_tensions", "plot_workspace"]
