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

from typing import TYPE_CHECKING

import numpy as np

from jointwear.mechanism.cycle import Diagnostic, LoadCycle

if TYPE_CHECKING:
    from jointwear.config import Config

__all__ = ["oscillating_cycle"]


def oscillating_cycle(config: Config) -> dict[str, LoadCycle]:
    """Load cycle of the oscillating bearing over one oscillation.

    Parameters
    ----------
    config : jointwear.config.Config
        Uses ``[mechanism]`` (type ``"oscillating"``) and
        ``simulation.steps_per_revolution`` (steps per oscillation).

    Returns
    -------
    dict of str to LoadCycle
        The cycle of the one joint, ``"bearing"``.
    """
    mech = config.mechanism
    steps = config.simulation.steps_per_revolution
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
