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

Only some models can follow a worn contour (``simulation.update_contour = true``):
:data:`CIRCULAR_ONLY` names the others and :func:`check_model_choice` refuses them, and
refuses NLCP's paper form off the mesh its spring area belongs to.
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
from jointwear.errors import ConfigError
from jointwear.geometry.contour import BushingContour, Pin
from jointwear.registry import Registry

__all__ = [
    "CIRCULAR_ONLY",
    "CONTACT_MODELS",
    "NOT_FOR_WEAR_RUNS",
    "CallableSpringLaw",
    "ContactParameters",
    "ContactSolution",
    "PowerLaw",
    "RevolutionWear",
    "SpringLaw",
    "check_model_choice",
    "check_paper_spring_area",
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
# reference solutions: exact elasticity and finite elements (imported when first used:
# the references import this package)
CONTACT_MODELS.add_lazy("persson", "jointwear.references.persson:model")
CONTACT_MODELS.add_lazy("fem", "jointwear.references.fem:model")

MODEL_DESCRIPTIONS = {
    "hertz": "Hertz force law F = K delta^n with the line-contact pressure profile (eqs. 1-3), "
    "circular bushings only",
    "winkler": "linear Winkler springs p = E_w/L delta, symmetric about the load (eqs. 4-5), "
    "circular bushings only",
    "asymmetric-winkler": "Winkler springs on the real (worn) contour, N = N_L + N_R (eq. 6); "
    "the default",
    "nlcp": "nonlinear springs p = K delta^n / A, cylinder on plane (eq. 7)",
    "persson": "reference: exact elastic pin in a hole (Persson), circular bushings only",
    "fem": "reference: finite elements of the bushing wall in a rigid housing (scikit-fem)",
}


#: registered models that assume a circular bushing, and why: they cannot follow a
#: worn contour (Winkler's springs are symmetric about the load, on the circle through
#: the compression centre; Hertz's and Persson's profiles are those of circles)
CIRCULAR_ONLY: dict[str, str] = {
    "winkler": "assumes a circular bushing",
    "hertz": "assumes a circular bushing",
    "persson": "is exact for a circular bushing only",
}

#: registered models refused in wear runs for another reason than circles, and why
NOT_FOR_WEAR_RUNS: dict[str, str] = {
    "fem": (
        "meshes and factorises the bushing wall anew at every contour update (minutes per "
        "run) and is a reference for single contours, not checked against worn-joint wear"
    ),
}

#: relative difference between NLCP's spring area and a node's area that the paper form
#: (node force ``K delta^n``) accepts [-]: a 1 degree mesh in floating point, nothing more
SPRING_AREA_TOLERANCE = 1e-9


def check_model_choice(model: str | Callable[..., Any] | SpringLaw, update_contour: bool) -> None:
    """Refuse a contact model that cannot follow a worn contour when the contour is updated.

    ``winkler`` evaluates its springs on the circle through the compression centre and
    ``hertz`` and ``persson`` solve circles: on a bushing worn into conformity (a load
    fixed in the bushing) their groove narrows as it deepens instead of widening, and
    the worn volume falls short of Archard's. A spring law on the real contour
    (``asymmetric-winkler``, ``nlcp``, a callable) follows it (the documentation's
    Validation page). The ``fem`` reference solves a worn contour, but a wear run would
    mesh the wall anew at every update and it was never checked against worn-joint
    wear (:data:`NOT_FOR_WEAR_RUNS`): it is refused there too.

    Parameters
    ----------
    model : str, SpringLaw or callable
        A registered name or a resolved law (a law with ``symmetric = True`` is refused
        like ``winkler``).
    update_contour : bool
        ``simulation.update_contour``.

    Raises
    ------
    ConfigError
        One line naming ``contact.model`` and the models that can follow the contour.
    """
    if not update_contour:
        return
    name = model if isinstance(model, str) else getattr(model, "name", None)
    symmetric = isinstance(model, SpringLaw) and model.symmetric
    if name in CIRCULAR_ONLY or symmetric:
        reason = CIRCULAR_ONLY.get(str(name), CIRCULAR_ONLY["winkler"])
        raise ConfigError(
            f"contact.model: {name!r} {reason} and cannot follow a worn contour; with "
            f"simulation.update_contour = true use 'asymmetric-winkler' (the default) or 'nlcp'"
        )
    if name in NOT_FOR_WEAR_RUNS:
        raise ConfigError(
            f"contact.model: {name!r} {NOT_FOR_WEAR_RUNS[name]}; with "
            f"simulation.update_contour = true use 'asymmetric-winkler' (the default) or "
            f"'nlcp', and compare single contours with `jointwear compare-models`"
        )


def check_paper_spring_area(spring_area: float, node_area: float, nodes: int) -> None:
    """Refuse NLCP's paper form where its spring area is not the area of a node.

    The paper form gives node ``j`` the force ``K delta_j^n`` whatever surface it
    stands for, while Archard's law wears that surface with the pressure
    ``p_j = K delta_j^n / A``: the worn volume is ``K_d sum_k N_k ds_k`` only if the
    spring area ``A`` is the node's ``R_b (2 pi / N) b``; otherwise it is
    ``(node area / A)`` times it (half on a 0.5 degree mesh with the 1 degree default).

    Parameters
    ----------
    spring_area : float
        NLCP spring area ``A`` [m^2].
    node_area : float
        Area of a node of the unworn mesh ``R_b (2 pi / N) b`` [m^2].
    nodes : int
        ``contact.nodes`` [-].

    Raises
    ------
    ConfigError
        One line naming ``contact.nlcp_variant`` and the mesh-independent form.
    """
    if abs(spring_area / node_area - 1.0) > SPRING_AREA_TOLERANCE:
        raise ConfigError(
            f"contact.nlcp_variant: 'paper' gives each node the force of a spring of "
            f"{spring_area:.4g} m^2, but a node of this mesh (contact.nodes = {nodes}) is "
            f"{node_area:.4g} m^2, so the wear would be {node_area / spring_area:.3g} x "
            f"Archard's; use contact.nlcp_variant = 'mesh-independent'"
        )


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
