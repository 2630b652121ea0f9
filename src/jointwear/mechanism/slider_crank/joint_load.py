"""The slider-crank's joint load as a load cycle, in the frame of the body with the bushing.

Both dynamics models (massless-link, contact-impact) give the force ``J`` of the rod
end on the slider in the global frame; :func:`slider_crank_cycle` turns it into the
:class:`~jointwear.mechanism.cycle.LoadCycle` on the bushing (slider or rod end) and
keeps the mechanism's own series (crank torque, slider position, ...) as diagnostics.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.mechanism.cycle import Diagnostic, LoadCycle, bushing_azimuth, crank_extras

if TYPE_CHECKING:
    from jointwear.config import SliderCrankConfig

__all__ = ["bushing_frame", "slider_crank_cycle"]

FloatArray = NDArray[np.float64]


def bushing_frame(
    force_x: ArrayLike,
    force_y: ArrayLike,
    rod_angle: ArrayLike,
    rod_increment: ArrayLike,
    bushing_body: str,
) -> tuple[FloatArray, FloatArray]:
    """Load azimuth and relative rotation in the frame of the body carrying the bushing.

    Parameters
    ----------
    force_x, force_y : array_like
        Global components of ``J``, the force the rod's pin exerts on the slider [N].
    rod_angle : array_like
        Rod angle at each step [rad].
    rod_increment : array_like
        Rod angle increment over each step [rad].
    bushing_body : {"slider", "rod"}
        Body that carries the bushing.

    Returns
    -------
    azimuth : ndarray
        Direction in which the pin presses on the bushing, unwrapped and shifted by
        whole turns so that its mean lies in (-pi, pi] [rad].
    relative_rotation : ndarray
        Increment of ``phi_pin - phi_bushing`` over each step [rad].
    """
    fx, fy = np.asarray(force_x, dtype=float), np.asarray(force_y, dtype=float)
    increment = np.asarray(rod_increment, dtype=float)
    if bushing_body == "slider":
        # the bushing does not rotate; the pin turns with the rod
        return bushing_azimuth(fx, fy), increment
    # bushing in the rod end, pin on the slider: the pin presses on it with -J,
    # seen in the rod's frame; phi_pin - phi_bushing = 0 - theta_2
    return bushing_azimuth(-fx, -fy, np.asarray(rod_angle, dtype=float)), -increment


def slider_crank_cycle(
    mechanism: SliderCrankConfig,
    force_x: FloatArray,
    force_y: FloatArray,
    rod_angle: FloatArray,
    rod_increment: FloatArray,
    slider_position: FloatArray,
    crank_torque: FloatArray,
    normal_x: FloatArray | None = None,
    normal_y: FloatArray | None = None,
    **fields,
) -> LoadCycle:
    """A slider-crank's load cycle in the bushing frame, its own series as diagnostics.

    Parameters
    ----------
    mechanism : jointwear.config.SliderCrankConfig
        The ``[mechanism]`` section (``crank_speed``, ``bushing_body``, ``spring_mode``).
    force_x, force_y : ndarray, shape (N,)
        Global components of ``J``, the force of the rod end on the slider [N].
    rod_angle, rod_increment : ndarray, shape (N,)
        Rod angle and its increment over each step [rad].
    slider_position : ndarray, shape (N,)
        Slider position ``x_3`` [m].
    crank_torque : ndarray, shape (N,)
        Crank driving torque [N m].
    normal_x, normal_y : ndarray, optional
        Direction of the contact normal if not along ``J`` (contact-impact) [-].
    **fields
        Further :class:`~jointwear.mechanism.cycle.LoadCycle` fields.
    """
    mech = mechanism
    steps = force_x.size
    nx = force_x if normal_x is None else normal_x
    ny = force_y if normal_y is None else normal_y
    azimuth, relative_rotation = bushing_frame(nx, ny, rod_angle, rod_increment, mech.bushing_body)
    load = fields.pop("load", None)
    diagnostics = {
        "crank_torque": Diagnostic(crank_torque, "N m", "crank driving torque"),
        "slider_position": Diagnostic(slider_position, "m", "slider position x_3"),
        "rod_angle": Diagnostic(rod_angle, "rad", "connecting-rod angle"),
        "global_force_x": Diagnostic(force_x, "N", "x force of the rod end on the slider"),
        "global_force_y": Diagnostic(force_y, "N", "y force of the rod end on the slider"),
    }
    lost = np.zeros(steps, bool) if fields.get("lost_steps") is None else fields["lost_steps"]
    extras = {
        "bushing_body": mech.bushing_body,
        "spring_mode": mech.spring_mode,
        **crank_extras(mech.crank_speed, crank_torque, lost),
    }
    return LoadCycle(
        time=mech.period * np.arange(steps) / steps,
        load=np.hypot(force_x, force_y) if load is None else load,
        azimuth=azimuth,
        relative_rotation=relative_rotation,
        period=mech.period,
        mechanism="slider-crank",
        joint="rod-slider",
        diagnostics=diagnostics,
        extras=extras,
        **fields,
    )
