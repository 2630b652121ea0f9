"""Hostile numbers: booleans, integers of hundreds of digits, absurd magnitudes, angles.

Every number a user gives (config file, ``--set``, options, sweep values, data files) is
finite, within physical bounds and really a number: ``true`` is not 1, an integer of 400
digits is refused with one line (not an ``OverflowError``), ``1e308 deg`` is no angle.
"""

from __future__ import annotations

import pytest

from jointwear import load_config
from jointwear.errors import ConfigError
from tests.hostile.harness import CSV_HEADER, GRID, PAPER, Bad, check_contract, sweep_toml

HUGE = "1" + "0" * 400  # an integer of 401 digits
BEYOND_PYTHON = "1" * 5000  # beyond Python's integer-to-text conversion limit
RUN = ["run", "{paper}", "--out", "{out}"]
SWING = (
    '[mechanism]\ntype = "oscillating"\nload = "1 kN"\namplitude = "25 deg"\nfrequency = "1 Hz"\n'
)
RESULT_AND_CSV = {"result.nc": "@result", "ring.csv": CSV_HEADER + "7.5,0\n"}


def _set(key_value: str) -> list[str]:
    return [*RUN, "--set", key_value]


CASES: list[Bad] = [
    # ------------------------------------------------------------ booleans are not numbers
    Bad(
        "boolean-for-exponent",
        "numbers",
        _set("contact.exponent=true"),
        ["contact.exponent", "expected a number, got a boolean"],
    ),
    Bad(
        "boolean-for-exponent-in-file",
        "numbers",
        ["run", "{tmp}/b.toml", "--out", "{out}"],
        ["contact.exponent", "got a boolean"],
        {"b.toml": "[contact]\nexponent = true\n"},
    ),
    Bad(
        "boolean-for-revolutions",
        "numbers",
        _set("simulation.revolutions=true"),
        ["simulation.revolutions", "got a boolean"],
    ),
    Bad(
        "boolean-for-nodes",
        "numbers",
        _set("contact.nodes=false"),
        ["contact.nodes", "got a boolean"],
    ),
    Bad(
        "boolean-for-mass-in-file",
        "numbers",
        ["run", "{tmp}/b.toml", "--out", "{out}"],
        ["mechanism.crank_mass", "boolean"],
        {"b.toml": "[mechanism]\ncrank_mass = true\n"},
    ),
    Bad(
        "boolean-for-poisson-ratio",
        "numbers",
        _set("materials.pin.poisson_ratio=true"),
        ["materials.pin.poisson_ratio", "boolean"],
    ),
    Bad(
        "boolean-for-restitution",
        "numbers",
        _set("dynamics.restitution=true"),
        ["dynamics.restitution", "boolean"],
    ),
    Bad(
        "boolean-for-load-harmonic",
        "numbers",
        ["run", "{tmp}/swing.toml", "--out", "{out}", "--set", "mechanism.load_harmonic=true"],
        ["mechanism.load_harmonic", "boolean"],
        {"swing.toml": SWING},
    ),
    Bad(
        "boolean-for-stiffness",
        "numbers",
        _set("contact.stiffness=true"),
        ["contact.stiffness", "boolean"],
    ),
    Bad(
        "boolean-in-sweep-grid",
        "numbers",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml", "[grid] contact.exponent", "boolean"],
        {"s.toml": sweep_toml('[grid]\n"contact.exponent" = [1.5, true]\n'), "tiny.toml": "@tiny"},
    ),
    Bad(
        "boolean-in-sweep-set",
        "numbers",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml", "contact.exponent", "boolean"],
        {
            "s.toml": 'base = "tiny.toml"\n[set]\n"contact.exponent" = true\n' + GRID,
            "tiny.toml": "@tiny",
        },
    ),
    Bad(
        "boolean-as-distribution-bound",
        "numbers",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml", "[sample] joint.clearance.low", "boolean"],
        {
            "s.toml": sweep_toml(
                '[sample]\n"joint.clearance" = {distribution = "uniform", low = true, '
                'high = "0.1 mm"}\nsamples = 2\n'
            ),
            "tiny.toml": "@tiny",
        },
    ),
    # ------------------------------------------------------------ integers of hundreds of digits
    Bad(
        "hundred-digit-integer-for-length",
        "numbers",
        _set(f"joint.clearance={HUGE}"),
        ["joint.clearance", "(401 chars)", "beyond any physical value"],
    ),
    Bad(
        "hundred-digit-integer-for-exponent",
        "numbers",
        ["run", "{tmp}/b.toml", "--out", "{out}"],
        ["contact.exponent", "beyond any physical value"],
        {"b.toml": f"[contact]\nexponent = {HUGE}\n"},
    ),
    Bad(
        "hundred-digit-integer-for-count",
        "numbers",
        _set(f"simulation.update_every={HUGE}"),
        ["simulation.update_every", "beyond any physical value"],
    ),
    Bad(
        "hundred-digit-integer-for-checkpoints",
        "numbers",
        _set(f"simulation.checkpoint_every={HUGE}"),
        ["simulation.checkpoint_every", "beyond any physical value"],
    ),
    Bad(
        "integer-beyond-python-limit-set",
        "numbers",
        _set(f"simulation.update_every={BEYOND_PYTHON}"),
        ["simulation.update_every", "(5002 chars)", "beyond any physical value"],
    ),
    Bad(
        "integer-beyond-python-limit-in-file",
        "numbers",
        ["run", "{tmp}/big.toml", "--out", "{out}"],
        ["big.toml", "not readable TOML", "4300 digits"],
        {"big.toml": f"[simulation]\nrevolutions = {BEYOND_PYTHON}\n"},
    ),
    Bad(
        "hundred-digit-integer-in-sweep-grid",
        "numbers",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml", "[grid] joint.clearance", "beyond any physical value"],
        {"s.toml": sweep_toml(f'[grid]\n"joint.clearance" = [{HUGE}]\n'), "tiny.toml": "@tiny"},
    ),
    Bad(
        "hundred-digit-integer-in-csv",
        "numbers",
        ["measure", "{tmp}/big.csv", "--radius", "7.5 mm"],
        ["big.csv", "non-finite"],
        {"big.csv": CSV_HEADER + f"{HUGE},0\n0,7.5\n-7.5,0\n"},
    ),
    # ------------------------------------------------------------ counts beyond any run
    Bad(
        "revolutions-beyond-bound",
        "numbers",
        _set("simulation.revolutions=1000000000000"),
        ["simulation.revolutions", "less than or equal to 1000000000"],
    ),
    Bad(
        "update-interval-beyond-bound",
        "numbers",
        _set("simulation.update_every=1e12"),
        ["simulation.update_every", "less than or equal to 1000000000"],
    ),
    Bad(
        "checkpoint-interval-beyond-bound",
        "numbers",
        _set("simulation.checkpoint_every=1e12"),
        ["simulation.checkpoint_every", "less than or equal to 1000000000"],
    ),
    Bad(
        "dynamics-update-beyond-bound",
        "numbers",
        _set("simulation.dynamics_update=1e12"),
        ["simulation.dynamics_update", "less than or equal to 1000000000"],
    ),
    # ------------------------------------------------------------ absurd magnitudes
    Bad(
        "absurd-modulus",
        "numbers",
        _set("materials.pin.youngs_modulus=1e200"),
        ["materials.pin.youngs_modulus", "beyond any physical value", "1e+100"],
    ),
    Bad(
        "absurd-length-with-unit",
        "numbers",
        _set("joint.axial_length=1e120 mm"),
        ["joint.axial_length", "beyond any physical value"],
    ),
    Bad(
        "absurd-angle-in-file",
        "numbers",
        ["run", "{tmp}/swing.toml", "--out", "{out}", "--set", "mechanism.load_angle=1e308 deg"],
        ["mechanism.load_angle", "'1e308 deg'", "beyond any physical value"],
        {"swing.toml": SWING},
    ),
    Bad(
        "angle-beyond-two-turns",
        "numbers",
        ["run", "{tmp}/swing.toml", "--out", "{out}", "--set", "mechanism.load_phase=1000 deg"],
        ["mechanism.load_phase", "less than or equal to 12.56"],
        {"swing.toml": SWING},
    ),
    Bad(
        "azimuth-absurd",
        "numbers",
        ["contact", "{paper}", "--load", "1 kN", "--azimuth", "1e308 deg"],
        ["--azimuth", "beyond any physical value"],
    ),
    Bad(
        "azimuth-fifty-turns",
        "numbers",
        ["contact", "{paper}", "--load", "1 kN", "--azimuth", "18000 deg"],
        ["--azimuth", "not a direction angle", "720 deg"],
    ),
    Bad(
        "angle-offset-absurd",
        "numbers",
        ["measure", "{tmp}/ring.csv", "--radius", "7.5 mm", "--angle-offset", "1e50 deg"],
        ["--angle-offset", "not a direction angle"],
        {"ring.csv": CSV_HEADER + "7.5,0\n"},
    ),
    Bad(
        "align-absurd",
        "numbers",
        ["compare", "{tmp}/result.nc", "{tmp}/ring.csv", "--align", "1e6 deg"],
        ["--align", "not a direction angle"],
        RESULT_AND_CSV,
    ),
    Bad(
        "overflowing-load",
        "numbers",
        ["contact", "{paper}", "--load", "1e400 N"],
        ["--load", "must be finite"],
    ),
    Bad(
        "overflowing-loads-list",
        "numbers",
        ["compare-models", "{paper}", "--loads", "1 kN,1e400 N"],
        ["--loads", "must be finite"],
    ),
    Bad(
        "nan-in-toml-file",
        "numbers",
        ["run", "{tmp}/n.toml", "--out", "{out}"],
        ["joint.clearance", "must be finite"],
        {"n.toml": "[joint]\nclearance = nan\n"},
    ),
    Bad(
        "inf-in-toml-file",
        "numbers",
        ["run", "{tmp}/n.toml", "--out", "{out}"],
        ["materials.bushing.youngs_modulus", "must be finite"],
        {"n.toml": "[materials.bushing]\nyoungs_modulus = -inf\n"},
    ),
    Bad(
        "nan-standard-deviation",
        "numbers",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml", "[sample] joint.clearance.std", "must be finite"],
        {
            "s.toml": sweep_toml(
                '[sample]\n"joint.clearance" = {distribution = "normal", mean = "0.1 mm", '
                "std = nan}\nsamples = 2\n"
            ),
            "tiny.toml": "@tiny",
        },
    ),
    Bad(
        "nan-threshold",
        "numbers",
        ["measure", "{tmp}/ring.csv", "--radius", "7.5 mm", "--threshold", "nan"],
        ["--threshold", "must be in [0, 1)"],
        {"ring.csv": CSV_HEADER + "7.5,0\n"},
    ),
    Bad(
        "infinite-magnification",
        "numbers",
        ["plot", "{tmp}/result.nc", "--magnification", "1e400"],
        ["--magnification", "positive number"],
        {"result.nc": "@result"},
    ),
]

