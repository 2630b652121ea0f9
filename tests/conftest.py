"""Shared fixtures: the paper's joint (Table 2 read in SI, see docs/reading-the-paper.md)."""

from __future__ import annotations

import json
import os
import shutil
import signal
import tempfile
import warnings
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import settings

from jointwear.config import Config, load_config
from jointwear.contact import ContactParameters
from jointwear.geometry import BushingContour, Pin

# The default run draws the same examples every time, so CI cannot fail on a lucky draw;
# `python -m pytest --hypothesis-profile=explore` draws fresh ones to look for new failures.
settings.register_profile("default", derandomize=True)
settings.register_profile("explore", derandomize=False)
settings.load_profile("default")

REPO = Path(__file__).resolve().parents[1]
PAPER_CONFIG = REPO / "tests" / "data" / "paper_joint.toml"
#: the suite's own memo of quantity texts (jointwear.quantity_memo), inherited by the
#: processes it starts: the user's cache folder is left alone
OWN_MEMO = "JOINTWEAR_CACHE_DIR" not in os.environ
if OWN_MEMO:
    os.environ["JOINTWEAR_CACHE_DIR"] = tempfile.mkdtemp(prefix="jointwear-memo-")
MEMO = os.environ["JOINTWEAR_CACHE_DIR"]


def pytest_unconfigure(config) -> None:
    if OWN_MEMO:
        shutil.rmtree(MEMO, ignore_errors=True)


def strict_json(text: str) -> Any:
    """``json.loads`` that refuses ``NaN`` and ``Infinity``, which are not JSON."""

    def refuse(name: str) -> Any:
        raise ValueError(f"not JSON: {name}")

    return json.loads(text, parse_constant=refuse)


def scar(
    nodes: int, depth: float = 20e-6, centre_deg: float = 20.0, width_deg: float = 12.0
) -> np.ndarray:
    """Gaussian wear scar [m] at the node angles, one-sided about the load line at 0 deg."""
    theta = 2 * np.pi * np.arange(nodes) / nodes
    phi = np.angle(np.exp(1j * theta))  # wrapped to (-pi, pi]
    return depth * np.exp(-(((phi - np.radians(centre_deg)) / np.radians(width_deg)) ** 2))


@pytest.fixture(scope="session")
def paper_config_path() -> Path:
    return PAPER_CONFIG


@pytest.fixture(scope="session")
def paper_config() -> Config:
    return load_config(PAPER_CONFIG)


@pytest.fixture(scope="session")
def params(paper_config: Config) -> ContactParameters:
    """Contact parameters of the paper's joint (R_p = 7.45 mm, c = 0.05 mm, PTFE bushing)."""
    return ContactParameters.from_config(paper_config)


@pytest.fixture(scope="session")
def pin(params: ContactParameters) -> Pin:
    return Pin(params.pin_radius)


@pytest.fixture(scope="session")
def clearance(params: ContactParameters) -> float:
    return params.bushing_radius - params.pin_radius


@pytest.fixture(scope="session")
def circle(params: ContactParameters) -> BushingContour:
    """Unworn bushing, 360 nodes (the paper's 1 degree spacing)."""
    return BushingContour.circle(params.bushing_radius, 360, params.axial_length)


@pytest.fixture(scope="session")
def worn(params: ContactParameters) -> BushingContour:
    """Bushing with a 20 um one-sided wear scar centred 20 deg counter-clockwise of 0 deg."""
    return BushingContour.from_wear_profile(params.bushing_radius, scar(360), params.axial_length)


#: fast tests of one stage or one function (no CLI, no files, no long simulations): run them
#: alone with ``python -m pytest -m "unit and not slow"``
UNIT_DIRECTORIES = ("contact", "geometry", "mechanism", "references", "tribology")
UNIT_FILES = ("test_config.py", "test_solvers.py")


def pytest_collection_modifyitems(config, items) -> None:
    tests = Path(__file__).resolve().parent
    for item in items:
        path = Path(str(item.fspath)).resolve().relative_to(tests)
        if path.parts[0] in UNIT_DIRECTORIES or path.as_posix() in UNIT_FILES:
            item.add_marker(pytest.mark.unit)


@pytest.fixture(autouse=True)
def signal_handlers_are_restored():
    """A test leaves SIGINT/SIGTERM as it found them; a leak is restored and reported.

    A child process inherits an ignored signal, and the command line keeps an inherited
    ignore (``nohup``): one test leaving SIGINT ignored in a worker would silently
    disable Ctrl-C in every later test's subprocess on that worker.
    """
    before = {each: signal.getsignal(each) for each in (signal.SIGINT, signal.SIGTERM)}
    yield
    for each, handler in before.items():
        if signal.getsignal(each) is not handler:
            signal.signal(each, handler)
            warnings.warn(f"the test changed the {each.name} handler; restored", stacklevel=1)
