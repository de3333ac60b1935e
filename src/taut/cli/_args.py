"""Parsing of the command line's value syntax: poses, vectors, numbers with their ranges,
output paths, the ROBOT argument."""

from __future__ import annotations

import argparse
import math
import os
import re
from collections.abc import Callable, Collection
from pathlib import Path
from typing import TYPE_CHECKING

from taut.cli._output import check_writable, warning
from taut.errors import PoseError, TautError
from taut.model import MAX_MAGNITUDE

if TYPE_CHECKING:
    import numpy as np

    from taut.model import Robot

_PI = re.compile(r"^([+-]?)(\d*\.?\d*)\*?pi(?:/(\d*\.?\d+))?$")


def number(text: str, what: str) -> float:
    """A float; angles may be written ``35deg`` or as multiples of pi (``pi/8``, ``-3pi/4``)."""
    t = text.strip().lower().replace(" ", "")
    scale = 1.0
    if t.endswith("deg"):
        t, scale = t[:-3], math.pi / 180
    m = _PI.match(t)
    try:
        if m:
            sign, k, div = m.groups()
            value = (-1 if sign == "-" else 1) * float(k or 1) * math.pi / float(div or 1)
        else:
            value = float(t)
    except (ValueError, ZeroDivisionError):
        raise TautError(f"{what}: {text!r} is not a number") from None
    value *= scale
    if not math.isfinite(value):
        raise TautError(f"{what}: {text!r} is not finite")
    if abs(value) > MAX_MAGNITUDE:
        raise TautError(f"{what}: {text!r} is out of range (taut takes magnitudes up to {MAX_MAGNITUDE:g} in SI units)")
    return value


def vector(text: str, what: str) -> np.ndarray:
    """Comma-separated numbers."""
    import numpy as np

    parts = [p for p in text.split(",")]
    if not text.strip() or any(not p.strip() for p in parts):
        raise TautError(f"{what}: expected comma-separated numbers, got {text!r}")
    return np.array([number(p, what) for p in parts])


def assignments(text: str, what: str) -> dict[str, float | None]:
    """``name=value,...`` (values as :func:`number`, so ``35deg`` and ``pi/8`` work); a bare
    ``name`` maps to None (the caller decides what it stands for).  Names are lower-cased."""
    out: dict[str, float | None] = {}
    for item in text.split(","):
        if not item.strip():
            continue
        name, eq, value = item.partition("=")
        name = name.strip().lower()
        if not name:
            raise TautError(f"{what}: expected name=value, got {item.strip()!r}")
        if name in out:
            raise TautError(f"{what}: {name!r} is given twice")
        out[name] = number(value, f"{what} {name}") if eq else None
    return out


def pose(robot: Robot, text: str) -> np.ndarray:
    """``x,y`` / ``x,y,theta`` / ``x,y,z,a,b,c`` followed by joint coordinates."""
    from taut.kinematics import as_poses

    values = vector(text, "--pose")
    if values.size != robot.pose_size:
        raise PoseError(
            f"--pose: {robot.name} needs {robot.pose_size} coordinates ({','.join(robot.pose_names)}), got {values.size}"
        )
    return as_poses(robot, values)[0][0]


def default_pose(robot: Robot) -> np.ndarray:
    """The example's `home` reference pose if it has one, else the centroid of the exits."""
    import numpy as np

    if robot.reference is not None and robot.reference.poses:
        name = "home" if "home" in robot.reference.poses else next(iter(robot.reference.poses))
        return np.asarray(robot.reference.poses[name], float)
    from taut.kinematics import default_guess

    return default_guess(robot)


def output_file(text: str | None, what: str, suffixes: Collection[str] | None = None) -> Path | None:
    """The path of an output option, checked before any computation (see
    :func:`taut.cli._output.check_writable`), with one of ``suffixes`` if given.  The file is
    written at exactly this path."""
    if text is None:
        return None
    path = Path(text)
    if suffixes is not None and path.suffix.lower() not in suffixes:
        raise TautError(f"{what}: {text!r} must end in one of {', '.join(sorted(suffixes))}")
    check_writable(path, what)
    return path


def plot_file(text: str | None) -> Path | None:
    """``--plot FILE``: :func:`output_file` with a suffix matplotlib writes (png, pdf, svg, ...)."""
    if text is None:
        return None
    from matplotlib.figure import Figure

    return output_file(text, "--plot", {f".{k}" for k in Figure().canvas.get_supported_filetypes()})


def load(spec: str, cable_set: str | None = None) -> Robot:
    """The robot of a command: a file in any format :mod:`taut.model` reads, or a built-in
    example; ``cable_set`` is the ``--cable-set`` of a CASPR model."""
    from taut.model import load_robot

    return load_robot(spec, cable_set=cable_set)


def straight_cables(robot: Robot, what: str, hint: str = "") -> None:
    """Warn, on stderr, that ``what`` takes ``robot``'s sagging cables (``cables[].weight``) as
    straight lines: its answer is the straight model's (``hint``: what models them)."""
    if robot.sagging_cables:
        cables = ", ".join(str(i + 1) for i in robot.sagging_cables)
        after = f" ({hint})" if hint else ""
        warning(f"{robot.name}: cables {cables} sag (cables[].weight); {what} takes them as straight lines{after}")


# ---- argparse types: numeric options are checked as the command line is parsed ----------

#: Largest count of a budget option (``--max-boxes``, ``--max-charts``, ...): the kernels
#: count in 64-bit signed integers.
MAX_COUNT = 2**63 - 1

#: Largest ``--seed``: NumPy's seed sequences take any non-negative integer, 32 bits are
#: the convention every other tool follows.
MAX_SEED = 2**32 - 1


