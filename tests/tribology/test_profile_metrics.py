"""The stacked metrics of many profiles equal each profile's own metrics to the bit."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear.tribology.metrics import JointGeometry, evaluate_metrics, profile_metrics

JOINT = JointGeometry(
    bushing_radius=0.01,
    clearance=5e-5,
    axial_length=0.0187,
    bushing_thickness=0.0036,
    density=8900.0,
)


def _profiles(nodes: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    theta = 2 * np.pi * np.arange(nodes) / nodes
    rows = [
        rng.random(nodes) * 1e-5,  # crossings everywhere
        np.maximum(np.cos(theta - 1.0), 0.0) ** 2 * 3e-5,  # one scar
        np.maximum(np.sin(3 * theta), 0.0) * 1e-5,  # three scars, one across node 0
        np.zeros(nodes),  # unworn: no width
        np.full(nodes, 2e-6),  # worn all round: exactly 2 pi
    ]
    with_nan = rng.random(nodes) * 1e-5
    with_nan[3] = np.nan
    rows.append(with_nan)
    return np.stack(rows)


@pytest.mark.parametrize("nodes", [16, 17, 360])
def test_each_row_as_alone(nodes):
    depth = _profiles(nodes, nodes)
    stacked = profile_metrics(depth, JOINT)
    for k, row in enumerate(depth):
        alone = evaluate_metrics(row, JOINT)
        assert list(stacked) == list(alone)
        for name, value in alone.items():
            np.testing.assert_array_equal(stacked[name][k], value, err_msg=name)


def test_worn_all_round_is_two_pi():
    depth = _profiles(360, 1)
    assert profile_metrics(depth, JOINT)["wear_width"][4] == 2 * np.pi
    assert profile_metrics(depth, JOINT)["wear_width"][3] == 0.0
