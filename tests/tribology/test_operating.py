"""Wear laws that follow how the joint runs: generalized Archard and running-in."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from jointwear import Simulation
from jointwear.config import config_from_dict
from jointwear.errors import ConfigError, MaterialLimitWarning
from jointwear.tribology import archard
from jointwear.tribology.operating import (
    WearConditions,
    power_law_wear_depth,
    running_in_mean_coefficient,
)
from jointwear.tribology.wear_laws import wear_law

RNG = np.random.default_rng(7)
PRESSURE = RNG.uniform(0.0, 2e7, size=(40, 36))
SLIDING = RNG.uniform(1e-5, 1e-4, size=40)
SPEED = RNG.uniform(1e-3, 5e-2, size=40)
K = 5.05e-13

OSCILLATING = {
    "type": "oscillating",
    "load": "1.5 kN",
    "load_angle": "-90 deg",
    "amplitude": "25 deg",
    "frequency": "0.5 Hz",
}


def config(wear: dict, frequency: str = "0.5 Hz", **simulation):
    return config_from_dict(
        {
            "mechanism": {**OSCILLATING, "frequency": frequency},
            "contact": {"nodes": 120},
            "simulation": {"steps_per_revolution": 48, "revolutions": 2000, **simulation},
            "wear": wear,
        }
    )


def test_zero_exponents_are_archard_bit_for_bit() -> None:
    got = power_law_wear_depth(PRESSURE, SLIDING, SPEED, K, 1e6, 0.01, 0.0, 0.0)
    np.testing.assert_array_equal(got, archard.wear_depth(PRESSURE, SLIDING, K))


def test_exponents_scale_the_wear_as_the_power_law_says() -> None:
    """h(c p, v) = c^(1+a) h(p, v) and h(p, c v) = c^b h(p, v); at p_ref, v_ref it is Archard."""
    a, b, c = 0.7, 0.4, 3.0
    base = power_law_wear_depth(PRESSURE, SLIDING, SPEED, K, 1e6, 0.01, a, b)
    np.testing.assert_allclose(
        power_law_wear_depth(c * PRESSURE, SLIDING, SPEED, K, 1e6, 0.01, a, b),
        c ** (1 + a) * base,
        rtol=1e-12,
    )
    np.testing.assert_allclose(
        power_law_wear_depth(PRESSURE, SLIDING, c * SPEED, K, 1e6, 0.01, a, b),
        c**b * base,
        rtol=1e-12,
    )
    uniform = np.full((40, 36), 2e6)
    np.testing.assert_allclose(
        power_law_wear_depth(uniform, SLIDING, np.full(40, 0.02), K, 2e6, 0.02, a, b),
        archard.wear_depth(uniform, SLIDING, K),
        rtol=1e-14,
    )


def test_a_run_at_twice_the_speed_wears_two_to_the_b_more() -> None:
    """Same load and sliding per cycle, twice the frequency: every step slides twice as fast."""
    wear = {"law": "power-law", "speed_exponent": 0.5, "pressure_exponent": 0.3}
    slow = Simulation(config(wear, "0.5 Hz", update_contour=False)).run(pressures=False)
    fast = Simulation(config(wear, "1 Hz", update_contour=False)).run(pressures=False)
    np.testing.assert_allclose(
        fast.dataset["wear_depth"].values[-1],
        math.sqrt(2.0) * slow.dataset["wear_depth"].values[-1],
        rtol=1e-12,
        atol=1e-12 * float(slow.dataset["wear_depth"].values[-1].max()),
    )


def test_a_zero_exponent_run_is_archards_run() -> None:
    archard_run = Simulation(config({}, update_contour=False)).run(pressures=False)
    power = Simulation(config({"law": "power-law"}, update_contour=False)).run(pressures=False)
    expected = archard_run.dataset["wear_depth"].values[-1]
    np.testing.assert_allclose(
        power.dataset["wear_depth"].values[-1], expected, rtol=0, atol=1e-12 * expected.max()
    )


def test_running_in_cycle_after_cycle_integrates_the_coefficient_exactly() -> None:
    """Constant pressure: sum of the cycles' wear = p ∫_0^s K(s') ds', K(s) = K∞ + ΔK e^{-s/λ}."""
    k0, k_inf, length, cycles = 8e-12, 5e-13, 0.05, 700
    wear = {"law": "running-in", "initial_wear_coefficient": k0, "running_in_distance": length}
    bushing = config({}).materials.bushing.model_copy(update={"wear_coefficient": k_inf})
    law = wear_law(config(wear, update_contour=True).wear, bushing)
    pressure = np.full((40, 3), 4e6)
    span = float(SLIDING.sum())
    total = sum(law(pressure, SLIDING, WearConditions(SPEED, n * span)) for n in range(cycles))
    s = cycles * span
    exact = 4e6 * (k_inf * s + (k0 - k_inf) * length * -math.expm1(-s / length))
    np.testing.assert_allclose(total, exact, rtol=1e-12)


