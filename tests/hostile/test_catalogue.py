"""Bad input, catalogued (docs/bad-input.md): one line on stderr, exit status 2, nothing left.

Every case runs the CLI in-process (``jointwear.cli.main``) and checks that

* the exit status is 2 (1 is reserved for internal errors),
* stderr is exactly one line, ``error: ...``, naming the key or file and the reason,
* there is no traceback and nothing on stdout,
* the ``--out`` directory (if any) holds no files: no results, no temporary files.

A few cases also run as real subprocesses, and ``--debug`` is checked to show the traceback.
"""

from __future__ import annotations

import subprocess
import sys

import pytest

from jointwear.cli import main
from jointwear.errors import JointwearError
from tests.hostile.harness import (  # noqa: F401
    COMMANDS,
    CSV_HEADER,
    GRID,
    PAPER,
    SMALL,
    Bad,
    check_contract,
    expand,
    files_in,
    materialise,
    run_cli,
    sweep_toml,
    tiny_toml,
)

#: a run of the paper's joint in the contact-impact dynamics, oiled
OILED_IMPACT = [
    "run",
    "{paper}",
    "--set",
    "dynamics.model=contact-impact",
    "--set",
    "lubrication.viscosity=0.1 Pa*s",
]
#: a valid duty cycle of two oscillating modes
DUTY = (
    '[mechanism]\ntype = "duty-cycle"\n'
    '[[mechanism.modes]]\ntype = "oscillating"\nshare = 0.4\nload = "1 kN"\n'
    'amplitude = "25 deg"\nfrequency = "1 Hz"\n'
    '[[mechanism.modes]]\ntype = "oscillating"\nshare = 0.6\nload = "2 kN"\n'
    'amplitude = "10 deg"\nfrequency = "1 Hz"\n'
)
CASES: list[Bad] = [
    # ------------------------------------------------------------ config files
    Bad(
        "config-file-missing",
        "config",
        ["run", "{tmp}/missing.toml"],
        ["missing.toml", "file not found"],
    ),
    Bad(
        "config-not-toml",
        "config",
        ["run", "{tmp}/bad.toml"],
        ["bad.toml", "not valid TOML"],
        {"bad.toml": "[joint\nclearance = 1\n"},
    ),
    Bad(
        "config-truncated",
        "config",
        ["run", "{tmp}/cut.toml"],
        ["cut.toml", "not valid TOML"],
        {"cut.toml": tiny_toml()[: tiny_toml().index("7.45") + 3]},
    ),
    Bad(
        "config-binary",
        "config",
        ["run", "{tmp}/bin.toml"],
        ["bin.toml", "cannot read"],
        {"bin.toml": b"\xff\xfe\x00\x81"},
    ),
    Bad("config-is-a-directory", "config", ["run", "{tmp}"], ["cannot read", "directory"]),
    Bad(
        "unknown-key-in-file",
        "config",
        ["run", "{tmp}/typo.toml"],
        ["joint.clearnce", "unknown key", "did you mean 'clearance'"],
        {"typo.toml": '[joint]\nclearnce = "0.1 mm"\n'},
    ),
    Bad(
        "unknown-section",
        "config",
        ["run", "{tmp}/typo.toml"],
        ["jiont", "unknown key", "did you mean 'joint'"],
        {"typo.toml": '[jiont]\nclearance = "0.1 mm"\n'},
    ),
    Bad(
        "unknown-key-set",
        "config",
        ["run", "{paper}", "--set", "materials.pin.densty=7800"],
        ["materials.pin.densty", "did you mean 'density'"],
    ),
    Bad(
        "mass-as-length",
        "config",
        ["run", "{paper}", "--set", "joint.clearance=5 kg"],
        ["joint.clearance", "'5 kg'", "expected a length"],
    ),
    Bad(
        "length-as-speed",
        "config",
        ["run", "{paper}", "--set", "mechanism.crank_speed=3 m"],
        ["mechanism.crank_speed", "expected an angular velocity"],
    ),
    Bad(
        "unknown-unit",
        "config",
        ["run", "{paper}", "--set", "joint.pin_radius=7 mmm"],
        ["joint.pin_radius", "cannot read '7 mmm'"],
    ),
    Bad(
        "text-for-integer",
        "config",
        ["run", "{paper}", "--set", "contact.nodes=many"],
        ["contact.nodes", "valid integer"],
    ),
    Bad(
        "fraction-for-integer",
        "config",
        ["run", "{paper}", "--set", "contact.nodes=90.5"],
        ["contact.nodes", "fractional part"],
    ),
    Bad(
        "text-for-boolean",
        "config",
        ["run", "{paper}", "--set", "simulation.update_contour=maybe"],
        ["simulation.update_contour", "valid boolean"],
    ),
    Bad(
        "boolean-for-quantity",
        "config",
        ["run", "{paper}", "--set", "joint.clearance=true"],
        ["joint.clearance", "boolean"],
    ),
    Bad(
        "pin-equals-bushing",
        "config",
        ["run", "{paper}", "--set", "joint.clearance=0"],
        ["joint.clearance", "greater than 0"],
    ),
    Bad(
        "pin-larger-than-bushing",
        "config",
        ["run", "{paper}", "--set", "joint.clearance=-0.1 mm"],
        ["joint.clearance", "greater than 0"],
    ),
    Bad(
        "negative-mass",
        "config",
        ["run", "{paper}", "--set", "mechanism.slider_mass=-5 kg"],
        ["mechanism.slider_mass", "greater than or equal to 0"],
    ),
    Bad(
        "zero-speed",
        "config",
        ["run", "{paper}", "--set", "mechanism.crank_speed=0 rpm"],
        ["mechanism.crank_speed", "greater than 0"],
    ),
    Bad(
        "nan",
        "config",
        ["run", "{paper}", "--set", "joint.clearance=nan"],
        ["joint.clearance", "must be finite"],
    ),
    Bad(
        "nan-with-unit",
        "config",
        ["run", "{paper}", "--set", "joint.clearance=nan mm"],
        ["joint.clearance", "must be finite"],
    ),
    Bad(
        "inf",
        "config",
        ["run", "{paper}", "--set", "materials.bushing.youngs_modulus=inf"],
        ["materials.bushing.youngs_modulus", "must be finite"],
    ),
    Bad(
        "poisson-ratio-0.5",
        "config",
        ["run", "{paper}", "--set", "materials.pin.poisson_ratio=0.5"],
        ["materials.pin.poisson_ratio", "less than 0.5"],
    ),
    Bad(
        "mechanism-cannot-assemble",
        "config",
        ["run", "{paper}", "--set", "mechanism.crank_length=250 mm"],
        ["mechanism.crank_length", "cannot assemble", "rod_length"],
    ),
    Bad(
        "unknown-contact-model",
        "config",
        ["run", "{paper}", "--set", "contact.model=nlcpp"],
        ["contact.model", "did you mean 'nlcp'"],
    ),
    Bad(
        "circular-model-on-a-worn-contour",
        "config",
        [
            "run",
            "{paper}",
            "--set",
            "contact.model=winkler",
            "--set",
            "simulation.update_contour=true",
        ],
        ["contact.model", "'winkler'", "cannot follow a worn contour", "'asymmetric-winkler'"],
    ),
    Bad(
        "hertz-on-a-worn-contour-in-a-life-study",
        "config",
        [
            "life",
            "{paper}",
            "--sample",
            "joint.clearance=uniform(low=0.05 mm, high=0.06 mm)",
            "--cases",
            "2",
            "--out",
            "{out}",
            "--set",
            "contact.model=hertz",
            "--set",
            "simulation.update_contour=true",
        ],
        ["contact.model", "'hertz'", "cannot follow a worn contour", "'nlcp'"],
    ),
    Bad(
        "persson-on-a-worn-contour-in-a-calibration",
        "config",
        [
            "calibrate",
            "{paper}",
            "{tmp}/ring.csv",
            "--fit",
            "wear_coefficient",
            "--set",
            "contact.model=persson",
            "--set",
            "simulation.update_contour=true",
        ],
        ["contact.model", "'persson'", "circular bushing only", "cannot follow a worn contour"],
        {"ring.csv": "x [mm],y [mm]\n7.5,0\n"},
    ),
    Bad(
        "fem-in-a-wear-run",
        "config",
        [
            "run",
            "{paper}",
            "--set",
            "contact.model=fem",
            "--set",
            "simulation.update_contour=true",
        ],
        ["contact.model", "'fem'", "every contour update", "'asymmetric-winkler'"],
    ),
    Bad(
        "nlcp-paper-form-off-its-mesh",
        "config",
        ["run", "{paper}", "--set", "contact.model=nlcp", "--set", "contact.nodes=720"],
        ["contact.nlcp_variant", "contact.nodes = 720", "0.5 x Archard's", "'mesh-independent'"],
    ),
    Bad(
        "unknown-choice",
        "config",
        ["run", "{paper}", "--set", "mechanism.spring_mode=pul"],
        ["mechanism.spring_mode", "did you mean 'pull'"],
    ),
    Bad(
        "int-or-adaptive",
        "config",
        ["run", "{paper}", "--set", "simulation.update_every=adaptiv"],
        ["simulation.update_every", "did you mean 'adaptive'"],
    ),
    Bad(
        "too-few-nodes",
        "config",
        ["run", "{paper}", "--set", "contact.nodes=8"],
        ["contact.nodes", "greater than or equal to 16"],
    ),
    Bad(
        "unknown-parameter-set",
        "config",
        ["run", "{paper}", "--set", "parameter_set=paper"],
        ["parameter_set", "did you mean 'nlcp-paper'"],
    ),
    Bad(
        "set-without-value",
        "config",
        ["run", "{paper}", "--set", "joint.clearance"],
        ["--set", "expected section.key=VALUE"],
    ),
    Bad(
        "set-below-a-value",
        "config",
        ["run", "{paper}", "--set", "joint.clearance.x=1"],
        ["joint.clearance.x", "is a value, not a section"],
    ),
    Bad(
        "value-for-a-section",
        "config",
        ["run", "{paper}", "--set", "joint=1"],
        ["joint", "valid dictionary"],
    ),
    # ------------------------------------------------------------ physics during a run
    Bad(
        "life-clearance-below-initial",
        "config",
        ["run", "{paper}", *SMALL, "--set", "life.clearance=0.01 mm"],
        ["life.clearance", "must exceed the initial clearance"],
    ),
    Bad(
        "life-wall-beyond-bushing",
        "config",
        ["run", "{paper}", *SMALL, "--set", "life.wall_thickness=3 mm"],
        ["life.wall_thickness", "must be below joint.bushing_thickness"],
    ),
    Bad(
        "bending-pin-on-one-slice",
        "config",
        ["run", "{paper}", *SMALL, "--set", "pin.model=beam", "--set", "pin.forks=[-0.015, 0.015]"],
        ["pin.model", 'a bending pin ("beam") needs joint.axial_slices >= 2'],
    ),
    Bad(
        "load-offset-outside-the-bushing",
        "config",
        [
            "run",
            "{paper}",
            *SMALL,
            "--set",
            "joint.axial_slices=5",
            "--set",
            "joint.load_offset=15 mm",
        ],
        ["joint.load_offset", "is outside the bushing"],
    ),
    Bad(
        "mechanism-type-unknown",
        "config",
        ["run", "{paper}", "--set", "mechanism.type=four-bars"],
        ["mechanism.type", "did you mean 'four-bar'"],
    ),
    Bad(
        "mechanism-key-of-another-type",
        "config",
        ["run", "{paper}", "--set", "mechanism.type=oscillating"],
        ["mechanism.crank_length: unknown key", "'amplitude'"],
    ),
    Bad(
        "contact-impact-for-a-prescribed-load",
        "config",
        ["dynamics", "{tmp}/history.toml", "--set", "dynamics.model=contact-impact"],
        ["dynamics.model", "prescribes its load"],
        files={
            "history.toml": '[mechanism]\ntype = "load-history"\nfile = "loads.csv"\n',
            "loads.csv": "time [ms],force_x [kN],force_y [kN],rotation [deg]\n0,1,0,0\n"
            "500,0,1,90\n1000,1,0,180\n",
        },
    ),
    Bad(
        "finite-length-film-in-contact-impact",
        "config",
        [*OILED_IMPACT, "--set", "lubrication.model=finite-length"],
        ["lubrication.model", "has no film in dynamics.model", "use 'long-bearing'"],
    ),
    Bad(
        "film-band-wider-than-the-clearance",
        "config",
        [
            *OILED_IMPACT,
            "--set",
            "lubrication.model=short-bearing",
            "--set",
            "lubrication.roughness=20 um",
        ],
        ["lubrication.roughness", "transition band", "narrower than the clearance"],
    ),
    Bad(
        "reynolds-cavitation-of-a-short-bearing",
        "config",
        [
            "run",
            "{paper}",
            "--set",
            "lubrication.model=short-bearing",
            "--set",
            "lubrication.viscosity=0.1 Pa*s",
            "--set",
            "lubrication.cavitation=Reynolds",
        ],
        ["lubrication.cavitation", "needs model = 'finite-length'"],
    ),
    Bad(
        "duty-cycle-shares-not-one",
        "config",
        ["run", "{tmp}/duty.toml"],
        ["mechanism.modes.share", "sum to 0.9, not 1"],
        files={
            "duty.toml": '[mechanism]\ntype = "duty-cycle"\n'
            '[[mechanism.modes]]\ntype = "oscillating"\nshare = 0.4\nload = "1 kN"\n'
            'amplitude = "25 deg"\nfrequency = "1 Hz"\n'
            '[[mechanism.modes]]\ntype = "oscillating"\nshare = 0.5\nload = "2 kN"\n'
            'amplitude = "10 deg"\nfrequency = "1 Hz"\n'
        },
    ),
    Bad(
        "duty-cycle-inside-a-duty-cycle",
        "config",
        ["run", "{tmp}/nested.toml"],
        ["mechanism.modes[0].type", "not another duty cycle"],
        files={
            "nested.toml": '[mechanism]\ntype = "duty-cycle"\n'
            '[[mechanism.modes]]\ntype = "duty-cycle"\nshare = 1.0\n'
        },
    ),
    Bad(
        "duty-cycle-mode-beyond-the-modes",
        "config",
        ["run", "{tmp}/duty.toml", "--set", "mechanism.modes.2.share=0.1"],
        ["mechanism.modes.2.share", "no mode 2", "has 2 modes"],
        files={"duty.toml": DUTY},
    ),
    Bad(
        "duty-cycle-mode-number-not-a-number",
        "config",
        ["run", "{tmp}/duty.toml", "--set", "mechanism.modes.last.share=0.1"],
        ["mechanism.modes.last.share", "'last' is not a mode's number"],
        files={"duty.toml": DUTY},
    ),
    Bad(
        "duty-cycle-mode-unknown-key",
        "config",
        ["run", "{tmp}/duty.toml", "--set", "mechanism.modes.1.frequncy=2 Hz"],
        ["mechanism.modes.1.frequncy", "did you mean 'frequency'"],
        files={"duty.toml": DUTY},
    ),
    Bad(
        "duty-cycle-share-set-off-the-sum",
        "config",
        ["run", "{tmp}/duty.toml", "--set", "mechanism.modes.0.share=0.6"],
        ["mechanism.modes.share", "sum to 1.2, not 1", "0.6 + 0.6"],
        files={"duty.toml": DUTY},
    ),
    Bad(
        "duty-cycle-mode-of-a-single-mechanism",
        "config",
        ["run", "{paper}", "--set", "mechanism.modes.0.share=1"],
        ["mechanism.modes.0.share", "no [[mechanism.modes]]", "duty-cycle"],
    ),
    Bad(
        "duty-cycle-mode-sampled-beyond-the-modes",
        "config",
        [
            "life",
            "{tmp}/duty.toml",
            "--sample",
            "mechanism.modes.3.frequency=uniform(low=30 rpm, high=90 rpm)",
            "--out",
            "{out}",
        ],
        ["[sample] mechanism.modes.3.frequency", "no mode 3", "has 2 modes"],
        files={"duty.toml": DUTY},
    ),
    Bad(
        "running-in-without-its-distance",
        "config",
        [
            "run",
            "{paper}",
            *SMALL,
            "--set",
            "wear.law=running-in",
            "--set",
            "wear.initial_wear_coefficient=1e-12",
        ],
        ["wear.running_in_distance: missing", "running-in"],
    ),
    Bad(
        "tabulated-temperature-outside-the-table",
        "config",
        ["run", "{tmp}/table.toml", *SMALL],
        ["wear.temperature", "outside the table", "not extrapolated"],
        files={
            "table.toml": '[wear]\nlaw = "tabulated"\ntable_against = "temperature"\n'
            "table_points = [293.0, 373.0]\ntable_coefficients = [5e-13, 2e-12]\n"
            "temperature = 400.0\n"
        },
    ),
    Bad(
        "no-convergence",
        "run",
        ["run", "{paper}", *SMALL, "--set", "contact.max_iterations=1"],
        ["did not converge", "contact.max_iterations"],
    ),
    # ------------------------------------------------------------ command line
    Bad(
        "unknown-option",
        "cli",
        ["run", "{paper}", "--frobnicate"],
        ["No such option: --frobnicate"],
    ),
    Bad(
        "unknown-command",
        "cli",
        ["rnu", "{paper}"],
        ["No such command 'rnu'", "'run'"],
        command="run",
    ),
    Bad("missing-config-argument", "cli", ["run"], ["CONFIG: missing"]),
    Bad(
        "checkpoint-without-out",
        "cli",
        ["run", "{paper}", "--checkpoint-every", "5"],
        ["--checkpoint-every", "needs --out"],
    ),
    Bad(
        "negative-checkpoint-interval",
        "cli",
        ["run", "{paper}", "--checkpoint-every", "-1"],
        ["--checkpoint-every", "must be >= 0"],
    ),
    Bad(
        "out-is-a-file",
        "cli",
        ["run", "{paper}", "--out", "{tmp}/afile"],
        ["--out", "afile", "not a directory"],
        {"afile": "x"},
    ),
    Bad(
        "resume-without-checkpoint",
        "cli",
        ["run", "--resume", "{tmp}"],
        ["no checkpoint to resume"],
    ),
    Bad(
        "resume-missing-directory",
        "cli",
        ["run", "--resume", "{tmp}/nowhere"],
        ["nowhere", "no such directory"],
    ),
    Bad(
        "resume-corrupt-checkpoint",
        "cli",
        ["run", "--resume", "{tmp}"],
        ["checkpoint.npz", "not a readable checkpoint"],
        {"checkpoint.toml": "@config", "checkpoint.npz": b"PK\x03\x04 truncated"},
    ),
    Bad(
        "force-as-length",
        "cli",
        ["contact", "{paper}", "--load", "5 m"],
        ["--load", "expected a force"],
    ),
    # ------------------------------------------------------------ data files
    Bad(
        "plot-garbage-netcdf",
        "data",
        ["plot", "{tmp}/broken.nc"],
        ["broken.nc", "not a readable netCDF result"],
        {"broken.nc": b"garbage\x00\x01"},
    ),
    Bad(
        "plot-truncated-netcdf",
        "data",
        ["plot", "{tmp}/cut.nc"],
        ["cut.nc", "not a readable netCDF result"],
        {"cut.nc": "@truncated-result"},
    ),
    Bad(
        "plot-foreign-netcdf",
        "data",
        ["plot", "{tmp}/other.nc"],
        ["other.nc", "not a jointwear result"],
        {"other.nc": "@foreign-netcdf"},
    ),
    Bad(
        "plot-missing-file", "data", ["plot", "{tmp}/missing.nc"], ["missing.nc", "file not found"]
    ),
    Bad(
        "plot-bad-magnification",
        "data",
        ["plot", "{tmp}/result.nc", "--magnification", "-1"],
        ["--magnification", "positive"],
        {"result.nc": "@result"},
    ),
    Bad(
        "measure-garbage-csv",
        "data",
        ["measure", "{tmp}/bad.csv", "--radius", "7.5 mm"],
        ["bad.csv"],
        {"bad.csv": "hello world\nfoo bar\n"},
    ),
    Bad(
        "measure-truncated-csv",
        "data",
        ["measure", "{tmp}/cut.csv", "--radius", "7.5 mm"],
        ["cut.csv", "line 3"],
        {"cut.csv": CSV_HEADER + "7.5,0\n0\n"},
    ),
    Bad(
        "measure-empty-csv",
        "data",
        ["measure", "{tmp}/empty.csv", "--radius", "7.5 mm"],
        ["empty.csv", "no data"],
        {"empty.csv": ""},
    ),
    Bad(
        "measure-nan-in-csv",
        "data",
        ["measure", "{tmp}/nan.csv", "--radius", "7.5 mm"],
        ["nan.csv", "non-finite"],
        {"nan.csv": CSV_HEADER + "7.5,nan\n0,7.5\n-7.5,0\n"},
    ),
    Bad(
        "measure-too-few-points",
        "data",
        ["measure", "{tmp}/few.csv", "--radius", "7.5 mm"],
        ["few.csv", "need at least"],
        {"few.csv": CSV_HEADER + "7.5,0\n0,7.5\n"},
    ),
    Bad(
        "measure-missing-file",
        "data",
        ["measure", "{tmp}/none.csv", "--radius", "7.5 mm"],
        ["none.csv", "file not found"],
    ),
    Bad(
        "measure-radius-as-mass",
        "data",
        ["measure", "{tmp}/few.csv", "--radius", "5 kg"],
        ["--radius", "expected a length"],
        {"few.csv": CSV_HEADER + "7.5,0\n"},
    ),
    Bad(
        "measure-radius-missing",
        "data",
        ["measure", "{tmp}/few.csv"],
        ["Missing option", "--radius"],
        {"few.csv": CSV_HEADER + "7.5,0\n"},
    ),
    # ------------------------------------------------------------ sweep files
    Bad(
        "sweep-file-missing",
        "sweep",
        ["sweep", "{tmp}/none.toml", "--out", "{out}"],
        ["none.toml", "file not found"],
    ),
    Bad(
        "sweep-not-toml",
        "sweep",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml", "not valid TOML"],
        {"s.toml": "[grid\n"},
    ),
    Bad(
        "sweep-unknown-config-key",
        "sweep",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml", "joint.clearnce", "did you mean 'clearance'"],
        {"s.toml": sweep_toml('[grid]\n"joint.clearnce" = [1e-4]\n'), "tiny.toml": "@tiny"},
    ),
    Bad(
        "sweep-unknown-table",
        "sweep",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml", "'grd'", "did you mean 'grid'"],
        {"s.toml": sweep_toml('[grd]\n"joint.clearance" = [1e-4]\n'), "tiny.toml": "@tiny"},
    ),
    Bad(
        "sweep-mass-as-length",
        "sweep",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml", "[grid] joint.clearance = '5 kg'", "expected a length"],
        {"s.toml": sweep_toml('[grid]\n"joint.clearance" = ["5 kg"]\n'), "tiny.toml": "@tiny"},
    ),
    Bad(
        "sweep-zip-lengths",
        "sweep",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml", "same length"],
        {
            "s.toml": sweep_toml(
                '[zip]\n"contact.model" = ["nlcp", "winkler"]\n"contact.exponent" = [1.5]\n'
            ),
            "tiny.toml": "@tiny",
        },
    ),
    Bad(
        "sweep-circular-model-on-a-worn-contour",
        "sweep",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml", "[set]", "contact.model", "'winkler'", "cannot follow a worn contour"],
        {
            "s.toml": sweep_toml(
                '"contact.model" = "winkler"\n"simulation.update_contour" = true\n' + GRID
            ),
            "tiny.toml": "@tiny",
        },
    ),
    Bad(
        "sweep-unknown-distribution",
        "sweep",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml", "unknown distribution 'lognormel'", "did you mean 'lognormal'"],
        {
            "s.toml": sweep_toml(
                '[sample]\n"joint.clearance" = {distribution = "lognormel", '
                'median = "0.1 mm", sigma = 0.1}\nsamples = 2\n'
            ),
            "tiny.toml": "@tiny",
        },
    ),
    Bad(
        "sweep-missing-samples",
        "sweep",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml", "samples: missing"],
        {
            "s.toml": sweep_toml(
                '[sample]\n"joint.clearance" = {distribution = "uniform", '
                'low = "0.05 mm", high = "0.1 mm"}\n'
            ),
            "tiny.toml": "@tiny",
        },
    ),
    Bad(
        "sweep-missing-base",
        "sweep",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml", "nobase.toml", "file not found"],
        {"s.toml": 'base = "nobase.toml"\n' + GRID},
    ),
    Bad(
        "sweep-zero-workers",
        "sweep",
        ["sweep", "{tmp}/s.toml", "--out", "{out}", "--workers", "0"],
        ["--workers", "must be >= 1"],
        {"s.toml": sweep_toml(GRID), "tiny.toml": "@tiny"},
    ),
    Bad(
        "sweep-without-out",
        "sweep",
        ["sweep", "{tmp}/s.toml"],
        ["--out: missing"],
        {"s.toml": sweep_toml(GRID), "tiny.toml": "@tiny"},
    ),
    Bad(
        "sweep-resume-not-a-sweep",
        "sweep",
        ["sweep", "--resume", "{tmp}"],
        ["not a sweep directory"],
    ),
    Bad(
        "sweep-bad-scheduler-address",
        "sweep",
        ["sweep", "{tmp}/s.toml", "--out", "{out}", "--scheduler", "notanaddress"],
        ["--scheduler", "cannot connect to notanaddress"],
        {"s.toml": sweep_toml(GRID), "tiny.toml": "@tiny"},
    ),
]


