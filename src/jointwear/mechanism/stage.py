"""The mechanism stage of a run: from a configuration to the load cycle of every joint.

:func:`load_cycles` is what a run calls (stage 1 of the pipeline: the joint's motion
-> its load cycle). It builds the mechanism's :class:`~jointwear.mechanism.inputs.MechanismInputs`
from the :class:`~jointwear.config.Config` (:func:`mechanism_inputs`) and hands them to
the mechanism type's registry entry (:func:`jointwear.mechanism.base.cycles_of`); no
mechanism reads the configuration itself.

This module sits above the contact layer (``tests/test_layering.py``): the
contact–impact model's elastic law is the contact stage's own (Hertz's stiffness,
eq. (2); the ``nlcp`` and ``winkler`` spring laws), resolved here
(:func:`elastic_law`) and passed down, so that the mechanism layer imports nothing
from the contact layer above it and each formula keeps one implementation. The oil
film of a lubricated joint in the contact–impact dynamics is resolved here too
(:func:`film_parameters`: the viscosity of the ``[lubrication]`` section from the
lubricants library, which lies above the mechanism layer).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from jointwear.config import Config
from jointwear.contact import ContactParameters, contact_law, hertz
from jointwear.errors import ConfigError
from jointwear.lubrication.lubricants import section_viscosity
from jointwear.mechanism.base import cycles_of
from jointwear.mechanism.cycle import LoadCycle
from jointwear.mechanism.impact.film import FilmParameters
from jointwear.mechanism.impact.force_laws import DISTRIBUTED_LAWS
from jointwear.mechanism.inputs import ElasticLaw, JointGeometry, MechanismInputs
from jointwear.registry import suggest

__all__ = [
    "COMPILED_DYNAMICS_REVOLUTIONS",
    "compiled_dynamics",
    "elastic_law",
    "film_parameters",
    "load_cycle",
    "load_cycles",
    "mechanism_inputs",
]

FloatArray = NDArray[np.float64]

#: integrated revolutions of a run up to which the Python right-hand side is faster
#: than loading numba and its cached machine code
COMPILED_DYNAMICS_REVOLUTIONS = 16


def load_cycles(config: Config, wear_depth: FloatArray | None = None) -> dict[str, LoadCycle]:
    """Load cycle of every clearance joint of the configured mechanism.

    Parameters
    ----------
    config : jointwear.config.Config
        Validated configuration (SI values).
    wear_depth : ndarray, shape (N,), optional
        Wear depth of the bushing on the ``contact.nodes`` grid, bushing frame [m]:
        the dynamics of the worn joint (the massless link grows by the deepest wear,
        contact-impact meets the worn contour). ``None``: the unworn joint.

    Returns
    -------
    dict of str to LoadCycle
        Joint name -> its load cycle, in the order of ``config.joints``.

    Raises
    ------
    ConfigError
        If ``dynamics.model`` names no model of the mechanism type.
    """
    return cycles_of(mechanism_inputs(config), wear_depth)


def load_cycle(config: Config, joint: str | None = None) -> LoadCycle:
    """Load cycle of one clearance joint (default: the first of ``config.joints``).

    Parameters
    ----------
    config : jointwear.config.Config
        Validated configuration (SI values).
    joint : str, optional
        Name of the joint.
    """
    cycles = load_cycles(config)
    if joint is None:
        return next(iter(cycles.values()))
    if joint not in cycles:
        raise ConfigError(
            f"mechanism.clearance_joint: no clearance joint {joint!r}{suggest(joint, cycles)}"
        )
    return cycles[joint]


def mechanism_inputs(config: Config) -> MechanismInputs:
    """What the configured mechanism's dynamics read, taken from the configuration.

    Parameters
    ----------
    config : jointwear.config.Config
        Uses ``[mechanism]``, ``[dynamics]``, ``[joint]``, ``contact.nodes``,
        ``simulation.steps_per_revolution`` and, for ``dynamics.model =
        "contact-impact"``, the elastic data of :func:`elastic_law`, the run plan
        of :func:`compiled_dynamics` and the film of :func:`film_parameters`.
    """
    joint = config.joint
    geometry = JointGeometry(
        pin_radius=joint.pin_radius,
        clearance=joint.clearance,
        axial_length=joint.axial_length,
        nodes=config.contact.nodes,
    )
    impact = config.dynamics.model == "contact-impact"
    return MechanismInputs(
        mechanism=config.mechanism,
        steps=config.simulation.steps_per_revolution,
        joint=geometry,
        dynamics=config.dynamics,
        elastic=elastic_law(config) if impact else None,
        compiled=compiled_dynamics(config) if impact else None,
        film=film_parameters(config) if impact else None,
    )


def film_parameters(config: Config) -> FilmParameters | None:
    """The oil film of the contact–impact dynamics, from ``[lubrication]`` (``None``: dry).

    The film model (``"short-bearing"`` or ``"long-bearing"``; the configuration refuses
    ``"finite-length"`` with ``dynamics.model = "contact-impact"``), the viscosity
    (:func:`jointwear.lubrication.lubricants.section_viscosity`: ``viscosity``, or the
    ``lubricant``'s at its ``temperature``) and the composite ``roughness``, which sets
    the band where the film hands over to the contact law
    (:meth:`~jointwear.mechanism.impact.film.FilmParameters.band`). The film's length
    is the joint's axial length.

    Parameters
    ----------
    config : jointwear.config.Config
        Uses ``[lubrication]``.
    """
    section = config.lubrication
    if not section.lubricated:
        return None
    return FilmParameters(
        model=section.model, viscosity=section_viscosity(section), roughness=section.roughness
    )


def elastic_law(config: Config) -> ElasticLaw:
    """The joint's elastic law for the contact–impact force laws, from the contact stage.

    Parameters
    ----------
    config : jointwear.config.Config
        Uses ``[joint]``, ``[materials]``, ``dynamics.force_law`` and, for the
        distributed laws, the spring-law keys of ``[contact]``.

    Returns
    -------
    ElasticLaw
        Hertz's stiffness of the pin in the hole, eq. (2) with ``R_i = R_p``,
        ``R_j = R_b`` (:func:`jointwear.contact.hertz.stiffness`), and for ``nlcp`` or
        ``winkler`` that contact model's spring law.
    """
    params = ContactParameters.from_config(config)
    stiffness = float(
        hertz.stiffness(
            params.pin_radius,
            params.bushing_radius,
            params.pin_youngs_modulus,
            params.pin_poisson_ratio,
            params.bushing_youngs_modulus,
            params.bushing_poisson_ratio,
        )
    )
    force_law = config.dynamics.force_law
    spring = contact_law(force_law, params) if force_law in DISTRIBUTED_LAWS else None
    return ElasticLaw(stiffness=stiffness, spring_law=spring)


def compiled_dynamics(config: Config) -> bool | None:
    """Whether the run's contact-impact integrations may run compiled (``None``: where it can).

    Loading numba and its cached machine code takes ~0.5 s per process; the compiled
    right-hand side saves ~30 ms per integrated revolution of the paper's joint (35 ms
    against 67 ms). A run whose integrations cover at most
    :data:`COMPILED_DYNAMICS_REVOLUTIONS` revolutions (settling included) takes the
    Python right-hand side (``False``). Both give the same bits, so the choice never
    changes a result; it is read from the configuration alone
    (:attr:`jointwear.config.SimulationConfig.contact_solves` bounds the contour
    updates, ``simulation.dynamics_update`` how many of them re-solve the dynamics).

    Parameters
    ----------
    config : Config
        The run's configuration.
    """
    sim = config.simulation
    schedule = sim.dynamics_update
    if schedule == "adaptive":
        return None
    solves = 1
    if sim.update_contour and schedule != "once":
        solves += sim.contact_solves // schedule
    revolutions = solves * (config.dynamics.revolutions_settle + 1)
    return None if revolutions > COMPILED_DYNAMICS_REVOLUTIONS else False