def test_the_mean_coefficient_of_a_point_is_the_coefficient() -> None:
    assert running_in_mean_coefficient(0.02, 0.0, 8e-12, 5e-13, 0.05) == pytest.approx(
        5e-13 + 7.5e-12 * math.exp(-0.4), rel=1e-15, abs=0
    )
    assert running_in_mean_coefficient(0.02, 1e-9, 8e-12, 5e-13, 0.05) == pytest.approx(
        5e-13 + 7.5e-12 * math.exp(-0.4), rel=1e-7, abs=0
    )


def test_running_in_is_the_steady_run_on_a_stretched_count_of_cycles() -> None:
    """K(s) = K∞ (1 + (r-1) e^{-s/λ}) wears after N cycles as K∞ after the stretched count
    N + (r-1) λ/S (1 - e^{-NS/λ}): K(s) multiplies the whole wear rate."""
    sliding = 4 * math.radians(25) * config({}).joint.bushing_radius  # per cycle [m]
    ratio, cycles = 4.0, 2000
    length = 100 * sliding  # N S / λ = 20: the transient is over
    extra = (ratio - 1) * 100 * -math.expm1(-cycles / 100)
    wear = {
        "law": "running-in",
        "initial_wear_coefficient": ratio * 5.05e-13,
        "running_in_distance": length,
    }
    run_in = Simulation(config(wear, update_contour=True, update_every="adaptive")).run(
        pressures=False
    )
    steady = Simulation(
        config({}, update_contour=True, update_every="adaptive", revolutions=cycles + 300)
    ).run(pressures=False)
    assert abs(extra - 300) < 1e-6
    expected = steady.dataset["wear_depth"].values[-1]
    np.testing.assert_allclose(
        run_in.dataset["wear_depth"].values[-1], expected, rtol=0, atol=2e-3 * expected.max()
    )


def test_running_in_needs_its_keys_and_contour_updates() -> None:
    with pytest.raises(ConfigError, match=r"^wear\.initial_wear_coefficient: missing"):
        config({"law": "running-in", "running_in_distance": "10 m"}, update_contour=True)
    with pytest.raises(ConfigError, match=r"^wear\.law: 'running-in' .*update_contour = true"):
        config(
            {"law": "running-in", "initial_wear_coefficient": 1e-12, "running_in_distance": 1.0},
            update_contour=False,
        )
    with pytest.raises(ConfigError, match=r"^wear\.law: .*'power-law'"):
        config({"law": "power-law-ish"})


def test_a_law_that_reads_the_conditions_refuses_without_them() -> None:
    law = wear_law(config({"law": "power-law"}).wear, config({}).materials.bushing)
    with pytest.raises(ConfigError, match=r"^wear\.law: 'power-law' needs the sliding speed"):
        law(PRESSURE, SLIDING)


TABLE = {"law": "tabulated", "table_against": "speed"}


def tabulated_law(**wear):
    return wear_law(config({**TABLE, **wear}).wear, config({}).materials.bushing)


def test_a_flat_table_is_archard() -> None:
    law = tabulated_law(table_points=[0.0, 1.0], table_coefficients=[K, K])
    np.testing.assert_allclose(
        law(PRESSURE, SLIDING, WearConditions(SPEED)),
        archard.wear_depth(PRESSURE, SLIDING, K),
        rtol=1e-13,
    )


