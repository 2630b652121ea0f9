"""Calibration: model parameters fitted to what was observed (``jointwear calibrate``).

Every fit is a least-squares fit of config parameters
(:mod:`jointwear.workflows.parameter_fit`, whose names this module also offers:
:class:`Parameter`, :func:`calibrate`, :func:`calibrate_metrics`); what differs is
what the model is fitted to:

* measured bushings -- their worn profiles
  (:func:`calibrate_to_measurements`, on
  :func:`jointwear.measurement.parameter_fit.calibrate_profiles`);
* an exact contact reference -- the contact laws' stiffness and exponent
  (:func:`calibrate_contact_laws`, on
  :func:`jointwear.references.spring_fit.calibrate_to_reference`);
* a row of the paper's tables -- its wear peak, width and mass
  (:func:`jointwear.paper.protocol.paper_row_calibration`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from jointwear.errors import ConfigError
from jointwear.workflows.parameter_fit import (
    CalibrationResult,
    Parameter,
    calibrate,
    calibrate_metrics,
    config_value,
)

__all__ = [
    "CalibrationResult",
    "ContactLawFits",
    "Parameter",
    "calibrate",
    "calibrate_contact_laws",
    "calibrate_metrics",
    "calibrate_to_measurements",
    "config_value",
]

#: the references the contact laws can be fitted to
REFERENCES = ("fem", "persson")


def calibrate_to_measurements(
    config: Path | None,
    measured: Sequence[Path],
    fit: Sequence[str],
    *,
    cases: Sequence[str] = (),
    overrides: Sequence[str] = (),
    units: str | None = None,
    circle_fit: str = "robust",
    noise: str | None = None,
    align: str = "best",
    profile: str = "auto",
    max_memory: str | None = None,
) -> Any:
    """Fit model parameters to measured wear profiles by least squares.

    Every measured file is simulated with ``config`` (plus its ``cases`` settings), and
    the simulated profiles minus the measured ones (each divided by its measured peak)
    are minimised over the ``fit`` parameters. Everything is checked before the first
    simulation.

    Parameters
    ----------
    config : Path
        The config file of the measured runs.
    measured : sequence of Path
        Measured inner-surface points, one file per bushing run with ``config`` as is.
    fit : sequence of str
        Parameters to fit: ``wear_coefficient``, ``axial_length``, ... or a dotted key;
        bounds as ``NAME=LOWER..UPPER`` (units allowed).
    cases : sequence of str
        Measured files with their own settings: ``FILE:KEY=VALUE[,KEY=VALUE...]``.
    overrides : sequence of str
        ``section.key=VALUE`` overrides of the config.
    units : str, optional
        Length unit of columns without one (default m).
    circle_fit : str
        Bushing centre of the measurements: ``robust`` or ``least-squares``.
    noise : str, optional
        Radial standard deviation of the points, e.g. ``"0.7 um"``; default estimated
        per file on the unworn arc.
    align : str
        ``"best"`` or the angle of the bushing's theta = 0 in the files' frame.
    profile : str
        Points to nodes: ``auto``, ``interpolate`` or ``bin``.
    max_memory : str, optional
        Refuse trials whose arrays would need more memory than this, e.g. ``"16 GiB"``.

    Returns
    -------
    ProfileCalibration
        The fit (:func:`~jointwear.measurement.parameter_fit.calibrate_profiles`); its
        ``summary()`` is the ``jointwear calibrate --json`` object.

    Raises
    ------
    ConfigError
        A missing config or file, an unknown parameter or option, a parameter named twice.
    """
    from jointwear.measurement.parameter_fit import calibrate_profiles, parse_fit
    from jointwear.resources import check_run
    from jointwear.workflows.inputs import load_config_file

    if config is None:
        raise ConfigError("CONFIG: missing; give the config of the measured runs (or --paper-row)")
    if config.suffix.lower() != ".toml" and config.suffix.lower() in {".csv", ".txt", ".dat"}:
        raise ConfigError(f"CONFIG: {config} looks like a measurement; give the config first")
    base = load_config_file(config, overrides)
    check_run(base, max_memory)  # every trial is a run of this size
    if not fit:
        raise ConfigError("--fit: name at least one parameter, e.g. --fit wear_coefficient")
    parameters = [parse_fit(text, base) for text in fit]
    keys = [p.key for p in parameters]
    if len(set(keys)) != len(keys):
        raise ConfigError("--fit: a parameter is named twice")
    fit_name, noise_m, alignment = _measurement_options(circle_fit, profile, align, noise, units)
    measured_cases = _measured_cases(measured, cases, units, alignment)
    return calibrate_profiles(
        base, measured_cases, parameters, fit=fit_name, profile=profile, noise=noise_m
    )


def _measurement_options(
    circle_fit: str, profile: str, align: str, noise: str | None, units: str | None
) -> tuple[str, float | None, str | float]:
    """The circle fit's name, the noise [m] (``None``: estimated) and the alignment."""
    from jointwear.measurement.compare import CIRCLE_FITS, PROFILE_CHOICES
    from jointwear.measurement.io import length_unit_factor
    from jointwear.registry import suggest
    from jointwear.units import to_si
    from jointwear.workflows.inputs import parse_align

    fit_name = circle_fit.replace("_", "-")
    if fit_name not in CIRCLE_FITS:
        raise ConfigError(
            f"--circle-fit: unknown circle fit {circle_fit!r}{suggest(fit_name, CIRCLE_FITS)}"
        )
    if profile not in PROFILE_CHOICES:
        raise ConfigError(
            f"--profile: unknown method {profile!r}{suggest(profile, PROFILE_CHOICES)}"
        )
    alignment = parse_align(align)
    noise_m = None
    if noise is not None:
        noise_m = to_si(noise, "length", "--noise")
        if not noise_m > 0:
            raise ConfigError(f"--noise: must be > 0, got {noise!r}")
    if units is not None:
        length_unit_factor(units, "--units")
    return fit_name, noise_m, alignment


