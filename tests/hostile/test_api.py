"""Hostile values through the Python API and the network: only jointwear's own errors.

``load_config``, ``Config.replace`` and ``Config.to_toml`` raise ``ConfigError`` (never
``OverflowError``, ``TypeError``, ``AttributeError``) and write TOML that reads back;
``sweep --scheduler`` asks the scheduler for its identity within a timeout, so a
server that accepts the connection and stays silent is a one-line error, not a hang.
"""

from __future__ import annotations

import contextlib
import socket
import threading
import tomllib

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from jointwear import load_config
from jointwear.config import config_from_dict
from jointwear.errors import ConfigError
from jointwear.units import parse_quantity, parse_unit, to_si
from tests.hostile.harness import GRID, PAPER, Bad, check_contract, run_cli, sweep_toml

SWEEP = ["sweep", "{tmp}/s.toml", "--out", "{out}"]
#: the page section of the tests below that are not one command (default: API)
FREE_AREAS = {
    "test_silent_scheduler_is_a_one_line_error": "network",
    "test_silent_scheduler_in_a_real_process": "network",
    "test_a_server_that_is_no_scheduler_is_refused": "network",
    "test_any_quantity_text_parses_or_is_refused": "units",
    "test_unbounded_expressions_are_refused_before_pint": "units",
    "test_bounded_expressions_still_read": "units",
}
SWEEP_FILES = {"s.toml": sweep_toml(GRID), "tiny.toml": "@tiny"}

CASES: list[Bad] = [
    # ------------------------------------------------------------ scheduler addresses
    Bad(
        "scheduler-refuses",
        "network",
        [*SWEEP, "--scheduler", "tcp://127.0.0.1:1"],
        ["--scheduler", "cannot connect to tcp://127.0.0.1:1", "refused"],
        SWEEP_FILES,
    ),
    Bad(
        "scheduler-port-out-of-range",
        "network",
        [*SWEEP, "--scheduler", "tcp://127.0.0.1:99999"],
        ["--scheduler", "port 99999 is not in 1..65535"],
        SWEEP_FILES,
    ),
    Bad(
        "scheduler-port-missing",
        "network",
        [*SWEEP, "--scheduler", "tcp://127.0.0.1:"],
        ["--scheduler", "cannot connect to tcp://127.0.0.1:"],
        SWEEP_FILES,
    ),
    Bad(
        "scheduler-unknown-protocol",
        "network",
        [*SWEEP, "--scheduler", "foo://host:8786"],
        ["--scheduler", "protocol 'foo' is not supported"],
        SWEEP_FILES,
    ),
    Bad(
        "scheduler-inproc-elsewhere",
        "network",
        [*SWEEP, "--scheduler", "inproc://x"],
        ["--scheduler", "cannot connect to inproc://x"],
        SWEEP_FILES,
    ),
    Bad(
        "scheduler-with-workers",
        "network",
        [*SWEEP, "--scheduler", "tcp://127.0.0.1:1", "--workers", "2"],
        ["--workers", "a dask cluster has its own workers"],
        SWEEP_FILES,
    ),
    Bad(
        "life-scheduler-refuses",
        "network",
        [
            "life",
            "{paper}",
            "--sample",
            "joint.clearance=uniform(low=0.05 mm, high=0.06 mm)",
            "--cases",
            "2",
            "--out",
            "{out}",
            "--scheduler",
            "tcp://127.0.0.1:1",
        ],
        ["--scheduler", "cannot connect to tcp://127.0.0.1:1"],
    ),
    # ------------------------------------------------------------ parameter sets
    Bad(
        "sweep-unknown-parameter-set",
        "sweep",
        SWEEP,
        ["s.toml", "[grid] parameter_set", "unknown parameter set 'nope'"],
        {
            "s.toml": sweep_toml('[grid]\nparameter_set = ["nlcp-paper", "nope"]\n'),
            "tiny.toml": "@tiny",
        },
    ),
    Bad(
        "sweep-unknown-parameter-set-in-set",
        "sweep",
        SWEEP,
        ["s.toml", "parameter_set", "unknown parameter set 'paper'", "'nlcp-paper'"],
        {
            "s.toml": 'base = "tiny.toml"\n[set]\nparameter_set = "paper"\n' + GRID,
            "tiny.toml": "@tiny",
        },
    ),
    Bad(
        "sweep-parameter-set-not-a-name",
        "sweep",
        SWEEP,
        ["s.toml", "[zip] parameter_set", "valid string"],
        {"s.toml": sweep_toml("[zip]\nparameter_set = [1, 2]\n"), "tiny.toml": "@tiny"},
    ),
    # ------------------------------------------------------------ config text
    Bad(
        "config-key-with-quote",
        "api",
        ["run", "{tmp}/q.toml", "--out", "{out}"],
        ['joint."clear"ance', "unknown key"],
        {"q.toml": "[joint]\n'\"clear\"ance' = 1\n"},
    ),
    Bad(
        "history-file-name-with-newline",
        "api",
        ["dynamics", "{tmp}/h.toml"],
        ["a\\nb.csv", "file not found"],
        {"h.toml": '[mechanism]\ntype = "load-history"\nfile = "a\\nb.csv"\n'},
    ),
    Bad(
        "history-file-name-with-nul",
        "api",
        ["dynamics", "{tmp}/h.toml"],
        ["mechanism.file", "embedded null byte"],
        {"h.toml": '[mechanism]\ntype = "load-history"\nfile = "a\\u0000b.csv"\n'},
    ),
]


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_bad_value(case: Bad, tmp_path, capsys, result_bytes):
    check_contract(case, tmp_path, capsys, result_bytes)


