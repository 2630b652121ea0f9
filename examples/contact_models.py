"""The four contact models of the paper on the unworn bushing, side by side.

Run: python examples/contact_models.py
"""

from __future__ import annotations

import numpy as np

import jointwear as jw
from jointwear.contact import CONTACT_MODELS, ContactParameters, solve

config = jw.load_config()
parameters = ContactParameters.from_config(config)
contour = jw.BushingContour.circle(config.joint.bushing_radius, 360, config.joint.axial_length)
pin = jw.Pin(config.joint.pin_radius)
loads = np.array([50.0, 100.0, 200.0, 400.0])  # [N]

print(
    f"{'model':20s} {'load [N]':>9s} {'half-angle [deg]':>17s} {'peak [MPa]':>11s} "
    f"{'approach [um]':>14s}"
)
for model in CONTACT_MODELS.names():
    solution = solve(contour, pin, loads, np.zeros_like(loads), model, parameters)
    for i, load in enumerate(loads):
        print(
            f"{model:20s} {load:9.0f} {np.degrees(solution.half_angle_left[i]):17.2f} "
            f"{solution.pressure[i].max() / 1e6:11.3f} {solution.penetration[i] * 1e6:14.3f}"
        )
