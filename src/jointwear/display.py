"""How a result is said to people: legible units, revolution counts, the end of a run,
and short text and HTML views for the REPL and notebooks.

``WearResult.__repr__`` and ``WearResult._repr_html_`` are these functions: a
result holds a whole dataset and config, and the default dataclass repr would
print all of it.
"""

from __future__ import annotations

import html
from typing import Any

from jointwear.state import revolution_number

__all__ = [
    "depth_unit",
    "end_of_run",
    "revolutions_text",
    "wear_result_html",
    "wear_result_repr",
]


def depth_unit(peak: float) -> tuple[float, str]:
    """Scale and name of the length unit that shows a depth legibly.

    Parameters
    ----------
    peak : float
        Largest depth to show [m].

    Returns
    -------
    scale : float
        Metres per unit [m].
    unit : str
        ``"nm"``, ``"µm"`` or ``"mm"``.
    """
    for scale, unit in ((1e-9, "nm"), (1e-6, "µm")):
        if peak < 1000 * scale:
            return scale, unit
    return 1e-3, "mm"


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


def _rows(result: Any) -> list[tuple[str, str]]:
    summary = result.summary()
    peak = summary["peak_wear_depth_m"]
    scale, unit = depth_unit(peak)
    mass_mg = summary["wear_mass_kg"] * 1e6
    return [
        ("contact model", str(summary["contact_model"])),
        (
            "revolutions",
            f"{revolutions_text(summary['revolutions'])} "
            f"({summary['contour_updates']} contour updates)",
        ),
        ("end", end_of_run(summary)),
        ("wear peak", f"{peak / scale:.4g} {unit}"),
        ("wear width", f"{summary['wear_width_deg']:.4g}°"),
        ("wear mass", f"{mass_mg:.4g} mg"),
        ("wear volume", f"{summary['wear_volume_m3'] * 1e9:.4g} mm³"),
        ("run time", f"{summary['runtime_s']:.3g} s"),
    ]


def wear_result_repr(result: Any) -> str:
    """One line: model, revolutions and the wear metrics of a result.

    Parameters
    ----------
    result : WearResult
        A simulation result.

    Returns
    -------
    str
        E.g. ``<WearResult nlcp, 1 r: peak 10.85 nm, width 115.9°, mass 0.003346 mg>``.
    """
    rows = dict(_rows(result))
    revolutions = rows["revolutions"].split(" ")[0]
    return (
        f"<WearResult {rows['contact model']}, {revolutions} r: peak {rows['wear peak']}, "
        f"width {rows['wear width']}, mass {rows['wear mass']}>"
    )


def wear_result_html(result: Any) -> str:
    """An HTML table of a result's metrics, for notebooks.

    Parameters
    ----------
    result : WearResult
        A simulation result.

    Returns
    -------
    str
        A ``<table>`` with one row per metric; the dataset is ``result.dataset``.
    """
    body = "".join(
        f"<tr><th style='text-align:left'>{html.escape(name)}</th>"
        f"<td style='text-align:left'>{html.escape(value)}</td></tr>"
        for name, value in _rows(result)
    )
    return (
        "<div><strong>WearResult</strong>"
        f"<table>{body}</table>"
        "<small>result.dataset: profiles, loads and pressures (xarray); "
        "result.plot(kind): figures</small></div>"
    )
