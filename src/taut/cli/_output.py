"""What the commands print and write (``docs/architecture.md`` §4.1): the JSON result on
stdout, the human form (rich text and tables), one-line errors and warnings on stderr, and
output files written whole or not at all."""

from __future__ import annotations

import json
import os
import stat
import sys
import tempfile
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path
from typing import TYPE_CHECKING

from taut.errors import TautError

if TYPE_CHECKING:
    from matplotlib.figure import FigureBase
    from rich.console import Console
    from rich.table import Table

#: Exit status of bad input (any :class:`~taut.errors.TautError`, or bad options).
BAD_INPUT = 2
#: Exit status after Ctrl-C (128 + SIGINT, as shells report it).
INTERRUPTED = 130


def one_line(text: str) -> str:
    """``text`` on one line: its non-blank lines joined by ``"; "``."""
    return "; ".join(ln.strip() for ln in str(text).splitlines() if ln.strip())


def error(message: str) -> None:
    """Print the one line ``taut: error: MESSAGE`` of bad input on stderr."""
    print(f"taut: error: {one_line(message)}", file=sys.stderr)


def warning(message: str) -> None:
    """Print the one line ``taut: warning: MESSAGE`` on stderr."""
    print(f"taut: warning: {one_line(message)}", file=sys.stderr)


def print_json(data: object) -> None:
    """One JSON document on stdout; NaN and infinities are refused, never printed."""
    print(json.dumps(data, indent=2, allow_nan=False))


def emit(data: dict, as_json: bool, human: Callable[[dict], None]) -> None:
    """The result: one JSON document on stdout, or the human form.  Called last, after every
    file of the command is written, so that a failure never follows printed output."""
    if as_json:
        print_json(data)
    else:
        human(data)


def console() -> Console:
    """The rich console of the human output, on stdout."""
    from rich.console import Console

    return Console()


def markup(text: object) -> str:
    """``text`` (a robot's name, a file name) escaped for rich markup, so that brackets in it
    are printed, not read as styles."""
    from rich.markup import escape

    return escape(str(text))


def table(title: str, header: Sequence[str], rows: Sequence[Sequence[str]] = ()) -> Table:
    """A rich table of right-aligned columns; the header and cells are plain text (``[m]`` in a
    header is printed as written)."""
    from rich.table import Table
    from rich.text import Text

    t = Table(title=Text(title))
    for h in header:
        t.add_column(Text(h), justify="right", no_wrap=True)
    for r in rows:
        t.add_row(*(Text(c) for c in r))
    return t


def print_table(con: Console, tab: Table) -> None:
    """Print ``tab`` at its full width, however narrow the console (rich's default is 80
    columns when stdout is not a terminal): a cell is never cut short."""
    from rich.measure import Measurement

    need = Measurement.get(con, con.options.update_width(1 << 20), tab).maximum
    width = con.width
    con.width = max(width, need)
    try:
        con.print(tab, crop=False)
    finally:
        con.width = width


def fmt(x: float) -> str:
    """A number as the human output shows it: 6 significant digits."""
    return f"{x:.6g}"


def _cannot_write(what: str, path: Path, exc: OSError) -> TautError:
    return TautError(f"{what}: cannot write {str(path)!r}: {exc.strerror or exc}")


def check_writable(path: Path, what: str) -> None:
    """Refuse, before anything is computed, an output ``path`` that cannot be written whole:
    a directory, an existing path that is not a regular file (a FIFO, a device, a dangling
    link: opening those could block or write elsewhere), or a path in a directory that does
    not exist or where no file can be created."""
    text = str(path)
    if not path.name:
        raise TautError(f"{what}: {text!r} is a directory; give a file name")
    try:
        mode = path.stat().st_mode
    except FileNotFoundError:
        if path.is_symlink():
            raise TautError(f"{what}: {text!r} is a symbolic link to nothing") from None
        mode = None
    except OSError as exc:
        raise _cannot_write(what, path, exc) from None
    if mode is not None and stat.S_ISDIR(mode):
        raise TautError(f"{what}: {text!r} is a directory; give a file name")
    if mode is not None and not stat.S_ISREG(mode):
        raise TautError(f"{what}: {text!r} exists and is not a regular file")
    if not path.parent.is_dir():
        raise TautError(f"{what}: the directory {str(path.parent)!r} does not exist")
    try:
        # the file is written beside its place and renamed onto it (see written): what must
        # work is creating a file in the directory (read-only mounts, /proc, permissions)
        fd, probe = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.")
    except OSError as exc:
        raise _cannot_write(what, path, exc) from None
    os.close(fd)
    os.unlink(probe)


def _file_mode(path: Path) -> int:
    """The permissions of a new file at ``path``: those of the file it replaces, or the
    default of the user's umask."""
    try:
        return stat.S_IMODE(path.stat().st_mode)
    except OSError:
        umask = os.umask(0)
        os.umask(umask)
        return 0o666 & ~umask


@contextmanager
def written(path: Path, what: str) -> Iterator[Path]:
    """A temporary path beside ``path`` (same directory and suffix) for the block to write;
    renamed onto ``path`` when the block ends, removed when it fails, so that ``path`` holds
    the whole file or is left as it was.  An :class:`OSError` (a full disk, a file too large)
    becomes one :class:`~taut.errors.TautError` naming ``what``."""
    check_writable(path, what)
    tmp: Path | None = None
    try:
        fd, name = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=path.suffix)
        os.close(fd)
        tmp = Path(name)
        os.chmod(tmp, _file_mode(path))
        yield tmp
        os.replace(tmp, path)
        tmp = None
    except OSError as exc:
        raise _cannot_write(what, path, exc) from None
    finally:
        if tmp is not None:
            tmp.unlink(missing_ok=True)


def save_figure(fig: FigureBase, path: Path, data: dict | None = None) -> None:
    """Write the figure of a ``--plot`` option (the whole figure a subfigure or an Axes'
    ``.figure`` belongs to) and close it; record the path in ``data``."""
    import matplotlib.pyplot as plt
    from matplotlib.figure import Figure

    root = fig if isinstance(fig, Figure) else fig.get_figure(root=True)
    assert root is not None, "every figure belongs to a root figure"
    try:
        with written(Path(path), "--plot") as tmp:
            root.savefig(tmp, dpi=110, bbox_inches="tight")
    finally:
        plt.close(root)
    if data is not None:
        data["plot"] = str(path)
