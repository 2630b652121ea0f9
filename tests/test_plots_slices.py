"""The figures of a run along the pin: until the wear-map figures, each figure shows the
slice worn deepest."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear import Simulation, load_config
from jointwear.plots import FIGURES, plot_dataset


@pytest.mark.parametrize("kind", FIGURES)
def test_every_figure_of_a_map_draws_the_slice_worn_deepest(kind):
    config = load_config(
        overrides={
            "contact.nodes": 48,
            "simulation.steps_per_revolution": 12,
            "simulation.revolutions": 2,
            "simulation.update_contour": True,
            "contact.spring_area": None,
            "joint.axial_slices": 3,
            "joint.load_offset": "-4 mm",
        }
    )
    dataset = Simulation(config).run().dataset
    figure = plot_dataset(dataset, kind)
    assert "z = -6.67 mm" in figure.axes[0].get_title()
    if kind == "wear_profiles":
        drawn = figure.axes[0].lines[-1].get_ydata()
        deepest = dataset["wear_depth"].values[-1, 0]
        np.testing.assert_allclose(drawn / drawn.max(), deepest / deepest.max(), rtol=1e-12)
