"""
Your own load history and contact law
=====================================

A load history exported from any multibody code (magnitude, direction on the
bushing and relative rotation per step of one cycle) drives the same wear
pipeline; a contact model can be any function ``pressure(penetration)``.

Run: ``python examples/own_load_history.py``
"""

from __future__ import annotations

import numpy as np

import jointwear as jw
from jointwear.mechanism import JointLoad
from jointwear.plots import new_figure

steps = 180
phase = 2 * np.pi * np.arange(steps) / steps
history = JointLoad.from_history(
    load=300 + 150 * np.cos(phase),  # [N]
    azimuth=np.radians(25) * np.sin(phase),  # [rad], oscillating hinge load
    relative_rotation=np.full(steps, np.radians(60) * 2 / steps),  # +-30 deg oscillation
    crank_speed=2 * np.pi,  # one cycle per second
)

config = jw.load_config(
    overrides={
        "contact.nodes": 360,
        "simulation.steps_per_revolution": steps,
        "simulation.revolutions": 20000,
        "simulation.update_contour": True,
        "simulation.update_every": 500,
    }
)


def stiffening_foundation(penetration: np.ndarray) -> np.ndarray:
    """A foundation that stiffens with compression, p = k d (1 + d / d0) [Pa]."""
    return 1.5e11 * penetration * (1 + penetration / 5e-6)


results = {}
for name, model in (("winkler", "asymmetric-winkler"), ("custom", stiffening_foundation)):
    results[name] = jw.Simulation(config, contact_model=model, joint_load=history).run()
    summary = results[name].summary()
    print(
        f"{name:8s}: peak {summary['peak_wear_depth_m'] * 1e6:6.2f} um, "
        f"width {summary['wear_width_deg']:5.1f} deg, mass {summary['wear_mass_kg'] * 1e6:.3f} mg"
    )

# %%
# The two worn profiles after 20000 cycles.
fig = new_figure((7, 4))
ax = fig.subplots()
for name, result in results.items():
    theta = np.degrees(np.angle(np.exp(1j * result.dataset["theta"].values)))
    order = np.argsort(theta)
    ax.plot(theta[order], result.wear_depth[order] * 1e6, label=name)
ax.set_xlim(-120, 120)
ax.set_xlabel("bushing angle [deg]")
ax.set_ylabel("wear depth [µm]")
ax.set_title("20000 cycles of an oscillating hinge load")
ax.grid(alpha=0.3)
ax.legend()