def count(least: int = 1, most: int = MAX_COUNT) -> Callable[[str], int]:
    """An argparse ``type``: a whole number from ``least`` to ``most``."""

    def convert(text: str) -> int:
        try:
            n = int(text)
        except ValueError:
            n = None
        if n is None or not least <= n <= most:
            raise argparse.ArgumentTypeError(f"expected a whole number from {least} to {most}, got {text!r}")
        return n

    convert.__name__ = "count"
    return convert


def seed(text: str) -> int:
    """An argparse ``type``: a random seed, 0 to :data:`MAX_SEED`."""
    return count(0, MAX_SEED)(text)


def real(
    *, above: float | None = None, least: float | None = None, below: float | None = None, most: float | None = None
) -> Callable[[str], float]:
    """An argparse ``type``: a finite number as :func:`number` reads it (``35deg``, ``pi/8``;
    magnitudes up to :data:`~taut.model.MAX_MAGNITUDE`), with optional bounds: greater than
    ``above``, at least ``least``, less than ``below``, at most ``most``."""
    bounds = [
        f"{name} {bound:g}"
        for name, bound in (("greater than", above), ("at least", least), ("less than", below), ("at most", most))
        if bound is not None
    ]

    def convert(text: str) -> float:
        try:
            x = number(text, "value")
        except TautError as exc:
            raise argparse.ArgumentTypeError(str(exc).removeprefix("value: ")) from None
        if (
            (above is not None and not x > above)
            or (least is not None and not x >= least)
            or (below is not None and not x < below)
            or (most is not None and not x <= most)
        ):
            want = "a finite number" + (f" {' and '.join(bounds)}" if bounds else "")
            raise argparse.ArgumentTypeError(f"expected {want}, got {text!r}")
        return x

    convert.__name__ = "real"
    return convert


#: Most local worker processes: more than this many per core only thrashes.
WORKERS_PER_CPU = 4


def worker_count(text: str) -> int:
    """``--workers N`` (an argparse ``type``): 1 to :data:`WORKERS_PER_CPU` per CPU."""
    largest = WORKERS_PER_CPU * (os.cpu_count() or 1)
    try:
        n = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a whole number of processes, got {text!r}") from None
    if not 1 <= n <= largest:
        raise argparse.ArgumentTypeError(f"expected 1 to {largest} processes on this machine, got {n}")
    return n


def scheduler_address(text: str) -> str:
    """``--scheduler ADDRESS`` (an argparse ``type``): ``tcp://HOST:PORT`` or ``HOST:PORT``.
    The command line has no options for TLS certificates, and in-process or UCX schedulers
    are not reached from another process, so TCP is the one transport it takes."""
    address = text.strip()
    scheme, sep, rest = address.partition("://")
    if not sep:
        scheme, rest = "tcp", address
    host, colon, port = rest.rpartition(":")
    if scheme.lower() != "tcp" and sep and host and port.isdigit():
        raise argparse.ArgumentTypeError(
            f"the command line reaches a dask scheduler over TCP only: expected tcp://HOST:PORT, got {text!r}"
        )
    if (
        scheme.lower() != "tcp"
        or not colon
        or not host
        or any(c.isspace() or c == "/" for c in host)
        or not port.isdigit()
        or len(port) > 5
        or not 0 < int(port) < 65536
    ):
        raise argparse.ArgumentTypeError(f"expected a dask scheduler address tcp://HOST:PORT, got {text!r}")
    return address


def add_parallel(parser: argparse.ArgumentParser, *, workers: int | None) -> None:
    """``--workers N`` (default ``workers``) and ``--scheduler ADDRESS``: where the work runs."""
    parser.add_argument("--workers", type=worker_count, default=workers, help="local worker processes")
    parser.add_argument(
        "--scheduler", type=scheduler_address, metavar="ADDRESS", help="dask.distributed scheduler tcp://HOST:PORT"
    )


#: Help of ``--pose``.
POSE_HELP = (
    "pose x,y | x,y,theta | x,y,z,a,b,c then joint coordinates (angles in rad, or 30deg, pi/8); "
    "write --pose=-1,... for a leading minus"
)


def grid(text: str | None, dimension: int) -> tuple[list[tuple[float, float, int]] | None, int | None]:
    """``--grid N`` (points per axis) or ``lo:hi:n;lo:hi:n[;...]`` (one range per axis), with
    at least one point per axis and at most :data:`MAX_GRID_POSES` poses in all."""
    import numpy as np

    from taut.workspace import MAX_GRID_POSES

    if text is None:
        return None, None
    if text.strip().isdigit():
        # more than 10 digits is more than MAX_GRID_POSES on one axis (and Python refuses
        # to convert thousands of digits)
        n = int(text) if len(text.strip()) <= 10 else MAX_GRID_POSES + 1
        count = n**dimension
        axes = None
    else:
        axes = []
        for part in text.split(";"):
            lo, hi, k = (part.split(":") + [None, None])[:3]
            if lo is None or hi is None or k is None or not k.strip().isdigit() or len(k.strip()) > 9:
                raise TautError(f"--grid: expected N or lo:hi:n;lo:hi:n[;...], got {text!r}")
            axes.append((number(lo, "--grid"), number(hi, "--grid"), int(k)))
        n = min(k for _, _, k in axes)
        count = int(np.prod([float(k) for _, _, k in axes]))
    if n < 1:
        raise TautError(f"--grid: every axis needs at least one point, got {text!r}")
    if count > MAX_GRID_POSES:
        raise TautError(f"--grid: {text!r} makes {float(count):.3g} poses, more than {MAX_GRID_POSES:,}")
    return axes, None if axes is not None else n
