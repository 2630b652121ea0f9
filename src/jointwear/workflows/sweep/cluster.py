"""Cases on a dask.distributed cluster: the connection, its probe, the chunks of cases."""

from __future__ import annotations

import asyncio
import uuid
from collections.abc import Callable, Mapping, Sequence
from typing import Any

from jointwear.errors import ConfigError
from jointwear.workflows.sweep.case import lost_record, one_line, run_cases
from jointwear.workflows.sweep.local import case_chunks
from jointwear.workflows.sweep.plan import Case

__all__ = ["CONNECT_TIMEOUT", "connect", "probe", "run_dask"]

#: seconds a dask scheduler has to answer the connection probe [s]
CONNECT_TIMEOUT = 10.0


def connect(scheduler: str, timeout: float | None = None) -> Any:
    """A dask.distributed client for ``scheduler`` (one-line errors if impossible).

    Parameters
    ----------
    scheduler : str
        Address of the scheduler, ``tcp://host:port``.
    timeout : float, optional
        Seconds the scheduler has to answer [s]; default :data:`CONNECT_TIMEOUT`.

    Raises
    ------
    ConfigError
        dask.distributed is not installed, or no scheduler answers at the address.
    """
    timeout = CONNECT_TIMEOUT if timeout is None else timeout
    try:
        from dask.distributed import Client
    except ImportError:
        raise ConfigError(
            "--scheduler: dask.distributed is not installed; "
            "install it with `pip install 'jointwear[sweep]'`"
        ) from None
    probe(scheduler, timeout)
    try:
        # not the process-wide default: a Client registers itself as dask's scheduler
        # before it connects, and a failed connection would leave that registration
        # behind for every later dask-aware call (xarray) in this process
        return Client(scheduler, timeout=timeout, set_as_default=False)
    except (OSError, TimeoutError, ValueError, TypeError) as exc:
        why = one_line(str(exc)) or type(exc).__name__
        raise ConfigError(f"--scheduler: cannot connect to {scheduler} ({why})") from None


def probe(scheduler: str, timeout: float) -> None:
    """Check that a TCP address is a dask scheduler that answers within ``timeout`` [s].

    A ``Client`` that fails to connect is half built: at interpreter exit its
    destructor waits for a loop that never ran and prints a traceback; and a
    server that accepts the connection but never answers would keep it waiting.
    So first the address is parsed, a TCP connection opened, and the scheduler
    asked for its identity (dask's own handshake), all within ``timeout``.
    """
    import socket

    from distributed.comm.addressing import parse_address, parse_host_port

    try:
        protocol, location = parse_address(scheduler)
        if protocol == "inproc":
            # a scheduler in this very process (a LocalCluster without processes)
            from distributed.comm.inproc import global_manager

            if global_manager.get_listener_for(location) is None:
                raise ValueError("no scheduler at this in-process address")
            return
        if protocol not in ("tcp", "tls"):
            # a Client would wait for a transport that is not there and fail at exit
            # with a traceback
            raise ValueError(f"protocol {protocol!r} is not supported; give tcp://host:port")
        host, port = parse_host_port(location)
        if not 0 < int(port) < 65536:
            raise ValueError(f"port {port} is not in 1..65535")
    except (ValueError, TypeError) as exc:
        raise ConfigError(f"--scheduler: cannot connect to {scheduler} ({exc})") from None
    try:
        with socket.create_connection((host, port), timeout=timeout):
            pass
    except OSError as exc:
        why = one_line(str(exc)) or type(exc).__name__
        raise ConfigError(f"--scheduler: cannot connect to {scheduler} ({why})") from None
    if protocol != "tcp":
        return  # TLS needs the cluster's certificates: the Client will handshake
    silent = ConfigError(
        f"--scheduler: no dask scheduler answered at {scheduler} within {timeout:g} s"
    )
    from concurrent.futures import ThreadPoolExecutor
    from concurrent.futures import TimeoutError as FutureTimeout

    # in a thread of its own: the caller may be inside an event loop (a notebook)
    executor = ThreadPoolExecutor(1, thread_name_prefix="jointwear-probe")
    try:
        reply = executor.submit(asyncio.run, _identity(scheduler, timeout)).result(timeout + 5)
    except (FutureTimeout, TimeoutError, OSError) as exc:
        raise silent from exc
    except Exception as exc:  # the comm's own errors: closed, bad handshake ...
        raise silent from exc
    finally:
        executor.shutdown(wait=False)
    if not isinstance(reply, Mapping) or reply.get("type") != "Scheduler":
        raise ConfigError(f"--scheduler: {scheduler} answered, but is not a dask scheduler")


async def _identity(address: str, timeout: float) -> Any:
    """The ``identity`` reply of the dask server at ``address`` (within ``timeout`` [s])."""
    from distributed.comm import connect

    async def ask() -> Any:
        comm = await connect(address, timeout=timeout)
        try:
            await comm.write({"op": "identity", "reply": True})
            return await comm.read()
        finally:
            comm.abort()

    return await asyncio.wait_for(ask(), timeout)


def run_dask(
    tasks: Sequence[tuple[Case, dict[str, Any]]],
    finish: Callable[[Case, dict[str, Any]], None],
    client: Any,
) -> str:
    """Run the cases on a dask cluster, in chunks; a chunk whose worker died is recorded
    as errors (``--resume`` runs them again).

    Parameters
    ----------
    tasks : sequence of (Case, dict)
        Each case and its task (:func:`~jointwear.workflows.sweep.case.run_case`).
    finish : callable
        ``finish(case, record)``, called in this process as each chunk comes back.
    client : dask.distributed.Client
        A connected client.

    Returns
    -------
    str
        The scheduler's address.
    """
    from dask.distributed import as_completed

    address = str(client.scheduler.address)
    token = uuid.uuid4().hex[:12]
    # chunks of cases, as for local workers: a task costs the scheduler, the client and
    # the worker a few milliseconds of the cores the cases run on
    chunks = case_chunks(tasks, max(1, sum(client.nthreads().values())))
    futures: dict[Any, Sequence[tuple[Case, dict[str, Any]]]] = {}
    try:
        for chunk in chunks:
            key = f"jointwear-{chunk[0][0].name}-{len(chunk)}-{token}"
            tasks_of = [task for _, task in chunk]
            futures[client.submit(run_cases, tasks_of, key=key, pure=False)] = chunk
        for future in as_completed(list(futures), loop=client.loop):
            chunk = futures[future]
            if future.status == "finished":
                records = future.result()
            else:
                exc = future.exception()
                why = f"{type(exc).__name__}: {one_line(str(exc))}"
                records = [lost_record(case.name, why) for case, _ in chunk]
            for (case, _), record in zip(chunk, records, strict=True):
                finish(case, record)
    except BaseException:
        for future in futures:
            future.cancel()
        raise
    return address
