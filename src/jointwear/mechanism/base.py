"""What a mechanism type provides, and the registries of mechanism types and dynamics models.

A mechanism type (``mechanism.type``) is an object with a one-line ``description``,
the names of its dynamics ``models`` and ``load_cycles(inputs, wear_depth)``: the
:class:`~jointwear.mechanism.cycle.LoadCycle` of each of its clearance joints in a
given state of wear (:class:`Mechanism`). A type with inertia also offers its
contact–impact solution (:class:`ContactImpactMechanism`). :data:`MECHANISMS` holds
one per type:

================  =================================================================
``slider-crank``  the paper's mechanism, clearance between rod and slider
                  (:mod:`jointwear.mechanism.slider_crank`); ``massless-link``
                  (paper eqs. 10-12) or ``contact-impact``
``four-bar``      crank-rocker four-bar, any of its three moving joints with
                  clearance (:mod:`jointwear.mechanism.four_bar`); ``massless-link``
                  or ``contact-impact``
``oscillating``   oscillating-bearing test, prescribed load
                  (:mod:`jointwear.mechanism.oscillating`)
``load-history``  one period of load read from a file (:mod:`jointwear.mechanism.history`)
``duty-cycle``    several modes of the types above, each in a share of the cycles
                  (:mod:`jointwear.mechanism.duty_cycle`)
================  =================================================================

A new mechanism is one module (or package) with such an object and one line here.
"""

from __future__ import annotations

from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from jointwear.config import MECHANISM_TYPES
from jointwear.errors import ConfigError
from jointwear.mechanism.cycle import LoadCycle
from jointwear.mechanism.impact.revolution import ContactImpactSolution
from jointwear.mechanism.inputs import MechanismInputs
from jointwear.mechanism.slider_crank import SLIDER_CRANK
from jointwear.registry import Registry

__all__ = [
    "DYNAMICS_MODELS",
    "MECHANISMS",
    "ContactImpactMechanism",
    "Mechanism",
    "cycles_of",
]

FloatArray = NDArray[np.float64]


class Mechanism(Protocol):
    """A mechanism type: what it is and the load cycles of its joints.

    Attributes
    ----------
    description : str
        One line for ``jointwear mechanisms``.
    models : tuple of str
        Its dynamics models (names of :data:`DYNAMICS_MODELS`); a type whose load is
        prescribed has the single model ``"prescribed"``, used whatever
        ``dynamics.model`` says.
    """

    description: str
    models: tuple[str, ...]

    def load_cycles(
        self, inputs: MechanismInputs, wear_depth: FloatArray | None = None
    ) -> dict[str, LoadCycle]:
        """Load cycle of each clearance joint, from the model ``inputs.dynamics.model``.

        Parameters
        ----------
        inputs : MechanismInputs
            The mechanism's section, the joint, the dynamics settings.
        wear_depth : ndarray, shape (N,), optional
            Wear depth of the bushing on the ``joint.nodes`` grid, bushing frame [m]:
            the dynamics of the worn joint. ``None``: the unworn joint.

        Returns
        -------
        dict of str to LoadCycle
            Joint name -> its load cycle.
        """
        ...


class ContactImpactMechanism(Mechanism, Protocol):
    """A mechanism type with inertia: its joint can also be solved with a free pin."""

    def contact_impact(
        self,
        inputs: MechanismInputs,
        wear_depth: FloatArray | None = None,
        compare: bool = True,
    ) -> ContactImpactSolution:
        """The contact–impact solution of its (one) clearance joint.

        Parameters
        ----------
        inputs : MechanismInputs
            With the joint's elastic law (:attr:`MechanismInputs.elastic`).
        wear_depth : ndarray, shape (N,), optional
            Wear depth of the bushing [m]; ``None``: the unworn joint.
        compare : bool
            Also run the massless-link model and report the load difference.
        """
        ...


#: ``mechanism.type`` -> :class:`Mechanism`; its names are those of the config schema
MECHANISMS: Registry[Mechanism] = Registry("mechanism type", "mechanism.type")
MECHANISMS.add("slider-crank", SLIDER_CRANK)
# (imported when a run names them: a slider-crank run loads no other mechanism's modules;
# the duty cycle's modes are solved through cycles_of below, a lazy entry, not a cycle)
MECHANISMS.add_lazy("four-bar", "jointwear.mechanism.four_bar:FOUR_BAR")
MECHANISMS.add_lazy("oscillating", "jointwear.mechanism.oscillating:OSCILLATING")
MECHANISMS.add_lazy("load-history", "jointwear.mechanism.history:LOAD_HISTORY")
MECHANISMS.add_lazy("duty-cycle", "jointwear.mechanism.duty_cycle:DUTY_CYCLE")
if set(MECHANISMS) != set(MECHANISM_TYPES):  # pragma: no cover - a programming error
    raise RuntimeError("mechanism registry and config schema disagree on the type names")

#: dynamics model name (``dynamics.model``) -> what it is
DYNAMICS_MODELS: Registry[str] = Registry("dynamics model", "dynamics.model")
DYNAMICS_MODELS.add(
    "massless-link",
    "clearance as a massless link along the load, continuous contact (eqs. 10-12); for "
    "the four-bar the ideal-joint reaction",
)
DYNAMICS_MODELS.add(
    "contact-impact",
    "pin free in the clearance: contact force law with hysteresis damping and friction, "
    "event-driven integration (no continuous-contact assumption)",
)


def cycles_of(
    inputs: MechanismInputs, wear_depth: FloatArray | None = None
) -> dict[str, LoadCycle]:
    """Load cycle of every clearance joint of a mechanism, by its type's registry entry.

    Parameters
    ----------
    inputs : MechanismInputs
        The ``[mechanism]`` section (its ``type`` picks the entry), the joint, the
        ``[dynamics]`` settings (``model`` picks the dynamics model).
    wear_depth : ndarray, shape (N,), optional
        Wear depth of the bushing on the ``joint.nodes`` grid, bushing frame [m]
        (the massless link grows by the deepest wear, contact-impact meets the worn
        contour). ``None``: the unworn joint.

    Returns
    -------
    dict of str to LoadCycle
        Joint name -> its load cycle, in the order of the mechanism's joints.

    Raises
    ------
    ConfigError
        If ``dynamics.model`` names no model of the mechanism type.
    """
    kind = inputs.mechanism.type
    mechanism = MECHANISMS.get(kind)
    model = inputs.dynamics.model
    if "prescribed" not in mechanism.models and model not in mechanism.models:
        DYNAMICS_MODELS.get(model)  # an unknown name, with the closest one
        raise ConfigError(
            f"dynamics.model: mechanism.type {kind!r} has no dynamics model {model!r}; "
            f"choose from {', '.join(repr(m) for m in mechanism.models)}"
        )
    return dict(mechanism.load_cycles(inputs, wear_depth))
