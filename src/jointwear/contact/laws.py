"""Contact laws shared by the pressure models, and their parameters.

A *spring law* maps the penetration of a bushing node to the pressure on it
(Winkler, asymmetric Winkler, NLCP). Hertz is not a spring model: it gives
the pressure profile in closed form (:mod:`jointwear.contact.hertz`).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from jointwear.errors import ConfigError

__all__ = ["CallableSpringLaw", "ContactParameters", "PowerLaw", "SpringLaw", "effective_modulus"]

FloatArray = NDArray[np.float64]


def effective_modulus(
    youngs_modulus_1: float, poisson_ratio_1: float, youngs_modulus_2: float, poisson_ratio_2: float
) -> float:
    """Plane-strain contact modulus ``E*`` [Pa].

    .. math:: 1/E^* = (1-\\nu_1^2)/E_1 + (1-\\nu_2^2)/E_2 = \\pi (\\sigma_1 + \\sigma_2)

    Parameters
    ----------
    youngs_modulus_1, youngs_modulus_2 : float
        Young's moduli [Pa].
    poisson_ratio_1, poisson_ratio_2 : float
        Poisson's ratios [-].
    """
    return 1.0 / (
        (1 - poisson_ratio_1**2) / youngs_modulus_1 + (1 - poisson_ratio_2**2) / youngs_modulus_2
    )


@dataclass(frozen=True)
class ContactParameters:
    """Everything a contact model may need, SI floats.

    Parameters
    ----------
    pin_radius : float
        Pin radius ``R_p`` [m].
    bushing_radius : float
        Unworn bushing inner radius ``R_b`` [m].
    axial_length : float
        Axial length ``b`` of the joint [m].
    bushing_thickness : float
        Bushing wall thickness ``L`` [m].
    pin_youngs_modulus, bushing_youngs_modulus : float
        Young's moduli [Pa].
    pin_poisson_ratio, bushing_poisson_ratio : float
        Poisson's ratios [-].
    exponent : float
        Force exponent ``n`` of Hertz/NLCP [-].
    foundation_modulus : {"youngs", "constrained"}
        Winkler foundation modulus definition (default ``"constrained"``, the thin-layer
        modulus, as ``contact.foundation_modulus``).
    spring_area : float
        NLCP spring area ``A`` of eq. (7) [m^2].
    nlcp_variant : {"paper", "mesh-independent"}
        How NLCP springs turn pressure into force (see :mod:`jointwear.contact.nlcp`).
    stiffness : float, optional
        NLCP spring stiffness ``K`` [N/m^n]; ``None`` (default) takes eq. (2),
        :func:`jointwear.contact.nlcp.stiffness`.
    """

    pin_radius: float
    bushing_radius: float
    axial_length: float
    bushing_thickness: float
    pin_youngs_modulus: float
    pin_poisson_ratio: float
    bushing_youngs_modulus: float
    bushing_poisson_ratio: float
    exponent: float = 1.5
    foundation_modulus: str = "constrained"
    spring_area: float = math.nan
    nlcp_variant: str = "paper"
    stiffness: float | None = None

    def __post_init__(self) -> None:
        if math.isnan(self.spring_area):
            default = self.bushing_radius * math.radians(1.0) * self.axial_length
            object.__setattr__(self, "spring_area", default)

    @classmethod
    def from_config(cls, config) -> ContactParameters:
        """Build from a :class:`jointwear.config.Config` (:meth:`from_sections`)."""
        return cls.from_sections(config.joint, config.materials, config.contact)

    @classmethod
    def from_sections(cls, joint, materials, contact) -> ContactParameters:
        """Build from the ``[joint]``, ``[materials]`` and ``[contact]`` config sections.

        An unset ``contact.spring_area`` takes the 1 degree default, as the config does.
        """
        return cls(
            pin_radius=joint.pin_radius,
            bushing_radius=joint.bushing_radius,
            axial_length=joint.axial_length,
            bushing_thickness=joint.bushing_thickness,
            pin_youngs_modulus=materials.pin.youngs_modulus,
            pin_poisson_ratio=materials.pin.poisson_ratio,
            bushing_youngs_modulus=materials.bushing.youngs_modulus,
            bushing_poisson_ratio=materials.bushing.poisson_ratio,
            exponent=contact.exponent,
            foundation_modulus=contact.foundation_modulus,
            spring_area=math.nan if contact.spring_area is None else contact.spring_area,
            nlcp_variant=contact.nlcp_variant,
            stiffness=contact.stiffness,
        )

    @property
    def effective_modulus(self) -> float:
        """Plane-strain contact modulus ``E*`` of pin and bushing [Pa]."""
        return effective_modulus(
            self.pin_youngs_modulus,
            self.pin_poisson_ratio,
            self.bushing_youngs_modulus,
            self.bushing_poisson_ratio,
        )


class SpringLaw:
    """Pressure on a node as a function of its penetration.

    Attributes
    ----------
    name : str
        Model name.
    force_area : float or None
        Area [m^2] that turns a node's pressure into its force. ``None`` means the
        node's own area ``r_j dtheta b`` (a converged surface integral).
    symmetric : bool
        Evaluate the penetration on a circle through the compression centre
        (traditional Winkler) instead of on the real contour.
    """

    name: str = "spring"
    force_area: float | None = None
    symmetric: bool = False

    def pressure(self, penetration: FloatArray) -> FloatArray:
        """Pressure [Pa] for penetration [m] (>= 0)."""
        raise NotImplementedError

    def pressure_derivative(self, penetration: FloatArray) -> FloatArray:
        """``dp/d(delta)`` [Pa/m] for penetration [m] (>= 0)."""
        raise NotImplementedError


@dataclass(frozen=True)
class PowerLaw(SpringLaw):
    """``p = coefficient * delta ** exponent``.

    Parameters
    ----------
    coefficient : float
        Pressure coefficient [Pa / m^exponent].
    exponent : float
        Exponent [-].
    name : str
        Model name.
    force_area : float or None
        See :class:`SpringLaw` [m^2].
    symmetric : bool
        See :class:`SpringLaw`.
    """

    coefficient: float
    exponent: float
    name: str = "power-law"
    force_area: float | None = None
    symmetric: bool = False

    def pressure(self, penetration: FloatArray) -> FloatArray:
        if self.exponent == 1.0:
            return self.coefficient * penetration
        if self.exponent == 1.5:  # the Hertz exponent: sqrt is much cheaper than pow
            return self.coefficient * penetration * np.sqrt(penetration)
        return self.coefficient * penetration**self.exponent

    def pressure_derivative(self, penetration: FloatArray) -> FloatArray:
        if self.exponent == 1.0:
            return np.where(penetration > 0, self.coefficient, 0.0)
        if self.exponent == 1.5:
            return 1.5 * self.coefficient * np.sqrt(penetration)
        with np.errstate(divide="ignore"):
            slope = self.coefficient * self.exponent * penetration ** (self.exponent - 1.0)
        return np.where(penetration > 0, slope, 0.0)


class CallableSpringLaw(SpringLaw):
    """Wrap a user function ``pressure(penetration)`` [m -> Pa] as a spring law.

    The derivative is taken by central differences with a relative step.

    Parameters
    ----------
    function : callable
        Vectorised ``p(delta)`` [Pa] with ``p(0) = 0``, non-decreasing.
    name : str
        Name used in reports.
    """

    def __init__(self, function: Callable[[FloatArray], FloatArray], name: str | None = None):
        if not callable(function):
            raise ConfigError("contact.model: expected a model name or a callable")
        self.function = function
        self.name = name or getattr(function, "__name__", "custom")

    def pressure(self, penetration: FloatArray) -> FloatArray:
        return np.asarray(self.function(penetration), dtype=float)

    def pressure_derivative(self, penetration: FloatArray) -> FloatArray:
        h = np.maximum(penetration, 1e-12) * 1e-6
        upper = self.pressure(penetration + h)
        lower = self.pressure(np.maximum(penetration - h, 0.0))
        width = (penetration + h) - np.maximum(penetration - h, 0.0)
        return np.where(penetration > 0, (upper - lower) / width, 0.0)
