"""Shared synthetic measurement: a Table 5-sized wear scar seen by an optical instrument."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pytest

from jointwear.measurement.synthetic import cosine_squared_scar, synthesize_measurement


@dataclass(frozen=True)
class Scenario:
    """A worn bushing and how the instrument sees it (SI units)."""

    radius: float = 7.5e-3  # unworn radius of the paper's bushing [m]
    nodes: int = 360
    peak: float = 60e-6  # Table 5 scale: 60 um deep ...
    width: float = np.radians(170.0)  # ... over 170 deg [rad]
    scar_angle: float = np.radians(30.0)  # deepest point, bushing frame [rad]
    center: tuple[float, float] = (12.3e-3, -4.0e-3)  # bushing centre, instrument frame [m]
    rotation: float = np.radians(40.0)  # bushing theta = 0 in the instrument frame [rad]
    noise: float = 1e-6  # radial noise [m]
    points: int = 3600
    seed: int = 20240611

    @property
    def depth(self) -> np.ndarray:
        return cosine_squared_scar(self.nodes, self.peak, self.width, self.scar_angle)

    def measure(self) -> tuple[np.ndarray, np.ndarray]:
        return synthesize_measurement(
            self.depth,
            self.radius,
            self.points,
            self.noise,
            self.seed,
            self.center,
            self.rotation,
        )

    @property
    def scar_direction(self) -> np.ndarray:
        """Unit vector towards the deepest point in the instrument frame."""
        angle = self.scar_angle + self.rotation
        return np.array([np.cos(angle), np.sin(angle)])


@pytest.fixture(scope="session")
def scenario() -> Scenario:
    return Scenario()


@pytest.fixture(scope="session")
def worn_points(scenario: Scenario) -> tuple[np.ndarray, np.ndarray]:
    """3600 randomly spaced points with 1 um radial noise, in a shifted and rotated frame."""
    return scenario.measure()
