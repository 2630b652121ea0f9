"""Quantities with units at the boundaries (config, CLI, reports).

Inside the package everything is an SI ``float``. This module is the only
place that converts: :func:`to_si` accepts a number (already SI) or a string
such as ``"0.2 mm"`` or ``"240 rpm"`` and returns the SI magnitude, after
checking the dimension.
"""

from __future__ import annotations

import importlib
import importlib.util
import io
import math
import sys
import tokenize
from functools import cache
from typing import Any

from jointwear.errors import ConfigError


class _Deferred:
    """Attributes of a module imported when first read."""

    def __init__(self, module: str) -> None:
        self._module = module

    def __getattr__(self, name: str) -> Any:
        return getattr(importlib.import_module(self._module), name)


def _deferred_call(module: str, name: str) -> Any:
    def call(*args: Any, **kwargs: Any) -> Any:
        return getattr(importlib.import_module(module), name)(*args, **kwargs)

    call.__name__ = name
    return call


def _import_pint() -> Any:
    """pint, imported without importing dask.

    With dask installed, pint's import loads ``dask.base`` (~0.1 s, most of it for
    ``Quantity.compute()`` on dask arrays), at every start of the command line. dask
    stays hidden while pint loads; then pint's dask helpers are pointed at modules
    imported on first use, so quantities of dask arrays work as before.
    """
    if "pint" in sys.modules or "dask" in sys.modules:
        import pint

        return pint
    try:
        has_dask = importlib.util.find_spec("dask") is not None
    except (ImportError, ValueError):
        has_dask = False
    sys.modules["dask"] = None  # type: ignore[assignment]  # find_spec answers None
    try:
        import pint
    finally:
        if sys.modules.get("dask", 0) is None:
            del sys.modules["dask"]
    if has_dask:
        from pint import compat
        from pint.facets import dask as facet

        helpers = {
            "dask_array": _Deferred("dask.array"),
            **{name: _deferred_call("dask.base", name)
               for name in ("compute", "persist", "visualize")},
        }
        for module in (compat, facet):
            for name, value in helpers.items():
                if getattr(module, name, 0) is None:
                    setattr(module, name, value)
        compat.HAS_DASK = True
    return pint


pint = _import_pint()

__all__ = [
    "DIMENSIONS",
    "MAX_DIGITS",
    "MAX_EXPONENT",
    "MAX_EXPRESSION",
    "MAX_MAGNITUDE",
    "MAX_TURN_ANGLE",
    "format_quantity",
    "parse_quantity",
    "parse_unit",
    "shown",
    "to_angle",
    "to_si",
    "to_si_unit",
    "ureg",
]

#: longest quantity or unit text read [characters]
MAX_EXPRESSION = 200
#: most digits in one number of a quantity text
MAX_DIGITS = 40
#: largest exponent in a unit expression (``m**3``, ``N/m**1.5``)
MAX_EXPONENT = 12
#: largest SI magnitude of any value: beyond it no quantity of a joint makes sense
MAX_MAGNITUDE = 1e100
#: largest direction angle [rad] (two turns either way)
MAX_TURN_ANGLE = 4 * math.pi


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


def to_angle(value: Any, key: str = "value", limit: float = MAX_TURN_ANGLE) -> float:
    """Convert a direction angle (``"12 deg"``; a bare number is radians) to radians.

    Parameters
    ----------
    value : float or str
        The angle [rad] or a string with a unit.
    key : str
        Name used in error messages (option or dotted config key).
    limit : float
        Largest magnitude accepted [rad]; default two turns.

    Raises
    ------
    ConfigError
        As :func:`to_si`, or if ``|angle| > limit``.
    """
    angle = to_si(value, "angle", key)
    if abs(angle) > limit:
        raise ConfigError(
            f"{key}: {shown(value)} is not a direction angle "
            f"(|angle| <= {math.degrees(limit):g} deg)"
        )
    return angle


def shown(value: Any, width: int = 40) -> str:
    """``repr(value)``, shortened to about ``width`` characters for a one-line message."""
    if isinstance(value, int) and value.bit_length() > 10_000:
        # repr() of an integer beyond Python's conversion limit (4300 digits) raises
        return f"an integer of about {value.bit_length() * math.log10(2):.0f} digits"
    try:
        text = repr(value)
    except ValueError:  # e.g. a list holding such an integer
        return f"a {type(value).__name__} too large to show"
    return text if len(text) <= width else f"{text[: width - 12]}...{text[-8:]} ({len(text)} chars)"


