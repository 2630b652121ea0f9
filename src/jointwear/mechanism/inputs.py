"""What a mechanism receives: its own config section and the few numbers of the joint.

No mechanism reads the whole :class:`~jointwear.config.Config`. A dynamics model gets a
:class:`MechanismInputs`: the ``[mechanism]`` section of its type, the ``[dynamics]``
section, the number of steps per revolution, the joint's geometry
(:class:`JointGeometry`) and, for the contact–impact model, the joint's elastic law
(:class:`ElasticLaw`). :func:`jointwear.mechanism.stage.mechanism_inputs` builds it
from a configuration.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

from jointwear.mechanism.impact.distributed import PressureLaw

if TYPE_CHECKING:
    from jointwear.config import DynamicsConfig
    from jointwear.mechanism.impact.film import FilmParameters

__all__ = ["ElasticLaw", "JointGeometry", "MechanismInputs"]


@dataclass(frozen=True)
class JointGeometry:
    """The clearance joint's numbers a mechanism needs (``[joint]``, ``contact.nodes``).

    Parameters
    ----------
    pin_radius : float
        Pin radius ``R_p`` [m].
    clearance : float
        Radial clearance ``c`` [m].
    axial_length : float
        Axial length ``b`` of the joint [m].
    nodes : int
        Nodes of the bushing contour (``contact.nodes``): the grid of a wear profile and
        of the distributed force laws [-].
    """

    pin_radius: float
    clearance: float
    axial_length: float
    nodes: int

    @property
    def bushing_radius(self) -> float:
        """Unworn bushing inner radius ``R_b = R_p + c`` [m]."""
        return self.pin_radius + self.clearance

    def with_clearance(self, clearance: float) -> JointGeometry:
        """The same joint with another radial clearance [m]."""
        return replace(self, clearance=clearance)


@dataclass(frozen=True)
class ElasticLaw:
    """Elastic part of the contact–impact force law, built from the contact stage's laws.

    Parameters
    ----------
    stiffness : float
        ``K`` of the point laws, eq. (2) with ``R_i = R_p``, ``R_j = R_b`` (Hertz, pin in
        a hole) [N/m^1.5].
    spring_law : PressureLaw, optional
        Pressure law of the bushing nodes for the distributed force laws (``nlcp``,
        ``winkler``); ``None`` for the point laws.
    """

    stiffness: float
    spring_law: PressureLaw | None = None


@dataclass(frozen=True)
class MechanismInputs:
    """Everything a mechanism's dynamics model reads, SI.

    Parameters
    ----------
    mechanism : pydantic model
        The ``[mechanism]`` section of the configured type
        (:class:`~jointwear.config.SliderCrankConfig`,
        :class:`~jointwear.config.FourBarConfig`, ...).
    steps : int
        Time steps per revolution (per oscillation, per period) ``N`` [-].
    joint : JointGeometry
        The clearance joint.
    dynamics : jointwear.config.DynamicsConfig
        The ``[dynamics]`` section (model settings, contact–impact settings).
    elastic : ElasticLaw, optional
        The joint's elastic law; needed by the contact–impact model only.
    compiled : bool or None
        Whether contact–impact integrations may run the compiled right-hand side:
        ``None`` where it can, ``False`` never (the same bits either way).
    film : FilmParameters, optional
        The oil film of a lubricated joint in the contact–impact dynamics; ``None``:
        a dry joint.
    """

    mechanism: Any
    steps: int
    joint: JointGeometry
    dynamics: DynamicsConfig
    elastic: ElasticLaw | None = None
    compiled: bool | None = None
    film: FilmParameters | None = None

    @property
    def clearance(self) -> float:
        """Radial clearance of the joint [m]."""
        return self.joint.clearance
