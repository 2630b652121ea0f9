"""The finite-length bearing against Raimondi and Boyd's published tables.

Raimondi and Boyd, "A solution for the finite journal bearing and its application to
analysis and design", ASLE Trans. 1 (1958): the full (360 deg) journal bearing under a
steady load, Reynolds' (Swift--Stieber) condition where the film ends, the film
beginning at the largest thickness. The rows below (h0/c = 1 - eps, Sommerfeld number
S, attitude angle phi in degrees) are their table as reproduced with Shigley's
*Mechanical Engineering Design* (ch. 12, figs. 12-16 to 12-24) and transcribed in the
public repository Piter-T-UC/MecaPy, file mecapy/mecapy/bearings/lubrication_data.py
(``RAIMONDI_BOYD``). The L/D = 1 rows at eps = 0.2, 0.4, 0.6, 0.8 (S and phi) agree
digit for digit with a second, independent transcription (a rotordynamics code's
validation test, ``tests/rotordin-validacao.js``), and the L/D = 1 Sommerfeld numbers
of all rows with a third (MathWorks Answers 707318, "design of journal bearing").
"""

from __future__ import annotations

import numpy as np
import pytest

from jointwear.errors import JointwearError
from jointwear.lubrication import reynolds
from jointwear.lubrication.mobility import dimensionless_finite
from jointwear.lubrication.orbit import OrbitSolver, periodic_orbit
from jointwear.lubrication.reynolds import complementary_pressure, reynolds_forces, steady_journal

#: L/D -> rows (h0/c, S, phi [deg]) of Raimondi and Boyd's full journal bearing
RAIMONDI_BOYD = {
    1.0: [
        (0.9, 1.33, 79.5),
        (0.8, 0.631, 74.02),
        (0.6, 0.264, 63.10),
        (0.4, 0.121, 50.58),
        (0.2, 0.0446, 36.24),
        (0.1, 0.0188, 26.45),
    ],
    0.5: [
        (0.9, 4.31, 81.62),
        (0.8, 2.03, 74.94),
        (0.6, 0.779, 61.45),
        (0.4, 0.319, 48.14),
        (0.2, 0.0923, 33.31),
        (0.1, 0.0313, 23.66),
    ],
    0.25: [
        (0.9, 16.2, 82.31),
        (0.8, 7.57, 75.18),
        (0.6, 2.83, 60.86),
        (0.4, 1.07, 46.72),
        (0.2, 0.261, 31.04),
        (0.1, 0.0736, 21.85),
    ],
}
ROWS = [(ratio, *row) for ratio, rows in RAIMONDI_BOYD.items() for row in rows]


@pytest.mark.parametrize(("ratio", "gap", "sommerfeld", "attitude"), ROWS)
def test_reynolds_condition_reproduces_raimondi_and_boyd(ratio, gap, sommerfeld, attitude):
    # like with like: Reynolds' condition, the film beginning at the largest thickness
    journal = steady_journal(1.0 - gap, ratio, "Reynolds", film_start=True)
    assert journal.sommerfeld_number == pytest.approx(sommerfeld, rel=0.02)
    assert np.degrees(journal.attitude_angle) == pytest.approx(attitude, rel=0.015)


@pytest.mark.parametrize(("ratio", "gap", "sommerfeld", "attitude"), ROWS)
def test_a_film_without_a_supply_line_carries_the_same_load(ratio, gap, sommerfeld, attitude):
    # the film then begins a little before the largest thickness: the load is the same
    # within 2.5 %, the line of centres turns by up to 4.5 deg at light loads (L/D = 1)
    journal = steady_journal(1.0 - gap, ratio, "Reynolds")
    assert journal.sommerfeld_number == pytest.approx(sommerfeld, rel=0.025)
    assert abs(np.degrees(journal.attitude_angle) - attitude) < 4.5


def test_half_sommerfeld_overstates_the_sommerfeld_number_at_the_same_eccentricity():
    # the positive part of the full film carries less than Reynolds' film: 5-21 % at
    # L/D = 1, less for shorter bearings (docs/validation.md)
    excess = [
        steady_journal(1.0 - gap, 1.0).sommerfeld_number / sommerfeld - 1.0
        for gap, sommerfeld, _ in RAIMONDI_BOYD[1.0]
    ]
    assert min(excess) > 0.04
    assert max(excess) < 0.22
    assert np.all(np.diff(excess) > 0)  # grows with the eccentricity


