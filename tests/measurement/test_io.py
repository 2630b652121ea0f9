"""Reading measured points: formats, units, and one clear DataError per bad file."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from jointwear.errors import ConfigError, DataError
from jointwear.measurement.io import read_points

R_MM = 7.5
CENTER_MM = (12.3, -4.0)


def ring_mm(n: int = 40, span_deg: float = 360.0) -> tuple[np.ndarray, np.ndarray]:
    # a full ring without its duplicate end point; a partial arc with both ends
    t = np.radians(span_deg) * np.arange(n) / (n if span_deg == 360.0 else n - 1)
    return CENTER_MM[0] + R_MM * np.cos(t), CENTER_MM[1] + R_MM * np.sin(t)


def write(path: Path, header: str | None, x: np.ndarray, y: np.ndarray, sep: str = ",") -> Path:
    lines = [] if header is None else [header]
    lines += [f"{a:.17g}{sep}{b:.17g}" for a, b in zip(x, y, strict=True)]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def test_csv_header_with_units(tmp_path: Path) -> None:
    x_mm, y_mm = ring_mm()
    x, y = read_points(write(tmp_path / "p.csv", "x [mm],y [mm]", x_mm, y_mm))
    np.testing.assert_allclose(x, x_mm * 1e-3, rtol=1e-15)
    np.testing.assert_allclose(y, y_mm * 1e-3, rtol=1e-15)


@pytest.mark.parametrize(
    ("header", "file_units_per_mm"),
    [
        ("x,y", 1e-3),
        ("X [um], Y [um]", 1e3),
        ("x (µm),y (µm)", 1e3),
        ('"x [in]","y [in]"', 1 / 25.4),
    ],
)
def test_csv_header_variants(tmp_path: Path, header: str, file_units_per_mm: float) -> None:
    x_mm, y_mm = ring_mm()
    file = write(tmp_path / "p.csv", header, x_mm * file_units_per_mm, y_mm * file_units_per_mm)
    x, _ = read_points(file)
    np.testing.assert_allclose(x, x_mm * 1e-3, rtol=1e-12)


def test_csv_extra_columns_semicolons_comments_and_bom(tmp_path: Path) -> None:
    x_mm, y_mm = ring_mm()
    rows = "\n".join(f"{i};{a};{b};0.0" for i, (a, b) in enumerate(zip(x_mm, y_mm, strict=True)))
    file = tmp_path / "cmm.csv"
    file.write_text(
        "\ufeff# exported by the instrument\nid;y [mm];x [mm];z [mm]\n" + rows + "\n",
        encoding="utf-8",
    )
    x, y = read_points(file)
    np.testing.assert_allclose(x, y_mm * 1e-3)  # columns are found by name, not position
    np.testing.assert_allclose(y, x_mm * 1e-3)


def test_whitespace_text_with_units(tmp_path: Path) -> None:
    x_mm, y_mm = ring_mm()
    file = write(tmp_path / "p.txt", None, x_mm, y_mm, sep="   ")
    x, y = read_points(file, units="mm")
    np.testing.assert_allclose(x, x_mm * 1e-3)
    np.testing.assert_allclose(y, y_mm * 1e-3)
    x_m, _ = read_points(write(tmp_path / "m.txt", None, x_mm * 1e-3, y_mm * 1e-3, sep="\t"))
    np.testing.assert_allclose(x_m, x_mm * 1e-3)  # default metres


def test_units_argument_applies_to_header_without_units(tmp_path: Path) -> None:
    x_mm, y_mm = ring_mm()
    x, _ = read_points(write(tmp_path / "p.csv", "x,y", x_mm, y_mm), units="mm")
    np.testing.assert_allclose(x, x_mm * 1e-3)
    file = write(tmp_path / "q.csv", "x [mm],y [mm]", x_mm, y_mm)
    assert np.allclose(read_points(file, units="mm")[0], x_mm * 1e-3, atol=0)  # agreeing: fine
    with pytest.raises(DataError, match=r"q\.csv: column 'x' is in mm but units 'um'"):
        read_points(file, units="um")


def test_bad_units_argument_is_a_config_error(tmp_path: Path) -> None:
    x_mm, y_mm = ring_mm()
    with pytest.raises(ConfigError, match="'deg' is not a length unit"):
        read_points(write(tmp_path / "p.txt", None, x_mm, y_mm, sep=" "), units="deg")


def _one_column(path: Path) -> None:
    path.write_text("\n".join(str(v) for v in ring_mm()[0]) + "\n")


def _three_points(path: Path) -> None:
    write(path, None, *(a[:3] for a in ring_mm()), sep=" ")


def _nan(path: Path) -> None:
    x, y = ring_mm()
    x[5] = np.nan
    write(path, None, x, y, sep=" ")


def _quarter_arc(path: Path) -> None:
    write(path, None, *ring_mm(30, span_deg=90.0), sep=" ")


def _collinear(path: Path) -> None:
    write(path, None, np.arange(10.0), 2 * np.arange(10.0), sep=" ")


def _cloud(path: Path) -> None:
    rng = np.random.default_rng(0)
    write(path, None, rng.uniform(-5, 5, 50), rng.uniform(-5, 5, 50), sep=" ")


def _text_in_numbers(path: Path) -> None:
    path.write_text("x,y\n1,2\n3,abc\n")


def _ragged(path: Path) -> None:
    path.write_text("x,y\n1,2\n3\n")


def _no_y_column(path: Path) -> None:
    write(path, "x [mm],z [mm]", *ring_mm())


def _angle_unit(path: Path) -> None:
    write(path, "x [deg],y [deg]", *ring_mm())


def _empty(path: Path) -> None:
    path.write_text("# nothing measured\n")


def _binary(path: Path) -> None:
    path.write_bytes(bytes(range(256)))


@pytest.mark.parametrize(
    ("make", "message"),
    [
        (_one_column, "expected 2 columns"),
        (_three_points, "only 3 point"),
        (_nan, "non-finite value .* data row 6"),
        (_quarter_arc, "cover only 90°"),
        (_collinear, "collinear"),
        (_cloud, "do not lie on a ring"),
        (_text_in_numbers, "line 3: 'abc' is not a number"),
        (_ragged, "line 3: expected 2 columns, found 1"),
        (_no_y_column, "no 'y' column"),
        (_angle_unit, "'deg' is not a length unit"),
        (_empty, "no data"),
        (_binary, "not a text file"),
    ],
)
def test_bad_files_raise_one_line_data_error_naming_the_file(
    tmp_path: Path, make, message: str
) -> None:
    file = tmp_path / f"measured{make.__name__}.csv"
    make(file)
    with pytest.raises(DataError, match=message) as info:
        read_points(file, units="mm")
    text = str(info.value)
    assert text.startswith(str(file))
    assert "\n" not in text


def test_missing_file(tmp_path: Path) -> None:
    with pytest.raises(DataError, match=r"nope\.csv: file not found"):
        read_points(tmp_path / "nope.csv")
    with pytest.raises(DataError, match="is a directory"):
        read_points(tmp_path)


def test_half_ring_is_enough(tmp_path: Path) -> None:
    x, _ = read_points(write(tmp_path / "half.txt", None, *ring_mm(40, 190.0), sep=" "), "mm")
    assert x.size == 40
