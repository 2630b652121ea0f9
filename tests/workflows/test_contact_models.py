"""Contact models against a reference: the reference always compared, its own deviation zero."""

from __future__ import annotations

import pytest

from jointwear.errors import ConfigError
from jointwear.workflows.contact_models import PLOT_FILES, compare_contact_models


def test_the_reference_joins_the_models_and_deviates_from_itself_by_nothing(
    paper_config_path, tmp_path
):
    out = tmp_path / "out"
    done = compare_contact_models(
        paper_config_path,
        "100 N,0.4 kN",
        models=["winkler,nlcp"],
        reference="hertz",
        out=out,
        overrides=["contact.nodes=180"],
    )
    assert list(done.comparison.models) == ["winkler", "nlcp", "hertz"]
    assert done.summary["reference"] == "hertz"
    assert done.comparison.loads_n == pytest.approx([100.0, 400.0])
    deviation = done.comparison.deviation("hertz")
    for key in ("half_angle_deg", "peak_pressure_pa", "approach_m"):
        assert list(deviation["hertz"][key]) == pytest.approx([0.0, 0.0], abs=1e-12)
    # a larger load spreads the contact: the half-angle grows with the load
    low, high = done.comparison.models["hertz"]["half_angle_deg"]
    assert high > low
    assert sorted(p.name for p in done.plots) == sorted(PLOT_FILES)
    assert sorted(p.name for p in out.iterdir()) == sorted(PLOT_FILES)
    assert done.fits == {}


@pytest.mark.parametrize(
    ("options", "message"),
    [
        ({"models": ["nlcpp"]}, "--models: unknown contact model 'nlcpp'; did you mean 'nlcp'"),
        ({"reference": "fen"}, "--reference: unknown contact model"),
        ({"target": "peak"}, "--target: unknown 'peak'"),
        ({"calibrate": True, "reference": "hertz"}, "--calibrate: the reference must be"),
    ],
)
def test_unknown_names_are_refused_before_any_solve(paper_config_path, options, message):
    with pytest.raises(ConfigError, match=message):
        compare_contact_models(paper_config_path, "100 N", **options)


def test_one_load_is_carried_along_its_direction(paper_config_path):
    """The pressure's resultant balances the load along it and nothing sideways."""
    from jointwear.workflows.contact_models import contact_on_unworn_bushing

    done = contact_on_unworn_bushing(paper_config_path, "0.3 kN", "30 deg", model="winkler")
    assert done.load == pytest.approx(300.0)
    assert done.summary["contact_model"] == "winkler"
    assert done.summary["resultant_normal_n"] == pytest.approx(300.0, rel=1e-6)
    assert abs(done.summary["resultant_tangential_n"]) < 1e-6 * 300.0
    with pytest.raises(ConfigError, match="--load: must be >= 0"):
        contact_on_unworn_bushing(paper_config_path, "-1 N")
