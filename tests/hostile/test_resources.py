"""Hostile sizes: memory is estimated from the sizes before anything is allocated.

A run's dense ``nodes x steps`` arrays and saved profiles, a sweep's cases, a measured
profile's nodes: each is estimated where the command starts and refused above a limit
(``--max-memory``, ``JOINTWEAR_MAX_MEMORY``, default half the RAM, at most 8 GiB),
with one line naming the keys, the estimate and how to raise the limit.
"""

from __future__ import annotations

import pytest

from jointwear import load_config
from jointwear.errors import ConfigError
from jointwear.resources import (
    DENSE_ARRAYS,
    ENVIRONMENT,
    MAX_CASES,
    check_run,
    format_bytes,
    memory_limit,
    parse_size,
    run_memory,
)
from tests.hostile.harness import CSV_HEADER, PAPER, Bad, check_contract, run_cli, sweep_toml

RUN = ["run", "{paper}", "--out", "{out}"]
HUGE_RUN = ["--set", "contact.nodes=200000", "--set", "simulation.steps_per_revolution=1000000"]
LIMIT_HINT = "--max-memory SIZE or JOINTWEAR_MAX_MEMORY"
SAMPLE = ["--sample", "joint.clearance=uniform(low=0.05 mm, high=0.06 mm)"]


def _grid(keys: int, values: int) -> str:
    """A sweep grid of ``keys`` keys with ``values`` values each."""
    names = ["joint.clearance", "joint.axial_length", "joint.bushing_thickness"][:keys]
    lines = [
        f'"{name}" = [{", ".join(f"{1 + i * 1e-3:.4f}e-3" for i in range(values))}]'
        for name in names
    ]
    return "[grid]\n" + "\n".join(lines) + "\n"


CASES: list[Bad] = [
    Bad(
        "dense-arrays-beyond-memory",
        "resources",
        [*RUN, *HUGE_RUN],
        [
            "contact.nodes, simulation.steps_per_revolution",
            "needs about 11.6 TiB of memory",
            "1000000 steps x 200000 nodes",
            LIMIT_HINT,
        ],
    ),
    Bad(
        "saved-profiles-beyond-memory",
        "resources",
        [
            *RUN,
            "--set",
            "contact.nodes=200000",
            "--set",
            "simulation.saved_profiles=100000",
            "--set",
            "simulation.steps_per_revolution=8",
        ],
        ["simulation.saved_profiles, contact.nodes", "100000 saved profiles", LIMIT_HINT],
    ),
    Bad(
        "limit-below-a-small-run",
        "resources",
        [*RUN, "--max-memory", "1 KiB"],
        ["contact.nodes", "more than the limit of 1 KiB (--max-memory)"],
    ),
    Bad(
        "limit-not-a-size",
        "resources",
        [*RUN, "--max-memory", "5 kg"],
        ["--max-memory", "'5 kg' is not a memory size"],
    ),
    Bad(
        "limit-negative",
        "resources",
        [*RUN, "--max-memory", "-1 GiB"],
        ["--max-memory", "must be a positive memory size"],
    ),
    Bad(
        "limit-zero",
        "resources",
        [*RUN, "--max-memory", "0"],
        ["--max-memory", "must be a positive memory size"],
    ),
    Bad(
        "limit-nan",
        "resources",
        [*RUN, "--max-memory", "nan GB"],
        ["--max-memory", "must be a positive memory size"],
    ),
    Bad(
        "sweep-grid-too-many-cases",
        "resources",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml: [grid]", "1,030,301 cases", f"more than {MAX_CASES:,}", "split it"],
        {"s.toml": sweep_toml(_grid(3, 101)), "tiny.toml": "@tiny"},
    ),
    Bad(
        "sweep-samples-too-many",
        "resources",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml: samples (1000000000000)", "cases, more than"],
        {
            "s.toml": sweep_toml(
                '[sample]\n"joint.clearance" = {distribution = "uniform", low = "0.05 mm", '
                'high = "0.1 mm"}\nsamples = 1000000000000\n'
            ),
            "tiny.toml": "@tiny",
        },
    ),
    Bad(
        "sweep-samples-hundred-digits",
        "resources",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml", "about 10^60 cases"],
        {
            "s.toml": sweep_toml(
                '[sample]\n"joint.clearance" = {distribution = "uniform", low = "0.05 mm", '
                f'high = "0.1 mm"}}\nsamples = 1{"0" * 60}\n'
            ),
            "tiny.toml": "@tiny",
        },
    ),
    Bad(
        "sweep-case-beyond-memory",
        "resources",
        ["sweep", "{tmp}/s.toml", "--out", "{out}", "--workers", "1"],
        ["simulation.steps_per_revolution", "1 running case(s)", LIMIT_HINT],
        {
            "s.toml": 'base = "tiny.toml"\n[set]\n"simulation.steps_per_revolution" = 1000000\n'
            '[grid]\n"contact.nodes" = [60, 200000]\n',
            "tiny.toml": "@tiny",
        },
    ),
    Bad(
        "sweep-limit-below-records",
        "resources",
        [
            "sweep",
            "{tmp}/s.toml",
            "--out",
            "{out}",
            "--workers",
            "1",
            "--max-memory",
            "1 KiB",
        ],
        ["more than the limit of 1 KiB (--max-memory)"],
        {
            "s.toml": sweep_toml('[grid]\n"joint.clearance" = ["0.05 mm", "0.1 mm"]\n'),
            "tiny.toml": "@tiny",
        },
    ),
    Bad(
        "measure-nodes-beyond-memory",
        "resources",
        ["measure", "{tmp}/ring.csv", "--radius", "7.5 mm", "--nodes", "100000000000"],
        ["--nodes", "needs about", LIMIT_HINT],
        {"ring.csv": CSV_HEADER + "7.5,0\n"},
    ),
    Bad(
        "calibrate-run-beyond-memory",
        "resources",
        ["calibrate", "{paper}", "{tmp}/ring.csv", "--fit", "wear_coefficient", *HUGE_RUN],
        ["contact.nodes, simulation.steps_per_revolution", LIMIT_HINT],
        {"ring.csv": CSV_HEADER + "7.5,0\n"},
    ),
    Bad(
        "life-cases-too-many",
        "resources",
        ["life", "{paper}", *SAMPLE, "--cases", "10000000", "--out", "{out}"],
        ["--cases", "10,000,000 cases", "split it"],
    ),
    Bad(
        "life-case-beyond-memory",
        "resources",
        ["life", "{paper}", *SAMPLE, "--cases", "2", "--out", "{out}", *HUGE_RUN],
        ["contact.nodes, simulation.steps_per_revolution", LIMIT_HINT],
    ),
]


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_bad_size(case: Bad, tmp_path, capsys, result_bytes):
    check_contract(case, tmp_path, capsys, result_bytes)


