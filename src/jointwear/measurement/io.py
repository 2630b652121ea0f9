"""Reading measured coordinates of a bushing's inner surface.

Two formats are accepted:

* **CSV with a header row** naming the columns ``x`` and ``y`` (other columns,
  e.g. ``z``, are ignored). A unit in brackets applies to its column:
  ``x [mm],y [mm]`` (any length unit pint knows: ``m``, ``mm``, ``um``, ``µm``,
  ``in`` ...). Columns without a unit are in metres, or in ``units`` if given.
  Comma, semicolon or tab separated.
* **Plain text without a header**: two columns ``x y`` separated by whitespace
  (or commas), in ``units`` (default metres).

Lines starting with ``#`` are comments. The points must describe a ring: at
least 8 finite points, not collinear, spread over at least half of the circle
as seen from their algebraic (Kåsa) circle centre. The centroid would not do
for that check: the centroid of a 90° arc sits near the arc, from where the arc
seems to span more than 200°.

All errors are :class:`~jointwear.errors.DataError` with a one-line message
that starts with the file name, except a bad ``units`` argument
(:class:`~jointwear.errors.ConfigError`).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from jointwear.errors import ConfigError, DataError
from jointwear.measurement.fit import angular_extent, fit_circle_kasa
from jointwear.tables import (
    delimiter_of,
    is_content,
    is_numeric_row,
    load_numbers,
    parse_header,
    read_text_lines,
    unit_factor,
)

__all__ = [
    "MIN_COVERAGE_DEG",
    "MIN_POINTS",
    "check_ring",
    "length_unit_factor",
    "read_points",
]

FloatArray = NDArray[np.float64]

#: Fewest points accepted in a measurement.
MIN_POINTS = 8
#: Smallest angular coverage of the ring [deg].
MIN_COVERAGE_DEG = 180.0
#: Largest radial scatter about the algebraic circle, relative to its radius [-];
#: far more than any wear, far less than a cloud of points that is no ring.
_MAX_RELATIVE_SCATTER = 0.1


def read_points(
    path: str | Path,
    units: str | None = None,
    *,
    min_points: int = MIN_POINTS,
    min_coverage_deg: float = MIN_COVERAGE_DEG,
) -> tuple[FloatArray, FloatArray]:
    """Read measured (x, y) points of a bushing's inner surface.

    Parameters
    ----------
    path : str or Path
        CSV file with an ``x,y`` header (units in brackets allowed) or a
        whitespace-separated two-column text file without header.
    units : str, optional
        Length unit of columns that do not carry one, e.g. ``"mm"``; default
        metres. If a header names a unit too, both must agree.
    min_points : int
        Fewest points accepted.
    min_coverage_deg : float
        Smallest angular coverage of the ring about its centre [deg].

    Returns
    -------
    x, y : ndarray, shape (M,)
        Coordinates [m], in file order.

    Raises
    ------
    DataError
        File missing or unreadable, no ``x``/``y`` columns or not two columns,
        unparsable or non-finite numbers, too few points, points that do not
        form a ring.
    ConfigError
        ``units`` is not a length unit.
    """
    path = Path(path)
    default_factor = 1.0 if units is None else length_unit_factor(units)
    lines = read_text_lines(path)
    content = [(i, line) for i, line in enumerate(lines) if is_content(line)]
    if not content:
        raise DataError(f"{path}: no data")
    first_index, first_line = content[0]
    delimiter = delimiter_of(first_line)

    if is_numeric_row(first_line, delimiter):
        data = load_numbers(path, lines, delimiter, None)
        if data.shape[1] != 2:
            raise DataError(
                f"{path}: expected 2 columns (x y) without a header, found {data.shape[1]}"
            )
        x, y = data[:, 0] * default_factor, data[:, 1] * default_factor
    else:
        columns = parse_header(path, first_line, delimiter)
        x_col, x_factor = _column(path, columns, "x", units, default_factor)
        y_col, y_factor = _column(path, columns, "y", units, default_factor)
        data = load_numbers(
            path, lines[first_index + 1 :], delimiter, (x_col, y_col), first_index + 2
        )
        x, y = data[:, 0] * x_factor, data[:, 1] * y_factor

    bad = np.flatnonzero(~(np.isfinite(x) & np.isfinite(y)))
    if bad.size:
        raise DataError(
            f"{path}: non-finite value (nan or inf) in data row {bad[0] + 1} "
            f"({bad.size} row(s) in all)"
        )
    if x.size < min_points:
        raise DataError(f"{path}: only {x.size} point(s), need at least {min_points}")
    check_ring(x, y, str(path), min_coverage_deg=min_coverage_deg)
    return x, y


def check_ring(
    x: FloatArray, y: FloatArray, source: str = "points", min_coverage_deg: float = MIN_COVERAGE_DEG
) -> None:
    """Raise :class:`DataError` unless the points describe a measured ring.

    Parameters
    ----------
    x, y : ndarray, shape (M,)
        Coordinates [m].
    source : str
        Name for messages (the file).
    min_coverage_deg : float
        Smallest angular coverage about the algebraic circle centre [deg]:
        360° minus the largest angular gap between neighbouring points.
    """
    try:
        circle = fit_circle_kasa(x, y)
    except DataError as exc:
        reason = str(exc).removeprefix("circle fit: ")
        raise DataError(f"{source}: not a ring of points ({reason})") from None
    dx, dy = x - circle.center_x, y - circle.center_y
    coverage = np.degrees(angular_extent(dx, dy))
    if coverage < min_coverage_deg:
        raise DataError(
            f"{source}: the points cover only {coverage:.0f}° of the ring about its centre, "
            f"need at least {min_coverage_deg:g}° (measure all round the bore)"
        )
    scatter = float(np.std(np.hypot(dx, dy))) / circle.radius
    if scatter > _MAX_RELATIVE_SCATTER:
        raise DataError(
            f"{source}: the points do not lie on a ring (radial scatter {100 * scatter:.0f} % "
            f"of the radius)"
        )


def _column(
    path: Path,
    columns: list[tuple[str, str | None]],
    name: str,
    units: str | None,
    default_factor: float,
) -> tuple[int, float]:
    """Index and metres-per-unit factor of the column called ``name``."""
    matches = [i for i, (column, _) in enumerate(columns) if column == name]
    header = ",".join(c if u is None else f"{c} [{u}]" for c, u in columns)
    if len(matches) != 1:
        how = "no" if not matches else "more than one"
        raise DataError(f"{path}: header '{header}' has {how} {name!r} column (need x and y)")
    index = matches[0]
    unit = columns[index][1]
    if unit is None:
        return index, default_factor
    factor = unit_factor(unit)
    if factor is None:
        raise DataError(f"{path}: column {name!r}: {unit!r} is not a length unit")
    if units is not None and not np.isclose(factor, default_factor, rtol=1e-12, atol=0.0):
        raise DataError(
            f"{path}: column {name!r} is in {unit} but units {units!r} were requested; "
            f"drop one of them"
        )
    return index, factor


def length_unit_factor(unit: str, key: str = "units") -> float:
    """Metres per length unit, e.g. ``length_unit_factor("mm") == 0.001``.

    Parameters
    ----------
    unit : str
        A length unit pint understands (``m``, ``mm``, ``um``, ``µm``, ``in`` ...).
    key : str
        Name of the setting for the error message (e.g. ``--units``).

    Raises
    ------
    ConfigError
        ``unit`` is not a length unit.
    """
    factor = unit_factor(unit)
    if factor is None:
        raise ConfigError(f"{key}: {unit!r} is not a length unit (e.g. m, mm, um)")
    return factor
