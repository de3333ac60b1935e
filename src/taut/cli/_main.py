"""``taut COMMAND ROBOT [options]`` (``docs/architecture.md`` §4).

Exit status: 0 success, 2 bad input (any :class:`taut.TautError`, or bad options),
3 an incomplete answer under ``--strict``, 1 internal error, 130 on Ctrl-C.  ``--json``
prints the machine-readable result on stdout; the fields named in the issues are a contract.

Every command is a module of :mod:`taut.cli` listed in :data:`COMMANDS`, with

* ``SUMMARY``: its one-line help, and optionally ``DESCRIPTION``, its long help;
* ``ROBOT``: whether it takes the ROBOT argument (and ``--cable-set``);
* ``add_arguments(parser)``: its options (``--json`` is added for every command);
* ``run(ns) -> int``: the command, returning the exit status.
"""

from __future__ import annotations

import argparse
import os
import signal
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from types import ModuleType
from typing import NoReturn

from taut.cli import _atlas as atlas
from taut.cli import _calibrate as calibrate
from taut.cli import _check as check
from taut.cli import _convert as convert
from taut.cli import _demo as demo
from taut.cli import _examples as examples
from taut.cli import _fk as fk
from taut.cli import _igp as igp
from taut.cli import _ik as ik
from taut.cli import _plan as plan
from taut.cli import _sag as sag
from taut.cli import _schema as schema
from taut.cli import _simulate as simulate
from taut.cli import _tensions as tensions
from taut.cli import _trajectory as trajectory
from taut.cli import _view as view
from taut.cli import _workspace as workspace
from taut.cli._output import BAD_INPUT, INTERRUPTED, error
from taut.errors import TautError
from taut.model import supported

#: Every command, in the order ``taut --help`` lists them.
COMMANDS: tuple[tuple[str, ModuleType], ...] = (
    ("examples", examples),
    ("schema", schema),
    ("ik", ik),
    ("tensions", tensions),
    ("workspace", workspace),
    ("sag", sag),
    ("fk", fk),
    ("igp", igp),
    ("plan", plan),
    ("atlas", atlas),
    ("trajectory", trajectory),
    ("check", check),
    ("calibrate", calibrate),
    ("simulate", simulate),
    ("view", view),
    ("convert", convert),
    ("demo", demo),
)


class _Parser(argparse.ArgumentParser):
    """argparse, with its refusals on one line: ``taut: error: ...`` and exit status 2."""

    def error(self, message: str) -> NoReturn:
        error(f"{message} (see `{self.prog} --help`)")
        raise SystemExit(BAD_INPUT)


def build_parser() -> argparse.ArgumentParser:
    p = _Parser(prog="taut", description="Cable-driven parallel robots: kinematics, statics, workspaces.")
    sub = p.add_subparsers(dest="command", required=True, parser_class=_Parser)
    for name, module in COMMANDS:
        long = getattr(module, "DESCRIPTION", None)
        c = sub.add_parser(
            name,
            help=module.SUMMARY,
            description=long or module.SUMMARY,
            formatter_class=argparse.RawDescriptionHelpFormatter if long else argparse.HelpFormatter,
        )
        if module.ROBOT:
            c.add_argument(
                "robot",
                help=f"robot file ({supported('read')}; a CASPR *_bodies.xml with its *_cables.xml beside it) "
                "or built-in example name (see `taut examples`)",
            )
            c.add_argument(
                "--cable-set",
                metavar="ID",
                help="CASPR model: the cable set to use (default: the file's default_cable_set)",
            )
        c.add_argument("--json", action="store_true", help="machine-readable result on stdout")
        module.add_arguments(c)
        c.set_defaults(run=module.run)
    return p


@contextmanager
def _quiet_warnings() -> Iterator[None]:
    """Library warnings (numba's, dask's, numpy's) are not messages for a user of the
    command line: input that would cause them is refused with an error, and what is left is
    noise on stderr.  Logging of third-party libraries is kept to errors, on stderr."""
    import logging
    import warnings

    logging.basicConfig(level=logging.ERROR, stream=sys.stderr)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        yield


def main(argv: list[str] | None = None) -> int:
    try:
        parser = build_parser()
        ns = parser.parse_args(argv)
        for name, value in vars(ns).items():
            # argparse turns ``--opt=--`` into an empty list; every option here takes one value
            if isinstance(value, list):
                parser.error(f"argument --{name.replace('_', '-')}: expected one value, got '--'")
        with _quiet_warnings():
            code: int = ns.run(ns)
        return code
    except TautError as exc:
        error(str(exc))
        return BAD_INPUT
    except (MemoryError, RecursionError) as exc:
        # input large or deep enough to exhaust the process: bad input, not a bug to report
        error(f"the input is too large to process ({type(exc).__name__})")
        return BAD_INPUT
    except KeyboardInterrupt:
        print("taut: interrupted", file=sys.stderr)
        return INTERRUPTED
    except BrokenPipeError:
        # the reader (e.g. `| head`) has gone: stop quietly, as Unix tools do
        sys.stderr.close()
        return 0
    except Exception as exc:  # noqa: BLE001 — the CLI reports, it does not dump tracebacks
        print(f"taut: internal error: {type(exc).__name__}: {exc} (please report it)", file=sys.stderr)
        return 1


def _unraisable(unraisable: sys.UnraisableHookArgs) -> None:
    """Errors in finalizers (``__del__`` of a library's half-built object after the error
    has been reported) are not messages for a user of the command line: one line, and only
    the error's, reaches stderr."""


class _Interrupts:
    """The command line's Ctrl-C: the first raises :class:`KeyboardInterrupt` and is
    remembered, so that the exit status is 130 even where a library swallowed the exception
    (in a finalizer, in compiled code's callbacks); a second one ends the process at once."""

    def __init__(self) -> None:
        self.count = 0

    def __call__(self, signum: int, frame: object) -> None:
        self.count += 1
        if self.count > 1:
            os.write(sys.stderr.fileno(), b"taut: interrupted\n")
            os._exit(INTERRUPTED)
        raise KeyboardInterrupt


def entry() -> None:
    sys.unraisablehook = _unraisable
    interrupts = _Interrupts()
    signal.signal(signal.SIGINT, interrupts)
    code = main()
    if interrupts.count and code != INTERRUPTED:
        print("taut: interrupted", file=sys.stderr)
        code = INTERRUPTED
    raise SystemExit(code)
