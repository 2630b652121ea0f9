r"""The oil film's force in the contact–impact dynamics: a lubricated clearance joint.

A lubricated pin flying in its bushing is carried by the pressure of the film before
it reaches the wall. :class:`FilmParameters` says which film (``"dry"``: none, today's
dynamics; ``"short-bearing"``, Ocvirk; ``"long-bearing"``, Sommerfeld) and its numbers
(viscosity, length, roughness, the transition band). :func:`joint_film_force` gives
the film's force for the relative state of the two bodies that the contact systems
hand to :class:`~jointwear.mechanism.impact.joint_contact.JointContact`: the pin-centre
offset ``e``, its rate and the sum of the angular velocities of pin and bushing.

The force is that of :mod:`jointwear.lubrication.film` (the short bearing of Ocvirk
[3]_, the long bearing of Sommerfeld as in Pinkus & Sternlicht [4]_; half-Sommerfeld cavitation:
the full-film pressure integrated where it is positive, with Sommerfeld's substitution;
wedge and squeeze together), written once more here as scalar functions of plain
floats because (a) the mechanism layer lies below the lubrication library and may not
import it, and (b) the right-hand side of the dynamics runs compiled: every function
of this module compiles unchanged with numba
(:mod:`jointwear.mechanism.impact.compiled_film`). The tests hold them to the
library's functions to 1e-9.

Kinematics
----------
With ``r = |e|``, ``n = e / r``, ``t = n`` turned by +90 degrees:

.. math::

    \varepsilon = \frac{r}{c}, \qquad \dot\varepsilon = \frac{\mathbf n\cdot\dot{\mathbf e}}{c},
    \qquad \dot\phi = \frac{e_x\dot e_y - e_y\dot e_x}{r^2}, \qquad
    \bar\omega = \omega_{pin} + \omega_{bushing} - 2\dot\phi .

The film's force on the pin is ``F_r n + F_t t``. The pressure acts normal to both
surfaces, through the centres of pin and bushing, so it has no moment about either.
Whichever body carries the bushing, the force on the body of the rod-side joint
centre (``e = C - D``) is ``F_r n + F_t t``, and on the other ``-(F_r n + F_t t)``.

Transition from film to contact
-------------------------------
The film's force grows without bound as the film closes (short bearing, pure squeeze:
like ``(1 - eps^2)^{-5/2}``), and a real film stops being a film once it is about as
thin as the surfaces are rough. Following Flores et al. [1]_ [2]_, the film acts alone
while the pin is well inside the clearance, and the contact–impact force law acts
together with it once the pin reaches the wall. In between lies a band of width
``delta_1`` below the wall (:meth:`FilmParameters.band`: by default the larger of
three roughnesses, where the hydrodynamic regime ``lambda = h_min / sigma > 3`` ends,
and a tenth of the clearance). With ``b = delta_1 / c`` and
``s = (e - c + delta_1) / delta_1``:

* ``e <= c - delta_1``: the film force at the pin's eccentricity;
* ``c - delta_1 < e < c``: the film force at the eccentricity
  ``eps_f = 1 - b + b (s - s^2/2)`` (:func:`film_eccentricity`), which leaves the
  pin's own with the same slope (C1) and levels off at ``1 - b/2`` at the wall: the
  film the force sees is never thinner than ``delta_1 / 2``;
* ``e >= c``: the contact–impact force law (penetration ``e - c``) plus the film force
  at ``eps_f = 1 - b/2``, with the pin's actual approach and sliding velocities: the
  squeeze film keeps damping the approach and the wedge keeps carrying while the
  solids touch.

The joint force is continuous and C1 in the position everywhere (the contact law
starts from zero at the wall). The band bounds the film's stiffness: its squeeze
damping at ``eps_f`` grows like ``(b (2 - b/2))^{-5/2}``; a band of 1 % of the clearance
makes it some 1e10 N s/m for an oiled pin of 0.05 mm clearance, and the equations of
motion of a pin that stays on the wall then take minutes per revolution to integrate
instead of a fifth of a second (measured on the paper's joint: 0.2 s per settled
revolution with the default tenth).

At ``eps_f < eps`` the wedge term is evaluated with the pin's actual sliding velocity
``c eps (dphi/dt - Omega)``, ``Omega = (omega_pin + omega_bushing) / 2``, i.e. with
``omega_bar eps / eps_f`` in place of ``omega_bar``: the force stays that of a film at
``eps_f`` for the pin's real velocity, so in the frame turning at ``Omega``, where the
film is a pure squeeze film, it only dissipates (checked in the tests) -- in the band
and in contact as well.

References
----------
.. [1] P. Flores, J. Ambrósio, J. C. P. Claro, H. M. Lankarani, C. S. Koshy, "A study
   on dynamics of mechanical systems including joints with clearance and
   lubrication", Mech. Mach. Theory 41 (2006) 247-261.
.. [2] P. Flores, J. Ambrósio, J. C. P. Claro, H. M. Lankarani, C. S. Koshy,
   "Lubricated revolute joints in rigid multibody systems", Nonlinear Dyn. 56 (2009)
   277-295.
.. [3] F. W. Ocvirk, "Short-bearing approximation for full journal bearings",
   NACA TN 2808 (1952).
.. [4] O. Pinkus, B. Sternlicht, *Theory of Hydrodynamic Lubrication*, McGraw-Hill
   (1961).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from jointwear.errors import ConfigError

__all__ = [
    "FILM_MODELS",
    "FilmParameters",
    "check_film_band",
    "film_eccentricity",
    "joint_film_force",
    "long_bearing",
    "short_bearing",
]

#: film models of the contact–impact dynamics, their codes in the compiled kernels
FILM_MODELS: dict[str, int] = {"dry": 0, "short-bearing": 1, "long-bearing": 2}
#: the smallest default transition band, as a share of the clearance: the film's
#: force is evaluated up to ``eps = 0.95``
SMALLEST_BAND = 0.1
#: the band in roughnesses: the hydrodynamic regime ends at ``h_min / sigma = 3``
BAND_ROUGHNESSES = 3.0
#: below this eccentricity ratio the long bearing's squeeze terms use this value (as
#: :data:`jointwear.lubrication.film.SMALLEST_ECCENTRICITY`)
SMALLEST_ECCENTRICITY = 1e-8
#: cells of the film angle searched for the ends of the long bearing's positive film
#: (as :data:`jointwear.lubrication.film.LONG_BEARING_CELLS`)
CELLS = 96
_EDGES = np.linspace(0.0, 2.0 * np.pi, CELLS + 1)
_EDGE_COS = np.cos(_EDGES)
_EDGE_SIN = np.sin(_EDGES)


@dataclass(frozen=True)
class FilmParameters:
    """The oil film of a lubricated joint in the contact–impact dynamics, SI.

    Parameters
    ----------
    model : str
        ``"dry"`` (no film: the dynamics of a dry joint, bit for bit),
        ``"short-bearing"`` (Ocvirk, ``L/D`` small) or ``"long-bearing"``
        (Sommerfeld, ``L/D`` large).
    viscosity : float
        Dynamic viscosity ``mu >= 0`` [Pa s].
    length : float, optional
        Length ``L`` of the film along the pin [m]; default the joint's axial length.
    roughness : float
        Composite roughness ``sigma = sqrt(Rq_pin^2 + Rq_bushing^2) >= 0`` [m]; sets
        the transition band (:meth:`band`).
    transition : float, optional
        Width ``delta_1`` of the band in which the film hands over to the contact
        [m], ``0 < delta_1 < c``; default :meth:`band`'s.
    """

    model: str = "dry"
    viscosity: float = 0.0
    length: float | None = None
    roughness: float = 0.0
    transition: float | None = None

    def __post_init__(self) -> None:
        if self.model not in FILM_MODELS:
            hint = (
                "; the finite-length film is available for load cycles, not in contact-impact "
                "dynamics"
                if self.model == "finite-length"
                else ""
            )
            raise ConfigError(
                f"lubrication.model: {self.model!r} is not a film model of the contact-impact "
                "dynamics; choose from " + ", ".join(repr(m) for m in FILM_MODELS) + hint
            )
        if not (math.isfinite(self.viscosity) and self.viscosity >= 0.0):
            raise ConfigError(f"lubrication.viscosity: must be >= 0 Pa*s, got {self.viscosity!r}")
        if self.length is not None and not (math.isfinite(self.length) and self.length > 0.0):
            raise ConfigError(f"lubrication.length: must be > 0 m, got {self.length!r}")
        if not (math.isfinite(self.roughness) and self.roughness >= 0.0):
            raise ConfigError(f"lubrication.roughness: must be >= 0 m, got {self.roughness!r}")
        if self.transition is not None and not (
            math.isfinite(self.transition) and self.transition > 0.0
        ):
            raise ConfigError(f"lubrication.transition: must be > 0 m, got {self.transition!r}")

    @property
    def active(self) -> bool:
        """Whether there is a film (``model`` is not ``"dry"``)."""
        return self.model != "dry"

    @property
    def code(self) -> int:
        """The model's code in the compiled kernels (:data:`FILM_MODELS`)."""
        return FILM_MODELS[self.model]

    def band(self, clearance: float) -> float:
        """Width ``delta_1`` of the transition band [m].

        ``transition`` if given, else ``max(3 sigma, c / 10)``: the film is a full film
        while ``h_min > 3 sigma`` (``lambda > 3``, the hydrodynamic regime), and its
        force is evaluated up to ``eps = 0.95`` (a narrower band makes the equations
        of motion far stiffer: module docstring).

        Parameters
        ----------
        clearance : float
            Radial clearance ``c`` [m].

        Raises
        ------
        ConfigError
            If the band is not narrower than the clearance.
        """
        band = self.transition
        if band is None:
            band = max(BAND_ROUGHNESSES * self.roughness, SMALLEST_BAND * clearance)
        if not band < clearance:
            key = "transition" if self.transition is not None else "roughness"
            raise ConfigError(
                f"lubrication.{key}: the film's transition band {band:.4g} m must be narrower "
                f"than the clearance {clearance:.4g} m"
            )
        return band


