"""Quantities read into SI at the boundary: units accepted, wrong ones refused with the key."""

from __future__ import annotations

import math

import pytest

from jointwear.errors import ConfigError
from jointwear.units import to_si


@pytest.mark.parametrize(
    ("text", "kind", "expected"),
    [
        ("0.2 mm", "length", 2e-4),
        ("7.45 mm", "length", 7.45e-3),
        ("20 um", "length", 2e-5),
        ("240 rpm", "angular_velocity", 8 * math.pi),
        ("120 rpm", "angular_velocity", 4 * math.pi),
        ("2 Hz", "angular_velocity", 4 * math.pi),  # two turns a second
        ("5.05e-13 m^2/N", "wear_coefficient", 5.05e-13),
        ("5.05e-13 mm^2/N", "wear_coefficient", 5.05e-19),
        ("209 GPa", "pressure", 2.09e11),
        ("500 MPa", "pressure", 5e8),
        ("200 N", "force", 200.0),
        ("0.2 kN", "force", 200.0),
        ("90 deg", "angle", math.pi / 2),
        ("2200 kg/m^3", "density", 2200.0),
        ("460 g", "mass", 0.46),
        (0.28, "dimensionless", 0.28),
        (3, "length", 3.0),
    ],
)
def test_units_accepted(text, kind, expected):
    assert to_si(text, kind) == pytest.approx(expected, rel=1e-12, abs=0)


@pytest.mark.parametrize(
    ("text", "kind", "needle"),
    [
        ("5 kg", "length", "expected a length"),
        ("5.05e-13 m^2", "wear_coefficient", "expected a wear coefficient"),
        ("240 rpm", "length", "expected a length"),
        ("nan mm", "length", "finite"),
        ("inf", "length", "finite"),
        (float("nan"), "force", "finite"),
        ("12 furlongs/s^3", "force", "expected a force"),
        ("12 blorps", "force", "cannot read"),
        ("", "length", "key"),
        (True, "length", "boolean"),
        ([1.0], "length", "expected a number"),
    ],
)
def test_units_rejected_with_the_key(text, kind, needle):
    with pytest.raises(ConfigError) as info:
        to_si(text, kind, "key")
    message = str(info.value)
    assert message.startswith("key:")
    assert needle in message
