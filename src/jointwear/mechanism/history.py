"""A load history read from a file: one period of a joint's load from another code.

The ``load-history`` mechanism type (``mechanism.type = "load-history"``) takes the
load cycle of a clearance joint from a file instead of computing it: a table
exported from another multibody code, the ``--csv`` output of ``jointwear
dynamics``, or the result file of ``jointwear run --out``.

CSV
---
A header row names the columns, each with its unit in brackets; column order is
free::

    time [s],force_x [N],force_y [N],rotation [deg]
    0.0,120.0,-40.0,0.0
    ...

Any unit pint converts to the column's dimension may stand in the brackets
(``time [ms]``, ``force_x [kN]``, ``rotation [rad]``, ``rotation [turn]``).

``time``
    Time of the row; shifted so that the first row is at 0. The steps need not be
    equally long: step ``k`` runs from row ``k`` to row ``k + 1``.
``force_x``, ``force_y``
    The force the pin exerts on the bushing, in the bushing's frame (``frame =
    "bushing"``) or in the global frame (``frame = "global"``).
``rotation``
    Cumulative rotation of the pin relative to the bushing (any origin).
``bushing_angle``
    With ``frame = "global"`` only, and then required: orientation of the body
    that carries the bushing; the load's azimuth on the bushing is
    ``atan2(force_y, force_x) - bushing_angle``.

The informative columns that ``jointwear dynamics --csv`` writes beside these
(:data:`INFORMATIVE_COLUMNS`: ``phase``, ``load``, ``azimuth``,
``relative_rotation`` and the mechanisms' diagnostics such as ``crank_torque``)
are accepted and ignored, so that its output reads back as the same cycle. Any
other column is an error. Fields are separated by commas (or semicolons, or
tabs); a leading UTF-8 byte-order mark, blank lines and comment lines starting
with ``#`` are allowed.

The end of the cycle
--------------------
The file is one cycle *as given*: the pin slides by the rotation between
consecutive rows and by nothing else, so the sliding distance of a cycle is
``R_b`` times the sum of ``|rotation[k + 1] - rotation[k]|`` over its rows. A
history that turns half a turn slides half a turn (no return stroke is added to
make it whole turns), and one that swings 0 -> 90 -> 0 deg slides twice as far as
one that swings 0 -> 90 deg.

A last row that *closes* the cycle, i.e. is at the same phase of the load as the
first row (forces equal to the first row's to 1e-9 of the largest force; with
``frame = "global"`` also the bushing turned by a whole number of turns, to 1e-9
rad) is recognised: its time is the period, and the step into it slides as its
rotation says (whole turns on for a pin that turns with the cycle, back to the
start for one that swings, any other angle for one that does neither). ``jointwear
dynamics --csv`` writes such a row. Without a closing row the period is ``period``
if given, else the last time plus the median time step; the last row's load then
acts until the end of the period, and that closing step does not slide: the file
says nothing of a rotation after its last row, and the next cycle starts again
from its first row, whose rotation counts from any origin. A pin that turns on
from the last row to the next cycle's first (a turning joint sampled without its
endpoint) needs the closing row to slide that step. A ``period`` given beside a
closing row must agree with it (to 1e-9 relative).

netCDF
------
A file whose name ends in ``.nc`` is read as a result file of ``jointwear run
--out`` (``result.nc``): the variables ``joint_load``, ``load_azimuth`` (bushing
frame) and ``relative_rotation`` on the dimension ``step``, the coordinate
``time`` and the attribute ``period_s``, so that a computed cycle can be reused
without its mechanism. Such a file is always in the bushing frame.

Errors
------
Every problem with the file raises :class:`~jointwear.errors.DataError` with one
line that starts with the file name and names the line or column at fault.
"""

from __future__ import annotations

import hashlib
import math
from collections.abc import Mapping
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

import numpy as np
from numpy.typing import NDArray

from jointwear.errors import DataError
from jointwear.io import check_input
from jointwear.mechanism.cycle import LoadCycle, bushing_azimuth
from jointwear.mechanism.inputs import MechanismInputs
from jointwear.registry import suggest
from jointwear.tables import (
    delimiter_of,
    is_content,
    is_numeric_row,
    load_numbers,
    parse_header,
    read_text_lines,
    unit_factor,
)

if TYPE_CHECKING:
    from jointwear.config import LoadHistoryConfig

