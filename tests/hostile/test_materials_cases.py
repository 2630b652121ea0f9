"""Bad materials input: unknown names, clashing wear forms, wrong units (one line, exit 2)."""

from __future__ import annotations

import pytest

from tests.hostile.harness import Bad, check_contract, sweep_toml, tiny_toml

TWO_FORMS = tiny_toml().replace(
    'wear_coefficient = "5.05e-13 m^2/N"',
    'wear_coefficient = "5.05e-13 m^2/N"\nspecific_wear_rate = "1e-6 mm^3/(N m)"',
)

CASES: list[Bad] = [
    Bad(
        "material-unknown-name",
        "config",
        ["run", "{paper}", "--set", "materials.bushing=bronz"],
        ["materials.bushing", "unknown material 'bronz'", "did you mean 'bronze'"],
    ),
    Bad(
        "material-unknown-name-in-table",
        "config",
        ["run", "{tmp}/m.toml"],
        ["materials.bushing.name", "unknown material 'acetal'", "choose from"],
        {"m.toml": '[materials.bushing]\nname = "acetal"\n'},
    ),
    Bad(
        "material-not-a-name",
        "config",
        ["run", "{paper}", "--set", "materials.pin=5"],
        ["materials.pin", "expected a material name or a table"],
    ),
    Bad(
        "material-two-wear-forms",
        "config",
        ["run", "{tmp}/two.toml"],
        [
            "materials.bushing",
            "give one of wear_coefficient, specific_wear_rate",
            "not wear_coefficient and specific_wear_rate",
        ],
        {"two.toml": TWO_FORMS},
    ),
    Bad(
        "material-wear-factor-without-hardness",
        "config",
        ["run", "{paper}", "--set", "materials.bushing.wear_factor_k=1e-4"],
        ["materials.bushing.hardness", "missing", "wear_factor_k needs it"],
    ),
    Bad(
        "material-specific-wear-rate-as-volume",
        "config",
        ["run", "{paper}", "--set", "materials.bushing.specific_wear_rate=1e-6 mm^3"],
        ["materials.bushing.specific_wear_rate", "dimension", "expected a wear coefficient"],
    ),
    Bad(
        "material-pv-limit-as-pressure",
        "config",
        ["run", "{paper}", "--set", "materials.bushing.max_pv=1.75 MPa"],
        ["materials.bushing.max_pv", "expected a pressure velocity"],
    ),
    Bad(
        "material-misspelt-key",
        "config",
        [
            "run",
            "{paper}",
            "--set",
            "materials.bushing=bronze",
            "--set",
            "materials.bushing.specifc_wear_rate=1e-15",
        ],
        ["materials.bushing.specifc_wear_rate", "did you mean 'specific_wear_rate'"],
    ),
    Bad(
        "materials-command-unknown-name",
        "cli",
        ["materials", "brnze"],
        ["NAME", "unknown material 'brnze'", "did you mean 'bronze'"],
    ),
    Bad(
        "grease-without-boundary-coefficient",
        "config",
        ["run", "{paper}", "--set", "lubrication.lubricant=grease-lithium-nlgi2"],
        ["materials.bushing.boundary_wear_coefficient", "missing", "is a grease"],
    ),
    Bad(
        "material-wear-table-unknown-variable",
        "config",
        ["run", "{tmp}/t.toml"],
        ["materials.bushing.wear_table", "unknown variable 'pvv'", "did you mean 'pv'"],
        {
            "t.toml": '[materials.bushing]\nname = "pom"\n[materials.bushing.wear_table]\n'
            'against = "pvv"\npoints = [1.0, 2.0]\ncoefficients = [1e-15, 2e-15]\n'
        },
    ),
    Bad(
        "sweep-unknown-material",
        "sweep",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml", "materials.bushing = 'brnze'", "did you mean 'bronze'"],
        {
            "s.toml": sweep_toml('[grid]\n"materials.bushing" = ["bronze", "brnze"]\n'),
            "tiny.toml": "@tiny",
        },
    ),
]


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_bad_materials_input(case: Bad, tmp_path, capsys, result_bytes):
    check_contract(case, tmp_path, capsys, result_bytes)
