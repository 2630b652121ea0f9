"""The progress bar of the long commands (run, sweep, life, reproduce), on stderr."""

from __future__ import annotations

import math
import sys
import time

from jointwear.cli.common import err_console
from jointwear.interrupts import raise_pending

__all__ = ["ProgressBar", "run_ends"]


class ProgressBar:
    """A rich progress bar on stderr that appears only for runs longer than a second.

    Off when ``quiet`` or when stderr is not a terminal. It is redrawn by the progress
    calls themselves (at most every :attr:`interval` seconds), not by a thread of its own:
    a sweep forks its workers only from a process without threads.
    """

    #: shortest time between two redraws [s]
    interval = 0.1

    def __init__(self, description: str, quiet: bool = False, delay: float = 1.0) -> None:
        self.enabled = not quiet and sys.stderr.isatty()
        self.description = description
        self.delay = delay
        self.start = time.perf_counter()
        self._bar = None
        self._task = None
        self._drawn = -math.inf

    def __call__(self, done: float, total: float) -> None:
        """Show ``done`` of ``total``; ``done == total``: the job is complete (the bar keeps
        the total it began with, so a run a limit ended shows where it ended)."""
        raise_pending()  # the work goes on only if no signal has arrived
        if not self.enabled:
            return
        if self._bar is None:
            if time.perf_counter() - self.start < self.delay or done >= total:
                return
            from rich.progress import BarColumn, MofNCompleteColumn, Progress, TimeRemainingColumn

            self._bar = Progress(
                "{task.description}",
                BarColumn(),
                MofNCompleteColumn(),
                TimeRemainingColumn(),
                console=err_console,
                transient=True,
                auto_refresh=False,
            )
            self._bar.start()
            self._task = self._bar.add_task(self.description, total=total)
            self._drawn = -math.inf
        now = time.perf_counter()
        due = now - self._drawn >= self.interval or done >= total
        self._bar.update(self._task, completed=done, refresh=due)
        if due:
            self._drawn = now

    def finish(self, done: float, description: str) -> None:
        """Show where the job ended and why; a job that ended before its total (a life
        limit) stays on screen, at the revolution it ended, with ``description``.

        Parameters
        ----------
        done : float
            Where the job ended [-].
        description : str
            Why, e.g. ``"stopped: wall_thickness"``.
        """
        if self._bar is None:
            return
        total = self._bar.tasks[0].total
        if total is not None and done < total:
            from rich.progress import TimeElapsedColumn

            # (no time remaining: the time it took, and the bar stays)
            self._bar.columns = (*self._bar.columns[:-1], TimeElapsedColumn())
            self._bar.live.transient = False
        self._bar.update(self._task, completed=done, description=description, refresh=True)

    def close(self) -> None:
        if self._bar is not None:
            self._bar.stop()
            self._bar = None

    def __enter__(self) -> ProgressBar:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def run_ends(summary: dict) -> tuple[float, str]:
    """Where a run ended (revolutions; the farthest joint's of several) and a short reason
    for the progress bar.

    Parameters
    ----------
    summary : dict
        The run's summary (``run --json``).

    Returns
    -------
    done : float
        Revolutions run [-].
    reason : str
        ``"revolutions"``, or ``"stopped: LIMIT"`` when life limits ended every joint.
    """
    joints = list(summary.get("joints", {}).values()) or [summary]
    done = max(float(joint["revolutions"]) for joint in joints)
    limits = sorted({str(joint["stopped_by"]) for joint in joints if joint["stopped_by"]})
    if limits and all(joint["stopped_by"] for joint in joints):
        return done, f"stopped: {', '.join(limits)}"
    return done, "revolutions"
