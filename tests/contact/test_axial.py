"""Slices along the pin: the planar solve per slice, force and moment balance, tilt, bending."""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointwear.contact import ContactParameters, contact_law, solve, solve_contact
from jointwear.contact.axial import (
    AxialSlices,
    Misalignment,
    slice_law,
    solve_axial,
    spring_law_of,
)
from jointwear.contact.laws import PowerLaw
from jointwear.contact.pin_beam import (
    Cantilever,
    Clevis,
    PinBeam,
    compliance,
    linearised_joint,
)
from jointwear.errors import ConfigError, ContactError, GeometryError
from jointwear.geometry import BushingContour
from tests.conftest import scar

EPS = np.finfo(float).eps
SPRING_MODELS = ["winkler", "asymmetric-winkler", "nlcp"]
#: near-zero clearance: the Winkler force of a slice is k R (pi/2) s (small-clearance limit)
TIGHT = 1e-12
#: the pin's curvature adds s^2 sin^2(phi) / 2 R_p to the penetration: a relative force
#: change of (2 / 3 pi) s / R_p ~ 1.2e-4 at the 4 um approach of these tests
CURVATURE = 5e-4


def planar_offset(solution, azimuth: float) -> np.ndarray:
    """Pin displacement along the load of a planar solution [m]."""
    return solution.eccentricity[:, 0] * np.cos(azimuth) + solution.eccentricity[:, 1] * np.sin(
        azimuth
    )


def balance_floor(solution) -> float:
    """The planar balance's tolerance for the slices' springs [N]."""
    area = np.abs(solution.force).sum() + np.abs(solution.lateral_force).sum()
    return max(1e-12, 8 * EPS * 4 * area)


@pytest.fixture(scope="module")
def winkler_k(params: ContactParameters) -> float:
    """Foundation stiffness E_w / L of the paper's joint [Pa/m]."""
    return contact_law("asymmetric-winkler", params).coefficient


@pytest.fixture(scope="module")
def tight(params: ContactParameters):
    """A bushing with near-zero clearance, the asymmetric Winkler law and its pin."""
    contour = BushingContour.circle(params.pin_radius + TIGHT, 360, params.axial_length)
    return contour, contact_law("asymmetric-winkler", params)


# ---------------------------------------------------------------- one slice, equal slices


@pytest.mark.parametrize("model", SPRING_MODELS)
@pytest.mark.parametrize("azimuth", [0.0, 0.7, -2.9])
def test_one_slice_is_the_planar_solve(params, pin, circle, worn, model, azimuth):
    law = contact_law(model, params)
    slices = AxialSlices(params.axial_length, 1)
    contours = [circle] if model == "winkler" else [circle, worn]
    for contour in contours:
        planar = solve(contour, pin, [230.0], [azimuth], model, params)
        axial = solve_axial(slices.contours(contour), slices, pin, 230.0, azimuth, law)
        peak = planar.pressure.max()
        assert np.abs(axial.pressure[0] - planar.pressure[0]).max() <= 1e-12 * peak
        assert axial.offset[0] == pytest.approx(planar_offset(planar, azimuth)[0], rel=1e-12, abs=0)
        assert axial.tilt == 0.0
        assert abs(axial.force_residual) <= balance_floor(axial)


@pytest.mark.parametrize("model", SPRING_MODELS)
@pytest.mark.parametrize("count", [2, 7, 20])
def test_aligned_slices_share_the_load_with_the_planar_pressure(
    params, pin, circle, worn, model, count
):
    law = contact_law(model, params)
    slices = AxialSlices(params.axial_length, count)
    for contour in [circle] if model == "winkler" else [circle, worn]:
        planar = solve(contour, pin, [300.0], [0.4], model, params)
        # free tilt: the moment of equal slices vanishes at zero tilt by symmetry
        axial = solve_axial(slices.contours(contour), slices, pin, 300.0, 0.4, law)
        np.testing.assert_allclose(axial.force, 300.0 / count, rtol=1e-9)
        peak = planar.pressure.max()
        assert np.abs(axial.pressure - planar.pressure[0]).max() <= 1e-9 * peak
        assert abs(axial.tilt) * params.axial_length <= 1e-9 * axial.centre_offset
        assert abs(axial.force_residual) <= balance_floor(axial)


