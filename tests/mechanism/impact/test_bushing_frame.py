"""A worn bushing that turns with its body: the contact in the body's frame.

Turning the bushing body by a whole number of nodes is the same as turning its wear
profile the other way on a fixed bushing; a bushing on the first body (``e`` from the
pin to the bushing) is the same as the pin offset reversed.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointwear.geometry.contour import BushingContour
from jointwear.mechanism.impact.bushing_frame import contact_force_in_frame, to_bushing_frame
from jointwear.mechanism.impact.joint_contact import JointContact

NODES, RADIUS, LENGTH, CLEARANCE = 72, 7.5e-3, 0.01, 5e-5


def contact(wear: np.ndarray, friction: float = 0.2) -> JointContact:
    contour = BushingContour.from_wear_profile(RADIUS, wear, LENGTH)
    return JointContact(
        force_law="lankarani-nikravesh",
        clearance=CLEARANCE,
        stiffness=8e8,
        restitution=0.9,
        friction_coefficient=friction,
        friction_arm=RADIUS - CLEARANCE,
        contour=contour,
    )


def scar() -> np.ndarray:
    theta = 2.0 * np.pi * np.arange(NODES) / NODES
    return 3e-5 * np.exp(-(np.angle(np.exp(1j * (theta - 1.0))) ** 2) / 0.2) + 1e-6 * theta


@pytest.mark.parametrize("shift", [0, 5, 17, 40])
@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_turned_bushing_is_the_turned_scar(shift: int, sign: float) -> None:
    """Body turned by ``shift`` nodes == scar turned by ``shift`` nodes on a fixed bushing."""
    angle = 2.0 * math.pi * shift / NODES
    wear = scar()
    fixed = contact(np.roll(wear, shift))
    turning = contact(wear)
    rng = np.random.default_rng(shift)
    for _ in range(20):
        direction = rng.uniform(0, 2 * math.pi)
        radius = CLEARANCE + rng.uniform(0.0, 4e-5)
        e = (radius * math.cos(direction), radius * math.sin(direction))
        v = tuple(rng.normal(0.0, 1e-2, 2))
        spin, approach = rng.normal(0.0, 2.0), 0.05
        # on the fixed bushing the pin's offset from the bushing centre is s e
        expected = fixed.force(sign * e[0], sign * e[1], sign * v[0], sign * v[1], spin, approach)
        got = contact_force_in_frame(turning, angle, sign, e, v, spin, approach)
        jx, jy, normal, tangential, nx, ny, delta, slip = got
        scale = max(abs(expected[2]), 1e-9)
        # force and normal back in the global frame: reversed with the offset
        assert sign * jx == pytest.approx(expected[0], abs=1e-9 * scale)
        assert sign * jy == pytest.approx(expected[1], abs=1e-9 * scale)
        assert (sign * nx, sign * ny) == pytest.approx(expected[4:6], abs=1e-12)
        assert (normal, tangential, delta, slip) == pytest.approx(
            (expected[2], expected[3], expected[6], expected[7]), rel=1e-9, abs=1e-15
        )


def test_frame_round_trip() -> None:
    """``s R(theta)`` undoes ``s R(-theta)``."""
    x, y = to_bushing_frame(0.7, -1.0, 0.3, -0.4)
    assert to_bushing_frame(-0.7, -1.0, x, y) == pytest.approx((0.3, -0.4), abs=1e-15)
    assert math.hypot(x, y) == pytest.approx(0.5)
