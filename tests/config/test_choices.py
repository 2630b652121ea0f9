"""The stages' choices as the configuration knows them, without importing the stages.

The names kept in :mod:`jointwear.config.choices` must be the stages' registries'
(else a valid model would be refused, or a removed one accepted); the lazy entries
must name the stages' functions; an unknown name gets the best match.
"""

from __future__ import annotations

import math
import subprocess
import sys
import typing

import pytest

from jointwear.config import MECHANISM_TYPES, Config, DynamicsConfig, load_config, schema
from jointwear.config import mechanisms as mechanism_tables
from jointwear.config.choices import (
    CHOICES,
    FOUR_BAR_GEOMETRY,
    LUBRICANT,
    MODEL_CHOICE,
    NLCP_STIFFNESS,
    PAPER_SPRING_AREA,
    Choice,
)
from jointwear.errors import ConfigError
from jointwear.registry import Lazy, resolve


@pytest.mark.parametrize("choice", CHOICES, ids=lambda choice: choice.key)
def test_the_names_are_the_stage_registrys(choice: Choice) -> None:
    registry = resolve(choice.registry, choice.key)
    assert tuple(registry.names()) == choice.names
    assert (registry.kind, registry.key) == (choice.kind, choice.key)


def test_the_mechanism_types_are_the_mechanism_registrys() -> None:
    from jointwear.mechanism import MECHANISMS

    assert MECHANISMS.names() == list(MECHANISM_TYPES)


def test_the_force_laws_are_the_contact_impact_dynamics() -> None:
    from jointwear.mechanism.impact.force_laws import FORCE_LAWS

    force_law = DynamicsConfig.model_fields["force_law"].annotation
    assert typing.get_args(force_law) == FORCE_LAWS


@pytest.mark.parametrize(
    ("entry", "module", "name"),
    [
        (FOUR_BAR_GEOMETRY, "jointwear.mechanism.four_bar", "check_four_bar"),
        (NLCP_STIFFNESS, "jointwear.contact.nlcp", "stiffness"),
        (MODEL_CHOICE, "jointwear.contact", "check_model_choice"),
        (PAPER_SPRING_AREA, "jointwear.contact", "check_paper_spring_area"),
        (LUBRICANT, "jointwear.lubrication.lubricants", "get_lubricant"),
    ],
)
def test_the_lazy_entries_name_the_stages_functions(entry: Lazy, module: str, name: str) -> None:
    assert entry.resolve() is getattr(sys.modules[module], name)


def test_importing_the_configuration_imports_no_stage() -> None:
    code = (
        "import sys, jointwear.config; "
        "print(sorted(m for m in sys.modules if m.startswith('jointwear.') and "
        "m.split('.')[1] in {'mechanism', 'contact', 'tribology', 'references', "
        "'simulation', 'coupling', 'results'}))"
    )
    loaded = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    ).stdout
    assert loaded.strip() == "[]"


def test_the_default_stiffness_is_eq_2(paper_config: Config) -> None:
    """K = 4/3 E* sqrt(R_p), reached through the lazy entry."""
    pin, bushing = paper_config.materials.pin, paper_config.materials.bushing
    modulus = 1.0 / (
        (1 - pin.poisson_ratio**2) / pin.youngs_modulus
        + (1 - bushing.poisson_ratio**2) / bushing.youngs_modulus
    )
    expected = 4.0 / 3.0 * modulus * math.sqrt(paper_config.joint.pin_radius)
    assert paper_config.nlcp_stiffness == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize(
    ("override", "message"),
    [
        (
            {"contact.model": "asymetric-winkler"},
            "contact.model: unknown contact model 'asymetric-winkler'; "
            "did you mean 'asymmetric-winkler'?",
        ),
        (
            {"dynamics.model": "contact-impakt"},
            "dynamics.model: unknown dynamics model 'contact-impakt'; "
            "did you mean 'contact-impact'?",
        ),
        ({"wear.law": "archart"}, "wear.law: unknown wear law 'archart'; did you mean 'archard'?"),
        (
            {"wear.law": "xyz"},
            "wear.law: unknown wear law 'xyz'; choose from 'archard', 'energy', 'power-law', "
            "'running-in', 'tabulated'",
        ),
    ],
)
def test_an_unknown_model_gets_the_best_match(
    paper_config: Config, override: dict[str, str], message: str
) -> None:
    for build in (lambda: load_config(overrides=override), lambda: paper_config.replace(override)):
        with pytest.raises(ConfigError) as info:
            build()
        assert str(info.value) == message


def test_a_lazy_default_that_points_nowhere_is_a_config_error(
    paper_config: Config, monkeypatch: pytest.MonkeyPatch
) -> None:
    broken = Lazy("jointwear.contact.nlcp:stifness", "contact.stiffness")
    monkeypatch.setattr(schema, "NLCP_STIFFNESS", broken)
    with pytest.raises(ConfigError) as info:
        paper_config.to_dict()
    assert str(info.value) == (
        "contact.stiffness: the registry entry 'jointwear.contact.nlcp:stifness' names "
        "'stifness', which 'jointwear.contact.nlcp' does not have"
    )


def test_a_lazy_check_that_points_nowhere_names_its_key(monkeypatch: pytest.MonkeyPatch) -> None:
    from pathlib import Path

    broken = Lazy("jointwear.mechanism.four_bar:check_fourbar", "mechanism")
    monkeypatch.setattr(mechanism_tables, "FOUR_BAR_GEOMETRY", broken)
    example = Path(__file__).resolve().parents[2] / "examples" / "four_bar.toml"
    with pytest.raises(ConfigError) as info:
        load_config(example)
    assert str(info.value) == (
        "mechanism: the registry entry 'jointwear.mechanism.four_bar:check_fourbar' names "
        "'check_fourbar', which 'jointwear.mechanism.four_bar' does not have"
    )
