"""The stages' open choices as the configuration knows them: names, not imports.

The configuration validates ``contact.model``, ``dynamics.model`` and ``wear.law``
against the names here, and reaches the stages' checks and closed-form defaults
through :class:`~jointwear.registry.Lazy` ``"module:attr"`` entries, imported when
first called. So :mod:`jointwear.config` imports no physics: it sits below the
stages that read it. Each :class:`Choice` names the stage's own registry
(``registry``), and a test checks that the two hold the same names.
"""

from __future__ import annotations

import typing
from dataclasses import dataclass
from typing import Literal

from jointwear.config.fields import one_of
from jointwear.registry import Lazy

__all__ = [
    "CHOICES",
    "CONTACT_MODEL",
    "DYNAMICS_MODEL",
    "FOUR_BAR_GEOMETRY",
    "IMPACT_FILM",
    "LUBRICANT",
    "MODEL_CHOICE",
    "NLCP_STIFFNESS",
    "PAPER_SPRING_AREA",
    "SLIDING_MODEL",
    "WEAR_LAW",
    "Choice",
    "SlidingModel",
]

#: ``simulation.sliding``: a closed set, validated as a Literal
SlidingModel = Literal["relative-rotation", "contact-azimuth"]


@dataclass(frozen=True)
class Choice:
    """An open choice of the configuration: the names it takes and where they live.

    Attributes
    ----------
    kind : str
        What is chosen, for messages: ``"contact model"``.
    key : str
        The config key that chooses: ``"contact.model"``.
    names : tuple of str
        The names the key takes, in the stage registry's order.
    registry : str
        ``"module:attr"`` of the stage's :class:`~jointwear.registry.Registry`.
    """

    kind: str
    key: str
    names: tuple[str, ...]
    registry: str

    def check(self, value: str) -> str:
        """``value`` if it is one of :attr:`names`; a ValueError with the best match."""
        return one_of(value, self.names, self.kind)


CONTACT_MODEL = Choice(
    "contact model",
    "contact.model",
    ("hertz", "winkler", "asymmetric-winkler", "nlcp", "persson", "fem"),
    "jointwear.contact:CONTACT_MODELS",
)
DYNAMICS_MODEL = Choice(
    "dynamics model",
    "dynamics.model",
    ("massless-link", "contact-impact"),
    "jointwear.mechanism:DYNAMICS_MODELS",
)
WEAR_LAW = Choice(
    "wear law",
    "wear.law",
    ("archard", "energy", "power-law", "running-in", "tabulated"),
    "jointwear.tribology.wear_laws:WEAR_LAWS",
)
SLIDING_MODEL = Choice(
    "sliding model",
    "simulation.sliding",
    typing.get_args(SlidingModel),
    "jointwear.tribology.sliding:SLIDING_MODELS",
)
#: every choice whose names are kept here
CHOICES: tuple[Choice, ...] = (CONTACT_MODEL, DYNAMICS_MODEL, WEAR_LAW, SLIDING_MODEL)

#: ``check_four_bar(ground, crank, coupler, rocker)``: the linkage assembles and turns
FOUR_BAR_GEOMETRY = Lazy("jointwear.mechanism.four_bar.geometry:check_four_bar", "mechanism")
#: ``stiffness(R_p, E_p, nu_p, E_b, nu_b)``: NLCP's spring stiffness, eq. (2) [N/m^n]
NLCP_STIFFNESS = Lazy("jointwear.contact.nlcp:stiffness", "contact.stiffness")
#: ``check_model_choice(model, update_contour)``: the model can follow a worn contour
MODEL_CHOICE = Lazy("jointwear.contact:check_model_choice", "contact.model")
#: ``get_lubricant(name, key)``: a lubricant of the library (an unknown name: the best match)
LUBRICANT = Lazy("jointwear.lubrication.lubricants:get_lubricant", "lubrication.lubricant")
#: ``check_film_band(model, roughness, clearance)``: the contact-impact film's transition
#: band is narrower than the clearance
IMPACT_FILM = Lazy("jointwear.mechanism.impact.film:check_film_band", "lubrication.roughness")
#: ``check_paper_spring_area(spring_area, node_area, nodes)``: NLCP's paper form fits the mesh
PAPER_SPRING_AREA = Lazy("jointwear.contact:check_paper_spring_area", "contact.nlcp_variant")
