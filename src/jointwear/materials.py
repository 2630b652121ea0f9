"""The materials library: named pin and bushing materials, each value with its source.

The library is a data file shipped with the package (``jointwear/data/materials.toml``).
A config names a material instead of writing its values::

    [materials]
    bushing = "bronze"

or names a base material and overrides single values::

    [materials.bushing]
    name = "bronze"
    youngs_modulus = "105 GPa"

Wear is accepted in one of three forms: ``wear_coefficient`` (the dimensional Archard
coefficient ``K_d`` [m^2/N]), ``specific_wear_rate`` (the same quantity as usually
tabulated, [mm^3/(N m)]) or the dimensionless ``wear_factor_k`` with the ``hardness``
``H`` [Pa], ``K_d = k / H``. A material also carries the datasheet limits the
engineering checks (:mod:`jointwear.tribology.metrics`) compare with: nominal pressure,
sliding speed and PV.

:func:`resolve_material` turns what a config says about one material into the table the
config validates; :func:`merge_material` is how defaults and ``--set`` overrides combine
with it (naming a material replaces the table; giving one wear form drops the others).
"""

from __future__ import annotations

import itertools
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass
from functools import cache
from importlib.resources import files
from types import MappingProxyType
from typing import Any

from jointwear.errors import ConfigError
from jointwear.registry import suggest
from jointwear.units import DIMENSIONS, format_quantity, registry, to_si

__all__ = [
    "BOUNDARY_KEY",
    "LIMIT_KEYS",
    "PROPERTY_KEYS",
    "TABLE_AGAINST",
    "TABLE_KEY",
    "WEAR_FORMS",
    "Material",
    "check_wear_forms",
    "display_unit",
    "get_material",
    "library",
    "merge_material",
    "read_library",
    "resolve_material",
    "wear_coefficient",
    "wear_forms",
    "wear_table",
]

#: the equivalent ways to give the wear coefficient; exactly one per material
WEAR_FORMS: tuple[tuple[str, ...], ...] = (
    ("wear_coefficient",),
    ("specific_wear_rate",),
    ("wear_factor_k", "hardness"),
)
#: the wear coefficient of the pair lubricated by a grease (boundary lubrication,
#: ``[lubrication] lubricant = "grease-..."``): a value of the pair, like ``K_d``
BOUNDARY_KEY = "boundary_wear_coefficient"
#: a wear coefficient tabulated against how the joint runs (``wear.law = "tabulated"``)
TABLE_KEY = "wear_table"
#: what a wear coefficient can be tabulated against -> the kind of its points
TABLE_AGAINST: dict[str, str] = {
    "speed": "velocity",
    "pv": "pressure_velocity",
    "temperature": "temperature",
}
WEAR_KEYS: tuple[str, ...] = (
    *(k for form in WEAR_FORMS for k in form),
    BOUNDARY_KEY,
    TABLE_KEY,
)
#: the datasheet limits, compared by the engineering checks
LIMIT_KEYS: tuple[str, ...] = (
    "max_static_pressure",
    "max_dynamic_pressure",
    "max_pv",
    "max_sliding_speed",
)
#: physical kind (a key of ``units.DIMENSIONS``) of every value a material may carry
KINDS: dict[str, str] = {
    "youngs_modulus": "pressure",
    "poisson_ratio": "dimensionless",
    "density": "density",
    "wear_coefficient": "wear_coefficient",
    "specific_wear_rate": "wear_coefficient",
    "wear_factor_k": "dimensionless",
    "hardness": "pressure",
    BOUNDARY_KEY: "wear_coefficient",
    "max_static_pressure": "pressure",
    "max_dynamic_pressure": "pressure",
    "max_pv": "pressure_velocity",
    "max_sliding_speed": "velocity",
}
PROPERTY_KEYS: tuple[str, ...] = tuple(KINDS)
#: units in which values are shown (``jointwear materials``, docs)
DISPLAY_UNITS: dict[str, str] = {
    "youngs_modulus": "GPa",
    "poisson_ratio": "",
    "density": "g/cm^3",
    "wear_coefficient": "m^2/N",
    "specific_wear_rate": "mm^3/(N*m)",
    "wear_factor_k": "",
    "hardness": "GPa",
    BOUNDARY_KEY: "m^2/N",
    "max_static_pressure": "MPa",
    "max_dynamic_pressure": "MPa",
    "max_pv": "MPa*m/s",
    "max_sliding_speed": "m/s",
}

