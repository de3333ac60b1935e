"""Parsing of the command line's value syntax: poses, vectors, grids."""

from __future__ import annotations

import argparse
import math
import os
import re
from collections.abc import Collection
from pathlib import Path
from typing import TYPE_CHECKING

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


def positive(value: float, what: str, *, largest: float = math.inf) -> float:
    """A finite value ``0 < value <= largest`` of a numeric option, or a :class:`TautError`."""
    if not (math.isfinite(value) and 0 < value <= largest):
        bound = "" if math.isinf(largest) else f" and at most {largest:g}"
        raise TautError(f"{what} must be a finite number greater than 0{bound}, got {value!r}")
    return value


def output_file(text: str | None, what: str, suffixes: Collection[str] | None = None) -> Path | None:
    """The path of an output option, checked before any computation: a file (not a
    directory) in an existing, writable directory, with one of ``suffixes`` if given.  The
    file is written at exactly this path."""
    if text is None:
        return None
    path = Path(text)
    if suffixes is not None and path.suffix.lower() not in suffixes:
        raise TautError(f"{what}: {text!r} must end in one of {', '.join(sorted(suffixes))}")
    if not path.name or path.is_dir():
        raise TautError(f"{what}: {text!r} is a directory; give a file name")
    parent = path.parent
    if not parent.is_dir():
        raise TautError(f"{what}: the directory {str(parent)!r} does not exist")
    existed = path.exists()
    try:
        # opening for append is the one reliable test (read-only mounts, /proc, permissions)
        with path.open("a"):
            pass
    except OSError as exc:
        raise TautError(f"{what}: cannot write {text!r}: {exc.strerror or exc}") from None
    if not existed:
        os.unlink(path)
    return path


def plot_file(text: str | None) -> Path | None:
    """``--plot FILE``: :func:`output_file` with a suffix matplotlib writes (png, pdf, svg, ...)."""
    if text is None:
        return None
    from matplotlib.figure import Figure

    return output_file(text, "--plot", {f".{k}" for k in Figure().canvas.get_supported_filetypes()})


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
