"""d-generic shell counts of the YT construction (2D and 3D): exact against brute force."""

import numpy as np
import pytest

from randmedia.generate.yt_stencil import Stencil, apply_flips, count_dtype, shell_counts
from randmedia.numerics.radial import RadialBinning


def brute_force_counts(image, cutoff):
    """h[x, b - 1] = sum over v with |v| <= cutoff in bin b of image[x + v] (np.roll)."""
    binning = RadialBinning.build(image.shape, cutoff)
    h = np.zeros((image.size, binning.counts.size - 1), dtype=np.int64)
    axes = tuple(range(image.ndim))
    for v, b in zip(binning.displacements(), binning.bin_of):
        if b == 0:
            continue
        h[:, b - 1] += np.roll(image, tuple(-c for c in v), axis=axes).reshape(-1)
    return h


@pytest.mark.parametrize("shape, cutoff", [((12, 13, 14), 4.5), ((11, 11, 11), 5.0),
                                           ((9, 16, 10), 4.0), ((17, 15), 7.0),
                                           ((41, 41), 20.0), ((13, 14, 13), 6.4),
                                           ((14, 14, 14), 6.9)])
def test_shell_counts_fft_and_flips_equal_brute_force(shape, cutoff):
    """Also with shells out to ~0.49 of the box (41^2, l_c = 20: the 2D long-range stages),
    where a stencil's reach wraps almost all the way round."""
    rng = np.random.default_rng(sum(shape))
    image = (rng.random(shape) < 0.35).astype(np.uint8)
    stencil = Stencil(shape, cutoff)
    expected = brute_force_counts(image, cutoff)
    np.testing.assert_array_equal(shell_counts(image, stencil), expected)
    # the smallest unsigned type that holds the fullest shell
    assert stencil.count_dtype == (np.uint8 if stencil.binning.counts[1:].max() <= 255 else np.uint16)
    # every tracked voxel applied as a +1 flip to zero counts
    h = np.zeros((image.size, stencil.n_columns), dtype=stencil.count_dtype)
    tracked = np.flatnonzero(image)
    apply_flips(h, stencil, tracked, np.ones(tracked.size, dtype=np.int16))
    np.testing.assert_array_equal(h, expected)
    # counts that pass below zero within a batch wrap and come back exact
    h[:] = 0
    apply_flips(h, stencil, tracked, -np.ones(tracked.size, dtype=np.int16))
    assert h.max() > expected.max()  # wrapped round
    apply_flips(h, stencil, np.concatenate([tracked, tracked]), np.ones(2 * tracked.size, dtype=np.int16))
    np.testing.assert_array_equal(h, expected)


def test_a_batch_of_swaps_gives_the_counts_of_the_new_image_3d():
    rng = np.random.default_rng(5)
    shape = (14, 12, 13)
    image = (rng.random(shape) < 0.3).astype(np.uint8).reshape(-1)
    stencil = Stencil(shape, 5.5)
    h = shell_counts(image.reshape(shape), stencil)
    flips, signs = [], []
    for _ in range(60):  # swaps: one voxel of each phase (a voxel may flip more than once)
        p = rng.choice(np.flatnonzero(image == 1))
        q = rng.choice(np.flatnonzero(image == 0))
        image[p], image[q] = 0, 1
        flips += [p, q]
        signs += [-1, 1]
    apply_flips(h, stencil, np.array(flips), np.array(signs))
    np.testing.assert_array_equal(h, shell_counts(image.reshape(shape), stencil))


def test_column_table_by_squared_length_matches_the_bins():
    stencil = Stencil((20, 21, 22), 7.3)
    d2 = (stencil.offsets**2).sum(axis=1)
    np.testing.assert_array_equal(stencil.column_of_d2[d2], stencil.column)
    outside = np.setdiff1d(np.arange(stencil.column_of_d2.size), d2)
    assert np.all(stencil.column_of_d2[outside] == -1)
    # clamped lookups: every displacement longer than l_c lands on the last entry, -1
    assert stencil.d2_limit == stencil.column_of_d2.size - 1 == d2.max() + 1
    assert stencil.column_of_d2[-1] == -1
    assert stencil.offsets.shape == (int(stencil.binning.counts[1:].sum()), 3)


def test_rejects_bad_shapes_and_overflowing_shells():
    with pytest.raises(ValueError, match="shape"):
        Stencil((5,), 1.0)
    stencil = Stencil((12, 12, 12), 3.0)
    with pytest.raises(ValueError, match="must be uint8"):
        apply_flips(np.zeros((12**3, stencil.n_columns), dtype=np.int32), stencil, [0], [1])
    with pytest.raises(ValueError, match="shape"):
        shell_counts(np.zeros((12, 12)), stencil)


def test_count_type_is_the_smallest_unsigned_type_holding_the_fullest_shell():
    assert [count_dtype(n) for n in (0, 255, 256, 65535, 65536, 2**32 - 1)] == [
        np.uint8, np.uint8, np.uint16, np.uint16, np.uint32, np.uint32]
    with pytest.raises(ValueError, match="uint32"):
        count_dtype(2**32)