LIBRARY_FILE = "materials.toml"


@dataclass(frozen=True)
class Material:
    """One named material of the library.

    Attributes
    ----------
    name : str
        Library name (``materials.bushing = "<name>"``).
    description : str
        What the material is.
    values : mapping of str to str or float
        The values as written in the library (strings with units, or numbers).
    sources : mapping of str to str
        Where each value comes from, by key.
    """

    name: str
    description: str
    values: Mapping[str, Any]
    sources: Mapping[str, str]

    def si(self, key: str) -> float | None:
        """A value in SI units (``None`` if the material does not give it).

        Parameters
        ----------
        key : str
            A key of :data:`PROPERTY_KEYS`; ``"wear_coefficient"`` is resolved from
            whichever wear form the material gives [m^2/N].
        """
        if key == "wear_coefficient":
            return wear_coefficient(self.values, f"materials library: {self.name}")
        if key not in self.values or key == TABLE_KEY:
            return None
        return to_si(self.values[key], KINDS[key], f"materials library: {self.name}.{key}")

    def limits(self) -> dict[str, float | None]:
        """The datasheet limits [SI], ``None`` where not published."""
        return {key: self.si(key) for key in LIMIT_KEYS}

    def summary(self) -> dict[str, Any]:
        """Plain data: SI values (``K_d`` resolved), limits, and the sources."""
        return {
            "name": self.name,
            "description": self.description,
            **{
                key: self.si(key)
                for key in (
                    "youngs_modulus",
                    "poisson_ratio",
                    "density",
                    "wear_coefficient",
                    BOUNDARY_KEY,
                    *LIMIT_KEYS,
                )
            },
            TABLE_KEY: self.wear_table(),
            "values": dict(self.values),
            "sources": dict(self.sources),
        }

    def wear_table(self) -> dict[str, Any] | None:
        """The tabulated wear coefficient in SI (:func:`wear_table`), ``None`` if none."""
        if TABLE_KEY not in self.values:
            return None
        return wear_table(self.values[TABLE_KEY], f"materials library: {self.name}.{TABLE_KEY}")

    def display(self, key: str, unit: bool = True) -> str:
        """A value in its display unit, e.g. ``"100 GPa"`` (``""`` if not given).

        Parameters
        ----------
        key : str
            A key of :data:`PROPERTY_KEYS`, or ``"wear_table"`` (its variable, range and
            coefficients, e.g. ``"K_d(pv): 3 points, 0.01-0.1 MPa m/s -> 1e-15-4e-15 m2/N"``).
        unit : bool
            Append the unit.
        """
        if key == TABLE_KEY:
            table = self.wear_table()
            return "" if table is None else describe_table(table)
        value = self.si(key)
        if value is None:
            return ""
        display = DISPLAY_UNITS[key]
        if not display:
            return f"{value:.3g}"
        number = format_quantity(value, display, digits=3).split(" ", 1)[0]
        return f"{number} {display_unit(key)}" if unit else number


def display_unit(key: str) -> str:
    """The display unit of a material key as plain text (``"MPa m/s"``)."""
    return DISPLAY_UNITS[key].replace("*", " ").replace("^", "")