def test_nlcp_paper_form_shares_its_spring_area(params):
    law = contact_law("nlcp", params)
    assert law.force_area == params.spring_area
    assert slice_law(law, 0.25).force_area == pytest.approx(
        0.25 * params.spring_area, rel=1e-15, abs=0
    )
    assert slice_law(law, 0.25).coefficient == law.coefficient
    mesh_law = contact_law("asymmetric-winkler", params)
    assert slice_law(mesh_law, 0.25) is mesh_law  # the slice contour carries the width


def test_every_slice_is_the_planar_solve_of_its_force(params, pin):
    """Different contours along the pin (a scar deepening towards one end), a load off the
    mid-plane: each slice's state is the planar balance of its own force on its contour."""
    count = 8
    slices = AxialSlices(params.axial_length, count)
    depth = np.linspace(2e-6, 30e-6, count)
    wear = np.stack([scar(360, depth=d, centre_deg=15.0) for d in depth])
    contours = slices.worn_contours(params.bushing_radius, wear)
    law = contact_law("nlcp", params)
    axial = solve_axial(contours, slices, pin, 250.0, 0.1, law, load_offset=2e-3)
    assert axial.loaded.all()
    assert abs(axial.force_residual) <= balance_floor(axial)
    assert abs(axial.moment_reaction) <= max(1e-12 * params.axial_length, 8 * EPS * 250.0)
    for index, contour in enumerate(contours):
        alone = solve_contact(contour, pin, [axial.force[index]], [0.1], slice_law(law, 1 / count))
        assert planar_offset(alone, 0.1)[0] == pytest.approx(axial.offset[index], rel=1e-12, abs=0)
        peak = alone.pressure.max()
        assert np.abs(alone.pressure[0] - axial.pressure[index]).max() <= 1e-9 * peak


# ---------------------------------------------------------------- balance, tilt, separation


@pytest.mark.parametrize("offset", [-7e-3, -1e-3, 0.0, 2.5e-3, 6e-3])
@pytest.mark.parametrize("model", SPRING_MODELS)
def test_force_and_moment_balance_to_the_planar_tolerance(params, pin, circle, model, offset):
    law = contact_law(model, params)
    slices = AxialSlices(params.axial_length, 20)
    axial = solve_axial(slices.contours(circle), slices, pin, 180.0, 2.0, law, load_offset=offset)
    # independent resultants from the pressure
    area = circle.spring_area * (slices.width / circle.axial_length)
    if law.force_area is not None:
        area = np.full(circle.nodes, law.force_area / slices.count)
    if model == "winkler":  # the springs on the circle: here the same circle
        area = circle.radius * circle.dtheta * slices.width
    force = (axial.pressure * area) @ np.cos(circle.theta - 2.0)
    np.testing.assert_allclose(force, axial.force, rtol=1e-12, atol=1e-12)
    assert abs(force.sum() - 180.0) <= balance_floor(axial)
    moment_floor = max(1e-12 * params.axial_length / 2, 8 * EPS * np.abs(force).sum() * 0.01)
    assert abs(force @ slices.centres - 180.0 * offset) <= moment_floor
    assert np.sign(axial.tilt) == np.sign(offset)