# ---------------------------------------------------------------- the network


@pytest.fixture
def silent_server():
    """A TCP server that accepts connections and never answers."""
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen()
    held: list[socket.socket] = []

    def accept() -> None:
        while True:
            try:
                connection, _ = server.accept()
            except OSError:
                return
            held.append(connection)

    threading.Thread(target=accept, daemon=True).start()
    yield f"tcp://127.0.0.1:{server.getsockname()[1]}"
    server.close()
    for connection in held:
        connection.close()


def test_silent_scheduler_is_a_one_line_error(silent_server, tmp_path, capsys, monkeypatch):
    """A server that accepts and never answers: 'no dask scheduler answered ... within N s'."""
    import jointwear.workflows.sweep.cluster

    monkeypatch.setattr(jointwear.workflows.sweep.cluster, "CONNECT_TIMEOUT", 0.5)
    (tmp_path / "s.toml").write_text(sweep_toml(GRID), encoding="utf-8")
    (tmp_path / "tiny.toml").write_text(PAPER.read_text(encoding="utf-8"), encoding="utf-8")
    out = tmp_path / "out"
    argv = ["sweep", str(tmp_path / "s.toml"), "--out", str(out), "--scheduler", silent_server]
    code, stdout, stderr = run_cli(capsys, argv)
    assert code == 2
    assert stdout == ""
    assert stderr == (
        f"error: --scheduler: no dask scheduler answered at {silent_server} within 0.5 s\n"
    )
    assert not out.exists()


def test_a_server_that_is_no_scheduler_is_refused(tmp_path):
    """A TCP server that answers with something else than dask is refused by the probe."""
    from jointwear.workflows.sweep.cluster import probe

    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen()

    def answer() -> None:
        connection, _ = server.accept()
        connection.sendall(b"HTTP/1.1 400 Bad Request\r\n\r\n" * 4)
        connection.close()

    threading.Thread(target=answer, daemon=True).start()
    address = f"tcp://127.0.0.1:{server.getsockname()[1]}"
    try:
        with pytest.raises(ConfigError, match="--scheduler: no dask scheduler answered"):
            probe(address, 2.0)
    finally:
        server.close()


# ---------------------------------------------------------------- the config API


def test_api_raises_only_config_errors():
    """Config.replace and config_from_dict turn every bad value into ConfigError."""
    config = load_config(PAPER)
    bad = [
        {5: 1},
        {"": 1},
        {"contact.exponent": 10**400},
        {"joint.clearance": object()},
        {"joint.clearance": [1]},
        {"joint.clearance": "9**9**9 m"},
        {"parameter_set": "nope"},
        {"parameter_set": True},
        {"simulation.update_every": 10**5000},
    ]
    for overrides in bad:
        with pytest.raises(ConfigError):
            config.replace(overrides)
    with pytest.raises(ConfigError, match="update_every: an integer of about 5000 digits"):
        config.replace({"simulation.update_every": 10**5000})
    with pytest.raises(ConfigError, match="config: expected a mapping"):
        config_from_dict([1, 2])  # type: ignore[arg-type]


