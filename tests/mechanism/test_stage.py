"""The mechanism stage of a run: a configuration's mechanism inputs and load cycles.

The stage hands each mechanism its own section and the joint's numbers, resolves the
contact-impact model's elastic law from the contact stage (Hertz's eq. (2), the
spring laws) and decides from the configuration alone whether the integrations may
run compiled.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointwear.config import Config, load_config
from jointwear.contact import ContactParameters, contact_law
from jointwear.errors import ConfigError
from jointwear.lubrication.lubricants import dynamic_viscosity
from jointwear.mechanism.impact.film import FilmParameters
from jointwear.mechanism.stage import (
    compiled_dynamics,
    elastic_law,
    load_cycle,
    load_cycles,
    mechanism_inputs,
)

from .four_bar.test_massless_link import EXAMPLE


def impact_config(config: Config, **overrides: object) -> Config:
    return config.replace({"dynamics.model": "contact-impact", **overrides})


def test_inputs_hold_the_sections_and_the_joint(paper_config: Config) -> None:
    inputs = mechanism_inputs(paper_config)
    assert inputs.mechanism is paper_config.mechanism
    assert inputs.dynamics is paper_config.dynamics
    assert inputs.steps == paper_config.simulation.steps_per_revolution
    joint = paper_config.joint
    assert inputs.clearance == joint.clearance
    assert inputs.joint.bushing_radius == joint.bushing_radius
    assert inputs.joint.nodes == paper_config.contact.nodes
    # the massless-link model needs no elastic law: none is built
    assert inputs.elastic is None
    assert mechanism_inputs(impact_config(paper_config)).elastic is not None


def test_elastic_stiffness_is_eq_2_of_the_pin_in_the_hole(
    paper_config: Config, params: ContactParameters
) -> None:
    sigma_p = (1 - params.pin_poisson_ratio**2) / (math.pi * params.pin_youngs_modulus)
    sigma_b = (1 - params.bushing_poisson_ratio**2) / (math.pi * params.bushing_youngs_modulus)
    r_p, r_b = params.pin_radius, params.bushing_radius
    expected = 4 / (3 * math.pi * (sigma_p + sigma_b)) * math.sqrt(r_p * r_b / (r_b - r_p))
    elastic = elastic_law(paper_config)
    assert elastic.stiffness == pytest.approx(expected, rel=1e-12)
    # paper's joint: PTFE bushing, R* = 1.12 m -> K ~ 8.2e8 N/m^1.5
    assert 8.0e8 < elastic.stiffness < 8.4e8
    # a point law needs no spring law
    assert elastic.spring_law is None


@pytest.mark.parametrize("law", ["nlcp", "winkler"])
def test_distributed_laws_take_the_contact_models_spring_law(
    paper_config: Config, params: ContactParameters, law: str
) -> None:
    spring = elastic_law(paper_config.replace({"dynamics.force_law": law})).spring_law
    expected = contact_law(law, params)
    depth = np.linspace(0.0, 2e-5, 5)
    np.testing.assert_array_equal(spring.pressure(depth), expected.pressure(depth))
    assert spring.force_area == expected.force_area


def test_load_cycles_of_every_joint_and_one_by_name() -> None:
    config = load_config(EXAMPLE)
    cycles = load_cycles(config)
    assert list(cycles) == list(config.joints)
    assert load_cycle(config, "coupler-rocker") is not cycles["coupler-rocker"]
    np.testing.assert_array_equal(
        load_cycle(config, "coupler-rocker").load, cycles["coupler-rocker"].load
    )
    np.testing.assert_array_equal(load_cycle(config).load, cycles["crank-coupler"].load)
    with pytest.raises(ConfigError, match=r"clearance_joint: no clearance joint 'coupler'"):
        load_cycle(config, "coupler")


@pytest.mark.parametrize(
    ("overrides", "compiled"),
    [
        ({}, False),  # one integration of settle + 1 = 3 revolutions
        ({"dynamics.revolutions_settle": 20}, None),
        ({"simulation.revolutions": 100, "simulation.dynamics_update": 1}, None),
        ({"simulation.revolutions": 100, "simulation.dynamics_update": "adaptive"}, None),
        ({"simulation.revolutions": 100, "simulation.dynamics_update": 50}, False),
        ({"simulation.update_contour": False, "simulation.dynamics_update": 1}, False),
    ],
)
def test_compiled_dynamics_follows_from_the_config_alone(
    paper_config: Config, overrides: dict, compiled: bool | None
) -> None:
    settings = {"simulation.update_contour": True, "dynamics.revolutions_settle": 2, **overrides}
    config = impact_config(paper_config, **settings)
    assert compiled_dynamics(config) is compiled
    assert mechanism_inputs(config).compiled is compiled


def test_a_lubricated_contact_impact_joint_carries_the_configured_film(
    paper_config: Config,
) -> None:
    oil = {"lubrication.model": "long-bearing", "lubrication.lubricant": "iso-vg-68"}
    warm = impact_config(
        paper_config,
        **oil,
        **{"lubrication.temperature": "60 degC", "lubrication.roughness": "0.8 um"},
    )
    film = mechanism_inputs(warm).film
    # the library's oil at 60 degC: thinner than at the 40 degC of its grade
    mu_60 = float(dynamic_viscosity("iso-vg-68", 333.15))
    assert film == FilmParameters("long-bearing", mu_60, roughness=0.8e-6)
    assert mu_60 < float(dynamic_viscosity("iso-vg-68", 313.15))
    # a lubricant without a temperature is taken at 40 degC
    assert mechanism_inputs(impact_config(paper_config, **oil)).film.viscosity == pytest.approx(
        float(dynamic_viscosity("iso-vg-68", 313.15)), rel=1e-15, abs=0
    )
    given = impact_config(
        paper_config, **{"lubrication.model": "short-bearing", "lubrication.viscosity": "1 Pa*s"}
    )
    assert mechanism_inputs(given).film == FilmParameters("short-bearing", 1.0, roughness=0.4e-6)
    # no film where the dynamics have none to carry: the massless link, a dry joint
    massless = paper_config.replace(
        {"lubrication.model": "short-bearing", "lubrication.viscosity": "1 Pa*s"}
    )
    assert mechanism_inputs(massless).film is None
    assert mechanism_inputs(impact_config(paper_config)).film is None


def test_a_finite_length_film_is_refused_in_the_contact_impact_dynamics(
    paper_config: Config,
) -> None:
    with pytest.raises(ConfigError, match="has no film in dynamics.model") as error:
        impact_config(
            paper_config,
            **{"lubrication.model": "finite-length", "lubrication.viscosity": "0.1 Pa*s"},
        )
    assert "\n" not in str(error.value)
    # the load cycle's film sharing keeps it
    paper_config.replace(
        {"lubrication.model": "finite-length", "lubrication.viscosity": "0.1 Pa*s"}
    )
