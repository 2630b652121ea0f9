"""Messages: unknown keys and values get the best match, invalid values name their key."""

from __future__ import annotations

import pytest

from jointwear.config import load_config
from jointwear.errors import ConfigError


@pytest.mark.parametrize(
    ("override", "needle"),
    [
        ("jiont.clearance=1e-5", "jiont: unknown key; did you mean 'joint'?"),
        ("joint.clearence=1e-5", "joint.clearence: unknown key; did you mean 'clearance'?"),
        ("mechansim.crank_length=1", "did you mean 'mechanism'?"),
        ("materials.pn.youngs_modulus=1", "did you mean 'pin'?"),
        ("materials.pin.young_modulus=1", "did you mean 'youngs_modulus'?"),
        ("contact.modle=nlcp", "did you mean 'model'?"),
        ("contact.model=nlpc", "contact.model: unknown contact model 'nlpc'; did you mean 'nlcp'?"),
        ("contact.model=winklr", "did you mean 'winkler'?"),
        ("contact.balance=equilibirum", "did you mean 'equilibrium'?"),
        ("contact.foundation_modulus=constraned", "did you mean 'constrained'?"),
    ],
)
def test_unknown_keys_and_values_suggest(paper_config_path, override, needle):
    with pytest.raises(ConfigError) as info:
        load_config(paper_config_path, [override])
    assert needle in str(info.value)
    assert "\n" not in str(info.value)


@pytest.mark.parametrize(
    ("override", "key"),
    [
        ("joint.clearance=0", "joint.clearance"),
        ("joint.clearance=-1e-6", "joint.clearance"),
        ('joint.pin_radius="5 kg"', "joint.pin_radius"),
        ("joint.axial_length=nan", "joint.axial_length"),
        ("materials.bushing.poisson_ratio=0.5", "materials.bushing.poisson_ratio"),
        ("materials.pin.poisson_ratio=-1.0", "materials.pin.poisson_ratio"),
        ("materials.pin.youngs_modulus=0", "materials.pin.youngs_modulus"),
        ("contact.nodes=8", "contact.nodes"),
        ("contact.exponent=0", "contact.exponent"),
        ("contact.tolerance=0", "contact.tolerance"),
        ("joint.clearance=true", "joint.clearance"),
        ('contact.stiffness="2e7 N/m"', "contact.stiffness"),
        ("contact.stiffness=0", "contact.stiffness"),
        ('contact.stiffness="2e7 Pa"', "contact.stiffness"),
    ],
)
def test_invalid_values_name_their_key(paper_config_path, override, key):
    with pytest.raises(ConfigError) as info:
        load_config(paper_config_path, [override])
    assert str(info.value).startswith(key + ":")
