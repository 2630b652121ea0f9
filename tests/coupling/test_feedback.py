"""The warnings a run gives once when its wear questions the load it was given."""

from __future__ import annotations

import pytest

from jointwear import Simulation
from jointwear.config import Config
from jointwear.coupling.feedback import FeedbackWarnings
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


def test_an_oiled_pin_off_the_wall_is_no_separation() -> None:
    """A pin the film carries is in free flight all the time; only its impacts are said."""
    dry_row = {"impacts": 0.0, "free_flight_fraction": 0.2}
    film_row = {"impacts": 0.0, "free_flight_fraction": 1.0, "min_film_thickness": 2e-5}
    with pytest.warns(WearFeedbackWarning, match="separates"):
        FeedbackWarnings(5e-5).check_separation(dry_row, 0.0)
    quiet = FeedbackWarnings(5e-5)
    quiet.check_separation(film_row, 0.0)
    assert quiet.messages == ()
    with pytest.warns(WearFeedbackWarning, match="breaks through its oil film"):
        FeedbackWarnings(5e-5).check_separation({**film_row, "impacts": 1.0}, 0.0)
