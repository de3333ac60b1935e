"""One executor interface for coarse-grained parallelism (``docs/architecture.md`` §5).

:func:`get_executor` returns an object with ``map(fn, items, *, callback=None) -> list``:

* :class:`SerialExecutor` (the default): a loop in this process;
* :class:`ProcessExecutor` (``workers > 1``): local worker processes
  (:class:`concurrent.futures.ProcessPoolExecutor`, started by a fork server so that a
  parent with threads — a progress bar, a dask client — is safe to fork from);
* :class:`DaskExecutor` (``scheduler="tcp://HOST:PORT"``, or an existing
  ``distributed.Client``): the workers of a ``dask.distributed`` cluster (the optional
  extra ``taut[dist]``).

``fn`` and the items must be picklable (module-level functions, NumPy arrays, robots).
Results come back in the order of ``items`` whatever the executor, and every item is
computed by the same code, so results are identical.  ``callback(i)`` is called in this
process as item ``i`` completes (in completion order), for progress bars.
"""

from __future__ import annotations

import multiprocessing
import operator
import re
import weakref
from abc import ABC, abstractmethod
from collections.abc import Callable, Iterable
from concurrent.futures import ProcessPoolExecutor, as_completed
from typing import TYPE_CHECKING, Any, Self, TypeVar

from taut.errors import TautError

if TYPE_CHECKING:
    from distributed import Client

T = TypeVar("T")
R = TypeVar("R")

__all__ = ["DaskExecutor", "Executor", "ProcessExecutor", "SerialExecutor", "as_executor", "get_executor"]

#: Seconds to wait for a dask scheduler before giving up.
CONNECT_TIMEOUT = 5.0


class Executor(ABC):
    """Base interface: ``map(fn, items, *, callback=None) -> list`` and ``close()``."""

    name = "executor"

    @abstractmethod
    def map(
        self, fn: Callable[[T], R], items: Iterable[T], *, callback: Callable[[int], None] | None = None
    ) -> list[R]:
        """``[fn(item) for item in items]`` in order; ``callback(i)`` as item ``i`` completes."""

    def close(self) -> None:  # noqa: B027 — optional hook, not abstract
        """Release workers (a no-op where there are none)."""

    def __enter__(self) -> Self:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def __repr__(self) -> str:
        return f"<{type(self).__name__}>"


class SerialExecutor(Executor):
    """Run every item in this process, in order."""

    name = "serial"

    def map(
        self, fn: Callable[[T], R], items: Iterable[T], *, callback: Callable[[int], None] | None = None
    ) -> list[R]:
        out = []
        for i, item in enumerate(items):
            out.append(fn(item))
            if callback is not None:
                callback(i)
        return out


def _shutdown(pool: ProcessPoolExecutor) -> None:
    pool.shutdown(wait=True, cancel_futures=True)


class ProcessExecutor(Executor):
    """Local worker processes; the pool starts on first use and is reused until
    :meth:`close` (or garbage collection)."""

    name = "processes"

    def __init__(self, workers: int):
        self.workers = int(workers)
        self._pool: ProcessPoolExecutor | None = None
        self._finalizer: weakref.finalize[[ProcessPoolExecutor], ProcessExecutor] | None = None

    def _get_pool(self) -> ProcessPoolExecutor:
        if self._pool is None:
            methods = multiprocessing.get_all_start_methods()
            ctx = multiprocessing.get_context("forkserver" if "forkserver" in methods else "spawn")
            self._pool = ProcessPoolExecutor(max_workers=self.workers, mp_context=ctx)
            self._finalizer = weakref.finalize(self, _shutdown, self._pool)
        return self._pool

    def map(
        self, fn: Callable[[T], R], items: Iterable[T], *, callback: Callable[[int], None] | None = None
    ) -> list[R]:
        items = list(items)
        pool = self._get_pool()
        futures = {pool.submit(fn, item): i for i, item in enumerate(items)}
        out: list[Any] = [None] * len(items)
        for fut in as_completed(futures):
            i = futures[fut]
            out[i] = fut.result()
            if callback is not None:
                callback(i)
        return out

    def close(self) -> None:
        if self._finalizer is not None:
            self._finalizer()
        self._pool = None
        self._finalizer = None

    def __repr__(self) -> str:
        return f"<ProcessExecutor workers={self.workers}>"


class DaskExecutor(Executor):
    """Items run as tasks on a ``dask.distributed`` cluster."""

    name = "dask"

    def __init__(self, client: Client, owns_client: bool = False):
        self.client: Client | None = client
        self._owns = owns_client

    def map(
        self, fn: Callable[[T], R], items: Iterable[T], *, callback: Callable[[int], None] | None = None
    ) -> list[R]:
        from distributed import as_completed as dask_completed

        client = self.client
        if client is None:
            raise TautError("this DaskExecutor is closed: its client was closed by close()")
        items = list(items)
        if not items:
            return []
        futures = client.map(fn, items, pure=False)
        index = {f.key: i for i, f in enumerate(futures)}
        try:
            for fut in dask_completed(futures, loop=client.loop):
                if fut.status == "error":
                    fut.result()  # re-raises the task's exception here
                if callback is not None:
                    callback(index[fut.key])
            return client.gather(futures)
        finally:
            for f in futures:
                f.release()

    def close(self) -> None:
        if self._owns and self.client is not None:
            self.client.close()
            self.client = None

    def __repr__(self) -> str:
        addr = getattr(getattr(self.client, "scheduler", None), "address", "?")
        return f"<DaskExecutor {addr}>"


