"""The film's force close to the wall, beyond the force tables' end (eps > 0.995).

Near the wall the film's pressure gathers within ``sqrt(1 - eps)`` of the smallest gap:
the long bearing's wedge force grows like ``(1 - eps^2)^-1`` (radial) and
``(1 - eps^2)^-1/2`` (tangential), its squeeze force like ``(1 - eps^2)^-3/2``, and a
finite bearing follows it where the gap is small against its length. The tables of
the orbit (long and finite bearing) and of the finite bearing's force must follow
these, not the short bearing's ``(1 - eps^2)^-5/2``.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointwear.lubrication.film import long_bearing_force
from jointwear.lubrication.mobility import TABLE_EDGE, dimensionless_force
from jointwear.lubrication.orbit import film_shape, table_shape_scalar

WALL = (0.99, 0.999, 0.9999)


def sommerfeld_wedge(eps: float) -> tuple[float, float]:
    """Half-Sommerfeld steady rotation, ``G`` at ``m = eps omega_bar = 1`` (L/D = 1).

    ``F_r = -12 mu U R^2 L eps^2 / (c^2 (2 + eps^2)(1 - eps^2))``,
    ``F_t = 6 pi mu U R^2 L eps / (c^2 (2 + eps^2) sqrt(1 - eps^2))``, with
    ``F = 6 mu R^2 (R/c)^2 m G``, ``R = c = 1``, ``L = 2``, ``mu = 1/6``, ``U = 1/eps``.
    """
    return (
        -4.0 * eps / ((2.0 + eps * eps) * (1.0 - eps * eps)),
        2.0 * math.pi / ((2.0 + eps * eps) * math.sqrt(1.0 - eps * eps)),
    )


def sommerfeld_squeeze(eps: float) -> float:
    """Long bearing moving straight at the wall, half-Sommerfeld: radial ``G`` at ``m = 1``.

    The pressure ``(deps/dt / eps)(1/H^2 - K)``, ``K = 2/(2 + 3 eps^2)``, is positive
    where ``cos theta < (1/sqrt K - 1)/eps``; integrated in closed form there
    (``int cos theta / H^2 = (sin gamma - eps gamma)/(1 - eps^2)^1.5``, ``gamma`` the
    Sommerfeld angle), with ``m = 2 deps/dt``, ``L = 2``.
    """
    k = 2.0 / (2.0 + 3.0 * eps * eps)
    edge = math.acos((1.0 / math.sqrt(k) - 1.0) / eps)
    root = math.sqrt(1.0 - eps * eps)
    gamma = math.acos((eps + math.cos(edge)) / (1.0 + eps * math.cos(edge)))

    def antiderivative(theta: float, g: float) -> float:
        return (math.sin(g) - eps * g) / root**3 - k * math.sin(theta)

    # from edge to 2 pi - edge, gamma from gamma to 2 pi - gamma
    integral = antiderivative(2.0 * math.pi - edge, 2.0 * math.pi - gamma) - antiderivative(
        edge, gamma
    )
    return 2.0 * (0.5 / eps) * integral


@pytest.mark.parametrize("eps", WALL)
def test_the_long_bearings_closed_form_is_the_reference(eps):
    rotation = long_bearing_force(1.0, 2.0, 1.0, 1.0 / 6.0, eps, 0.0, 1.0 / eps)
    squeeze = long_bearing_force(1.0, 2.0, 1.0, 1.0 / 6.0, eps, 0.5, 0.0)
    assert (rotation.radial, rotation.tangential) == pytest.approx(sommerfeld_wedge(eps), rel=1e-7)
    assert squeeze.radial == pytest.approx(sommerfeld_squeeze(eps), rel=1e-7)
    assert abs(squeeze.tangential) < 1e-9 * abs(squeeze.radial)


@pytest.mark.parametrize("eps", WALL)
def test_the_orbits_long_bearing_is_sommerfelds_close_to_the_wall(eps):
    """Wedge, squeeze along the line of centres, and the two together, within 1 %."""
    shape, scalar = film_shape("long", 1.0), table_shape_scalar("long", 1.0)
    wedge = shape(eps, np.array([0.0]))[:, 0]
    assert wedge == pytest.approx(sommerfeld_wedge(eps), rel=0.01)
    squeeze = shape(eps, np.array([0.5 * np.pi]))[:, 0]
    assert squeeze[0] == pytest.approx(sommerfeld_squeeze(eps), rel=0.01)
    assert abs(squeeze[1]) < 1e-3 * abs(squeeze[0])
    # wedge and squeeze together, approaching the wall (direction within the film's
    # inner scale sqrt(1 - eps) of the wedge, and beyond)
    betas = np.array([0.3, 1.0, 2.0, -3.0]) * math.sqrt(1.0 - eps)
    betas = np.concatenate([betas, [0.4, 1.2, 2.5]])
    exact = dimensionless_force("long", np.full_like(betas, eps), betas, np.array(1.0))
    table = shape(eps, betas)
    size = np.hypot(*exact)
    assert np.max(np.abs(table - exact) / size) < 0.01
    for beta, value in zip(betas, table.T, strict=True):
        assert scalar(eps, float(beta)) == pytest.approx(tuple(value), rel=1e-12, abs=1e-12)


def test_the_growth_exponents_near_the_wall():
    """From 1 - eps = 1e-4 to 1e-5: wedge -1 and -1/2, squeeze -3/2 in (1 - eps^2)."""
    shape = film_shape("long", 1.0)
    near, nearer = 1.0 - 1e-4, 1.0 - 1e-5
    ratio = (1.0 - nearer**2) / (1.0 - near**2)

    def exponent(beta: float, component: int) -> float:
        values = [abs(shape(e, np.array([beta]))[component, 0]) for e in (near, nearer)]
        return math.log(values[1] / values[0]) / math.log(ratio)

    assert exponent(0.0, 0) == pytest.approx(-1.0, abs=0.01)
    assert exponent(0.0, 1) == pytest.approx(-0.5, abs=0.01)
    assert exponent(0.5 * math.pi, 0) == pytest.approx(-1.5, abs=0.01)


@pytest.mark.parametrize("eps", [0.999, 0.9999])
def test_a_long_finite_bearing_near_the_wall_is_the_long_bearing(eps):
    """L/D = 4: within a few per cent of Sommerfeld, closer the closer the wall."""
    betas = np.array([0.0, 0.5 * np.pi, 0.02, 1.0])
    eps_ = np.full_like(betas, eps)
    finite = dimensionless_force("finite", eps_, betas, np.array(4.0))
    long = dimensionless_force("long", eps_, betas, np.array(4.0))
    gap = np.abs(finite - long) / np.hypot(*long)
    assert np.max(gap) < (0.02 if eps == 0.999 else 0.01)


def test_a_finite_bearing_goes_from_ocvirk_to_sommerfeld_as_the_gap_closes():
    """L/D = 0.02: Ocvirk's at eps = 0.99, where the film's width ``sqrt(1 - eps) R`` is
    not small against L; towards the long bearing once it is (1 - eps = 1e-5, where
    the axial ends still take some 20 %)."""
    ratio = np.array(0.02)
    wedge = np.array([0.0])

    def gap_to(model: str, eps: float) -> float:
        finite = dimensionless_force("finite", np.array([eps]), wedge, ratio)[:, 0]
        other = dimensionless_force(model, np.array([eps]), wedge, ratio)[:, 0]
        return float(np.hypot(*(finite - other)) / np.hypot(*other))

    assert gap_to("short", 0.99) < 0.05
    assert gap_to("long", 0.99) > 0.9
    assert gap_to("long", 1.0 - 1e-5) < 0.25
    assert gap_to("short", 1.0 - 1e-5) > 0.9
    # in between, the further from Ocvirk the closer to the wall
    gaps = [gap_to("short", eps) for eps in (0.99, 0.999, 0.9999, 1.0 - 1e-5)]
    assert np.all(np.diff(gaps) > 0.0)


@pytest.mark.parametrize("model", ["long", "finite"])
def test_continuous_across_the_tables_end(model):
    """Across eps = 0.995 the pure wedge and the pure squeeze move by < 0.2 %."""
    shape = film_shape(model, 1.0)
    betas = np.array([0.0, 0.5 * np.pi, np.pi])
    below, above = shape(TABLE_EDGE, betas), shape(np.nextafter(TABLE_EDGE, 1.0), betas)
    assert np.max(np.abs(above - below) / np.hypot(*below)) < 2e-3


def test_the_finite_force_is_the_orbits_near_the_wall():
    """The finite bearing's force (mobility) and the orbit's spline of it agree."""
    rng = np.random.default_rng(2)
    eps = 1.0 - 10.0 ** -rng.uniform(2.3, 5.5, 50)
    betas = rng.uniform(-0.5, 0.5 * np.pi, 50)
    force = dimensionless_force("finite", eps, betas, np.array(1.0))
    spline = film_shape("finite", 1.0)(eps, betas)
    assert np.max(np.abs(spline - force) / np.hypot(*force)) < 5e-3