def _check_expression(text: str, key: str) -> None:
    """Refuse a quantity or unit text whose evaluation could take unbounded time or memory.

    pint evaluates the text as arithmetic, with Python integers: ``9**9**9`` would
    compute a number with 370 million digits. Allowed: at most
    :data:`MAX_EXPRESSION` characters, numbers of at most :data:`MAX_DIGITS` digits
    and exponents that are plain numbers within +-:data:`MAX_EXPONENT`, raising a
    unit or a number, or a parenthesised group that holds no exponent itself.
    """
    if len(text) > MAX_EXPRESSION:
        raise ConfigError(
            f"{key}: {shown(text)} is too long for a quantity ({MAX_EXPRESSION} characters at most)"
        )
    try:
        canonical = pint.util.string_preprocessor(text)
        tokens = [
            t
            for t in tokenize.generate_tokens(io.StringIO(canonical).readline)
            if t.type not in (tokenize.NEWLINE, tokenize.NL, tokenize.ENDMARKER)
        ]
    except (tokenize.TokenError, SyntaxError, ValueError) as exc:
        raise ConfigError(f"{key}: cannot read {shown(text)} as a quantity ({exc})") from None
    # groups[-1]: does the innermost open parenthesis hold an exponent?
    groups: list[bool] = [False]
    closed_power = False  # the group just closed held an exponent
    exponent_end = -1  # index of the token after the last exponent
    for i, token in enumerate(tokens):
        if token.type == tokenize.NUMBER:
            digits = sum(c.isdigit() for c in token.string)
            if digits > MAX_DIGITS:
                raise ConfigError(
                    f"{key}: a number of {digits} digits in {shown(text)} "
                    f"(at most {MAX_DIGITS} digits)"
                )
        if token.string == "(":
            groups.append(False)
        elif token.string == ")" and len(groups) > 1:
            closed_power = groups.pop()
            groups[-1] = groups[-1] or closed_power
            continue
        elif token.string in ("**", "^"):
            groups[-1] = True
            if i == exponent_end or (tokens[i - 1].string == ")" and closed_power):
                raise ConfigError(f"{key}: {shown(text)}: exponents cannot be nested")
            length = _exponent_length(tokens[i + 1 :])
            if not length:
                raise ConfigError(
                    f"{key}: {shown(text)}: an exponent must be a number within "
                    f"+-{MAX_EXPONENT} (e.g. m**3, N/m**1.5)"
                )
            exponent_end = i + 1 + length
        closed_power = False


def _exponent_length(tokens: list[tokenize.TokenInfo]) -> int:
    """Tokens of a leading exponent within +-MAX_EXPONENT (``3``, ``-1.5``, ``(2)``); 0 if none."""
    strings = [t.string for t in tokens[:4]]
    start, end = 0, 0
    if strings[:1] == ["("]:
        if ")" not in strings:
            return 0
        start, end = 1, 1
        strings = strings[1 : strings.index(")")]
    if strings[:1] in (["-"], ["+"]):
        start += 1
        strings = strings[1:]
    if len(strings) < 1 or (end and len(strings) != 1):
        return 0
    number = tokens[start]
    if number.type != tokenize.NUMBER:
        return 0
    try:
        bounded = abs(float(number.string)) <= MAX_EXPONENT
    except ValueError:  # complex or other literals
        return 0
    return start + 1 + end if bounded else 0


def parse_quantity(text: str, key: str = "value") -> Any:
    """Read a quantity text such as ``"7.5 mm"`` with pint, after bounding its cost.

    The one place where jointwear turns text into a quantity (config values,
    options, sweep values); see :func:`_check_expression` for what is refused.

    Parameters
    ----------
    text : str
        The quantity, e.g. ``"0.2 mm"``, ``"2e7 N/m**1.5"``.
    key : str
        Name used in error messages.

    Returns
    -------
    pint.Quantity or float or int
        A number for a text without unit.

    Raises
    ------
    ConfigError
        Unreadable, too long, too many digits or an unbounded exponent.
    """
    text = text.strip()
    _check_expression(text, key)
    try:
        return ureg.Quantity(text)
    except OverflowError:
        raise ConfigError(
            f"{key}: {shown(text)} is beyond any physical value "
            f"(|value| <= {MAX_MAGNITUDE:g} in SI units)"
        ) from None
    except Exception as exc:
        why = " ".join(str(exc).split()) or type(exc).__name__
        raise ConfigError(f"{key}: cannot read {shown(text)} as a quantity ({why})") from None


def parse_unit(text: str, key: str = "unit") -> pint.Unit:
    """Read a unit text such as ``"mm"`` or ``"kN"`` (bounded like :func:`parse_quantity`).

    Parameters
    ----------
    text : str
        The unit.
    key : str
        Name used in error messages.

    Raises
    ------
    ConfigError
        Unreadable or unbounded (see :func:`parse_quantity`).
    """
    text = text.strip()
    _check_expression(text, key)
    try:
        return ureg.Unit(text)
    except Exception as exc:
        why = " ".join(str(exc).split()) or type(exc).__name__
        raise ConfigError(f"{key}: cannot read {shown(text)} as a unit ({why})") from None


def _convert(
    value: Any, target: pint.Unit, expected: str, key: str, alternative: str | None = None
) -> float:
    if isinstance(value, bool):
        raise ConfigError(f"{key}: expected a number or a quantity string, got a boolean")
    try:
        magnitude: float | None = _magnitude(value, target, expected, key, alternative)
    except (OverflowError, ArithmeticError):  # float() of an integer of hundreds of digits
        magnitude = None
    if magnitude is not None and not math.isfinite(magnitude):
        raise ConfigError(f"{key}: must be finite, got {shown(value)}")
    if magnitude is None or abs(magnitude) > MAX_MAGNITUDE:
        raise ConfigError(
            f"{key}: {shown(value)} is beyond any physical value "
            f"(|value| <= {MAX_MAGNITUDE:g} in SI units)"
        )
    return magnitude


def _magnitude(
    value: Any, target: pint.Unit, expected: str, key: str, alternative: str | None
) -> float:
    """SI magnitude of a number or quantity text (may overflow to inf or raise)."""
    if isinstance(value, int | float):
        return float(value)
    if not isinstance(value, str):
        raise ConfigError(f"{key}: expected a number or a quantity string, got {shown(value)}")
    quantity = parse_quantity(value, key)
    if isinstance(quantity, int | float):
        return float(quantity)
    if quantity.unitless:
        # a bare number written as text ("7.5e-3") is SI, as a number would be
        return float(quantity.magnitude)
    if not quantity.check(target.dimensionality) and not (
        alternative is not None and quantity.check(alternative)
    ):
        raise ConfigError(
            f"{key}: {shown(value)} has dimension {quantity.dimensionality}, expected {expected}"
        )
    return float(quantity.to(target).magnitude)


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
