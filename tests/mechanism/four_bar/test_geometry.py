"""The four-bar's geometry: Grashof's condition, change points and assembly are refused."""

from __future__ import annotations

from pathlib import Path

import pytest

from jointwear.config import load_config
from jointwear.errors import ConfigError
from jointwear.mechanism.four_bar.geometry import check_four_bar
from tests.mechanism.four_bar.linkages import linkage

EXAMPLE = Path(__file__).resolve().parents[3] / "examples" / "four_bar.toml"


# ------------------------------------------------------------------ validation


@pytest.mark.parametrize(
    ("lengths", "key", "words"),
    [
        ((0.2, 0.13, 0.18, 0.12), "mechanism.crank_length:", "shortest"),
        ((0.3, 0.05, 0.12, 0.12), "mechanism.crank_length:", "Grashof"),
        ((0.2, 0.05, 0.2, 0.05), "mechanism.crank_length:", "change-point"),
        ((0.2, 0.05, 0.15, 0.1), "mechanism.crank_length:", "change-point"),
    ],
)
def test_linkages_whose_crank_cannot_turn_are_rejected(lengths, key: str, words: str) -> None:
    with pytest.raises(ConfigError) as info:
        check_four_bar(*lengths)
    message = str(info.value)
    assert message.startswith(key)
    assert words in message
    assert "\n" not in message


def test_config_rejects_a_non_grashof_linkage_naming_the_key() -> None:
    with pytest.raises(ConfigError, match=r"^mechanism\.crank_length: Grashof"):
        load_config(EXAMPLE, {"mechanism.ground_length": "0.4 m"})
    with pytest.raises(ConfigError, match=r"^mechanism\.crank_length: the crank"):
        load_config(EXAMPLE).replace({"mechanism.crank_length": "0.15 m"})


def test_assembly_name_and_lengths_checked() -> None:
    with pytest.raises(ConfigError, match=r"^mechanism\.assembly:"):
        linkage(assembly="inverted")
    with pytest.raises(ConfigError, match=r"^mechanism\.ground_length:"):
        check_four_bar(-0.2, 0.05, 0.18, 0.12)
