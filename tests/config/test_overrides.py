"""Overrides: ``--set`` parsing, dotted keys with units, Config.replace's forms."""

from __future__ import annotations

import math

import pytest

from jointwear.config import load_config, parse_override
from jointwear.errors import ConfigError


@pytest.mark.parametrize(
    ("text", "key", "value"),
    [
        ("joint.clearance=0.2 mm", "joint.clearance", "0.2 mm"),
        ('joint.clearance="0.2 mm"', "joint.clearance", "0.2 mm"),
        ("contact.nodes=720", "contact.nodes", 720),
        ("contact.tolerance=1e-10", "contact.tolerance", 1e-10),
        ("simulation.update_contour=true", "simulation.update_contour", True),
        ("contact.model = nlcp", "contact.model", "nlcp"),
        ("mechanism.crank_speed=240 rpm", "mechanism.crank_speed", "240 rpm"),
    ],
)
def test_parse_override(text, key, value):
    assert parse_override(text) == (key, value)


@pytest.mark.parametrize("text", ["joint.clearance", "=3", ""])
def test_parse_override_rejects_malformed(text):
    with pytest.raises(ConfigError, match="section.key=VALUE"):
        parse_override(text)


def test_overrides_apply_with_units(paper_config_path):
    cfg = load_config(
        paper_config_path,
        [
            "mechanism.crank_speed=240 rpm",
            'joint.clearance="0.2 mm"',
            "contact.nodes=720",
            "contact.model=nlcp",
            "contact.nlcp_variant=mesh-independent",
        ],
    )
    assert cfg.mechanism.crank_speed == pytest.approx(8 * math.pi, rel=1e-15, abs=0)
    assert cfg.joint.clearance == pytest.approx(2e-4, rel=1e-15, abs=0)
    assert cfg.contact.nodes == 720
    assert cfg.contact.model == "nlcp"
    assert cfg.contact.nlcp_variant == "mesh-independent"
    # mapping overrides and Config.replace do the same
    same = load_config(paper_config_path, {"mechanism.crank_speed": "240 rpm"})
    assert same.mechanism.crank_speed == cfg.mechanism.crank_speed
    replaced = load_config(paper_config_path).replace({"joint.clearance": "0.2 mm"})
    assert replaced.joint.clearance == cfg.joint.clearance


def test_replace_takes_a_mapping_strings_or_one_string(paper_config):
    wider = 2e-4
    for overrides in (
        {"joint.clearance": "0.2 mm"},
        ["joint.clearance=0.2 mm"],
        ("joint.clearance=0.2 mm" for _ in range(1)),
        "joint.clearance=0.2 mm",
    ):
        assert paper_config.replace(overrides).joint.clearance == pytest.approx(
            wider, rel=1e-15, abs=0
        )
    # one string is one override, not a sequence of one-character ones
    with pytest.raises(ConfigError, match=r"^joint\.clearance: .*'abc'"):
        paper_config.replace("joint.clearance=abc")


@pytest.mark.parametrize(
    "overrides", [5, None, b"joint.clearance=1e-4", [("joint.clearance", 1e-4)]]
)
def test_replace_refuses_other_overrides_with_a_config_error(paper_config, overrides):
    with pytest.raises(ConfigError, match="^overrides: expected") as info:
        paper_config.replace(overrides)
    assert "\n" not in str(info.value)
