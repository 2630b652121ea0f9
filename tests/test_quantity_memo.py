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
from jointwear.units import to_si, to_si_unit

SRC = Path(__file__).resolve().parents[1] / "src"
PAPER = Path(__file__).resolve().parent / "data" / "paper_joint.toml"


#: a fresh interpreter's memo begins empty, not from the package's seed
NO_SEED = "from jointwear import quantity_memo\nquantity_memo.SEED = None\n"


def fresh_process(code: str, memo: Path | str, seed: bool = False) -> dict:
    """The JSON ``code`` prints, run in a fresh interpreter whose memo folder is ``memo``
    (beginning from the package's seed if ``seed``)."""
    path = os.pathsep.join([str(SRC), os.environ.get("PYTHONPATH", "")])
    env = {**os.environ, "PYTHONPATH": path, quantity_memo.ENVIRONMENT: str(memo)}
    code = code if seed else NO_SEED + code
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
    # without the seed, every process sends every text to pint: nothing is kept
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
    # (the text itself, or its unit where pint read "mm" in another text before)
    assert quantity_memo.has_unit("3 mm") or quantity_memo.knows_unit("mm")
    with pytest.raises(ConfigError, match="has dimension"):
        to_si("3 mm", "mass", "k")
    # the rate's radian power is part of what was asked: rpm in rad/s and in Hz differ
    assert to_si("60 rpm", "angular_velocity") == pytest.approx(2 * 3.141592653589793)
    assert to_si("60 rpm", "frequency") == pytest.approx(1.0)
    assert to_si("60 rpm", "angular_velocity") == pytest.approx(2 * 3.141592653589793)


#: numbers written as a config might write them, read by pint and by the memo of units
NUMBERS = [
    "70", "7.45", "-3", "+2.5", "0.05", ".5", "5.", "1e-3", "2E7", "5.05e-13", "120",
    "0.1", "0.3", "1.1", "3.3333333333333335", "123456789012345678901", "9.81", "-0.0",
    "6.02214076e23", "1e-300",
]  # fmt: skip
#: (unit, how it is converted): to_si with a kind, or to_si_unit with an SI unit
UNITS = [
    ("mm", "length"), ("um", "length"), ("inch", "length"), ("rpm", "angular_velocity"),
    ("rpm", "frequency"), ("Hz", "angular_velocity"), ("cycle/min", "frequency"),
    ("deg/s", "angular_velocity"), ("deg", "angle"), ("GPa", "pressure"), ("MPa", "pressure"),
    ("m^2/N", "wear_coefficient"), ("kg/m^3", "density"), ("lbf", "force"),
    ("N/m", "stiffness"), ("m/s^2", "acceleration"), ("N/mm**1.5", "unit:N/m**1.5"),
]  # fmt: skip

CONVERT = (
    "import json, sys\n"
    "from jointwear.units import to_si, to_si_unit\n"
    "def convert(text, how):\n"
    "    return to_si_unit(text, how[5:]) if how.startswith('unit:') else to_si(text, how)\n"
    "texts = json.loads(sys.argv[1])\n"
    "values = [convert(text, how) for text, how in texts]\n"
    "print(json.dumps({'values': [repr(v) for v in values], 'pint': 'pint' in sys.modules}))\n"
)


