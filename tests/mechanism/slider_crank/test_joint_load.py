"""The slider-crank's load cycle in the frame of the body that carries the bushing."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear.config import Config
from jointwear.geometry.angles import wrap_angle
from jointwear.mechanism import LoadCycle
from jointwear.mechanism.stage import load_cycle

# --------------------------------------------------------------- load object


def test_joint_load_fields(paper_config: Config) -> None:
    load = load_cycle(paper_config)
    n = paper_config.simulation.steps_per_revolution
    assert isinstance(load, LoadCycle)
    for name in ("phase", "time", "load", "azimuth", "relative_rotation", "force_x", "force_y"):
        assert getattr(load, name).shape == (n,)
    for name in ("crank_torque", "slider_position", "rod_angle"):
        assert load.diagnostics[name].values.shape == (n,)
    np.testing.assert_allclose(load.phase, 2 * np.pi * np.arange(n) / n)
    np.testing.assert_allclose(load.time, load.phase / paper_config.mechanism.crank_speed)
    assert load.period == pytest.approx(2 * np.pi / paper_config.mechanism.crank_speed)
    assert np.all(load.load >= 0)
    np.testing.assert_allclose(load.load, np.hypot(load.force_x, load.force_y))
    # pull spring, bushing on the slider: the pin presses towards the crank (-x)
    np.testing.assert_allclose(np.cos(load.azimuth), load.force_x / load.load)
    assert np.all(load.force_x < 0)
    weights = np.abs(load.relative_rotation)
    assert load.sliding_mean_load == pytest.approx(np.sum(load.load * weights) / weights.sum())
    assert not load.contact_lost
    assert not load.lost_steps.any()


def test_bushing_on_rod_frame(paper_config: Config) -> None:
    on_slider = load_cycle(paper_config)
    on_rod = load_cycle(paper_config.replace({"mechanism.bushing_body": "rod"}))
    np.testing.assert_allclose(on_rod.load, on_slider.load)
    np.testing.assert_allclose(on_rod.relative_rotation, -on_slider.relative_rotation)
    # the bushing sees -J, turned into the rod's frame
    expected = on_slider.azimuth + np.pi - on_slider.diagnostics["rod_angle"].values
    np.testing.assert_allclose(wrap_angle(on_rod.azimuth - expected), 0.0, atol=1e-12)
    # a bushing in the rod sees the load almost along the rod: a narrow azimuth band
    assert np.ptp(on_rod.azimuth) < 0.2 * np.ptp(on_slider.azimuth)
