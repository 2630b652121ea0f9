"""The sections: the paper's config in SI, open bounds, defaults, K's unit by the exponent."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import pytest

from jointwear.config import load_config
from jointwear.errors import ConfigError


def test_paper_config_in_si(paper_config):
    assert paper_config.mechanism.crank_speed == pytest.approx(4 * math.pi, rel=1e-15)
    assert paper_config.mechanism.crank_length == pytest.approx(0.07)
    assert paper_config.joint.pin_radius == pytest.approx(7.45e-3)
    assert paper_config.joint.clearance == pytest.approx(5e-5)
    assert paper_config.bushing_radius == pytest.approx(7.5e-3)
    assert paper_config.materials.pin.youngs_modulus == pytest.approx(2.09e11)
    assert paper_config.materials.bushing.wear_coefficient == pytest.approx(5.05e-13)
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
