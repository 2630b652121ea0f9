"""Output files: strict JSON."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from jointwear.cli.common import emit_json
from jointwear.io import write_json
from tests.conftest import strict_json

#: what a summary may hold where a value is unknown or undefined
UNDEFINED = {
    "nan": math.nan,
    "inf": -math.inf,
    "numpy": np.float64("nan"),
    "nested": {"quantiles": [1.0, math.nan], "bound": (math.inf, 2)},
}
#: the same in JSON: null
NULLS = {
    "nan": None,
    "inf": None,
    "numpy": None,
    "nested": {"quantiles": [1.0, None], "bound": [None, 2]},
}


def test_written_json_is_strict(tmp_path: Path) -> None:
    write_json(tmp_path / "out.json", UNDEFINED)
    assert strict_json((tmp_path / "out.json").read_text(encoding="utf-8")) == NULLS


def test_printed_json_is_strict(capsys) -> None:
    emit_json(UNDEFINED)
    assert strict_json(capsys.readouterr().out) == NULLS
