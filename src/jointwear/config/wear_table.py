"""The ``[wear]`` keys of a wear coefficient tabulated against how the joint runs.

``wear.law = "tabulated"``: ``table_coefficients`` [1/Pa] at ``table_points`` of the
variable ``table_against`` (``"speed"`` [m/s], ``"pv"`` [Pa m/s] or ``"temperature"`` [K],
SI numbers), linearly interpolated (:mod:`jointwear.tribology.operating`). A temperature
table needs ``wear.temperature`` [K] inside its range (known before the run: refused
outside it); speed and PV are known step by step only, and are clamped to the table's
ends with a warning.
"""

from __future__ import annotations

import itertools
from typing import Any

__all__ = ["TABLE_VARIABLES", "check_table"]

#: what a wear coefficient can be tabulated against -> its SI unit
TABLE_VARIABLES: dict[str, str] = {"speed": "m/s", "pv": "Pa*m/s", "temperature": "K"}


def check_table(wear: Any) -> None:
    """Refuse an incomplete or malformed table of a ``tabulated`` wear law.

    Parameters
    ----------
    wear : WearConfig
        The ``[wear]`` section.

    Raises
    ------
    ValueError
        One line naming the key and the reason.
    """
    if wear.law != "tabulated":
        return
    for key in ("table_against", "table_points", "table_coefficients"):
        if getattr(wear, key) is None:
            raise ValueError(f"wear.{key}: missing (needed by wear.law = 'tabulated')")
    points, coefficients = wear.table_points, wear.table_coefficients
    if len(points) != len(coefficients):
        raise ValueError(
            f"wear.table_coefficients: {len(coefficients)} values for {len(points)} "
            f"table_points; give one coefficient per point"
        )
    if any(b <= a for a, b in itertools.pairwise(points)):
        raise ValueError("wear.table_points: the points must increase strictly")
    if wear.table_against == "temperature":
        if wear.temperature is None:
            raise ValueError("wear.temperature: missing (needed by a table against temperature)")
        if not points[0] <= wear.temperature <= points[-1]:
            raise ValueError(
                f"wear.temperature: {wear.temperature:g} K is outside the table "
                f"({points[0]:g} to {points[-1]:g} K); a tabulated coefficient is not "
                f"extrapolated"
            )
