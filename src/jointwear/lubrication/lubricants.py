"""The lubricants library: named oils and greases, their viscosity at a temperature.

The library is a data file shipped with the package (``jointwear/data/lubricants.toml``):
ISO VG 10 to 680 mineral oils and a few greases, each value with its source. A
lubricant carries two kinematic viscosities (40 and 100 degC), the density at 15 degC
with its thermal expansion, and its regime: ``"hydrodynamic"`` for oils (the film
models apply) or ``"boundary"`` for greases in slowly oscillating pin joints (no film;
the asperities carry the load).

Between and beyond the two tabulated temperatures the kinematic viscosity follows the
Walther relation of ASTM D341,

.. math:: \\log_{10}\\log_{10}(\\nu + 0.7) = A - B\\log_{10} T,

``nu`` in mm^2/s and ``T`` in kelvin, with ``A`` and ``B`` from the two tabulated
points (which it reproduces exactly). ASTM D341 states it for ``nu >= 2 mm^2/s``; below
that (thin oils well above 100 degC) it errs on the thin side. The dynamic viscosity is
``mu = nu rho(T)`` with ``rho(T) = rho_15 / (1 + alpha (T - 15 degC))``.

Sources: [1]_, [2]_, [3]_.

References
----------
.. [1] ASTM D341, Standard practice for viscosity-temperature equations and charts for
   liquid petroleum or hydrocarbon products.
.. [2] ISO 3448:1992, Industrial liquid lubricants -- ISO viscosity classification.
.. [3] ASTM D2270, Standard practice for calculating viscosity index from kinematic
   viscosity at 40 and 100 degC.
"""

from __future__ import annotations

import tomllib
from collections.abc import Mapping
from dataclasses import dataclass
from functools import cache
from importlib.resources import files
from types import MappingProxyType
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.errors import ConfigError
from jointwear.registry import suggest
from jointwear.units import to_si, to_si_unit

if TYPE_CHECKING:
    from jointwear.config import LubricationConfig

__all__ = [
    "REGIMES",
    "Lubricant",
    "density",
    "dynamic_viscosity",
    "get_lubricant",
    "kinematic_viscosity",
    "library",
    "section_viscosity",
]

FloatArray = NDArray[np.float64]

LIBRARY_FILE = "lubricants.toml"
#: the regimes a lubricant may name
REGIMES: tuple[str, ...] = ("hydrodynamic", "boundary")
#: the temperatures of the two tabulated viscosities and of the density [K]
T40 = 313.15
T100 = 373.15
T15 = 288.15
#: the constant of ASTM D341's log-log relation [mm^2/s]
WALTHER_SHIFT = 0.7
#: keys of a library entry and their SI units ("" for the regime, a word)
UNITS: dict[str, str] = {
    "kinematic_viscosity_40": "m**2/s",
    "kinematic_viscosity_100": "m**2/s",
    "density": "kg/m**3",
    "thermal_expansion": "1/K",
    "regime": "",
}


@dataclass(frozen=True)
class Lubricant:
    """One named lubricant of the library (SI values).

    Attributes
    ----------
    name : str
        Library name, e.g. ``"iso-vg-68"``.
    description : str
        What the lubricant is.
    kinematic_viscosity_40, kinematic_viscosity_100 : float
        Kinematic viscosity at 40 and 100 degC [m^2/s].
    density : float
        Density at 15 degC [kg/m^3].
    thermal_expansion : float
        Volumetric thermal expansion coefficient [1/K].
    regime : str
        ``"hydrodynamic"`` or ``"boundary"``.
    sources : mapping of str to str
        Where each value comes from, by key.
    """

    name: str
    description: str
    kinematic_viscosity_40: float
    kinematic_viscosity_100: float
    density: float
    thermal_expansion: float
    regime: str
    sources: Mapping[str, str]


def read_entry(name: str, table: Mapping[str, object]) -> Lubricant:
    """One library table as a :class:`Lubricant`; a malformed entry raises ConfigError."""
    values: dict[str, object] = {}
    sources: dict[str, str] = {}
    for key, unit in UNITS.items():
        entry = table.get(key)
        where = f"lubricants library: {name}.{key}"
        if not isinstance(entry, Mapping) or set(entry) != {"value", "source"}:
            raise ConfigError(f"{where}: expected {{ value = ..., source = ... }}")
        values[key] = entry["value"] if not unit else to_si_unit(entry["value"], unit, where)
        sources[key] = str(entry["source"])
    unknown = sorted(set(table) - set(UNITS) - {"description"})
    if unknown:
        raise ConfigError(f"lubricants library: {name}: unknown keys {unknown}")
    if values["regime"] not in REGIMES:
        raise ConfigError(f"lubricants library: {name}.regime: expected one of {REGIMES}")
    if not 0.0 < values["kinematic_viscosity_100"] < values["kinematic_viscosity_40"]:
        raise ConfigError(
            f"lubricants library: {name}: needs 0 < viscosity at 100 degC < at 40 degC"
        )
    return Lubricant(
        name=name,
        description=str(table.get("description", "")),
        kinematic_viscosity_40=float(values["kinematic_viscosity_40"]),
        kinematic_viscosity_100=float(values["kinematic_viscosity_100"]),
        density=to_si(values["density"], "density", f"lubricants library: {name}.density"),
        thermal_expansion=float(values["thermal_expansion"]),
        regime=str(values["regime"]),
        sources=MappingProxyType(sources),
    )


