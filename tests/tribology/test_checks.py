"""Engineering checks of a run against the bushing's datasheet limits (nominal p, v, PV),
and against the range of its contact model (tribology/checks.py)."""

from __future__ import annotations

import math
import warnings
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from jointwear import Simulation, load_config
from jointwear.config import Config
from jointwear.errors import ContactModelWarning, MaterialLimitWarning
from jointwear.paper.cases import PAPER_ROWS
from jointwear.tribology.checks import SYMMETRIC_WEAR_FRACTION, model_validity
from jointwear.tribology.metrics import compare_with_limits, engineering_checks, operating_values

R_P, B = 7.45e-3, 20e-3


def test_constant_load_constant_speed_oscillation_is_the_datasheet_pv():
    # a triangular swing: the pin turns at constant speed w, back and forth
    steps, period, load, amplitude = 40, 2.0, 300.0, 0.4
    w = 4 * amplitude / period
    rotation = np.where(np.arange(steps) < steps // 2, 1.0, -1.0) * 2 * amplitude / (steps / 2)
    values = operating_values(
        np.full(steps, load), rotation, np.full(steps, period / steps), R_P, B
    )
    p, v = load / (2 * R_P * B), R_P * w
    assert values["nominal_pressure"] == pytest.approx(p, rel=1e-12)
    assert values["sliding_speed"] == pytest.approx(v, rel=1e-12, abs=0)
    assert values["pv"] == pytest.approx(p * v, rel=1e-12)
    assert values["pv_max"] == pytest.approx(p * v, rel=1e-12)
    assert math.isnan(values["peak_pressure"])


def test_unequal_steps_weigh_pv_by_time():
    # half the period at rest under load F, half sliding at v under 2F: mean PV = (2F) v / 2 / A
    load = np.array([100.0, 200.0])
    values = operating_values(load, [0.0, 0.5], [1.0, 1.0], R_P, B)
    area = 2 * R_P * B
    assert values["pv"] == pytest.approx(0.5 * (200.0 / area) * R_P * 0.5, rel=1e-12)
    assert values["pv_max"] == pytest.approx((200.0 / area) * R_P * 0.5, rel=1e-12)


@pytest.fixture(scope="module")
def oscillating():
    # sinusoidal swing A sin(2 pi f t) under a constant load F (steps a multiple of 4, so
    # the turning points are step boundaries and the sliding per cycle is exactly 4 A R_p)
    load, amplitude, frequency = 1500.0, math.radians(25), 0.25
    cfg = load_config(
        overrides={
            "mechanism.type": "oscillating",
            "mechanism.load": load,
            "mechanism.amplitude": amplitude,
            "mechanism.frequency": frequency,
            "contact.model": "winkler",
            "contact.nodes": 120,
            "simulation.steps_per_revolution": 400,
            "materials.bushing": "ptfe-fabric",
        }
    )
    result = Simulation(cfg).run()
    return cfg, result, (load, amplitude, frequency)


def test_oscillating_bearing_pv_is_the_closed_form(oscillating):
    cfg, result, (load, amplitude, frequency) = oscillating
    checks = engineering_checks(result.joint_dataset(), cfg)
    b = cfg.joint.axial_length
    # mean PV = F / (2 R_p b) * 4 A f R_p = 2 F A f / b; largest = F / (2 R_p b) * 2 pi f A R_p
    assert checks["pv"]["value"] == pytest.approx(2 * load * amplitude * frequency / b, rel=1e-9)
    assert checks["pv_max"]["value"] == pytest.approx(
        math.pi * load * amplitude * frequency / b, rel=2e-4
    )
    assert checks["sliding_speed"]["value"] == pytest.approx(
        2 * math.pi * frequency * amplitude * cfg.joint.pin_radius, rel=2e-4
    )
    # the local peak carries the load on less than the projected area
    assert checks["peak_pressure"]["value"] >= checks["nominal_pressure"]["value"]
    assert checks["pv_peak_local"]["value"] >= checks["pv"]["value"]
    assert checks["pv"]["limit"] == pytest.approx(1.6e6)
    assert checks["pv"]["ok"] is True
    assert checks["pv_max"]["ok"] is None  # reported, not compared


def material(**limits):
    keys = ("max_static_pressure", "max_dynamic_pressure", "max_pv", "max_sliding_speed")
    return SimpleNamespace(**{k: limits.get(k) for k in keys})


VALUES = {
    "nominal_pressure": 1e6,
    "peak_pressure": 5e6,
    "sliding_speed": 0.1,
    "pv": 1e5,
    "pv_max": 2e5,
    "pv_peak_local": 5e5,
}


def test_warns_once_per_exceeded_limit():
    with pytest.warns(MaterialLimitWarning, match=r"materials\.bushing\.max_pv: .*PV") as record:
        checks = compare_with_limits(
            VALUES, material(max_pv=0.9e5, max_sliding_speed=1.0), "bronze"
        )
    assert len(record) == 1
    assert "'bronze'" in str(record[0].message)
    assert checks["pv"]["ok"] is False
    assert checks["sliding_speed"]["ok"] is True


def test_no_warning_within_the_limits_or_without_limits():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        within = compare_with_limits(VALUES, material(max_pv=1e5, max_static_pressure=5e6))
        unknown = compare_with_limits(VALUES, {})
    assert within["pv"]["ok"] is True  # the limit itself is allowed
    assert within["peak_pressure"]["ok"] is True
    assert all(entry["ok"] is None for entry in unknown.values())
    assert unknown["pv"]["limit"] is None


# ---------------------------------------------------------------- the contact model's range


def liner(**overrides) -> Config:
    """A pin swinging +-25 deg under a load fixed in the bushing (the paper's PTFE joint)."""
    return load_config(
        overrides={
            "mechanism.type": "oscillating",
            "mechanism.load": "1.5 kN",
            "mechanism.load_frame": "bushing",
            "mechanism.amplitude": "25 deg",
            "mechanism.frequency": "0.25 Hz",
            "contact.nodes": 180,
            "simulation.steps_per_revolution": 40,
            **overrides,
        }
    )


def validity_warnings(config: Config) -> tuple[dict[str, str], dict]:
    """The contact-model warnings of a run (message -> count) and its summary."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        summary = Simulation(config).run().summary()
    said: dict[str, int] = {}
    for w in caught:
        if issubclass(w.category, (ContactModelWarning, MaterialLimitWarning)):
            said[str(w.message)] = said.get(str(w.message), 0) + 1
    assert all(count == 1 for count in said.values()), said  # once per run
    return said, summary


def test_a_circular_model_warns_once_its_wear_outgrows_a_tenth_of_the_clearance() -> None:
    clearance = 0.05e-3
    said, summary = validity_warnings(liner(**{"contact.model": "winkler"}))
    assert summary["peak_wear_depth_m"] < SYMMETRIC_WEAR_FRACTION * clearance
    assert not said
    said, summary = validity_warnings(
        liner(**{"contact.model": "winkler", "simulation.revolutions": 200})
    )
    assert summary["peak_wear_depth_m"] > SYMMETRIC_WEAR_FRACTION * clearance
    [message] = said
    assert message.startswith("contact.model: 'winkler' assumes a circular bushing")
    assert "simulation.update_contour = true" in message
    assert "'asymmetric-winkler'" in message
    # the model on the real contour, frozen as well: no model to blame
    said, _ = validity_warnings(
        liner(**{"contact.model": "asymmetric-winkler", "simulation.revolutions": 200})
    )
    assert not said


def test_hertz_warns_where_its_contact_is_not_small() -> None:
    light = liner(**{"contact.model": "hertz", "mechanism.load": "20 N"})
    said, _ = validity_warnings(light)
    assert not said  # a/R_b = 0.21 at 20 N: Hertz's peak within 1 % of Persson's
    said, _ = validity_warnings(liner(**{"contact.model": "hertz", "mechanism.load": "200 N"}))
    [message] = said
    assert message.startswith("contact.model: 'hertz' assumes a contact small")
    assert "a/R_b = 0.6" in message  # 37.7 deg at 200 N


def unworn_validity(config: Config) -> dict[str, str]:
    """:func:`model_validity` of the unworn contact of ``config``'s load cycle."""
    simulation = Simulation(config)
    solution = simulation.contact(simulation.initial_contour())
    return model_validity(config, simulation.law, np.zeros(config.contact.nodes), [solution])


def test_a_contact_cut_at_the_quarter_circle_and_large_strains_warn() -> None:
    soft = {"materials.bushing.youngs_modulus": "50 MPa", "mechanism.load": "2 kN"}
    found = unworn_validity(liner(**{"contact.model": "hertz", **soft}))
    assert set(found) == {"hertz_half_width", "arc", "strain"}
    assert found["arc"].startswith("contact.model: 'hertz' spreads the contact 90 deg")
    # Winkler's springs at the same load: 82 deg, an approach of 0.18 of the wall
    found = unworn_validity(liner(**{"contact.foundation_modulus": "youngs", **soft}))
    assert set(found) == {"strain"}
    assert found["strain"].startswith("joint.bushing_thickness: the elastic approach")
    assert not unworn_validity(liner(**{"contact.foundation_modulus": "youngs"}))


@pytest.mark.parametrize(
    ("bushing", "thickness", "warned"),
    [
        ("uhmwpe", "2.5 mm", True),  # nu = 0.46, contact half-width ~ 1 wall
        ("uhmwpe", "0.1 mm", False),  # a thin liner: the constrained modulus is exact
        ("ptfe", "2.5 mm", False),  # nu = 0.38: within 2.5 % of the FE wall
    ],
)
def test_the_constrained_modulus_of_a_nearly_incompressible_thick_wall_warns(
    bushing: str, thickness: str, warned: bool
) -> None:
    config = liner(
        **{
            "materials.bushing": bushing,
            "joint.bushing_thickness": thickness,
            "mechanism.load": "3 kN",
        }
    )
    said, _ = validity_warnings(config)
    assert [m.split(":")[0] for m in said] == (["contact.foundation_modulus"] if warned else [])
    if warned:  # Young's modulus is the other error (too soft), not warned about
        said, _ = validity_warnings(config.replace({"contact.foundation_modulus": "youngs"}))
        assert not said


def test_a_peak_pressure_above_the_bushing_limit_warns_through_the_material_checks() -> None:
    said, _ = validity_warnings(liner(**{"materials.bushing.max_static_pressure": "1 MPa"}))
    [message] = said
    assert message.startswith("materials.bushing.max_static_pressure: peak pressure")
    said, _ = validity_warnings(liner(**{"materials.bushing.max_static_pressure": "50 MPa"}))
    assert not said


@pytest.mark.parametrize("name", sorted(PAPER_ROWS))
def test_the_papers_cases_stay_inside_their_models(name: str) -> None:
    config = load_config(
        Path(__file__).resolve().parents[2] / "examples" / "paper" / f"{name}.toml"
    )
    said, _ = validity_warnings(config)
    assert not said


def test_wear_deeper_than_a_tenth_of_the_radius_warns() -> None:
    """The contour models wear along the bushing's rays: past h = 0.1 R_b they fall ~2 %
    short of the exact conformal bore, and the run says so (and where to stop)."""
    config = liner()
    radius = config.joint.bushing_radius
    shallow = np.full(config.contact.nodes, 0.09 * radius)
    assert "deep_wear" not in model_validity(config, "asymmetric-winkler", shallow)
    found = model_validity(config, "asymmetric-winkler", shallow / 0.09 * 0.12)
    assert found["deep_wear"].startswith("life.peak_wear_depth: the wear (0.9 mm)")
    assert "2.4% low" in found["deep_wear"]


@pytest.mark.parametrize(
    ("poisson", "slices", "warns"), [(0.38, 10, True), (0.2, 10, False), (0.38, 1, False)]
)
def test_slices_on_a_liner_with_free_ends_that_bulge_warn(poisson, slices, warns) -> None:
    """Finite elements of the liner along the pin: with Poisson's ratio 0 the slices hold to
    0.3 %, with PTFE's 0.38 they overstate the end slices' line load by half; only sliced
    runs on such a liner are told."""
    config = liner(**{"materials.bushing.poisson_ratio": poisson, "joint.axial_slices": slices})
    found = model_validity(config, "asymmetric-winkler", np.zeros(config.contact.nodes))
    assert ("free_liner_ends" in found) is warns
    if warns:
        assert found["free_liner_ends"].startswith("joint.axial_slices: each slice is a confined")
        assert f"ratio {poisson:g}" in found["free_liner_ends"]