def read_library(text: str) -> dict[str, Material]:
    """Materials from the text of a library file (the format of ``data/materials.toml``).

    Parameters
    ----------
    text : str
        TOML: one table per material, every value ``{ value = ..., source = ... }``.

    Raises
    ------
    ConfigError
        For an unknown key, a value without its source or unit, or two wear forms.
    """
    data = tomllib.loads(text)
    out: dict[str, Material] = {}
    for name, table in data.items():
        values: dict[str, Any] = {}
        sources: dict[str, str] = {}
        for key, entry in table.items():
            if key == "description":
                continue
            if (
                (key not in KINDS and key != TABLE_KEY)
                or not isinstance(entry, Mapping)
                or set(entry)
                != {
                    "value",
                    "source",
                }
            ):
                raise ConfigError(
                    f"materials library: {name}.{key}: expected a known key with "
                    "{ value = ..., source = ... }"
                )
            values[key] = entry["value"]
            sources[key] = str(entry["source"])
        material = Material(
            name,
            str(table.get("description", "")),
            MappingProxyType(values),
            MappingProxyType(sources),
        )
        for key in values:
            material.si(key)  # every value reads with its unit
        material.wear_table()
        material.si("wear_coefficient")  # exactly one wear form
        out[name] = material
    return out


@cache
def library() -> MappingProxyType[str, Material]:
    """The materials library, name -> :class:`Material` (read once)."""
    text = files("jointwear").joinpath("data", LIBRARY_FILE).read_text(encoding="utf-8")
    return MappingProxyType(read_library(text))


def get_material(name: str, key: str = "material") -> Material:
    """The library material ``name``; an unknown name raises with the closest name.

    Parameters
    ----------
    name : str
        Library name, e.g. ``"bronze"``.
    key : str
        Config key named in the error message.
    """
    materials = library()
    if not isinstance(name, str) or name not in materials:
        raise ConfigError(f"{key}: unknown material {name!r}{suggest(str(name), materials)}")
    return materials[name]


def wear_forms(table: Mapping[str, Any]) -> list[tuple[str, ...]]:
    """The wear forms (entries of :data:`WEAR_FORMS`) a material table gives."""
    return [f for f in WEAR_FORMS if any(table.get(k) is not None for k in f)]


def check_wear_forms(table: Mapping[str, Any], key: str) -> tuple[str, ...] | None:
    """The one wear form ``table`` gives (``None`` if none).

    Parameters
    ----------
    table : mapping
        Material values.
    key : str
        Config key (the material) named in error messages.

    Raises
    ------
    ConfigError
        For two forms at once, or ``wear_factor_k`` without ``hardness`` (or the reverse).
    """
    forms = wear_forms(table)
    if len(forms) > 1:
        given = " and ".join(f[0] for f in forms)
        raise ConfigError(
            f"{key}: give one of wear_coefficient, specific_wear_rate, or wear_factor_k "
            f"with hardness, not {given}"
        )
    if not forms:
        return None
    missing = [k for k in forms[0] if table.get(k) is None]
    if missing:
        other = next(k for k in forms[0] if k not in missing)
        raise ConfigError(
            f"{key}.{missing[0]}: missing; {other} needs it (K_d = wear_factor_k / hardness)"
        )
    return forms[0]


def wear_coefficient(table: Mapping[str, Any], key: str) -> float | None:
    """``K_d`` [m^2/N] from whichever wear form ``table`` gives (``None`` if none).

    Parameters
    ----------
    table : mapping
        Material values: numbers (SI) or strings with units.
    key : str
        Config key (the material) named in error messages.

    Raises
    ------
    ConfigError
        For two forms at once, a form without its partner, a value of the wrong unit
        or a hardness that is not positive.
    """
    form = check_wear_forms(table, key)
    if form is None:
        return None
    if form == ("wear_factor_k", "hardness"):
        k = to_si(table["wear_factor_k"], "dimensionless", f"{key}.wear_factor_k")
        hardness = to_si(table["hardness"], "pressure", f"{key}.hardness")
        if not k >= 0:
            raise ConfigError(f"{key}.wear_factor_k: must be >= 0, got {table['wear_factor_k']!r}")
        if not hardness > 0:
            raise ConfigError(f"{key}.hardness: must be > 0, got {table['hardness']!r}")
        return k / hardness
    return to_si(table[form[0]], "wear_coefficient", f"{key}.{form[0]}")


