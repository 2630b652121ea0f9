"""The mechanism tables: a slider-crank that cannot assemble is refused."""

from __future__ import annotations

from pathlib import Path

import pytest

from jointwear.config import load_config
from jointwear.errors import ConfigError


@pytest.mark.parametrize("crank", ["0.2 m", "200 mm", "0.3 m"])
def test_crank_not_shorter_than_rod_is_rejected(paper_config_path, crank):
    with pytest.raises(ConfigError) as info:
        load_config(paper_config_path, [f'mechanism.crank_length="{crank}"'])
    message = str(info.value)
    assert message.startswith("mechanism.crank_length:")
    assert "rod_length" in message


def test_a_four_bar_whose_crank_cannot_turn_is_refused() -> None:
    """Grashof: s + l <= p + q, checked by the four-bar's own function (a lazy entry)."""
    example = Path(__file__).resolve().parents[2] / "examples" / "four_bar.toml"
    turning = load_config(example, {"mechanism.rocker_length": "130 mm"})  # 50 + 200 <= 310
    assert turning.mechanism.rocker_length == pytest.approx(0.13)
    with pytest.raises(ConfigError) as info:
        load_config(example, {"mechanism.rocker_length": "60 mm"})  # 50 + 200 > 240
    assert str(info.value).startswith("mechanism.crank_length: Grashof's condition s + l <= p + q")
