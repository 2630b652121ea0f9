"""Quantities with units at the boundaries (config, CLI, reports).

Inside the package everything is an SI ``float``. This module is the only
place that converts: :func:`to_si` accepts a number (already SI) or a string
such as ``"0.2 mm"`` or ``"240 rpm"`` and returns the SI magnitude, after
checking the dimension.

Turns and cycles
----------------
pint takes the radian for a dimensionless unit, so ``rpm`` (revolutions per
minute), ``Hz``, ``rad/s`` and ``1/min`` all have the dimension ``1/[time]`` and
pint converts between them as if one revolution were one radian. jointwear does
not: a value with an angle unit (``rad``, ``deg``, ``rev``, ``turn``, ``rpm``)
counts radians, one without (``Hz``, ``1/s``, ``1/min``) counts turns (cycles),
and between the two lies the factor 2π (:func:`to_si`). So ``"120 rpm"`` as an
angular velocity is 4π rad/s, ``"2 Hz"`` too; ``"30 rpm"`` as a frequency is
0.5 Hz, ``"10 rad/s"`` is 10/(2π) Hz.

Bare numbers
------------
A bare number (``35``, or the text ``"35"``) is SI. Where one is almost surely
a unit slip (:data:`BARE_LIMITS`: an angle beyond a turn, a length of a joint's
part beyond a metre, ...) the boundaries that read user text refuse it with a
message that says how it was read and how to give a unit
(:func:`check_bare`): ``mechanism.amplitude: 35 is read as 35 rad (a bare
number is SI), more than 6.283 rad; give a unit, e.g. "35 deg"``.
"""

from __future__ import annotations

import io
import math
import re
import tokenize
from functools import cache
from typing import TYPE_CHECKING, Any

from jointwear import quantity_memo
from jointwear.errors import ConfigError

if TYPE_CHECKING:
    import pint