@pytest.mark.parametrize(
    "name", ['we"ird.csv', "back\\slash.csv", "new\nline.csv", "tab\tand\x7fdel\x01.csv", "é✓.csv"]
)
def test_to_toml_round_trips_any_file_name(name, tmp_path):
    """Quotes, backslashes, newlines and control characters in strings survive to_toml."""
    config = load_config(None, {"mechanism.type": "load-history", "mechanism.file": name})
    text = config.to_toml()
    data = tomllib.loads(text)
    assert data["mechanism"]["file"] == str((tmp_path.cwd() / name).resolve())
    again = config_from_dict(data, defaults=False)
    assert again.to_toml() == text


def test_to_toml_of_a_lone_surrogate_is_a_config_error():
    """A string that no file can hold (a lone surrogate) is a ConfigError, not a crash."""
    with pytest.raises(ConfigError, match="mechanism.file"):
        load_config(None, {"mechanism.type": "load-history", "mechanism.file": "a\ud800.csv"})


@settings(max_examples=150, deadline=None)
@given(st.text(alphabet="0123456789.e*^()+- m", max_size=40))
def test_any_quantity_text_parses_or_is_refused(text):
    """Random quantity texts give a number or ConfigError: no hang, no other exception."""
    with contextlib.suppress(ConfigError):
        to_si(text, "length", "k")


@pytest.mark.parametrize(
    "text",
    ["9**9**9", "9^9^9 m", "2**100000 m", "(9**9)**9 m", "2**(9**9)", "m**2**2", "1" * 60],
)
def test_unbounded_expressions_are_refused_before_pint(text, monkeypatch):
    """Unbounded expressions never reach pint (which would evaluate them)."""
    from jointwear.units import ureg

    def evaluate(*args, **kwargs):
        raise AssertionError("pint was asked to evaluate an unbounded expression")

    monkeypatch.setattr(ureg, "Quantity", evaluate)
    with pytest.raises(ConfigError):
        parse_quantity(text)
    with pytest.raises(ConfigError):
        parse_unit(text)


@pytest.mark.parametrize(
    ("text", "metres"),
    [
        ("2**3 mm", 8e-3),
        ("1 mm**2/mm", 1e-3),
        ("m²/m", 1.0),
        ("2**(-1) m", 0.5),
        ("(2 mm)**2/mm", 4e-3),
        ("1e-3 km", 1.0),
    ],
)
def test_bounded_expressions_still_read(text, metres):
    """Powers within the bound, superscripts and parentheses read as before."""
    assert to_si(text, "length") == pytest.approx(metres)


@pytest.mark.slow
def test_silent_scheduler_in_a_real_process(silent_server, tmp_path):
    """A real `jointwear sweep` against a silent server gives up after its 10 s, in one line."""
    import subprocess
    import sys

    (tmp_path / "s.toml").write_text(sweep_toml(GRID), encoding="utf-8")
    (tmp_path / "tiny.toml").write_text(PAPER.read_text(encoding="utf-8"), encoding="utf-8")
    out = tmp_path / "out"
    argv = ["sweep", str(tmp_path / "s.toml"), "--out", str(out), "--scheduler", silent_server]
    done = subprocess.run(
        [sys.executable, "-m", "jointwear", *argv],
        capture_output=True,
        text=True,
        check=False,
        timeout=120,
    )
    assert done.returncode == 2, done.stderr
    assert done.stderr == (
        f"error: --scheduler: no dask scheduler answered at {silent_server} within 10 s\n"
    )
    assert not out.exists()


def _config_keys() -> list[str]:
    from jointwear.config import Config, SliderCrankConfig

    keys: list[str] = []

    def walk(model, prefix: str) -> None:
        for name, field in model.model_fields.items():
            if hasattr(field.annotation, "model_fields"):
                walk(field.annotation, f"{prefix}{name}.")
            elif f"{prefix}{name}" != "mechanism":
                keys.append(f"{prefix}{name}")

    walk(Config, "")
    return keys + [f"mechanism.{name}" for name in SliderCrankConfig.model_fields]


HOSTILE_VALUES = [
    True,
    10**400,
    10**5000,
    [10**5000],
    float("nan"),
    -float("inf"),
    1e308,
    "9**9**9",
    "1e400 m",
    "\x00",
    "1" * 300,
    {"a": 1},
    None,
    1j,
]


@pytest.mark.parametrize("key", _config_keys())
def test_every_key_takes_hostile_values_with_config_errors_only(key):
    """Every config key given any hostile value: a ConfigError with a one-line message."""
    config = load_config(PAPER)
    for value in HOSTILE_VALUES:
        try:
            config.replace({key: value}).to_toml()
        except ConfigError as exc:
            message = str(exc)
            assert "\n" not in message
            assert len(message) < 1000
