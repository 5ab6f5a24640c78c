"""FFT two-point estimator: exact against brute force; known-answer cases."""

import itertools

import numpy as np
import pytest

from randmedia.describe.two_phase import two_point_function
from randmedia.numerics.radial import RadialBinning, periodic_autocorrelation
from randmedia.generate.disks import overlapping_disks_image
from randmedia.theory.overlapping import s2_void


def brute_force_autocorrelation(image):
    """C(v) = mean_x I(x) I(x+v) by explicit periodic shifts (slow, obviously right)."""
    image = image.astype(float)
    out = np.empty(image.shape)
    for shift in itertools.product(*[range(n) for n in image.shape]):
        shifted = np.roll(image, tuple(-s for s in shift), axis=tuple(range(image.ndim)))
        out[shift] = (image * shifted).mean()
    return out


@pytest.mark.parametrize("shape", [(9, 9), (8, 8), (7, 10), (5, 6, 7)])
def test_fft_autocorrelation_equals_brute_force(shape):
    image = np.random.default_rng(1).random(shape) < 0.4
    np.testing.assert_allclose(periodic_autocorrelation(image), brute_force_autocorrelation(image),
                               atol=1e-12)


@pytest.mark.parametrize("shape", [(31, 31), (32, 32), (21, 26), (15, 16, 17)])
def test_binning_uses_minimal_image_displacements(shape):
    r_max = min(shape) / 2 - 0.5
    binning = RadialBinning.build(shape, r_max)
    # count of lattice vectors with |v| <= r_max, by direct enumeration over one period
    grids = np.meshgrid(*[np.arange(-(n // 2), n - n // 2) for n in shape], indexing="ij")
    norms = np.sqrt(sum(g.astype(float) ** 2 for g in grids))
    assert binning.counts.sum() == np.count_nonzero(norms <= r_max)
    assert binning.counts[0] == 1 and binning.r_mean[0] == 0.0
    # bins are labelled at the mean distance of their displacements, within the bin
    k = np.arange(binning.counts.size)
    assert np.all(np.abs(binning.r_mean - k) <= 0.5)
    # bin 1 = [0.5, 1.5): the 2d axis neighbours at 1 and the 2d(d-1) face diagonals at sqrt 2
    d = len(shape)
    axis, diagonal = 2 * d, 2 * d * (d - 1)
    assert binning.counts[1] == axis + diagonal
    assert binning.r_mean[1] == pytest.approx((axis + diagonal * np.sqrt(2)) / (axis + diagonal))


@pytest.mark.parametrize("shape", [(15, 15), (16, 16), (13, 18), (9, 10, 11)])
def test_radial_s2_equals_brute_force_radial_average(shape):
    """Whole estimator vs independent code: explicit minimal images, np.roll, rint bins."""
    rng = np.random.default_rng(8)
    images = (rng.random((2,) + shape) < 0.45).astype(np.uint8)
    r_max = min(shape) / 2 - 0.6
    ds = two_point_function(images, phase=1, r_max=r_max)
    offsets = [range(-(n // 2), n - n // 2) for n in shape]  # minimal images, odd or even
    for k, image in enumerate(images):
        sums, counts = {}, {}
        indicator = image.astype(float)
        for v in itertools.product(*offsets):
            distance = np.sqrt(sum(c * c for c in v))
            if distance > r_max:
                continue
            shifted = np.roll(indicator, tuple(-c for c in v), axis=tuple(range(len(shape))))
            b = int(np.rint(distance))
            sums[b] = sums.get(b, 0.0) + (indicator * shifted).mean()
            counts[b] = counts.get(b, 0) + 1
        expected = np.array([sums[b] / counts[b] for b in sorted(sums)])
        np.testing.assert_allclose(ds["S2_samples"].values[k], expected, atol=1e-12)
        np.testing.assert_array_equal(ds["n_vectors"].values, [counts[b] for b in sorted(counts)])


def test_bernoulli_pixels_known_answer():
    """Independent pixels with probability p: S2(0) = phi, S2(r > 0) = p^2 in expectation."""
    rng = np.random.default_rng(3)
    p = 0.35
    images = (rng.random((20, 65, 65)) < p).astype(np.uint8)
    ds = two_point_function(images, phase=1, r_max=20)
    np.testing.assert_allclose(ds["S2"].values[0], ds["phi_samples"].values.mean(), atol=1e-12)
    z = (ds["S2"].values[1:] - p**2) / ds["S2_sem"].values[1:]
    assert np.all(np.abs(z) < 4.5)


def test_rejects_r_max_beyond_half_image_and_wrong_rank():
    with pytest.raises(ValueError, match="must be < min"):
        RadialBinning.build((20, 40), 10.0)
    with pytest.raises(ValueError, match="n_samples"):
        two_point_function(np.zeros(10), phase=0, r_max=2)


def test_overlapping_disks_match_exact_s2_within_3_sem():
    """The slice's acceptance criterion at package level (independent seed from the workflow)."""
    radius, phi2 = 5.0, 0.3
    rng = np.random.default_rng(2020)
    images = np.stack([overlapping_disks_image(rng, 151, radius, phi2) for _ in range(30)])
    ds = two_point_function(images, phase=0, r_max=4 * radius)
    deviation = ds["S2"].values - s2_void(ds["r"].values, radius, phi2)
    assert np.all(np.abs(deviation) <= 3 * ds["S2_sem"].values)


def test_bin_labelling_bias_is_far_below_statistical_error():
    """Labelling a bin by its mean distance, vs the exact bin-average, costs < 1e-3."""
    radius, phi2 = 6.0, 0.3
    binning = RadialBinning.build((201, 201), 36.0)
    exact = lambda r: s2_void(r, radius, phi2)  # noqa: E731
    bias = np.abs(binning.average_of(exact) - exact(binning.r_mean))
    assert bias.max() < 1e-3


def test_displacements_at_exactly_r_max_are_kept():
    """(10, 0), (6, 8), ... lie at exactly r = 10: the last bin must hold all of them
    (float fftfreq grids put some at 10.000000000000002 and dropped them)."""
    binning = RadialBinning.build((101, 101), 10.0)
    vectors = {tuple(v) for v in binning.displacements()}
    for v in [(10, 0), (0, 10), (-10, 0), (6, 8), (-8, -6)]:
        assert v in vectors
    assert binning.counts[10] == sum(1 for v in vectors if round(np.hypot(*v)) == 10)


def test_angular_bin_weights_average_over_directions():
    """With angular weights a bin's mean is the trapezoid rule for the mean over directions:
    weights sum to 1 per bin, and an anisotropic modulation cos(4 theta) -- the symmetry of
    the pixel grid -- averages out far better than with equal weights per displacement
    (whose half-pixel annuli bunch along the axes in some bins)."""
    shape, m = (400, 400), 4  # a 100-pixel image on a 4 x 4 sub-pixel grid
    lattice = RadialBinning.build(shape, 24.0 * m / 4, 2.0)
    angular = RadialBinning.build(shape, 24.0 * m / 4, 2.0, angular=True)
    np.testing.assert_allclose(np.bincount(angular.bin_of, weights=angular.weight), 1.0, rtol=1e-12)
    np.testing.assert_array_equal(angular.counts, lattice.counts)
    d = angular.displacements()
    theta = np.arctan2(d[:, 0], d[:, 1])
    radial = 1.0 / (1.0 + angular.distance)
    for binning in (lattice, angular):
        field = np.zeros(int(np.prod(shape)))
        field[binning.flat_index] = radial * (1 + 0.5 * np.cos(4 * theta))
        relative = binning.average(field.reshape(shape)) / binning.average_of(lambda r: 1 / (1 + r)) - 1
        worst = np.abs(relative[2:]).max()  # from r = 1 px (4 sub-pixels)
        if binning is lattice:
            assert worst > 0.02
        else:
            assert worst < 0.008
    # labels: the weighted mean distance, inside each bin
    assert np.all(np.abs(angular.r_mean[1:] / 2.0 - np.arange(1, angular.counts.size)) <= 0.5)
    with pytest.raises(ValueError, match="2D"):
        RadialBinning.build((20, 20, 20), 5.0, angular=True)
