"""Contact pressure models (stage 2 of the pipeline: joint load -> bushing pressure).

Every model is selected by name (``CONTACT_MODELS``) or passed as a callable
``pressure(penetration)`` (pvlib's pattern), and solved by :func:`solve`:

======================  =====================================================
``hertz``               Hertz force law + line-contact profile (eqs. 1-3)
``winkler``             linear springs, symmetric about the load (eqs. 4-5)
``asymmetric-winkler``  linear springs on the real contour (eq. 6)
``nlcp``                power-law springs, cylinder on plane (eq. 7)
``persson``             reference: exact elastic pin in a hole (circular bushings)
``fem``                 reference: finite elements of the wall in a rigid housing
======================  =====================================================
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from numpy.typing import ArrayLike

from jointwear.contact import asymmetric_winkler, hertz, nlcp, winkler
from jointwear.contact.balance import solve_contact
from jointwear.contact.kernel import RevolutionWear, revolution_wear
from jointwear.contact.laws import (
    CallableSpringLaw,
    ContactParameters,
    PowerLaw,
    SpringLaw,
    effective_modulus,
)
from jointwear.contact.solution import ContactSolution
from jointwear.geometry.contour import BushingContour, Pin
from jointwear.references import fem_model, persson_model
from jointwear.registry import Registry

__all__ = [
    "CONTACT_MODELS",
    "CallableSpringLaw",
    "ContactParameters",
    "ContactSolution",
    "PowerLaw",
    "RevolutionWear",
    "SpringLaw",
    "contact_law",
    "effective_modulus",
    "revolution_wear",
    "solve",
    "solve_contact",
]

#: name -> factory ``(ContactParameters) -> law``
CONTACT_MODELS: Registry[Callable[[ContactParameters], Any]] = Registry(
    "contact model", "contact.model"
)
CONTACT_MODELS.add("hertz", hertz.HertzLaw)
CONTACT_MODELS.add("winkler", winkler.spring_law)
CONTACT_MODELS.add("asymmetric-winkler", asymmetric_winkler.spring_law)
CONTACT_MODELS.add("nlcp", nlcp.spring_law)
# reference solutions: exact elasticity and finite elements
CONTACT_MODELS.add("persson", persson_model)
CONTACT_MODELS.add("fem", fem_model)

MODEL_DESCRIPTIONS = {
    "hertz": "Hertz force law F = K delta^n with the line-contact pressure profile (eqs. 1-3)",
    "winkler": "linear Winkler springs p = E_w/L delta, symmetric about the load (eqs. 4-5)",
    "asymmetric-winkler": "Winkler springs on the real (worn) contour, N = N_L + N_R (eq. 6)",
    "nlcp": "nonlinear springs p = K delta^n / A, cylinder on plane (eq. 7)",
    "persson": "reference: exact elastic pin in a hole (Persson), circular bushings only",
    "fem": "reference: finite elements of the bushing wall in a rigid housing (scikit-fem)",
}


def contact_law(model: str | Callable[..., Any] | SpringLaw, parameters: ContactParameters):
    """Resolve a model name or callable into a law.

    Parameters
    ----------
    model : str, SpringLaw or callable
        Registry name, a ready law, or ``pressure(penetration)`` [m -> Pa].
    parameters : ContactParameters
        Geometry and materials.
    """
    if isinstance(model, str):
        return CONTACT_MODELS.get(model)(parameters)
    if isinstance(model, SpringLaw) or hasattr(model, "solve"):
        return model
    return CallableSpringLaw(model)


def solve(
    contour: BushingContour,
    pin: Pin,
    load: ArrayLike,
    azimuth: ArrayLike,
    model: str | Callable[..., Any] | SpringLaw,
    parameters: ContactParameters,
    **options: Any,
) -> ContactSolution:
    """Pressure distribution for many loads with any contact model.

    Parameters
    ----------
    contour : BushingContour
        Current bushing contour.
    pin : Pin
        The pin.
    load : array_like, shape (M,)
        Load magnitudes [N].
    azimuth : array_like, shape (M,)
        Load directions in the bushing frame [rad].
    model : str, SpringLaw or callable
        Contact model.
    parameters : ContactParameters
        Geometry and materials.
    **options
        Passed to :func:`solve_contact` (``balance``, ``tolerance``, ...).
    """
    law = contact_law(model, parameters)
    if hasattr(law, "solve"):
        # closed-form or reference models (Hertz, exact/FE references) solve themselves
        return law.solve(contour, pin, load, azimuth, **options)
    options.setdefault("max_penetration", parameters.bushing_thickness)
    return solve_contact(contour, pin, load, azimuth, law, **options)
