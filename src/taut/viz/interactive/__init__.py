"""Interactive 3-D views: plotly figures of a robot and of the results computed by the other
packages, to rotate, scrub through and hover over — inline in a notebook, or written to an
HTML file that opens offline (:func:`write_html`).  Needs the ``view`` extra (plotly), which
is imported on first use; without it a view raises a one-line
:class:`~taut.errors.TautError` naming the extra.

Like the rest of :mod:`taut.viz` these functions only draw (``docs/architecture.md`` §1).

- :func:`view_robot` — a robot at one pose, cables coloured by tension, slack ones dashed;
- :func:`view_motion` — poses over time (a trajectory, a planned path): time slider and play
  button, cable lengths and tensions in a linked 2-D plot;
- :func:`view_trajectory` — the same for a wrapping trajectory (:func:`taut.wrapping.run_trajectory`),
  cables drawn along their wrapped paths;
- :func:`view_equilibria` — the solutions of the geometrico-static problem with a selector;
- :func:`view_workspace` — a grid or certified workspace as a layer that can be hidden;
- :func:`view_control` — a controlled motion: reference and simulated platform side by side,
  the tension margin over time;
- :func:`write_html` — figures to one HTML file, plotly.js embedded or written once beside it.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports

if TYPE_CHECKING:
    from taut.viz.interactive._control import view_control
    from taut.viz.interactive._equilibria import view_equilibria
    from taut.viz.interactive._html import PLOTLY_JS, html_fragment, write_html, write_plotly_js
    from taut.viz.interactive._motion import MAX_FRAMES, view_motion, view_trajectory
    from taut.viz.interactive._robot import view_robot
    from taut.viz.interactive._scene import POSE_TRACES
    from taut.viz.interactive._workspace import MAX_POINTS, view_workspace

_LAZY = {
    "MAX_FRAMES": "taut.viz.interactive._motion",
    "MAX_POINTS": "taut.viz.interactive._workspace",
    "PLOTLY_JS": "taut.viz.interactive._html",
    "POSE_TRACES": "taut.viz.interactive._scene",
    "html_fragment": "taut.viz.interactive._html",
    "view_control": "taut.viz.interactive._control",
    "view_equilibria": "taut.viz.interactive._equilibria",
    "view_motion": "taut.viz.interactive._motion",
    "view_robot": "taut.viz.interactive._robot",
    "view_trajectory": "taut.viz.interactive._motion",
    "view_workspace": "taut.viz.interactive._workspace",
    "write_html": "taut.viz.interactive._html",
    "write_plotly_js": "taut.viz.interactive._html",
}

__all__ = [
    "MAX_FRAMES",
    "MAX_POINTS",
    "PLOTLY_JS",
    "POSE_TRACES",
    "html_fragment",
    "view_control",
    "view_equilibria",
    "view_motion",
    "view_robot",
    "view_trajectory",
    "view_workspace",
    "write_html",
    "write_plotly_js",
]

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
