"""A grease without a film model is boundary lubrication: the bushing wears with the pair's
coefficient with the grease, the dry joint's numbers otherwise unchanged."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear import Simulation
from jointwear.config import Config
from jointwear.config.greases import greased
from jointwear.errors import ConfigError

GREASE = "grease-lithium-nlgi2"


@pytest.fixture(scope="module")
def bronze(paper_config: Config) -> Config:
    """The paper's joint with the library's bronze bushing, one revolution, no update."""
    return paper_config.replace(
        {
            "materials.bushing": "bronze",
            "contact.nodes": 90,
            "simulation.steps_per_revolution": 72,
            "simulation.update_contour": False,
        }
    )


@pytest.mark.parametrize(
    ("lubrication", "expected"),
    [
        ({}, False),
        ({"lubrication.lubricant": "iso-vg-68"}, False),  # an oil without a film: dry
        ({"lubrication.lubricant": GREASE}, True),
        (
            {
                "lubrication.lubricant": GREASE,
                "lubrication.model": "short-bearing",
            },
            False,  # a film model: the grease's base oil is the film
        ),
    ],
)
def test_only_a_grease_without_film_is_boundary_lubrication(
    bronze: Config, lubrication: dict, expected: bool
) -> None:
    assert greased(bronze.replace(lubrication)) is expected


def test_a_dry_joint_wears_with_its_own_material(bronze: Config) -> None:
    """Not greased: the very same material object, so every number is the dry joint's."""
    assert bronze.wearing_bushing is bronze.materials.bushing
    oil = bronze.replace({"lubrication.lubricant": "iso-vg-68"})
    assert oil.wearing_bushing is oil.materials.bushing


def test_greased_bronze_wears_as_the_library_says(bronze: Config) -> None:
    """The library's bronze is the grease-lubricated one: greased, it wears the same."""
    dry = Simulation(bronze).run(pressures=False)
    wet = Simulation(bronze.replace({"lubrication.lubricant": GREASE})).run(pressures=False)
    assert wet.wear_depth.max() > 0
    np.testing.assert_allclose(wet.wear_depth, dry.wear_depth, rtol=1e-14, atol=0)


@pytest.mark.parametrize("law", ["archard", "power-law"])
def test_wear_is_proportional_to_the_greased_coefficient(bronze: Config, law: str) -> None:
    """Archard's law on the fused path and a generalised law (a = b = 0) on the general
    path: the wear of the greased joint scales with boundary_wear_coefficient alone."""
    base = bronze.replace({"wear.law": law, "lubrication.lubricant": GREASE})
    k_dry = bronze.materials.bushing.wear_coefficient
    one = Simulation(base.replace({"materials.bushing.boundary_wear_coefficient": k_dry})).run(
        pressures=False
    )
    three = base.replace({"materials.bushing.boundary_wear_coefficient": 3 * k_dry})
    assert three.materials.bushing.wear_coefficient == k_dry  # the dry value is kept
    worn = Simulation(three).run(pressures=False)
    np.testing.assert_allclose(worn.wear_depth, 3 * one.wear_depth, rtol=1e-12, atol=0)


def test_a_grease_needs_the_pairs_coefficient(bronze: Config) -> None:
    with pytest.raises(ConfigError) as refused:
        bronze.replace({"materials.bushing": "ptfe", "lubrication.lubricant": GREASE})
    message = str(refused.value)
    assert "\n" not in message
    assert message.startswith("materials.bushing.boundary_wear_coefficient: missing")
    assert f"{GREASE!r} is a grease" in message
    assert "'ptfe' gives none" in message


def test_a_named_pin_takes_no_greased_coefficient(bronze: Config) -> None:
    """A wear value belongs to the pair, which the bushing's entry describes."""
    pin = bronze.replace({"materials.pin": "bronze"}).materials.pin
    assert pin.boundary_wear_coefficient is None
    assert pin.wear_coefficient is None