def test_rigid_pin_imposed_tilt_on_a_winkler_foundation(params, pin, tight, winkler_k):
    """Near-zero clearance: every slice carries k R (pi/2) s_i h, s_i = delta_0 + gamma z_i,
    so the edge slices' forces (their first revolution's wear) are in the ratio of their
    offsets, which tends to (delta_0 + gamma L/2) / (delta_0 - gamma L/2)."""
    contour, law = tight
    length = params.axial_length
    gaps = []
    for count in (10, 40, 160):
        slices = AxialSlices(length, count)
        axial = solve_axial(
            slices.contours(contour), slices, pin, 200.0, 1.0, law,
            misalignment=Misalignment(2e-4, plane=1.0),
        )  # fmt: skip
        assert axial.tilt == pytest.approx(2e-4, rel=1e-15, abs=0)
        linear = winkler_k * params.pin_radius * (math.pi / 2) * axial.offset
        np.testing.assert_allclose(axial.line_load, linear, rtol=CURVATURE)
        np.testing.assert_allclose(axial.offset, axial.centre_offset + 2e-4 * slices.centres)
        edge = slices.centres[-1]
        ratio = (axial.centre_offset + 2e-4 * edge) / (axial.centre_offset - 2e-4 * edge)
        assert axial.force[-1] / axial.force[0] == pytest.approx(ratio, rel=CURVATURE)
        continuous = (axial.centre_offset + 1e-4 * length) / (axial.centre_offset - 1e-4 * length)
        gaps.append(continuous - axial.force[-1] / axial.force[0])
        # the supports carry the moment of the imposed tilt: k R (pi/2) gamma sum z_i^2 h
        moment = winkler_k * params.pin_radius * (math.pi / 2) * 2e-4 * length**3 / 12
        moment *= 1 - 1 / count**2
        assert axial.moment_reaction == pytest.approx(moment, rel=CURVATURE)
    # the edge slice's centre approaches the edge as h / 2: first order in 1 / N
    assert gaps[0] / gaps[1] == pytest.approx(4.0, rel=0.1)
    assert gaps[1] / gaps[2] == pytest.approx(4.0, rel=0.1)


@pytest.mark.parametrize("offset", [1e-3, 2e-3, 3e-3])
def test_load_offset_on_a_winkler_foundation(params, pin, tight, offset):
    """A rigid pin free to tilt under a load at z = a: (1 + 6a/L)/(1 - 6a/L) edge to edge;
    with N slices the edge centres are at +-(L/2)(1 - 1/N) and sum z_i^2 h = (L^3/12)(1 -
    1/N^2), so the ratio is (1 + q)/(1 - q), q = (6a/L) N/(N + 1)."""
    contour, law = tight
    length = params.axial_length
    continuous = (1 + 6 * offset / length) / (1 - 6 * offset / length)
    misses = []
    for count in (10, 40, 160):
        slices = AxialSlices(length, count)
        axial = solve_axial(
            slices.contours(contour), slices, pin, 200.0, -0.5, law, load_offset=offset
        )
        ratio = axial.force[-1] / axial.force[0]
        q = 6 * offset / length * count / (count + 1)
        # near the separation threshold (q -> 1) the ratio magnifies the slices' error
        assert ratio == pytest.approx((1 + q) / (1 - q), rel=CURVATURE / (1 - q))
        assert abs(axial.moment_reaction) <= 1e-12 * length
        misses.append(abs(ratio / continuous - 1))
    assert misses[0] > misses[1] > misses[2]


def test_separation_shortens_the_contact(params, pin, circle, clearance):
    """Beyond the separation threshold the end slices leave the bushing: fewer slices carry
    the load, with force and moment still balanced."""
    law = contact_law("asymmetric-winkler", params)
    slices = AxialSlices(params.axial_length, 40)
    contours = slices.contours(circle)
    counts = []
    for offset in (0.0, 2e-3, 4e-3, 6e-3, 7.5e-3):
        axial = solve_axial(contours, slices, pin, 200.0, 0.3, law, load_offset=offset)
        counts.append(int(axial.loaded.sum()))
        assert abs(axial.force_residual) <= balance_floor(axial)
        assert abs(axial.moment_reaction) <= 1e-12 * params.axial_length
        # unloaded slices are open (the pin clear of the wall), loaded ones pressed in
        assert np.all(axial.force >= 0)
        assert np.all(axial.offset[~axial.loaded] <= clearance)
        assert np.all(axial.penetration[~axial.loaded] == 0)
        # the contact is one stretch at the loaded end
        assert np.all(axial.loaded[np.argmax(axial.loaded) :])
    assert counts[0] == counts[1] == 40
    assert counts == sorted(counts, reverse=True)
    assert counts[-1] < counts[-2] < 40
    assert axial.contact_length == pytest.approx(counts[-1] * slices.width, rel=1e-12, abs=0)


