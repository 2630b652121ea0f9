"""The plan of a sweep: grid, zip and samples expanded, bad files refused, stored."""

from __future__ import annotations

import json

import numpy as np
import pytest

from jointwear.errors import ConfigError, DataError
from jointwear.workflows.sweep import SweepPlan, expand_sweep, load_plan, load_sweep
from tests.workflows.sweep.conftest import TINY, write_sweep

# ---------------------------------------------------------------- expansion


def test_grid_is_the_cartesian_product_in_file_order(base):
    plan = expand_sweep(
        {
            "grid": {
                "joint.clearance": ["0.05 mm", "0.1 mm", 2e-4],
                "mechanism.crank_speed": ["120 rpm", "240 rpm"],
            }
        },
        base,
    )
    assert plan.keys == ["joint.clearance", "mechanism.crank_speed"]
    assert [c.overrides for c in plan.cases][:3] == [
        {"joint.clearance": "0.05 mm", "mechanism.crank_speed": "120 rpm"},
        {"joint.clearance": "0.05 mm", "mechanism.crank_speed": "240 rpm"},
        {"joint.clearance": "0.1 mm", "mechanism.crank_speed": "120 rpm"},
    ]
    assert len(plan.cases) == 6
    assert plan.config(plan.cases[5]).joint.clearance == pytest.approx(2e-4)
    assert plan.config(plan.cases[5]).mechanism.crank_speed == pytest.approx(8 * np.pi)


def test_zip_goes_row_by_row_and_multiplies_the_grid(base):
    plan = expand_sweep(
        {
            "grid": {"joint": {"clearance": ["0.05 mm", "0.1 mm"]}},  # nested table form
            "zip": {"contact.model": ["winkler", "nlcp"], "contact.exponent": [1.0, 1.5]},
        },
        base,
    )
    assert len(plan.cases) == 4
    assert plan.cases[1].overrides == {
        "joint.clearance": "0.05 mm",
        "contact.model": "nlcp",
        "contact.exponent": 1.5,
    }


def test_zip_lists_of_different_length_fail(base):
    with pytest.raises(ConfigError, match=r"\[zip\] lists must have the same length"):
        expand_sweep(
            {"zip": {"contact.model": ["winkler", "nlcp"], "contact.exponent": [1.0]}}, base
        )


def test_samples_are_seeded_and_reproducible(base):
    spec = {
        "sample": {
            "materials.bushing.wear_coefficient": {
                "distribution": "lognormal",
                "median": "5.05e-13 m^2/N",
                "sigma": 0.5,
            },
            "joint.clearance": {"distribution": "uniform", "low": "0.05 mm", "high": "0.2 mm"},
            "contact.nodes": {"distribution": "loguniform", "low": 40, "high": 90},
            "mechanism.spring_preload": {"distribution": "normal", "mean": "20 N", "std": "1 N"},
            "contact.model": {"distribution": "choice", "values": ["winkler", "nlcp"]},
        },
        "samples": 50,
        "seed": 7,
    }
    first, again = expand_sweep(spec, base), expand_sweep(spec, base)
    assert [c.overrides for c in first.cases] == [c.overrides for c in again.cases]
    other = expand_sweep({**spec, "seed": 8}, base)
    assert [c.overrides for c in first.cases] != [c.overrides for c in other.cases]
    k = np.array([c.overrides["materials.bushing.wear_coefficient"] for c in first.cases])
    assert 1e-13 < np.median(k) < 2e-12  # SI (1/Pa), around the median
    clearance = np.array([c.overrides["joint.clearance"] for c in first.cases])
    assert clearance.min() >= 5e-5
    assert clearance.max() <= 2e-4
    assert all(isinstance(c.overrides["contact.nodes"], int) for c in first.cases)
    assert {c.overrides["contact.model"] for c in first.cases} == {"winkler", "nlcp"}
    assert all(c.invalid is None for c in first.cases)


def test_samples_and_seed_may_follow_the_sample_table(tmp_path):
    path = write_sweep(
        tmp_path,
        TINY
        + """
        [sample]
        "joint.clearance" = {distribution = "uniform", low = "0.05 mm", high = "0.2 mm"}
        samples = 3
        seed = 2
    """,
    )
    plan = load_sweep(path)
    assert len(plan.cases) == 3
    assert plan.seed == 2


