"""The scalar results of a run: the ``jointwear run --json`` object and ``summary.json``.

:func:`summarize` reads one joint's result (a Dataset or its plain arrays);
:func:`run_summary` makes the summary of a whole result, every joint's beside the most
worn one's, with the engineering checks if asked: the one object ``run --json`` prints
and ``summary.json`` holds.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from jointwear.record import WALL_CLOCK_KEYS
from jointwear.results.axial import axial_summary
from jointwear.state import revolution_number
from jointwear.tribology.metrics import PIN_METRICS, WEAR_METRICS, engineering_checks

if TYPE_CHECKING:
    import xarray as xr

    from jointwear.results.wear_result import WearResult

__all__ = ["WALL_CLOCK_KEYS", "film_summary", "run_summary", "summarize"]


def summarize(dataset: xr.Dataset) -> dict[str, Any]:
    """The scalar results of a single-joint result dataset (SI, units in the keys).

    The wear metrics (:data:`~jointwear.tribology.metrics.WEAR_METRICS`) at the end
    of the run, what ran, and the life: ``stopped_by`` (the ``[life]`` limit that
    ended the run, or ``None``), ``life_revolutions`` and ``life_hours`` (where it
    was reached, a fraction of a revolution included, or ``None``; then ``revolutions``
    is the same) and ``dynamics_updates`` (solves of the dynamics on the
    worn joint, the first on the unworn joint not counted).
    """
    out: dict[str, Any] = {
        m.key: float(dataset[m.name].values[-1]) * m.scale
        for m in (*WEAR_METRICS, *PIN_METRICS)
        if m.key is not None and m.name in dataset
    }
    revolutions = revolution_number(dataset["update_revolution"].values[-1])
    stopped_by = str(dataset.attrs.get("stopped_by", "")) or None
    period = float(
        dataset.attrs.get("mean_cycle_duration_s", dataset.attrs.get("period_s", math.nan))
    )
    updates = dataset.sizes.get("dynamics_update", 1)
    out.update(
        {
            "revolutions": revolutions,
            "contour_updates": int(dataset.sizes["update"]),
            "contact_model": dataset.attrs["contact_model"],
            # (a file written before the attributes were: named as nothing else is)
            "mechanism": str(dataset.attrs.get("mechanism", "unknown")),
            "joint": str(dataset.attrs.get("joint", "joint")),
            "stopped_by": stopped_by,
            "life_revolutions": revolutions if stopped_by else None,
            "life_hours": revolutions * period / 3600.0 if stopped_by else None,
            "dynamics_updates": max(int(updates) - 1, 0),
            # the contact-impact dynamics' integrator that ran (absent for other models)
            **(
                {"integrator": str(dataset.attrs["integrator"])}
                if "integrator" in dataset.attrs
                else {}
            ),
            "runtime_s": float(dataset.attrs.get("runtime_s", math.nan)),
            # (a file written before compile times were recorded has none)
            **{k: float(dataset.attrs[k]) for k in WALL_CLOCK_KEYS[1:] if k in dataset.attrs},
        }
    )
    if "z" in dataset["wear_depth"].dims:  # along the pin (a planar run has no z)
        out.update(axial_summary(dataset["wear_depth"].values[-1], dataset["z"].values))
    out.update(film_summary(dataset))
    return out


def film_summary(dataset: xr.Dataset) -> dict[str, Any]:
    """A lubricated run's film over the cycle; empty for a dry run (the keys are absent).

    Every lubricated run has ``film_model``, ``max_eccentricity_ratio`` (the largest
    ``|e| / c`` of the pin over the cycle), ``min_film_thickness_m`` (the least gap
    ``c (1 - max |e| / c)`` between the unworn surfaces; negative only where the solids
    overlapped, in the contact-impact dynamics) and ``peak_joint_force_n`` (the largest
    force between pin and bushing, film and solids together). Where the film shares the
    load cycle's load (``[lubrication]`` under the massless link) these are the orbit's
    and the cycle's largest load, and ``min_film_parameter`` (the least),
    ``asperity_load_fraction`` (the time-weighted mean over the cycle's steps) and
    ``lubrication_regime`` (that of the least film parameter: hydrodynamic above 3,
    mixed above 1, else boundary) follow. Where the film acts in the contact-impact
    dynamics they are the last solve's (``dynamics_*`` record; the integrated peak
    between the samples included).
    """
    model = dataset.attrs.get("film_model")
    if "film_parameter" in dataset:
        return {"film_model": model, **_orbit_summary(dataset)}
    if "dynamics_min_film_thickness" in dataset:
        return {
            "film_model": model,
            "max_eccentricity_ratio": float(dataset["dynamics_max_eccentricity_ratio"].values[-1]),
            "min_film_thickness_m": float(dataset["dynamics_min_film_thickness"].values[-1]),
            "peak_joint_force_n": float(dataset["dynamics_peak_joint_force"].values[-1]),
        }
    return {}


def _orbit_summary(dataset: xr.Dataset) -> dict[str, Any]:
    """The film keys of a load cycle shared along the pin's orbit."""
    # (only a lubricated run's summary loads the film's libraries: scipy's integrators)
    from jointwear.lubrication.asperity import lubrication_regime

    time = np.asarray(dataset["time"].values, float)
    period = float(dataset.attrs.get("period_s", math.nan))
    duration = np.diff(np.append(time, period))
    least = float(dataset["film_parameter"].values.min())
    fraction = np.asarray(dataset["asperity_load_fraction"].values, float)
    eccentricity = np.hypot(
        dataset["eccentricity_ratio_x"].values, dataset["eccentricity_ratio_y"].values
    )
    return {
        "max_eccentricity_ratio": float(eccentricity.max()),
        "min_film_thickness_m": float(dataset["min_film_thickness"].values.min()),
        "peak_joint_force_n": float(dataset["joint_load"].values.max()),
        "min_film_parameter": least,
        "asperity_load_fraction": float(np.sum(fraction * duration) / np.sum(duration)),
        "lubrication_regime": str(lubrication_regime(least)),
    }


def run_summary(result: WearResult, checks: bool = False) -> dict[str, Any]:
    """The summary of a result (SI units in the key names).

    With several clearance joints, the top-level values are those of the most worn
    joint (``joint``), and ``joints`` holds every joint's.

    Parameters
    ----------
    result : WearResult
        The result.
    checks : bool
        Add the engineering checks (PV, pressure, speed against the bushing's limits,
        :func:`jointwear.tribology.metrics.engineering_checks`) as ``checks``, the top
        level's and each joint's; each exceeded limit warns once.
    """
    several = len(result.joints) > 1
    out = summarize(result.joint_data())
    if several:
        out["joints"] = {j: summarize(result.joint_dataset(j)) for j in result.joints}
    out["runtime_s"] = result.runtime
    if checks:
        out["checks"] = engineering_checks(result.joint_data(), result.config)
        for joint, entry in out.get("joints", {}).items():
            entry["checks"] = engineering_checks(result.joint_data(joint), result.config)
    return out
