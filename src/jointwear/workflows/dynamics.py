"""The load cycle of each clearance joint over one period (``jointwear dynamics``).

:func:`joint_load_cycles` solves the mechanism's dynamics
(:func:`~jointwear.mechanism.stage.load_cycles`) and writes the per-step arrays of each
joint's cycle to CSV files that read back as a load history.
"""

from __future__ import annotations

import csv
import warnings
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from jointwear.errors import ConfigError, DataError
from jointwear.io import atomic_write, os_reason

if TYPE_CHECKING:
    from jointwear.config import Config
    from jointwear.mechanism import LoadCycle

__all__ = ["JointCycles", "check_csv", "csv_paths", "joint_load_cycles", "write_csv"]


@dataclass(frozen=True)
class JointCycles:
    """Outcome of :func:`joint_load_cycles`.

    Attributes
    ----------
    config : Config
        The configuration the cycles were solved with.
    cycles : dict of str to LoadCycle
        Per clearance joint its load cycle.
    summaries : dict of str to dict
        Per joint the cycle's summary with the clearance (the ``dynamics --json``
        object of a single joint) [SI].
    """

    config: Config
    cycles: dict[str, LoadCycle]
    summaries: dict[str, dict[str, Any]]


def joint_load_cycles(
    config: Path,
    *,
    overrides: Sequence[str] = (),
    strict: bool = False,
    csv_path: Path | None = None,
    on_warnings: Callable[[list[str]], None] | None = None,
) -> JointCycles:
    """Solve the load cycle of each clearance joint; write their per-step arrays to CSV.

    Parameters
    ----------
    config : Path
        The mechanism's config file.
    overrides : sequence of str
        ``section.key=VALUE`` overrides of the config.
    strict : bool
        Fail instead of warning when the continuous-contact assumption fails (sets
        ``dynamics.strict``).
    csv_path : Path, optional
        CSV file of the per-step arrays (time, forces in the bushing frame, cumulative
        rotation, load, azimuth, ...); with several joints one file per joint
        (:func:`csv_paths`). Checked before anything is computed.
    on_warnings : callable, optional
        ``on_warnings(messages)``: the warnings of the dynamics, every one, before the
        files are written; without it they are issued as warnings.

    Returns
    -------
    JointCycles
        The config, each joint's cycle and its summary.

    Raises
    ------
    ConfigError
        A bad config or CSV target; a strict run whose contact assumption fails.
    DataError
        A CSV file cannot be written.
    """
    from jointwear.mechanism.stage import load_cycles
    from jointwear.workflows.inputs import load_config_file

    changes = list(overrides)
    if strict:
        changes.append("dynamics.strict=true")
    if csv_path is not None:  # before anything is computed
        check_csv(csv_path)
    cfg = load_config_file(config, changes)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        cycles = load_cycles(cfg)
    if on_warnings is not None:
        on_warnings([str(warning.message) for warning in caught])
    else:
        for warning in caught:
            warnings.warn_explicit(
                warning.message, warning.category, warning.filename, warning.lineno
            )
    if csv_path is not None:
        paths = csv_paths(csv_path, list(cycles))
        for path in paths.values():
            check_csv(path)
        try:
            for joint, path in paths.items():
                write_csv(path, cycles[joint])
        except OSError as exc:
            raise DataError(f"--csv: {exc.filename or csv_path}: {os_reason(exc)}") from None
    context = {"clearance_m": cfg.joint.clearance}
    summaries = {joint: {**cycle.summary(), **context} for joint, cycle in cycles.items()}
    return JointCycles(cfg, cycles, summaries)


def write_csv(path: Path, cycle: LoadCycle) -> None:
    """Write the per-step arrays of ``cycle`` to ``path`` (atomically, full precision).

    Parameters
    ----------
    path : Path
        The CSV file; its header carries the units, and it reads back as
        ``mechanism.type = 'load-history'``.
    cycle : LoadCycle
        The load cycle.
    """
    columns = cycle.columns()
    rows = zip(*columns.values(), strict=True)
    with atomic_write(path, encoding="utf-8", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(columns)
        writer.writerows([repr(float(value)) for value in row] for row in rows)


def check_csv(path: Path) -> None:
    """A --csv target must be absent or a regular file (not a link, folder or device).

    Parameters
    ----------
    path : Path
        The file to be written.

    Raises
    ------
    ConfigError
        ``path`` is a directory, a link or a special file, or a parent is a file.
    """
    if path.is_symlink() or (path.exists() and not path.is_file()):
        kind = "a directory" if path.is_dir() and not path.is_symlink() else "not a regular file"
        raise ConfigError(f"--csv: {path} is {kind}")
    for parent in path.parents:  # created when missing; the first existing one is a folder
        if parent.exists():
            if not parent.is_dir():
                raise ConfigError(f"--csv: {parent} is not a directory")
            break


def csv_paths(path: Path, joints: list[str]) -> dict[str, Path]:
    """One CSV path per joint: ``path`` itself for a single joint, else ``NAME.JOINT.csv``.

    Parameters
    ----------
    path : Path
        The ``--csv`` file.
    joints : list of str
        The clearance joints' names.

    Returns
    -------
    dict of str to Path
        Per joint its file.
    """
    if len(joints) == 1:
        return {joints[0]: path}
    return {
        joint: path.with_name(f"{path.stem}.{joint}{path.suffix or '.csv'}") for joint in joints
    }
