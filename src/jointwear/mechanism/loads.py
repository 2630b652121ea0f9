"""The joint load over one crank revolution: what the dynamics hands to the wear model.

Every dynamics model (``dynamics.model``) returns a :class:`JointLoad`: per time
step the magnitude and direction of the force between pin and bushing, and the
relative rotation of pin and bushing, which sets the sliding distance of the
Archard step (SPEC section 1, steps 1 and 3).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["JointLoad", "bushing_frame", "wrap_angle"]

FloatArray = NDArray[np.float64]


def wrap_angle(angle: FloatArray | float) -> FloatArray:
    """Wrap angles to the interval (-pi, pi] [rad].

    Parameters
    ----------
    angle : array_like
        Angles [rad].

    Returns
    -------
    ndarray
        The same angles in (-pi, pi] [rad].
    """
    wrapped = np.mod(np.asarray(angle, dtype=float) + np.pi, 2.0 * np.pi) - np.pi
    # mod maps +pi to -pi; the interval is closed on the right
    return np.where(wrapped == -np.pi, np.pi, wrapped)


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
        azimuth = np.arctan2(fy, fx)
        relative_rotation = increment
    else:
        # bushing in the rod end, pin on the slider: the pin presses on it with -J,
        # seen in the rod's frame; phi_pin - phi_bushing = 0 - theta_2
        azimuth = np.arctan2(-fy, -fx) - np.asarray(rod_angle, dtype=float)
        relative_rotation = -increment
    # continuous in time, and placed (by a whole turn) so that its mean is in (-pi, pi]
    azimuth = np.unwrap(azimuth)
    return azimuth + (wrap_angle(azimuth.mean()) - azimuth.mean()), relative_rotation


@dataclass(frozen=True, eq=False)
class JointLoad:
    """Load on the clearance joint at ``N`` equally spaced crank angles of one revolution.

    Step ``k`` (``k = 0 .. N-1``) starts at crank angle ``phi_k = 2 pi k / N`` and
    covers ``[phi_k, phi_k + 2 pi / N]``. Forces and angles are sampled at
    ``phi_k``; increments (``relative_rotation``) belong to the step.

    Attributes
    ----------
    crank_angle : ndarray, shape (N,)
        Crank angle ``phi_1 = omega t`` at the start of each step [rad].
    time : ndarray, shape (N,)
        Time since the crank passed ``phi_1 = 0`` [s].
    load : ndarray, shape (N,)
        Magnitude ``F_N`` of the joint force, eq. (12) [N]; never negative.
    azimuth : ndarray, shape (N,)
        Direction in which the pin presses on the bushing, measured in the frame
        of the body that carries the bushing, counter-clockwise from its x axis
        [rad]. Unwrapped (continuous from step to step) and shifted by whole
        turns so that its mean lies in (-pi, pi].
    relative_rotation : ndarray, shape (N,)
        Signed increment of ``phi_pin - phi_bushing`` over step ``k`` [rad];
        ``R_b * |relative_rotation|`` is the sliding distance of the step.
    crank_torque : ndarray, shape (N,)
        Driving torque on the crank that keeps ``omega`` constant,
        counter-clockwise positive [N m].
    force_x, force_y : ndarray, shape (N,)
        Global components of ``J``, the force the connecting rod's end exerts on
        the slider through the joint [N].
    slider_position : ndarray, shape (N,)
        Position ``x_3`` of the bushing-side joint centre on the slider [m].
    rod_angle : ndarray, shape (N,)
        Angle of the rod (crank pin B to joint centre C), counter-clockwise from
        the global x axis [rad]. The paper's ``phi_2`` is ``-rod_angle``.
    contact_lost : bool
        True if the model's continuous-contact assumption fails somewhere.
    contact_lost_angles : ndarray
        Crank angles [rad] of the steps where it fails.
    crank_speed : float
        Constant crank angular velocity ``omega`` [rad/s].
    bushing_body : {"slider", "rod"}
        Body that carries the bushing (the frame of ``azimuth``).
    model : str
        Name of the dynamics model that produced the load.
    iterations : int
        Force/geometry fixed-point iterations used (0 without clearance).
    converged : bool
        False if the fixed point did not converge and a one-pass result is
        reported instead (only together with ``contact_lost``).
    """

    crank_angle: FloatArray
    time: FloatArray
    load: FloatArray
    azimuth: FloatArray
    relative_rotation: FloatArray
    crank_torque: FloatArray
    force_x: FloatArray
    force_y: FloatArray
    slider_position: FloatArray
    rod_angle: FloatArray
    contact_lost: bool
    contact_lost_angles: FloatArray
    crank_speed: float
    bushing_body: Literal["slider", "rod"] = "slider"
    model: str = "massless-link"
    iterations: int = 0
    converged: bool = True

    @classmethod
    def from_history(
        cls,
        load: ArrayLike,
        azimuth: ArrayLike,
        relative_rotation: ArrayLike,
        crank_speed: float = 2.0 * np.pi,
        bushing_body: Literal["slider", "rod"] = "slider",
    ) -> JointLoad:
        """A joint load from arrays, e.g. exported by another multibody code.

        Parameters
        ----------
        load : array_like, shape (N,)
            Load magnitude at each step [N].
        azimuth : array_like, shape (N,)
            Direction in which the pin presses on the bushing, bushing frame [rad].
        relative_rotation : array_like, shape (N,)
            Rotation of the pin relative to the bushing over each step [rad].
        crank_speed : float
            Angular velocity of the cycle, ``2 pi / period`` [rad/s].
        bushing_body : {"slider", "rod"}
            Body that carries the bushing (informative).

        Returns
        -------
        JointLoad
            Steps equally spaced over one cycle; torque and positions are NaN.
        """
        from jointwear.errors import DataError

        load = np.asarray(load, dtype=float).ravel()
        azimuth = np.asarray(azimuth, dtype=float).ravel()
        rotation = np.asarray(relative_rotation, dtype=float).ravel()
        if not (load.size == azimuth.size == rotation.size) or load.size < 2:
            raise DataError(
                "load history: load, azimuth and relative_rotation need one "
                "value per step (at least 2 steps)"
            )
        if not (
            np.all(np.isfinite(load))
            and np.all(np.isfinite(azimuth))
            and np.all(np.isfinite(rotation))
        ):
            raise DataError("load history: values must be finite")
        if np.any(load < 0):
            raise DataError("load history: load magnitudes must be >= 0")
        steps = load.size
        angle = 2.0 * np.pi * np.arange(steps) / steps
        nan = np.full(steps, np.nan)
        return cls(
            crank_angle=angle,
            time=angle / crank_speed,
            load=load,
            azimuth=azimuth,
            relative_rotation=rotation,
            crank_torque=nan,
            force_x=load * np.cos(azimuth),
            force_y=load * np.sin(azimuth),
            slider_position=nan,
            rod_angle=nan,
            contact_lost=False,
            contact_lost_angles=np.zeros(0),
            crank_speed=crank_speed,
            bushing_body=bushing_body,
            model="history",
        )

    @property
    def steps(self) -> int:
        """Number of time steps ``N`` per revolution."""
        return int(self.crank_angle.size)

    @property
    def time_step(self) -> float:
        """Duration of one step ``2 pi / (N omega)`` [s]."""
        return 2.0 * np.pi / (self.steps * self.crank_speed)

    @property
    def total_relative_rotation(self) -> float:
        """Total relative rotation of pin and bushing over one revolution [rad]."""
        return float(np.sum(np.abs(self.relative_rotation)))

    def azimuth_increment(self) -> FloatArray:
        """Change of the load azimuth over each step, wrapped to (-pi, pi] [rad]."""
        return wrap_angle(np.roll(self.azimuth, -1) - self.azimuth)

    def sliding_distance(
        self,
        radius: float,
        variant: Literal["relative-rotation", "contact-azimuth"] = "relative-rotation",
    ) -> FloatArray:
        """Sliding distance at the pin-bushing interface over each step [m].

        Parameters
        ----------
        radius : float
            Radius at which the sliding is measured, normally the bushing
            radius ``R_b`` [m].
        variant : {"relative-rotation", "contact-azimuth"}
            ``"relative-rotation"`` (default, kinematically correct): ``R |d(phi_pin -
            phi_bushing)|``. ``"contact-azimuth"``: ``R |d psi|``, the change of the
            load azimuth on the bushing, as the paper words it (section 3.1).

        Returns
        -------
        ndarray, shape (N,)
            Sliding distance ``ds_k`` of each step [m].
        """
        if variant == "relative-rotation":
            return radius * np.abs(self.relative_rotation)
        if variant == "contact-azimuth":
            return self.contact_azimuth_sliding_distance(radius)
        raise ValueError(f"unknown sliding variant {variant!r}")

    def contact_azimuth_sliding_distance(self, radius: float) -> FloatArray:
        """Sliding distance ``R |d psi|`` from the load azimuth change (paper wording) [m].

        Parameters
        ----------
        radius : float
            Radius at which the sliding is measured [m].
        """
        return radius * np.abs(self.azimuth_increment())

    @property
    def mean_load(self) -> float:
        """Time mean of the load magnitude [N]."""
        return float(np.mean(self.load))

    @property
    def sliding_mean_load(self) -> float:
        """Sliding-weighted mean load ``sum F |d phi| / sum |d phi|`` [N].

        Archard wear over a revolution is proportional to ``sum F ds``, so this is
        the load that, applied over the total sliding distance, wears as much.
        Falls back to the time mean if pin and bushing do not rotate relatively.
        """
        weight = np.abs(self.relative_rotation)
        total = weight.sum()
        if total == 0.0:
            return self.mean_load
        return float(np.sum(self.load * weight) / total)

    def summary(self) -> dict[str, Any]:
        """Scalar results (SI, units in the keys), keyed as ``jointwear dynamics --json``."""
        azimuth_deg = np.degrees(self.azimuth)
        return {
            "dynamics_model": self.model,
            "bushing_body": self.bushing_body,
            "steps": self.steps,
            "crank_speed_rad_s": float(self.crank_speed),
            "load_min_n": float(self.load.min()),
            "load_max_n": float(self.load.max()),
            "load_mean_n": self.mean_load,
            "load_sliding_mean_n": self.sliding_mean_load,
            "azimuth_min_deg": float(azimuth_deg.min()),
            "azimuth_max_deg": float(azimuth_deg.max()),
            "azimuth_range_deg": float(azimuth_deg.max() - azimuth_deg.min()),
            "total_relative_rotation_rad": self.total_relative_rotation,
            "crank_torque_rms_nm": float(np.sqrt(np.mean(self.crank_torque**2))),
            "crank_torque_max_abs_nm": float(np.max(np.abs(self.crank_torque))),
            "contact_lost": bool(self.contact_lost),
            # rounded so that 2 pi k / N prints as 15.0, not 14.999999999999998
            "contact_lost_crank_angles_deg": [
                float(a) for a in np.round(np.degrees(self.contact_lost_angles), 9)
            ],
            "iterations": int(self.iterations),
            "fixed_point_converged": bool(self.converged),
        }

    def columns(self) -> dict[str, FloatArray]:
        """Per-step arrays keyed by unit-bearing column headers (for CSV output)."""
        return {
            "crank_angle [deg]": np.round(np.degrees(self.crank_angle), 9),
            "time [s]": self.time,
            "load [N]": self.load,
            "azimuth [deg]": np.degrees(self.azimuth),
            "relative_rotation [rad]": self.relative_rotation,
            "force_x [N]": self.force_x,
            "force_y [N]": self.force_y,
            "crank_torque [N m]": self.crank_torque,
            "slider_position [m]": self.slider_position,
            "rod_angle [deg]": np.degrees(self.rod_angle),
        }