__all__ = [
    "INFORMATIVE_COLUMNS",
    "LOAD_HISTORY",
    "MIN_ROWS",
    "LoadHistoryMechanism",
    "history_cycle",
    "read_load_history",
]

FloatArray = NDArray[np.float64]

#: Fewest data rows (closing row included) a CSV load history may have.
MIN_ROWS = 8

#: Columns read from a CSV file -> the SI unit their values are converted to.
_COLUMNS = {"time": "s", "force_x": "N", "force_y": "N", "rotation": "rad"}
#: The extra column of the global frame -> its SI unit.
_GLOBAL_COLUMNS = {"bushing_angle": "rad"}

#: Columns that ``jointwear dynamics --csv`` writes for information; a load history
#: accepts and ignores them (:meth:`LoadCycle.columns` plus the diagnostics of the
#: mechanism types).
INFORMATIVE_COLUMNS = frozenset(
    {
        "phase",
        "load",
        "azimuth",
        "relative_rotation",
        "crank_torque",
        "slider_position",
        "rod_angle",
        "coupler_angle",
        "rocker_angle",
        "global_force_x",
        "global_force_y",
        "pin_angle",
    }
)

#: How closely a last row must repeat the first to close the cycle: forces relative
#: to the largest force [-], the bushing's angle (global frame) off whole turns [rad].
_CLOSURE_TOLERANCE = 1e-9
#: How closely ``period`` must agree with the time of a closing row, relative [-].
_PERIOD_TOLERANCE = 1e-9

_TURN = 2.0 * math.pi
#: What a column's SI unit measures, for messages.
_KIND = {"s": "time", "N": "force", "rad": "angle"}


def read_load_history(
    path: str | Path,
    frame: Literal["bushing", "global"] = "bushing",
    period: float | None = None,
) -> LoadCycle:
    """Read one period of a joint's load from a CSV or netCDF file.

    The formats, the closing row and the end of the cycle are described in the
    module documentation (:mod:`jointwear.mechanism.history`). The cycle slides as
    given: its total relative rotation is the sum of ``|Δrotation|`` between
    consecutive rows (of a CSV file), nothing added.

    Parameters
    ----------
    path : str or Path
        CSV file with a unit-bearing header, or (suffix ``.nc``) a result file of
        ``jointwear run --out``.
    frame : {"bushing", "global"}
        Frame of the forces in a CSV file; ``"global"`` needs a ``bushing_angle``
        column [-].
    period : float, optional
        Duration of the cycle [s]; default from the closing row, or the last time
        plus the median step.

    Returns
    -------
    LoadCycle
        The cycle, time shifted to start at 0; ``mechanism="load-history"``,
        ``model="prescribed"``, ``joint="joint"``.

    Raises
    ------
    DataError
        The file is missing, unreadable or not UTF-8; a column is missing, unknown,
        duplicated, without a unit or in a unit of the wrong dimension; a value is
        not a finite number; a row has the wrong number of fields; time does not
        increase; fewer than :data:`MIN_ROWS` rows; ``period`` contradicts the file.
    """
    path = Path(path)
    if path.suffix.lower() == ".nc":
        return _read_result(path, frame, period)
    table = _read_table(path, frame)
    if frame == "global":
        azimuth = bushing_azimuth(table["force_x"], table["force_y"], table["bushing_angle"])
    else:
        azimuth = bushing_azimuth(table["force_x"], table["force_y"])
    time, rotation = table["time"] - table["time"][0], table["rotation"]
    if _closes(table):
        if period is not None and not math.isclose(period, time[-1], rel_tol=_PERIOD_TOLERANCE):
            raise DataError(
                f"{path}: period {period:g} s disagrees with the closing last row, "
                f"which ends the cycle after {time[-1]:g} s"
            )
        period, end_rotation = float(time[-1]), float(rotation[-1])
        keep = slice(0, -1)
    else:
        if period is None:
            period = float(time[-1] + np.median(np.diff(time)))
        elif period <= time[-1]:
            raise DataError(
                f"{path}: period {period:g} s ends before the last row "
                f"(at {time[-1]:g} s after the first)"
            )
        # the cycle as given: the step from the last row to the end of the period does
        # not turn (no return stroke to whole turns: the next cycle counts from its own
        # first row)
        end_rotation = float(rotation[-1])
        keep = slice(None)
    return LoadCycle(
        time=time[keep],
        load=np.hypot(table["force_x"], table["force_y"])[keep],
        azimuth=azimuth[keep],
        relative_rotation=np.diff(np.append(rotation[keep], end_rotation)),
        period=period,
        mechanism="load-history",
        model="prescribed",
        joint="joint",
    )


