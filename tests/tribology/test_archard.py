"""Archard wear: local law, global form, for every contact model."""

from __future__ import annotations

import functools
import warnings
from pathlib import Path

import numpy as np
import pytest

from jointwear import Simulation, load_config
from jointwear.contact import ContactParameters, nlcp, solve, winkler
from jointwear.errors import ConfigError, ContactModelWarning
from jointwear.tribology import archard


def test_uniform_pressure_wears_k_d_p_s() -> None:
    """Closed form: a uniform 2 MPa sliding 50 x 0.1 mm wears K_d p s = 5.05 nm everywhere."""
    pressure = np.full((50, 36), 2e6)  # [Pa]
    ds = np.full(50, 1e-4)  # [m], 5 mm in all
    depth = archard.wear_depth(pressure, ds, 5.05e-13)
    assert depth.shape == (36,)
    np.testing.assert_allclose(depth, 5.05e-9, rtol=1e-12)


def test_wear_stays_where_and_when_the_pressure_is() -> None:
    """Pressure on node 3 during step 7 only: that node wears K_d p ds, no other node wears."""
    pressure = np.zeros((10, 8))
    pressure[7, 3] = 4e6
    ds = np.arange(1, 11) * 1e-5  # step 7 slides 80 um
    depth = archard.wear_depth(pressure, ds, 1e-12)
    assert depth[3] == pytest.approx(1e-12 * 4e6 * 8e-5, rel=1e-6, abs=0)
    assert np.count_nonzero(depth) == 1


def test_local_law_summed_over_the_surface_is_the_global_form() -> None:
    """sum_j h_j A_j = K_d sum_k N_k ds_k with N_k = sum_j p_jk A_j (Archard's V = K_d N s)."""
    rng = np.random.default_rng(1)
    pressure = rng.random((50, 36)) * 1e6  # [Pa]
    ds = rng.random(50) * 1e-4  # [m]
    area = rng.random(36) * 1e-6  # [m^2], unequal springs
    volume = float(archard.wear_depth(pressure, ds, 5e-13) @ area)
    normal_force = pressure @ area  # [N] per step
    assert volume == pytest.approx(
        archard.archard_volume(normal_force, ds, 5e-13), rel=1e-12, abs=0
    )


def test_archard_volume() -> None:
    assert archard.archard_volume([100.0, 200.0], [1e-3, 2e-3], 1e-12) == pytest.approx(
        5e-13, rel=1e-6, abs=0
    )


# ------------------------------------------ the global form, for every contact model

#: (model, nlcp_variant, nodes, contour update): every contact model on every mesh it is
#: allowed on. With contour update the revolution runs through the fused kernel (the
#: wear accumulated inside the balance), without it through the NumPy solve and the wear
#: law; the circular-only models run without.
GLOBAL_FORM_CASES = [
    *[("hertz", None, n, False) for n in (180, 360, 720, 1440)],
    *[("winkler", None, n, False) for n in (180, 360, 720, 1440)],
    *[("asymmetric-winkler", None, n, True) for n in (180, 360, 720, 1440)],
    ("nlcp", "paper", 360, True),
    *[("nlcp", "mesh-independent", n, True) for n in (180, 360, 720, 1440)],
]
#: the references: their pressure is sampled onto the nodes from their own grids, so
#: the load they balance holds on the nodes to a few 1e-5 only
REFERENCE_CASES = [("persson", None, 360, False), ("fem", None, 360, False)]


def case_id(case: tuple) -> str:
    model, variant, nodes, _ = case
    return f"{model}{'-' + variant if variant else ''}-{nodes}"


def spread(pressure: np.ndarray, theta: np.ndarray, azimuth: np.ndarray) -> np.ndarray:
    """``kappa_k = sum_j |F_jk| / sum_j F_jk cos(theta_j - psi_k)`` on the unworn circle.

    The springs are radial and, on a circle, of equal area: the ratio of the force they
    press into the surface to the force they carry along the load does not depend on
    the area a model turns pressure into force with.
    """
    cos = np.cos(theta[None, :] - azimuth[:, None])
    return pressure.sum(axis=1) / (pressure * cos).sum(axis=1)


@functools.cache
def archard_ratio(case: tuple) -> tuple[float, float, float]:
    """Worn volume of one revolution over ``K_d sum_k F_k ds_k``, the load-weighted
    spread factor of the unworn contact, and its widest half-angle [rad]."""
    model, variant, nodes, update = case
    config = load_config(
        Path(__file__).resolve().parents[1] / "data" / "paper_joint.toml",
        {
            "contact.model": model,
            "contact.nodes": nodes,
            "simulation.update_contour": update,
            "simulation.steps_per_revolution": 12 if (model, nodes) in REFERENCES else 60,
            **({"contact.nlcp_variant": variant} if variant else {}),
        },
    )
    simulation = Simulation(config)
    contour = simulation.initial_contour()
    solution = simulation.contact(contour)
    load, ds = simulation.load_cycle.load, simulation.sliding_distance
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ContactModelWarning)  # Hertz's wide contact
        depth = simulation.run(pressures=False).wear_depth
    volume = float(np.sum(depth * contour.spring_area))
    load_form = archard.archard_volume(load, ds, config.materials.bushing.wear_coefficient)
    kappa = spread(solution.pressure, contour.theta, simulation.load_cycle.azimuth)
    weighted = float(np.sum(kappa * load * ds) / np.sum(load * ds))
    widest = float(max(solution.half_angle_left.max(), solution.half_angle_right.max()))
    return volume / load_form, weighted, widest


