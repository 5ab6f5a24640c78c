"""Window (reduced-sample) pore sizes of 3D images: randmedia.describe.window_pores.

Exact checks (the reduced-sample formula, a ball in the middle of a window, the kept
triangles) and a statistical check against the exact overlapping-sphere F(delta) and the
periodic estimator on the same images (docs/debye3d.md, 'Window pore sizes').
"""

from __future__ import annotations

import numpy as np
import pytest

from randmedia.describe.pore_size import pore_size_functions
from randmedia.describe.window_pores import (reduced_sample_F, window_pore_size_functions,
                                             window_void_distances)
from randmedia.generate.balls import overlapping_balls_image
from randmedia.numerics.gaussian import default_margin
from randmedia.theory import overlapping as ov


def test_reduced_sample_F_counts_only_points_far_enough_from_the_faces():
    d = np.array([0.5, 2.0, 3.0, 5.0])
    b = np.array([4.0, 1.0, 4.0, 2.5])
    F, at_risk = reduced_sample_F(d, b, np.array([0.0, 1.0, 2.5, 3.5, 5.0]))
    # delta = 1: all four at risk, d >= 1 for three; 2.5: points 0, 2, 3 at risk, d >= 2.5: 2, 3
    # 3.5: points 0, 2 at risk, d >= 3.5: none; 5: nobody at risk
    np.testing.assert_array_equal(at_risk, [4, 4, 3, 2, 0])
    np.testing.assert_allclose(F[:4], [1.0, 0.75, 2 / 3, 0.0])
    assert np.isnan(F[4])


def test_distances_in_a_solid_shell_around_a_void_ball():
    """A void ball of radius 6 voxels (centre of a 32^3 window, solid elsewhere): the faces
    never enter (finite d everywhere), and the distances are those of uniform points in a
    ball to its sphere: mean R/4 and largest ~R, with R the level set's radius from its void
    volume (one query point per voxel)."""
    n, radius = 32, 6.0
    centre = np.full(3, n / 2)
    grid = np.indices((n,) * 3)[::-1].transpose(1, 2, 3, 0) + 0.5
    image = (np.linalg.norm(grid - centre, axis=-1) > radius).astype(np.uint8)
    d, b = window_void_distances(image, np.random.default_rng(1), sigma=0.5, supersample=2)
    level_set_radius = (3 * d.size / (4 * np.pi)) ** (1 / 3)
    assert level_set_radius == pytest.approx(radius, abs=0.5)
    assert np.all(np.isfinite(d)) and np.all(b > 0)
    assert np.mean(d) == pytest.approx(level_set_radius / 4, abs=0.1)
    assert level_set_radius - 1.0 < d.max() <= level_set_radius + 0.1


def test_margin_must_exceed_the_kernel():
    image = np.zeros((16, 16, 16), dtype=np.uint8)
    image[:, :, :8] = 1
    with pytest.raises(ValueError, match="kernel radius"):
        window_void_distances(image, np.random.default_rng(0), sigma=1.0, supersample=2, margin=3)


def test_window_pores_of_overlapping_spheres_agree_with_periodic_and_exact():
    """Periodic overlapping-sphere images read as windows: F within 3 SEM + 0.01 of the
    periodic estimator on the same images and of exact up to where the periodic estimator
    is validated (3 SEM + 0.035: the smoothed level set loses pore space near thin gaps,
    docs/debye3d.md); <delta> within 3 SEM + 6 % of exact."""
    rng = np.random.default_rng(4)
    radius, phi2 = 4.0, 0.3
    images = np.array([overlapping_balls_image(rng, 40, radius, phi2, 3) for _ in range(6)])
    kw = dict(sigma=0.5, supersample=2, delta_max=6.0, delta_bin=0.25)
    window = window_pore_size_functions(images, np.random.default_rng(1), **kw)
    periodic = pore_size_functions(images, np.random.default_rng(1), **kw)
    assert window.attrs["estimator"] == "window"
    assert window.attrs["margin"] == default_margin(0.5, 2)
    sem = np.hypot(window["F_sem"].values, periodic["F_sem"].values)
    assert np.all(np.abs(window["F"].values - periodic["F"].values) <= 3 * sem + 0.01)
    exact = ov.pore_size_complementary_cdf(window["delta"].values, radius, phi2, dim=3)
    assert np.all(np.abs(window["F"].values - exact) <= 3 * window["F_sem"].values + 0.035)
    mean = window["mean_delta_samples"].values
    exact_mean = ov.pore_size_moment(1, radius, phi2, dim=3)
    assert abs(mean.mean() - exact_mean) <= 3 * mean.std(ddof=1) / np.sqrt(mean.size) + 0.06 * exact_mean
