"""Whether a run stayed inside the range where its contact model holds.

:func:`model_validity` looks at what a run produced -- the final wear profile and the
contact solutions of the unworn and the final contour -- and says, one line each,
where the contact model was used outside its assumptions; :func:`warn_model_validity`
gives those lines as :class:`~jointwear.errors.ContactModelWarning` and compares the
peak pressure with the bushing material's limit through the engineering checks
(:func:`~jointwear.tribology.metrics.compare_with_limits`,
:class:`~jointwear.errors.MaterialLimitWarning`). The simulation calls it once, at the
end of a run (never inside the loop over revolutions).

The thresholds, and why:

* :data:`SYMMETRIC_WEAR_FRACTION` (0.1): a model that solves circles (``winkler``,
  ``hertz``, ``persson``; refused with contour update) keeps wearing the unworn
  bushing's pressure. A groove of depth ``h`` in a bore of clearance ``c`` is already
  conformal over ``cos(alpha) = c / (c + h)``: 24.6 degrees either side at
  ``h = 0.1 c``, as wide as the elastic contact arcs of small joints (the paper's
  joint: 24-45 degrees at 50-400 N, docs/references.md), so from there on the worn
  contour, not the circle, sets the pressure (a load fixed in the bushing then wears
  a groove 4x too deep within 50 revolutions).
* :data:`DEEP_WEAR_FRACTION` (0.1): the contour models push and wear along the
  bushing's rays, while the worn bore's normal is the pin's. Against the exact
  rigid-conformal worn bore (:mod:`jointwear.references.conformal`) this costs about
  ``0.2 h / R_b`` in peak depth and worn volume: 1 % on a 40 mm bronze joint after 20
  clearances (``h / R = 0.05``), 2.8 % on the paper's joint (``h / R = 0.13``), so
  past ``h = 0.1 R_b`` the deviation is beyond 2 % and growing.
* :data:`HERTZ_HALF_ANGLE` (0.5 rad, 29 degrees): Hertz's half-space solution needs
  a contact small against the radii. Against Persson's exact solution of the pin in
  a hole (paper materials) its peak pressure is 1 % low at ``a / R_b = 0.33``,
  3.5 % at 0.47 and 8 % at 0.66, and its arc 4 %, 10 % too wide
  (``jointwear.references.persson``).
* :data:`ARC_LIMIT` (90 degrees, less one node spacing): a pin smaller than the bore
  touches no farther than a quarter circle from the load line; a contact that gets
  there was cut (Hertz's ellipse is, spring windows end there), so the model no
  longer describes it.
* :data:`STRAIN_LIMIT` (0.1): the contact models are linear-elastic, small-strain.
  The approach over the wall thickness is the mean compressive strain under the
  compression centre; at 0.1 the Green strain differs from the linear one by 5 %,
  and polymer liners have left their linear range well before (their yield strains
  are a few per cent; :data:`~jointwear.tribology.metrics.CHECKS` compares the
  pressures with the datasheet limits).
* :data:`INCOMPRESSIBLE_POISSON` (0.4) with :data:`THIN_WALL_RATIO` (10): the
  constrained modulus ``E (1 - nu) / ((1 + nu)(1 - 2 nu))`` is the thin-layer limit
  of a wall bonded in its housing. It holds for the paper's PTFE (nu = 0.38: peak
  pressure and approach within 2.5 % of the FE model of the wall). For a nearly
  incompressible wall that is not thin against its contact the wall flows sideways
  and is softer: FE of the paper's bushing (wall 3.65 mm, contact half-width about
  one wall) gives a peak pressure 8 % below constrained Winkler at nu = 0.42 and
  25 % below at nu = 0.46; a 1 mm wall at nu = 0.46, 19 % (half-width 2.9 walls) and
  8 % (5.7 walls); a 0.1 mm wall at nu = 0.46 (42 walls) 0.3 %. Warned where
  ``nu > 0.4`` and the contact half-width ``R_b alpha`` is below 10 walls.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Iterable
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from jointwear.contact import CIRCULAR_ONLY, ContactSolution
from jointwear.errors import ContactModelWarning
from jointwear.tribology.metrics import CHECKS, compare_with_limits

__all__ = [
    "ARC_LIMIT",
    "DEEP_WEAR_FRACTION",
    "HERTZ_HALF_ANGLE",
    "INCOMPRESSIBLE_POISSON",
    "STRAIN_LIMIT",
    "SYMMETRIC_WEAR_FRACTION",
    "THIN_WALL_RATIO",
    "model_validity",
    "warn_model_validity",
]

#: peak wear over the clearance beyond which a circular-bushing model is in doubt [-]
SYMMETRIC_WEAR_FRACTION = 0.1
#: peak wear over the bushing radius beyond which wear along rays is in doubt [-]
DEEP_WEAR_FRACTION = 0.1
#: Hertz's half-width over the bushing radius beyond which the contact is not small [-]
HERTZ_HALF_ANGLE = 0.5
#: contact half-angle a pin smaller than the bore cannot pass [rad]
ARC_LIMIT = 0.5 * math.pi
#: approach over the wall thickness beyond which strains are not small [-]
STRAIN_LIMIT = 0.1
#: Poisson ratio above which the constrained modulus needs a thin wall [-]
INCOMPRESSIBLE_POISSON = 0.4
#: contact half-width, in wall thicknesses, below which such a wall is not thin [-]
THIN_WALL_RATIO = 10.0
#: Poisson ratio above which a liner's free ends are markedly softer than the confined
#: sections the slices along the pin are (finite elements: 0.3 % error at 0, 50 % at 0.38) [-]
FREE_END_POISSON = 0.25


def _widest(solutions: list[ContactSolution]) -> float:
    """The widest contact half-angle of ``solutions`` [rad] (0 without any)."""
    return max(
        (
            float(max(s.half_angle_left.max(initial=0.0), s.half_angle_right.max(initial=0.0)))
            for s in solutions
        ),
        default=0.0,
    )


def _free_liner_ends(config: Any) -> str | None:
    """The message for slices along the pin on a liner whose free ends bulge, else ``None``."""
    joint, bushing = config.joint, config.materials.bushing
    if getattr(joint, "axial_slices", 1) == 1 or bushing.poisson_ratio <= FREE_END_POISSON:
        return None
    return (
        f"joint.axial_slices: each slice is a confined section, but a liner with Poisson's "
        f"ratio {bushing.poisson_ratio:g} is softer within about a wall thickness "
        f"({joint.bushing_thickness * 1e3:.3g} mm) of its free ends, so the end slices' load "
        f"and wear are overstated (finite elements of a PTFE liner under a tilted pin: "
        f"edge-to-mid line load 1.15 against the slices' 1.74); read the edge wear as an "
        f"upper bound"
    )


def model_validity(
    config: Any,
    model: Any,
    wear_depth: ArrayLike,
    solutions: Iterable[ContactSolution] = (),
) -> dict[str, str]:
    """Where a run used its contact model outside the model's assumptions.

    Parameters
    ----------
    config : jointwear.config.Config
        The run's configuration (joint, bushing material, contact settings).
    model : str or law
        The contact model: a registered name or the resolved law (its ``name``, and
        ``symmetric`` for a spring law).
    wear_depth : array_like, shape (N,)
        The final wear profile of the bushing [m].
    solutions : iterable of ContactSolution
        Contact solutions of the run (the unworn and the final contour); without
        any, only the wear is checked.

    Returns
    -------
    dict
        Check name (``"circular_wear"``, ``"deep_wear"``, ``"hertz_half_width"``, ``"arc"``,
        ``"strain"``, ``"constrained_modulus"``, ``"free_liner_ends"``) -> one-line message
        naming the setting to change; empty where the model holds.
    """
    solutions = list(solutions)
    name = model if isinstance(model, str) else str(getattr(model, "name", "custom"))
    symmetric = bool(getattr(model, "symmetric", False))
    joint, contact = config.joint, config.contact
    out: dict[str, str] = {}

    peak = float(np.max(wear_depth, initial=0.0))
    if (name in CIRCULAR_ONLY or symmetric) and peak > SYMMETRIC_WEAR_FRACTION * joint.clearance:
        out["circular_wear"] = (
            f"contact.model: {name!r} assumes a circular bushing, but the wear "
            f"({peak * 1e3:.3g} mm) exceeds {SYMMETRIC_WEAR_FRACTION:g} of the clearance "
            f"({joint.clearance * 1e3:.3g} mm), where the worn contour sets the pressure; "
            f"set simulation.update_contour = true with contact.model = 'asymmetric-winkler'"
        )
    if peak > DEEP_WEAR_FRACTION * joint.bushing_radius:
        out["deep_wear"] = (
            f"life.peak_wear_depth: the wear ({peak * 1e3:.3g} mm) exceeds "
            f"{DEEP_WEAR_FRACTION:g} of the bushing radius ({joint.bushing_radius * 1e3:.3g} mm), "
            f"where wear and pressure along the bushing's rays depart from the worn bore's "
            f"normal (peak depth and volume about {0.2 * peak / joint.bushing_radius:.1%} low "
            f"against the exact conformal wear); stop the run earlier with life.peak_wear_depth"
        )
    if liner_ends := _free_liner_ends(config):
        out["free_liner_ends"] = liner_ends
    if not solutions:
        return out

    widest = _widest(solutions)
    radius = joint.bushing_radius
    if name == "hertz" and widest > HERTZ_HALF_ANGLE:
        out["hertz_half_width"] = (
            f"contact.model: 'hertz' assumes a contact small against the bushing, but its "
            f"half-width reaches {math.degrees(widest):.3g} deg (a/R_b = {widest:.3g} > "
            f"{HERTZ_HALF_ANGLE:g}: its peak pressure is then several per cent below the "
            f"exact solution's); use contact.model = 'asymmetric-winkler'"
        )
    if widest >= ARC_LIMIT - 2.0 * math.pi / contact.nodes:
        out["arc"] = (
            f"contact.model: {name!r} spreads the contact {math.degrees(widest):.3g} deg "
            f"either side of the load, to the quarter circle beyond which a pin smaller than "
            f"the bore cannot touch, so the contact was cut there; "
            + (
                "use contact.model = 'asymmetric-winkler'"
                if name == "hertz"
                else "the wall is too soft for the load: check joint.bushing_thickness and "
                "materials.bushing.youngs_modulus"
            )
        )
    approach = max((float(np.max(s.penetration, initial=0.0)) for s in solutions), default=0.0)
    strain = approach / joint.bushing_thickness
    if strain > STRAIN_LIMIT:
        out["strain"] = (
            f"joint.bushing_thickness: the elastic approach ({approach * 1e6:.3g} um) is "
            f"{strain:.3g} of the wall ({joint.bushing_thickness * 1e3:.3g} mm), beyond the "
            f"small strains (< {STRAIN_LIMIT:g}) of the linear-elastic contact models; the "
            f"wall is too soft for the load (check materials.bushing.youngs_modulus)"
        )
    nu = config.materials.bushing.poisson_ratio
    half_width = radius * widest
    if (
        name in ("winkler", "asymmetric-winkler")
        and contact.foundation_modulus == "constrained"
        and nu > INCOMPRESSIBLE_POISSON
        and half_width < THIN_WALL_RATIO * joint.bushing_thickness
    ):
        out["constrained_modulus"] = (
            f"contact.foundation_modulus: the constrained modulus overstates the stiffness "
            f"of a nearly incompressible wall (materials.bushing.poisson_ratio = {nu:g}) that "
            f"is not thin against its contact (half-width {half_width * 1e3:.3g} mm, "
            f"{half_width / joint.bushing_thickness:.2g} walls): the peak pressure may be "
            f"10-25 % high; fit the foundation to the FE wall with `jointwear compare-models "
            f"CONFIG --calibrate` and set joint.bushing_thickness as it says"
        )
    return out


def warn_model_validity(
    config: Any,
    model: Any,
    wear_depth: ArrayLike,
    solutions: Iterable[ContactSolution | None] = (),
    where: str = "",
) -> dict[str, str]:
    """Warn once for each way a run left its contact model's range (:func:`model_validity`).

    Each message is a :class:`~jointwear.errors.ContactModelWarning`; the peak
    pressure of ``solutions`` is compared with ``materials.bushing.max_static_pressure``
    by the engineering checks (:func:`~jointwear.tribology.metrics.compare_with_limits`,
    a :class:`~jointwear.errors.MaterialLimitWarning` above it).

    Parameters
    ----------
    config : jointwear.config.Config
        The run's configuration.
    model : str or law
        The contact model (see :func:`model_validity`).
    wear_depth : array_like, shape (N,)
        The final wear profile [m].
    solutions : iterable of ContactSolution or None
        Contact solutions of the run; ``None`` entries are skipped.
    where : str
        Names the joint in messages (e.g. ``"joint 'rod-slider': "``).

    Returns
    -------
    dict
        :func:`model_validity`'s messages (without ``where``).
    """
    solved = [s for s in solutions if s is not None]
    found = model_validity(config, model, wear_depth, solved)
    for message in found.values():
        key, _, reason = message.partition(": ")
        warnings.warn(f"{key}: {where}{reason}", ContactModelWarning, stacklevel=3)
    if solved:
        values = dict.fromkeys(CHECKS, math.nan)
        values["peak_pressure"] = max(float(np.max(s.pressure, initial=0.0)) for s in solved)
        bushing = config.materials.bushing
        compare_with_limits(values, bushing, bushing.name, where)
    return found