def test_a_table_in_speed_interpolates_linearly_step_by_step() -> None:
    """K(v) linear between (0, K) and (0.1 m/s, 3K): h_j = Σ_k K (1 + 20 v_k) p_jk Δs_k."""
    law = tabulated_law(table_points=[0.0, 0.1], table_coefficients=[K, 3 * K])
    expected = (SLIDING * K * (1 + 20 * SPEED)) @ PRESSURE
    np.testing.assert_allclose(law(PRESSURE, SLIDING, WearConditions(SPEED)), expected, rtol=1e-12)


def test_a_table_in_pv_reads_the_local_pressure() -> None:
    """K(pv) = K (1 + pv / 1e5 Pa m/s): h_j = K Σ_k (p + p² v / 1e5) Δs_k."""
    law = tabulated_law(
        table_against="pv", table_points=[0.0, 1e7], table_coefficients=[K, 101 * K]
    )
    expected = K * (SLIDING @ PRESSURE + (SLIDING * SPEED) @ PRESSURE**2 / 1e5)
    np.testing.assert_allclose(law(PRESSURE, SLIDING, WearConditions(SPEED)), expected, rtol=1e-12)


def test_beyond_the_table_its_end_values_are_used_with_one_warning() -> None:
    law = tabulated_law(table_points=[0.02, 0.03], table_coefficients=[K, 2 * K])
    slow, fast = np.full(40, 0.001), np.full(40, 1.0)
    with pytest.warns(MaterialLimitWarning, match=r"^wear\.table_points: the speed .*end values"):
        low = law(PRESSURE, SLIDING, WearConditions(slow))
    np.testing.assert_allclose(low, archard.wear_depth(PRESSURE, SLIDING, K), rtol=1e-13)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # said once per run
        high = law(PRESSURE, SLIDING, WearConditions(fast))
    np.testing.assert_allclose(high, archard.wear_depth(PRESSURE, SLIDING, 2 * K), rtol=1e-13)


def test_a_temperature_table_takes_the_operating_temperature_and_refuses_beyond() -> None:
    table = {"table_against": "temperature", "table_points": [293.0, 373.0]}
    law = tabulated_law(**table, table_coefficients=[K, 5 * K], temperature=353.0)
    np.testing.assert_allclose(
        law(PRESSURE, SLIDING, WearConditions(SPEED)),
        archard.wear_depth(PRESSURE, SLIDING, 4 * K),
        rtol=1e-13,
    )
    with pytest.raises(ConfigError, match=r"^wear\.temperature: 400 K is outside the table"):
        config({**TABLE, **table, "table_coefficients": [K, 5 * K], "temperature": 400.0})


@pytest.mark.parametrize(
    ("wear", "message"),
    [
        ({"table_points": [0.0, 1.0]}, r"^wear\.table_coefficients: missing"),
        (
            {"table_points": [0.0, 1.0], "table_coefficients": [K, K, K]},
            r"^wear\.table_coefficients: 3 values for 2 table_points",
        ),
        (
            {"table_points": [1.0, 1.0], "table_coefficients": [K, K]},
            r"^wear\.table_points: the points must increase strictly",
        ),
    ],
)
def test_a_malformed_table_is_refused(wear, message) -> None:
    with pytest.raises(ConfigError, match=message):
        config({**TABLE, **wear})


def test_a_run_with_a_speed_table_wears_faster_at_the_higher_speed() -> None:
    """A table rising with speed: at twice the frequency a cycle wears more (Archard: equal)."""
    wear = {**TABLE, "table_points": [0.0, 0.2], "table_coefficients": [K, 5 * K]}
    runs = [
        Simulation(config(wear, f, update_contour=False)).run(pressures=False)
        for f in ("0.5 Hz", "1 Hz")
    ]
    peaks = [r.summary()["peak_wear_depth_m"] for r in runs]
    assert peaks[1] > 1.05 * peaks[0]
