"""Named parameter sets: plain data, the SI unit in every key name (PyBaMM style).

A parameter set supplies the defaults of a configuration; a config file names
one with ``parameter_set = "..."`` and overrides any key.

Mechanism keys are keyed by mechanism type (``mechanism[slider-crank].crank_length``):
a set supplies the mechanism defaults of the types it knows, and its joint and
material values to every type.

``nlcp-paper`` holds the slider-crank and joint of the NLCP paper (Tables 1-2),
read in SI (the paper prints g and mm where kg and m reproduce its results, see
``docs/reproduction.md``). The paper does not give the joint's axial length, the
bushing wall thickness, the spring preload or the PTFE density; the values here
are placeholders of the right size (the reproduction calibrates them on one
table row).

A set holds values, not model choices: ``nlcp-paper`` is the default set of every
config, so a ``contact.model`` or ``contact.foundation_modulus`` named here would be
every joint's default. The paper's configs (``jointwear.paper`` / ``examples/paper``)
name the paper's model and ``foundation_modulus = "youngs"`` themselves.
"""

from __future__ import annotations

from types import MappingProxyType
from typing import Any

from jointwear.errors import ConfigError
from jointwear.registry import suggest

__all__ = ["PARAMETER_SETS", "get_parameter_set"]

NLCP_PAPER: dict[str, Any] = {
    # Table 1 (printed in g and mm; SI magnitudes reproduce the paper)
    "mechanism[slider-crank].crank_length [m]": 0.07,
    "mechanism[slider-crank].rod_length [m]": 0.2,
    "mechanism[slider-crank].crank_mass [kg]": 0.46,
    "mechanism[slider-crank].rod_mass [kg]": 1.09,
    "mechanism[slider-crank].slider_mass [kg]": 5.0,
    "mechanism[slider-crank].spring_stiffness [N/m]": 1800.0,
    # not in the paper: calibrated / assumed
    "mechanism[slider-crank].spring_preload [N]": 20.0,
    "mechanism[slider-crank].spring_mode": "pull",
    "mechanism[slider-crank].gravity [m/s**2]": 9.81,
    "mechanism[slider-crank].crank_speed [rad/s]": 4.0 * 3.141592653589793,  # 120 rpm
    # Table 2
    "joint.pin_radius [m]": 7.45e-3,
    "joint.clearance [m]": 0.05e-3,
    # not in the paper: calibrated
    "joint.axial_length [m]": 20e-3,
    "joint.bushing_thickness [m]": 2.5e-3,
    "materials.pin.youngs_modulus [Pa]": 2.09e11,
    "materials.pin.poisson_ratio [1]": 0.28,
    "materials.bushing.youngs_modulus [Pa]": 5.0e8,
    "materials.bushing.poisson_ratio [1]": 0.38,
    "materials.bushing.density [kg/m**3]": 2200.0,
    "materials.bushing.wear_coefficient [1/Pa]": 5.05e-13,
}

PARAMETER_SETS: MappingProxyType[str, dict[str, Any]] = MappingProxyType({"nlcp-paper": NLCP_PAPER})


def get_parameter_set(name: str, mechanism: str = "slider-crank") -> dict[str, Any]:
    """Return a parameter set as a nested dict of SI values (unit stripped from keys).

    Parameters
    ----------
    name : str
        Name of the set, e.g. ``"nlcp-paper"``.
    mechanism : str
        Mechanism type whose ``mechanism[type].*`` defaults are taken; those of other
        types are left out.
    """
    if name not in PARAMETER_SETS:
        raise ConfigError(
            f"parameter_set: unknown parameter set {name!r}{suggest(name, PARAMETER_SETS)}"
        )
    nested: dict[str, Any] = {}
    for flat_key, value in PARAMETER_SETS[name].items():
        path = flat_key.split(" [")[0].split(".")
        if path[0].startswith("mechanism["):
            if path[0] != f"mechanism[{mechanism}]":
                continue
            path[0] = "mechanism"
        node = nested
        for part in path[:-1]:
            node = node.setdefault(part, {})
        node[path[-1]] = value
    return nested
