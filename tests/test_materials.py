"""The materials library and how a config names a material (jointwear.materials)."""

from __future__ import annotations

import tomllib
from importlib.resources import files
from pathlib import Path

import pytest
from pydantic.fields import FieldInfo

from jointwear import load_config
from jointwear.config import config_from_dict, is_section, key_field
from jointwear.config.parameter_sets import get_parameter_set
from jointwear.errors import ConfigError
from jointwear.materials import (
    KINDS,
    LIMIT_KEYS,
    TABLE_KEY,
    WEAR_FORMS,
    get_material,
    library,
    markdown,
    merge_material,
)
from jointwear.workflows.sweep import expand_sweep

REQUIRED = {
    "ptfe",
    "ptfe-glass",
    "ptfe-fabric",
    "pom",
    "pa66",
    "uhmwpe",
    "bronze",
    "steel",
    "alumina",
}


def raw_library() -> dict:
    text = files("jointwear").joinpath("data", "materials.toml").read_text(encoding="utf-8")
    return tomllib.loads(text)


# ---------------------------------------------------------------- the data file


def test_library_has_the_materials_a_designer_expects():
    assert set(library()) >= REQUIRED


def test_every_value_has_a_source():
    for name, table in raw_library().items():
        assert table.get("description"), name
        for key, entry in table.items():
            if key == "description":
                continue
            assert key in KINDS or key == TABLE_KEY, (name, key)
            assert set(entry) == {"value", "source"}, (name, key)
            assert len(entry["source"].strip()) > 10, (name, key)


def test_every_material_is_complete_and_wear_coefficients_say_how_good_they_are():
    for name, material in library().items():
        for key in ("youngs_modulus", "poisson_ratio", "density", "wear_coefficient"):
            assert material.si(key) is not None, (name, key)
        forms = [f for f in WEAR_FORMS if any(k in material.values for k in f)]
        assert len(forms) == 1, name
        # a wear coefficient is a property of a pair, not of a material: never precise
        for key in forms[0]:
            source = material.sources[key]
            assert "order of magnitude" in source or "NLCP paper" in source or key == "hardness"


def test_values_lie_in_physical_ranges():
    for name, material in library().items():
        assert 1e8 < material.si("youngs_modulus") < 1e12, name
        assert 0 < material.si("poisson_ratio") < 0.5, name
        assert 500 < material.si("density") < 20000, name
        assert 1e-18 < material.si("wear_coefficient") < 1e-11, name
        limits = [material.si(k) for k in LIMIT_KEYS]
        assert all(v is None or v > 0 for v in limits), name


def test_bearing_datasheet_values_are_the_published_ones():
    # PV limits in MPa m/s, from psi ft/min tables: 50 000 psi ft/min = 1.75 MPa m/s
    assert get_material("bronze-sintered").si("max_pv") == pytest.approx(1.75e6)
    assert get_material("bronze").si("max_pv") == pytest.approx(2.625e6)
    assert get_material("pa66").si("max_pv") == pytest.approx(0.105e6)
    # polymers are two orders softer than metals; PTFE wears far faster than filled PTFE
    assert (
        get_material("ptfe").si("youngs_modulus")
        < get_material("bronze").si("youngs_modulus") / 100
    )
    assert get_material("ptfe").si("wear_coefficient") > 10 * get_material("ptfe-glass").si(
        "wear_coefficient"
    )


def test_ptfe_is_the_papers_default_bushing_exactly():
    defaults = get_parameter_set("nlcp-paper")["materials"]["bushing"]
    ptfe = get_material("ptfe")
    for key, value in defaults.items():
        assert ptfe.si(key) == value, key
    named = load_config(overrides={"materials.bushing": "ptfe"}).materials.bushing
    default = load_config().materials.bushing
    for key in ("youngs_modulus", "poisson_ratio", "density", "wear_coefficient"):
        assert getattr(named, key) == getattr(default, key)


def test_docs_page_shows_the_library_as_it_is():
    page = Path(__file__).resolve().parents[1] / "docs" / "materials.md"
    assert markdown() in page.read_text(encoding="utf-8"), (
        "docs/materials.md is out of date: paste jointwear.materials.markdown() into it"
    )


# ---------------------------------------------------------------- config


def test_a_name_gives_the_librarys_values_and_limits(paper_config_path):
    bushing = load_config(paper_config_path, ["materials.bushing=bronze"]).materials.bushing
    bronze = get_material("bronze")
    assert bushing.name == "bronze"
    assert bushing.youngs_modulus == 100e9
    assert bushing.density == bronze.si("density")
    assert bushing.wear_coefficient == pytest.approx(1e-6 / 640e6, rel=1e-12, abs=0)
    assert bushing.max_pv == pytest.approx(2.625e6)