def test_imposed_tilt_separates_and_the_supports_take_the_moment(params, pin, circle):
    law = contact_law("nlcp", params)
    slices = AxialSlices(params.axial_length, 20)
    contours = slices.contours(circle)
    loaded, reactions = [], []
    for angle in (0.0, 6e-4, 2e-3, 3e-3):
        axial = solve_axial(contours, slices, pin, 150.0, 0.0, law,
                            misalignment=Misalignment(angle, plane=0.0))  # fmt: skip
        loaded.append(int(axial.loaded.sum()))
        reactions.append(axial.moment_reaction)
        assert abs(axial.force_residual) <= balance_floor(axial)
    assert loaded[0] == 20
    assert loaded[-1] < loaded[-2] <= 20
    assert loaded == sorted(loaded, reverse=True)
    assert abs(reactions[0]) <= 1e-12 * params.axial_length
    assert 0 < reactions[1] < reactions[2] < reactions[3]


def test_a_pin_tilted_past_its_clearance_presses_the_opposite_wall(params, pin, circle):
    law = contact_law("asymmetric-winkler", params)
    slices = AxialSlices(params.axial_length, 20)
    clearance = params.bushing_radius - params.pin_radius
    angle = 3 * clearance / params.axial_length  # the ends move 1.5 clearances apart
    axial = solve_axial(slices.contours(circle), slices, pin, 100.0, 0.0, law,
                        misalignment=Misalignment(angle))  # fmt: skip
    assert axial.force[-1] > 0 > axial.force[0]
    assert abs(axial.force_residual) <= balance_floor(axial)


def test_convergence_in_slices(params, pin, circle):
    """The moment of an imposed tilt converges as 1/N^2 (midpoint rule of a smooth line
    load); the edge slice's line load as 1/N (its centre is h/2 from the edge)."""
    law = contact_law("asymmetric-winkler", params)
    moments, edges = [], []
    for count in (10, 20, 40, 80, 160):
        slices = AxialSlices(params.axial_length, count)
        axial = solve_axial(slices.contours(circle), slices, pin, 200.0, 0.0, law,
                            misalignment=Misalignment(1e-4))  # fmt: skip
        assert axial.loaded.all()
        moments.append(axial.moment)
        edges.append(axial.line_load[-1])
    moment_order = np.log2(np.abs(np.diff(moments))[:-1] / np.abs(np.diff(moments))[1:])
    edge_order = np.log2(np.abs(np.diff(edges))[:-1] / np.abs(np.diff(edges))[1:])
    np.testing.assert_allclose(moment_order, 2.0, atol=0.1)
    np.testing.assert_allclose(edge_order, 1.0, atol=0.05)


def test_misalignment_across_the_load(params, pin, circle):
    """A tilt in the plane perpendicular to the load: the slices' forces along the load are
    symmetric in z, their sideways forces antisymmetric (a load on a node: the mesh is
    symmetric about it); turning the plane by pi mirrors it."""
    law = contact_law("asymmetric-winkler", params)
    slices = AxialSlices(params.axial_length, 10)
    contours = slices.contours(circle)
    tilted = Misalignment(2e-3, plane=math.pi / 2)
    axial = solve_axial(contours, slices, pin, 200.0, 0.0, law, misalignment=tilted)
    assert abs(axial.tilt) < 1e-15
    assert axial.lateral_tilt == pytest.approx(2e-3, rel=1e-12, abs=0)
    np.testing.assert_allclose(axial.force, axial.force[::-1], rtol=1e-9)
    np.testing.assert_allclose(axial.lateral_force, -axial.lateral_force[::-1], rtol=1e-9)
    # the pin's end at +z leans counter-clockwise and presses the bushing that way
    assert axial.lateral_force[-1] > 0
    assert axial.lateral_moment > 0
    mirrored = Misalignment(2e-3, plane=-math.pi / 2)
    other = solve_axial(contours, slices, pin, 200.0, 0.0, law, misalignment=mirrored)
    np.testing.assert_allclose(other.lateral_force, -axial.lateral_force, rtol=1e-9)
    # the sideways offsets bring the pin's ends nearer the wall (its distance from the
    # centre is hypot(s, t)): less offset along the load carries the load
    aligned = solve_axial(contours, slices, pin, 200.0, 0.0, law)
    assert axial.centre_offset < aligned.centre_offset


