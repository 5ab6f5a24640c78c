"""The two-point estimator in 3D against exact answers (issue 13, section 1).

Tolerances as in randmedia.compare.debye2020: k SEM over samples plus the
bin-labelling bias |exact bin average - exact(r of the bin's label)| computed
from the exact curve itself.
"""

import itertools

import numpy as np
import pytest

from randmedia.describe.two_phase import two_point_function
from randmedia.describe.window import periodic_estimator_expectation, window_binning, window_s2_samples
from randmedia.generate.balls import overlapping_balls_image
from randmedia.generate.poisson_planes import poisson_plane_image
from randmedia.numerics.radial import RadialBinning
from randmedia.stats import standard_error
from randmedia.theory.debye import debye_s2
from randmedia.theory.overlapping import s2_void

K_SIGMA = 3.0


def labelling_bias(binning, exact):
    return np.abs(binning.average_of(exact) - exact(binning.r_mean))


def test_overlapping_spheres_match_exact_s2_3d():
    radius, phi2, side = 4.0, 0.3, 48
    rng = np.random.default_rng(303)
    images = np.stack([overlapping_balls_image(rng, side, radius, phi2, 3) for _ in range(16)])
    ds = two_point_function(images, phase=0, r_max=4 * radius)

    def exact(r):
        return s2_void(r, radius, phi2, dim=3)

    binning = RadialBinning.build(images.shape[1:], 4 * radius)
    np.testing.assert_array_equal(binning.r_mean, ds["r"].values)
    deviation = ds["S2"].values - exact(ds["r"].values)
    tolerance = K_SIGMA * ds["S2_sem"].values + labelling_bias(binning, exact)
    assert np.all(np.abs(deviation) <= tolerance)
    assert ds["S2_sem"].values.max() < 0.02  # the test has teeth


@pytest.fixture(scope="module")
def plane_media():
    a, phi2, side = 3.0, 0.3, 40
    rng = np.random.default_rng(1313)
    images = np.stack([poisson_plane_image(rng, (side,) * 3, a, phi2) for _ in range(64)])
    return a, phi2, images


def test_poisson_planes_window_s2_is_debye_3d(plane_media):
    """The minus-sampling estimator on the (non-periodic) Poisson-plane windows: Eq. (21)."""
    a, phi2, images = plane_media
    r_max = 16.0
    curves = window_s2_samples(images, phase=1, r_max=r_max)
    binning = window_binning(images.shape[1:], r_max)

    def exact(r):
        return debye_s2(r, phi2, a)

    mean, sem = curves.mean(axis=0), standard_error(curves)
    tolerance = K_SIGMA * sem + labelling_bias(binning, exact)
    assert np.all(np.abs(mean - exact(binning.r_mean)) <= tolerance)
    assert sem.max() < 0.01


def test_periodic_estimator_on_a_window_sees_the_seam(plane_media):
    """Consequence of the non-periodic windows: the periodic estimator measures
    periodic_estimator_expectation, not Eq. (21). Paired per image against the window
    estimator (the phase-fraction fluctuations cancel), the difference matches the
    prediction and is far outside its own errors."""
    a, phi2, images = plane_media
    r_max = 16.0
    periodic = two_point_function(images, phase=1, r_max=r_max)["S2_samples"].values
    window = window_s2_samples(images, phase=1, r_max=r_max)
    binning = RadialBinning.build(images.shape[1:], r_max)

    def exact(r):
        return debye_s2(r, phi2, a)

    predicted = periodic_estimator_expectation(exact, binning) - binning.average_of(exact)
    difference = periodic - window
    mean, sem = difference.mean(axis=0)[1:], standard_error(difference)[1:]
    assert np.all(np.abs(mean - predicted[1:]) <= K_SIGMA * sem)
    assert np.abs(predicted[1] / sem[0]) > 10  # the seam is measurable, ...
    assert predicted[1] < -0.02 * 0.21 * np.exp(-1 / a)  # ... > 2 % of chi_V at r = 1 (L = 40)


def test_poisson_lines_window_s2_is_debye_2d():
    a, phi2, side = 3.0, 0.4, 96
    rng = np.random.default_rng(22)
    images = np.stack([poisson_plane_image(rng, (side, side), a, phi2) for _ in range(64)])
    curves = window_s2_samples(images, phase=1, r_max=20.0)
    binning = window_binning(images.shape[1:], 20.0)

    def exact(r):
        return debye_s2(r, phi2, a)

    mean, sem = curves.mean(axis=0), standard_error(curves)
    assert np.all(np.abs(mean - exact(binning.r_mean)) <= K_SIGMA * sem + labelling_bias(binning, exact))


@pytest.mark.parametrize("shape", [(9, 11), (7, 8, 9), (10, 6, 7)])
def test_window_estimator_equals_explicit_pair_sums(shape):
    rng = np.random.default_rng(sum(shape))
    images = (rng.random((2,) + shape) < 0.4).astype(np.uint8)
    r_max = min(shape) / 2 - 0.6
    curves = window_s2_samples(images, phase=1, r_max=r_max)
    reference = RadialBinning.build(shape, r_max)
    np.testing.assert_array_equal(window_binning(shape, r_max).counts, reference.counts)
    np.testing.assert_allclose(window_binning(shape, r_max).r_mean, reference.r_mean, rtol=1e-15)
    for k, image in enumerate(images):
        sums, counts = {}, {}
        for v in itertools.product(*[range(-int(r_max), int(r_max) + 1)] * len(shape)):
            distance = np.sqrt(sum(c * c for c in v))
            if distance > r_max:
                continue
            # pairs (x, x + v) with both ends in the window
            a = image[tuple(slice(max(0, -c), n - max(0, c)) for c, n in zip(v, shape))]
            b = image[tuple(slice(max(0, c), n - max(0, -c)) for c, n in zip(v, shape))]
            value = (a * b).mean()
            bin_ = int(np.rint(distance))
            sums[bin_] = sums.get(bin_, 0.0) + value
            counts[bin_] = counts.get(bin_, 0) + 1
        expected = [sums[b] / counts[b] for b in sorted(sums)]
        np.testing.assert_allclose(curves[k], expected, atol=1e-12)


@pytest.mark.parametrize("shape", [(12, 10), (8, 9, 10)])
def test_seam_expectation_equals_explicit_average_over_positions(shape):
    """E C(v) = (1/N) sum_x S2(|true displacement of the pair (x, x+v mod L)|), enumerated."""
    def s2(r):
        return debye_s2(r, 0.3, 2.0)

    binning = RadialBinning.build(shape, min(shape) / 2 - 0.6)
    predicted = periodic_estimator_expectation(s2, binning)
    positions = np.indices(shape).reshape(len(shape), -1).T
    values = np.empty(len(binning.distance))
    for m, v in enumerate(binning.displacements()):
        target = positions + v
        wrapped = target - np.mod(target, shape)  # the unwrapped part: 0 or +-L per axis
        true = v - wrapped
        values[m] = s2(np.sqrt((true * true).sum(axis=1))).mean()
    expected = np.bincount(binning.bin_of, weights=values) / binning.counts
    np.testing.assert_allclose(predicted, expected, rtol=1e-12)


def test_window_estimator_rejects_bad_input():
    with pytest.raises(ValueError, match="min"):
        window_binning((10, 10, 10), 5.0)
    with pytest.raises(ValueError, match="n_samples"):
        window_s2_samples(np.zeros((4, 4)), phase=1, r_max=1.0)
