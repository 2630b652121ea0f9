"""Quantities with units at the boundaries (config, CLI, reports).

Inside the package everything is an SI ``float``. This module is the only
place that converts: :func:`to_si` accepts a number (already SI) or a string
such as ``"0.2 mm"`` or ``"240 rpm"`` and returns the SI magnitude, after
checking the dimension.
"""

from __future__ import annotations

import math
from functools import cache
from typing import Any

import pint

from jointwear.errors import ConfigError

__all__ = ["DIMENSIONS", "format_quantity", "to_si", "to_si_unit", "ureg"]


def _registry() -> pint.UnitRegistry:
    # parsing pint's definition files costs ~0.2 s at every start; its on-disk
    # cache brings that to ~0.03 s. A cache that cannot be written is no error.
    try:
        return pint.UnitRegistry(cache_folder=":auto:")
    except Exception:
        return pint.UnitRegistry()


ureg = _registry()
ureg.define("rpm = revolution / minute")

#: SI unit used for each physical kind of parameter.
DIMENSIONS: dict[str, str] = {
    "length": "m",
    "area": "m**2",
    "volume": "m**3",
    "mass": "kg",
    "force": "N",
    "stiffness": "N/m",
    "pressure": "Pa",
    "angular_velocity": "rad/s",
    "angle": "rad",
    "velocity": "m/s",
    "pressure_velocity": "Pa*m/s",
    "acceleration": "m/s**2",
    "density": "kg/m**3",
    "wear_coefficient": "1/Pa",
    "moment_of_inertia": "kg*m**2",
    "time": "s",
    "frequency": "Hz",
    "torque": "N*m",
    "torsional_stiffness": "N*m/rad",
    "dimensionless": "",
}


@cache
def _unit(kind: str) -> pint.Unit:
    return ureg.Unit(DIMENSIONS[kind])


def to_si(value: Any, kind: str, key: str = "value") -> float:
    """Convert a number or a string with units to an SI float.

    Parameters
    ----------
    value : float or str
        A plain number (taken as SI) or a string with a unit, e.g. ``"7.5 mm"``.
    kind : str
        Physical kind, a key of :data:`DIMENSIONS`, e.g. ``"length"``.
    key : str
        Name used in error messages (dotted config key).

    Returns
    -------
    float
        Magnitude in the SI unit of ``kind``.

    Raises
    ------
    ConfigError
        If the string does not parse, has the wrong dimension or is not finite.
    """
    what = kind.replace("_", " ")
    article = "an" if what[0] in "aeiou" else "a"
    expected = f"{article} {what} (e.g. in {DIMENSIONS[kind] or 'dimensionless'})"
    # a rotational speed may be written as a frequency ("2 Hz", "120 1/min")
    alternative = "1/[time]" if kind == "angular_velocity" else None
    return _convert(value, _unit(kind), expected, key, alternative)


def to_si_unit(value: Any, unit: str, key: str = "value") -> float:
    """Convert a number or a string with units to the SI unit ``unit``.

    For quantities whose dimension is not one of :data:`DIMENSIONS`, such as the
    NLCP stiffness ``K`` in ``N/m**n`` with a configurable exponent ``n``.

    Parameters
    ----------
    value : float or str
        A plain number (taken as SI) or a string with a unit, e.g. ``"2e7 N/m**1.5"``.
    unit : str
        The SI unit (pint syntax) the value is expressed in, e.g. ``"N/m**1.5"``.
    key : str
        Name used in error messages (dotted config key).
    """
    return _convert(value, ureg.Unit(unit), f"a quantity in {unit}", key)


def _convert(
    value: Any, target: pint.Unit, expected: str, key: str, alternative: str | None = None
) -> float:
    if isinstance(value, bool):
        raise ConfigError(f"{key}: expected a number or a quantity string, got a boolean")
    if isinstance(value, int | float):
        magnitude = float(value)
    elif isinstance(value, str):
        try:
            quantity = ureg.Quantity(value.strip())
        except Exception as exc:
            raise ConfigError(f"{key}: cannot read {value!r} as a quantity ({exc})") from None
        if isinstance(quantity, int | float):
            magnitude = float(quantity)
        elif quantity.unitless:
            # a bare number written as text ("7.5e-3") is SI, as a number would be
            magnitude = float(quantity.magnitude)
        else:
            if not quantity.check(target.dimensionality) and not (
                alternative is not None and quantity.check(alternative)
            ):
                raise ConfigError(
                    f"{key}: {value!r} has dimension {quantity.dimensionality}, expected {expected}"
                )
            magnitude = float(quantity.to(target).magnitude)
    else:
        raise ConfigError(f"{key}: expected a number or a quantity string, got {value!r}")
    if not math.isfinite(magnitude):
        raise ConfigError(f"{key}: must be finite, got {value!r}")
    return magnitude


def format_quantity(value: float, unit: str, digits: int = 6) -> str:
    """Format an SI value in a display unit, e.g. ``format_quantity(5e-5, "mm")``.

    Parameters
    ----------
    value : float
        SI magnitude.
    unit : str
        Display unit understood by pint.
    digits : int
        Significant digits.
    """
    quantity = ureg.Quantity(value, ureg.Unit(_si_unit_for(unit))).to(unit)
    return f"{quantity.magnitude:.{digits}g} {unit}"


def _si_unit_for(unit: str) -> str:
    dimensionality = ureg.Unit(unit).dimensionality
    for si in DIMENSIONS.values():
        if si and ureg.Unit(si).dimensionality == dimensionality:
            return si
    return str(ureg.Quantity(1, unit).to_base_units().units)
