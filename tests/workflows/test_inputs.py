"""What a workflow reads: a config file, loads and rotations given with units."""

from __future__ import annotations

import math

import pytest

from jointwear.errors import ConfigError
from jointwear.workflows.inputs import load_config_file, parse_align, parse_loads, split_list


def test_loads_are_read_in_newtons_whatever_their_unit():
    assert parse_loads("50 N, 0.1 kN,200 N") == pytest.approx([50.0, 100.0, 200.0])
    assert parse_loads("10 lbf") == pytest.approx([10 * 4.4482216152605])


@pytest.mark.parametrize("text", ["", "0 N", "-5 N", "50 N,inf N", "5 kg"])
def test_loads_that_are_no_positive_forces_are_refused(text):
    with pytest.raises(ConfigError, match="^--loads"):
        parse_loads(text)


def test_an_alignment_is_best_or_an_angle_in_radians():
    assert parse_align(" Best ") == "best"
    assert parse_align("90 deg") == pytest.approx(math.pi / 2)
    with pytest.raises(ConfigError, match="^--align"):
        parse_align("12 mm")


def test_repeated_and_comma_separated_values_are_one_list():
    assert split_list(["nlcp, winkler", "", "hertz,"]) == ["nlcp", "winkler", "hertz"]
    assert split_list(None) == []


def test_a_config_file_that_is_missing_is_named(tmp_path, paper_config_path):
    with pytest.raises(ConfigError, match=r"^\S*nope.toml: file not found$"):
        load_config_file(tmp_path / "nope.toml")
    config = load_config_file(paper_config_path, ["joint.clearance=0.2 mm"])
    assert config.joint.clearance == pytest.approx(2e-4)
