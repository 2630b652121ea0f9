"""FE reference: exact ring modes, mesh convergence, thin-layer limit, worn contours."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from jointwear.contact import ContactParameters, solve
from jointwear.contact.winkler import foundation_modulus
from jointwear.geometry import BushingContour, Pin
from jointwear.geometry.angles import wrap_angle
from jointwear.references.fem import FemModel, build_mesh
from jointwear.references.persson import PerssonProblem, annulus_compliance
from tests.conftest import scar

LOAD = 200.0


def test_ring_modes_match_exact_annulus(joint: ContactParameters) -> None:
    """A cos(k theta) pressure on the bore: FE radial displacement == Kolosov-Muskhelishvili."""
    r_b, wall = joint.bushing_radius, joint.bushing_thickness
    contour = BushingContour.circle(r_b, 360, joint.axial_length)
    mesh = build_mesh(contour, wall, 5e8, 0.38, 180, 6)
    for k in (0, 1, 2, 3, 6):
        shape = np.cos(k * mesh.theta)
        u_r = mesh.radial_displacement(shape * mesh.weight)
        fe = np.mean(u_r * shape) / np.mean(shape**2)
        exact = annulus_compliance([k], r_b, r_b + wall, 5e8, 0.38)[0]
        assert fe == pytest.approx(exact, rel=2e-3, abs=0), k


def _fe(joint: ContactParameters, pin: Pin, circumferential: int, radial: int):
    contour = BushingContour.circle(joint.bushing_radius, 2 * circumferential, joint.axial_length)
    model = FemModel(joint, circumferential=circumferential, radial=radial)
    return model.solve_one(contour, pin, LOAD, 0.0)


def test_mesh_convergence(
    joint: ContactParameters, joint_pin: Pin, exact_bushing: PerssonProblem
) -> None:
    """Refining around and through the wall: errors against the exact ring solution shrink."""
    exact = exact_bushing.solve(LOAD / joint.axial_length, 320)
    levels = [(45, 1), (90, 2), (180, 4)]
    states = [_fe(joint, joint_pin, nt, nr) for nt, nr in levels]
    peak = np.array([s.peak_pressure for s in states])
    error = np.abs(peak / exact.peak_pressure - 1.0)
    assert np.all(np.diff(error) < 0)
    order = np.log2(error[:-1] / error[1:])
    assert np.all(order > 1.5), order  # observed ~2.1 and ~2.5
    assert error[-1] < 5e-4
    # self-convergence (no exact solution needed): successive changes shrink
    changes = np.abs(np.diff(peak))
    assert changes[1] < 0.5 * changes[0]
    assert states[-1].approach == pytest.approx(exact.approach, rel=2e-4)
    # the edge is located to a fraction of the node spacing (360 / (2 nt) deg)
    for (nt, _), state in zip(levels, states, strict=True):
        spacing = 180.0 / nt
        assert abs(math.degrees(state.half_angle_left - exact.half_angle)) < 0.3 * spacing
        assert state.half_angle_left == pytest.approx(state.half_angle_right, abs=1e-9)


@pytest.mark.slow
def test_mesh_convergence_fine(
    joint: ContactParameters, joint_pin: Pin, exact_bushing: PerssonProblem
) -> None:
    exact = exact_bushing.solve(LOAD / joint.axial_length, 640)
    states = [_fe(joint, joint_pin, nt, nr) for nt, nr in [(180, 4), (360, 8), (720, 16)]]
    error = np.array([abs(s.peak_pressure / exact.peak_pressure - 1) for s in states])
    assert np.all(np.diff(error) < 0)
    assert error[-1] < 2e-5
    assert abs(math.degrees(states[-1].half_angle_left - exact.half_angle)) < 0.1


def test_default_mesh_matches_exact_bushing(
    joint: ContactParameters, joint_pin: Pin, exact_bushing: PerssonProblem
) -> None:
    """The default FE model agrees with the exact solution of the same problem."""
    contour = BushingContour.circle(joint.bushing_radius, 360, joint.axial_length)
    fe = solve(contour, joint_pin, [50.0, 400.0], [0.0, 0.0], "fem", joint)
    for i, load in enumerate((50.0, 400.0)):
        exact = exact_bushing.solve(load / joint.axial_length)
        assert fe.pressure[i].max() == pytest.approx(exact.peak_pressure, rel=1e-3)
        assert fe.penetration[i] == pytest.approx(exact.approach, rel=1e-3)
        assert math.degrees(fe.half_angle_left[i]) == pytest.approx(
            math.degrees(exact.half_angle), abs=0.25
        )
        assert fe.normal_force[i] == pytest.approx(load, rel=1e-9)


def test_thin_layer_is_constrained_winkler(joint: ContactParameters, joint_pin: Pin) -> None:
    """L/R_b = 0.013, contact arc ~80 wall thicknesses wide: Winkler with the constrained
    modulus E(1-nu)/((1+nu)(1-2nu)) is exact; Winkler with E is off by 1.87."""
    wall = 0.1e-3
    params = ContactParameters(
        joint.pin_radius,
        joint.bushing_radius,
        joint.axial_length,
        wall,
        joint.pin_youngs_modulus,
        joint.pin_poisson_ratio,
        joint.bushing_youngs_modulus,
        joint.bushing_poisson_ratio,
        foundation_modulus="constrained",
    )
    contour = BushingContour.circle(joint.bushing_radius, 720, joint.axial_length)
    load = [20000.0]
    fe = FemModel(params, circumferential=360, radial=3, grading=1.0).solve(
        contour, joint_pin, load, [0.0]
    )
    constrained = solve(contour, joint_pin, load, [0.0], "winkler", params)
    alpha = fe.half_angle_left[0]
    assert alpha * joint.bushing_radius > 50 * wall
    phi = wrap_angle(contour.theta)
    inner = np.abs(phi) < 0.7 * alpha
    ratio = fe.pressure[0, inner] / constrained.pressure[0, inner]
    assert np.all(np.abs(ratio - 1.0) < 0.01), (ratio.min(), ratio.max())
    assert fe.penetration[0] == pytest.approx(constrained.penetration[0], rel=0.01)
    assert math.degrees(alpha) == pytest.approx(
        math.degrees(constrained.half_angle_left[0]), abs=0.5
    )
    # the FE pressure per unit local penetration is E_c / L, not E / L (1.87x higher)
    delta = contour.penetration(joint_pin, fe.eccentricity[0])
    stiffness = fe.pressure[0, inner] / delta[inner]
    e, nu = joint.bushing_youngs_modulus, joint.bushing_poisson_ratio
    constrained_modulus = foundation_modulus(e, nu, "constrained")
    np.testing.assert_allclose(stiffness, constrained_modulus / wall, rtol=0.01)
    assert np.all(stiffness / (e / wall) > 1.85)
    assert constrained_modulus / e == pytest.approx(1.872, abs=1e-3)
    # and Winkler with E, loaded the same, misses the approach and the peak
    youngs = solve(
        contour, joint_pin, load, [0.0], "winkler", replace(params, foundation_modulus="youngs")
    )
    assert youngs.penetration[0] > 1.3 * fe.penetration[0]
    assert youngs.pressure[0].max() < 0.9 * fe.pressure[0].max()


def test_worn_contour_and_equilibrium(joint: ContactParameters, joint_pin: Pin) -> None:
    worn = BushingContour.from_wear_profile(joint.bushing_radius, scar(360), joint.axial_length)
    model = FemModel(joint, circumferential=90, radial=3)
    paper = model.solve(worn, joint_pin, [LOAD], [0.0])
    assert paper.normal_force[0] == pytest.approx(LOAD, rel=1e-9)
    assert abs(paper.tangential_force[0]) > 1.0  # the scar pushes the pin sideways
    full = model.solve(worn, joint_pin, [LOAD], [0.0], balance="equilibrium")
    assert full.normal_force[0] == pytest.approx(LOAD, rel=1e-6)
    assert abs(full.tangential_force[0]) < 1e-6 * LOAD
    # the worn side carries less near the scar centre (20 deg)
    assert full.pressure[0, 20] < full.pressure[0, 340]
