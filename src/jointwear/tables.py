"""Reading tables of numbers with units in their headers (CSV or whitespace separated).

Shared by every reader of user data files (measured bushings, load histories): a
header row whose column names may carry a unit in brackets (``x [mm]``,
``force_x (kN)``), ``#`` comment lines, an optional UTF-8 byte-order mark, comma,
semicolon, tab or whitespace separators. Every problem is a
:class:`~jointwear.errors.DataError` whose one-line message starts with the file.
"""

from __future__ import annotations

import csv
import re
import warnings
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from jointwear.errors import ConfigError, DataError
from jointwear.units import parse_unit, registry

__all__ = [
    "delimiter_of",
    "is_content",
    "is_numeric_row",
    "load_numbers",
    "parse_header",
    "read_text_lines",
    "unit_factor",
]

FloatArray = NDArray[np.float64]

# a column name with an optional unit in brackets: "x", "x [mm]", "X(um)"
_COLUMN = re.compile(r"^\s*(?P<name>[^\[\]()]*?)\s*(?:[\[(]\s*(?P<unit>[^\[\]()]*?)\s*[\])])?\s*$")


def read_text_lines(path: Path) -> list[str]:
    """The lines of a UTF-8 text file (a byte-order mark is dropped).

    Parameters
    ----------
    path : Path
        The file.
    """
    from jointwear.io import read_input

    return read_input(path, "data file").splitlines()


def is_content(line: str) -> bool:
    """True for a line that is neither blank nor a ``#`` comment."""
    stripped = line.strip()
    return bool(stripped) and not stripped.startswith("#")


def delimiter_of(line: str) -> str | None:
    """The separator of a row: comma, semicolon or tab, else ``None`` (whitespace)."""
    for candidate in (",", ";", "\t"):
        if candidate in line:
            return candidate
    return None  # any whitespace


def is_numeric_row(line: str, delimiter: str | None) -> bool:
    """True if every field of the row reads as a number."""
    try:
        [float(token) for token in line.split(delimiter) if token.strip()]
    except ValueError:
        return False
    return True


def parse_header(path: Path, line: str, delimiter: str | None) -> list[tuple[str, str | None]]:
    """Column names (lower case) and their units in brackets (``None`` if none).

    Parameters
    ----------
    path : Path
        The file (for messages).
    line : str
        The header row.
    delimiter : str or None
        Separator (:func:`delimiter_of`).
    """
    names = next(csv.reader([line], delimiter=delimiter)) if delimiter else line.split()
    columns = []
    for name in names:
        match = _COLUMN.match(name)
        if match is None or not match["name"]:
            raise DataError(f"{path}: cannot read column name {name.strip()!r} in the header")
        columns.append((match["name"].strip().lower(), match["unit"] or None))
    return columns


def load_numbers(
    path: Path,
    lines: list[str],
    delimiter: str | None,
    usecols: tuple[int, int] | None,
    first_line_number: int = 1,
) -> FloatArray:
    """The numbers of the data rows as a 2-D array; a bad row is named in the error.

    Parameters
    ----------
    path : Path
        The file (for messages).
    lines : list of str
        The data rows.
    delimiter : str or None
        Separator (:func:`delimiter_of`).
    usecols : tuple of int or None
        Columns to read (all if ``None``).
    first_line_number : int
        Line number of ``lines[0]`` in the file.
    """
    with warnings.catch_warnings():
        # an empty file is reported below as "too few points", not as a warning
        warnings.simplefilter("ignore", UserWarning)
        try:
            data = np.loadtxt(
                lines, delimiter=delimiter, comments="#", usecols=usecols, ndmin=2, dtype=float
            )
        except (ValueError, IndexError) as exc:
            # numpy's row numbers skip or count comment lines inconsistently: name the line
            reason = _first_bad_line(lines, delimiter, usecols, first_line_number)
            if reason is None:
                reason = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
            raise DataError(f"{path}: cannot read the numbers ({reason})") from None
    if data.size == 0:
        return np.zeros((0, 2 if usecols is None else len(usecols)))
    return data


def _first_bad_line(
    lines: list[str], delimiter: str | None, usecols: tuple[int, int] | None, first: int
) -> str | None:
    """Describe the first line ``np.loadtxt`` cannot read (for the error message only)."""
    expected: int | None = None if usecols is None else max(usecols) + 1
    for number, line in enumerate(lines, start=first):
        text = line.split("#", 1)[0]
        if not text.strip():
            continue
        fields = text.split(delimiter)
        if expected is None:
            expected = len(fields)
        if len(fields) < expected or (usecols is None and len(fields) != expected):
            return f"line {number}: expected {expected} columns, found {len(fields)}"
        for index in range(len(fields)) if usecols is None else usecols:
            try:
                float(fields[index])
            except ValueError:
                return f"line {number}: {fields[index].strip()!r} is not a number"
    return None


def unit_factor(unit: str, target: str = "m") -> float | None:
    """``target`` units per ``unit`` (default metres), or None if the dimensions differ."""
    try:
        parsed = parse_unit(unit)  # bounded: a header cannot make pint compute 9**9**9
    except ConfigError:
        return None
    if parsed.dimensionality != registry().Unit(target).dimensionality:
        return None
    return float(registry().Quantity(1.0, parsed).to(target).magnitude)
