"""
Contact models side by side
===========================

The paper's four contact models and the two references (exact elasticity and
finite elements of the bushing wall) on the unworn bushing: contact half-angle,
peak pressure and approach for a range of loads, and the pressure distributions
at 200 N.

Run: ``python examples/contact_models.py``
"""

from __future__ import annotations

import numpy as np

import jointwear as jw
from jointwear.contact import CONTACT_MODELS, ContactParameters, solve
from jointwear.plots import new_figure

config = jw.load_config()
parameters = ContactParameters.from_config(config)
contour = jw.BushingContour.circle(config.joint.bushing_radius, 360, config.joint.axial_length)
pin = jw.Pin(config.joint.pin_radius)
loads = np.array([50.0, 100.0, 200.0, 400.0])  # [N]

solutions = {
    model: solve(contour, pin, loads, np.zeros_like(loads), model, parameters)
    for model in CONTACT_MODELS.names()
}
print(
    f"{'model':20s} {'load [N]':>9s} {'half-angle [deg]':>17s} {'peak [MPa]':>11s} "
    f"{'approach [um]':>14s}"
)
for model, solution in solutions.items():
    for i, load in enumerate(loads):
        print(
            f"{model:20s} {load:9.0f} {np.degrees(solution.half_angle_left[i]):17.2f} "
            f"{solution.pressure[i].max() / 1e6:11.3f} {solution.penetration[i] * 1e6:14.3f}"
        )

# %%
# Pressure over the bushing at 200 N, the load pointing at 0 deg.
angle = np.degrees(np.angle(np.exp(1j * contour.theta)))  # (-180, 180]
order = np.argsort(angle)
fig = new_figure((7, 4))
ax = fig.subplots()
for model, solution in solutions.items():
    ax.plot(angle[order], solution.pressure[2, order] / 1e6, label=model)
ax.set_xlim(-90, 90)
ax.set_xlabel("angle from the load line [deg]")
ax.set_ylabel("contact pressure [MPa]")
ax.set_title("Unworn bushing, 200 N")
ax.grid(alpha=0.3)
ax.legend(fontsize=8)
