"""Helpers of the mrj2016 comparison: rounding margins, Gaussianity radius, lattices."""

import math

import numpy as np
import pytest

from randmedia.compare.mrj2016 import gaussian_radius, rounding_margin
from randmedia.generate import spheres


@pytest.mark.parametrize("text, margin", [("0.4148", 5e-5), ("2.135", 5e-4), ("1", 0.5), ("2.26e-1", 5e-4),
                                          ("2.45e-5", 5e-8), ("inf", 0.0), ("0.6356", 5e-5), ("1000", 0.5)])
def test_rounding_margin(text, margin):
    assert rounding_margin(text) == pytest.approx(margin)


def test_gaussian_radius():
    R = np.arange(0.5, 4.01, 0.5)
    skew = np.array([0.5, 0.3, 0.12, 0.05, 0.2, 0.05, 0.02, 0.01])
    kurt = np.zeros_like(R)
    throws = np.full(R.shape, 1000)
    assert gaussian_radius(R, skew, kurt, throws, threshold=0.15) == 3.0
    throws[4] = 10  # a noisy radius with few windows is ignored
    assert gaussian_radius(R, skew, kurt, throws, threshold=0.15) == 1.5
    assert math.isnan(gaussian_radius(R, skew + 1, kurt, throws))


def test_lattices_of_touching_spheres():
    for lattice, phi, z in (("fcc", math.pi / (3 * math.sqrt(2)), 12), ("bcc", math.pi * math.sqrt(3) / 8, 8)):
        assert spheres.lattice_packing_fraction(lattice) == pytest.approx(phi)
        x, box = spheres.lattice_spheres(lattice, 2)
        d = np.linalg.norm(x[:, None] - x[None], axis=-1)
        # nearest-neighbour distance D (within the cell, images aside)
        assert d[d > 0].min() == pytest.approx(1.0)
    assert spheres.lattice_covering_radius("bcc") == pytest.approx(math.sqrt(5 / 3) / 2)
    assert spheres.lattice_covering_radius("fcc") == pytest.approx(1 / math.sqrt(2))


def test_overlapping_spheres_sample():
    rng = np.random.default_rng(0)
    x, box = spheres.overlapping_spheres(rng, 0.636, 1000)
    rho = spheres.overlapping_intensity(0.636)
    assert rho == pytest.approx(-math.log(1 - 0.636) / (math.pi / 6))
    assert box[0, 0] ** 3 * rho == pytest.approx(1000)
    assert abs(len(x) - 1000) < 5 * math.sqrt(1000)
    assert np.all((x >= 0) & (x < box[0, 0]))
    x2, _ = spheres.overlapping_spheres(np.random.default_rng(0), 0.636, 1000)
    np.testing.assert_array_equal(x, x2)


def test_binning_systematic_uses_only_conventions_consistent_with_the_paper():
    """Away from the zeros of m(k) a convention must agree with the published values (median
    deviation <= k_sigma errors); each row's margin is the largest shift a consistent convention
    makes from ours -- large at a zero, zero elsewhere if the conventions agree there."""
    import pandas as pd

    from randmedia.compare.mrj2016 import BINNING_PREFIX, binning_systematic

    kD = np.array([7.9, 8.5, 9.1, 9.7, 10.2])  # 9.1 is next to the zero 8.987
    published = pd.DataFrame({"kD": kD.astype(str), "chiV_over_D3": [1.0, 0.5, 0.01, 0.3, 0.6],
                              "sem_over_D3": 0.01})
    ours = pd.DataFrame({"kD": kD, "chiV_over_D3": [1.0, 0.5, 0.005, 0.3, 0.6], "sem_over_D3": 0.01})
    for name, values in (("bin_width", [1.0, 0.5, 0.005, 0.3, 0.6]),     # ours
                         ("wide", [1.01, 0.49, 0.012, 0.31, 0.6]),       # consistent, differs at the zero
                         ("shifted", [1.3, 0.8, 0.2, 0.6, 0.9]),         # inconsistent everywhere
                         ("absent", [np.nan] * 5)):                      # does not apply
        ours[f"{BINNING_PREFIX}{name}_over_D3"] = values
        ours[f"{BINNING_PREFIX}{name}_sem_over_D3"] = 0.01
    margin, consistent = binning_systematic(ours, published, k_sigma=3.0)
    assert consistent == ["bin_width", "wide"]
    np.testing.assert_allclose(margin, [0.01, 0.01, 0.007, 0.01, 0.0], atol=1e-12)
    # without other conventions: no margin
    margin, consistent = binning_systematic(ours[["kD", "chiV_over_D3", "sem_over_D3"]], published, 3.0)
    assert consistent == [] and (margin == 0).all()
