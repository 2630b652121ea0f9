"""Load histories from files: round trips through ``dynamics --csv``, frames, units, bad files."""

from __future__ import annotations

import csv
import hashlib
import json
import re
from collections.abc import Mapping
from pathlib import Path

import numpy as np
import pytest

from jointwear import Simulation, load_config
from jointwear.cli import main
from jointwear.errors import DataError
from jointwear.mechanism import LoadCycle
from jointwear.mechanism.history import MIN_ROWS, history_cycle, read_load_history
from jointwear.mechanism.stage import load_cycle

REPO = Path(__file__).resolve().parents[2]
PAPER = REPO / "tests" / "data" / "paper_joint.toml"
EXAMPLE = REPO / "examples" / "load_history" / "load_history.toml"

MECHANISMS = {
    "slider-crank": None,  # the paper's own [mechanism] section
    "oscillating": 'type = "oscillating"\nload = "500 N"\namplitude = "25 deg"\n'
    'frequency = "0.5 Hz"\n',
}
HISTORY = 'type = "load-history"\nfile = "loads.csv"\n'
LONG_RUN = ["simulation.revolutions=200", "simulation.update_contour=true"]
FIELDS = ("time", "load", "azimuth", "relative_rotation")


# ---------------------------------------------------------------- helpers
def paper_toml(mechanism: str | None) -> str:
    """The paper's config with its ``[mechanism]`` section replaced (None: kept)."""
    text = PAPER.read_text(encoding="utf-8")
    if mechanism is None:
        return text
    return re.sub(r"\[mechanism\]\n.*?\n(?=\[)", f"[mechanism]\n{mechanism}\n", text, flags=re.S)


def write_config(folder: Path, mechanism: str | None, name: str = "config.toml") -> Path:
    path = folder / name
    path.write_text(paper_toml(mechanism), encoding="utf-8")
    return path


def write_csv(path: Path, columns: Mapping[str, np.ndarray], comment: str = "") -> Path:
    """A load-history CSV, full precision, as ``dynamics --csv`` writes it."""
    with path.open("w", encoding="utf-8", newline="") as handle:
        handle.write(comment)
        writer = csv.writer(handle)
        writer.writerow(columns)
        writer.writerows(zip(*([repr(float(v)) for v in c] for c in columns.values()), strict=True))
    return path


def dynamics_csv(config: Path, out: Path, capsys: pytest.CaptureFixture[str]) -> Path:
    main(["dynamics", str(config), "--json", "--csv", str(out)])
    capsys.readouterr()
    return out


def wear(config: Path, overrides: list[str] = ()) -> tuple[float, float]:
    summary = Simulation(load_config(config, overrides)).run().summary()
    return summary["peak_wear_depth_m"], summary["wear_mass_kg"]


def assert_same_cycle(actual: LoadCycle, expected: LoadCycle, rtol: float = 1e-12) -> None:
    """Equal fields, each to ``rtol`` of its largest magnitude (increments pass through 0)."""
    assert actual.steps == expected.steps
    assert actual.period == pytest.approx(expected.period, rel=rtol, abs=0)
    for name in FIELDS:
        want = getattr(expected, name)
        scale = max(float(np.max(np.abs(want))), np.finfo(float).tiny)
        np.testing.assert_allclose(
            getattr(actual, name), want, rtol=0, atol=rtol * scale, err_msg=name
        )


def example_columns(steps: int = 24, closing: bool = True) -> dict[str, np.ndarray]:
    """A small bushing-frame history in SI: rotating load, oscillating pin."""
    phase = 2 * np.pi * np.arange(steps + closing) / steps
    load = 300 + 100 * np.cos(phase)
    azimuth = 0.4 * np.sin(phase) - 1.0
    return {
        "time [s]": 0.8 * phase / (2 * np.pi),
        "force_x [N]": load * np.cos(azimuth),
        "force_y [N]": load * np.sin(azimuth),
        "rotation [rad]": 0.5 * np.sin(phase),
    }


