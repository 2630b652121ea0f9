"""
Wear along the pin: a misaligned pin
====================================

The paper's joint with its pin tilted by 3e-4 rad (0.017 deg) against the bushing, as
when the bores of a clevis are out of line. One cycle of the slider-crank's load is
balanced on 20 slices along the pin (:func:`jointwear.contact.axial.solve_axial`, the
asymmetric Winkler law), each slice's pressure worn by Archard's law, and the wear of one
revolution scaled to 10 000 (no contour update: the first revolution's rate). The result
is laid out as a run cut into slices writes it (``wear_depth`` over ``revolution``,
``z``, ``theta``) and drawn with :mod:`jointwear.plots_axial`.

Run: ``python examples/wear_map_along_the_pin.py``
"""

from __future__ import annotations

import numpy as np
import xarray as xr

import jointwear as jw
from jointwear.contact import ContactParameters, contact_law
from jointwear.contact.axial import AxialSlices, Misalignment, solve_axial
from jointwear.mechanism.stage import load_cycle
from jointwear.plots_axial import edge_profiles, wear_map, worn_bore
from jointwear.tribology.archard import wear_depth
from jointwear.tribology.sliding import SLIDING_MODELS

REVOLUTIONS = 10_000
config = jw.load_config(None, {"contact.nodes": 360, "simulation.steps_per_revolution": 180})
joint = config.joint
cycle = load_cycle(config)
sliding = SLIDING_MODELS.get(config.simulation.sliding)(cycle, joint.bushing_radius)
law = contact_law("asymmetric-winkler", ContactParameters.from_config(config))
slices = AxialSlices(joint.axial_length, 20)
contours = slices.contours(jw.BushingContour.circle(joint.bushing_radius, 360, joint.axial_length))
pin = jw.Pin(joint.pin_radius)
tilt = Misalignment(3e-4, plane=0.0)

# pressure of every slice and node at every step: (steps, slices, nodes)
pressure = np.stack(
    [
        solve_axial(contours, slices, pin, load, azimuth, law, misalignment=tilt).pressure
        for load, azimuth in zip(cycle.load, cycle.azimuth, strict=True)
    ]
)
coefficient = config.materials.bushing.wear_coefficient
per_revolution = np.stack(
    [wear_depth(pressure[:, i], sliding, coefficient) for i in range(slices.count)]
)
final = REVOLUTIONS * per_revolution
theta = contours[0].theta
result = xr.Dataset(
    {
        "wear_depth": (("revolution", "z", "theta"), np.stack([0 * final, final]), {"units": "m"}),
        "bushing_radius": (("z", "theta"), joint.bushing_radius + final, {"units": "m"}),
        "wear_rate": (("z", "theta"), per_revolution, {"units": "m"}),
    },
    coords={
        "revolution": [0.0, float(REVOLUTIONS)],
        "z": ("z", slices.centres, {"units": "m", "long_name": "axial position of slice centre"}),
        "theta": theta,
    },
    attrs={"contact_model": "asymmetric-winkler"},
)
peak_row, peak_node = np.unravel_index(np.argmax(final), final.shape)
print(
    f"deepest wear {final.max() * 1e6:.2f} um at z = {slices.centres[peak_row] * 1e3:+.2f} mm, "
    f"{np.degrees(theta[peak_node]):.0f} deg; the deepest of each end over the mid-plane's: "
    f"{final[0].max() / final[9:11].mean(axis=0).max():.2f}, "
    f"{final[-1].max() / final[9:11].mean(axis=0).max():.2f}"
)

# %%
# The bore unrolled: angle across, axial position up. The tilt presses one end of the
# bushing harder in the half of the cycle that loads it towards the tilt's plane.
unrolled = wear_map(result, label="misaligned pin")

# %%
# The worn profile at the mid-plane and in the two end slices.
profiles = edge_profiles(result, label="misaligned pin")

# %%
# The worn bore in 3-D, the radial wear exaggerated (the factor is in the title).
bore = worn_bore(result, label="misaligned pin")