def convert_all(texts: list[tuple[str, str]], memo: Path | str) -> dict:
    path = os.pathsep.join([str(SRC), os.environ.get("PYTHONPATH", "")])
    env = {**os.environ, "PYTHONPATH": path, quantity_memo.ENVIRONMENT: str(memo)}
    done = subprocess.run(
        [sys.executable, "-c", CONVERT, json.dumps(texts)],
        env=env, capture_output=True, text=True, timeout=120,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def test_new_numbers_in_units_read_before_convert_without_pint_to_pints_bits(tmp_path):
    # each unit read once, in a text of another number (pint reads it, the memo keeps it)
    primed = convert_all([(f"1.5 {unit}", how) for unit, how in UNITS], tmp_path)
    assert primed["pint"]
    texts = [(f"{number} {unit}", how) for unit, how in UNITS for number in NUMBERS]
    memo = convert_all(texts, tmp_path)
    assert not memo["pint"]
    # pint alone, with no memo: the same bits (repr of a float reads back exactly)
    assert memo["values"] == convert_all(texts, "")["values"]
    # texts of other shapes go to pint, whatever it makes of them ("007 mm" is 0 m)
    odd = [("007 mm", "length"), ("1_000 mm", "length"), ("1e5mm", "length"),
           ("2 mm * 3", "length"), ("5 mm / 2", "length"), ("1.5 1/min", "frequency")]  # fmt: skip
    assert convert_all(odd, tmp_path)["values"] == convert_all(odd, "")["values"]


def test_a_unit_read_before_keeps_pints_refusals_and_messages():
    assert to_si("70 mm", "length") == pytest.approx(0.07)
    assert quantity_memo.knows_unit("mm")
    # another dimension, a literal pint cannot read, a number beyond any value, too many
    # digits: pint's answers, with their messages
    with pytest.raises(ConfigError, match="joint.clearance: '75 mm' has dimension"):
        to_si("75 mm", "mass", "joint.clearance")
    with pytest.raises(ConfigError, match="cannot read '0x10 mm' as a quantity"):
        to_si("0x10 mm", "length", "joint.clearance")
    with pytest.raises(ConfigError, match="must be finite, got '1e400 mm'"):
        to_si("1e400 mm", "length", "joint.clearance")
    with pytest.raises(ConfigError, match="'1e104 mm' is beyond any physical value"):
        to_si("1e104 mm", "length", "joint.clearance")
    with pytest.raises(ConfigError, match="a number of 41 digits"):
        to_si("1" * 41 + " mm", "length", "joint.clearance")
    # a number in a unit is no bare number, whatever its size
    assert to_si("1500 mm", "length", "joint.pin_radius", bare_limit=1.0) == pytest.approx(1.5)


def test_a_unit_with_an_offset_is_not_kept():
    with pytest.raises(ConfigError):
        to_si_unit("20 degC", "K", "lubrication.temperature")
    assert to_si_unit("20 kelvin", "K") == 20.0
    assert quantity_memo.knows_unit("kelvin")
    assert not quantity_memo.knows_unit("degC")


SEED = json.loads(quantity_memo.SEED.read_text(encoding="utf-8"))
STALE = "the seed is stale: regenerate it with `python -m tests.units_seed`"


def test_the_seed_is_made_for_this_units_module():
    assert SEED["stamp"]["units"] == quantity_memo.seed_stamp()["units"], STALE


def test_the_seed_holds_pints_answers_bit_for_bit():
    from tests.units_seed import read_units

    now = read_units()
    for unit, targets in SEED["units"].items():
        for target, answer in targets.items():
            # JSON keeps a float's shortest repr, which reads back exactly
            assert now["units"][unit][target] == answer, (unit, target)
    if now["stamp"] == SEED["stamp"]:
        assert now == SEED, STALE


def test_a_fresh_install_reads_the_paper_without_pint(tmp_path):
    if quantity_memo.seed_stamp() != SEED["stamp"]:
        pytest.skip(f"the seed was made by pint {SEED['stamp']['pint']}; {STALE}")
    seeded = fresh_process(LOAD, tmp_path / "new", seed=True)
    assert not seeded["pint"]
    assert seeded["config"] == fresh_process(LOAD, "")["config"]


def test_a_seed_of_another_pint_is_not_used(tmp_path):
    other = {**SEED, "stamp": {**SEED["stamp"], "pint": "0.1"}}
    (tmp_path / "seed.json").write_text(json.dumps(other))
    code = (
        "import pathlib\nfrom jointwear import quantity_memo\n"
        f"quantity_memo.SEED = pathlib.Path({str(tmp_path / 'seed.json')!r})\n"
    )
    assert fresh_process(code + LOAD, tmp_path / "memo", seed=True)["pint"]


NEW_UNIT = (
    "import json, sys\nfrom jointwear.units import to_si\n"
    "print(json.dumps({'si': to_si('50 um', 'length'), 'pint': 'pint' in sys.modules}))\n"
)


def test_with_the_memo_turned_off_the_seed_is_still_read(tmp_path, monkeypatch):
    # the seed is the package's data, not the user's cache: a config in its units needs
    # no pint with the memo off too, to the same numbers; a unit it lacks goes to pint in
    # every process, and the memo writes nothing
    if quantity_memo.seed_stamp() != SEED["stamp"]:
        pytest.skip(f"the seed was made by pint {SEED['stamp']['pint']}; {STALE}")
    # the user's cache folder and the working folder both inside tmp_path
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    monkeypatch.setenv("HOME", str(tmp_path))
    monkeypatch.chdir(tmp_path)
    off = fresh_process(LOAD, "", seed=True)
    assert not off["pint"]
    assert off["config"] == fresh_process(LOAD, "")["config"]
    for _ in range(2):
        new = fresh_process(NEW_UNIT, "", seed=True)
        assert new == {"si": pytest.approx(5e-5, rel=1e-15), "pint": True}
    # (pint keeps a cache of its parsed definitions of its own, under "pint")
    assert not [p for p in tmp_path.rglob("*") if "pint" not in p.relative_to(tmp_path).parts]
