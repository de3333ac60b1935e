"""A HiGHS instance that prints nothing.

highspy (≥ 1.8) writes its banner ("Running HiGHS …") from C to the process's stdout the
first time an instance does anything, including the callback registration that
``highspy.Highs.__init__`` itself performs; ``output_flag`` set after construction is too
late.  :class:`QuietHighs` sets it before that first call, so that ``taut … --json`` keeps
stdout for the result alone.
"""

from __future__ import annotations

import highspy


class QuietHighs(highspy.Highs):
    """``highspy.Highs`` with ``output_flag`` off from the start: no banner, no log on stdout.

    Examples
    --------
    >>> status, value = QuietHighs().getOptionValue("output_flag")
    >>> value
    False
    """

    def enableCallbacks(self) -> None:  # noqa: N802 — highspy's name, called by Highs.__init__
        self.setOptionValue("output_flag", False)
        super().enableCallbacks()