@cache
def library() -> MappingProxyType[str, Lubricant]:
    """The lubricants library, name -> :class:`Lubricant` (read once)."""
    text = files("jointwear").joinpath("data", LIBRARY_FILE).read_text(encoding="utf-8")
    data = tomllib.loads(text)
    return MappingProxyType({name: read_entry(name, table) for name, table in data.items()})


def get_lubricant(name: str | Lubricant, key: str = "lubricant") -> Lubricant:
    """The library lubricant ``name``; an unknown name raises with the closest name.

    Parameters
    ----------
    name : str or Lubricant
        Library name, e.g. ``"iso-vg-68"``; case, spaces and underscores do not matter
        (``"ISO VG 68"``). A :class:`Lubricant` passes through.
    key : str
        Config key named in the error message.

    Raises
    ------
    ConfigError
        For an unknown name.
    """
    if isinstance(name, Lubricant):
        return name
    lubricants = library()
    # a grade as it is printed on the can ("ISO VG 68") names the library's "iso-vg-68"
    canonical = "-".join(name.lower().replace("_", " ").split()) if isinstance(name, str) else None
    if canonical not in lubricants:
        raise ConfigError(
            f"{key}: unknown lubricant {name!r}{suggest(canonical or str(name), lubricants)}"
        )
    return lubricants[canonical]


def walther_constants(lubricant: Lubricant) -> tuple[float, float]:
    """``A`` and ``B`` of ASTM D341 through the two tabulated viscosities."""
    low = np.log10(np.log10(lubricant.kinematic_viscosity_40 * 1e6 + WALTHER_SHIFT))
    high = np.log10(np.log10(lubricant.kinematic_viscosity_100 * 1e6 + WALTHER_SHIFT))
    slope = (low - high) / (np.log10(T100) - np.log10(T40))
    return float(low + slope * np.log10(T40)), float(slope)


def kinematic_viscosity(lubricant: str | Lubricant, temperature: ArrayLike) -> FloatArray:
    """Kinematic viscosity at a temperature, ASTM D341 (Walther) [m^2/s].

    .. math:: \\nu = 10^{10^{A - B\\log_{10}T}} - 0.7 \\quad [\\mathrm{mm^2/s}]

    Parameters
    ----------
    lubricant : str or Lubricant
        Library name or entry.
    temperature : array_like
        Temperature ``T`` [K].
    """
    entry = get_lubricant(lubricant)
    a, b = walther_constants(entry)
    log_log = a - b * np.log10(np.asarray(temperature, dtype=float))
    return (10.0 ** (10.0**log_log) - WALTHER_SHIFT) * 1e-6


def density(lubricant: str | Lubricant, temperature: ArrayLike) -> FloatArray:
    """Density at a temperature, ``rho_15 / (1 + alpha (T - 15 degC))`` [kg/m^3].

    Parameters
    ----------
    lubricant : str or Lubricant
        Library name or entry.
    temperature : array_like
        Temperature ``T`` [K].
    """
    entry = get_lubricant(lubricant)
    rise = np.asarray(temperature, dtype=float) - T15
    return entry.density / (1.0 + entry.thermal_expansion * rise)


def dynamic_viscosity(lubricant: str | Lubricant, temperature: ArrayLike) -> FloatArray:
    """Dynamic viscosity ``mu = nu(T) rho(T)`` [Pa s].

    Parameters
    ----------
    lubricant : str or Lubricant
        Library name (e.g. ``"iso-vg-68"``) or entry.
    temperature : array_like
        Temperature ``T`` [K].

    Raises
    ------
    ConfigError
        For an unknown lubricant name (with the closest name).
    """
    return kinematic_viscosity(lubricant, temperature) * density(lubricant, temperature)


def section_viscosity(section: LubricationConfig) -> float:
    """The dynamic viscosity a ``[lubrication]`` section names [Pa s].

    ``viscosity`` where given, else the ``lubricant``'s at the section's temperature
    (:func:`dynamic_viscosity`, ASTM D341; 40 degC if no temperature is given): the one
    value both the load cycle's film (:mod:`jointwear.contact.lubricated`) and the
    contact–impact dynamics' film (:func:`jointwear.mechanism.stage.film_parameters`)
    run with.

    Parameters
    ----------
    section : jointwear.config.LubricationConfig
        The validated section (SI), a film model chosen.
    """
    if section.viscosity is not None:
        return float(section.viscosity)
    return float(dynamic_viscosity(section.lubricant, section.oil_temperature))
