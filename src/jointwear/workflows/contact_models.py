"""Contact models: one load on the unworn bushing (``jointwear contact``), and every model
against the references over a load range (``jointwear compare-models``).

:func:`contact_on_unworn_bushing` solves one load with the config's contact model.
:func:`compare_contact_models` solves one load at a time on the unworn bushing with
each model (:func:`~jointwear.references.compare.compare_models`), measures each
model's contact half-angle, peak pressure and approach from a reference (the finite
elements by default), and can fit Winkler's stiffness and NLCP's ``K``, ``n`` to that
reference (:func:`~jointwear.references.spring_fit.calibrate_to_reference`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from jointwear.errors import ConfigError

__all__ = [
    "PLOT_FILES",
    "ComparedModels",
    "OneLoad",
    "compare_contact_models",
    "contact_on_unworn_bushing",
]

#: the p(theta) plot ``compare-models --out`` writes
PLOT_FILES = ("compare_models_pressure.png", "compare_models_pressure.svg")


@dataclass(frozen=True)
class ComparedModels:
    """Outcome of :func:`compare_contact_models`.

    Attributes
    ----------
    summary : dict
        The ``jointwear compare-models --json`` object.
    comparison : ModelComparison
        Per model and load: half-angle, peak pressure, approach
        (:func:`~jointwear.references.compare.compare_models`).
    reference : str
        The model the deviations are measured from.
    fits : dict
        The contact laws fitted to the reference (``calibrate``), by law.
    plots : list of Path
        The plot files written.
    """

    summary: dict[str, Any]
    comparison: Any
    reference: str
    fits: dict[str, Any] = field(default_factory=dict)
    plots: list[Path] = field(default_factory=list)


def compare_contact_models(
    config: Path,
    loads: str,
    *,
    models: Sequence[str] | None = None,
    reference: str = "fem",
    out: Path | None = None,
    calibrate: bool = False,
    target: str = "pressure",
    overrides: Sequence[str] = (),
) -> ComparedModels:
    """Contact half-angle, peak pressure and approach of every model over a load range.

    Parameters
    ----------
    config : Path
        The joint's config file (geometry, materials, contact settings).
    loads : str
        Comma-separated loads with units, e.g. ``"50 N,100 N,200 N"``.
    models : sequence of str, optional
        Models to compare (repeated or comma-separated); default all, references
        included.
    reference : str
        The model the deviations are measured from.
    out : Path, optional
        Folder for the p(theta) plot (PNG + SVG).
    calibrate : bool
        Also fit Winkler's stiffness and NLCP's ``K``, ``n`` to the reference
        (``fem`` or ``persson``).
    target : str
        What the fit matches: ``"pressure"`` or ``"metrics"``.
    overrides : sequence of str
        ``section.key=VALUE`` overrides of the config.

    Returns
    -------
    ComparedModels
        The summary, the comparison, the fits and the plots.

    Raises
    ------
    ConfigError
        An unknown model, reference or target, a bad load or config.
    """
    from jointwear.contact import CONTACT_MODELS, ContactParameters
    from jointwear.io import check_out, staged_output
    from jointwear.references.compare import DEFAULT_MODELS, compare_models, plot_pressure
    from jointwear.registry import suggest
    from jointwear.workflows.inputs import load_config_file, parse_loads, split_list

    if out is not None:
        out = check_out(out, files=PLOT_FILES)
    cfg = load_config_file(config, overrides)
    force = parse_loads(loads)
    names = split_list(models) or list(DEFAULT_MODELS)
    for name in names:
        if name not in CONTACT_MODELS:
            raise ConfigError(
                f"--models: unknown contact model {name!r}{suggest(name, CONTACT_MODELS)}"
            )
    if reference not in CONTACT_MODELS:
        raise ConfigError(
            f"--reference: unknown contact model {reference!r}{suggest(reference, CONTACT_MODELS)}"
        )
    if reference not in names:
        names.append(reference)
    if target not in ("pressure", "metrics"):
        raise ConfigError(f"--target: unknown {target!r}; choose 'pressure' or 'metrics'")
    if calibrate and reference not in ("fem", "persson"):
        raise ConfigError("--calibrate: the reference must be 'fem' or 'persson'")
    params = ContactParameters.from_config(cfg)
    options = {
        "balance": cfg.contact.balance,
        "tolerance": cfg.contact.tolerance,
        "max_iterations": cfg.contact.max_iterations,
    }
    comparison = compare_models(params, force, names, cfg.contact.nodes, options)
    summary = comparison.to_json()
    summary["reference"] = reference
    if comparison.errors:
        summary["errors"] = dict(comparison.errors)
    plots: list[Path] = []
    if out is not None:
        with staged_output(out, files=PLOT_FILES) as staging:
            staged = plot_pressure(comparison, staging)
        plots = [out / path.name for path in staged]
        summary["plots"] = [str(p) for p in plots]
    fits = {}
    if calibrate:
        from jointwear.references.spring_fit import calibrate_to_reference

        fits = calibrate_to_reference(
            params, force, reference=reference, target=target, nodes=cfg.contact.nodes
        )
        summary["calibration"] = {name: fit.to_json() for name, fit in fits.items()}
    return ComparedModels(summary, comparison, reference, fits, plots)


@dataclass(frozen=True)
class OneLoad:
    """Outcome of :func:`contact_on_unworn_bushing`.

    Attributes
    ----------
    summary : dict
        The ``jointwear contact --json`` object.
    load : float
        The load [N].
    """

    summary: dict[str, Any]
    load: float


def contact_on_unworn_bushing(
    config: Path,
    load: str = "200 N",
    azimuth: str = "0 deg",
    *,
    model: str | None = None,
    overrides: Sequence[str] = (),
) -> OneLoad:
    """The pressure distribution of one load on the unworn bushing.

    There is no contour to update, so a model that solves circles is as good as any
    here (a run with contour update refuses it).

    Parameters
    ----------
    config : Path
        The joint's config file.
    load : str
        The joint load with its unit, e.g. ``"200 N"``.
    azimuth : str
        The load's direction in the bushing frame, e.g. ``"0 deg"``.
    model : str, optional
        Contact model (instead of the config's ``contact.model``).
    overrides : sequence of str
        ``section.key=VALUE`` overrides of the config.

    Returns
    -------
    OneLoad
        The contact's summary (penetration, contact angles, peak pressure, resultants)
        and the load [N].

    Raises
    ------
    ConfigError
        A bad config, unit or model, or a negative load.
    """
    from jointwear.contact import ContactParameters, solve
    from jointwear.geometry import BushingContour, Pin
    from jointwear.units import to_angle, to_si
    from jointwear.workflows.inputs import load_config_file

    changes = [*overrides, "simulation.update_contour=false"]
    if model is not None:
        changes.append(f"contact.model={model}")
    cfg = load_config_file(config, changes)
    force = to_si(load, "force", "--load")
    angle = to_angle(azimuth, "--azimuth")
    if force < 0:
        raise ConfigError("--load: must be >= 0 (use --azimuth for the direction)")
    params = ContactParameters.from_config(cfg)
    contour = BushingContour.circle(
        cfg.joint.bushing_radius, cfg.contact.nodes, cfg.joint.axial_length
    )
    result = solve(
        contour,
        Pin(cfg.joint.pin_radius),
        [force],
        [angle],
        cfg.contact.model,
        params,
        balance=cfg.contact.balance,
        tolerance=cfg.contact.tolerance,
        max_iterations=cfg.contact.max_iterations,
    )
    return OneLoad(result.summary(0), force)