REFERENCES = {(m, n) for m, _, n, _ in REFERENCE_CASES}


@pytest.mark.parametrize("case", GLOBAL_FORM_CASES + REFERENCE_CASES, ids=case_id)
def test_worn_volume_is_the_load_times_the_spread_factor(case: tuple) -> None:
    """V = K_d sum_k kappa_k F_k ds_k: Archard's global form with the force the springs
    press into the surface, kappa F (kappa >= 1, -> 1 for a narrow contact)."""
    ratio, kappa, widest = archard_ratio(case)
    assert ratio == pytest.approx(kappa, rel=2e-4 if case in REFERENCE_CASES else 1e-9)
    assert 1.0 < kappa < 1.0 / np.cos(widest)


@pytest.mark.parametrize(
    "family",
    [
        [c for c in GLOBAL_FORM_CASES if c[0] == model]
        for model in ("hertz", "winkler", "asymmetric-winkler", "nlcp")
    ],
    ids=["hertz", "winkler", "asymmetric-winkler", "nlcp"],
)
def test_the_worn_volume_does_not_depend_on_the_mesh(family: list) -> None:
    """180 to 1440 nodes (and NLCP's paper form on its 1 degree mesh) wear the same volume."""
    ratios = [archard_ratio(case)[0] for case in family]
    np.testing.assert_allclose(ratios, ratios[0], rtol=1e-4)


def test_linear_springs_spread_the_load_as_the_closed_form() -> None:
    """Winkler's kappa on a fine mesh is spread_factor(alpha) step by step (small-clearance
    kinematics; the pin's curvature changes it by ~1e-5)."""
    config = load_config(
        Path(__file__).resolve().parents[1] / "data" / "paper_joint.toml",
        {"contact.nodes": 1440, "simulation.steps_per_revolution": 60},
    )
    simulation = Simulation(config)
    contour = simulation.initial_contour()
    solution = simulation.contact(contour)
    kappa = spread(solution.pressure, contour.theta, simulation.load_cycle.azimuth)
    alpha = np.maximum(solution.half_angle_left, solution.half_angle_right)
    np.testing.assert_allclose(kappa, winkler.spread_factor(alpha), rtol=2e-4)
    assert kappa.max() > 1.02  # a conformal contact: the check is not 1 = 1


def test_nlcp_paper_form_off_its_mesh_would_wear_half_and_is_refused() -> None:
    """The paper's node force K delta^n with 1 degree springs on a 0.5 degree mesh balances
    the load with twice the area it wears: V = kappa F s / 2. The measure above sees it,
    and the configuration (or the law handed to a simulation) is refused."""
    path = Path(__file__).resolve().parents[1] / "data" / "paper_joint.toml"
    config = load_config(path, {"contact.nodes": 720, "simulation.steps_per_revolution": 30})
    parameters = ContactParameters.from_config(config)
    # the paper's law as nlcp.spring_law builds it: force area = the 1 degree spring
    assert parameters.nlcp_variant == "paper"
    paper_law = nlcp.spring_law(parameters)
    node_area = config.bushing_radius * 2 * np.pi / 720 * config.joint.axial_length
    assert paper_law.force_area == pytest.approx(2 * node_area, rel=1e-12, abs=0)
    simulation = Simulation(config)
    contour = simulation.initial_contour()
    cycle = simulation.load_cycle
    solution = solve(contour, simulation.pin, cycle.load, cycle.azimuth, paper_law, parameters)
    ds = simulation.sliding_distance
    k_d = config.materials.bushing.wear_coefficient
    volume = float(archard.wear_depth(solution.pressure, ds, k_d) @ contour.spring_area)
    kappa = spread(solution.pressure, contour.theta, cycle.azimuth)
    ratio = volume / archard.archard_volume(cycle.load, ds, k_d)
    assert ratio == pytest.approx(0.5 * np.sum(kappa * cycle.load * ds) / np.sum(cycle.load * ds))
    with pytest.raises(ConfigError, match=r"^contact\.nlcp_variant: .*'mesh-independent'$"):
        config.replace({"contact.model": "nlcp", "contact.nlcp_variant": "paper"})
    with pytest.raises(ConfigError, match=r"contact\.nlcp_variant: .* 0\.5 x Archard's"):
        Simulation(config, contact_model=paper_law)
    # a spring area of one's own is a mesh of one's own: refused off it as well
    with pytest.raises(ConfigError, match=r"contact\.nodes = 360"):
        config.replace({"contact.model": "nlcp", "contact.nodes": 360, "contact.spring_area": 1e-5})