def test_name_with_overrides_and_no_defaults_leaking_in(tmp_path):
    path = tmp_path / "c.toml"
    path.write_text(
        '[materials.bushing]\nname = "bronze"\nyoungs_modulus = "105 GPa"\n'
        '[materials.pin]\nname = "steel"\n',
        encoding="utf-8",
    )
    materials = load_config(path).materials
    assert materials.bushing.youngs_modulus == 105e9
    assert materials.bushing.poisson_ratio == 0.34  # bronze's, not the PTFE default's 0.38
    assert materials.bushing.density == 8930.0
    assert materials.pin.youngs_modulus == 210e9
    # a named pin takes its elastic data only: it wears only if its table says so
    assert materials.pin.wear_coefficient is None


@pytest.mark.parametrize(
    ("overrides", "expected"),
    [
        ({"materials.bushing.specific_wear_rate": "1e-6 mm^3/(N m)"}, 1e-15),
        ({"materials.bushing.specific_wear_rate": "1e-6 mm**3/(N*m)"}, 1e-15),
        ({"materials.bushing.wear_factor_k": 1e-4, "materials.bushing.hardness": "200 MPa"}, 5e-13),
        (
            {"materials.bushing": "bronze", "materials.bushing.wear_coefficient": "3e-15 m^2/N"},
            3e-15,
        ),
    ],
)
def test_wear_forms_convert_to_k_d(paper_config_path, overrides, expected):
    # the paper file gives wear_coefficient: a --set wear form replaces it
    bushing = load_config(paper_config_path, overrides).materials.bushing
    assert bushing.wear_coefficient == pytest.approx(expected, rel=1e-12, abs=0)


def test_the_pin_wears_only_where_its_table_gives_a_wear_form(paper_config_path):
    cfg = load_config(
        paper_config_path, {"materials.pin": "steel", "materials.pin.wear_factor_k": 1e-6}
    )
    assert cfg.materials.pin.wear_coefficient == pytest.approx(1e-6 / 7.5e9, rel=1e-6, abs=0)


def test_two_wear_forms_in_one_table_are_refused(tmp_path):
    path = tmp_path / "c.toml"
    path.write_text(
        '[materials.bushing]\nyoungs_modulus = "1 GPa"\npoisson_ratio = 0.3\ndensity = 1000\n'
        'wear_coefficient = 1e-15\nspecific_wear_rate = "1e-6 mm^3/(N m)"\n',
        encoding="utf-8",
    )
    with pytest.raises(ConfigError, match=r"^materials\.bushing: give one of wear_coefficient"):
        load_config(path)


@pytest.mark.parametrize(
    ("override", "message"),
    [
        (
            "materials.bushing=bronz",
            "materials.bushing: unknown material 'bronz'; did you mean 'bronze'?",
        ),
        ("materials.bushing.name=pomm", "materials.bushing.name: unknown material 'pomm'"),
        ("materials.bushing.wear_factor_k=1e-4", "materials.bushing.hardness: missing"),
        ("materials.bushing.hardness=1e9", "materials.bushing.wear_factor_k: missing"),
        ("materials.bushing.max_pv=-1", "materials.bushing.max_pv"),
        ("materials.bushing.max_pv=1 MPa", "materials.bushing.max_pv"),
        ("materials.bushing.specifc_wear_rate=1", "did you mean 'specific_wear_rate'"),
    ],
)
def test_bad_materials_name_the_key(paper_config_path, override, message):
    with pytest.raises(ConfigError) as info:
        load_config(paper_config_path, [override])
    assert message in str(info.value)
    assert "\n" not in str(info.value)


def test_keys_resolve_for_set_sweeps_and_calibration():
    assert isinstance(key_field("materials.bushing"), FieldInfo)
    assert is_section("materials.bushing")  # [grid.materials.bushing] tables still flatten
    assert is_section("materials")
    assert not is_section("materials.bushing.max_pv")
    for key in ("specific_wear_rate", "wear_factor_k", "hardness", "name", "max_pv"):
        assert isinstance(key_field(f"materials.bushing.{key}"), FieldInfo)


def test_to_toml_round_trips_named_and_overridden_materials(paper_config_path):
    cfg = load_config(
        paper_config_path,
        [
            "materials.bushing=bronze",
            "materials.pin=steel",
            "materials.bushing.youngs_modulus=105 GPa",
        ],
    )
    again = config_from_dict(tomllib.loads(cfg.to_toml()))
    assert again.materials == cfg.materials
    assert again.to_dict() == cfg.to_dict()