def test_the_grid_is_converged_for_the_reynolds_condition(monkeypatch):
    coarse = [steady_journal(eps, 1.0, "Reynolds", True) for eps in (0.6, 0.9)]
    monkeypatch.setattr(reynolds, "ANGLE_NODES", 240)
    monkeypatch.setattr(reynolds, "AXIAL_CELLS", 32)
    fine = [steady_journal(eps, 1.0, "Reynolds", True) for eps in (0.6, 0.9)]
    for a, b in zip(coarse, fine, strict=True):
        assert a.sommerfeld_number == pytest.approx(b.sommerfeld_number, rel=1e-3)
        assert a.attitude_angle == pytest.approx(b.attitude_angle, abs=2e-4)


def test_the_complementarity_conditions_hold():
    theta, stretch, operator = reynolds.film_system(0.7, 0.5)
    source = np.tile(stretch * np.sin(theta - 0.4), reynolds.AXIAL_CELLS)
    pressure = complementary_pressure(operator, source)
    residual = -operator @ pressure - source
    scale = np.abs(source).max()
    assert pressure.min() >= 0.0
    assert residual.min() > -1e-9 * scale  # no film pulls
    assert np.abs(pressure * residual).max() < 1e-9 * scale * pressure.max()
    assert 0.2 < np.mean(pressure > 0) < 0.8  # a film and a cavity


def test_without_cavitation_the_film_is_the_full_film():
    # a source that is positive everywhere: the film never ruptures
    theta, stretch, operator = reynolds.film_system(0.3, 1.0)
    source = np.tile(stretch * (1.5 + np.sin(theta)), reynolds.AXIAL_CELLS)
    full = np.linalg.solve(-operator.toarray(), source)
    assert full.min() > 0
    np.testing.assert_allclose(complementary_pressure(operator, source), full, rtol=1e-10)


def test_an_unknown_cavitation_is_refused():
    with pytest.raises(JointwearError, match="cavitation"):
        steady_journal(0.5, 1.0, "Gumbel")  # type: ignore[arg-type]


def test_the_reynolds_table_matches_direct_solutions():
    # the force factor the orbit reads, interpolated, against the solver at random states
    rng = np.random.default_rng(1)
    eps, beta = rng.uniform(0, 0.99, 40), rng.uniform(-np.pi, np.pi, 40)
    table = dimensionless_finite(eps, beta, np.full(40, 1.0), "Reynolds")
    direct = np.array(
        [reynolds_forces(e, 1.0, [b])[:, 0] for e, b in zip(eps, beta, strict=True)]
    ).T
    assert np.max(np.abs(table - direct) / np.hypot(*direct)) < 2e-3


def test_a_steady_load_settles_where_the_reynolds_film_carries_it():
    # the orbit (mobility method, squeeze and wedge) of a turning journal under a fixed
    # load ends at the steady solution: S = mu N L D (R/c)^2 / W at eps = 0.6, L/D = 1
    radius, clearance, viscosity, speed = 0.01, 20e-6, 0.05, 100.0
    steady = steady_journal(0.6, 1.0, "Reynolds")
    length = 2 * radius
    load = (
        viscosity * speed / (2 * np.pi) * length * 2 * radius * (radius / clearance) ** 2
    ) / steady.sommerfeld_number
    solver = OrbitSolver(radius, length, clearance, viscosity, 1e-9, 200e9, "finite-reynolds")
    steps, period = 4, 0.01
    orbit = periodic_orbit(
        solver,
        np.arange(steps) * period / steps,
        period,
        np.zeros(steps),
        np.full(steps, -load),  # pressing downwards
        np.full(steps, 0.5 * speed),
        start=[0.2, -0.2],
    )
    attitude = np.arctan2(orbit.eccentricity_x, -orbit.eccentricity_y)
    np.testing.assert_allclose(orbit.eccentricity_ratio, 0.6, rtol=2e-3)
    np.testing.assert_allclose(attitude, steady.attitude_angle, rtol=2e-3)
