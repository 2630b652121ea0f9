"""What the balance's tests share: a batch of loads and independent resultants."""

from __future__ import annotations

import numpy as np

EPS = np.finfo(float).eps
SPRING_MODELS = ["winkler", "asymmetric-winkler", "nlcp"]
PAPER_MODELS = ["hertz", *SPRING_MODELS]  # the registry may hold reference models too
RNG = np.random.default_rng(2024)
LOADS = np.concatenate([[0.0, 1e-3, 0.1], RNG.uniform(1, 400, 12), [1000.0, 3000.0]])
AZIMUTHS = RNG.uniform(-np.pi, np.pi, LOADS.size)


def force_area(model, contour, params, azimuth):
    """Area turning node pressure into node force, shape (M, N) [m^2]."""
    shape = (np.size(azimuth), contour.nodes)
    if model == "nlcp" and params.nlcp_variant == "paper":
        return np.full(shape, params.spring_area)
    if model == "winkler":  # springs on the circle through the compression centre
        radius = contour.radius_at(azimuth)
        return np.broadcast_to((radius * contour.dtheta * contour.axial_length)[:, None], shape)
    return np.broadcast_to(contour.spring_area, shape)


def resultants(sol, contour, area, azimuth):
    """Independent resultant along and across the load, and sum |f_j|."""
    force = sol.pressure * area
    phi = contour.theta[None, :] - np.asarray(azimuth)[:, None]
    return (force * np.cos(phi)).sum(1), (force * np.sin(phi)).sum(1), np.abs(force).sum(1)


def bound(total):
    return np.maximum(1e-12, 8 * EPS * total)


def pin_frame(sol, azimuth):
    """Pin displacement along / across the load [m]."""
    c, s = np.cos(azimuth), np.sin(azimuth)
    e = sol.eccentricity
    return e[:, 0] * c + e[:, 1] * s, -e[:, 0] * s + e[:, 1] * c


def revolution_loads(count: int = 360) -> tuple[np.ndarray, np.ndarray]:
    """A smooth load history like a revolution's: 130-420 N, the direction sweeping 60 deg."""
    t = np.linspace(0, 2 * np.pi, count, endpoint=False)
    return 275 + 125 * np.sin(t) + 20 * np.sin(3 * t), np.radians(180 + 30 * np.sin(t))