def test_replace_switches_material_by_name(paper_config_path):
    cfg = load_config(paper_config_path, ["materials.bushing=bronze"])
    pom = cfg.replace({"materials.bushing.name": "pom"}).materials.bushing
    # a new name starts from the library, not from bronze's values
    assert pom == cfg.replace({"materials.bushing": "pom"}).materials.bushing
    assert pom.youngs_modulus == 2.8e9
    assert pom.max_sliding_speed is None


def test_merge_material_rules():
    base = {"youngs_modulus": 1.0, "wear_coefficient": 2.0}
    assert merge_material(base, "pom") == "pom"
    assert merge_material(base, {"name": "pom"}) == {"name": "pom"}
    assert merge_material("pom", {"density": 3}) == {"name": "pom", "density": 3}
    assert merge_material(base, {"specific_wear_rate": 3.0}) == {
        "youngs_modulus": 1.0,
        "specific_wear_rate": 3.0,
    }
    # the two keys of k/H keep each other
    both = merge_material(merge_material(base, {"wear_factor_k": 1e-4}), {"hardness": 1e9})
    assert both == {"youngs_modulus": 1.0, "wear_factor_k": 1e-4, "hardness": 1e9}


def test_a_sweep_over_the_bushing_material(paper_config_path):
    base = load_config(paper_config_path)
    plan = expand_sweep({"grid": {"materials.bushing": ["bronze", "pom", "ptfe"]}}, base)
    configs = [plan.config(case) for case in plan.cases]
    assert [c.materials.bushing.name for c in configs] == ["bronze", "pom", "ptfe"]
    assert all(case.invalid is None for case in plan.cases)
    with pytest.raises(ConfigError, match="did you mean 'bronze'"):
        expand_sweep({"grid": {"materials.bushing": ["brnze"]}}, base)


# ---------------------------------------------------------------- tabulated coefficients

#: a test entry (test values, not data): bushing elastic data and wear tables
ELASTIC = """
youngs_modulus = { value = "100 GPa", source = "test" }
poisson_ratio = { value = 0.34, source = "test" }
density = { value = "8930 kg/m^3", source = "test" }
wear_coefficient = { value = "2e-15 m^2/N", source = "test" }
"""


def table_entry(name: str, table: str, source: str = "test") -> str:
    """A library entry of ``name`` whose ``wear_table`` value is the TOML ``table``."""
    return (
        f"[{name}]\ndescription = 'test entry'\n{ELASTIC}"
        f"[{name}.wear_table]\nsource = '{source}'\n[{name}.wear_table.value]\n{table}\n"
    )


PV_TABLE = """against = "pv"
points = ["1 Pa*m/s", "1 MPa*m/s"]
coefficients = ["2e-6 mm^3/(N m)", "2e-15 m^2/N"]"""
HOT_TABLE = """against = "temperature"
points = ["20 degC", "100 degC"]
coefficients = ["1e-15 m^2/N", "3e-15 m^2/N"]"""
TABLE_ENTRIES = table_entry("table-test", PV_TABLE, "test source, table 9") + table_entry(
    "table-test-temperature", HOT_TABLE
)


@pytest.fixture
def with_tables(monkeypatch):
    """The library with the test entries added (test tables, not data)."""
    from types import MappingProxyType

    import jointwear.materials as materials

    entries = {**library(), **materials.read_library(TABLE_ENTRIES)}
    monkeypatch.setattr(materials, "library", lambda: MappingProxyType(entries))
    return entries


def test_a_library_table_is_read_into_si(with_tables):
    pv = with_tables["table-test"].wear_table()
    assert pv == {"against": "pv", "points": [1.0, 1e6], "coefficients": [2e-15, 2e-15]}
    hot = with_tables["table-test-temperature"].wear_table()
    assert hot["points"] == pytest.approx([293.15, 373.15], abs=1e-12)


@pytest.mark.parametrize(
    ("table", "message"),
    [
        ('against = "pvv"\npoints = [1, 2]\ncoefficients = [1e-15, 1e-15]', "did you mean 'pv'"),
        ('against = "pv"\npoints = [2, 1]\ncoefficients = [1e-15, 1e-15]', "increase strictly"),
        ('against = "pv"\npoints = [1, 2]\ncoefficients = [1e-15]', "one coefficient per point"),
        ('against = "speed"\npoints = ["1 MPa", 2]\ncoefficients = [1, 2]', "velocity"),
    ],
)
def test_a_malformed_library_table_is_refused_in_one_line(table: str, message: str):
    from jointwear.materials import read_library

    with pytest.raises(ConfigError, match=message) as refused:
        read_library(table_entry("table-test", table))
    assert "\n" not in str(refused.value)
    assert "table-test.wear_table" in str(refused.value)