def _measured_cases(
    measured: Sequence[Path], cases: Sequence[str], units: str | None, alignment: str | float
) -> list[Any]:
    """The measured files read, each with its settings; a file given twice is numbered."""
    from jointwear.measurement.parameter_fit import MeasuredCase, parse_case

    specs: list[tuple[Path, dict[str, Any]]] = [(path, {}) for path in measured]
    specs += [parse_case(text) for text in cases]
    if not specs:
        raise ConfigError("MEASURED: give at least one measured file (or --case FILE:...)")
    read = [MeasuredCase.from_file(path, overrides, units, alignment) for path, overrides in specs]
    seen: dict[str, int] = {}
    for i, item in enumerate(read):
        # the same file (name) twice, e.g. with other settings: number the repeats
        seen[item.name] = seen.get(item.name, 0) + 1
        if seen[item.name] > 1:
            read[i] = MeasuredCase(
                f"{item.name}#{seen[item.name]}", item.x, item.y, item.overrides, item.align
            )
    return read


@dataclass(frozen=True)
class ContactLawFits:
    """Outcome of :func:`calibrate_contact_laws`.

    Attributes
    ----------
    reference : str
        ``"fem"`` or ``"persson"``.
    loads_n : list of float
        The loads fitted over [N].
    fits : dict
        Per law (``winkler``, ``nlcp``), its fit
        (:class:`~jointwear.references.spring_fit.LawFit`).
    """

    reference: str
    loads_n: list[float]
    fits: dict[str, Any]

    def summary(self) -> dict[str, Any]:
        """The ``jointwear calibrate --reference ... --json`` object."""
        return {
            "reference": self.reference,
            "loads_n": self.loads_n,
            "fits": {name: fit.to_json() for name, fit in self.fits.items()},
        }


def calibrate_contact_laws(
    reference: str,
    loads: str,
    *,
    config: Path | None = None,
    overrides: Sequence[str] = (),
    measured: Sequence[Path] = (),
) -> ContactLawFits:
    """Fit Winkler's stiffness and NLCP's ``K``, ``n`` to an exact reference over loads.

    Parameters
    ----------
    reference : str
        ``"fem"`` or ``"persson"``.
    loads : str
        Comma-separated loads with units, e.g. ``"50 N,100 N,200 N"``.
    config : Path, optional
        The joint's config file; default the parameter set's defaults.
    overrides : sequence of str
        ``section.key=VALUE`` overrides of the config.
    measured : sequence of Path
        Must be empty: the laws are fitted to a reference, not to measurements.

    Returns
    -------
    ContactLawFits
        The fitted laws.

    Raises
    ------
    ConfigError
        An unknown reference, measured files given, a bad load or config.
    """
    from jointwear.config import load_config
    from jointwear.contact import ContactParameters
    from jointwear.references.spring_fit import calibrate_to_reference
    from jointwear.workflows.inputs import load_config_file, parse_loads

    if reference not in REFERENCES:
        from jointwear.registry import suggest

        raise ConfigError(
            f"--reference: unknown reference {reference!r}{suggest(reference, REFERENCES)}"
        )
    if measured:
        raise ConfigError("--reference: fits the contact laws to a reference, not measured files")
    if config is not None:
        cfg = load_config_file(config, overrides)
    else:
        cfg = load_config(overrides=list(overrides))
    force = parse_loads(loads)
    fits = calibrate_to_reference(
        ContactParameters.from_config(cfg), force, reference=reference, nodes=cfg.contact.nodes
    )
    return ContactLawFits(reference, force, fits)