def _point(value: Any, kind: str, key: str) -> float:
    """One point of a table in SI; a temperature as kelvin or ``"60 degC"``."""
    if kind != "temperature":
        return to_si(value, kind, key)
    if not isinstance(value, str):
        return float(value)
    number, _, unit = value.strip().partition(" ")
    try:
        return float(registry().Quantity(float(number), unit.strip() or "K").to("K").magnitude)
    except Exception as exc:  # pint's and float's errors alike: one message
        raise ConfigError(f"{key}: cannot read {value!r} as a temperature ({exc})") from None


def wear_table(value: Any, key: str) -> dict[str, Any]:
    """A wear coefficient tabulated against how the joint runs, in SI.

    Parameters
    ----------
    value : mapping
        ``against`` (``"speed"``, ``"pv"`` or ``"temperature"``), ``points`` (increasing;
        strings with units, or SI numbers: m/s, Pa m/s, K) and ``coefficients`` (one wear
        coefficient ``K_d`` per point, [m^2/N] or any unit of that dimension).
    key : str
        Where the table is, for messages.

    Returns
    -------
    dict
        ``{"against": str, "points": list of float, "coefficients": list of float}`` (SI).

    Raises
    ------
    ConfigError
        One line naming the key: an unknown variable, a unit of the wrong dimension,
        points that do not increase, fewer than two points, or a count that differs.
    """
    if not isinstance(value, Mapping) or set(value) != {"against", "points", "coefficients"}:
        raise ConfigError(
            f"{key}: expected {{ against = ..., points = [...], coefficients = [...] }}"
        )
    against, points, coefficients = value["against"], value["points"], value["coefficients"]
    if against not in TABLE_AGAINST:
        raise ConfigError(
            f"{key}.against: unknown variable {against!r}{suggest(str(against), TABLE_AGAINST)}"
        )
    if not isinstance(points, list | tuple) or not isinstance(coefficients, list | tuple):
        raise ConfigError(f"{key}: points and coefficients must be lists")
    if not 2 <= len(points) == len(coefficients):
        raise ConfigError(
            f"{key}: {len(coefficients)} coefficients for {len(points)} points; give one "
            "coefficient per point, at least two"
        )
    kind = TABLE_AGAINST[against]
    grid = [_point(p, kind, f"{key}.points") for p in points]
    if any(b <= a for a, b in itertools.pairwise(grid)):
        raise ConfigError(f"{key}.points: the points must increase strictly")
    ks = [to_si(k, "wear_coefficient", f"{key}.coefficients") for k in coefficients]
    if not all(k > 0 for k in ks):
        raise ConfigError(f"{key}.coefficients: every coefficient must be > 0")
    return {"against": against, "points": grid, "coefficients": ks}


#: display unit of a table's points, by what it is against
TABLE_UNITS: dict[str, str] = {"speed": "m/s", "pv": "MPa*m/s", "temperature": "K"}


def describe_table(table: Mapping[str, Any]) -> str:
    """A tabulated wear coefficient in one line: variable, points, range of ``K_d``."""
    against, unit = table["against"], TABLE_UNITS[table["against"]]
    points = table["points"]
    low, high = (
        format_quantity(p, unit, digits=3).split(" ", 1)[0] for p in (points[0], points[-1])
    )
    ks = table["coefficients"]
    return (
        f"K_d({against}): {len(ks)} points, {low}-{high} {unit.replace('*', ' ')} -> "
        f"{min(ks):.3g}-{max(ks):.3g} m2/N"
    )


