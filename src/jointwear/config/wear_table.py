"""The ``[wear]`` keys of a wear coefficient tabulated against how the joint runs.

``wear.law = "tabulated"``: ``table_coefficients`` [1/Pa] at ``table_points`` of the
variable ``table_against`` (``"speed"`` [m/s], ``"pv"`` [Pa m/s] or ``"temperature"`` [K],
SI numbers), linearly interpolated (:mod:`jointwear.tribology.operating`). Without these
keys the table is the bushing material's ``wear_table`` (a library entry's, with its
source: :mod:`jointwear.materials`). A temperature table needs ``wear.temperature`` [K]
inside its range (known before the run: refused outside it); speed and PV are known step
by step only, and are clamped to the table's ends with a warning.
"""

from __future__ import annotations

import itertools
from typing import Annotated, Any, Literal

from pydantic import Field

from jointwear.config.fields import Section

__all__ = [
    "TABLE_KEYS",
    "TABLE_VARIABLES",
    "TableCoefficients",
    "TablePoints",
    "WearTable",
    "check_table",
    "table_of",
]

#: what a wear coefficient can be tabulated against -> its SI unit
TABLE_VARIABLES: dict[str, str] = {"speed": "m/s", "pv": "Pa*m/s", "temperature": "K"}
#: the ``[wear]`` keys of a table
TABLE_KEYS: tuple[str, ...] = ("table_against", "table_points", "table_coefficients")
TablePoints = Annotated[list[Annotated[float, Field(ge=0)]], Field(min_length=2, max_length=1000)]
TableCoefficients = Annotated[
    list[Annotated[float, Field(gt=0)]], Field(min_length=2, max_length=1000)
]


class WearTable(Section):
    """A wear coefficient ``K_d`` [1/Pa] at increasing ``points`` [m/s, Pa m/s or K] of
    the variable ``against`` (SI numbers; a library entry's are read from its units)."""

    against: Literal["speed", "pv", "temperature"]
    points: TablePoints
    coefficients: TableCoefficients


def table_of(wear: Any, bushing: Any) -> WearTable | None:
    """The table a ``tabulated`` law runs with: ``[wear]``'s own, else the bushing's.

    Parameters
    ----------
    wear : WearConfig
        The ``[wear]`` section.
    bushing : MaterialConfig
        The bushing's material (its ``wear_table``, or ``None``).
    """
    if any(getattr(wear, key) is not None for key in TABLE_KEYS):
        return WearTable(
            against=wear.table_against,
            points=wear.table_points,
            coefficients=wear.table_coefficients,
        )
    return getattr(bushing, "wear_table", None)


def check_table(wear: Any, bushing: Any = None) -> None:
    """Refuse an incomplete or malformed table of a ``tabulated`` wear law.

    Parameters
    ----------
    wear : WearConfig
        The ``[wear]`` section.
    bushing : MaterialConfig, optional
        The bushing's material, whose ``wear_table`` serves where ``[wear]`` gives none
        (``None``: the section alone, whose own table keys are checked if it gives any).

    Raises
    ------
    ValueError
        One line naming the key and the reason.
    """
    if wear.law != "tabulated":
        return
    own = any(getattr(wear, key) is not None for key in TABLE_KEYS)
    if not own and (bushing is None or bushing.wear_table is not None):
        table = None if bushing is None else bushing.wear_table
        if table is not None:
            _check_temperature(wear, table.against, table.points)
        return
    for key in TABLE_KEYS:
        if getattr(wear, key) is None:
            raise ValueError(
                f"wear.{key}: missing (needed by wear.law = 'tabulated', unless the bushing's "
                "material has a wear_table)"
            )
    points, coefficients = wear.table_points, wear.table_coefficients
    if len(points) != len(coefficients):
        raise ValueError(
            f"wear.table_coefficients: {len(coefficients)} values for {len(points)} "
            f"table_points; give one coefficient per point"
        )
    if any(b <= a for a, b in itertools.pairwise(points)):
        raise ValueError("wear.table_points: the points must increase strictly")
    _check_temperature(wear, wear.table_against, points)


def _check_temperature(wear: Any, against: str, points: list[float]) -> None:
    if against != "temperature":
        return
    if wear.temperature is None:
        raise ValueError("wear.temperature: missing (needed by a table against temperature)")
    if not points[0] <= wear.temperature <= points[-1]:
        raise ValueError(
            f"wear.temperature: {wear.temperature:g} K is outside the table "
            f"({points[0]:g} to {points[-1]:g} K); a tabulated coefficient is not "
            f"extrapolated"
        )
