"""A duty cycle's modes by dotted key: ``mechanism.modes.N.KEY`` in ``--set`` and lookups."""

from __future__ import annotations

import math

import pytest
from pydantic.fields import FieldInfo

from jointwear.config import config_from_dict, field_kind, key_field, load_config
from jointwear.errors import ConfigError

CRANK = {"type": "slider-crank", "crank_speed": "90 rpm", "share": 0.4}
SWING = {
    "type": "oscillating",
    "load": "2 kN",
    "amplitude": "25 deg",
    "frequency": "0.5 Hz",
    "share": 0.6,
}


@pytest.fixture(scope="module")
def duty():
    return config_from_dict({"mechanism": {"type": "duty-cycle", "modes": [CRANK, SWING]}})


def test_a_mode_key_is_the_field_of_its_type() -> None:
    """The unit of a mode's key is that of the same key of a single mechanism."""
    speed = key_field("mechanism.modes.0.crank_speed")
    assert isinstance(speed, FieldInfo)
    assert field_kind(speed) == field_kind(key_field("mechanism.crank_speed"))
    assert field_kind(key_field("mechanism.modes.1.frequency", mode="oscillating")) is not None
    assert field_kind(key_field("mechanism.modes.3.share")) is None  # the schema has no count


def test_a_mode_speed_set_with_units_changes_that_mode_only(duty) -> None:
    changed = duty.replace(["mechanism.modes.0.crank_speed=120 rpm"])
    assert changed.mechanism.modes[0].crank_speed == pytest.approx(4 * math.pi, rel=1e-12)
    assert changed.mechanism.modes[1] == duty.mechanism.modes[1]
    before, after = duty.mechanism.modes[0].model_dump(), changed.mechanism.modes[0].model_dump()
    assert {key for key in before if before[key] != after[key]} == {"crank_speed"}


def test_both_shares_set_together_are_taken(duty) -> None:
    changed = duty.replace({"mechanism.modes.0.share": 0.25, "mechanism.modes.1.share": 0.75})
    assert [mode.share for mode in changed.mechanism.modes] == [0.25, 0.75]


def test_a_whole_mode_can_be_replaced(duty) -> None:
    changed = duty.replace({"mechanism.modes.1": {**SWING, "load": "3 kN"}})
    assert changed.mechanism.modes[1].load == pytest.approx(3000.0)
    assert changed.mechanism.modes[0] == duty.mechanism.modes[0]


@pytest.mark.parametrize(
    ("override", "message"),
    [
        ("mechanism.modes.2.share=0.1", r"^mechanism\.modes\.2\.share: no mode 2; .* has 2 modes"),
        ("mechanism.modes.-1.share=0.1", r"^mechanism\.modes\.-1\.share: '-1' is not a mode's"),
        ("mechanism.modes.one.share=0.1", r"^mechanism\.modes\.one\.share: 'one' is not a mode's"),
        (
            "mechanism.modes.1.frequncy=1 Hz",
            r"^mechanism\.modes\.1\.frequncy: unknown key; did you mean 'frequency'",
        ),
        (
            "mechanism.modes.0.share=0.5",
            r"^mechanism\.modes\.share: .*sum to 1\.1, not 1 .*: 0\.5 \+ 0\.6;",
        ),
        ("mechanism.modes.0.crank_speed=3 m", r"^mechanism\.modes\.0\.crank_speed: "),
    ],
)
def test_a_bad_mode_key_is_refused_naming_it(duty, override, message) -> None:
    with pytest.raises(ConfigError, match=message):
        duty.replace([override])


def test_a_bare_number_slip_in_a_mode_is_refused() -> None:
    """As for a single mechanism's key: 35 is read as 35 rad, more than a turn."""
    modes = (
        'mechanism.modes=[{type = "slider-crank", share = 0.4}, {type = "oscillating", '
        'load = "2 kN", amplitude = "25 deg", frequency = "0.5 Hz", share = 0.6}]'
    )
    with pytest.raises(ConfigError, match=r"^mechanism\.modes\.1\.amplitude: 35 is read as 35 rad"):
        load_config(None, ["mechanism.type=duty-cycle", modes, "mechanism.modes.1.amplitude=35"])


def test_a_mode_number_without_modes_is_refused() -> None:
    with pytest.raises(
        ConfigError, match=r"^mechanism\.modes\.0\.share: .*no \[\[mechanism\.modes"
    ):
        config_from_dict({}).replace(["mechanism.modes.0.share=1"])


def test_an_unknown_key_of_a_mode_suggests_from_every_mode_type() -> None:
    with pytest.raises(ConfigError, match=r"unknown key 'crank_sped' .*did you mean 'crank_speed'"):
        key_field("mechanism.modes.0.crank_sped")
