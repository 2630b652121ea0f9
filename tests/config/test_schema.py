"""Checks across sections: the contact model against contour updating and NLCP's mesh."""

from __future__ import annotations

import math

import pytest

from jointwear.config import load_config
from jointwear.errors import ConfigError


@pytest.mark.parametrize(
    ("model", "reason"),
    [
        ("winkler", "assumes a circular bushing"),
        ("hertz", "assumes a circular bushing"),
        ("persson", "is exact for a circular bushing only"),
    ],
)
def test_a_model_that_cannot_follow_a_worn_contour_is_refused_with_contour_update(model, reason):
    from jointwear import Simulation

    frozen = load_config(overrides={"contact.model": model})
    assert frozen.contact.model == model  # without contour update: allowed
    message = (
        f"contact.model: '{model}' {reason} and cannot follow a worn contour; with "
        "simulation.update_contour = true use 'asymmetric-winkler' (the default) or 'nlcp'"
    )
    with pytest.raises(ConfigError) as refused:
        load_config(overrides={"contact.model": model, "simulation.update_contour": True})
    assert str(refused.value) == message
    with pytest.raises(ConfigError) as refused:
        frozen.replace({"simulation.update_contour": True})
    assert str(refused.value) == message
    # the model handed to a simulation, not named in its config: refused the same way
    updating = load_config(overrides={"simulation.update_contour": True})
    with pytest.raises(ConfigError) as refused:
        Simulation(updating, contact_model=model)
    assert str(refused.value) == message


def test_the_models_on_the_real_contour_follow_a_worn_one():
    from jointwear import Simulation

    for model in ("asymmetric-winkler", "nlcp"):
        overrides = {"contact.model": model, "simulation.update_contour": True}
        assert load_config(overrides=overrides).contact.model == model
    # the FE reference solves one worn contour, but is no model for a wear run
    with pytest.raises(ConfigError, match="'fem' meshes and factorises the bushing wall"):
        load_config(overrides={"contact.model": "fem", "simulation.update_contour": True})
    # a pressure law of one's own is evaluated on the real contour
    updating = load_config(overrides={"simulation.update_contour": True})
    Simulation(updating, contact_model=lambda depth: 1e11 * depth)


@pytest.mark.parametrize(
    ("overrides", "allowed"),
    [
        ({"contact.nodes": 360}, True),  # the paper's 1 degree springs on a 1 degree mesh
        ({"contact.nodes": 720}, False),
        ({"contact.nodes": 180}, False),
        ({"contact.nodes": 720, "contact.nlcp_variant": "mesh-independent"}, True),
        # a spring area of one's own, and the mesh it belongs to
        ({"contact.nodes": 720, "contact.spring_area": 7.5e-3 * math.pi / 360 * 0.02}, True),
        ({"contact.nodes": 360, "contact.spring_area": 2e-6}, False),
    ],
)
def test_nlcps_paper_form_only_on_the_mesh_its_spring_area_belongs_to(overrides, allowed):
    overrides = {
        "contact.model": "nlcp",
        "joint.clearance": "0.05 mm",
        "joint.pin_radius": "7.45 mm",
        "joint.axial_length": "20 mm",
        **overrides,
    }
    if allowed:
        assert load_config(overrides=overrides).contact.model == "nlcp"
    else:
        with pytest.raises(
            ConfigError, match=r"^contact\.nlcp_variant: 'paper' .*'mesh-independent'$"
        ):
            load_config(overrides=overrides)
