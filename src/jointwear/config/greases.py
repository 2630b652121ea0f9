"""A grease as boundary lubrication: which wear coefficient the bushing wears with.

A library lubricant whose regime is ``"boundary"`` (the greases of
:mod:`jointwear.lubrication.lubricants`) named as ``lubrication.lubricant`` with no
film model (``lubrication.model = "dry"``, the default) is boundary lubrication: no
film carries any load, pin and bushing touch as in the dry joint, and the wear
follows the pair's coefficient with the grease,
``materials.bushing.boundary_wear_coefficient`` [m^2/N], instead of its dry
``wear_coefficient``. With a film model the grease's base oil is the film, as an oil
is (the wear then keeps ``wear_coefficient``).
"""

from __future__ import annotations

from typing import Any

from jointwear.config.choices import LUBRICANT

__all__ = ["BOUNDARY_REGIME", "check_grease", "greased", "wearing_bushing"]

#: the regime of a library lubricant that builds no film (a grease)
BOUNDARY_REGIME = "boundary"


def greased(config: Any) -> bool:
    """The joint is boundary lubricated by a grease: a ``boundary`` lubricant, no film.

    Parameters
    ----------
    config : ConfigSchema
        The configuration (its ``[lubrication]`` section).
    """
    section = config.lubrication
    if section.lubricated or section.lubricant is None:
        return False
    return LUBRICANT(section.lubricant, "lubrication.lubricant").regime == BOUNDARY_REGIME


def check_grease(config: Any) -> None:
    """Refuse a grease without the bushing's wear coefficient with it.

    Parameters
    ----------
    config : ConfigSchema
        The configuration.

    Raises
    ------
    ValueError
        One line naming ``materials.bushing.boundary_wear_coefficient``.
    """
    if not greased(config) or config.materials.bushing.boundary_wear_coefficient is not None:
        return
    name = config.materials.bushing.name
    which = f"the library's {name!r} gives none" if name else "the bushing's table gives none"
    raise ValueError(
        "materials.bushing.boundary_wear_coefficient: missing (lubrication.lubricant = "
        f"{config.lubrication.lubricant!r} is a grease: without a film model the joint wears "
        f"with the pair's coefficient with the grease, and {which}); give it, or a film model"
    )


def wearing_bushing(config: Any) -> Any:
    """The bushing's material as it wears: greased, its ``boundary_wear_coefficient``
    as ``wear_coefficient`` [m^2/N]; otherwise ``materials.bushing`` itself.

    Parameters
    ----------
    config : ConfigSchema
        The validated configuration.
    """
    bushing = config.materials.bushing
    if not greased(config):
        return bushing
    return bushing.model_copy(update={"wear_coefficient": bushing.boundary_wear_coefficient})
