"""
A greased oscillating pin
=========================

A heavily loaded pivot, as in an excavator's arm: a steel pin of 50 mm swinging
+-30 degrees once every 10 s in a bronze bushing under 40 kN, greased with a
lithium-complex EP grease (NLGI 2, base oil ISO VG 220). A grease in a slowly
oscillating pin builds no film to speak of: the squeeze of its base oil slows the pin's
approach to the wall, but over the cycle the pin settles on its asperities and the
bulk contact, and the joint wears as a boundary-lubricated one. The bronze's wear
coefficient in the materials library is the boundary-lubricated value
(``jointwear materials``), so the dry run is the greased pin's wear without a film.

Run: ``python examples/greased_oscillating_pin.py``.
"""

from __future__ import annotations

import jointwear as jw
from jointwear.plots import plot_wear_result

pivot = [
    "mechanism.type=oscillating",
    "mechanism.load=40 kN",
    "mechanism.load_angle=-90 deg",
    "mechanism.amplitude=30 deg",
    "mechanism.frequency=0.1 Hz",
    "joint.pin_radius=25 mm",
    "joint.clearance=0.1 mm",
    "joint.axial_length=60 mm",
    "joint.bushing_thickness=5 mm",
    "materials.pin=steel",
    "materials.bushing=bronze",
    "simulation.steps_per_revolution=120",
]
boundary = jw.Simulation(jw.load_config(overrides=pivot)).run(pressures=False).summary()
greased = [
    *pivot,
    "lubrication.model=finite-length",
    "lubrication.lubricant=grease-lithium-complex-ep-nlgi2",
    "lubrication.temperature=40 degC",
    "lubrication.roughness=0.8 um",
]
result = jw.Simulation(jw.load_config(overrides=greased)).run()
wet = result.summary()
print(
    f"without film: wear volume {boundary['wear_volume_m3'] * 1e18:.4g} um^3 per cycle\n"
    f"greased:      wear volume {wet['wear_volume_m3'] * 1e18:.4g} um^3 per cycle, "
    f"{wet['lubrication_regime']} (least film parameter {wet['min_film_parameter']:.2f}); "
    f"solid contact carries {100 * wet['asperity_load_fraction']:.1f} % of the load"
)

# %%
# The grease's base oil carries next to nothing: the regime is boundary and the wear
# is within a few per cent of the wear without a film.
ratio = wet["wear_volume_m3"] / boundary["wear_volume_m3"]
if wet["lubrication_regime"] != "boundary" or not 0.9 < ratio <= 1.0:
    raise RuntimeError(f"a greased slow pivot should wear as a boundary-lubricated one: {ratio}")

# %%
# The pin rests near the bottom of its clearance and swings a little with the sliding.
orbit = plot_wear_result(result, "journal_orbit")

# %%
film = plot_wear_result(result, "film")