def check_film_band(model: str, roughness: float, clearance: float) -> None:
    """Refuse a film whose default transition band is not narrower than the clearance.

    Parameters
    ----------
    model : str
        ``lubrication.model`` (a film model of the contact–impact dynamics).
    roughness : float
        Composite roughness ``sigma`` [m].
    clearance : float
        Radial clearance ``c`` [m].

    Raises
    ------
    ConfigError
        One line naming ``lubrication.roughness``: ``3 sigma >= c``.
    """
    FilmParameters(model, roughness=roughness).band(clearance)


def sommerfeld_angle(theta: float, eps: float) -> float:
    """Sommerfeld's angle ``gamma(theta)`` [rad].

    (:func:`jointwear.lubrication.film.sommerfeld_angle`.)

    Parameters
    ----------
    theta : float
        Film angle from the largest film [rad].
    eps : float
        Eccentricity ratio in [0, 1) [-].
    """
    b = eps / (1.0 + math.sqrt(1.0 - eps * eps))
    return theta - 2.0 * math.atan(b * math.sin(theta) / (1.0 + b * math.cos(theta)))


def short_bearing(
    radius: float,
    length: float,
    clearance: float,
    viscosity: float,
    eps: float,
    rate: float,
    wedge: float,
) -> tuple[float, float]:
    r"""Short-bearing (Ocvirk) film force, half-Sommerfeld cavitation [N].

    .. math::

        F_r = \frac{\mu R L^3}{2c^2}\int_{\theta_1}^{\theta_1+\pi}
              \frac{(\bar\omega\varepsilon\sin\theta - 2\dot\varepsilon\cos\theta)\cos\theta}
                   {(1+\varepsilon\cos\theta)^3}\,d\theta,
        \qquad \theta_1 = \operatorname{atan2}(2\dot\varepsilon, \varepsilon\bar\omega),

    ``F_t`` the same with ``sin theta``, in closed form with Sommerfeld's substitution
    (:func:`jointwear.lubrication.film.short_bearing_force`, Ocvirk 1952).

    Parameters
    ----------
    radius : float
        Pin radius ``R`` [m].
    length : float
        Film length ``L`` [m].
    clearance : float
        Radial clearance ``c`` [m].
    viscosity : float
        ``mu`` [Pa s].
    eps : float
        Eccentricity ratio in [0, 1) [-].
    rate : float
        ``deps/dt`` [1/s], positive towards the wall.
    wedge : float
        Effective wedge speed ``omega_bar`` [rad/s].

    Returns
    -------
    tuple of float
        ``(F_r, F_t)``, the force on the pin along ``n`` and ``t`` [N].
    """
    wedge_eps = wedge * eps
    squeeze = 2.0 * rate
    start = math.atan2(squeeze, wedge_eps)
    one_minus = 1.0 - eps * eps
    g0 = sommerfeld_angle(start, eps)
    g1 = sommerfeld_angle(start + math.pi, eps)
    s_ss = ((0.5 * g1 - 0.25 * math.sin(2.0 * g1)) - (0.5 * g0 - 0.25 * math.sin(2.0 * g0))) / (
        one_minus**1.5
    )
    s_cc = (
        (0.5 + eps * eps) * (g1 - g0)
        + 0.25 * (math.sin(2.0 * g1) - math.sin(2.0 * g0))
        - 2.0 * eps * (math.sin(g1) - math.sin(g0))
    ) / one_minus**2.5
    s_sc = (
        0.5 * (math.sin(g1) ** 2 - math.sin(g0) ** 2) + eps * (math.cos(g1) - math.cos(g0))
    ) / one_minus**2
    scale = viscosity * radius * length**3 / (2.0 * clearance**2)
    return (
        scale * (wedge_eps * s_sc - squeeze * s_cc),
        scale * (wedge_eps * s_ss - squeeze * s_sc),
    )


