"""Every contact model against the references, over a load range.

For each load (pin pressing at azimuth 0 on the unworn bushing) every model
gives its contact half-angle, peak pressure and *approach*: the spring models'
penetration of the compression centre, and for the references the comparable
quantity, the pin displacement along the load minus the clearance.
:func:`pressure_figure` draws ``p(theta)`` of all models side by side, one panel
per load, and :func:`plot_pressure` writes it.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.contact import ContactParameters, ContactSolution, solve
from jointwear.errors import ConfigError, JointwearError
from jointwear.geometry.angles import wrap_angle
from jointwear.geometry.contour import BushingContour, Pin

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = [
    "DEFAULT_MODELS",
    "METRICS",
    "ModelComparison",
    "compare_models",
    "plot_pressure",
    "pressure_figure",
]

FloatArray = NDArray[np.float64]

#: models compared by default, references last
DEFAULT_MODELS = ("hertz", "winkler", "asymmetric-winkler", "nlcp", "persson", "fem")
#: tabulated quantities (JSON keys) and how they are printed: (label, unit, scale)
METRICS = {
    "half_angle_deg": ("contact half-angle", "deg", 1.0),
    "peak_pressure_pa": ("peak pressure", "MPa", 1e-6),
    "approach_m": ("approach", "um", 1e6),
}


@dataclass
class ModelComparison:
    """Results of :func:`compare_models`.

    Attributes
    ----------
    loads_n : ndarray
        Loads [N].
    models : dict
        ``{model: {"half_angle_deg": [...], "peak_pressure_pa": [...], "approach_m": [...]}}``
        in degrees, Pa and m (NaN where a model has no solution).
    solutions : dict
        ``{model: ContactSolution}`` (models that solved every load).
    contour : BushingContour
        The unworn contour the pressures live on.
    errors : dict
        ``{model: message}`` for models that failed at some load.
    """

    loads_n: FloatArray
    models: dict[str, dict[str, FloatArray]]
    solutions: dict[str, ContactSolution]
    contour: BushingContour
    errors: dict[str, str] = field(default_factory=dict)

    def to_json(self) -> dict[str, Any]:
        """Plain data, ``{"loads_n": [...], "models": {name: {metric: [...]}}}``."""
        return {
            "loads_n": [float(x) for x in self.loads_n],
            "models": {
                name: {key: [float(v) for v in values] for key, values in metrics.items()}
                for name, metrics in self.models.items()
            },
        }

    def deviation(self, reference: str) -> dict[str, dict[str, FloatArray]]:
        """Relative deviation of every model from ``reference`` per metric [-].

        Parameters
        ----------
        reference : str
            A compared model, e.g. ``"fem"``.
        """
        if reference not in self.models:
            raise ConfigError(f"--reference: {reference!r} is not among the compared models")
        ref = self.models[reference]
        with np.errstate(divide="ignore", invalid="ignore"):
            return {
                name: {k: np.asarray(v) / np.asarray(ref[k]) - 1.0 for k, v in metrics.items()}
                for name, metrics in self.models.items()
            }


def _metrics(solution: ContactSolution) -> dict[str, FloatArray]:
    half = 0.5 * (solution.half_angle_left + solution.half_angle_right)
    return {
        "half_angle_deg": np.degrees(half),
        "peak_pressure_pa": solution.pressure.max(axis=1),
        "approach_m": np.asarray(solution.penetration, dtype=float),
    }


def compare_models(
    parameters: ContactParameters,
    loads: ArrayLike,
    models: Sequence[str] = DEFAULT_MODELS,
    nodes: int = 360,
    options: Mapping[str, Any] | None = None,
) -> ModelComparison:
    """Solve every model for every load on the unworn bushing (load at azimuth 0).

    Parameters
    ----------
    parameters : ContactParameters
        Geometry and materials of the joint.
    loads : array_like
        Loads [N], > 0.
    models : sequence of str
        Registered contact model names.
    nodes : int
        Contour nodes [-].
    options : mapping, optional
        Options of the spring models' balance (``balance``, ``tolerance``, ...);
        the references ignore those they do not know.
    """
    loads = np.asarray(loads, dtype=float).ravel()
    if loads.size == 0 or np.any(~np.isfinite(loads)) or np.any(loads <= 0):
        raise ConfigError("--loads: need one or more finite loads > 0")
    contour = BushingContour.circle(parameters.bushing_radius, nodes, parameters.axial_length)
    pin = Pin(parameters.pin_radius)
    azimuth = np.zeros_like(loads)
    opts = dict(options or {})
    results: dict[str, dict[str, FloatArray]] = {}
    solutions: dict[str, ContactSolution] = {}
    errors: dict[str, str] = {}
    for name in models:
        try:
            solution = solve(contour, pin, loads, azimuth, name, parameters, **opts)
        except JointwearError as exc:
            if isinstance(exc, ConfigError):
                raise
            errors[name] = str(exc)
            rows = {k: np.full(loads.size, np.nan) for k in METRICS}
            for i, load in enumerate(loads):
                try:
                    one = solve(contour, pin, [load], [0.0], name, parameters, **opts)
                except JointwearError:
                    continue
                for k, v in _metrics(one).items():
                    rows[k][i] = v[0]
            results[name] = rows
            continue
        solutions[name] = solution
        results[name] = _metrics(solution)
    return ModelComparison(loads, results, solutions, contour, errors)


_STYLES = {
    "hertz": {"color": "tab:purple", "linestyle": ":"},
    "winkler": {"color": "tab:blue", "linestyle": "--"},
    "asymmetric-winkler": {"color": "tab:cyan", "linestyle": "-."},
    "nlcp": {"color": "tab:orange", "linestyle": "-"},
    "persson": {"color": "0.45", "linestyle": "-", "linewidth": 2.4},
    "fem": {"color": "black", "linestyle": "-", "linewidth": 1.6},
}


def plot_pressure(
    comparison: ModelComparison, directory: str | Path, name: str = "compare_models_pressure"
) -> list[Path]:
    """Plot ``p(theta)`` of every model side by side, one panel per load (PNG + SVG).

    Files are written atomically.

    Parameters
    ----------
    comparison : ModelComparison
        Result of :func:`compare_models`.
    directory : str or Path
        Output folder (created if missing).
    name : str
        File stem.

    Returns
    -------
    list of Path
        The written files.
    """
    from jointwear.plots import save_figure

    fig = pressure_figure(comparison)
    return save_figure(fig, directory, name)


def pressure_figure(comparison: ModelComparison) -> Figure:
    """``p(theta)`` of every model side by side, one panel per load.

    Parameters
    ----------
    comparison : ModelComparison
        Result of :func:`compare_models`.

    Returns
    -------
    matplotlib.figure.Figure
        The figure (built without pyplot; nothing is written).
    """
    from jointwear.plots import new_figure

    loads = comparison.loads_n
    count = loads.size
    columns = min(count, 4)
    rows = math.ceil(count / columns)
    fig = new_figure((3.6 * columns, 3.0 * rows))
    axes = fig.subplots(rows, columns, squeeze=False, sharey=False)
    theta = comparison.contour.theta
    phi = np.degrees(wrap_angle(theta))
    order = np.argsort(phi)
    for i, load in enumerate(loads):
        ax = axes[i // columns][i % columns]
        widest = 0.0
        for model, solution in comparison.solutions.items():
            p = solution.pressure[i]
            style = dict(_STYLES.get(model, {}))
            style.setdefault("linewidth", 1.3)
            ax.plot(phi[order], p[order] / 1e6, label=model, **style)
            loaded = phi[p > 0]
            if loaded.size:
                widest = max(widest, float(np.abs(loaded).max()))
        span = min(180.0, max(20.0, 1.15 * widest + 5.0))
        ax.set_xlim(-span, span)
        ax.set_ylim(bottom=0.0)
        ax.set_title(f"{load:g} N")
        ax.set_xlabel("angle from load line [deg]")
        if i % columns == 0:
            ax.set_ylabel("contact pressure [MPa]")
        ax.grid(alpha=0.3)
    for j in range(count, rows * columns):
        axes[j // columns][j % columns].set_visible(False)
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=min(len(labels), 6), frameon=False)
    fig.tight_layout(rect=(0, 0.08 if rows == 1 else 0.05, 1, 1))
    return fig
