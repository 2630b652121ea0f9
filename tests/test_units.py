"""Units at the boundary: the 2π between turns and radians, and bare numbers that are unit slips.

pint takes the radian for dimensionless, so on its own it converts "30 rpm" to 3.14 Hz and
"5 Hz" to 5 rad/s. jointwear counts radians in a unit with an angle (rpm, rad/s, deg/s,
rev/s) and turns in one without (Hz, 1/s, 1/min). Every config key of kind angular
velocity or frequency is found from the config model, so a new key is covered here.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st
from pydantic import BaseModel
from pydantic.fields import FieldInfo

from jointwear.cli import main
from jointwear.config import MECHANISM_TYPES, Config, check_bare_numbers, field_kind, load_config
from jointwear.errors import ConfigError
from jointwear.units import BARE_LIMITS, DIMENSIONS, format_quantity, to_angle, to_si

REPO = Path(__file__).resolve().parents[1]
#: a config of each mechanism type, to set its keys in
EXAMPLES = {
    "slider-crank": REPO / "examples" / "paper" / "table3_winkler_120rpm.toml",
    "four-bar": REPO / "examples" / "four_bar.toml",
    "oscillating": REPO / "examples" / "oscillating_liner.toml",
    "load-history": REPO / "examples" / "load_history" / "load_history.toml",
}
RATES = ("angular_velocity", "frequency")
TURN = 2 * math.pi


def keys_of_kind(*kinds: str) -> list[tuple[str, str, str]]:
    """(mechanism type, dotted key, kind) of every config key of ``kinds``."""
    found: list[tuple[str, str, str]] = []

    def walk(model: type[BaseModel], prefix: str, mechanism: str) -> None:
        for name, info in model.model_fields.items():
            annotation = info.annotation
            if isinstance(annotation, type) and issubclass(annotation, BaseModel):
                walk(annotation, f"{prefix}{name}.", mechanism)
            elif field_kind(info) in kinds:
                found.append((mechanism, f"{prefix}{name}", field_kind(info)))

    for mechanism, model in MECHANISM_TYPES.items():
        walk(model, "mechanism.", mechanism)
    sections = {n: i for n, i in Config.model_fields.items() if n != "mechanism"}
    for name, info in sections.items():
        if isinstance(info.annotation, type) and issubclass(info.annotation, BaseModel):
            walk(info.annotation, f"{name}.", "slider-crank")
        elif field_kind(info) in kinds:
            found.append(("slider-crank", name, field_kind(info)))
    return found


RATE_KEYS = keys_of_kind(*RATES)


def value_of(config: Config, dotted: str) -> float:
    node = config
    for part in dotted.split("."):
        node = getattr(node, part)
    return node


# ---------------------------------------------------------------- the 2π rule
def test_the_rate_keys_are_found() -> None:
    """The enumeration sees the keys it must (and so would see a new one)."""
    keys = {(m, k) for m, k, _ in RATE_KEYS}
    assert {
        ("slider-crank", "mechanism.crank_speed"),
        ("four-bar", "mechanism.crank_speed"),
        ("oscillating", "mechanism.frequency"),
    } <= keys
    assert {m for m, _, _ in RATE_KEYS} <= set(EXAMPLES)


# one speed, written in every unit: 2 turns a second
TWO_TURNS_A_SECOND = [
    "120 rpm",
    "2 Hz",
    "2 1/s",
    "120 1/min",
    "2 rev/s",
    "2 turn/s",
    "720 deg/s",
    f"{2 * TURN!r} rad/s",
    "0.002 kHz",
    "7200 rev/h",
]


@pytest.mark.parametrize(
    ("mechanism", "key", "kind"), RATE_KEYS, ids=[f"{m}:{k}" for m, k, _ in RATE_KEYS]
)
@pytest.mark.parametrize("text", TWO_TURNS_A_SECOND)
def test_every_rate_key_reads_two_turns_a_second_in_any_unit(
    mechanism: str, key: str, kind: str, text: str
) -> None:
    config = load_config(EXAMPLES[mechanism], {key: text})
    expected = 2 * TURN if kind == "angular_velocity" else 2.0  # rad/s, Hz
    assert value_of(config, key) == pytest.approx(expected, rel=1e-14, abs=0)


@pytest.mark.parametrize(
    ("mechanism", "key", "kind"), RATE_KEYS, ids=[f"{m}:{k}" for m, k, _ in RATE_KEYS]
)
def test_every_rate_key_both_ways(mechanism: str, key: str, kind: str) -> None:
    """30 rpm is 0.5 Hz, 5 Hz is 300 rpm = 10π rad/s, 10 rad/s is 10/(2π) Hz."""
    read = {
        t: value_of(load_config(EXAMPLES[mechanism], {key: t}), key)
        for t in ("30 rpm", "5 Hz", "10 rad/s")
    }
    if kind == "angular_velocity":  # rad/s
        expected = {"30 rpm": math.pi, "5 Hz": 10 * math.pi, "10 rad/s": 10.0}
    else:  # Hz
        expected = {"30 rpm": 0.5, "5 Hz": 5.0, "10 rad/s": 10 / TURN}
    assert read == pytest.approx(expected, rel=1e-14, abs=0)


def dynamics_period(config: Path, override: str, capsys: pytest.CaptureFixture[str]) -> float:
    main(["dynamics", str(config), "--json", "--set", override])
    return json.loads(capsys.readouterr().out)["period_s"]


@pytest.mark.parametrize(
    ("mechanism", "key"),
    [(m, k) for m, k, _ in RATE_KEYS if k.startswith("mechanism.")],
    ids=[f"{m}:{k}" for m, k, _ in RATE_KEYS if k.startswith("mechanism.")],
)
@pytest.mark.parametrize(
    ("text", "period"),
    [
        ("30 rpm", 2.0),
        ("0.5 Hz", 2.0),
        ("5 Hz", 0.2),
        ("300 rpm", 0.2),
        ("10 rad/s", TURN / 10),
        ("1800 deg/s", 0.2),
        ("5 rev/s", 0.2),
        ("30 1/min", 2.0),
    ],
)
def test_dynamics_period_of_every_rate_key(
    mechanism: str, key: str, text: str, period: float, capsys: pytest.CaptureFixture[str]
) -> None:
    """One cycle (a crank revolution, an oscillation) lasts one turn at the given rate."""
    read = dynamics_period(EXAMPLES[mechanism], f"{key}={text}", capsys)
    assert read == pytest.approx(period, rel=1e-12, abs=0)


def test_paper_speeds_are_unchanged() -> None:
    """The paper's "120 rpm" and "240 rpm" read as before: 4π and 8π rad/s exactly."""
    for rpm, expected in ((120, 4 * math.pi), (240, 8 * math.pi)):
        assert to_si(f"{rpm} rpm", "angular_velocity") == expected
    assert to_si("0.25 Hz", "frequency") == 0.25  # the oscillating example