def history_cycle(mechanism: LoadHistoryConfig) -> LoadCycle:
    """The load cycle of a ``load-history`` mechanism.

    Parameters
    ----------
    mechanism : jointwear.config.LoadHistoryConfig
        The ``[mechanism]`` section (type ``"load-history"``): ``file`` (an absolute
        path, as :func:`~jointwear.config.load_config` resolves it), ``frame``,
        ``period`` [s] and ``load_scale`` [-], the factor on the load.

    Returns
    -------
    LoadCycle
        The cycle of the one joint, ``"joint"``, with the file's path and SHA-256
        in its extras (``history_file``, ``history_sha256``).
    """
    mech = mechanism
    path = Path(mech.file)
    cycle = read_load_history(path, mech.frame, mech.period)
    with path.open("rb") as handle:
        digest = hashlib.file_digest(handle, "sha256").hexdigest()
    return replace(
        cycle,
        load=cycle.load * mech.load_scale,
        extras={"history_file": str(path), "history_sha256": digest},
    )


def _read_table(path: Path, frame: str) -> dict[str, FloatArray]:
    """The columns a load history needs, SI, one value per data row."""
    lines = read_text_lines(path)
    content = [number for number, line in enumerate(lines) if is_content(line)]
    if not content:
        raise DataError(f"{path}: no data")
    header_index = content[0]
    delimiter = delimiter_of(lines[header_index])
    if is_numeric_row(lines[header_index], delimiter):
        raise DataError(
            f"{path}: no header row (the first line must name the columns with their units, "
            f"e.g. '{','.join(f'{name} [{unit}]' for name, unit in _COLUMNS.items())}')"
        )
    columns = parse_header(path, lines[header_index], delimiter)
    wanted = {**_COLUMNS, **(_GLOBAL_COLUMNS if frame == "global" else {})}
    found = _check_header(path, columns, wanted)
    data = load_numbers(path, lines[header_index + 1 :], delimiter, None, header_index + 2)
    # file line numbers of the data rows, for messages
    line_numbers = [number + 1 for number in content[1:]]
    if data.shape[0] < MIN_ROWS:
        raise DataError(f"{path}: only {data.shape[0]} data row(s), need at least {MIN_ROWS}")
    if data.shape[1] != len(columns):
        raise DataError(
            f"{path}: line {line_numbers[0]}: expected {len(columns)} fields as in the "
            f"header, found {data.shape[1]}"
        )
    table = {}
    for name, (index, factor) in found.items():
        values = data[:, index]
        bad = np.flatnonzero(~np.isfinite(values))
        if bad.size:
            raise DataError(
                f"{path}: line {line_numbers[bad[0]]}: column {name!r} is not a finite "
                f"number ({values[bad[0]]})"
            )
        table[name] = values * factor
    back = np.flatnonzero(np.diff(table["time"]) <= 0)
    if back.size:
        raise DataError(
            f"{path}: line {line_numbers[back[0] + 1]}: time does not increase "
            f"(every row must come after the one before)"
        )
    return table


def _check_header(
    path: Path, columns: list[tuple[str, str | None]], wanted: Mapping[str, str]
) -> dict[str, tuple[int, float]]:
    """Index and factor to SI of each wanted column; errors for the header's faults."""
    known = [*wanted, *sorted(INFORMATIVE_COLUMNS)]
    found: dict[str, tuple[int, float]] = {}
    for index, (name, unit) in enumerate(columns):
        if name in (column for column, _ in columns[:index]):
            raise DataError(f"{path}: column {name!r} appears more than once in the header")
        if name in _GLOBAL_COLUMNS and name not in wanted:
            raise DataError(
                f"{path}: column {name!r} is read with frame = 'global' only (the forces "
                f"are taken in the bushing's frame)"
            )
        if name not in known:
            raise DataError(f"{path}: unknown column {name!r}{suggest(name, known)}")
        if name not in wanted:
            continue
        if unit is None:
            raise DataError(
                f"{path}: column {name!r} has no unit; write it in brackets, "
                f"e.g. '{name} [{wanted[name]}]'"
            )
        factor = unit_factor(unit, wanted[name])
        if factor is None:
            raise DataError(
                f"{path}: column {name!r}: {unit!r} is not a unit of "
                f"{_KIND[wanted[name]]} (e.g. {wanted[name]})"
            )
        found[name] = (index, factor)
    missing = [name for name in wanted if name not in found]
    if missing:
        raise DataError(
            f"{path}: missing column(s) {', '.join(repr(m) for m in missing)} "
            f"(need {', '.join(f'{n} [{u}]' for n, u in wanted.items())})"
        )
    return found


