"""TOML: a written config reads back as the same config; bad files are named."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, reject, settings
from hypothesis import strategies as st

from jointwear.config import Config, config_from_dict, load_config
from jointwear.errors import ConfigError


def test_to_toml_round_trip(paper_config_path):
    cfg = load_config(paper_config_path, ["mechanism.crank_speed=240 rpm", "contact.nodes=720"])
    text = cfg.to_toml()
    data = tomllib.loads(text)
    again = config_from_dict(data, defaults=False)
    assert again.to_dict() == cfg.to_dict()
    assert again.to_toml() == text  # a fixed point
    assert again.mechanism.crank_speed == cfg.mechanism.crank_speed  # exact float repr
    assert again.spring_area == cfg.spring_area
    assert again.mechanism.rod_centroidal_inertia == cfg.mechanism.rod_centroidal_inertia


EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


SHARED_OVERRIDES = {
    "joint.clearance": st.floats(1e-6, 1e-3).map(lambda v: f"{v!r} m"),
    "joint.pin_radius": st.floats(2e-3, 5e-2),
    "materials.pin.poisson_ratio": st.floats(-0.99, 0.49),
    "materials.bushing.wear_coefficient": st.floats(1e-18, 1e-10),
    "contact.nodes": st.integers(16, 2000),
    "simulation.revolutions": st.integers(1, 10**9),
    "simulation.update_every": st.sampled_from([1, 7, "adaptive"]),
}


#: values past a turn are written with their unit (``"6.98 rad"``): drawn on both sides
MECHANISMS = {
    "slider-crank": (
        EXAMPLES / "paper" / "table3_winkler_120rpm.toml",
        {"mechanism.crank_speed": st.floats(1.0, 5e4).map(lambda v: f"{v!r} rpm")},
    ),
    "four-bar": (
        EXAMPLES / "four_bar.toml",
        {
            "mechanism.rocker_spring_angle": st.floats(-2000.0, 2000.0).map(lambda v: f"{v!r} deg"),
            "mechanism.clearance_joint": st.sampled_from(
                [["crank-coupler"], ["rocker-ground", "coupler-rocker"]]
            ),
        },
    ),
    "oscillating": (EXAMPLES / "oscillating_liner.toml", {}),
}


@st.composite
def configs(draw: st.DrawFn) -> Config:
    """A config from an example of each mechanism (or a load history under an arbitrary
    file name), with some of its values overridden."""
    kind = draw(st.sampled_from([*MECHANISMS, "load-history"]))
    if kind == "load-history":
        path = None
        name = draw(
            st.text(
                st.characters(blacklist_categories=("Cs",), blacklist_characters="\x00/"),
                min_size=1,
                max_size=12,
            ).filter(lambda text: text not in {".", ".."})
        )
        overrides: dict[str, object] = {"mechanism.type": kind, "mechanism.file": name}
        choices = SHARED_OVERRIDES
    else:
        path, specific = MECHANISMS[kind]
        overrides = {}
        choices = {**SHARED_OVERRIDES, **specific}
    keys = draw(st.lists(st.sampled_from(sorted(choices)), unique=True, max_size=4))
    overrides.update({key: draw(choices[key]) for key in keys})
    try:
        return load_config(path, overrides)
    except ConfigError:  # a combination the config refuses (e.g. clearance past the pin)
        reject()


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(config=configs())
def test_to_toml_reads_back_as_the_same_config(config: Config, tmp_path_factory):
    """The written config, with the header a run puts above it, loads as the same config,
    and writing that again gives the same text."""
    text = config.to_toml()
    path = tmp_path_factory.mktemp("config") / "config.toml"
    path.write_text("# fully resolved configuration, SI units\n" + text, encoding="utf-8")
    again = config_from_dict(tomllib.loads(path.read_text(encoding="utf-8")), defaults=False)
    assert again.to_dict() == config.to_dict()
    assert again.to_toml() == text
    assert load_config(path).to_dict() == config.to_dict()


def test_angles_past_a_turn_are_written_with_their_unit():
    config = load_config(EXAMPLES / "four_bar.toml", {"mechanism.rocker_spring_angle": "400 deg"})
    written = tomllib.loads(config.to_toml())["mechanism"]["rocker_spring_angle"]
    assert written == f"{math.radians(400)!r} rad"


def test_missing_and_invalid_files(tmp_path):
    with pytest.raises(ConfigError, match="file not found"):
        load_config(tmp_path / "missing.toml")
    bad = tmp_path / "bad.toml"
    bad.write_text("joint = [")
    with pytest.raises(ConfigError, match="not valid TOML"):
        load_config(bad)