UNITS_PER_TURN_A_SECOND = {  # how many of the unit one turn a second is
    "rpm": 60.0,
    "Hz": 1.0,
    "rad/s": TURN,
    "rev/s": 1.0,
    "deg/s": 360.0,
    "1/min": 60.0,
    "turn/min": 60.0,
    "1/s": 1.0,
}
positive = st.floats(min_value=1e-6, max_value=1e6, allow_nan=False, allow_infinity=False)


@given(positive, st.sampled_from(sorted(UNITS_PER_TURN_A_SECOND)))
def test_rate_in_any_unit_is_its_turns_a_second(number: float, unit: str) -> None:
    turns = number / UNITS_PER_TURN_A_SECOND[unit]
    assert to_si(f"{number!r} {unit}", "frequency") == pytest.approx(turns, rel=1e-13, abs=0)
    assert to_si(f"{number!r} {unit}", "angular_velocity") == pytest.approx(
        TURN * turns, rel=1e-13, abs=0
    )


@given(
    positive,
    st.sampled_from(sorted(UNITS_PER_TURN_A_SECOND)),
    st.sampled_from(sorted(UNITS_PER_TURN_A_SECOND)),
)
def test_rate_round_trips_between_the_kinds_and_units(number: float, unit: str, other: str) -> None:
    """A speed read as an angular velocity, written in another unit and read as a
    frequency is its turns a second; written back in the first unit, the number given."""
    omega = to_si(f"{number!r} {unit}", "angular_velocity")
    text = f"{omega / TURN * UNITS_PER_TURN_A_SECOND[other]!r} {other}"
    frequency = to_si(text, "frequency")
    assert frequency == pytest.approx(omega / TURN, rel=1e-13, abs=0)
    assert to_si(text, "angular_velocity") == pytest.approx(omega, rel=1e-13, abs=0)
    assert frequency * UNITS_PER_TURN_A_SECOND[unit] == pytest.approx(number, rel=1e-13, abs=0)


