"""Incomplete answers at the command line: a certified search that left boxes undecided
(:mod:`taut.dgp._undecided`) still prints its result, with ``"complete": false`` and the
undecided boxes' enclosures in the JSON and one warning line on stderr naming the
sub-problems concerned; under ``--strict`` the exit status is then :data:`INCOMPLETE`."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from typing import TYPE_CHECKING

from taut.cli._cables import cable_numbers

if TYPE_CHECKING:
    from taut.dgp import UndecidedBox

#: Exit status of a ``--strict`` command whose answer is incomplete.
INCOMPLETE = 3

#: The exit statuses, for the commands' help.
EXIT_STATUS = (
    "Exit status: 0 the answer (complete, or incomplete without --strict), 2 bad input, "
    f"{INCOMPLETE} the answer is incomplete and --strict was given (the JSON is printed all the same)."
)

#: The warning names at most this many sub-problems (a robot with many cables has hundreds),
#: then says how many more; the JSON lists them all.
NAMED = 12

#: How the warning counts the boxes of each cause of :data:`taut.dgp.CAUSES`.
CAUSE_TEXT = {
    "narrow": "too narrow to split",
    "singular": "around a singular solution, even in 256-bit balls",
    "budget": "left when the box budget ran out",
    "tension-sign": "of a solution whose tension signs are undecided",
    "domain-border": "of a solution on the search domain's bound",
}


def add_strict(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--strict",
        action="store_true",
        help=f"exit with status {INCOMPLETE} when the answer is incomplete (boxes left undecided)",
    )


def warning(boxes: Sequence[UndecidedBox], what: str, multiprecision_hint: bool = False) -> str:
    """The one warning line of an incomplete answer: how many boxes, why, and the taut sets
    (1-based, in first-seen order, the first :data:`NAMED`) of the sub-problems they belong to.
    ``multiprecision_hint``: the search would try narrow boxes again with python-flint, so
    say how to install it when it is missing."""
    subsets = list(dict.fromkeys(b.taut for b in boxes))
    names = ", ".join("{" + ",".join(map(str, cable_numbers(t))) + "}" for t in subsets[:NAMED])
    if len(subsets) > NAMED:
        names += f" and {len(subsets) - NAMED} more"
    causes = dict.fromkeys(CAUSE_TEXT, 0)
    for b in boxes:
        causes[b.cause] += 1
    why = ", ".join(f"{k} {CAUSE_TEXT[c]}" for c, k in causes.items() if k)
    if causes["narrow"] and multiprecision_hint:
        from taut.interval import precise_available

        if not precise_available():
            why += "; pip install 'taut[precise]' searches them again in multi-precision"
    noun = "box" if len(boxes) == 1 else "boxes"
    where = "sub-problem" if len(subsets) == 1 else "sub-problems"
    return (
        f"taut: warning: {len(boxes)} {noun} could not be certified ({why}) in {where} {names}: "
        f"the list of {what} may be incomplete"
    )


def report(boxes: Sequence[UndecidedBox], what: str, strict: bool, multiprecision_hint: bool = False) -> int:
    """Print the warning of an incomplete answer (nothing when ``boxes`` is empty) and
    return the exit status."""
    if not boxes:
        return 0
    print(warning(boxes, what, multiprecision_hint), file=sys.stderr)
    return INCOMPLETE if strict else 0
