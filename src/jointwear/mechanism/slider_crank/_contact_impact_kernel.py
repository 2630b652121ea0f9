"""The slider-crank's contact-impact right-hand side, compiled by numba.

Imported by :mod:`jointwear.mechanism.slider_crank.contact_impact` on first use only
(``import numba`` and loading the cached machine code cost a few tenths of a second,
which a run without contact-impact dynamics should not pay). The physics is that of
:meth:`~jointwear.mechanism.slider_crank.contact_impact.SliderCrankContactSystem.evaluate`
and :meth:`~jointwear.mechanism.impact.joint_contact.JointContact.force` (point laws),
which stay the readable reference: every expression below is written in the same order,
so the compiled right-hand side gives the same bits (``math.hypot`` is CPython's
algorithm, :func:`hypot`), and the integrator takes the same steps.

``solve_ivp`` calls the right-hand side ~10^4 times per revolution; in Python each
call costs a few microseconds of interpreter work, here a fraction of one. The
parameters travel in one array (indices ``P_*``), and the wear profile of a worn
bushing (empty for a circular one) in another, so a call passes five arguments.
A lubricated joint adds the film's force
(:func:`jointwear.mechanism.impact.film.joint_film_force`, compiled by
:mod:`jointwear.mechanism.impact.compiled_film`) where ``P_FILM`` holds its model's code;
a dry joint (code 0) runs the same expressions as before.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from jointwear.mechanism.impact.compiled_film import SOURCE_DIGEST, joint_film_force

#: indices into the parameter array (``SliderCrankContactSystem._kernel_parameters``)
(
    P_CRANK,
    P_ROD,
    P_OMEGA,
    P_ROD_MASS,
    P_GRAVITY,
    P_INERTIA_B,
    P_SLIDER_MASS,
    P_CRANK_MASS,
    P_SPRING_PULL,
    P_PRELOAD,
    P_SPRING_STIFFNESS,
    P_CLEARANCE,
    P_STIFFNESS,
    P_EXPONENT,
    P_HYSTERESIS,
    P_FRICTION,
    P_V0,
    P_V1,
    P_ARM,
    P_FLOOR,
    P_FILM,
    P_PIN_RADIUS,
    P_FILM_LENGTH,
    P_VISCOSITY,
    P_FILM_BAND,
) = range(25)
N_PARAMETERS = 25

_FLAGS = {"cache": True}


def _with_film(function):
    """``njit`` with the disk cache keyed also by the film force's source.

    numba reloads a cached function while its own file is unchanged, even when a
    function compiled into it (the film force, another file) has changed: the name of
    the cache entry carries :data:`~jointwear.mechanism.impact.compiled_film.SOURCE_DIGEST`.
    """
    function.__qualname__ = f"{function.__qualname__}_film_{SOURCE_DIGEST}"
    return njit(**_FLAGS)(function)


@njit(**_FLAGS)
def _two_product(x, y):
    """``x y`` and its rounding error, exactly (Dekker's product, no FMA needed)."""
    z = x * y
    c = 134217729.0 * x
    xh = c - (c - x)
    xl = x - xh
    c = 134217729.0 * y
    yh = c - (c - y)
    yl = y - yh
    return z, ((xh * yh - z) + xh * yl + xl * yh) + xl * yl


@njit(**_FLAGS)
def hypot(x, y):
    """``math.hypot`` as CPython computes it (``vector_norm``: scaled, with a differential
    correction), so that the compiled gap equals the reference's to the bit; numba's own
    ``math.hypot`` calls the C library, which differs in the last bit for ~0.5 % of
    the arguments. Equal for every normal number (subnormals are scaled differently)."""
    a, b = abs(x), abs(y)
    if math.isinf(a) or math.isinf(b):
        return math.inf
    if math.isnan(a) or math.isnan(b):
        return math.nan
    big = a if a > b else b
    if big == 0.0:
        return big
    _, exponent = math.frexp(big)
    scale = math.ldexp(1.0, -exponent)
    csum, frac1, frac2 = 1.0, 0.0, 0.0
    for v in (a * scale, b * scale):
        high, low = _two_product(v, v)
        total = csum + high
        frac2 += (csum - total) + high
        frac1 += low
        csum = total
    h = math.sqrt(csum - 1.0 + (frac1 + frac2))
    high, low = _two_product(-h, h)
    total = csum + high
    frac2 += (csum - total) + high
    frac1 += low
    csum = total
    h += (csum - 1.0 + (frac1 + frac2)) / (2.0 * h)
    return h / scale


@njit(**_FLAGS)
def clearance_at(ex, ey, clearance, wear):
    """Mirror of :meth:`JointContact.clearance_at` (``wear`` holds the closed profile)."""
    if wear.size == 0:
        return clearance
    nodes = wear.size - 1
    angle = math.atan2(ey, ex)
    if angle < 0.0:
        # ``angle % (2 pi)`` for an angle in [-pi, pi]: the same one rounding of angle + 2 pi
        # (Python's float modulo), without the call of a modulo
        angle += 2.0 * math.pi
    position = angle * nodes / (2.0 * math.pi)
    index = min(int(position), nodes - 1)
    fraction = position - index
    return clearance + (1.0 - fraction) * wear[index] + fraction * wear[index + 1]


@_with_film
def point_force(ex, ey, vx, vy, spin, impact_velocity, p, wear):
    """Mirror of :meth:`JointContact.force` for the point laws (the slider does not turn:
    the film's wedge sees the rod's spin)."""
    r = hypot(ex, ey)
    if r > 0.0:
        nx, ny = ex / r, ey / r
    else:
        nx, ny = 1.0, 0.0
    rate = nx * vx + ny * vy
    delta = r - clearance_at(ex, ey, p[P_CLEARANCE], wear)
    elastic = p[P_STIFFNESS] * delta ** p[P_EXPONENT] if delta > 0.0 else 0.0
    slip = -ny * vx + nx * vy + p[P_ARM] * spin
    film = p[P_FILM]
    film_x = film_y = 0.0
    if film != 0.0:
        film_x, film_y = joint_film_force(
            ex, ey, vx, vy, spin, film, p[P_PIN_RADIUS], p[P_FILM_LENGTH], p[P_CLEARANCE],
            p[P_VISCOSITY], p[P_FILM_BAND],
        )  # fmt: skip
    if elastic <= 0.0:
        if film != 0.0:
            return film_x, film_y, 0.0, 0.0, nx, ny, delta, slip
        return 0.0, 0.0, 0.0, 0.0, nx, ny, delta, slip
    floor = p[P_FLOOR]
    approach = impact_velocity if impact_velocity > floor else floor
    normal = elastic * (1.0 + p[P_HYSTERESIS] * rate / approach)
    normal = max(normal, 0.0)
    tangential = 0.0
    if p[P_FRICTION] > 0.0 and normal > 0.0:
        speed = abs(slip)
        if speed > p[P_V0]:
            s = min((speed - p[P_V0]) / (p[P_V1] - p[P_V0]), 1.0)
            tangential = p[P_FRICTION] * s * s * (3.0 - 2.0 * s) * normal * math.copysign(1.0, slip)
    jx = normal * nx - tangential * ny
    jy = normal * ny + tangential * nx
    if film != 0.0:
        jx, jy = jx + film_x, jy + film_y
    return jx, jy, normal, tangential, nx, ny, delta, slip


@njit(**_FLAGS)
def spring(x3, p):
    """Mirror of :meth:`SliderCrankContactSystem.spring`."""
    if p[P_SPRING_PULL] != 0.0:
        return p[P_PRELOAD] + p[P_SPRING_STIFFNESS] * (p[P_CRANK] + p[P_ROD] - x3)
    return -(p[P_PRELOAD] + p[P_SPRING_STIFFNESS] * (x3 - (p[P_ROD] - p[P_CRANK])))


@_with_film
def evaluate(t, y, impact_velocity, p, wear):
    """Mirror of :meth:`SliderCrankContactSystem.evaluate`, as a tuple.

    Returns ``(theta'', x_3'', J_x, J_y, F_N, F_T, n_x, n_y, delta, v_T, T, e_x, e_y)``.
    """
    theta, x3, theta_dot, x3_dot = y[0], y[1], y[2], y[3]
    w = p[P_OMEGA]
    l1, l2 = p[P_CRANK], p[P_ROD]
    rod_mass, gravity = p[P_ROD_MASS], p[P_GRAVITY]
    phi = w * t
    cphi, sphi = math.cos(phi), math.sin(phi)
    bx, by = l1 * cphi, l1 * sphi
    abx, aby = -w * w * bx, -w * w * by
    ct, st = math.cos(theta), math.sin(theta)
    ex = bx + l2 * ct - x3
    ey = by + l2 * st
    vx = -w * by - l2 * st * theta_dot - x3_dot
    vy = w * bx + l2 * ct * theta_dot
    jx, jy, normal, tangential, nx, ny, delta, slip = point_force(
        ex, ey, vx, vy, theta_dot, impact_velocity, p, wear
    )
    half = 0.5 * l2
    theta_ddot = (
        -rod_mass * half * (-st * abx + ct * aby)
        - rod_mass * gravity * half * ct
        - l2 * (-st * jx + ct * jy)
        - p[P_ARM] * tangential
    ) / p[P_INERTIA_B]
    x3_ddot = (jx + spring(x3, p)) / p[P_SLIDER_MASS]
    agx = abx + half * (-st * theta_ddot - ct * theta_dot * theta_dot)
    agy = aby + half * (ct * theta_ddot - st * theta_dot * theta_dot)
    rbx = rod_mass * agx + jx
    rby = rod_mass * (agy + gravity) + jy
    torque = bx * rby - by * rbx + 0.5 * p[P_CRANK_MASS] * gravity * bx
    return (theta_ddot, x3_ddot, jx, jy, normal, tangential, nx, ny, delta, slip, torque, ex, ey)


@_with_film
def rhs(t, y, impact_velocity, p, wear):
    """Mirror of :meth:`SliderCrankContactSystem.rhs`."""
    out = evaluate(t, y, impact_velocity, p, wear)
    result = np.empty(5)
    result[0] = y[2]
    result[1] = y[3]
    result[2] = out[0]
    result[3] = out[1]
    result[4] = out[10] * p[P_OMEGA]
    return result


@njit(**_FLAGS)
def clearance_state(t, y, p):
    """Mirror of :meth:`SliderCrankContactSystem.clearance_state`."""
    theta, x3, theta_dot, x3_dot = y[0], y[1], y[2], y[3]
    w, l1, l2 = p[P_OMEGA], p[P_CRANK], p[P_ROD]
    phi = w * t
    cphi, sphi = math.cos(phi), math.sin(phi)
    ct, st = math.cos(theta), math.sin(theta)
    ex = l1 * cphi + l2 * ct - x3
    ey = l1 * sphi + l2 * st
    vx = -w * l1 * sphi - l2 * st * theta_dot - x3_dot
    vy = w * l1 * cphi + l2 * ct * theta_dot
    return ex, ey, vx, vy


@njit(**_FLAGS)
def gap(t, y, p, wear):
    """Mirror of the point laws' :meth:`JointContact.gap` at the state ``y``."""
    ex, ey, _, _ = clearance_state(t, y, p)
    return hypot(ex, ey) - clearance_at(ex, ey, p[P_CLEARANCE], wear)


@njit(**_FLAGS)
def gap_rate(t, y, p):
    """Mirror of :meth:`JointContact.gap_rate` at the state ``y``."""
    ex, ey, vx, vy = clearance_state(t, y, p)
    r = hypot(ex, ey)
    if r == 0.0:
        return 0.0
    return (ex * vx + ey * vy) / r


@njit(**_FLAGS)
def gap_and_rate(t, y, p, wear):
    """:func:`gap` and :func:`gap_rate` in one call."""
    ex, ey, vx, vy = clearance_state(t, y, p)
    r = hypot(ex, ey)
    rate = 0.0 if r == 0.0 else (ex * vx + ey * vy) / r
    return r - clearance_at(ex, ey, p[P_CLEARANCE], wear), rate