_ADDRESS = re.compile(r"^(?:(?P<scheme>[a-z]+)://)?(?P<host>\[[0-9a-fA-F:.]+\]|[^\s/:\[\]]+):(?P<port>\d{1,5})$")


def _check_address(address: str, timeout: float) -> None:
    """Refuse an address that is not ``[SCHEME://]HOST:PORT``; for ``tcp`` check within
    ``timeout`` seconds that a dask scheduler listens there.

    A dask scheduler speaks first: on connection it sends its handshake, a frame whose
    first 8 bytes are a little-endian length.  Anything else (an HTTP server, an SSH
    daemon) would leave ``distributed.Client`` reading a frame that never ends, so the
    whole exchange is bounded here, before a client exists."""
    import socket
    import struct

    m = _ADDRESS.match(address)
    if m is None or not 0 < int(m["port"]) < 65536:
        raise TautError(f"scheduler address must look like tcp://HOST:PORT, got {address!r}")
    if (m["scheme"] or "tcp") != "tcp":
        return
    host = m["host"].strip("[]")
    try:
        with socket.create_connection((host, int(m["port"])), timeout=timeout) as sock:
            sock.settimeout(timeout)
            head = b""
            while len(head) < 8:
                chunk = sock.recv(8 - len(head))
                if not chunk:
                    break
                head += chunk
    except TimeoutError:
        raise TautError(f"no dask scheduler answered at {address} within {timeout:g} s") from None
    except OSError as exc:
        raise TautError(f"cannot reach the dask scheduler at {address} ({exc.strerror or exc})") from None
    if len(head) < 8 or struct.unpack("<Q", head)[0] >= 1 << 32:
        raise TautError(f"the server at {address} is not a dask scheduler")


def _dask_client(scheduler: object, timeout: float) -> tuple[Client, bool]:
    try:
        from distributed import Client
    except ImportError:
        raise TautError(
            "a dask scheduler was requested but dask.distributed is not installed; install the extra: pip install 'taut[dist]'"
        ) from None
    if isinstance(scheduler, Client):
        return scheduler, False
    address = getattr(scheduler, "scheduler_address", None)  # a LocalCluster or similar
    if address is None:
        if not isinstance(scheduler, str) or not scheduler.strip():
            raise TautError(
                f"scheduler must be an address such as tcp://host:8786 or a distributed.Client, got {scheduler!r}"
            )
        address = scheduler.strip()
        _check_address(address, timeout)
    try:
        client = Client(address, timeout=timeout, set_as_default=False)
    except (OSError, TimeoutError, ValueError) as exc:
        raise TautError(
            f"cannot reach the dask scheduler at {address} within {timeout:g} s ({type(exc).__name__}: {exc})"
        ) from None
    return client, True


def get_executor(workers: int | None = None, scheduler: object = None, *, timeout: float = CONNECT_TIMEOUT) -> Executor:
    """The executor for ``workers`` local processes or a dask ``scheduler``.

    ``workers`` ``None`` or 1 (and no scheduler): serial.  ``workers > 1``: local processes.
    ``scheduler``: an address (``tcp://host:8786``), a ``distributed.Client`` (used as is,
    not closed by :meth:`Executor.close`) or a cluster object with a ``scheduler_address``.
    Raises :class:`TautError` for a bad worker count, both options at once, a missing
    ``taut[dist]`` extra, or a scheduler not reachable within ``timeout`` seconds."""
    if scheduler is not None and workers not in (None, 1):
        raise TautError("give either a number of local workers or a dask scheduler, not both")
    if scheduler is not None:
        client, owns = _dask_client(scheduler, timeout)
        return DaskExecutor(client, owns_client=owns)
    if workers is None:
        return SerialExecutor()
    try:
        count = operator.index(workers)
    except TypeError:
        count = 0
    if isinstance(workers, bool) or count < 1:
        raise TautError(f"workers must be a positive integer, got {workers!r}")
    workers = count
    return SerialExecutor() if workers == 1 else ProcessExecutor(workers)


def as_executor(executor: object) -> Executor:
    """``None`` → serial; an :class:`Executor` as is; a ``distributed.Client`` (or a cluster
    object) → :class:`DaskExecutor`.  Anything else is a :class:`TautError`."""
    if executor is None:
        return SerialExecutor()
    if isinstance(executor, Executor):
        return executor
    if hasattr(executor, "scheduler_address") or (hasattr(executor, "submit") and hasattr(executor, "gather")):
        return get_executor(scheduler=executor)
    raise TautError(f"executor must come from taut.parallel.get_executor, got {type(executor).__name__}")