def merge_material(base: Any, update: Any) -> Any:
    """Combine a material table with what overrides it (defaults, ``--set``).

    A name (a string, or a table with ``name``) replaces the base entirely; a table
    without a name updates the base key by key, and a wear form it gives drops the
    base's other wear forms (``specific_wear_rate`` replaces ``wear_coefficient``).

    Parameters
    ----------
    base : str or mapping
        The material so far: a library name or a table.
    update : str or mapping
        What overrides it.
    """
    if not isinstance(update, Mapping) or update.get("name") is not None:
        return update
    if isinstance(base, str):
        base = {"name": base}
    out = dict(base) if isinstance(base, Mapping) else {}
    given = wear_forms(update)
    for form in WEAR_FORMS:
        if given and form not in given:
            for key in form:
                out.pop(key, None)
    out.update(update)
    return out


def resolve_material(raw: Any, key: str, wear: bool = True) -> Any:
    """What a config says about one material, as the table its section validates.

    A library name (``"bronze"``) or a table with ``name`` starts from the library's
    values; the table's other keys override them. Tables without a name pass unchanged.

    Parameters
    ----------
    raw : str or mapping
        The config value of ``materials.pin`` or ``materials.bushing``.
    key : str
        Its dotted key, for messages.
    wear : bool
        Take the library's wear coefficient (the bushing). A named pin takes its elastic
        data only: a wear coefficient belongs to a pair of materials, and the pin wears
        only where its table gives a wear key (``wear_factor_k`` then takes the library's
        ``hardness``).

    Raises
    ------
    ConfigError
        For an unknown name (with the closest known name) or a value that is neither a
        name nor a table.
    """
    if isinstance(raw, str):
        raw, where = {"name": raw}, key
    elif isinstance(raw, Mapping):
        where = f"{key}.name"
    else:
        raise ConfigError(f"{key}: expected a material name or a table, got {raw!r}")
    name = raw.get("name")
    if name is None:
        table = dict(raw)
    else:
        material = get_material(name, where)
        base = dict(material.values)
        overrides = {k: v for k, v in raw.items() if k != "name" and v is not None}
        if not wear and not wear_forms(overrides):
            base = {k: v for k, v in base.items() if k not in WEAR_KEYS}
        table = {"name": name, **merge_material(base, overrides)}
    check_wear_forms(table, key)
    return table


#: the overview columns of the library: key, header
OVERVIEW: tuple[tuple[str, str], ...] = (
    ("youngs_modulus", "E"),
    ("poisson_ratio", "ν"),
    ("density", "ρ"),
    ("wear_coefficient", "K_d"),
    (BOUNDARY_KEY, "K_d greased"),
    ("max_static_pressure", "p static"),
    ("max_dynamic_pressure", "p max"),
    ("max_pv", "PV max"),
    ("max_sliding_speed", "v max"),
)


def markdown() -> str:
    """The library as markdown: an overview table, then every value with its source."""

    def header(key: str, text: str) -> str:
        unit = display_unit(key)
        return f"{text} [{unit}]" if unit else text

    lines = [
        "| name | " + " | ".join(header(k, h) for k, h in OVERVIEW) + " |",
        "|---|" + "---|" * len(OVERVIEW),
    ]
    for m in library().values():
        cells = [m.display(k, unit=False) or "—" for k, _ in OVERVIEW]
        lines.append(f"| `{m.name}` | " + " | ".join(cells) + " |")
    for m in library().values():
        lines += ["", f"**`{m.name}`**: {m.description}", ""]
        for key, value in m.values.items():
            shown = f'"{value}"' if isinstance(value, str) else value
            if key == TABLE_KEY:
                lines.append(f"- `{key}`: {m.display(key)}: {m.sources[key]}")
                continue
            lines.append(f"- `{key} = {shown}`: {m.sources[key]}")
    return "\n".join(lines) + "\n"


def material_units() -> dict[str, str]:
    """SI unit of each material value (``units.DIMENSIONS`` spelling)."""
    return {key: DIMENSIONS[kind] for key, kind in KINDS.items()}