def long_bearing_sign(cos_t: float, sin_t: float, eps: float, rate: float, wedge: float) -> float:
    """``(1 + eps cos theta)^2`` times the long bearing's full-film pressure over ``6 mu (R/c)^2``.

    (:func:`jointwear.lubrication.film.long_bearing_pressure_sign`.)

    Parameters
    ----------
    cos_t, sin_t : float
        ``cos theta``, ``sin theta`` [-].
    eps : float
        Eccentricity ratio [-].
    rate : float
        ``deps/dt`` [1/s].
    wedge : float
        ``omega_bar`` [rad/s].
    """
    rotation = wedge * eps * sin_t * (2.0 + eps * cos_t) / (2.0 + eps * eps)
    squeeze = rate * (3.0 * eps - 4.0 * cos_t - 2.0 * eps * cos_t * cos_t)
    return rotation + squeeze / (2.0 + 3.0 * eps * eps)


def long_bearing_root(
    left: float, right: float, positive_left: bool, eps: float, rate: float, wedge: float
) -> float:
    """The root of :func:`long_bearing_sign` in a cell whose ends differ in sign [rad].

    Newton's method kept inside the shrinking bracket (bisection where a Newton step
    would leave it), to a few units in the last place: scipy's root finders cannot be
    called from the compiled right-hand side. The force's error is of second order
    in the root's (the pressure vanishes there).
    """
    a, b = left, right
    x = 0.5 * (a + b)
    k_rot = wedge * eps / (2.0 + eps * eps)
    k_sq = rate / (2.0 + 3.0 * eps * eps)
    for _ in range(100):
        c, s = math.cos(x), math.sin(x)
        value = k_rot * s * (2.0 + eps * c) + k_sq * (3.0 * eps - 4.0 * c - 2.0 * eps * c * c)
        if (value > 0.0) == positive_left:
            a = x
        else:
            b = x
        slope = k_rot * (2.0 * c + eps * (c * c - s * s)) + k_sq * (4.0 * s + 4.0 * eps * c * s)
        step = x - value / slope if slope != 0.0 else 0.5 * (a + b)
        if abs(step - x) <= 4.0 * 2.220446049250313e-16 * max(abs(x), 1.0) or b - a <= 1e-15:
            return step
        x = step if a < step < b else 0.5 * (a + b)
    return x


