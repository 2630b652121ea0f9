"""What a run says, once each, when its wear questions the load it was given.

The massless-link dynamics assume the pin stays on the bushing wall: a run says so when
the wear grows past the clearance or when the load falls near zero (where the pin may
leave the wall). A contact-impact solve on the worn joint says when the pin separates.
Each message is a :class:`~jointwear.errors.WearFeedbackWarning`, given once per run,
and kept for the run's record.
"""

from __future__ import annotations

import warnings
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from jointwear.errors import WearFeedbackWarning

if TYPE_CHECKING:
    from jointwear.mechanism.cycle import LoadCycle

__all__ = ["FeedbackWarnings"]

FloatArray = NDArray[np.float64]

#: the dynamics model whose load assumes the pin stays on the wall
WALL_CONTACT_MODEL = "massless-link"


class FeedbackWarnings:
    """The wear-feedback warnings of one run, each given once.

    Parameters
    ----------
    clearance : float
        Radial clearance of the unworn joint [m].
    """

    def __init__(self, clearance: float) -> None:
        self.clearance = clearance
        #: key -> message of each warning given
        self.given: dict[str, str] = {}
        #: the load cycle whose smallest and largest load are known, and those loads [N]
        self._load_range_of: tuple[LoadCycle, float, float] | None = None

    @property
    def messages(self) -> tuple[str, ...]:
        """The messages given, in order."""
        return tuple(self.given.values())

    def warn_once(self, key: str, message: str) -> None:
        """Give ``message`` unless the warning ``key`` was given."""
        if key not in self.given:
            self.given[key] = message
            warnings.warn(message, WearFeedbackWarning, stacklevel=3)

    def check_contact(self, cycle: LoadCycle, revolution: float, wear_depth: FloatArray) -> None:
        """Say once when the continuous-contact assumption of the load is in doubt.

        Parameters
        ----------
        cycle : LoadCycle
            The load cycle the run wears under.
        revolution : float
            Revolutions completed [-].
        wear_depth : ndarray, shape (N,)
            The wear profile at ``revolution`` [m].
        """
        given = self.given
        # (nothing left to say: both said, or the clearance said and this cycle's load
        # range seen; a run checks at every update)
        seen = self._load_range_of is not None and self._load_range_of[0] is cycle
        if cycle.model != WALL_CONTACT_MODEL or (
            "clearance" in given and ("load" in given or seen)
        ):
            return
        clearance = self.clearance
        # (the peak only until its warning was given: a run checks at every update)
        peak = clearance if "clearance" in given else float(wear_depth.max())
        if peak >= clearance:
            self.warn_once(
                "clearance",
                f"simulation: the wear ({peak * 1e3:.3g} mm) has grown past the clearance "
                f"({clearance * 1e3:.3g} mm) by revolution {revolution:.10g}, but the massless-"
                f"link load assumes the pin stays on the wall; set dynamics.model = "
                f"'contact-impact' and simulation.dynamics_update = 'adaptive' to let the "
                f"worn joint's dynamics feed back",
            )
        if "load" not in given:
            low, high = self._load_range(cycle)
            if low < 1e-3 * high:
                self.warn_once(
                    "load",
                    f"dynamics: the joint load falls to {low:.3g} N "
                    f"(peak {high:.3g} N), where the pin may leave the wall; "
                    f"dynamics.model = 'contact-impact' models the separation",
                )

    def check_separation(self, row: dict[str, float], revolution: float) -> None:
        """Say once that the pin separates from the bushing, from a dynamics record row.

        Parameters
        ----------
        row : dict
            The row of the solve (:func:`jointwear.coupling.dynamics.dynamics_row`).
        revolution : float
            Revolutions completed at the solve [-].
        """
        if "min_film_thickness" in row:
            # an oiled pin off the wall rides on its film: that is no separation
            if row["impacts"] > 0:
                self.warn_once(
                    "separation",
                    f"dynamics: the pin breaks through its oil film ({int(row['impacts'])} "
                    f"impacts at revolution {revolution:.10g}); the wear follows the contact "
                    "force of the impacts",
                )
        elif row["impacts"] > 0 or row["free_flight_fraction"] > 0:
            self.warn_once(
                "separation",
                f"dynamics: the pin separates from the bushing ({int(row['impacts'])} impacts, "
                f"{row['free_flight_fraction']:.3g} of the cycle in free flight at revolution "
                f"{revolution:.10g}); the wear follows the contact-impact load",
            )

    def _load_range(self, cycle: LoadCycle) -> tuple[float, float]:
        """Smallest and largest load of ``cycle`` [N], computed once per cycle."""
        cached = self._load_range_of
        if cached is None or cached[0] is not cycle:
            cached = (cycle, float(cycle.load.min()), float(cycle.load.max()))
            self._load_range_of = cached
        return cached[1], cached[2]
