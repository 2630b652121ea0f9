"""The sections: the paper's config in SI, open bounds, defaults, K's unit by the exponent."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import pytest

from jointwear.config import load_config
from jointwear.errors import ConfigError


def test_paper_config_in_si(paper_config):
    assert paper_config.mechanism.crank_speed == pytest.approx(4 * math.pi, rel=1e-15, abs=0)
    assert paper_config.mechanism.crank_length == pytest.approx(0.07)
    assert paper_config.joint.pin_radius == pytest.approx(7.45e-3)
    assert paper_config.joint.clearance == pytest.approx(5e-5)
    assert paper_config.bushing_radius == pytest.approx(7.5e-3)
    assert paper_config.materials.pin.youngs_modulus == pytest.approx(2.09e11)
    assert paper_config.materials.bushing.wear_coefficient == pytest.approx(
        5.05e-13, rel=1e-6, abs=0
    )
    assert paper_config.contact.model == "asymmetric-winkler"
    assert paper_config.spring_area == pytest.approx(7.5e-3 * math.pi / 180 * 20e-3)


def test_poisson_ratio_limits_are_open(paper_config_path):
    for value in (-0.99, 0.0, 0.49):
        cfg = load_config(paper_config_path, [f"materials.bushing.poisson_ratio={value}"])
        assert cfg.materials.bushing.poisson_ratio == value


def test_nlcp_stiffness_units_follow_the_exponent(paper_config_path):
    # K has the unit N/m^n: a unit string is checked against the configured exponent
    cfg = load_config(paper_config_path, ['contact.stiffness="2e4 N/mm**1.5"'])
    assert cfg.contact.stiffness == pytest.approx(2e4 * 1e3**1.5, rel=1e-12)
    linear = load_config(paper_config_path, ["contact.exponent=1", 'contact.stiffness="3 N/mm"'])
    assert linear.contact.stiffness == pytest.approx(3e3, rel=1e-12)
    with pytest.raises(ConfigError, match=r"^contact.stiffness: .* N/m\*\*1.5"):
        load_config(paper_config_path, ['contact.stiffness="3 N/mm"'])
    # the default is eq. (2), written into the resolved config
    default = load_config(paper_config_path)
    assert default.contact.stiffness is None
    assert default.to_dict()["contact"]["stiffness"] == pytest.approx(6.708e7, rel=1e-3)


def test_the_default_contact_model_balances_the_real_contour():
    """A joint of one's own gets Winkler's springs on the real (worn) contour, with the
    thin-layer modulus of a wall bonded in its housing; the paper's configs name the
    paper's reading (E_w = E) themselves."""

    contact = load_config().contact
    assert (contact.model, contact.foundation_modulus) == ("asymmetric-winkler", "constrained")
    paper = sorted((Path(__file__).resolve().parents[2] / "examples" / "paper").glob("*.toml"))
    assert len(paper) == 15
    for path in paper:
        text = tomllib.loads(path.read_text(encoding="utf-8"))["contact"]
        assert text["model"] in ("asymmetric-winkler", "nlcp"), path.name
        assert text["foundation_modulus"] == "youngs", path.name


# ---------------------------------------------------------------- [lubrication]
def test_lubrication_is_dry_by_default():
    assert load_config().lubrication.model == "dry"
    assert not load_config().lubrication.lubricated


def test_cavitation_is_half_sommerfeld_unless_reynolds_is_asked_for():
    assert load_config().lubrication.cavitation == "half-Sommerfeld"
    config = load_config(
        overrides=[
            "lubrication.model=finite-length",
            "lubrication.viscosity=0.1 Pa*s",
            "lubrication.cavitation=Reynolds",
        ]
    )
    assert config.lubrication.cavitation == "Reynolds"
    assert config.replace({}).lubrication == config.lubrication  # reads back from its TOML


def test_the_asperity_defaults_are_the_librarys():
    from jointwear.config import LubricationConfig
    from jointwear.lubrication.asperity import DEFAULT_ETA_BETA_SIGMA, DEFAULT_SIGMA_OVER_BETA

    section = LubricationConfig()
    assert section.eta_beta_sigma == DEFAULT_ETA_BETA_SIGMA
    assert section.sigma_over_beta == DEFAULT_SIGMA_OVER_BETA


def test_a_lubricant_temperature_in_celsius_reads_in_kelvin():
    config = load_config(
        overrides=[
            "lubrication.model=finite-length",
            "lubrication.lubricant=iso-vg-68",
            "lubrication.temperature=60 degC",
            "lubrication.roughness=0.3 um",
        ]
    )
    assert config.lubrication.temperature == pytest.approx(333.15)
    assert config.lubrication.roughness == pytest.approx(0.3e-6, rel=1e-6, abs=0)
    assert config.replace({}).lubrication == config.lubrication  # reads back from its TOML


def test_a_lubricant_without_temperature_is_at_40_degc():
    config = load_config(
        overrides=["lubrication.model=long-bearing", "lubrication.lubricant=iso-vg-46"]
    )
    assert config.lubrication.oil_temperature == pytest.approx(313.15)


def test_viscosity_reads_in_pascal_seconds():
    config = load_config(
        overrides=["lubrication.model=short-bearing", "lubrication.viscosity=50 cP"]
    )
    assert config.lubrication.viscosity == pytest.approx(0.05)


@pytest.mark.parametrize(
    ("overrides", "message"),
    [
        (["lubrication.model=short-bearin"], "did you mean 'short-bearing'"),
        (["lubrication.lubricant=iso-vg-6"], "did you mean 'iso-vg-68'"),
        (
            ["lubrication.viscosity=0.1 Pa*s", "lubrication.lubricant=iso-vg-68"],
            "lubrication.viscosity: give viscosity or lubricant, not both",
        ),
        (["lubrication.model=finite-length"], "lubrication.viscosity: missing"),
        (["lubrication.viscosity=0.1 m"], "lubrication.viscosity"),
        (["lubrication.lubricant=iso-vg-68", "lubrication.temperature=60"], "below 173.15 K"),
        (["lubrication.temperature=60 degC"], "give lubricant"),
        (["lubrication.cavitation=reynold"], "did you mean 'Reynolds'"),
        (
            [
                "lubrication.model=short-bearing",
                "lubrication.viscosity=0.1 Pa*s",
                "lubrication.cavitation=Reynolds",
            ],
            "lubrication.cavitation: 'Reynolds' needs model = 'finite-length'",
        ),
    ],
)
def test_bad_lubrication_keys_are_refused_in_one_line(overrides, message):
    with pytest.raises(
        ConfigError, match=message.replace("(", r"\(").replace("*", r"\*")
    ) as caught:
        load_config(overrides=overrides)
    assert "\n" not in str(caught.value)
