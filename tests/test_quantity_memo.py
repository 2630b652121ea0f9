"""The memo of quantity texts: pint's answers reused by later processes, nothing else.

A text pint converted is recalled with the same bits in a fresh process that imports no
pint; a text pint refuses is refused by pint every time, with its message; a memo of
other code or another pint is not read.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from jointwear import quantity_memo
from jointwear.errors import ConfigError
from jointwear.units import to_si

SRC = Path(__file__).resolve().parents[1] / "src"
PAPER = Path(__file__).resolve().parent / "data" / "paper_joint.toml"


def fresh_process(code: str, memo: Path | str) -> dict:
    """The JSON ``code`` prints, run in a fresh interpreter whose memo folder is ``memo``."""
    path = os.pathsep.join([str(SRC), os.environ.get("PYTHONPATH", "")])
    env = {**os.environ, "PYTHONPATH": path, quantity_memo.ENVIRONMENT: str(memo)}
    done = subprocess.run(
        [sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=120
    )
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


LOAD = (
    "import json, sys\n"
    "from jointwear.config import load_config\n"
    f"config = load_config({str(PAPER)!r})\n"
    "print(json.dumps({'config': config.to_dict(), 'pint': 'pint' in sys.modules}))\n"
)


def test_a_config_read_before_is_read_again_without_pint(tmp_path):
    first = fresh_process(LOAD, tmp_path)
    again = fresh_process(LOAD, tmp_path)
    assert first["pint"]
    assert not again["pint"]
    # the same bits: JSON keeps a float's shortest repr, which reads back exactly
    assert again["config"] == first["config"]
    assert (tmp_path / quantity_memo.FILE_NAME).is_file()


def test_no_folder_no_memo(tmp_path):
    assert fresh_process(LOAD, "")["pint"]
    assert fresh_process(LOAD, "")["pint"]


def test_a_memo_of_other_code_or_another_pint_is_not_read(tmp_path):
    wrong = {"stamp": "another", "texts": {"70 mm": {"m|": 1.0}}}
    (tmp_path / quantity_memo.FILE_NAME).write_text(json.dumps(wrong))
    code = (
        "import json\nfrom jointwear.units import to_si\n"
        "print(json.dumps(to_si('70 mm', 'length')))\n"
    )
    assert fresh_process(code, tmp_path) == pytest.approx(0.07)
    # and replaced by this code's memo
    assert json.loads((tmp_path / quantity_memo.FILE_NAME).read_text())["stamp"] != "another"


def stamped(texts: object) -> str:
    return json.dumps({"stamp": quantity_memo.stamp(), "texts": texts})


@pytest.mark.parametrize(
    "content",
    ["", "{", "[1, 2]", '{"stamp": 3}', "\x00\xff", "STAMPED-TEXT", "STAMPED-TARGET"],
)
def test_a_broken_memo_is_no_error(tmp_path, content):
    # (an entry of the right stamp but the wrong shape is read as absent)
    content = content.replace("STAMPED-TEXT", stamped({"120 rpm": 5}))
    content = content.replace("STAMPED-TARGET", stamped({"120 rpm": {"rad/s|1": True}}))
    (tmp_path / quantity_memo.FILE_NAME).write_text(content, encoding="latin-1")
    code = (
        "import json\nfrom jointwear.units import to_si\n"
        "print(json.dumps(to_si('120 rpm', 'angular_velocity')))\n"
    )
    assert fresh_process(code, tmp_path) == pytest.approx(4 * 3.141592653589793)


def test_refused_texts_are_not_remembered_and_keep_their_messages():
    for _ in range(2):
        with pytest.raises(ConfigError, match="has dimension"):
            to_si("70 kg", "length", "joint.clearance")
    assert not quantity_memo.has_unit("70 kg")


def test_a_text_remembered_for_one_kind_is_converted_by_pint_for_another():
    assert to_si("3 mm", "length") == pytest.approx(3e-3)
    assert quantity_memo.has_unit("3 mm")
    with pytest.raises(ConfigError, match="has dimension"):
        to_si("3 mm", "mass", "k")
    # the rate's radian power is part of what was asked: rpm in rad/s and in Hz differ
    assert to_si("60 rpm", "angular_velocity") == pytest.approx(2 * 3.141592653589793)
    assert to_si("60 rpm", "frequency") == pytest.approx(1.0)
    assert to_si("60 rpm", "angular_velocity") == pytest.approx(2 * 3.141592653589793)
