"""Loading: parameter-set defaults underneath, every section required without them."""

from __future__ import annotations

import pytest

from jointwear.config import config_from_dict, load_config
from jointwear.errors import ConfigError


def test_defaults_from_the_parameter_set():
    cfg = load_config()
    assert cfg.parameter_set == "nlcp-paper"
    assert cfg.joint.pin_radius == pytest.approx(7.45e-3)
    assert cfg.contact.tolerance == 1e-12


def test_defaults_false_requires_every_section():
    with pytest.raises(ConfigError, match="missing"):
        config_from_dict({"joint": {"pin_radius": 1e-3}}, defaults=False)


def test_unknown_parameter_set():
    with pytest.raises(ConfigError, match="parameter_set"):
        config_from_dict({"parameter_set": "nlcp-papr"})
