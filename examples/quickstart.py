"""Quick start: wear of the paper's joint with NLCP, one revolution and 2000 revolutions.

Run: python examples/quickstart.py
"""

from __future__ import annotations

from pathlib import Path

import jointwear as jw

HERE = Path(__file__).parent
config = jw.load_config(HERE / "paper" / "table3_nlcp_120rpm.toml")

one = jw.Simulation(config).run().summary()
print(
    f"one revolution: peak {one['peak_wear_depth_m'] * 1e9:.2f} nm, "
    f"width {one['wear_width_deg']:.1f} deg, mass {one['wear_mass_kg'] * 1e9:.3f} ug"
)

long_run = config.replace(
    {
        "simulation.revolutions": 2000,
        "simulation.update_contour": True,
        "simulation.update_every": 50,
    }
)
result = jw.Simulation(long_run).run()
many = result.summary()
print(
    f"2000 revolutions, contour updated every 50: peak {many['peak_wear_depth_m'] * 1e6:.2f} um, "
    f"width {many['wear_width_deg']:.1f} deg, mass {many['wear_mass_kg'] * 1e6:.2f} mg "
    f"({many['contour_updates']} updates, {many['runtime_s']:.2f} s)"
)

# the result is an xarray Dataset with units on every variable
depth = result.dataset["wear_depth"]
print(depth.attrs["long_name"], "[" + depth.attrs["units"] + "]", depth.dims, depth.shape)
