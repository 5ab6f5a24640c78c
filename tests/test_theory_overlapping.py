"""Exact overlapping-disk/sphere S2 (Eqs. 32-33) against limits and Monte Carlo."""

import numpy as np
import pytest

from randmedia.theory.overlapping import s2_void, union_volume_ratio


@pytest.mark.parametrize("dim", [2, 3])
def test_limits(dim):
    assert union_volume_ratio(0.0, 1.0, dim) == pytest.approx(1.0)
    assert union_volume_ratio(2.0, 1.0, dim) == pytest.approx(2.0)
    assert union_volume_ratio(5.0, 1.0, dim) == 2.0
    assert s2_void(0.0, 1.0, 0.3, dim) == pytest.approx(0.7)
    assert s2_void(10.0, 1.0, 0.3, dim) == pytest.approx(0.49)


@pytest.mark.parametrize("dim", [2, 3])
@pytest.mark.parametrize("r", [0.3, 1.0, 1.7])
def test_union_volume_matches_monte_carlo(dim, r):
    rng = np.random.default_rng(4)
    n = 400_000
    points = rng.uniform(-1.0, 1.0 + r, size=(n, dim))
    points[:, 1:] = rng.uniform(-1.0, 1.0, size=(n, dim - 1))
    box = (2.0 + r) * 2.0 ** (dim - 1)
    first = np.sum(points**2, axis=1) <= 1.0
    second = np.sum((points - np.eye(dim)[0] * r) ** 2, axis=1) <= 1.0
    hits = first | second
    estimate = hits.mean() * box
    error = np.sqrt(hits.mean() * (1 - hits.mean()) / n) * box
    ball = np.pi if dim == 2 else 4 * np.pi / 3
    assert abs(estimate / ball - union_volume_ratio(r, 1.0, dim)) < 4 * error / ball


def test_bad_input():
    with pytest.raises(ValueError):
        union_volume_ratio(1.0, 1.0, dim=4)
    with pytest.raises(ValueError):
        s2_void(1.0, 1.0, 1.2)
