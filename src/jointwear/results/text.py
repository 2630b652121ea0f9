"""Revolution counts and the end of a run, as a result says them to people."""

from __future__ import annotations

from typing import Any

from jointwear.state import revolution_number

__all__ = ["end_of_run", "revolution_number", "revolutions_text"]


def revolutions_text(value: float) -> str:
    """A revolution count for people: a whole number in full, a fraction to two decimals,
    under one revolution to three digits (``352011``, ``352011.63``, ``0.00513``).

    Parameters
    ----------
    value : float
        Revolutions [-].
    """
    number = revolution_number(value)
    if isinstance(number, int):
        return str(number)
    return f"{number:.2f}" if abs(number) >= 1.0 else f"{number:.3g}"


def end_of_run(summary: dict[str, Any]) -> str:
    """Why and when a run ended, one line from its summary values
    (:func:`jointwear.results.summarize`).

    ``stopped: wall_thickness reached at 0.00513 revolutions (7.13e-07 h)`` or
    ``completed: 1000 revolutions (no life limit reached)``.

    Parameters
    ----------
    summary : dict
        A single joint's summary.
    """
    if summary.get("stopped_by"):
        return (
            f"stopped: {summary['stopped_by']} reached at "
            f"{revolutions_text(summary['life_revolutions'])} revolutions "
            f"({summary['life_hours']:.3g} h)"
        )
    revolutions = revolutions_text(summary["revolutions"])
    return f"completed: {revolutions} revolutions (no life limit reached)"
