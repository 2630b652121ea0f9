"""Winkler's and NLCP's spring constants fitted to a reference; `compare-models --calibrate`."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from jointwear.cli import main
from jointwear.contact import ContactParameters, PowerLaw, solve, solve_contact
from jointwear.contact.winkler import foundation_modulus
from jointwear.geometry import BushingContour, Pin
from jointwear.references.spring_fit import calibrate_to_reference, fit_nlcp, fit_winkler


def _circle(params: ContactParameters) -> tuple[BushingContour, Pin]:
    return BushingContour.circle(params.bushing_radius, 360, params.axial_length), Pin(
        params.pin_radius
    )


def test_fit_recovers_known_laws(joint: ContactParameters) -> None:
    """Fitting to a reference made by the model itself returns the model's constants."""
    contour, pin = _circle(joint)
    loads = np.array([50.0, 100.0, 200.0, 400.0])
    azimuth = np.zeros_like(loads)
    k_true = 1.7e11
    ref = solve_contact(contour, pin, loads, azimuth, PowerLaw(k_true, 1.0, symmetric=True))
    fit = fit_winkler(joint, contour, pin, loads, ref, reference_name="synthetic")
    assert fit.values["stiffness_pa_per_m"] == pytest.approx(k_true, rel=1e-6)
    assert fit.rms_residual < 1e-8
    assert fit.equivalent["joint.bushing_thickness"] == pytest.approx(
        joint.bushing_youngs_modulus / k_true, rel=1e-6
    )
    c_true, n_true = 3e12, 1.2
    ref = solve_contact(contour, pin, loads, azimuth, PowerLaw(c_true, n_true))
    for target in ("pressure", "metrics"):
        fit = fit_nlcp(joint, contour, pin, loads, ref, target=target)
        assert fit.values["exponent"] == pytest.approx(n_true, rel=1e-4)
        assert fit.values["coefficient_pa_per_m_n"] == pytest.approx(c_true, rel=1e-3)


def test_winkler_fitted_to_fe_is_constrained_for_thin_wall(joint: ContactParameters) -> None:
    """Calibrated to the FE bushing, Winkler's stiffness lands on the constrained modulus."""
    thin = ContactParameters(
        joint.pin_radius,
        joint.bushing_radius,
        joint.axial_length,
        0.5e-3,
        joint.pin_youngs_modulus,
        joint.pin_poisson_ratio,
        joint.bushing_youngs_modulus,
        joint.bushing_poisson_ratio,
    )
    fits = calibrate_to_reference(thin, [400.0, 1000.0, 2000.0], "fem", models=("winkler",))
    fit = fits["winkler"]
    constrained = foundation_modulus(5e8, 0.38, "constrained") / 0.5e-3
    assert fit.values["stiffness_pa_per_m"] == pytest.approx(constrained, rel=0.05)
    assert fit.uncertainty["stiffness_pa_per_m"] < 0.05 * fit.values["stiffness_pa_per_m"]
    assert fit.equivalent["ratio_to_youngs_over_thickness"] > 1.7


def test_calibration_to_paper_joint_fe(joint: ContactParameters) -> None:
    fits = calibrate_to_reference(joint, [50.0, 100.0, 200.0, 400.0], "fem")
    assert set(fits) == {"winkler", "nlcp", "nlcp-k"}
    for fit in fits.values():
        assert fit.rms_residual < 0.1
        assert all(math.isfinite(v) for v in fit.uncertainty.values())
        json.dumps(fit.to_json())
    # the fitted laws do better than the paper's constants
    contour, pin = _circle(joint)
    loads = np.array([50.0, 100.0, 200.0, 400.0])
    ref = solve(contour, pin, loads, np.zeros(4), "fem", joint)
    paper = solve(contour, pin, loads, np.zeros(4), "winkler", joint)
    fitted = solve_contact(
        contour,
        pin,
        loads,
        np.zeros(4),
        PowerLaw(fits["winkler"].values["stiffness_pa_per_m"], 1.0, symmetric=True),
    )
    err_paper = np.abs(paper.pressure - ref.pressure).max()
    err_fitted = np.abs(fitted.pressure - ref.pressure).max()
    assert err_fitted < 0.5 * err_paper


def _run(capsys, *args: str) -> dict:
    main(["compare-models", *args, "--json"])
    out = capsys.readouterr().out.strip().splitlines()
    assert len(out) == 1
    return json.loads(out[0])


def test_cli_calibrate(capsys, paper_config_path: Path) -> None:
    data = _run(
        capsys,
        str(paper_config_path),
        "--loads",
        "100 N,300 N",
        "--models",
        "winkler",
        "--reference",
        "persson",
        "--calibrate",
    )
    assert data["reference"] == "persson"
    assert set(data["calibration"]) == {"winkler", "nlcp", "nlcp-k"}
    assert data["calibration"]["winkler"]["values"]["stiffness_pa_per_m"] > 0