def long_bearing_antiderivatives(theta: float, eps: float) -> tuple[float, float, float, float]:
    """Antiderivatives of the long bearing's four force integrands at ``theta``.

    (:func:`jointwear.lubrication.film.long_bearing_antiderivatives`: rotation times
    ``cos``, ``sin``; squeeze times ``cos``, ``sin``.)

    Parameters
    ----------
    theta : float
        Film angle [rad].
    eps : float
        Eccentricity ratio [-].
    """
    cos_t, sin_t = math.cos(theta), math.sin(theta)
    film = 1.0 + eps * cos_t
    gamma = sommerfeld_angle(theta, eps)
    root = math.sqrt(1.0 - eps * eps)
    k = 2.0 / (2.0 + 3.0 * eps * eps)
    return (
        -(cos_t * cos_t) / film,
        gamma / root - sin_t * cos_t / film,
        (math.sin(gamma) - eps * gamma) / root**3 - k * sin_t,
        -cos_t / film + k * cos_t,
    )


def long_bearing(
    radius: float,
    length: float,
    clearance: float,
    viscosity: float,
    eps: float,
    rate: float,
    wedge: float,
) -> tuple[float, float]:
    r"""Long-bearing (Sommerfeld) film force, half-Sommerfeld cavitation [N].

    The full-film pressure

    .. math::

        p = \frac{6\mu R^2}{c^2}\Big[
            \frac{\bar\omega\varepsilon\sin\theta(2+\varepsilon\cos\theta)}
                 {(2+\varepsilon^2)(1+\varepsilon\cos\theta)^2}
            + \frac{\dot\varepsilon}{\varepsilon}\Big(
              \frac{1}{(1+\varepsilon\cos\theta)^2} - \frac{2}{2+3\varepsilon^2}\Big)\Big]

    integrated in closed form between its roots
    (:func:`jointwear.lubrication.film.long_bearing_force`): the turn is cut into
    :data:`CELLS` cells, a cell whose ends differ in sign holds a root
    (:func:`long_bearing_root`), and each positive run of cells adds the difference
    of :func:`long_bearing_antiderivatives` at its ends.

    Parameters
    ----------
    radius : float
        Pin radius ``R`` [m].
    length : float
        Film length ``L`` [m].
    clearance : float
        Radial clearance ``c`` [m].
    viscosity : float
        ``mu`` [Pa s].
    eps : float
        Eccentricity ratio in [0, 1) [-].
    rate : float
        ``deps/dt`` [1/s], positive towards the wall.
    wedge : float
        Effective wedge speed ``omega_bar`` [rad/s].

    Returns
    -------
    tuple of float
        ``(F_r, F_t)`` [N].
    """
    eps = max(eps, SMALLEST_ECCENTRICITY)
    rot_cos = rot_sin = sq_cos = sq_sin = 0.0
    run_start = run_end = start = end = 0.0
    running = False
    q_left = long_bearing_sign(_EDGE_COS[0], _EDGE_SIN[0], eps, rate, wedge)
    for k in range(CELLS + 1):
        if k < CELLS:
            left, right = _EDGES[k], _EDGES[k + 1]
            q_right = long_bearing_sign(_EDGE_COS[k + 1], _EDGE_SIN[k + 1], eps, rate, wedge)
            # the positive part of the cell, as lubrication.film.positive_cells has it
            start, end = left, right
            if (q_left > 0.0) != (q_right > 0.0):
                root = long_bearing_root(left, right, q_left > 0.0, eps, rate, wedge)
                if q_left > 0.0:
                    end = root
                else:
                    start = root
            elif not q_left > 0.0:
                start = right
            q_left = q_right
            if not start < end:
                continue
            if running and start == run_end:
                run_end = end
                continue
        if running:
            a = long_bearing_antiderivatives(run_start, eps)
            b = long_bearing_antiderivatives(run_end, eps)
            rot_cos += b[0] - a[0]
            rot_sin += b[1] - a[1]
            sq_cos += b[2] - a[2]
            sq_sin += b[3] - a[3]
        if k < CELLS:
            run_start, run_end, running = start, end, True
    rotation = wedge * eps / (2.0 + eps * eps)
    squeeze = rate / eps
    scale = 6.0 * viscosity * radius**3 * length / clearance**2
    return (
        scale * (rotation * rot_cos + squeeze * sq_cos),
        scale * (rotation * rot_sin + squeeze * sq_sin),
    )


