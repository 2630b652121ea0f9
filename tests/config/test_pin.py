"""Along the pin: the [joint] keys and the [pin] section, their defaults and the
combinations refused."""

from __future__ import annotations

import math

import pytest

from jointwear.config import load_config
from jointwear.errors import ConfigError


def test_the_defaults_are_the_planar_joint_and_are_written_back():
    config = load_config()
    joint, pin = config.joint, config.pin
    assert (joint.axial_slices, joint.misalignment, joint.load_offset) == (1, 0.0, 0.0)
    assert joint.misalignment_angle is None
    assert pin.model == "rigid"
    again = load_config(overrides={"joint.axial_slices": 7, "joint.misalignment": "0.05 deg"})
    text = again.to_toml()
    assert "axial_slices = 7" in text
    assert again.joint.misalignment == pytest.approx(math.radians(0.05), rel=1e-15, abs=0)


def test_quantities_are_read_in_si():
    config = load_config(
        overrides={
            "joint.axial_slices": 10,
            "joint.load_offset": "-2 mm",
            "joint.misalignment": "1 mrad",
            "joint.misalignment_angle": "90 deg",
            "pin": {"model": "beam", "forks": ["-15 mm", "15 mm"], "fit_clearance": "5 um"},
        }
    )
    assert config.joint.load_offset == pytest.approx(-2e-3)
    assert config.joint.misalignment_angle == pytest.approx(math.pi / 2)
    assert config.pin.forks == pytest.approx((-0.015, 0.015))
    assert config.pin.fit_clearance == pytest.approx(5e-6)


#: several slices, a bending pin in a clevis
SLICES = {"joint.axial_slices": 3}
BEAM = {**SLICES, "pin.model": "beam"}
FORKS = {"pin.forks": [-0.01, 0.01]}

REFUSED = [
    ({"joint.misalignment": "0.1 deg"}, "joint.misalignment: an imposed tilt needs"),
    ({"joint.load_offset": "1 mm"}, "joint.load_offset: a load off the mid-plane needs"),
    ({"pin.model": "beam", **FORKS}, 'pin.model: a bending pin ("beam") needs'),
    ({**SLICES, "joint.misalignment_angle": "10 deg"}, "joint.misalignment_angle: gives"),
    ({**SLICES, "joint.load_offset": "11 mm"}, "joint.load_offset: 0.011 m is outside"),
    (BEAM, "pin.forks: a clevis pin needs the axial positions of its two forks"),
    ({**BEAM, "pin.support": "cantilever"}, "pin.clamp: a cantilever pin needs"),
    ({**BEAM, "pin.forks": [0.01, -0.01]}, "pin.forks: the fork positions must increase"),
    ({**SLICES, **FORKS}, 'pin.forks: only a bending pin (pin.model = "beam")'),
    ({**BEAM, **FORKS, "pin.clamp": 0.0}, "pin.clamp: a clevis pin has no clamp"),
    ({**SLICES, "contact.model": "hertz"}, "contact.model: 'hertz' solves a whole"),
    ({**SLICES, "contact.balance": "equilibrium"}, "contact.balance: axial slices balance"),
    (
        {**SLICES, "lubrication.model": "short-bearing", "lubrication.viscosity": "0.1 Pa*s"},
        "lubrication.model: a film ('short-bearing') is solved for the whole bearing",
    ),
    ({"joint.axial_slices": 0}, "joint.axial_slices"),
]


@pytest.mark.parametrize(("overrides", "message"), REFUSED)
def test_contradictions_are_refused_in_one_line(overrides, message):
    with pytest.raises(ConfigError) as refused:
        load_config(overrides=overrides)
    text = str(refused.value)
    assert message in text
    assert "\n" not in text


def test_an_unknown_pin_model_is_refused_with_the_closest_name():
    with pytest.raises(ConfigError, match="pin.model") as refused:
        load_config(overrides={"joint.axial_slices": 3, "pin.model": "beem"})
    assert "beam" in str(refused.value)