def test_display_units_follow_the_rule() -> None:
    assert format_quantity(4 * math.pi, "rpm") == "120 rpm"
    assert format_quantity(0.5, "1/min") == "30 1/min"
    assert format_quantity(0.5, "Hz") == "0.5 Hz"  # a frequency, not 0.5 rad/s shown in Hz


def test_a_rate_of_a_squared_angle_is_refused() -> None:
    with pytest.raises(ConfigError, match=r"^f: '2 sr/s' is not a rate of turns or of an angle"):
        to_si("2 sr/s", "frequency", "f")


# ---------------------------------------------------------------- bare numbers
BARE_KEYS = keys_of_kind(*BARE_LIMITS)


def test_bare_limits_cover_the_kinds_whose_unit_is_not_obvious() -> None:
    kinds = {kind for _, _, kind in BARE_KEYS}
    assert kinds == {"angle", "length", "angular_velocity", "frequency", "velocity"}


@pytest.mark.parametrize(
    ("mechanism", "key", "kind"), BARE_KEYS, ids=[f"{m}:{k}" for m, k, _ in BARE_KEYS]
)
def test_a_bare_number_beyond_its_keys_limit_is_refused_with_the_si_reading(
    mechanism: str, key: str, kind: str
) -> None:
    limit = 10.0 if key.startswith("mechanism.") and kind == "length" else BARE_LIMITS[kind][0]
    unit, hint = DIMENSIONS[kind], BARE_LIMITS[kind][1]
    number = round(limit * 1.5 + 1)
    data = {"mechanism": {"type": mechanism}}
    section, _, name = key.rpartition(".")
    node = data
    for part in section.split("."):
        node = node.setdefault(part, {})
    node[name] = number
    with pytest.raises(ConfigError) as info:
        check_bare_numbers(data)
    assert str(info.value) == (
        f"{key}: {number} is read as {number} {unit} (a bare number is SI), more than "
        f'{limit:.4g} {unit}; give a unit, e.g. "{number} {hint}"'
    )
    # the same number with its unit, or a bare number within the limit, passes
    node[name] = f"{number} {unit}"
    check_bare_numbers(data)
    node[name] = limit
    check_bare_numbers(data)


@pytest.mark.parametrize(
    ("override", "message"),
    [
        (
            "mechanism.amplitude=35",
            "mechanism.amplitude: 35 is read as 35 rad (a bare number is "
            'SI), more than 6.283 rad; give a unit, e.g. "35 deg"',
        ),
        ('mechanism.amplitude="35"', 'e.g. "35 deg"'),
        ("mechanism.frequency=120", "mechanism.frequency: 120 is read as 120 Hz"),
        ("joint.pin_radius=7.45", "joint.pin_radius: 7.45 is read as 7.45 m"),
    ],
)
def test_config_file_and_set_refuse_a_unit_slip(override: str, message: str) -> None:
    with pytest.raises(ConfigError) as info:
        load_config(EXAMPLES["oscillating"], [override])
    assert message in str(info.value)


