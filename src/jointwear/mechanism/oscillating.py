r"""The oscillating bearing: a pin swinging under a radial load (bushing qualification test).

Self-lubricating liners and bushings are qualified on oscillating-bearing rigs
(e.g. +-25 deg under a constant radial load, SAE AS81934): the pin turns back and
forth by ``amplitude`` either way while a load presses it onto the bushing. The
rotation of the pin relative to the bushing over one cycle of period
``T = 1 / frequency`` is

.. math::

    \varphi(t) = A \sin(2 \pi t / T),

so one cycle slides ``4 A R_b`` at the bushing radius. The load is

.. math::

    F(t) = F_0 + F_1 \cos(2 \pi h t / T + \phi_F),

directed at ``load_angle`` in the bushing's frame (``load_frame = "bushing"``, the
usual rig: the load is fixed and the bushing wears in one place), or turning with
the pin (``"pin"``: the load direction follows ``load_angle + varphi``).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from jointwear.mechanism.cycle import Diagnostic, LoadCycle
from jointwear.mechanism.impact.revolution import ContactImpactSolution
from jointwear.mechanism.inputs import MechanismInputs
from jointwear.mechanism.oscillating_impact import oscillating_contact_impact

__all__ = ["OSCILLATING", "OscillatingMechanism", "oscillating_cycle"]


def oscillating_cycle(inputs: MechanismInputs) -> dict[str, LoadCycle]:
    """Load cycle of the oscillating bearing over one oscillation.

    Parameters
    ----------
    inputs : MechanismInputs
        Uses the ``[mechanism]`` section (type ``"oscillating"``) and the steps per
        oscillation.

    Returns
    -------
    dict of str to LoadCycle
        The cycle of the one joint, ``"bearing"``.
    """
    mech = inputs.mechanism
    steps = inputs.steps
    period = mech.period
    time = period * np.arange(steps) / steps
    phase = 2.0 * np.pi * np.arange(steps + 1) / steps
    rotation = mech.amplitude * np.sin(phase)
    load = mech.load + mech.load_amplitude * np.cos(
        mech.load_harmonic * phase[:-1] + mech.load_phase
    )
    azimuth = np.full(steps, mech.load_angle)
    if mech.load_frame == "pin":
        azimuth = azimuth + rotation[:-1]
    cycle = LoadCycle.from_arrays(
        load=load,
        azimuth=azimuth,
        relative_rotation=np.diff(rotation),
        period=period,
        time=time,
        mechanism="oscillating",
        joint="bearing",
        diagnostics={
            "pin_angle": Diagnostic(rotation[:-1], "rad", "angle of the pin from mid-stroke"),
        },
        extras={
            "load_frame": mech.load_frame,
            "amplitude_deg": float(np.degrees(mech.amplitude)),
            "frequency_hz": float(mech.frequency),
        },
    )
    return {"bearing": cycle}


class OscillatingMechanism:
    """The oscillating bearing as a mechanism type (:class:`jointwear.mechanism.base.Mechanism`).

    The load is prescribed (the pin on the wall along the load, whatever
    ``dynamics.model`` names) unless ``dynamics.model = "contact-impact"``: then the
    loaded pin is free in the clearance (:mod:`jointwear.mechanism.oscillating_impact`).
    """

    description = "oscillating-bearing test: pin swinging +-amplitude under a radial load"
    models = ("prescribed", "contact-impact")

    def load_cycles(
        self, inputs: MechanismInputs, wear_depth: NDArray[np.float64] | None = None
    ) -> dict[str, LoadCycle]:
        """:func:`oscillating_cycle`, independent of the wear; with contact–impact the
        free pin's load on the bushing worn by ``wear_depth`` [m]."""
        if inputs.dynamics.model == "contact-impact":
            return {"bearing": self.contact_impact(inputs, wear_depth).load_cycle()}
        return oscillating_cycle(inputs)

    def contact_impact(
        self,
        inputs: MechanismInputs,
        wear_depth: NDArray[np.float64] | None = None,
        compare: bool = True,
    ) -> ContactImpactSolution:
        """The free pin's solution (:func:`.oscillating_impact.oscillating_contact_impact`).

        Parameters
        ----------
        inputs : MechanismInputs
            With the joint's elastic law.
        wear_depth : ndarray, shape (N,), optional
            Wear depth of the bushing [m]; ``None``: the unworn joint.
        compare : bool
            Also report the difference from the prescribed load.
        """
        prescribed = oscillating_cycle(inputs)["bearing"]
        return oscillating_contact_impact(inputs, prescribed, wear_depth, compare)


#: the registry entry
OSCILLATING = OscillatingMechanism()