def film_eccentricity(eps: float, band: float) -> float:
    """The eccentricity ratio at which the film's force is evaluated [-].

    ``eps`` up to ``eps_1 = 1 - b``; then ``eps_1 + b (s - s^2 / 2)`` with
    ``s = (eps - eps_1) / b`` (C1 at both ends); ``1 - b / 2`` from the wall on
    (module docstring).

    Parameters
    ----------
    eps : float
        The pin's eccentricity ratio ``|e| / c`` [-].
    band : float
        The transition band over the clearance, ``b = delta_1 / c`` in (0, 1) [-].
    """
    start = 1.0 - band
    if eps <= start:
        return eps
    s = (eps - start) / band
    if s >= 1.0:
        return 1.0 - 0.5 * band
    return start + band * (s - 0.5 * s * s)


def joint_film_force(
    ex: float,
    ey: float,
    vx: float,
    vy: float,
    spin: float,
    model: float,
    radius: float,
    length: float,
    clearance: float,
    viscosity: float,
    band: float,
) -> tuple[float, float]:
    """The film's force on the body of the joint centre ``D`` (``e = C - D``) [N].

    The sign convention of the contact force ``J`` of
    :meth:`~jointwear.mechanism.impact.joint_contact.JointContact.force`: ``-(F_r n +
    F_t t)``, the film's force on the pin being ``F_r n + F_t t`` when ``C`` carries the
    pin (and on the bushing when ``C`` carries the bushing: the two cases agree).

    Parameters
    ----------
    ex, ey : float
        ``e = C - D`` [m].
    vx, vy : float
        ``e'`` [m/s].
    spin : float
        ``omega_pin + omega_bushing``, the sum of the two bodies' angular velocities
        [rad/s].
    model : float
        :data:`FILM_MODELS` code (1 short, 2 long bearing; 0 gives no force) [-].
    radius : float
        Pin radius ``R`` [m].
    length : float
        Film length ``L`` [m].
    clearance : float
        Radial clearance ``c`` [m].
    viscosity : float
        ``mu`` [Pa s].
    band : float
        Transition band over the clearance ``delta_1 / c`` [-].

    Returns
    -------
    tuple of float
        ``(J_x, J_y)`` of the film [N].
    """
    r = math.sqrt(ex * ex + ey * ey)
    if r > 0.0:
        nx, ny = ex / r, ey / r
        turn = (ex * vy - ey * vx) / (r * r)
    else:
        speed = math.sqrt(vx * vx + vy * vy)
        if speed == 0.0:
            return 0.0, 0.0
        nx, ny = vx / speed, vy / speed
        turn = 0.0
    eps = r / clearance
    rate = (nx * vx + ny * vy) / clearance
    eps_film = film_eccentricity(eps, band)
    wedge = spin - 2.0 * turn
    if eps_film < eps:
        wedge = wedge * (eps / eps_film)
    if model == 1.0:
        radial, tangential = short_bearing(
            radius, length, clearance, viscosity, eps_film, rate, wedge
        )
    elif model == 2.0:
        radial, tangential = long_bearing(
            radius, length, clearance, viscosity, eps_film, rate, wedge
        )
    else:
        return 0.0, 0.0
    return -(radial * nx - tangential * ny), -(radial * ny + tangential * nx)