def test_play_lets_the_pin_align_until_it_bears(params, pin, circle):
    law = contact_law("asymmetric-winkler", params)
    slices = AxialSlices(params.axial_length, 20)
    contours = slices.contours(circle)
    free = solve_axial(contours, slices, pin, 200.0, 0.0, law, load_offset=2e-3)
    wide = Misalignment(5e-4, plane=0.0, play=1e-3)  # the free tilt is within the play
    roomy = solve_axial(contours, slices, pin, 200.0, 0.0, law, load_offset=2e-3,
                        misalignment=wide)  # fmt: skip
    assert roomy.tilt == pytest.approx(free.tilt, rel=1e-12, abs=0)
    assert abs(roomy.moment_reaction) <= 1e-12 * params.axial_length
    narrow = Misalignment(5e-4, plane=0.0, play=1e-4)
    held = solve_axial(contours, slices, pin, 200.0, 0.0, law, load_offset=2e-3,
                       misalignment=narrow)  # fmt: skip
    assert free.tilt < 4e-4
    assert held.tilt == pytest.approx(4e-4, rel=1e-12, abs=0)  # imposed minus the play
    assert held.moment_reaction > 0  # the supports hold the pin back from aligning


def test_nested_brentq_agrees_with_the_hybrid_method(params, pin, worn):
    law = contact_law("asymmetric-winkler", params)
    slices = AxialSlices(params.axial_length, 12)
    contours = slices.contours(worn)
    for offset in (-3e-3, 0.5e-3, 6e-3):
        hybrid = solve_axial(contours, slices, pin, 220.0, 0.2, law, load_offset=offset)
        nested = solve_axial(contours, slices, pin, 220.0, 0.2, law, load_offset=offset,
                             method="nested")  # fmt: skip
        assert nested.tilt == pytest.approx(hybrid.tilt, rel=1e-9, abs=1e-15)
        np.testing.assert_allclose(nested.force, hybrid.force, rtol=1e-9, atol=1e-9)


def test_no_load_no_pressure(params, pin, circle):
    law = contact_law("asymmetric-winkler", params)
    slices = AxialSlices(params.axial_length, 5)
    axial = solve_axial(slices.contours(circle), slices, pin, 0.0, 1.0, law, load_offset=3e-3)
    assert not axial.pressure.any()
    assert not axial.force.any()
    assert axial.tilt == 0.0


# ---------------------------------------------------------------- the bent pin


def test_a_stiff_pin_is_the_rigid_pin(params, pin, circle):
    law = contact_law("asymmetric-winkler", params)
    slices = AxialSlices(params.axial_length, 16)
    contours = slices.contours(circle)
    rigid = solve_axial(contours, slices, pin, 400.0, 0.0, law, load_offset=1.5e-3)
    steel = PinBeam.solid(params.pin_radius, 209e9, 0.28)
    clevis = Clevis((-0.015, 0.015))
    for factor, tolerance in ((1.0, 1e-1), (1e4, 1e-4), (1e8, 1e-8)):
        stiff = PinBeam(steel.bending_stiffness * factor, steel.shear_stiffness * factor)
        bent = solve_axial(contours, slices, pin, 400.0, 0.0, law, load_offset=1.5e-3,
                           compliance=compliance(stiff, clevis, slices.centres))  # fmt: skip
        change = np.abs(bent.force - rigid.force).max() / rigid.force.max()
        assert change <= tolerance
        assert abs(bent.force_residual) <= balance_floor(bent)
        assert abs(bent.moment_reaction) <= 1e-12 * params.axial_length
    assert change > 1e-12  # the pin did bend


