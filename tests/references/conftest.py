"""Fixtures of the reference tests: the paper joint as used in docs/references.md."""

from __future__ import annotations

import math

import pytest

from jointwear.contact import ContactParameters
from jointwear.geometry import Pin
from jointwear.references.persson import PerssonProblem

R_PIN = 7.45e-3
R_BUSHING = 7.5e-3
AXIAL = 18.67e-3
WALL = 3.65e-3


@pytest.fixture(scope="session")
def joint() -> ContactParameters:
    """The paper's joint: steel pin in a PTFE bushing, b = 18.67 mm, L = 3.65 mm, Winkler's
    ``E_w = E`` (the paper's reading, as docs/references.md compares it)."""
    return ContactParameters(
        R_PIN, R_BUSHING, AXIAL, WALL, 2.09e11, 0.28, 5.0e8, 0.38, foundation_modulus="youngs"
    )


@pytest.fixture(scope="session")
def joint_pin() -> Pin:
    return Pin(R_PIN)


@pytest.fixture(scope="session")
def exact_bushing() -> PerssonProblem:
    """Exact solution of the FE model's problem: rigid pin, bushing in a rigid housing."""
    return PerssonProblem(
        R_PIN,
        R_BUSHING,
        math.inf,
        0.28,
        5.0e8,
        0.38,
        housing="rigid",
        outer_radius=R_BUSHING + WALL,
    )