__all__ = [
    "BARE_LIMITS",
    "DIMENSIONS",
    "MAX_DIGITS",
    "MAX_EXPONENT",
    "MAX_EXPRESSION",
    "MAX_MAGNITUDE",
    "MAX_TURN_ANGLE",
    "check_bare",
    "format_quantity",
    "parse_quantity",
    "parse_unit",
    "registry",
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


@cache
def registry() -> pint.UnitRegistry:
    """The package's unit registry (:data:`ureg`), built when a text is first read.

    pint is imported here, not with this module: a value given as a plain SI number
    needs no unit, and pint's import costs ~0.15 s of a run's start (~0.3 s where
    dask is installed, whose ``dask.base`` pint imports with itself).
    """
    import pint

    # parsing pint's definition files costs ~0.2 s at every start; its on-disk
    # cache brings that to ~0.03 s. A cache that cannot be written is no error.
    try:
        units = pint.UnitRegistry(cache_folder=":auto:")
    except Exception:
        units = pint.UnitRegistry()
    units.define("rpm = revolution / minute")
    units.define("@alias revolution = rev")
    return units


if TYPE_CHECKING:
    #: the package's unit registry (:func:`registry`)
    ureg: pint.UnitRegistry


def __getattr__(name: str) -> Any:
    # ``ureg``: the registry, built on first use (PEP 562 module attribute)
    if name == "ureg":
        return registry()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


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


#: Kinds counted per unit time -> the power of the radian in their SI unit: an
#: angular velocity counts radians (rad/s), a frequency turns (Hz = cycles/s).
_PER_TIME_ANGLE_POWER: dict[str, int] = {"angular_velocity": 1, "frequency": 0}

#: One turn [rad]: an angular velocity in rad/s is 2π times the frequency in Hz.
_TURN = 2.0 * math.pi

#: Largest SI magnitude of a bare number of each kind that is taken as meant: above
#: it the number is almost surely in another unit (an angle in degrees, a bushing's
#: radius in millimetres, a crank speed in rpm), and :func:`check_bare` refuses it.
#: kind -> (limit [SI unit of the kind], the unit it was most likely meant in).
BARE_LIMITS: dict[str, tuple[float, str]] = {
    "angle": (_TURN, "deg"),  # more than a turn: degrees
    "length": (1.0, "mm"),  # a joint's pin, clearance, bushing: far below a metre
    "angular_velocity": (1000.0, "rpm"),  # ~9550 rpm
    "frequency": (100.0, "1/min"),  # oscillation tests run at a few Hz
    "velocity": (100.0, "mm/s"),  # sliding speeds of plain bearings: a few m/s
}


#: a quantity text of one number and a unit after a space (``"70 mm"``, ``"-2e7 N/m**1.5"``):
#: a decimal literal as Python's tokenizer (and so pint) reads it, the unit from a letter on
_NUMBER_AND_UNIT = re.compile(
    r"(?P<number>[+-]?(?:(?:0|[1-9][0-9]*)(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?)"
    r"\s+(?P<unit>[A-Za-z_].*)",
    re.DOTALL,
)


def _number_and_unit(text: str) -> tuple[str, str] | None:
    """The number and the unit of a text of one number and a unit, None for other texts."""
    text = text.strip()
    match = _NUMBER_AND_UNIT.fullmatch(text)
    if match is None or len(text) > MAX_EXPRESSION:
        return None
    number = match["number"]
    if sum(c.isdigit() for c in number) > MAX_DIGITS:
        return None
    return number, match["unit"]


def _has_known_unit(text: str) -> bool:
    """Whether ``text`` is a number in a unit pint read before (a quantity with a unit)."""
    parts = _number_and_unit(text)
    return parts is not None and quantity_memo.knows_unit(parts[1])


@cache
def _unit(text: str) -> pint.Unit:
    return registry().Unit(text)


def to_si(value: Any, kind: str, key: str = "value", *, bare_limit: float | None = None) -> float:
    """Convert a number or a string with units to an SI float.

    An angular velocity and a frequency convert into each other with the factor
    2π: a unit with an angle (``rpm``, ``rad/s``, ``deg/s``, ``rev/s``) counts
    radians, one without (``Hz``, ``1/s``, ``1/min``) counts turns, ``1 Hz = 2π
    rad/s = 60 rpm`` (pint alone would take one turn for one radian).

    Parameters
    ----------
    value : float or str
        A plain number (taken as SI) or a string with a unit, e.g. ``"7.5 mm"``.
    kind : str
        Physical kind, a key of :data:`DIMENSIONS`, e.g. ``"length"``.
    key : str
        Name used in error messages (dotted config key).
    bare_limit : float, optional
        Largest magnitude [SI unit of ``kind``] of a bare number (see
        :func:`check_bare`); default: a bare number is not checked.

    Returns
    -------
    float
        Magnitude in the SI unit of ``kind``.

    Raises
    ------
    ConfigError
        If the string does not parse, has the wrong dimension or is not finite, or a
        bare number exceeds ``bare_limit``.
    """
    what = kind.replace("_", " ")
    article = "an" if what[0] in "aeiou" else "a"
    expected = f"{article} {what} (e.g. in {DIMENSIONS[kind] or 'dimensionless'})"
    magnitude = _convert(value, DIMENSIONS[kind], expected, key, _PER_TIME_ANGLE_POWER.get(kind))
    if bare_limit is not None:
        check_bare(value, kind, key, bare_limit)
    return magnitude


def bare_number(value: Any) -> float | None:
    """The number of a bare number (``35``, ``"35"``, ``"3.5e1"``), None for anything else.

    Parameters
    ----------
    value : Any
        A config or option value [SI if a bare number].
    """
    if isinstance(value, bool):
        return None
    if isinstance(value, int | float):
        number = float(value) if abs(value) <= MAX_MAGNITUDE else math.inf
    elif isinstance(value, str):
        if quantity_memo.has_unit(value) or _has_known_unit(value):  # pint read its unit before
            return None
        try:
            quantity = parse_quantity(value)
        except ConfigError:
            return None
        if isinstance(quantity, int | float):
            number = float(quantity)
        elif quantity.unitless:
            number = float(quantity.magnitude)
        else:
            return None
    else:
        return None
    return number if math.isfinite(number) else None


def check_bare(value: Any, kind: str, key: str, limit: float | None = None) -> None:
    """Refuse a bare number that is almost surely a unit slip.

    A bare number is SI; beyond the plausible magnitude of its kind
    (:data:`BARE_LIMITS`: an angle of more than a turn, a bushing of more than a
    metre) the message says how it was read and how to give a unit. Anything else
    (a string with a unit, a bare number within the limit, a kind without a limit)
    passes.

    Parameters
    ----------
    value : Any
        The value as given.
    kind : str
        Physical kind, a key of :data:`DIMENSIONS`.
    key : str
        Name used in the message (dotted config key or option).
    limit : float, optional
        Largest magnitude [SI unit of ``kind``]; default from :data:`BARE_LIMITS`.

    Raises
    ------
    ConfigError
        ``KEY: 35 is read as 35 rad (a bare number is SI), more than 6.283 rad;
        give a unit, e.g. "35 deg"``.
    """
    number = bare_number(value)
    default, hint = BARE_LIMITS.get(kind, (None, DIMENSIONS[kind]))
    limit = default if limit is None else limit
    if number is None or limit is None or abs(number) <= limit:
        return
    text = value.strip() if isinstance(value, str) else repr(value)
    unit = DIMENSIONS[kind]
    raise ConfigError(
        f"{key}: {text} is read as {text} {unit} (a bare number is SI), more than "
        f'{limit:.4g} {unit}; give a unit, e.g. "{text} {hint}"'
    )


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
    return _convert(value, unit, f"a quantity in {unit}", key)


def to_angle(value: Any, key: str = "value", limit: float = MAX_TURN_ANGLE) -> float:
    """Convert a direction angle (``"12 deg"``; a bare number is radians) to radians.

    A bare number of more than a turn is refused as a unit slip (:func:`check_bare`).

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
        As :func:`to_si`, if ``|angle| > limit``, or for a bare number of more than a
        turn.
    """
    angle = to_si(value, "angle", key, bare_limit=min(limit, BARE_LIMITS["angle"][0]))
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
    from pint.util import string_preprocessor

    try:
        canonical = string_preprocessor(text)
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
        return registry().Quantity(text)
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
        return registry().Unit(text)
    except Exception as exc:
        why = " ".join(str(exc).split()) or type(exc).__name__
        raise ConfigError(f"{key}: cannot read {shown(text)} as a unit ({why})") from None


def _convert(
    value: Any, target: str, expected: str, key: str, angle_power: int | None = None
) -> float:
    if isinstance(value, bool):
        raise ConfigError(f"{key}: expected a number or a quantity string, got a boolean")
    try:
        magnitude: float | None = _magnitude(value, target, expected, key, angle_power)
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


def _radian_power(unit: Any) -> float:
    """Power of the radian in a unit: 1 for rpm, deg/s or rad/s, 0 for Hz, 1/min, m."""
    return dict(registry().Quantity(1.0, unit).to_root_units().unit_items()).get("radian", 0)


def _magnitude(value: Any, target: str, expected: str, key: str, angle_power: int | None) -> float:
    """SI magnitude of a number or quantity text (may overflow to inf or raise).

    ``target`` is the SI unit's text. A text goes to pint unless pint read it for the
    same target before (:mod:`jointwear.quantity_memo`); a plain number needs no pint.
    ``angle_power`` (for a rate: 1 in rad/s, 0 in Hz) makes a rate of the other kind
    convert with the factor 2π of a turn, which pint's dimensionless radian drops.
    """
    if isinstance(value, int | float):
        return float(value)
    if not isinstance(value, str):
        raise ConfigError(f"{key}: expected a number or a quantity string, got {shown(value)}")
    conversion = f"{target}|{'' if angle_power is None else angle_power}"
    known = quantity_memo.recall(value, conversion)
    parts = None if known is not None else _number_and_unit(value)
    if parts is not None:
        known = _known_unit_magnitude(parts, conversion)
    if known is not None:
        return known
    quantity = parse_quantity(value, key)
    if isinstance(quantity, int | float):
        return float(quantity)
    if quantity.unitless:
        # a bare number written as text ("7.5e-3") is SI, as a number would be
        return float(quantity.magnitude)
    unit = _unit(target)
    magnitude, turns = _pint_magnitude(value, quantity, unit, expected, key, angle_power)
    if math.isfinite(magnitude) and abs(magnitude) <= MAX_MAGNITUDE:
        quantity_memo.remember(value, conversion, magnitude)
        if parts is not None:
            _remember_unit(parts, quantity, unit, conversion, turns, magnitude)
    return magnitude


def _known_unit_magnitude(parts: tuple[str, str], conversion: str) -> float | None:
    """The SI magnitude of a number in a unit pint read before for ``conversion``: the
    number times pint's factor (and the turn factor of a rate), as pint computes it."""
    scale = quantity_memo.recall_unit(parts[1], conversion)
    if scale is None:
        return None
    factor, turns = scale
    magnitude = float(parts[0]) * factor * turns
    return magnitude if math.isfinite(magnitude) and abs(magnitude) <= MAX_MAGNITUDE else None


def _remember_unit(
    parts: tuple[str, str],
    quantity: Any,
    unit: pint.Unit,
    conversion: str,
    turns: float,
    magnitude: float,
) -> None:
    """Keep the unit of a text of one number and a unit (``parts``, from
    :func:`_number_and_unit`) with pint's factor into ``unit``, where pint read the text
    as that number in that unit (no offset, no scale) and its answer was the number
    times the factor (and ``turns``), bit for bit."""
    number, text = float(parts[0]), parts[1]
    units = registry()
    try:
        own = units.Unit(text)
        if quantity.units != own or quantity.magnitude != number:
            return
        if units.Quantity(0.0, own).to(unit).magnitude != 0.0:  # an offset (degC)
            return
        factor = float(units.Quantity(1, own).to(unit).magnitude)
    except Exception:  # (pint reads the unit alone otherwise: nothing kept)
        return
    if number * factor * turns == magnitude:
        quantity_memo.remember_unit(text, conversion, factor, turns)


def _pint_magnitude(
    value: str, quantity: Any, unit: pint.Unit, expected: str, key: str, angle_power: int | None
) -> tuple[float, float]:
    """pint's SI magnitude of a quantity with a unit (see :func:`_magnitude`), and the
    factor between turns and radians it holds (1 but for a rate of the other kind)."""
    if not quantity.check(unit.dimensionality):
        raise ConfigError(
            f"{key}: {shown(value)} has dimension {quantity.dimensionality}, expected {expected}"
        )
    magnitude = float(quantity.to(unit).magnitude)
    if angle_power is None:
        return magnitude, 1.0
    given = _radian_power(quantity.units)
    if given not in (0, 1):
        raise ConfigError(
            f"{key}: {shown(value)} is not a rate of turns or of an angle, expected {expected}"
        )
    # rpm -> Hz: pint's 2π rad/min per revolution counted as 2π cycles/min; divide by 2π
    turns = _TURN ** (angle_power - given)
    return magnitude * turns, turns


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
    units = registry()
    quantity = units.Quantity(value, units.Unit(_si_unit_for(unit))).to(unit)
    return f"{quantity.magnitude:.{digits}g} {unit}"


def _si_unit_for(unit: str) -> str:
    """The SI unit of :data:`DIMENSIONS` a display unit shows (``"rpm"`` -> rad/s, ``"Hz"`` -> Hz).

    The power of the radian must match too: an angular velocity is shown in rpm or
    deg/s, a frequency in Hz or 1/min (pint's dimensionless radian would mix them).
    """
    units = registry()
    parsed = units.Unit(unit)
    for si in DIMENSIONS.values():
        if (
            si
            and units.Unit(si).dimensionality == parsed.dimensionality
            and _radian_power(si) == _radian_power(parsed)
        ):
            return si
    return str(units.Quantity(1, unit).to_base_units().units)