@pytest.mark.parametrize(
    "support", [Clevis((-0.016, 0.016)), Clevis((-0.012, 0.02)), Cantilever(-0.018)]
)
def test_the_bent_pin_on_a_winkler_foundation_is_the_linear_beam(params, pin, tight, support):
    """Near-zero clearance, a bushing 50 times stiffer than PTFE (the pin bends): the slices'
    balance with the pin's compliance is the linear beam on the foundation k R pi/2, loaded
    by its supports."""
    contour, law = tight
    law = PowerLaw(50 * law.coefficient, 1.0, name="asymmetric-winkler")
    slices = AxialSlices(params.axial_length, 24)
    beam = PinBeam.solid(params.pin_radius, 209e9, 0.28)
    axial = solve_axial(
        slices.contours(contour),
        slices,
        pin,
        2000.0,
        0.4,
        law,
        load_offset=1e-3,
        compliance=compliance(beam, support, slices.centres),
    )
    foundation = np.full(slices.count, law.coefficient * params.pin_radius * math.pi / 2)
    linear = linearised_joint(beam, support, slices.centres, slices.widths, foundation, 2000.0,
                              1e-3)  # fmt: skip
    np.testing.assert_allclose(axial.offset, linear, rtol=CURVATURE)
    assert np.abs(axial.deflection).max() > 0.1 * np.abs(axial.offset).max()  # it bends


def test_a_clevis_pin_bends_load_onto_the_bushing_ends(params, pin, circle):
    law = contact_law("asymmetric-winkler", params)
    law = PowerLaw(400 * law.coefficient, 1.0, name="stiff")  # a bronze-like wall
    slices = AxialSlices(params.axial_length, 20)
    beam = PinBeam.solid(params.pin_radius, 209e9, 0.28)
    clevis = Clevis((-0.015, 0.015))
    matrix = compliance(beam, clevis, slices.centres)
    rigid = solve_axial(slices.contours(circle), slices, pin, 3000.0, 0.0, law)
    bent = solve_axial(slices.contours(circle), slices, pin, 3000.0, 0.0, law, compliance=matrix)
    assert np.ptp(rigid.force) <= 1e-9 * rigid.force.max()
    assert bent.force[0] > bent.force[10]
    assert bent.force[-1] > bent.force[9]
    np.testing.assert_allclose(bent.force, bent.force[::-1], rtol=1e-9)
    # the pin sags between the forks: the bending is greatest at the middle
    assert np.argmin(bent.deflection) in (9, 10)
    np.testing.assert_allclose(bent.deflection, -matrix @ bent.force, rtol=1e-9, atol=1e-18)


@pytest.mark.parametrize("support", [Clevis((-0.015, 0.015)), Cantilever(-0.016)])
def test_the_linearised_foundation_is_the_derivative_of_the_balance(params, pin, circle, support):
    """The slices' stiffness per unit length (dF_i/ds_i / h) is the foundation of the
    linearised joint: the beam on it, loaded by its supports' reactions to a unit load,
    gives the derivative of the balanced pin's offsets with respect to the load."""
    law = contact_law("asymmetric-winkler", params)
    law = PowerLaw(50 * law.coefficient, 1.0, name="stiff")
    slices = AxialSlices(params.axial_length, 16)
    contours = slices.contours(circle)
    beam = PinBeam.solid(params.pin_radius, 209e9, 0.28)
    matrix = compliance(beam, support, slices.centres)
    load, step, offset = 2000.0, 1.0, 1e-3
    states = [
        solve_axial(contours, slices, pin, w, 0.2, law, load_offset=offset, compliance=matrix)
        for w in (load - step, load, load + step)
    ]
    derivative = (states[2].offset - states[0].offset) / (2 * step)
    foundation = states[1].foundation_stiffness
    linear = linearised_joint(beam, support, slices.centres, slices.widths, foundation, 1.0, offset)
    np.testing.assert_allclose(linear, derivative, rtol=1e-5)
    assert np.ptp(derivative) > 0.1 * np.abs(derivative).max()  # tilt and bending both count


