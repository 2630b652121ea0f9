"""
Quick start
===========

Wear of the paper's joint with the NLCP contact model: one revolution, then
2000 revolutions with the worn contour fed back every 50.

Run: ``python examples/quickstart.py`` (prints the metrics; the figures show in
a notebook or in the documentation's gallery).
"""

from __future__ import annotations

import jointwear as jw
from jointwear.paper import case_config
from jointwear.plots import plot_wear_result

# The paper's cases ship with the package (the TOML files in examples/paper/);
# jw.load_config("examples/paper/table3_nlcp_120rpm.toml") reads the same file.
config = case_config("table3_nlcp_120rpm")

one = jw.Simulation(config).run().summary()
print(
    f"one revolution: peak {one['peak_wear_depth_m'] * 1e9:.2f} nm, "
    f"width {one['wear_width_deg']:.1f} deg, mass {one['wear_mass_kg'] * 1e9:.3f} ug"
)

# %%
# A config is immutable; :meth:`~jointwear.Config.replace` returns a changed,
# validated copy. Keys are dotted (``section.key``), values SI numbers or strings
# with units.
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

# %%
# The result is an xarray Dataset with units on every variable.
depth = result.dataset["wear_depth"]
print(depth.attrs["long_name"], "[" + depth.attrs["units"] + "]", depth.dims, depth.shape)

# %%
# Figures are :class:`matplotlib.figure.Figure` objects; nothing is written
# until you call ``fig.savefig`` (or :func:`jointwear.plots.save_figure`).
contour = plot_wear_result(result, "wear_polar")

# %%
history = plot_wear_result(result, "wear_history")
