"""Calibrating the wear laws that follow how the joint runs, from several measured contours.

Truth: runs with known parameters; "measurements": their worn contours seen by a
synthetic instrument (random spacing, 0.5 um noise, shifted and rotated frame). The fit
must cover the truth with its 95 % intervals, and say when the cases cannot tell the
parameters apart.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from jointwear import Simulation
from jointwear.config import Config, config_from_dict
from jointwear.errors import FitMisfitWarning
from jointwear.measurement.parameter_fit import MeasuredCase, calibrate_profiles
from jointwear.measurement.synthetic import synthesize_measurement
from jointwear.workflows.parameter_fit import Parameter

KD = "materials.bushing.wear_coefficient"
B = "wear.speed_exponent"
K0 = "wear.initial_wear_coefficient"
LENGTH = "wear.running_in_distance"
NOISE = 0.5e-6  # [m]


def base(wear: dict, update: bool, **simulation) -> Config:
    return config_from_dict(
        {
            "mechanism": {
                "type": "oscillating",
                "load": "1.5 kN",
                "load_angle": "-90 deg",
                "amplitude": "25 deg",
                "frequency": "0.5 Hz",
            },
            "contact": {"nodes": 72},
            "simulation": {
                "steps_per_revolution": 24,
                "revolutions": 1000,
                "update_contour": update,
                **simulation,
            },
            "wear": wear,
        }
    )


def measure(truth: Config, overrides: dict, seed: int, name: str) -> MeasuredCase:
    depth = Simulation(truth.replace(overrides)).run(pressures=False).wear_depth
    x, y = synthesize_measurement(
        depth, truth.bushing_radius, 2400, NOISE, seed, (2e-3, -1e-3), math.radians(40 * seed)
    )
    return MeasuredCase(name, x, y, dict(overrides))


def covered(fit, truth: dict[str, float], widths: float = 1.5) -> None:
    """The truth within ``widths`` times the 95 % half-width (1.5: about 3 sigma)."""
    for parameter in fit.parameters:
        key, value = parameter.key, truth[parameter.key]
        low, high = fit.intervals[key]
        if parameter.logarithmic:
            value, low, high, fitted = map(math.log, (value, low, high, fit.values[key]))
        else:
            fitted = fit.values[key]
        half = (high - low) / 2
        assert abs(value - fitted) < widths * half, (key, value, fitted, half)


POWER = {"law": "power-law", "speed_exponent": 0.6}


def test_speed_exponent_and_coefficient_from_two_speeds() -> None:
    truth = base(POWER, update=False).replace({KD: 2e-12})
    cases = [
        measure(truth, {"mechanism.frequency": 0.25, "simulation.revolutions": 2000}, 1, "a"),
        measure(truth, {"mechanism.frequency": 2.0, "simulation.revolutions": 500}, 2, "b"),
    ]
    start = truth.replace({KD: 1e-12, B: 0.0})
    parameters = [Parameter(KD, 1e-13, 1e-10), Parameter(B, -0.5, 2.0)]
    with warnings.catch_warnings():
        warnings.simplefilter("error", FitMisfitWarning)
        fit = calibrate_profiles(start, cases, parameters)
    covered(fit, {KD: 2e-12, B: 0.6})
    assert fit.values[B] == pytest.approx(0.6, abs=0.05)
    assert fit.not_identifiable == {}
    assert fit.summary()["not_identifiable"] == {}


def test_one_speed_cannot_tell_the_exponent_from_the_coefficient() -> None:
    """At one speed only K_d v^b is measured: the fit says so instead of inventing both."""
    truth = base(POWER, update=False).replace({KD: 2e-12})
    cases = [
        measure(truth, {"simulation.revolutions": 2000}, 3, "a"),
        measure(truth, {"simulation.revolutions": 500}, 4, "b"),
    ]
    start = truth.replace({KD: 1e-12, B: 0.0})
    parameters = [Parameter(KD, 1e-13, 1e-10), Parameter(B, -0.5, 2.0)]
    with pytest.warns(FitMisfitWarning, match=r"wear\.speed_exponent is not identifiable"):
        fit = calibrate_profiles(start, cases, parameters)
    assert set(fit.not_identifiable) == {KD, B}
    # what the cases do fix: K_d v^b at that speed (within the noise)
    speed = 4 * math.radians(25) * truth.bushing_radius * 0.5  # mean sliding speed [m/s]
    assert np.isfinite(fit.values[KD] * speed ** fit.values[B])


@pytest.mark.slow
def test_running_in_from_contours_at_three_cycle_counts() -> None:
    """K_0 and lambda of running-in from bushings measured after 30, 100 and 1000 cycles.

    A cycle slides S = 4 A R_b = 13 mm: lambda = 0.8 m is 61 cycles, so the first two
    bushings are measured while the joint runs in (after it, only (K_0 - K_inf) lambda
    shows, and the fit says that the two are not identifiable on their own).
    """
    wear = {"law": "running-in", "initial_wear_coefficient": 3e-12, "running_in_distance": 0.8}
    truth = base(wear, update=True, update_every="adaptive")
    cases = [
        measure(truth, {"simulation.revolutions": n}, seed, f"{n}.csv")
        for seed, n in enumerate((30, 100, 1000), start=5)
    ]
    start = truth.replace({K0: 1e-12, LENGTH: 3.0})
    parameters = [Parameter(K0, 6e-13, 3e-11), Parameter(LENGTH, 0.05, 20.0)]
    fit = calibrate_profiles(start, cases, parameters)
    covered(fit, {K0: 3e-12, LENGTH: 0.8})
    assert fit.not_identifiable == {}
