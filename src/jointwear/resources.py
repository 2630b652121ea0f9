"""Memory, work and wall-clock limits, checked before anything is allocated or run.

A run holds a few dense ``contact.nodes x simulation.steps_per_revolution``
arrays (pressures on the unworn and worn contour, the contact windows) and its
saved profiles; a sweep holds one record per case. These estimates are checked
where a command starts, against a limit the user can raise:

* ``--max-memory SIZE`` (``run``, ``sweep``, ``life``, ``measure``, ...), else
* the environment variable ``JOINTWEAR_MAX_MEMORY``, else
* half the machine's memory, at most 8 GiB.

``SIZE`` is a quantity of information (``"16 GiB"``, ``"500 MB"``; a bare
number is bytes). A refused size ends with one line naming the keys, the
estimate and how to raise the limit (:class:`~jointwear.errors.ConfigError`).

A wall-clock limit (``--time-limit``, :class:`Deadline`) is checked between
revolutions of a run and between the cases of a sweep; on expiry the command
ends with :class:`~jointwear.errors.TimeLimitError` (exit status 2), keeping a
run's checkpoint and a sweep's finished cases for ``--resume``.
"""

from __future__ import annotations

import math
import os
import time
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING

from jointwear.errors import ConfigError, TimeLimitError

if TYPE_CHECKING:
    from jointwear.config import Config

__all__ = [
    "DEFAULT_CAP",
    "DENSE_ARRAYS",
    "ENVIRONMENT",
    "MAX_CASES",
    "Deadline",
    "available_cpus",
    "check_case_count",
    "check_memory",
    "check_nodes",
    "check_run",
    "check_sweep",
    "format_bytes",
    "memory_limit",
    "parse_size",
    "parse_time_limit",
    "run_memory",
]

#: environment variable that sets the memory limit
ENVIRONMENT = "JOINTWEAR_MAX_MEMORY"
#: the default limit is half the machine's memory, at most this [bytes]
DEFAULT_CAP = 8 * 2**30
#: dense nodes x steps float64 arrays a run holds at once (measured peak: ~7)
DENSE_ARRAYS = 8
#: bytes a sweep keeps per case besides its wear profile (record, parameters)
CASE_OVERHEAD = 4096
#: most cases of one sweep or life study
MAX_CASES = 1_000_000
#: float64 arrays of the node grid a profile measurement holds
PROFILE_ARRAYS = 16

_FLOAT = 8  # bytes


def parse_size(text: str | float, key: str = "--max-memory") -> int:
    """Bytes in a memory size such as ``"16 GiB"`` or ``"500 MB"`` (a bare number is bytes).

    Parameters
    ----------
    text : str or float
        The size.
    key : str
        Option or variable named in error messages.

    Raises
    ------
    ConfigError
        Not a quantity of information, or not positive.
    """
    from jointwear.units import parse_quantity, shown

    quantity = parse_quantity(str(text), key) if isinstance(text, str) else text
    try:
        if getattr(quantity, "unitless", True):  # a bare number: bytes
            size = float(getattr(quantity, "magnitude", quantity))
        else:
            size = float(quantity.to("byte").magnitude)
    except Exception:
        raise ConfigError(
            f"{key}: {shown(text)} is not a memory size (e.g. '16 GiB', '500 MB')"
        ) from None
    if not (math.isfinite(size) and size > 0):
        raise ConfigError(f"{key}: must be a positive memory size, got {shown(text)}")
    return int(min(size, 2.0**62))


