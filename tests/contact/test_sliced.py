"""Whole runs along the pin (``joint.axial_slices > 1``) against closed forms and the
planar joint."""

from __future__ import annotations

import numpy as np
import pytest

import jointwear as jw
from jointwear.contact import ContactParameters, contact_law
from jointwear.contact.axial import AxialSlices
from jointwear.contact.sliced import SlicedSolver, solver_of
from jointwear.contact.solver import ContactSolver, WarmStart


def swing(**extra):
    """A pin swinging under a fixed 200 N load in the bushing (one worn spot, under the
    load line): 8 steps, 72 nodes, the paper's joint."""
    overrides = {
        "mechanism": {
            "type": "oscillating",
            "load": "200 N",
            "load_angle": "-90 deg",
            "amplitude": "25 deg",
            "frequency": "1 Hz",
        },
        "contact.model": "asymmetric-winkler",
        "contact.nodes": 72,
        "contact.spring_area": None,
        "simulation.steps_per_revolution": 8,
        "simulation.revolutions": 1,
        "simulation.update_contour": True,
        **extra,
    }
    return jw.load_config(overrides=overrides)


def winkler_offset(config) -> float:
    """The mid-plane approach of a pin on a linear foundation without clearance,
    ``delta_0 = W / (k R (pi/2) L)`` [m], ``k`` the law's pressure per penetration."""
    parameters = ContactParameters.from_sections(config.joint, config.materials, config.contact)
    law = contact_law(config.contact.model, parameters)
    stiffness = float(law.pressure(np.array([1e-9]))[0] / 1e-9)
    joint = config.joint
    return 200.0 / (stiffness * joint.bushing_radius * joint.axial_length * np.pi / 2)


def edge_ratio(result) -> float:
    """Peak wear of the last slice over the first's."""
    peaks = result.wear_depth.max(axis=1)
    return float(peaks[-1] / peaks[0])


def test_one_slice_is_the_planar_solver():
    config = swing()
    assert type(solver_of(config, "asymmetric-winkler", fused_archard=True)) is ContactSolver
    sliced = solver_of(
        config.replace({"joint.axial_slices": 3}), "asymmetric-winkler", fused_archard=True
    )
    assert isinstance(sliced, SlicedSolver)


@pytest.mark.parametrize(
    ("update_every", "compiled"), [(1, None), ("adaptive", None), ("adaptive", False)]
)
def test_aligned_slices_wear_as_the_planar_joint(update_every, compiled):
    # an aligned rigid pin loads every slice with W/N and the planar pressure: the whole
    # run's wear, each saved profile and the worn volume are the planar joint's, by the
    # compiled balance (None: where it serves) and by solve_axial alone (False)
    extra = {"simulation.revolutions": 100, "simulation.update_every": update_every}
    planar = jw.Simulation(swing(**extra)).run()
    simulation = jw.Simulation(swing(**extra, **{"joint.axial_slices": 4}))
    simulation.solver.planar.compiled = compiled
    sliced = simulation.run()
    reference = planar.dataset["wear_depth"].values
    maps = sliced.dataset["wear_depth"].values
    assert maps.shape == (reference.shape[0], 4, 72)
    scale = reference.max()
    assert scale > 0
    assert np.abs(maps - reference[:, None, :]).max() <= 1e-9 * scale
    for key in ("peak_wear_depth_m", "wear_volume_m3", "wear_width_deg"):
        assert sliced.summary()[key] == pytest.approx(planar.summary()[key], rel=1e-9, abs=0)
    assert sliced.summary()["edge_to_mid_wear_ratio"] == pytest.approx(1.0, rel=1e-9)
    # slices worn alike: the deepest is said to be the one nearest the mid-plane
    assert abs(sliced.summary()["peak_wear_z_m"]) == pytest.approx(0.25 * 0.02 / 2)


#: a linear foundation without clearance spreads the contact to the quarter circle
QUARTER_CIRCLE = pytest.mark.filterwarnings(
    "ignore:contact.model:jointwear.errors.ContactModelWarning"
)


