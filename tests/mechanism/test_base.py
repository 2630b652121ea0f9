"""The registries of mechanism types and dynamics models, and the dispatch by them."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from jointwear.config import MECHANISM_TYPES, Config, load_config
from jointwear.errors import ConfigError
from jointwear.mechanism import DYNAMICS_MODELS, MECHANISMS, ContactImpactMechanism, Mechanism
from jointwear.mechanism.base import cycles_of
from jointwear.mechanism.stage import load_cycle, mechanism_inputs

OSCILLATING = Path(__file__).resolve().parents[2] / "examples" / "oscillating_liner.toml"


def test_every_type_of_the_schema_is_registered_with_its_models() -> None:
    assert set(MECHANISMS) == set(MECHANISM_TYPES)
    for name, entry in MECHANISMS.items():
        assert isinstance(entry.description, str)
        assert entry.description, name
        assert set(entry.models) - {"prescribed"} <= set(DYNAMICS_MODELS)
    # the types with inertia offer both dynamics models and a contact-impact solution
    for name in ("slider-crank", "four-bar"):
        entry: ContactImpactMechanism = MECHANISMS.get(name)
        assert entry.models == ("massless-link", "contact-impact")
        assert callable(entry.contact_impact)
    # the oscillating bearing's load is prescribed unless its pin is let free
    oscillating: ContactImpactMechanism = MECHANISMS.get("oscillating")
    assert oscillating.models == ("prescribed", "contact-impact")
    assert callable(oscillating.contact_impact)
    history: Mechanism = MECHANISMS.get("load-history")
    assert history.models == ("prescribed",)
    assert not hasattr(history, "contact_impact")


def test_registry_and_unknown_model(paper_config: Config) -> None:
    assert "massless-link" in DYNAMICS_MODELS
    message = r"dynamics\.model: unknown dynamics model .*massless-link"
    with pytest.raises(ConfigError, match=message):
        load_cycle(paper_config.replace({"dynamics.model": "massles-link"}))
    # past the configuration's check too (inputs built by hand)
    inputs = mechanism_inputs(paper_config)
    wrong = replace(inputs, dynamics=inputs.dynamics.model_copy(update={"model": "massles-link"}))
    with pytest.raises(ConfigError, match=message):
        cycles_of(wrong)


def test_a_prescribed_load_ignores_the_dynamics_model_and_the_wear() -> None:
    inputs = mechanism_inputs(load_config(OSCILLATING))
    plain = cycles_of(inputs)
    other = replace(inputs, dynamics=inputs.dynamics.model_copy(update={"model": "other"}))
    worn = cycles_of(other, np.full(inputs.joint.nodes, 1e-5))
    assert list(plain) == list(worn) == ["bearing"]
    np.testing.assert_array_equal(plain["bearing"].load, worn["bearing"].load)
    assert worn["bearing"].model == "prescribed"
