"""
Wear along the pin: a clevis pin in a misaligned lug
====================================================

The paper's joint as a clevis: the pin held in two forks 15 mm either side of the
bushing's mid-plane, the bore of the lug out of line by 0.03 deg against them, the pin
bending between the forks (a Timoshenko beam on the bushing's slices). Twenty slices
along the pin each wear on their own contour. The same joint with its bores in line is
run beside it: the misaligned pin wears the end of the bushing it tilts towards and
reaches the wear limit sooner.

Run: ``python examples/clevis_pin_misaligned.py``
"""

from __future__ import annotations

import jointwear as jw
from jointwear.plots_axial import edge_profiles, wear_map, worn_bore

COMMON = {
    "contact.model": "asymmetric-winkler",
    "contact.nodes": 180,
    "simulation.steps_per_revolution": 90,
    "simulation.revolutions": 20_000,
    "simulation.update_contour": False,  # the first revolution's wear rate, scaled
    "life.peak_wear_depth": "40 um",
    "joint.axial_slices": 20,
    "pin.model": "beam",
    "pin.support": "clevis",
    "pin.forks": ["-15 mm", "15 mm"],
}
aligned = jw.Simulation(jw.load_config(None, COMMON)).run()
misaligned = jw.Simulation(
    jw.load_config(None, {**COMMON, "joint.misalignment": "0.03 deg"})
).run()

for name, result in (("aligned", aligned), ("misaligned", misaligned)):
    summary = result.summary()
    print(
        f"{name:>10}: deepest wear at z = {summary['peak_wear_z_m'] * 1e3:+.1f} mm, "
        f"edge/mid {summary['edge_to_mid_wear_ratio']:.2f}, "
        f"40 um reached after {summary['life_revolutions']:.0f} revolutions"
    )

# the tilt moves the deepest wear into an end slice and shortens the life
half_length, slice_length = 0.5 * 0.02, 0.02 / 20
misaligned_summary, aligned_summary = misaligned.summary(), aligned.summary()
assert abs(misaligned_summary["peak_wear_z_m"]) > half_length - slice_length
assert misaligned_summary["life_revolutions"] < aligned_summary["life_revolutions"]

# %%
# The bore unrolled: angle across, axial position up. The tilt presses the end of the
# bushing it leans towards in the half of the cycle that loads it there.
unrolled = wear_map(misaligned.dataset, label="misaligned clevis pin")

# %%
# The worn profile at the mid-plane and in the two end slices.
profiles = edge_profiles(misaligned.dataset, label="misaligned clevis pin")

# %%
# The worn bore in 3-D, the radial wear exaggerated (the factor is in the title).
bore = worn_bore(misaligned.dataset, label="misaligned clevis pin")