# ---------------------------------------------------------------- round trips
@pytest.mark.parametrize("overrides", [[], LONG_RUN], ids=["one-revolution", "200-updated"])
@pytest.mark.parametrize("kind", MECHANISMS)
def test_dynamics_csv_reads_back_as_the_same_cycle_and_wear(
    kind: str, overrides: list[str], tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = write_config(tmp_path, MECHANISMS[kind], "source.toml")
    dynamics_csv(source, tmp_path / "loads.csv", capsys)
    history = write_config(tmp_path, HISTORY)
    assert_same_cycle(load_cycle(load_config(history)), load_cycle(load_config(source)))
    expected, actual = wear(source, overrides), wear(history, overrides)
    assert expected[0] > 0
    np.testing.assert_allclose(actual, expected, rtol=1e-12, atol=0)


def test_global_frame_with_a_turning_bushing_equals_the_bushing_frame(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    dynamics_csv(write_config(tmp_path, None, "source.toml"), tmp_path / "loads.csv", capsys)
    cycle = read_load_history(tmp_path / "loads.csv")
    # the bushing turns a whole turn and wobbles; the closing row stays a closing row
    time = np.append(cycle.time, cycle.period)
    turn = 2 * np.pi * time / cycle.period
    bushing_angle = 0.3 + turn + 0.2 * np.sin(2 * turn)
    local = np.append(cycle.azimuth, cycle.azimuth[0])
    load = np.append(cycle.load, cycle.load[0])
    write_csv(
        tmp_path / "global.csv",
        {
            "time [s]": time,
            "force_x [N]": load * np.cos(local + bushing_angle),
            "force_y [N]": load * np.sin(local + bushing_angle),
            "rotation [rad]": cycle.rotation,
            "bushing_angle [rad]": bushing_angle,
        },
    )
    glob = tmp_path / "global.toml"
    glob.write_text(paper_toml(HISTORY.replace("loads.csv", "global.csv") + 'frame = "global"\n'))
    assert_same_cycle(load_cycle(load_config(glob)), cycle)
    bushing = write_config(tmp_path, HISTORY)
    np.testing.assert_allclose(wear(glob, LONG_RUN), wear(bushing, LONG_RUN), rtol=1e-12, atol=0)


def test_units_in_the_brackets_are_converted(tmp_path: Path) -> None:
    si = example_columns()
    scaled = {
        "rotation [deg]": np.degrees(si["rotation [rad]"]),
        "force_y [kN]": si["force_y [N]"] / 1e3,
        "time [ms]": si["time [s]"] * 1e3,
        "force_x [kN]": si["force_x [N]"] / 1e3,
    }
    expected = read_load_history(write_csv(tmp_path / "si.csv", si))
    actual = read_load_history(write_csv(tmp_path / "scaled.csv", scaled))
    assert_same_cycle(actual, expected)
    assert expected.period == 0.8
    assert expected.steps == 24


def test_without_a_closing_row_the_last_step_holds_the_load_and_does_not_slide(
    tmp_path: Path,
) -> None:
    closed = read_load_history(write_csv(tmp_path / "closed.csv", example_columns()))
    path = write_csv(tmp_path / "open.csv", example_columns(closing=False))
    # without a period the median step closes the cycle: here the same 0.8 s
    for cycle in (read_load_history(path, period=0.8), read_load_history(path)):
        assert cycle.steps == closed.steps
        assert cycle.period == pytest.approx(closed.period, rel=1e-15, abs=0)
        for name in ("time", "load", "azimuth"):
            np.testing.assert_allclose(getattr(cycle, name), getattr(closed, name), rtol=1e-15)
        # the rows' rotations as given; the closing step, of which the file says nothing,
        # slides nothing (the closed file's last step slides into its closing row)
        np.testing.assert_array_equal(cycle.relative_rotation[:-1], closed.relative_rotation[:-1])
        assert cycle.relative_rotation[-1] == 0.0
        assert closed.relative_rotation[-1] != 0.0
    # a period beside a closing row must agree with it
    assert read_load_history(tmp_path / "closed.csv", period=0.8).period == 0.8
    with pytest.raises(DataError, match=r"closed\.csv: period 0\.9 s disagrees"):
        read_load_history(tmp_path / "closed.csv", period=0.9)


def test_open_cycle_of_a_turning_pin_slides_its_rows_only(tmp_path: Path) -> None:
    """No hidden step to whole turns: three turns sampled without their endpoint slide
    what the rows say; with the closing row they slide the three turns."""
    columns = example_columns(closing=False)
    time = columns["time [s]"]
    columns["rotation [rad]"] = 3 * 2 * np.pi * time / 0.8 + 0.1 * np.sin(7 * time)  # 3 turns
    cycle = read_load_history(write_csv(tmp_path / "turning.csv", columns))
    rows = columns["rotation [rad]"]
    assert cycle.rotation[-1] == pytest.approx(rows[-1] - rows[0], rel=1e-14, abs=0)
    assert cycle.total_relative_rotation == pytest.approx(
        np.sum(np.abs(np.diff(rows))), rel=1e-14, abs=0
    )
    closed = {name: np.append(values, values[0]) for name, values in columns.items()}
    closed["time [s]"][-1] = 0.8
    closed["rotation [rad]"][-1] = rows[0] + 3 * 2 * np.pi
    whole = read_load_history(write_csv(tmp_path / "closed.csv", closed))
    assert whole.rotation[-1] == pytest.approx(3 * 2 * np.pi, rel=1e-14, abs=0)


def test_non_uniform_steps_are_kept_as_they_are(tmp_path: Path) -> None:
    rng = np.random.default_rng(7)
    columns = example_columns(steps=40)
    time = np.concatenate(([0.0], np.cumsum(rng.uniform(0.5, 2.0, 40)))) + 12.5  # not from 0
    columns["time [s]"] = time
    cycle = read_load_history(write_csv(tmp_path / "uneven.csv", columns))
    np.testing.assert_allclose(cycle.time, time[:-1] - time[0], rtol=1e-14, atol=1e-13)
    np.testing.assert_allclose(cycle.step_duration, np.diff(time), rtol=1e-12)
    assert cycle.period == pytest.approx(time[-1] - time[0], rel=1e-15, abs=0)
    np.testing.assert_allclose(
        cycle.relative_rotation, np.diff(columns["rotation [rad]"]), rtol=0, atol=1e-15
    )


def test_bom_comments_blank_lines_and_informative_columns_are_accepted(tmp_path: Path) -> None:
    columns = example_columns()
    plain = read_load_history(write_csv(tmp_path / "plain.csv", columns))
    steps = len(columns["time [s]"])
    extra = {
        **columns,
        "crank_torque [N m]": np.ones(steps),
        "phase [deg]": np.zeros(steps),
        "pin_angle [rad]": np.zeros(steps),
        "rocker_angle [rad]": np.zeros(steps),
    }
    path = write_csv(tmp_path / "extra.csv", extra, comment="# exported by hand\n\n")
    text = path.read_text(encoding="utf-8")
    path.write_bytes(
        b"\xef\xbb\xbf" + text.replace("\n", "\n# between rows\n", 3).encode() + b"\n\n\n"
    )
    assert_same_cycle(read_load_history(path), plain, rtol=0)


def test_history_cycle_scales_the_load_and_records_the_file(tmp_path: Path) -> None:
    path = write_csv(tmp_path / "loads.csv", example_columns())
    config = write_config(tmp_path, HISTORY + "load_scale = 2.5\n")
    cycle = history_cycle(load_config(config).mechanism)
    plain = read_load_history(path)
    np.testing.assert_allclose(cycle.load, 2.5 * plain.load, rtol=1e-15)
    assert (cycle.mechanism, cycle.model, cycle.joint) == ("load-history", "prescribed", "joint")
    assert cycle.extras["history_file"] == str(path.resolve())
    assert cycle.extras["history_sha256"] == hashlib.sha256(path.read_bytes()).hexdigest()


def test_result_netcdf_reads_as_a_load_history(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    main(["run", str(PAPER), "--out", str(tmp_path / "out"), "--no-plots", "--json"])
    capsys.readouterr()
    result = tmp_path / "out" / "result.nc"
    expected = load_cycle(load_config(PAPER))
    assert_same_cycle(read_load_history(result), expected, rtol=0)
    assert_same_cycle(read_load_history(result, period=0.5), expected, rtol=0)
    with pytest.raises(DataError, match=r"result\.nc: .*bushing frame"):
        read_load_history(result, frame="global")
    with pytest.raises(DataError, match=r"result\.nc: period 0\.6 s disagrees"):
        read_load_history(result, period=0.6)


# ---------------------------------------------------------------- sliding as given
def constant_load_history(folder: Path, name: str, rotation_deg: list[float]) -> Path:
    """A config of a history under a constant 100 N downwards, rows 10 ms apart."""
    lines = ["time [s],force_x [N],force_y [N],rotation [deg]"]
    lines += [f"{0.01 * i!r},0,-100,{angle!r}" for i, angle in enumerate(rotation_deg)]
    (folder / f"{name}.csv").write_text("\n".join(lines) + "\n", encoding="utf-8")
    return write_config(folder, HISTORY.replace("loads.csv", f"{name}.csv"), f"{name}.toml")


def dynamics_json(config: Path, capsys: pytest.CaptureFixture[str]) -> dict:
    main(["dynamics", str(config), "--json"])
    return json.loads(capsys.readouterr().out)


@pytest.mark.parametrize(
    ("short", "long", "ratio"),
    [
        # half a turn (not whole turns: no closing row) against a full turn (closing row)
        ([9.0 * i for i in range(21)], [18.0 * i for i in range(21)], 2.0),
        # a swing out (no closing row) against out and back (the last row closes it)
        ([9.0 * i for i in range(11)], [9.0 * min(i, 20 - i) for i in range(21)], 2.0),
        # three quarters of a turn out (nearer a whole turn than none) and back
        ([9.0 * i for i in range(31)], [9.0 * min(i, 60 - i) for i in range(61)], 2.0),
    ],
    ids=["half-vs-full-turn", "out-vs-out-and-back", "three-quarters-out-vs-out-and-back"],
)
def test_a_history_slides_exactly_its_rows(
    short: list[float],
    long: list[float],
    ratio: float,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
) -> None:
    """Under one constant load the wear depth of a revolution is proportional to the
    sliding, and the sliding is the sum of |Δrotation| between rows: nothing added to
    close the cycle. (The worn mass is not quite: the worn area grows with the depth
    squared, 1e-6 relative here.)"""
    configs = [constant_load_history(tmp_path, n, r) for n, r in (("a", short), ("b", long))]
    for config, rotation in zip(configs, (short, long), strict=True):
        expected = np.radians(np.sum(np.abs(np.diff(rotation))))
        assert load_cycle(load_config(config)).total_relative_rotation == pytest.approx(
            expected, rel=1e-14, abs=0
        )
        summary = dynamics_json(config, capsys)
        assert summary["total_relative_rotation_rad"] == pytest.approx(expected, rel=1e-14, abs=0)
    depth_a, depth_b = (Simulation(load_config(c)).run().wear_depth for c in configs)
    assert depth_a.max() > 0
    np.testing.assert_allclose(depth_b, ratio * depth_a, rtol=1e-9, atol=0)


def test_a_cycle_of_no_whole_turns_reads_back_from_its_csv(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """``dynamics --csv`` of a history that turns half a turn (its closing row is half a
    turn on) reads back as the same cycle, with the same wear."""
    columns = example_columns(closing=False)
    columns["rotation [rad]"] = np.pi * columns["time [s]"] / 0.8  # 0 -> 172.5 deg
    write_csv(tmp_path / "loads.csv", columns)
    source = write_config(tmp_path, HISTORY, "source.toml")
    again = write_config(tmp_path, HISTORY.replace("loads.csv", "again.csv"))
    dynamics_csv(source, tmp_path / "again.csv", capsys)
    expected = load_cycle(load_config(source))
    assert expected.rotation[-1] == pytest.approx(np.pi * 23 / 24, rel=1e-14, abs=0)
    assert_same_cycle(load_cycle(load_config(again)), expected)
    np.testing.assert_allclose(wear(again, LONG_RUN), wear(source, LONG_RUN), rtol=1e-12)


# ---------------------------------------------------------------- bad files
GOOD_HEADER = "time [s],force_x [N],force_y [N],rotation [rad]"


def rows(count: int = 12, fields: int = 4) -> list[str]:
    return [
        ",".join([f"{0.1 * k:g}", "100", f"{k}", f"{0.01 * k:g}", "0"][:fields])
        for k in range(count)
    ]


def with_row(index: int, line: str) -> list[str]:
    """The good rows with data row ``index`` (file line ``index + 2``) replaced by ``line``."""
    body = rows()
    body[index] = line
    return body


def text(header: str = GOOD_HEADER, body: list[str] | None = None) -> str:
    return "\n".join([header, *(rows() if body is None else body)]) + "\n"


BAD_FILES: dict[str, tuple[str | bytes | None, str]] = {
    "missing-file": (None, "file not found"),
    "not-utf8": (text().encode("utf-8") + "# é\n".encode("latin-1"), "UTF-8"),
    "empty": ("# nothing here\n\n", "no data"),
    "no-header": (text(header="0,1,2,3"), "no header row"),
    "missing-column": (
        text("time [s],force_x [N],force_y [N]", rows(fields=3)),
        "missing column(s) 'rotation'",
    ),
    "unknown-column": (
        text(GOOD_HEADER + ",forse_x [N]", rows(fields=5)),
        "unknown column 'forse_x'; did you mean 'force_x'?",
    ),
    "bushing-angle-in-bushing-frame": (
        text(GOOD_HEADER + ",bushing_angle [deg]", rows(fields=5)),
        "frame = 'global' only",
    ),
    "unit-does-not-parse": (
        text(GOOD_HEADER.replace("[s]", "[blorp]")),
        "column 'time': 'blorp' is not a unit of time",
    ),
    "wrong-dimension": (
        text(GOOD_HEADER.replace("[s]", "[N]")),
        "column 'time': 'N' is not a unit of time",
    ),
    "angle-in-metres": (
        text(GOOD_HEADER.replace("[rad]", "[mm]")),
        "column 'rotation': 'mm' is not a unit of angle",
    ),
    "no-units": (text("time,force_x,force_y,rotation"), "column 'time' has no unit"),
    "duplicate-column": (
        text(GOOD_HEADER + ",force_x [kN]", rows(fields=5)),
        "column 'force_x' appears more than once",
    ),
    "nan": (
        text(body=with_row(6, "0.6,nan,1,0")),
        "line 8: column 'force_x' is not a finite number (nan)",
    ),
    "inf": (
        text(body=with_row(3, "0.3,1,2,inf")),
        "line 5: column 'rotation' is not a finite number (inf)",
    ),
    "not-a-number": (
        text(body=with_row(3, "0.3,1,x,0")),
        "line 5: 'x' is not a number",
    ),
    "time-goes-back": (
        text(body=with_row(5, "0.35,1,2,0")),
        "line 7: time does not increase",
    ),
    "time-repeats": (
        text(body=with_row(5, "0.4,1,2,0")),
        "line 7: time does not increase",
    ),
    "too-few-rows": (text(body=rows(MIN_ROWS - 1)), f"only {MIN_ROWS - 1} data row(s)"),
    "short-row": (
        text(body=with_row(4, "0.4,1,2")),
        "line 6: expected 4 columns, found 3",
    ),
    "long-rows": (text(body=rows(fields=5)), "line 2: expected 4 fields as in the header, found 5"),
    "broken-netcdf": (b"CDF\x01 not really", "not a readable netCDF result"),
}


@pytest.mark.parametrize("case", BAD_FILES)
def test_bad_file_is_a_one_line_data_error_naming_it(case: str, tmp_path: Path) -> None:
    content, expected = BAD_FILES[case]
    path = tmp_path / (f"{case}.nc" if "netcdf" in case else f"{case}.csv")
    if isinstance(content, bytes):
        path.write_bytes(content)
    elif content is not None:
        path.write_text(content, encoding="utf-8")
    with pytest.raises(DataError) as info:
        read_load_history(path)
    message = str(info.value)
    assert message.startswith(f"{path}: "), message
    assert expected in message
    assert "\n" not in message


def test_global_frame_needs_the_bushing_angle(tmp_path: Path) -> None:
    path = tmp_path / "loads.csv"
    path.write_text(text(), encoding="utf-8")
    with pytest.raises(DataError, match=r"loads\.csv: missing column\(s\) 'bushing_angle'"):
        read_load_history(path, frame="global")


def test_period_shorter_than_the_file_is_an_error(tmp_path: Path) -> None:
    path = tmp_path / "loads.csv"
    path.write_text(text(), encoding="utf-8")
    with pytest.raises(DataError, match=r"loads\.csv: period 1 s ends before the last row"):
        read_load_history(path, period=1.0)


# ---------------------------------------------------------------- CLI
def cli(argv: list[str], capsys: pytest.CaptureFixture[str]) -> tuple[int, str, str]:
    try:
        main(argv)
    except SystemExit as exc:
        code = int(exc.code or 0)
    else:
        code = 0
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def test_dynamics_of_a_load_history_config(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    loads = write_csv(tmp_path / "loads.csv", example_columns())
    (tmp_path / "config.toml").write_text(f"[mechanism]\n{HISTORY}", encoding="utf-8")
    again = tmp_path / "again.csv"
    code, out, err = cli(
        ["dynamics", str(tmp_path / "config.toml"), "--json", "--csv", str(again)], capsys
    )
    assert (code, err) == (0, "")
    # a load history's own --csv output reads back as the same history
    assert_same_cycle(read_load_history(again), read_load_history(loads))
    data = json.loads(out)
    assert data["mechanism"] == "load-history"
    assert data["steps"] == 24
    assert data["period_s"] == 0.8
    assert data["history_sha256"] == hashlib.sha256(loads.read_bytes()).hexdigest()


@pytest.mark.parametrize("case", ["missing-file", "unknown-column", "wrong-dimension", "nan"])
def test_dynamics_reports_a_bad_history_in_one_line(
    case: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    content, expected = BAD_FILES[case]
    if content is not None:
        (tmp_path / "loads.csv").write_text(content, encoding="utf-8")
    (tmp_path / "config.toml").write_text(f"[mechanism]\n{HISTORY}", encoding="utf-8")
    code, out, err = cli(["dynamics", str(tmp_path / "config.toml"), "--json"], capsys)
    assert code == 2
    assert out == ""
    assert err.count("\n") == 1
    assert err.startswith(f"error: {(tmp_path / 'loads.csv').resolve()}: ")
    assert expected in err


def test_example_load_history_runs(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = cli(["run", str(EXAMPLE), "--json"], capsys)
    assert code == 0, err
    assert json.loads(out)["peak_wear_depth_m"] > 0
    # 181 rows in ms and kN: the last closes the cycle
    cycle = load_cycle(load_config(EXAMPLE))
    assert (cycle.steps, cycle.period) == (180, pytest.approx(0.72, rel=1e-15, abs=0))
    assert cycle.rotation[-1] == pytest.approx(0.0, abs=1e-12)  # the pin swings back
    assert 100 < cycle.load.min() < cycle.load.max() < 1000


@pytest.mark.parametrize(
    "example",
    ["paper/table3_winkler_120rpm.toml", "four_bar.toml", "oscillating_liner.toml"],
)
def test_every_mechanism_writes_what_reads_back(tmp_path: Path, example: str) -> None:
    """A mechanism's diagnostics must be known to the reader, or its CSV would not read back."""
    from jointwear.mechanism.stage import load_cycles
    from jointwear.workflows.dynamics import write_csv

    root = Path(__file__).resolve().parents[2] / "examples"
    for joint, cycle in load_cycles(load_config(root / example)).items():
        path = tmp_path / f"{joint}.csv"
        write_csv(path, cycle)
        back = read_load_history(path)
        np.testing.assert_allclose(back.load, cycle.load, rtol=1e-12)
        np.testing.assert_allclose(
            back.relative_rotation,
            cycle.relative_rotation,
            rtol=0,
            atol=1e-12 * np.abs(cycle.relative_rotation).max(),
        )
