"""The reproduction of the paper: its cases, the calibration on one row, the report.

=========================================  ================================================
:mod:`jointwear.paper.cases`               the paper's table rows (SI) and the shipped
                                           config of every case (``configs/*.toml``)
:mod:`jointwear.paper.protocol`            the protocol: what the paper leaves open,
                                           calibrated on one row
:mod:`jointwear.paper.reproduce`           every case run, the stated trends checked,
                                           the sensitivity to the readings of the paper
:mod:`jointwear.paper.report`              ``report.md`` and the paper-style figures
=========================================  ================================================

This package sits on top of the library: nothing else in ``jointwear`` imports it
(the command line's ``reproduce`` and ``calibrate --paper-row`` do, on use).
"""

from __future__ import annotations

from jointwear.paper.cases import PAPER_ROWS, PaperRow, case_config, case_names
from jointwear.paper.protocol import (
    CALIBRATION_CASE,
    CALIBRATION_PARAMETERS,
    calibrate_paper_row,
)
from jointwear.paper.reproduce import check_trends, reproduce, run_cases

__all__ = [
    "CALIBRATION_CASE",
    "CALIBRATION_PARAMETERS",
    "PAPER_ROWS",
    "PaperRow",
    "calibrate_paper_row",
    "case_config",
    "case_names",
    "check_trends",
    "reproduce",
    "run_cases",
]
