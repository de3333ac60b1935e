"""Progress bars of long commands: rich, on stderr, only when stderr is a terminal and
``--json`` is not given, so that stdout stays the result alone."""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager

#: ``progress(done, total)``: the callback every long-running library function takes.
ProgressCallback = Callable[[int, "int | None"], None]


def wanted(as_json: bool) -> bool:
    """Whether a command shows a bar: stderr is a terminal and the output is not ``--json``."""
    return not as_json and sys.stderr.isatty()


@contextmanager
def progress_bar(label: str, enabled: bool) -> Iterator[ProgressCallback | None]:
    """A ``progress(done, total)`` callback drawing a transient bar on stderr, or None
    (the library then reports nothing) when ``enabled`` is false."""
    if not enabled:
        yield None
        return
    from rich.console import Console
    from rich.progress import Progress

    bar = Progress(console=Console(stderr=True), transient=True)
    task = bar.add_task(label, total=None)
    with bar:

        def update(done: int, total: int | None) -> None:
            bar.update(task, completed=done, total=total)

        yield update