def test_a_flexible_pin_far_out_of_balance(params, pin, circle):
    """A hard case: a cantilevered pin a tenth as stiff as steel, a wall 400 times NLCP's,
    11 kN near the bushing's end. The pin jams (its clamped end presses the opposite wall)
    and the middle slices open; the balance gets there by following the pin's flexibility
    up from the rigid pin's, and still meets force, moment and w = -C F."""
    law = contact_law("nlcp", params)
    law = PowerLaw(400 * law.coefficient, law.exponent, name="stiff", force_area=law.force_area)
    slices = AxialSlices(params.axial_length, 12)
    beam = PinBeam.solid(params.pin_radius, 0.1 * 209e9, 0.28)
    matrix = compliance(beam, Cantilever(-0.011), slices.centres)
    axial = solve_axial(slices.contours(circle), slices, pin, 11206.0, 0.3, law,
                        load_offset=8.64e-3, compliance=matrix)  # fmt: skip
    assert axial.force[0] < 0  # the opposite wall
    assert 0 < axial.loaded.sum() < 11
    assert abs(axial.force_residual) <= 1e-13 * 11206.0
    assert abs(axial.moment_reaction) <= 1e-13 * 11206.0 * params.axial_length
    np.testing.assert_allclose(axial.deflection, -matrix @ axial.force, rtol=1e-9, atol=1e-18)


def test_imposed_misalignment_with_a_bent_pin(params, pin, circle):
    law = contact_law("asymmetric-winkler", params)
    slices = AxialSlices(params.axial_length, 10)
    beam = PinBeam.solid(params.pin_radius, 209e9, 0.28)
    matrix = compliance(beam, Clevis((-0.015, 0.015)), slices.centres)
    axial = solve_axial(slices.contours(circle), slices, pin, 300.0, 0.0, law,
                        misalignment=Misalignment(3e-4), compliance=matrix)  # fmt: skip
    assert axial.tilt == pytest.approx(3e-4, rel=1e-15, abs=0)
    assert abs(axial.force_residual) <= balance_floor(axial)
    np.testing.assert_allclose(axial.deflection, -matrix @ axial.force, rtol=1e-9, atol=1e-18)


# ---------------------------------------------------------------- refusals


def test_refusals(params, pin, circle):
    law = contact_law("asymmetric-winkler", params)
    slices = AxialSlices(params.axial_length, 4)
    contours = slices.contours(circle)
    with pytest.raises(ContactError, match="contact.model: 'hertz'"):
        spring_law_of(contact_law("hertz", params))
    with pytest.raises(GeometryError, match="build them with AxialSlices.contours"):
        solve_axial([circle] * 4, slices, pin, 100.0, 0.0, law)
    with pytest.raises(GeometryError, match="4 contours for 3 slices"):
        solve_axial(contours, AxialSlices(params.axial_length, 3), pin, 100.0, 0.0, law)
    one = AxialSlices(params.axial_length, 1)
    with pytest.raises(ConfigError, match="joint.load_offset"):
        solve_axial(one.contours(circle), one, pin, 100.0, 0.0, law, load_offset=1e-3)
    with pytest.raises(ConfigError, match="joint.axial_slices"):
        AxialSlices(params.axial_length, 0)
    with pytest.raises(ConfigError, match="joint.misalignment"):
        Misalignment(-1e-3)
    with pytest.raises(ContactError, match="joint.misalignment"):
        solve_axial(contours, slices, pin, 100.0, 0.0, law, misalignment=Misalignment(2.0, 1.5))
    with pytest.raises(ContactError, match="through the bushing wall in slice 3"):
        solve_axial(contours, slices, pin, 5e4, 0.0, law, load_offset=8e-3, max_penetration=2.5e-3)
    with pytest.raises(GeometryError, match="compliance"):
        solve_axial(contours, slices, pin, 100.0, 0.0, law, compliance=np.eye(3))
    with pytest.raises(ContactError, match="load: must be >= 0"):
        solve_axial(contours, slices, pin, -1.0, 0.0, law)