@QUARTER_CIRCLE
def test_imposed_tilt_on_a_winkler_foundation_wears_the_edges_in_proportion():
    # rigid pin, tilt gamma imposed in the load plane, linear foundation, clearance ~0:
    # every slice's line load is k R (pi/2) (delta_0 + gamma z), and so is the wear
    # under the load line; edge to edge (delta_0 + gamma L/2) / (delta_0 - gamma L/2)
    count, tilt = 80, 4e-5
    config = swing(
        **{"joint.clearance": "1e-9 m", "joint.axial_slices": count, "joint.misalignment": tilt}
    )
    centre, edge = winkler_offset(config), 0.5 * config.joint.axial_length
    measured = edge_ratio(jw.Simulation(config).run())
    continuous = (centre + tilt * edge) / (centre - tilt * edge)
    assert measured == pytest.approx(continuous, rel=1e-2)
    # at the edge slices' centres the closed form holds to the pin's curvature
    z = AxialSlices(config.joint.axial_length, count).centres[-1]
    assert measured == pytest.approx((centre + tilt * z) / (centre - tilt * z), rel=1e-3)


@QUARTER_CIRCLE
def test_a_load_off_the_mid_plane_wears_the_ends_as_a_rigid_pin_on_a_foundation():
    # a self-aligning pin under a load at z = a on a linear foundation: the line load is
    # linear in z with the load's moment, ends in the ratio (1 + 6a/L) / (1 - 6a/L)
    count, offset = 40, 0.5e-3
    config = swing(
        **{"joint.clearance": "1e-9 m", "joint.axial_slices": count, "joint.load_offset": offset}
    )
    length = config.joint.axial_length
    measured = edge_ratio(jw.Simulation(config).run())
    q = 6 * offset / length
    assert measured == pytest.approx((1 + q) / (1 - q), rel=1e-2)
    # the midpoint rule's moment of inertia of the slices: q N / (N + 1) at their centres
    q_slices = q * count / (count + 1)
    assert measured == pytest.approx((1 + q_slices) / (1 - q_slices), rel=1e-3)


def test_a_misaligned_joint_wears_out_at_an_edge_and_sooner():
    extra = {
        "joint.axial_slices": 5,
        "simulation.revolutions": 10**6,
        "simulation.update_every": "adaptive",
        "life.peak_wear_depth": "5 um",
    }
    aligned = jw.Simulation(swing(**extra)).run().summary()
    misaligned_run = jw.Simulation(swing(**extra, **{"joint.misalignment": 1e-3})).run()
    misaligned = misaligned_run.summary()
    assert aligned["stopped_by"] == misaligned["stopped_by"] == "peak_wear_depth"
    assert misaligned["life_revolutions"] < aligned["life_revolutions"]
    centres = AxialSlices(0.02, 5).centres
    assert misaligned["peak_wear_z_m"] in (centres[0], centres[-1])
    assert misaligned["edge_to_mid_wear_ratio"] > 1.0
    deepest = np.unravel_index(np.argmax(misaligned_run.wear_depth), (5, 72))[0]
    assert deepest in (0, 4)


def test_a_bending_pin_in_a_clevis_loads_both_edges_more_than_the_middle():
    # a stiff (bronze-like) wall under a long pin held at its ends: the pin bows away
    # from the middle of the bushing, whose ends then carry more
    config = swing(
        **{
            "joint.axial_slices": 9,
            "materials.bushing.youngs_modulus": "110 GPa",
            "pin": {"model": "beam", "support": "clevis", "forks": ["-15 mm", "15 mm"]},
            "mechanism.load": "5 kN",
        }
    )
    result = jw.Simulation(config).run()
    peaks = result.wear_depth.max(axis=1)
    assert peaks[0] > peaks[4]
    assert peaks[-1] > peaks[4]
    assert peaks[0] == pytest.approx(peaks[-1], rel=1e-6)  # symmetric supports
    assert result.summary()["edge_to_mid_wear_ratio"] > 1.0


MESH_FREE = {"contact.model": "nlcp", "contact.nlcp_variant": "mesh-independent"}


