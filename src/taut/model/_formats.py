"""The robot file formats taut reads and writes, chosen by the file's name.

Adding a format is one entry in :data:`FORMATS`: a name pattern, a reader (or None), a writer
(or None). The most specific pattern is listed first (``*_bodies.xml`` before any ``*.xml``).
"""

from __future__ import annotations

import fnmatch
import os
import stat
import tempfile
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from taut.errors import RobotFileError

if TYPE_CHECKING:
    from taut.model._robot import Robot

#: ``reader(path, text, cable_set)``: the text of the file (read with the size and
#: regular-file limits of :func:`taut.model.load_robot`) to a validated robot.
Reader = Callable[[Path, str, "str | None"], "Robot"]
#: ``writer(robot, path)``: writes the file (and any companion files the format needs).
Writer = Callable[["Robot", Path], None]


@dataclass(frozen=True)
class Format:
    """One file format: its name, the file-name patterns that select it, how to read and write it."""

    name: str
    patterns: tuple[str, ...]
    reader: Reader | None
    writer: Writer | None
    #: whether ``--cable-set`` means something for this format
    cable_sets: bool = False


def _read_taut(path: Path, text: str, cable_set: str | None) -> Robot:
    from taut.model._io import parse_robot

    if cable_set is not None:
        raise RobotFileError(f"{path}: --cable-set selects a cable set of a CASPR model; a taut file has one set")
    return parse_robot(text, str(path), json_text=path.name.lower().endswith(".json"))


def _write_taut(robot: Robot, path: Path) -> None:
    from taut.model._io import save_robot

    save_robot(robot, path)


def _read_caspr(path: Path, text: str, cable_set: str | None) -> Robot:
    from taut.model._caspr import parse_caspr

    return parse_caspr(path, text, cable_set)


def _write_caspr(robot: Robot, path: Path) -> None:
    from taut.model._caspr import write_caspr

    write_caspr(robot, path)


def _read_wirex(path: Path, text: str, cable_set: str | None) -> Robot:
    from taut.model._wirex import parse_wirex, wirex_robot

    if cable_set is not None:
        raise RobotFileError(f"{path}: --cable-set selects a cable set of a CASPR model; a WireX file has one set")
    return wirex_robot(parse_wirex(text.encode("utf-8"), str(path)), str(path))


def _write_wirex(robot: Robot, path: Path) -> None:
    from taut.model._wirex import write_wirex

    write_wirex(robot, path)


def _write_mjcf(robot: Robot, path: Path) -> None:
    from taut.model._mjcf import write_mjcf

    write_mjcf(robot, path)


#: Every format, most specific pattern first.
FORMATS: tuple[Format, ...] = (
    Format("caspr", ("*_bodies.xml",), _read_caspr, _write_caspr, cable_sets=True),
    Format("mujoco", ("*.mjcf.xml",), None, _write_mjcf),
    Format("wirex", ("*.wcrfx",), _read_wirex, _write_wirex),
    Format("taut", ("*.yaml", "*.yml", "*.json"), _read_taut, _write_taut),
)


def supported(kind: str) -> str:
    """The patterns of the formats that can be read (``kind="read"``) or written (``"write"``)."""
    pats = [p for f in FORMATS if (f.reader if kind == "read" else f.writer) is not None for p in f.patterns]
    return ", ".join(pats)


def format_of(path: str | Path, kind: str = "read") -> Format:
    """The format whose pattern matches the file name of ``path`` (case-insensitive), able to
    read (``kind="read"``) or write (``kind="write"``) it.

    Raises
    ------
    RobotFileError
        If no format matches, naming the supported ones.
    """
    name = Path(path).name.lower()
    for fmt in FORMATS:
        able = fmt.reader if kind == "read" else fmt.writer
        match = next((p for p in fmt.patterns if fnmatch.fnmatchcase(name, p)), None) if able else None
        if match is not None:
            if kind == "write" and name == match.removeprefix("*"):
                raise RobotFileError(f"{path}: the file name is only the extension; give a name before it")
            return fmt
    verb = "read" if kind == "read" else "write"
    raise RobotFileError(f"{path}: taut cannot {verb} this kind of file; supported: {supported(kind)}")


def read_robot(path: Path, text: str, cable_set: str | None = None) -> Robot:
    """Read the text of the file ``path`` in the format its name selects."""
    reader = format_of(path, "read").reader
    assert reader is not None, "format_of returns a format able to read"
    return reader(path, text, cable_set)


def _check_target(path: Path) -> None:
    """Refuse a file to write that cannot be replaced by a regular file: a directory, a FIFO
    or a device (opening those could block or write elsewhere), a dangling link, a path in
    a directory that does not exist."""
    try:
        mode = path.stat().st_mode
    except FileNotFoundError:
        if path.is_symlink():
            raise RobotFileError(f"{path}: a symbolic link to nothing; cannot write the file") from None
        mode = None
    if mode is not None and stat.S_ISDIR(mode):
        raise RobotFileError(f"{path}: a directory; cannot write the file")
    if mode is not None and not stat.S_ISREG(mode):
        raise RobotFileError(f"{path}: exists and is not a regular file; cannot write the file")
    if not path.parent.is_dir():
        raise RobotFileError(f"{path}: the directory {str(path.parent)!r} does not exist")


def write_robot(robot: Robot, path: str | Path) -> str:
    """Write ``robot`` to ``path`` in the format its name selects; return the format's name.

    The file and its companions (a CASPR model's ``*_cables.xml``) are written in a
    temporary directory beside ``path`` and moved into place only when every one is
    written, so that a failure leaves no file written and none overwritten.

    Raises
    ------
    RobotFileError
        If no format writes such a name, if a file to write is a directory, a FIFO, a device
        or a dangling link, or if writing fails (a full disk).
    """
    path = Path(path)
    fmt = format_of(path, "write")
    assert fmt.writer is not None, "format_of returns a format able to write"
    _check_target(path)
    try:
        with tempfile.TemporaryDirectory(dir=path.parent, prefix=f".{path.name}.", ignore_cleanup_errors=True) as tmp:
            fmt.writer(robot, Path(tmp) / path.name)
            written = sorted(Path(tmp).iterdir())
            for f in written:
                _check_target(path.parent / f.name)
            for f in written:
                os.replace(f, path.parent / f.name)
    except OSError as exc:
        raise RobotFileError(f"{path}: cannot write the file: {exc.strerror or exc}") from None
    return fmt.name


def load_robot(spec: str | Path, *, cable_set: str | None = None) -> Robot:
    """Load a robot from a file path, or a built-in example by name (``taut examples``).

    The file's name selects its format (:mod:`taut.model._formats`): taut's YAML/JSON, a
    WireX ``.wcrfx`` file, or a CASPR ``*_bodies.xml`` model whose cable set ``cable_set``
    (default: the file's ``default_cable_set``) is read from the ``*_cables.xml`` beside it."""
    from taut.model._examples import example, example_names
    from taut.model._io import check_regular, read_text

    path = Path(spec)
    if not path.exists():
        if str(spec) in example_names():
            if cable_set is not None:
                raise RobotFileError(f"{spec}: --cable-set selects a cable set of a CASPR model, not of an example")
            return example(str(spec))
        raise RobotFileError(f"{spec}: no such file and not a built-in example (see `taut examples`)")
    check_regular(path)  # before the name is judged: /dev/zero is not a file of any format
    format_of(path, "read")
    return read_robot(path, read_text(path), cable_set)