def available_cpus() -> int:
    """CPUs this process may use [-]."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # not on Linux
        return max(1, os.cpu_count() or 1)


def _physical_memory() -> int | None:
    try:
        return int(os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES"))
    except (AttributeError, ValueError, OSError):  # not on this platform
        return None


def memory_limit(option: str | None = None) -> tuple[int, str]:
    """The memory limit [bytes] and where it comes from (for the message).

    Parameters
    ----------
    option : str, optional
        The value of ``--max-memory``; it wins over :data:`ENVIRONMENT`.
    """
    if option is not None:
        return parse_size(option, "--max-memory"), "--max-memory"
    if os.environ.get(ENVIRONMENT):
        return parse_size(os.environ[ENVIRONMENT], ENVIRONMENT), ENVIRONMENT
    total = _physical_memory()
    limit = DEFAULT_CAP if total is None else min(total // 2, DEFAULT_CAP)
    return limit, "the default"


def format_bytes(size: float) -> str:
    """``size`` in bytes as a short text with binary prefixes, e.g. ``"1.5 GiB"``."""
    for unit in ("B", "KiB", "MiB", "GiB", "TiB", "PiB"):
        if size < 1024 or unit == "PiB":
            return f"{size:.3g} {unit}"
        size /= 1024
    raise AssertionError("unreachable")


def check_memory(parts: Sequence[tuple[str, str, float]], limit: str | None = None) -> float:
    """Refuse a job whose estimated memory exceeds the limit.

    Parameters
    ----------
    parts : sequence of (keys, detail, bytes)
        What needs memory: the keys that set it (named in the message), how
        the estimate is made, and the estimate [bytes].
    limit : str, optional
        ``--max-memory`` (default: :data:`ENVIRONMENT` or the default).

    Returns
    -------
    float
        The estimate [bytes].

    Raises
    ------
    ConfigError
        If the estimate exceeds the limit.
    """
    total = float(sum(size for _, _, size in parts))
    allowed, source = memory_limit(limit)
    if total <= allowed:
        return total
    biggest = sorted(parts, key=lambda part: part[2], reverse=True)
    keys, detail, _ = biggest[0]
    raise ConfigError(
        f"{keys}: needs about {format_bytes(total)} of memory ({detail}), more than the "
        f"limit of {format_bytes(allowed)} ({source}); make them smaller or raise the "
        f"limit with --max-memory SIZE or {ENVIRONMENT}"
    )


def run_memory(config: Config) -> list[tuple[str, str, float]]:
    """What one run of ``config`` holds in memory, by the keys that size it [bytes].

    Parameters
    ----------
    config : Config
        The run's configuration.
    """
    nodes = config.contact.nodes
    steps = config.simulation.steps_per_revolution
    profiles = config.simulation.saved_profiles
    joints = len(config.joints)
    return [
        (
            "contact.nodes, simulation.steps_per_revolution",
            f"{DENSE_ARRAYS * joints} arrays of {steps} steps x {nodes} nodes",
            DENSE_ARRAYS * joints * steps * nodes * _FLOAT,
        ),
        (
            "simulation.saved_profiles, contact.nodes",
            f"{profiles} saved profiles x {nodes} nodes x {joints} joint(s)",
            profiles * nodes * joints * _FLOAT,
        ),
    ]


def check_run(config: Config, limit: str | None = None) -> float:
    """Refuse a run whose arrays would not fit in the memory limit; the estimate [bytes].

    Parameters
    ----------
    config : Config
        The run's configuration.
    limit : str, optional
        ``--max-memory``.
    """
    return check_memory(run_memory(config), limit)


def check_case_count(cases: int, where: str) -> None:
    """Refuse a sweep of more than :data:`MAX_CASES` cases, before they are expanded.

    Parameters
    ----------
    cases : int
        Product of the grid's lengths, the zipped lists' length and the samples [-].
    where : str
        The file and tables that set the number, for the message.
    """
    if cases > MAX_CASES:
        shown = f"{cases:,}" if cases < 10**15 else f"about 10^{len(str(cases)) - 1}"
        raise ConfigError(
            f"{where}: {shown} cases, more than {MAX_CASES:,} in one study; "
            "split it into several sweeps"
        )


def check_sweep(
    cases: int, config: Config, where: str, limit: str | None = None, parallel: int = 1
) -> float:
    """Refuse a sweep whose case records and running cases would not fit in memory.

    Parameters
    ----------
    cases : int
        Number of cases [-].
    config : Config
        The base configuration (sizes of one case).
    where : str
        The keys that set the number of cases, for the message.
    limit : str, optional
        ``--max-memory``.
    parallel : int
        Cases that run at the same time [-].

    Returns
    -------
    float
        The estimate [bytes].
    """
    check_case_count(cases, where)
    nodes = config.contact.nodes
    per_case = CASE_OVERHEAD + nodes * _FLOAT
    parts = [
        (where, f"{cases} case records of {nodes} nodes", cases * per_case),
        *(
            (keys, f"{parallel} running case(s) x {detail}", parallel * size)
            for keys, detail, size in run_memory(config)
        ),
    ]
    return check_memory(parts, limit)


def check_nodes(nodes: int, points: int, key: str, limit: str | None = None) -> float:
    """Refuse a measured profile grid that would not fit in memory; the estimate [bytes].

    Parameters
    ----------
    nodes : int
        Nodes of the profile grid [-].
    points : int
        Measured points [-] (0 if not known yet).
    key : str
        The option that sets ``nodes``.
    limit : str, optional
        ``--max-memory``.
    """
    size = PROFILE_ARRAYS * (nodes + points) * _FLOAT
    return check_memory([(key, f"{PROFILE_ARRAYS} arrays of {nodes} nodes", size)], limit)


# ---------------------------------------------------------------- wall clock


def parse_time_limit(text: str | None, key: str = "--time-limit") -> float | None:
    """Seconds in a wall-clock limit such as ``"90 min"`` (a bare number is seconds).

    Parameters
    ----------
    text : str, optional
        The limit; ``None`` for none.
    key : str
        Option named in error messages.
    """
    if text is None:
        return None
    from jointwear.units import shown, to_si

    seconds = to_si(text, "time", key)
    if not seconds > 0:
        raise ConfigError(f"{key}: must be a positive time, got {shown(text)}")
    return seconds


class Deadline:
    """A wall-clock limit, checked at points where a job can stop cleanly.

    Parameters
    ----------
    seconds : float, optional
        The limit [s]; ``None`` for none.
    unit : str
        What :meth:`check` counts, for the message (``"revolutions"``, ``"cases"``).
    resume : str, optional
        The command that continues the job, named in the message.
    """

    def __init__(
        self, seconds: float | None, unit: str = "revolutions", resume: str | None = None
    ) -> None:
        self.seconds = seconds
        self.unit = unit
        self.resume = resume
        self.start = time.monotonic()

    def expired(self) -> bool:
        """True once the limit has passed."""
        return self.seconds is not None and time.monotonic() - self.start >= self.seconds

    def check(self, done: int, total: int | None = None) -> None:
        """Raise :class:`~jointwear.errors.TimeLimitError` once the limit has passed.

        Parameters
        ----------
        done : int
            Revolutions or cases done so far [-].
        total : int, optional
            Of how many [-].
        """
        if total is not None and done >= total:
            return  # finished: nothing to stop
        if not self.expired():
            return
        of = "" if total is None else f" of {total}"
        message = f"time limit of {self.seconds:g} s reached after {done}{of} {self.unit}"
        if self.resume:
            message += f"; continue with `{self.resume}`"
        raise TimeLimitError(message)

    def watching(self, progress: Callable[[int, int], None]) -> Callable[[int, int], None]:
        """A progress callback that reports to ``progress``, then checks the limit.

        Parameters
        ----------
        progress : callable
            ``progress(done, total)``, e.g. a progress bar [-].
        """

        def report_and_check(done: int, total: int) -> None:
            progress(done, total)
            self.check(done, total)

        return report_and_check