# ---------------------------------------------------------------- the catalogue


def test_catalogue_is_large_enough():
    assert len(CASES) >= 30
    assert len({c.id for c in CASES}) == len(CASES)
    assert {c.area for c in CASES} == {"config", "run", "cli", "data", "sweep"}


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_bad_input(case: Bad, tmp_path, capsys, result_bytes):
    check_contract(case, tmp_path, capsys, result_bytes)


# ---------------------------------------------------------------- real processes


SUBPROCESS_CASES = [
    "mass-as-length",
    "mechanism-type-unknown",
    *(
        pytest.param(name, marks=pytest.mark.slow)
        for name in ("plot-garbage-netcdf", "unknown-option", "sweep-unknown-config-key")
    ),
]


@pytest.mark.parametrize("case_id", SUBPROCESS_CASES)
def test_bad_input_in_a_real_process(case_id, tmp_path, result_bytes):
    case = next(c for c in CASES if c.id == case_id)
    materialise(tmp_path, case.files, result_bytes)
    out = tmp_path / "out"
    argv = expand(case.argv, tmp_path, out)
    if case.area == "run":
        argv += ["--out", str(out), "--json", "--no-plots"]
    done = subprocess.run(
        [sys.executable, "-m", "jointwear", *argv],
        capture_output=True,
        text=True,
        check=False,
        timeout=120,
    )
    assert done.returncode == 2, done.stderr
    assert done.stdout == ""
    lines = done.stderr.splitlines()
    assert len(lines) == 1, done.stderr
    assert lines[0].startswith("error: ")
    assert all(fragment in lines[0] for fragment in case.expect)
    assert files_in(out) == []


def test_debug_shows_the_traceback(capsys):
    with pytest.raises(JointwearError, match="joint.clearance"):
        main(["--debug", "run", str(PAPER), "--set", "joint.clearance=5 kg"])
    done = subprocess.run(
        [
            sys.executable,
            "-m",
            "jointwear",
            "--debug",
            "run",
            str(PAPER),
            "--set",
            "joint.clearance=5 kg",
        ],
        capture_output=True,
        text=True,
        check=False,
        timeout=120,
    )
    assert "Traceback" in done.stderr
    assert "ConfigError" in done.stderr


def test_internal_errors_exit_1(monkeypatch, capsys):
    import jointwear.simulation

    def broken(self, *args, **kwargs):
        raise ZeroDivisionError("a bug")

    monkeypatch.setattr(jointwear.simulation.Simulation, "run", broken)
    code, _, stderr = run_cli(capsys, ["run", str(PAPER)])
    assert code == 1
    assert stderr.startswith("internal error: ZeroDivisionError: a bug")
    assert "--debug" in stderr
