"""Pending rST fixes of docstrings in modules being rewritten on another branch.

Each entry is (where, text as it is, text as it should be). The handler
applies an entry only while the old text is still there, so once the source is
fixed it does nothing; then delete the entry (and, when empty, this extension).
"""

from __future__ import annotations

#: numpydoc renames citations (``[1]_`` -> ``[R6753b5d8acc9-1]_``), which breaks
#: the column widths of a simple table that holds them: keep citations out of tables.
PENDING = [
    (
        "jointwear.mechanism",
        "=================  ==========================================================\n"
        "``massless-link``  slider-crank, clearance as a massless link along the\n"
        "                   load (continuous contact), paper eqs. (10)-(12)\n"
        "``contact-impact`` slider-crank with the pin free in the clearance: contact\n"
        "                   force law with hysteresis damping, Coulomb friction,\n"
        "                   event-driven integration (:mod:`.contact_impact`)\n"
        "=================  ==========================================================",
        "==================  ==========================================================\n"
        "``massless-link``   slider-crank, clearance as a massless link along the\n"
        "                    load (continuous contact), paper eqs. (10)-(12)\n"
        "``contact-impact``  slider-crank with the pin free in the clearance: contact\n"
        "                    force law with hysteresis damping, Coulomb friction,\n"
        "                    event-driven integration (:mod:`.contact_impact`)\n"
        "==================  ==========================================================",
    ),
    (
        "jointwear.mechanism.force_laws",
        "============================  ===========================  =====================\n"
        "``lankarani-nikravesh`` [1]_  ``chi = 3 (1 - c_e^2) / 4``  derived for ``c_e -> 1``\n"
        "``hunt-crossley`` [2]_ [3]_   ``chi = 3 (1 - c_e) / 2``    derived for ``c_e -> 1``\n"
        "``flores`` [4]_               ``chi = 8 (1 - c_e) / (5 c_e)``  any ``c_e`` (soft materials)\n"  # noqa: E501
        "============================  ===========================  =====================",
        "=======================  ===============================  ============================\n"
        "``lankarani-nikravesh``  ``chi = 3 (1 - c_e^2) / 4``      derived for ``c_e -> 1``\n"
        "``hunt-crossley``        ``chi = 3 (1 - c_e) / 2``        derived for ``c_e -> 1``\n"
        "``flores``               ``chi = 8 (1 - c_e) / (5 c_e)``  any ``c_e`` (soft materials)\n"
        "=======================  ===============================  ============================\n"
        "\n"
        "(Lankarani and Nikravesh [1]_, Hunt and Crossley [2]_ with Marhefka and Orin [3]_,\n"
        "Flores et al. [4]_.)",
    ),
    (
        "jointwear.mechanism.slider_crank.crank_angle_grid",
        "``k = 0 .. N-1``",
        "``k = 0, 1, ..., N-1``",
    ),
]


def _fix(app, what, name, obj, options, lines):
    text = "\n".join(lines)
    fixed = text
    for _where, old, new in PENDING:  # the old texts are specific enough to match anywhere
        fixed = fixed.replace(old, new)
    if fixed != text:
        lines[:] = fixed.split("\n")


def setup(app):
    app.connect("autodoc-process-docstring", _fix, priority=100)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