@pytest.mark.parametrize(
    "extra",
    [
        {"joint.misalignment": 2e-4},
        {"joint.load_offset": 2e-3},
        {"joint.misalignment": 2e-4, "joint.misalignment_angle": "30 deg"},
        MESH_FREE,
        {**MESH_FREE, "contact.exponent": 1.3},
    ],
)
def test_the_compiled_balance_is_the_axial_balance(extra):
    # warm-started from a perturbed balance, on slices worn differently: the compiled
    # balance of every step gives solve_axial's pressure, forces and Archard's wear
    config = jw.load_config(
        overrides={
            "simulation.steps_per_revolution": 30,
            "contact.nodes": 90,
            "contact.spring_area": None,
            "simulation.update_contour": True,
            "joint.axial_slices": 7,
            **extra,
        }
    )
    simulation = jw.Simulation(config)
    solver, cycle, sliding = simulation.solver, simulation.load_cycle, simulation.sliding_distance
    theta = solver.initial_contour().theta
    depth = np.linspace(0.5, 2.0, 7)[:, None] * 2e-6 * np.cos(theta - 1.0).clip(0)
    contour = solver.contour(depth)
    solver.planar.compiled = False
    reference = solver.solve(contour, cycle)
    solver.planar.compiled = None
    start = solver.warm_start(reference, contour, cycle.azimuth)
    warm = WarmStart(np.asarray(start.warm_offset) * (1 + 1e-3), None, None)
    peak = reference.slice_pressure.max()
    for compiled in (solver.solve(contour, cycle, warm=warm), solver.solve(contour, cycle)):
        # (warm, and cold: each load from the last one's approach)
        assert np.abs(compiled.slice_pressure - reference.slice_pressure).max() <= 1e-12 * peak
        assert np.abs(compiled.slice_force - reference.slice_force).max() <= 1e-10
    fused = solver.solve(contour, cycle, warm=warm, sliding=sliding)
    assert fused.slice_pressure is None
    wear = solver.wear_per_revolution(fused, simulation.wear_law, sliding)
    expected = solver.wear_per_revolution(reference, simulation.wear_law, sliding)
    assert np.abs(wear - expected).max() <= 1e-12 * expected.max()


#: a wearing pin (its wear coefficient of the same order as the bushing's) [1/Pa]
K_PIN = 2e-13


@pytest.mark.parametrize(("update_every", "compiled"), [(1, None), (1, False), ("adaptive", None)])
def test_aligned_slices_with_a_wearing_pin_wear_as_the_planar_joint(update_every, compiled):
    # an aligned rigid pin: every slice of the bushing and of the pin sees the planar
    # pressure, so both maps are the planar profiles in every slice, the pin's wear
    # facing each slice at every step included (compiled balance and solve_axial alone;
    # adaptive jumps, which carry the pin's map with the bushing's)
    extra = {
        "simulation.revolutions": 60 if update_every == 1 else 600,
        "simulation.update_every": update_every,
        "materials.pin.wear_coefficient": K_PIN,
    }
    planar = jw.Simulation(swing(**extra)).run()
    simulation = jw.Simulation(swing(**extra, **{"joint.axial_slices": 4}))
    simulation.solver.planar.compiled = compiled
    sliced = simulation.run()
    assert sliced.dataset["pin_wear_depth"].dims == ("z", "theta")
    assert planar.dataset["pin_wear_depth"].dims == ("theta",)
    for name in ("wear_depth", "pin_wear_depth"):
        reference, maps = planar.dataset[name].values, sliced.dataset[name].values
        scale = reference.max()
        assert scale > 0
        assert np.abs(maps - np.expand_dims(reference, -2)).max() <= 1e-9 * scale, name
    for key in ("pin_peak_wear_depth_m", "pin_wear_volume_m3", "peak_wear_depth_m"):
        assert sliced.summary()[key] == pytest.approx(planar.summary()[key], rel=1e-9, abs=0)


def first_revolution(count: int, **extra):
    """One revolution of the swinging pin on ``count`` slices, both surfaces unworn."""
    wearing = {"joint.axial_slices": count, "materials.pin.wear_coefficient": K_PIN}
    config = swing(**wearing, **extra)
    return config, jw.Simulation(config).run()


def test_a_tilted_pin_wears_its_loaded_edge_as_the_bushing_wears_its_own():
    # on the unworn joint the pin's wear of slice s, summed over its nodes, is
    # K_p sum_k sum_j p_sjk (R_b / R_p) ds_k, and the bushing's K_d sum_k sum_j p_sjk ds_k:
    # in every slice their ratio is K_p R_b / (K_d R_p), so the pin's edges wear in the
    # bushing's ratio (however differently each spreads its scar)
    config, result = first_revolution(10, **{"joint.misalignment": 4e-4})
    bushing = result.dataset["wear_depth"].values[-1]
    pin = result.dataset["pin_wear_depth"].values
    joint, k_bushing = config.joint, config.materials.bushing.wear_coefficient
    ratio = K_PIN * joint.bushing_radius / (k_bushing * joint.pin_radius)
    pin_totals, bushing_totals = pin.sum(axis=1), bushing.sum(axis=1)
    np.testing.assert_allclose(pin_totals, ratio * bushing_totals, rtol=1e-12)
    edge_to_edge = pin_totals[-1] / pin_totals[0]
    assert edge_to_edge == pytest.approx(bushing_totals[-1] / bushing_totals[0], rel=1e-12)
    assert edge_to_edge > 1.5  # (the tilt loads the last slice's edge)
    assert pin[-1].max() > pin[0].max()