def _run(config):
    from jointwear import Simulation

    return Simulation(config).run(pressures=False).wear_depth


@pytest.fixture
def table_joint(with_tables, paper_config_path):
    return load_config(
        paper_config_path,
        overrides={
            "materials.bushing": "table-test",
            "contact.nodes": 72,
            "simulation.steps_per_revolution": 72,
            "simulation.update_contour": False,
        },
    )


def test_naming_the_material_runs_its_table(table_joint):
    """The library's table is the [wear] table: the same wear, number for number; a flat
    table at the material's K_d is Archard's law; twice the table, twice the wear."""
    import numpy as np

    tabulated = table_joint.replace({"wear.law": "tabulated"})
    assert tabulated.materials.bushing.wear_table.against == "pv"
    by_name = _run(tabulated)
    written = {
        "wear.table_against": "pv",
        "wear.table_points": [1.0, 1e6],
        "wear.table_coefficients": [2e-15, 2e-15],
    }
    np.testing.assert_array_equal(by_name, _run(tabulated.replace(written)))
    np.testing.assert_allclose(by_name, _run(table_joint), rtol=1e-12, atol=0)
    doubled = {**written, "wear.table_coefficients": [4e-15, 4e-15]}
    np.testing.assert_allclose(_run(tabulated.replace(doubled)), 2 * by_name, rtol=1e-14, atol=0)


def test_a_temperature_table_interpolates_and_refuses_extrapolation(with_tables, table_joint):
    """Half-way between 20 and 100 degC the coefficient is the mean of the two points:
    the wear of Archard's law with K_d = 2e-15, the entry's own coefficient."""
    import numpy as np

    hot = table_joint.replace({"materials.bushing": "table-test-temperature"})
    midway = hot.replace({"wear.law": "tabulated", "wear.temperature": 333.15})
    np.testing.assert_allclose(_run(midway), _run(hot), rtol=1e-12, atol=0)
    with pytest.raises(ConfigError, match="outside the table.*not extrapolated"):
        hot.replace({"wear.law": "tabulated", "wear.temperature": 400.0})


def test_a_config_may_write_the_bushings_table(paper_config_path):
    table = {"against": "pv", "points": ["1 kPa*m/s", "1 MPa*m/s"], "coefficients": [1e-15] * 2}
    config = load_config(
        paper_config_path,
        overrides={
            "materials.bushing": {"name": "pom", "wear_table": table},
            "wear.law": "tabulated",
        },
    )
    assert config.materials.bushing.wear_table.points == [1e3, 1e6]


def test_a_tabulated_law_needs_a_table_somewhere(paper_config_path):
    with pytest.raises(ConfigError, match="wear.table_against: missing.*wear_table"):
        load_config(paper_config_path, overrides={"wear.law": "tabulated"})


def test_the_materials_command_lists_the_table_with_its_source(with_tables, capsys):
    import json

    from jointwear.cli import main

    main(["materials", "table-test"])
    out = capsys.readouterr().out
    assert "wear_table" in out
    assert "test source, table 9" in out
    assert "points [Pa m/s]: 1, 1e+06" in out
    main(["materials", "table-test", "--json"])
    entry = json.loads(capsys.readouterr().out)["materials"]["table-test"]
    assert entry["wear_table"]["points"] == [1.0, 1e6]
    assert entry["sources"]["wear_table"] == "test source, table 9"


def test_the_documented_skf_table_follows_skfs_rating_life():
    """docs/materials.md's PTFE composite table is SKF's G_h = K_M / (pv)_eff with
    K_M = 480, (pv)_eff = max(pv, 0.025) MPa m/s, read as K_d = h_L (pv)_eff / (K_M pv)
    at h_L = 0.3 mm (hours to seconds, MPa to Pa), to its three digits."""
    page = (Path(__file__).resolve().parents[1] / "docs" / "materials.md").read_text("utf-8")
    block = page.split("[materials.bushing.wear_table]")[-1].split("```")[0]
    table = tomllib.loads(block)
    from jointwear.materials import wear_table

    si = wear_table(table, "docs")
    for pv, k in zip(si["points"], si["coefficients"], strict=True):
        mpa_m_s = pv / 1e6
        expected = 0.3e-3 * max(mpa_m_s, 0.025) / (480 * mpa_m_s * 3600 * 1e6)
        assert k == pytest.approx(expected, rel=5e-3, abs=0)


