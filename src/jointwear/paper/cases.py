"""The paper's cases: its table rows (in SI) and the shipped config of every case.

The configs are package data (``jointwear/paper/configs/*.toml``; ``examples/paper``
in a source checkout links to them): one per row of Tables 3-5 and per figure case
(Figs. 13-15), carrying the values calibrated on one row
(:mod:`jointwear.paper.protocol`).
"""

from __future__ import annotations

from dataclasses import dataclass
from importlib.resources import files
from importlib.resources.abc import Traversable
from pathlib import Path
from typing import Any

from jointwear.config import Config, load_config
from jointwear.errors import ConfigError
from jointwear.registry import suggest

__all__ = [
    "DISPLAY_UNITS",
    "PAPER_ROWS",
    "PaperRow",
    "case_config",
    "case_names",
    "configs_folder",
    "deviation",
    "shown",
]


@dataclass(frozen=True)
class PaperRow:
    """One row of the paper's Tables 3-5, in SI.

    Parameters
    ----------
    table : str
        Table of the paper.
    peak : float
        Wear peak [m].
    width : float
        Wear width [deg].
    mass : float
        Wear mass [kg].
    time : float
        The paper's run time [s].
    """

    table: str
    peak: float
    width: float
    mass: float
    time: float

    @property
    def targets(self) -> dict[str, float]:
        """The row as ``jointwear run --json`` summary keys: peak [m], width [deg], mass [kg]."""
        return {
            "peak_wear_depth_m": self.peak,
            "wear_width_deg": self.width,
            "wear_mass_kg": self.mass,
        }


#: the paper prints mm and g; converted here (1e-5 mm = 1e-8 m, 1e-6 g = 1e-9 kg)
PAPER_ROWS: dict[str, PaperRow] = {
    "table3_nlcp_120rpm": PaperRow("Table 3", 1.003e-8, 130, 3.381e-9, 2.11),
    "table3_nlcp_240rpm": PaperRow("Table 3", 1.22e-8, 134, 4.357e-9, 1.81),
    "table3_winkler_120rpm": PaperRow("Table 3", 1.056e-8, 115, 3.355e-9, 2.12),
    "table3_winkler_240rpm": PaperRow("Table 3", 1.26e-8, 118, 4.326e-9, 1.61),
    "table4_nlcp_clearance_0.2mm": PaperRow("Table 4", 1.44e-8, 102, 4.23e-9, 1.68),
    "table4_winkler_clearance_0.2mm": PaperRow("Table 4", 1.46e-8, 90, 4.21e-9, 1.34),
    "table5_nlcp_10000r": PaperRow("Table 5", 0.062e-3, 169, 0.0354e-3, 19.81),
    "table5_nlcp_15000r": PaperRow("Table 5", 0.0875e-3, 178, 0.0539e-3, 29.03),
    "table5_winkler_10000r": PaperRow("Table 5", 0.061e-3, 165, 0.0353e-3, 14.12),
    "table5_winkler_15000r": PaperRow("Table 5", 0.0859e-3, 176, 0.0538e-3, 21.09),
}


#: the unit every table of the report shows a metric in: key -> (factor from SI, unit);
#: the paper prints its tables in mm and g (see :data:`PAPER_ROWS`)
DISPLAY_UNITS: dict[str, tuple[float, str]] = {
    "peak": (1e3, "mm"),
    "width": (1.0, "°"),
    "mass": (1e3, "g"),
}


def shown(key: str, value: float) -> str:
    """A metric as the report shows it, with its unit (``shown("peak", 1.1e-8)``: ``1.1e-05 mm``).

    Parameters
    ----------
    key : {"peak", "width", "mass"}
        The metric (:data:`DISPLAY_UNITS`).
    value : float
        Its value in SI: peak [m], width [deg], mass [kg].
    """
    scale, unit = DISPLAY_UNITS[key]
    return f"{value * scale:.4g}{'' if unit == '°' else ' '}{unit}"


def configs_folder() -> Traversable:
    """The folder of the shipped paper configs (package data ``jointwear/paper/configs``)."""
    return files("jointwear.paper") / "configs"


def case_names() -> list[str]:
    """Names of the paper cases shipped with the package (``examples/paper``)."""
    return sorted(
        p.name.removesuffix(".toml") for p in configs_folder().iterdir() if p.name.endswith(".toml")
    )


def case_config(name: str, overrides: dict[str, Any] | None = None) -> Config:
    """The config of a paper case, with optional dotted-key overrides.

    Parameters
    ----------
    name : str
        A name of :func:`case_names` (``table3_winkler_120rpm``).
    overrides : dict, optional
        Dotted config keys to values (SI numbers or strings with units).

    Raises
    ------
    ConfigError
        Unknown case (with a did-you-mean suggestion) or a bad override.
    """
    names = case_names()
    if name not in names:
        raise ConfigError(f"case: unknown paper case {name!r}{suggest(name, names)}")
    return load_config(Path(str(configs_folder() / f"{name}.toml")), overrides or {})


def deviation(ours: float, paper: float) -> float:
    """Relative deviation ``ours / paper - 1`` [-]."""
    return ours / paper - 1.0
