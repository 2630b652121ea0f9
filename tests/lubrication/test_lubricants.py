"""The lubricants library and the viscosity-temperature relation."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear.errors import ConfigError
from jointwear.lubrication.lubricants import (
    density,
    dynamic_viscosity,
    get_lubricant,
    kinematic_viscosity,
    library,
)

CELSIUS = 273.15


@pytest.mark.parametrize("name", list(library()))
def test_the_two_tabulated_viscosities_are_reproduced_exactly(name):
    entry = library()[name]
    values = kinematic_viscosity(name, np.array([40.0, 100.0]) + CELSIUS)
    np.testing.assert_allclose(
        values, [entry.kinematic_viscosity_40, entry.kinematic_viscosity_100], rtol=1e-12
    )


@pytest.mark.parametrize("name", list(library()))
def test_viscosity_falls_monotonically_with_temperature(name):
    temperatures = np.linspace(-10.0, 150.0, 321) + CELSIUS
    assert np.all(np.diff(kinematic_viscosity(name, temperatures)) < 0)
    assert np.all(np.diff(dynamic_viscosity(name, temperatures)) < 0)


def test_iso_grades_are_their_midpoints_and_thicker_grades_are_thicker():
    oils = [e for e in library().values() if e.name.startswith("iso-vg-")]
    grades = [int(e.name.removeprefix("iso-vg-")) for e in oils]
    assert grades == [10, 15, 22, 32, 46, 68, 100, 150, 220, 320, 460, 680]
    for oil, grade in zip(oils, grades, strict=True):
        assert oil.kinematic_viscosity_40 == pytest.approx(grade * 1e-6)
        assert oil.regime == "hydrodynamic"
    at_60 = [kinematic_viscosity(oil, 60 + CELSIUS) for oil in oils]
    assert np.all(np.diff(at_60) > 0)


def test_greases_are_flagged_as_boundary_lubrication():
    greases = [e for e in library().values() if e.name.startswith("grease-")]
    assert len(greases) >= 2
    assert all(g.regime == "boundary" for g in greases)


def test_every_value_has_a_source():
    for entry in library().values():
        assert set(entry.sources) == {
            "kinematic_viscosity_40",
            "kinematic_viscosity_100",
            "density",
            "thermal_expansion",
            "regime",
        }
        assert all(source.strip() for source in entry.sources.values())


def test_dynamic_viscosity_is_kinematic_times_density():
    oil = get_lubricant("iso-vg-68")
    assert density(oil, 15 + CELSIUS) == pytest.approx(oil.density)
    assert density(oil, 80 + CELSIUS) < oil.density
    t = 55 + CELSIUS
    assert dynamic_viscosity("iso-vg-68", t) == pytest.approx(
        kinematic_viscosity(oil, t) * density(oil, t)
    )
    # ISO VG 68 at 40 degC: 68 mm^2/s times about 0.87 g/cm^3
    assert dynamic_viscosity("iso-vg-68", 40 + CELSIUS) == pytest.approx(0.059, rel=0.02)


def test_an_unknown_lubricant_is_refused_with_the_closest_name():
    with pytest.raises(
        ConfigError, match=r"lubricant: unknown lubricant 'iso-vg-64'; did you mean 'iso-vg-68'\?"
    ):
        dynamic_viscosity("iso-vg-64", 313.15)


@pytest.mark.parametrize("written", ["ISO VG 100", "iso vg 100", "ISO_VG_100", " iso-vg-100 "])
def test_a_grade_written_as_on_the_can_is_the_library_entry(written):
    assert get_lubricant(written) is get_lubricant("iso-vg-100")


def test_a_config_keeps_the_library_name_of_a_grade_written_with_spaces():
    from jointwear.config.sections import LubricationConfig

    section = LubricationConfig(model="short-bearing", lubricant="ISO VG 100")
    assert section.lubricant == "iso-vg-100"
    with pytest.raises(ValueError, match=r"unknown lubricant 'ISO VG 99'; did you mean 'iso-vg-"):
        LubricationConfig(model="short-bearing", lubricant="ISO VG 99")
