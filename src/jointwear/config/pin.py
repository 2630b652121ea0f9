"""The ``[pin]`` section: a rigid pin, or a beam held by a clevis or a cantilever.

Read by a joint cut into axial slices (``joint.axial_slices >= 2``): a bending pin
(``model = "beam"``) adds its deflection under the slices' forces to each slice's offset
(:mod:`jointwear.contact.pin_beam`). Positions along the pin are measured from the
bushing's mid-plane. The pin's elastic constants are ``[materials.pin]``'s.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from jointwear.config.fields import NonNegLength, Section, si

__all__ = ["PinConfig"]

AxialPosition = Annotated[float, si("length"), Field(ge=-10.0, le=10.0)]


class PinConfig(Section):
    """The pin along its axis (SI once validated).

    Attributes
    ----------
    model : {"rigid", "beam"}
        A rigid pin, or a beam on the bushing's slices.
    beam_theory : {"timoshenko", "euler-bernoulli"}
        With or without shear deformation (a bending pin).
    support : {"clevis", "cantilever"}
        Two forks holding the pin simply supported, or a clamp.
    forks : tuple of float, optional
        Axial positions of the two forks' mid-planes ``z_A < z_B`` [m] (a clevis).
    fit_clearance : float
        Radial clearance of the pin in the fork bores [m]: the pin may tilt by
        ``2 c_f / (z_B - z_A)`` before it bears on them (a clevis).
    clamp : float, optional
        Axial position of the clamped section [m] (a cantilever).
    """

    model: Literal["rigid", "beam"] = "rigid"
    beam_theory: Literal["timoshenko", "euler-bernoulli"] = "timoshenko"
    support: Literal["clevis", "cantilever"] = "clevis"
    forks: tuple[AxialPosition, AxialPosition] | None = None
    fit_clearance: NonNegLength = 0.0
    clamp: AxialPosition | None = None

    @model_validator(mode="after")
    def _supports_given(self) -> PinConfig:
        if self.model == "rigid":
            for key in ("forks", "clamp"):
                if getattr(self, key) is not None:
                    raise ValueError(
                        f'pin.{key}: only a bending pin (pin.model = "beam") is held by '
                        f"supports; a rigid pin takes its tilt from joint.misalignment"
                    )
            return self
        unused = "clamp" if self.support == "clevis" else "forks"
        if getattr(self, unused) is not None:
            raise ValueError(f"pin.{unused}: a {self.support} pin has no {unused}")
        if self.support == "clevis":
            if self.forks is None:
                raise ValueError(
                    "pin.forks: a clevis pin needs the axial positions of its two forks, e.g. "
                    'forks = ["-15 mm", "15 mm"]'
                )
            if not self.forks[0] < self.forks[1]:
                raise ValueError(
                    f"pin.forks: the fork positions must increase, got {list(self.forks)}"
                )
        elif self.clamp is None:
            raise ValueError("pin.clamp: a cantilever pin needs the axial position of its clamp")
        return self


#: contact models that solve a whole cross-section and cannot be cut into slices
WHOLE_SECTION_MODELS = frozenset({"hertz", "persson", "fem"})


def check_along_the_pin(config) -> None:
    """Refuse the along-the-pin keys that contradict each other or the rest of the joint.

    Parameters
    ----------
    config : ConfigSchema
        The configuration being validated.

    Raises
    ------
    ValueError
        One line naming the key (the schema turns it into a ConfigError).
    """
    joint, pin, count = config.joint, config.pin, config.joint.axial_slices
    if count == 1:
        for key, value, what in (
            ("joint.misalignment", joint.misalignment, "an imposed tilt"),
            ("joint.load_offset", joint.load_offset, "a load off the mid-plane"),
        ):
            if value != 0:
                raise ValueError(
                    f"{key}: {what} needs joint.axial_slices >= 2 (one slice has no length "
                    f"to tilt along)"
                )
        if pin.model == "beam":
            raise ValueError(
                'pin.model: a bending pin ("beam") needs joint.axial_slices >= 2 (one slice '
                "cannot bend)"
            )
    if joint.misalignment_angle is not None and joint.misalignment == 0:
        raise ValueError(
            "joint.misalignment_angle: gives the plane of joint.misalignment, which is 0"
        )
    if abs(joint.load_offset) > 0.5 * joint.axial_length:
        raise ValueError(
            f"joint.load_offset: {joint.load_offset:g} m is outside the bushing "
            f"(|offset| <= joint.axial_length / 2 = {0.5 * joint.axial_length:g} m)"
        )
    if count == 1:
        return
    if config.contact.model in WHOLE_SECTION_MODELS:
        raise ValueError(
            f"contact.model: {config.contact.model!r} solves a whole cross-section and cannot "
            f"be cut into joint.axial_slices; use 'asymmetric-winkler', 'nlcp' or 'winkler'"
        )
    lubrication = getattr(config, "lubrication", None)
    if lubrication is not None and lubrication.model != "dry":
        raise ValueError(
            f"lubrication.model: a film ({lubrication.model!r}) is solved for the whole "
            f"bearing length and needs joint.axial_slices = 1 (the film along the slices of a "
            f"tilted pin is not modelled)"
        )
    if config.contact.balance != "paper":
        raise ValueError(
            'contact.balance: axial slices balance the load along its line ("paper"); '
            f"{config.contact.balance!r} needs joint.axial_slices = 1"
        )
