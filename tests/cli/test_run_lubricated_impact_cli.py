"""``jointwear run`` of a lubricated joint in the contact-impact dynamics.

The separating slider-crank (push spring, light rod, 0.2 mm clearance, 240 rpm) hits
its bushing dry; an oil film of 1 Pa s (short bearing) keeps the pin off the wall
(Flores et al., Nonlinear Dyn. 56 (2009) 277-295: the film cushions the impacts), so
the run sees no impact, a lower joint force and no solid contact to wear.
"""

from __future__ import annotations

import json

import pytest
import xarray as xr

from jointwear.cli import main
from jointwear.mechanism.slider_crank.contact_impact import impact_kernel

pytestmark = pytest.mark.skipif(
    impact_kernel() is None, reason="numba missing or JOINTWEAR_NO_NUMBA set"
)

SEPARATING = [
    "dynamics.model=contact-impact",
    "mechanism.spring_mode=push",
    "mechanism.spring_preload=1 N",
    "mechanism.crank_speed=240 rpm",
    "joint.clearance=0.2 mm",
    "mechanism.rod_mass=0.3 kg",
    f"mechanism.rod_inertia={0.3 * 0.2**2 / 12}",
    "contact.nodes=120",
    "simulation.steps_per_revolution=90",
]
OIL = ["lubrication.model=short-bearing", "lubrication.viscosity=1 Pa*s"]
FILM_KEYS = ("film_model", "max_eccentricity_ratio", "min_film_thickness_m", "peak_joint_force_n")


def run(config, out, settings: list[str], capsys) -> tuple[dict, xr.Dataset]:
    arguments = [f"--set={setting}" for setting in settings]
    main(["run", str(config), *arguments, "--out", str(out), "--json", "--no-plots", "-q"])
    summary = json.loads(capsys.readouterr().out)
    with xr.open_dataset(out / "result.nc") as dataset:
        return summary, dataset.load()


def test_an_oil_film_keeps_the_pin_off_the_wall(paper_config_path, tmp_path, capsys) -> None:
    dry, dry_data = run(paper_config_path, tmp_path / "dry", SEPARATING, capsys)
    wet, wet_data = run(paper_config_path, tmp_path / "wet", SEPARATING + OIL, capsys)
    # observed: dry 9 impacts, peak contact force 493 N; oiled 0 impacts, max |e|/c 0.86,
    # peak joint force 214 N (the mechanism's inertia load)
    assert dry_data["dynamics_impacts"].values[-1] >= 2
    assert wet_data["dynamics_impacts"].values[-1] == 0
    for key in FILM_KEYS:
        assert key not in dry
    assert wet["film_model"] == "short-bearing"
    assert wet["max_eccentricity_ratio"] < 1.0
    clearance = 0.2e-3
    assert wet["min_film_thickness_m"] == pytest.approx(
        clearance * (1.0 - wet["max_eccentricity_ratio"]), rel=1e-12, abs=0
    )
    assert wet["peak_joint_force_n"] < 0.6 * dry_data["dynamics_peak_load"].values[-1]
    # the film carries the pin throughout: no solid contact, nothing wears
    assert wet_data["joint_load"].values.max() == 0.0
    assert wet["wear_volume_m3"] == 0.0 < dry["wear_volume_m3"]
    # the dynamics carried the film: the load cycle's film sharing did not run again
    assert "film_parameter" not in wet_data
    for name in ("max_eccentricity_ratio", "min_film_thickness", "peak_joint_force"):
        variable = wet_data[f"dynamics_{name}"]
        assert variable.attrs["units"] in {"1", "m", "N"}
        assert variable.attrs["long_name"]
    written = json.loads((tmp_path / "wet" / "summary.json").read_text(encoding="utf-8"))
    assert {key: written[key] for key in FILM_KEYS} == {key: wet[key] for key in FILM_KEYS}