def test_bare_si_numbers_within_the_limits_are_read_as_si() -> None:
    """The paper's calibrated bare floats and a bare angle within a turn are SI."""
    config = load_config(
        EXAMPLES["oscillating"], ["mechanism.amplitude=0.5", "joint.axial_length=0.0186"]
    )
    assert config.mechanism.amplitude == 0.5
    assert config.joint.axial_length == 0.0186


def test_the_api_bound_message_says_how_a_bare_number_was_read() -> None:
    config = load_config(EXAMPLES["oscillating"])
    with pytest.raises(ConfigError) as info:
        config.replace({"mechanism.amplitude": 35})
    assert str(info.value) == (
        "mechanism.amplitude: Input should be less than or equal to 12.566370614359172 rad; "
        '35 is read as 35 rad (a bare number is SI), give a unit, e.g. "35 deg"'
    )
    with pytest.raises(ConfigError) as info:
        config.replace({"mechanism.load_phase": -35})
    assert str(info.value).endswith(
        '-35 is read as -35 rad (a bare number is SI), give a unit, e.g. "-35 deg"'
    )
    with pytest.raises(ConfigError) as info:  # below 0: no unit mends it
        config.replace({"joint.clearance": -1e-4})
    assert str(info.value) == (
        "joint.clearance: Input should be greater than 0 m; -0.0001 is read as -0.0001 m "
        "(a bare number is SI)"
    )
    with pytest.raises(ConfigError) as info:
        config.replace({"mechanism.amplitude": "1000 deg"})
    assert str(info.value).endswith("rad, got '1000 deg' = 17.4533 rad")


@pytest.mark.parametrize(
    ("mechanism", "overrides"),
    [
        (
            "oscillating",
            {
                "mechanism.amplitude": "400 deg",
                "mechanism.load_angle": "-450 deg",
                "mechanism.frequency": "20000 rpm",
                "joint.axial_length": "1.5 m",
            },
        ),
        (
            "four-bar",
            {
                "mechanism.crank_speed": "20000 rpm",
                "mechanism.rocker_spring_angle": "500 deg",
                "materials.bushing.max_sliding_speed": "150 m/s",
            },
        ),
    ],
)
def test_values_beyond_the_bare_limits_read_back_from_to_toml(
    mechanism: str, overrides: dict[str, str], tmp_path: Path
) -> None:
    """A saved config (run --out) re-runs: values a bare number would be refused for are
    written with their SI unit, and read back exactly."""
    config = load_config(EXAMPLES[mechanism], overrides)
    path = tmp_path / "config.toml"
    path.write_text(config.to_toml(), encoding="utf-8")
    again = load_config(path)
    for key in overrides:
        assert value_of(again, key) == value_of(config, key)


@pytest.mark.parametrize(
    ("value", "message"),
    [
        (
            90,
            "--azimuth: 90 is read as 90 rad (a bare number is SI), more than 6.283 rad; "
            'give a unit, e.g. "90 deg"',
        ),
        ("-400", 'e.g. "-400 deg"'),
    ],
)
def test_a_bare_direction_angle_beyond_a_turn_is_refused(value: object, message: str) -> None:
    with pytest.raises(ConfigError) as info:
        to_angle(value, "--azimuth")
    assert message in str(info.value)
    assert to_angle(-3, "--azimuth") == -3.0
    assert to_angle("400 deg", "--azimuth") == pytest.approx(math.radians(400))


def test_field_kind_reads_every_unit_bearing_field() -> None:
    info = Config.model_fields["joint"].annotation.model_fields["pin_radius"]
    assert isinstance(info, FieldInfo)
    assert field_kind(info) == "length"
    assert field_kind(Config.model_fields["parameter_set"]) is None
