"""The warnings a run gives once when its wear questions the load it was given."""

from __future__ import annotations

import pytest

from jointwear import Simulation
from jointwear.config import Config
from jointwear.errors import WearFeedbackWarning


def test_massless_link_warns_when_wear_passes_the_clearance(small: Config) -> None:
    config = small.replace(
        {
            "simulation.revolutions": 40000,
            "simulation.update_contour": True,
            "simulation.update_every": "adaptive",
        }
    )
    with pytest.warns(WearFeedbackWarning, match="contact-impact") as caught:
        Simulation(config).run()
    assert sum("clearance" in str(w.message) for w in caught) == 1  # said once