#: a history whose time column carries an unbounded unit expression
HISTORY = "time [9**9**9 s],force_x [N],force_y [N],rotation [rad]\n0,1,0,0\n0.5,1,0,3\n"

UNIT_CASES: list[Bad] = [
    # ------------------------------------------------------------ unit expressions
    Bad(
        "power-tower-set",
        "units",
        _set("joint.clearance=9**9**9 m"),
        ["joint.clearance", "'9**9**9 m'", "exponents cannot be nested"],
    ),
    Bad(
        "caret-power-tower",
        "units",
        _set("joint.clearance=9^9^9 m"),
        ["joint.clearance", "exponents cannot be nested"],
    ),
    Bad(
        "power-tower-in-file",
        "units",
        ["run", "{tmp}/p.toml", "--out", "{out}"],
        ["joint.pin_radius", "exponents cannot be nested"],
        {"p.toml": '[joint]\npin_radius = "2**3**4 mm"\n'},
    ),
    Bad(
        "huge-exponent",
        "units",
        _set("joint.clearance=2**100000 m"),
        ["joint.clearance", "an exponent must be a number within +-12"],
    ),
    Bad(
        "exponent-not-a-number",
        "units",
        _set("joint.clearance=2**m m"),
        ["joint.clearance", "an exponent must be a number"],
    ),
    Bad(
        "power-of-a-power-in-parentheses",
        "units",
        _set("joint.clearance=(2**12)**12 m"),
        ["joint.clearance", "exponents cannot be nested"],
    ),
    Bad(
        "expression-too-long",
        "units",
        _set("joint.clearance=1" + "*1" * 120 + " mm"),
        ["joint.clearance", "too long for a quantity", "200 characters"],
    ),
    Bad(
        "number-with-fifty-digits",
        "units",
        _set("joint.clearance=" + "1" * 50 + " mm"),
        ["joint.clearance", "a number of 50 digits"],
    ),
    Bad(
        "overflowing-power",
        "units",
        _set("joint.clearance=1e300**2 m"),
        ["joint.clearance", "beyond any physical value"],
    ),
    Bad(
        "stiffness-unit-exponent-beyond-bound",
        "units",
        _set("contact.stiffness=1e10 N/m**99"),
        ["contact.stiffness", "an exponent must be a number within"],
    ),
    Bad(
        "power-tower-in-sweep-grid",
        "units",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml", "[grid] joint.clearance", "exponents cannot be nested"],
        {
            "s.toml": sweep_toml('[grid]\n"joint.clearance" = ["0.1 mm", "9**9**9 m"]\n'),
            "tiny.toml": "@tiny",
        },
    ),
    Bad(
        "power-tower-in-sweep-distribution",
        "units",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml", "[sample] joint.clearance.high", "exponents cannot be nested"],
        {
            "s.toml": sweep_toml(
                '[sample]\n"joint.clearance" = {distribution = "uniform", low = "0.05 mm", '
                'high = "9**9**9 m"}\nsamples = 2\n'
            ),
            "tiny.toml": "@tiny",
        },
    ),
    Bad(
        "power-tower-in-csv-header",
        "units",
        ["measure", "{tmp}/p.csv", "--radius", "7.5 mm"],
        ["p.csv", "'9**9**9 m' is not a length unit"],
        {"p.csv": "x [9**9**9 m],y [mm]\n7.5,0\n0,7.5\n-7.5,0\n"},
    ),
    Bad(
        "power-tower-in-load-history-header",
        "units",
        ["dynamics", "{tmp}/h.toml"],
        ["h.csv", "'9**9**9 s' is not a unit of time"],
        {
            "h.toml": '[mechanism]\ntype = "load-history"\nfile = "h.csv"\n',
            "h.csv": HISTORY,
        },
    ),
    Bad(
        "power-tower-in-option",
        "units",
        ["contact", "{paper}", "--load", "9**9**9 N"],
        ["--load", "exponents cannot be nested"],
    ),
    Bad(
        "power-tower-as-radius",
        "units",
        ["measure", "{tmp}/ring.csv", "--radius", "9**9**9 mm"],
        ["--radius", "exponents cannot be nested"],
        {"ring.csv": CSV_HEADER + "7.5,0\n"},
    ),
    Bad(
        "power-tower-as-column-unit",
        "units",
        ["measure", "{tmp}/ring.csv", "--radius", "7.5 mm", "--units", "9**9**9 m"],
        ["--units", "is not a length unit"],
        {"ring.csv": "7.5 0\n"},
    ),
    Bad(
        "power-tower-as-memory",
        "units",
        [*RUN, "--max-memory", "9**9**9 GiB"],
        ["--max-memory", "exponents cannot be nested"],
    ),
    Bad(
        "time-limit-as-length",
        "units",
        [*RUN, "--time-limit", "5 m"],
        ["--time-limit", "expected a time"],
    ),
    # ------------------------------------------------------------ bare numbers: unit slips
    Bad(
        "bare-amplitude-in-degrees",
        "units",
        ["run", "{tmp}/swing.toml", "--out", "{out}", "--set", "mechanism.amplitude=35"],
        [
            "mechanism.amplitude",
            "35 is read as 35 rad (a bare number is SI), more than 6.283 rad",
            'give a unit, e.g. "35 deg"',
        ],
        {"swing.toml": SWING},
    ),
    Bad(
        "bare-load-angle-in-file",
        "units",
        ["run", "{tmp}/swing.toml", "--out", "{out}"],
        ["mechanism.load_angle", "-90 is read as -90 rad", 'e.g. "-90 deg"'],
        {"swing.toml": SWING + "load_angle = -90\n"},
    ),
    Bad(
        "bare-pin-radius-in-millimetres",
        "units",
        _set("joint.pin_radius=7.45"),
        ["joint.pin_radius", "7.45 is read as 7.45 m (a bare number is SI)", 'e.g. "7.45 mm"'],
    ),
    Bad(
        "bare-rod-length-in-millimetres",
        "units",
        _set("mechanism.rod_length=200"),
        ["mechanism.rod_length", "200 is read as 200 m", "more than 10 m", 'e.g. "200 mm"'],
    ),
    Bad(
        "bare-crank-speed-in-rpm",
        "units",
        _set("mechanism.crank_speed=3000"),
        ["mechanism.crank_speed", "3000 is read as 3000 rad/s", 'e.g. "3000 rpm"'],
    ),
    Bad(
        "bare-frequency-in-cycles-per-minute",
        "units",
        ["run", "{tmp}/swing.toml", "--out", "{out}", "--set", "mechanism.frequency=120"],
        ["mechanism.frequency", "120 is read as 120 Hz", 'e.g. "120 1/min"'],
        {"swing.toml": SWING},
    ),
    Bad(
        "bare-sliding-speed-limit",
        "units",
        _set("materials.bushing.max_sliding_speed=500"),
        ["materials.bushing.max_sliding_speed", "500 is read as 500 m/s", 'e.g. "500 mm/s"'],
    ),
    Bad(
        "bare-angle-as-text-in-sweep-grid",
        "units",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml: [grid] mechanism.amplitude: 10 is read as 10 rad", 'e.g. "10 deg"'],
        {
            "s.toml": 'base = "swing.toml"\n[grid]\n"mechanism.amplitude" = ["25 deg", "10"]\n',
            "swing.toml": SWING,
        },
    ),
    Bad(
        "bare-angle-as-distribution-bound",
        "units",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml: [sample] mechanism.amplitude.high: 40 is read as 40 rad", 'e.g. "40 deg"'],
        {
            "s.toml": 'base = "swing.toml"\n[sample]\n"mechanism.amplitude" = '
            '{distribution = "uniform", low = "10 deg", high = 40}\nsamples = 2\n',
            "swing.toml": SWING,
        },
    ),
    Bad(
        "bare-radius-in-millimetres",
        "units",
        ["measure", "{tmp}/ring.csv", "--radius", "40.15"],
        ["--radius", "40.15 is read as 40.15 m (a bare number is SI)", 'e.g. "40.15 mm"'],
        {"ring.csv": CSV_HEADER + "40.15,0\n"},
    ),
    Bad(
        "bare-floor-in-micrometres",
        "units",
        ["measure", "{tmp}/ring.csv", "--radius", "7.5 mm", "--floor", "3"],
        ["--floor", "3 is read as 3 m"],
        {"ring.csv": CSV_HEADER + "7.5,0\n"},
    ),
    Bad(
        "bare-azimuth-in-degrees",
        "units",
        ["contact", "{paper}", "--load", "1 kN", "--azimuth", "90"],
        ["--azimuth", "90 is read as 90 rad", 'e.g. "90 deg"'],
    ),
    Bad(
        "crank-speed-in-squared-angle",
        "units",
        _set("mechanism.crank_speed=2 sr/s"),
        ["mechanism.crank_speed", "is not a rate of turns or of an angle"],
    ),
]