def test_environment_sets_the_limit(monkeypatch, capsys, tmp_path):
    """``JOINTWEAR_MAX_MEMORY`` refuses a run the default would allow; --max-memory wins."""
    monkeypatch.setenv(ENVIRONMENT, "1 KiB")
    code, _, err = run_cli(capsys, ["run", str(PAPER), "--out", str(tmp_path / "o")])
    assert code == 2
    assert f"limit of 1 KiB ({ENVIRONMENT})" in err
    assert memory_limit("2 GiB") == (2 * 2**30, "--max-memory")
    monkeypatch.setenv(ENVIRONMENT, "lots")
    with pytest.raises(ConfigError, match=f"{ENVIRONMENT}: cannot read 'lots'"):
        memory_limit()


def test_raised_limit_admits_the_run():
    """A run refused by the default is admitted with a limit above its estimate."""
    config = load_config(PAPER, {"contact.nodes": 20000, "simulation.steps_per_revolution": 20000})
    with pytest.raises(ConfigError, match="needs about 23.8 GiB"):
        check_run(config, "8 GiB")
    assert check_run(config, "32 GiB") == pytest.approx(sum(p[2] for p in run_memory(config)))


def test_estimate_counts_the_dense_arrays():
    """The estimate is DENSE_ARRAYS float64 arrays of steps x nodes plus the saved profiles."""
    config = load_config(PAPER, {"contact.nodes": 1000, "simulation.steps_per_revolution": 500})
    dense, profiles = run_memory(config)
    assert dense[2] == DENSE_ARRAYS * 1000 * 500 * 8
    assert profiles[2] == config.simulation.saved_profiles * 1000 * 8


@pytest.mark.parametrize(
    ("text", "size"),
    [("16 GiB", 16 * 2**30), ("500 MB", 500e6), ("4096", 4096), ("1 kibibyte", 1024)],
)
def test_sizes_read(text, size):
    """Memory sizes read with binary and decimal prefixes; a bare number is bytes."""
    assert parse_size(text) == size


def test_sizes_shown():
    """Sizes print with binary prefixes."""
    assert format_bytes(1536) == "1.5 KiB"
    assert format_bytes(11.6 * 2**40) == "11.6 TiB"