def _closes(table: Mapping[str, FloatArray]) -> bool:
    """True if the last row repeats the first row's phase (see the module notes)."""
    force_x, force_y = table["force_x"], table["force_y"]
    scale = float(np.max(np.hypot(force_x, force_y)))
    forces_match = max(abs(force_x[-1] - force_x[0]), abs(force_y[-1] - force_y[0])) <= (
        _CLOSURE_TOLERANCE * scale
    )
    # in the global frame the bushing must be back where it was, too; the pin need not
    # (a cycle that turns half a turn ends half a turn on: the load's phase repeats)
    angles = [name for name in _GLOBAL_COLUMNS if name in table]
    return forces_match and all(_whole_turns(table[name][-1] - table[name][0]) for name in angles)


def _whole_turns(angle: float) -> bool:
    """True if ``angle`` [rad] is a whole number of turns, to the closure tolerance."""
    return abs(angle - _TURN * round(angle / _TURN)) <= _CLOSURE_TOLERANCE


def _read_result(path: Path, frame: str, period: float | None) -> LoadCycle:
    """The load cycle stored in a result file of ``jointwear run --out``."""
    if frame != "bushing":
        raise DataError(
            f"{path}: a jointwear result holds the load in the bushing frame; use frame = 'bushing'"
        )
    dataset = _open_result(path)
    arrays = {}
    for name, unit in (
        ("time", "s"),
        ("joint_load", "N"),
        ("load_azimuth", "rad"),
        ("relative_rotation", "rad"),
    ):
        if name not in dataset or dataset[name].dims != ("step",):
            raise DataError(f"{path}: no variable {name!r} on the dimension 'step'")
        given = str(dataset[name].attrs.get("units", unit))
        factor = unit_factor(given, unit)
        if factor is None:
            raise DataError(f"{path}: variable {name!r} is in {given!r}, expected {unit}")
        arrays[name] = np.asarray(dataset[name].values, dtype=float) * factor
    stored = dataset.attrs.get("period_s")
    if stored is None:
        raise DataError(f"{path}: no attribute 'period_s'")
    stored = float(stored)
    if period is not None and not math.isclose(period, stored, rel_tol=_PERIOD_TOLERANCE):
        raise DataError(f"{path}: period {period:g} s disagrees with the file's {stored:g} s")
    try:
        return LoadCycle(
            time=arrays["time"],
            load=arrays["joint_load"],
            azimuth=arrays["load_azimuth"],
            relative_rotation=arrays["relative_rotation"],
            period=stored,
            mechanism="load-history",
            model="prescribed",
            joint="joint",
        )
    except DataError as exc:
        raise DataError(f"{path}: {exc}") from None


def _open_result(path: Path) -> Any:
    """The dataset of a netCDF result file, loaded into memory (xarray, h5netcdf).

    Only the load variables are read from it (a history is not checked as a wear
    result); the reader is the one ``jointwear run --out`` files are written for.
    """
    check_input(path, "result", max_bytes=None)
    # xarray is imported only for a result file, not for every CSV history
    import xarray as xr

    try:
        with xr.open_dataset(path, engine="h5netcdf") as handle:
            return handle.load()
    except Exception as exc:
        raise DataError(f"{path}: not a readable netCDF result ({type(exc).__name__})") from None


class LoadHistoryMechanism:
    """A load history as a mechanism type (:class:`jointwear.mechanism.base.Mechanism`)."""

    description = (
        "one period of joint load from a file (CSV or netCDF), e.g. another multibody code"
    )
    models = ("prescribed",)

    def load_cycles(
        self, inputs: MechanismInputs, wear_depth: FloatArray | None = None
    ) -> dict[str, LoadCycle]:
        """:func:`history_cycle`; a prescribed load does not depend on the wear [m]."""
        cycle = history_cycle(inputs.mechanism)
        return {cycle.joint: cycle}


#: the registry entry
LOAD_HISTORY = LoadHistoryMechanism()
