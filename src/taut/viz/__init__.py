"""Figures and the HTML report (``docs/architecture.md`` §1: ``viz`` reads model, kinematics, statics
and workspace results; it never imports ``cli``).

- :func:`draw_robot` — a robot at one pose (planar: 2-D axes; spatial: 3-D axes);
- :func:`plot_workspace` — a grid workspace result (planar mask image, spatial scatter);
- :func:`plot_tensions` — cable tensions along a sequence of poses;
- :class:`Report` — a self-contained ``index.html`` with PNG figures, tables and JSON.

Every function takes ``ax=None`` (a new figure) or an existing ``Axes`` and returns the
``Axes``; cable *i* has the same colour in every figure and is labelled with its 1-based
number.
"""

from taut.viz.report import Report
from taut.viz.robot import draw_robot
from taut.viz.tensions import plot_tensions
from taut.viz.workspace import plot_workspace

__all__ = ["Report", "draw_robot", "plot_tensions", "plot_workspace"]