def test_set_applies_to_every_case(tmp_path):
    plan = load_sweep(
        write_sweep(
            tmp_path,
            TINY
            + """
        [grid]
        "joint.clearance" = ["0.05 mm", "0.1 mm"]
    """,
        )
    )
    assert plan.base.contact.nodes == 60
    assert all(plan.config(c).simulation.revolutions == 1 for c in plan.cases)


@pytest.mark.parametrize(
    ("body", "message"),
    [
        ('[grid]\n"joint.clearnce" = [1e-4]', "unknown key 'clearnce'.*did you mean 'clearance'"),
        ('[grid]\n"jont.clearance" = [1e-4]', "did you mean 'joint'"),
        ('[grid]\n"joint.clearance" = ["5 kg"]', r"\[grid\] joint.clearance = '5 kg'.*dimension"),
        ('[grid]\n"joint.clearance" = 1e-4', "expected a list of values"),
        ('[grid]\n"joint.clearance" = []', "empty"),
        ('[grid]\n"contact.model" = ["nlcpp"]', "did you mean 'nlcp'"),
        ('[grids]\n"joint.clearance" = [1e-4]', "unknown key 'grids'.*did you mean 'grid'"),
        ("samples = 3", "given without a .sample. table"),
        (
            '[sample]\n"joint.clearance" = {distribution = "gauss", mean = 1}\nsamples = 2',
            "unknown distribution 'gauss'",
        ),
        (
            '[sample]\n"joint.clearance" = {distribution = "uniform", low = 1e-4}\nsamples = 2',
            "high missing",
        ),
        (
            '[sample]\n"joint.clearance" = {distribution = "uniform", low = 2e-4, high = 1e-4}\n'
            "samples = 2",
            "low < high",
        ),
        (
            '[sample]\n"joint.clearance" = {distribution = "uniform", low = "1 kg", high = 1}\n'
            "samples = 2",
            "dimension",
        ),
        (
            '[sample]\n"contact.model" = {distribution = "uniform", low = 1, high = 2}\n'
            "samples = 2",
            "use 'choice'",
        ),
        (
            '[grid]\n"joint.clearance" = [1e-4]\n[zip]\n"joint.clearance" = [1e-4]',
            "appears in both",
        ),
        ('[grid]\n"joint" = [1]', "is a section"),
        ("", "nothing to sweep"),
    ],
)
def test_bad_sweep_files_fail_before_running(tmp_path, body, message):
    path = write_sweep(tmp_path, body)
    with pytest.raises(ConfigError, match=message) as info:
        load_sweep(path)
    assert str(info.value).startswith(str(path))
    assert "\n" not in str(info.value)


def test_missing_base_names_the_file(tmp_path):
    path = write_sweep(tmp_path, '[grid]\n"joint.clearance" = [1e-4]', base="nope.toml")
    with pytest.raises(ConfigError, match=r"base = 'nope.toml'.*nope.toml: file not found"):
        load_sweep(path)


def test_stored_plan_gives_the_same_case_configs(base):
    """Derived defaults (rod inertia, spring area) follow the swept keys after --resume too."""
    plan = expand_sweep(
        {
            "grid": {
                "mechanism.rod_mass": ["1 kg", "3 kg"],
                "joint.axial_length": ["10 mm", "30 mm"],
            }
        },
        base,
    )
    again = SweepPlan.from_dict(json.loads(json.dumps(plan.to_dict())), "plan")
    configs = [plan.config(c) for c in plan.cases]
    assert [again.config(c).to_dict() for c in again.cases] == [c.to_dict() for c in configs]
    assert configs[0].spring_area != configs[1].spring_area
    assert (
        configs[0].mechanism.rod_centroidal_inertia != configs[2].mechanism.rod_centroidal_inertia
    )


def test_resume_of_a_non_sweep_directory(tmp_path):
    with pytest.raises(DataError, match="not a sweep directory"):
        load_plan(tmp_path)