# ---------------------------------------------------------------- bronze's table (SKF)

#: SKF, Spherical plain bearings and rod ends (PUB BU/P1 06116/1 EN, 2013), table 5, p. 52:
#: the temperature factor b2 of the steel/bronze rating life, by band of operating
#: temperature: (upper end of the band [degC], b2); above 180 degC SKF gives none
SKF_B2 = ((120.0, 1.0), (160.0, 0.9), (180.0, 0.8))


def skf_b2(celsius: float) -> float:
    """SKF's ``b2`` at ``celsius`` [degC]: the band whose upper end (inclusive) comes first."""
    return next(b2 for upper, b2 in SKF_B2 if celsius <= upper)


def kelvin(celsius: float) -> float:
    from jointwear.units import registry

    return registry().Quantity(celsius, "degC").to("K").magnitude


def test_bronzes_table_is_its_coefficient_over_skfs_temperature_factor():
    """Every point of bronze's table is K_d / b2(T), K_d the entry's own coefficient and b2
    SKF's band value (a point 1 K past a band's end is in the next band); the table spans
    -30 degC (SKF's lower end for steel/bronze rod ends) to 180 degC (the end of SKF's table)."""
    from jointwear.units import registry

    bronze = get_material("bronze")
    table = bronze.wear_table()
    assert table["against"] == "temperature"
    assert table["points"][0] == pytest.approx(kelvin(-30.0), abs=1e-9)
    assert table["points"][-1] == pytest.approx(kelvin(180.0), abs=1e-9)
    k_d = bronze.si("wear_coefficient")
    bands = set()
    for point, coefficient in zip(table["points"], table["coefficients"], strict=True):
        celsius = registry().Quantity(point, "K").to("degC").magnitude
        assert coefficient == pytest.approx(k_d / skf_b2(celsius), rel=1e-7, abs=0), celsius
        bands.add(skf_b2(celsius))
    assert bands == {b2 for _, b2 in SKF_B2}
    assert "table 5 p. 52" in bronze.sources["wear_table"]


@pytest.fixture
def bronze_joint(paper_config_path):
    """The paper's joint with a bronze bushing (coarse grid, no contour update: the wear
    is linear in K_d)."""
    return load_config(
        paper_config_path,
        overrides={
            "materials.bushing": "bronze",
            "contact.nodes": 72,
            "simulation.steps_per_revolution": 72,
            "simulation.update_contour": False,
        },
    )


def test_bronze_wears_by_skfs_temperature_factor(bronze_joint):
    """At 100 degC (b2 = 1) the tabulated law is Archard's law with bronze's K_d; at 140
    degC the wear is 1/0.9 of that, at 170 degC 1/0.8 = 1.25 times."""
    import numpy as np

    def at(celsius: float):
        return _run(
            bronze_joint.replace({"wear.law": "tabulated", "wear.temperature": kelvin(celsius)})
        )

    cool = at(100.0)
    np.testing.assert_allclose(cool, _run(bronze_joint), rtol=1e-12, atol=0)
    np.testing.assert_allclose(at(140.0), cool / 0.9, rtol=1e-7, atol=0)
    hot = at(170.0)
    np.testing.assert_allclose(hot, cool / 0.8, rtol=1e-7, atol=0)
    assert hot.max() == pytest.approx(1.25 * cool.max(), rel=1e-7, abs=0)


@pytest.mark.parametrize("celsius", [-40.0, 185.0])
def test_bronzes_table_refuses_a_temperature_outside_it(bronze_joint, celsius: float):
    """Below -30 degC and above 180 degC SKF gives no factor: the run is refused in one line
    naming the key, not extrapolated."""
    with pytest.raises(ConfigError, match=r"wear\.temperature: .* outside the table") as refused:
        bronze_joint.replace({"wear.law": "tabulated", "wear.temperature": kelvin(celsius)})
    assert "\n" not in str(refused.value)
    assert "not extrapolated" in str(refused.value)


def test_wear_temperature_reads_a_temperature_with_its_unit(bronze_joint):
    """``wear.temperature = "170 degC"`` is 443.15 K (an offset unit, not a factor), and a
    text that is no temperature is refused in one line naming the key."""
    tabulated = bronze_joint.replace({"wear.law": "tabulated", "wear.temperature": "170 degC"})
    assert tabulated.wear.temperature == pytest.approx(443.15, rel=1e-12, abs=0)
    with pytest.raises(ConfigError, match=r"wear\.temperature") as refused:
        bronze_joint.replace({"wear.law": "tabulated", "wear.temperature": "170 mm"})
    assert "\n" not in str(refused.value)