CASES += UNIT_CASES


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_bad_number(case: Bad, tmp_path, capsys, result_bytes):
    check_contract(case, tmp_path, capsys, result_bytes)


def test_true_is_not_one_in_the_api():
    """``Config.replace`` and ``load_config`` refuse ``True`` for a number, as the CLI does."""
    config = load_config(PAPER)
    with pytest.raises(ConfigError, match="contact.exponent: expected a number, got a boolean"):
        config.replace({"contact.exponent": True})
    with pytest.raises(ConfigError, match="simulation.saved_profiles: .*boolean"):
        load_config(PAPER, {"simulation.saved_profiles": True})
    # a boolean key still takes a boolean
    assert load_config(PAPER, {"simulation.update_contour": True}).simulation.update_contour


def test_integer_exactly_at_the_bound_is_accepted():
    """The largest count a config may ask for is accepted (the bound is inclusive)."""
    config = load_config(PAPER, {"simulation.revolutions": 10**9})
    assert config.simulation.revolutions == 10**9
    with pytest.raises(ConfigError, match="simulation.revolutions"):
        load_config(PAPER, {"simulation.revolutions": 10**9 + 1})


@pytest.mark.slow
@pytest.mark.parametrize(
    "case_id", ["power-tower-set", "integer-beyond-python-limit-set", "boolean-for-exponent"]
)
def test_bad_number_in_a_real_process(case_id, tmp_path, result_bytes):
    """In a real process too: a power tower or a 5000-digit integer ends in one line, exit 2."""
    import subprocess
    import sys

    from tests.hostile.harness import expand, files_in, materialise

    case = next(c for c in CASES if c.id == case_id)
    materialise(tmp_path, case.files, result_bytes)
    out = tmp_path / "out"
    done = subprocess.run(
        [sys.executable, "-m", "jointwear", *expand(case.argv, tmp_path, out)],
        capture_output=True,
        text=True,
        check=False,
        timeout=120,
    )
    assert done.returncode == 2, done.stderr
    lines = done.stderr.splitlines()
    assert len(lines) == 1
    assert lines[0].startswith("error: ")
    assert all(fragment in lines[0] for fragment in case.expect)
    assert files_in(out) == []
