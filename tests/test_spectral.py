"""Spectral density (Klatt & Torquato 2016, Sec. IV): NUFFT structure factor, form factor, Eq. (11)."""

import itertools
import math

import numpy as np
import pytest
from scipy.integrate import quad

from mrj_helpers import TRICLINIC, rsa_packing
from randmedia.describe import spectral
from randmedia.generate.spheres import bragg_peak_count, lattice_spheres
from randmedia.theory import overlapping as theory


def test_allowed_wavevectors_are_the_reciprocal_lattice_of_a_triclinic_cell():
    k_max = 6.0
    n, k, kmag = spectral.allowed_wavevectors(TRICLINIC, k_max)
    inverse = np.linalg.inv(TRICLINIC)
    expected = set()
    for v in itertools.product(range(-12, 13), repeat=3):
        kk = 2 * math.pi * np.array(v) @ inverse
        if 0 < np.linalg.norm(kk) <= k_max:
            expected.add(v)
    found = {tuple(v) for v in n}
    assert len(found) == len(n) == len(expected) // 2  # one of each +-k
    assert all(v in expected and tuple(-np.array(v)) not in found for v in found)
    np.testing.assert_allclose(k, 2 * math.pi * n @ inverse, atol=1e-12)
    np.testing.assert_allclose(kmag, np.linalg.norm(k, axis=1), rtol=1e-13)


def test_nufft_agrees_with_the_direct_sum_to_1e6_relative():
    rng = np.random.default_rng(0)
    x = rsa_packing(rng, TRICLINIC, 150)
    _, k, kmag, S = spectral.structure_factor(x, TRICLINIC, 20.0)
    direct = spectral.structure_factor_direct(x, k)
    assert np.max(np.abs(S - direct) / direct) < 1e-6
    # S is invariant under translation and wrapping of the positions
    _, _, _, S_shifted = spectral.structure_factor(x + [3.3, -7.1, 40.2], TRICLINIC, 20.0)
    np.testing.assert_allclose(S_shifted, S, rtol=1e-6, atol=1e-9)


@pytest.mark.parametrize("lattice, cells", [("fcc", 3), ("bcc", 4)])
def test_lattice_bragg_peaks(lattice, cells):
    """S(k) = N exactly at the reciprocal-lattice vectors of the crystal, 0 at every other k."""
    x, box = lattice_spheres(lattice, cells, rng=np.random.default_rng(1))
    n_vec, _, _, S = spectral.structure_factor(x, box, 20.0)
    N = len(x)
    peaks = S > N / 2
    assert peaks.sum() == bragg_peak_count(lattice, 20.0)
    np.testing.assert_allclose(S[peaks], N, rtol=1e-8)
    assert S[~peaks].max() < 1e-8 * N
    # the peaks sit at n / cells = (h, k, l) obeying the selection rule
    hkl = n_vec[peaks] / cells
    assert np.allclose(hkl, np.round(hkl))


def test_form_factor_limits_and_zeros():
    D = 1.0
    assert spectral.sphere_form_factor(0.0, D) == pytest.approx(math.pi / 6)
    assert spectral.sphere_form_factor(1e-3, D) == pytest.approx(math.pi / 6, rel=1e-6)
    k = np.linspace(0.1, 20, 50)
    x = k * D / 2
    closed = 4 * math.pi * (D / 2) ** 3 * (np.sin(x) - x * np.cos(x)) / x**3  # 3D ball
    np.testing.assert_allclose(spectral.sphere_form_factor(k, D), closed, rtol=1e-12)
    zeros = spectral.form_factor_zeros(20.0, D)
    np.testing.assert_allclose(np.tan(zeros / 2), zeros / 2, rtol=1e-9)  # tan x = x
    np.testing.assert_allclose(zeros, [8.9868189, 15.4505037], rtol=1e-7)
    assert spectral.sphere_form_factor(1.0, dim=2) == pytest.approx(
        math.pi / 1.0 * __import__("scipy").special.jv(1, 0.5), rel=1e-12)


def test_eq11_transform_of_the_exact_overlapping_autocovariance():
    """Simpson on a grid (the estimator used for packings) against adaptive quadrature, and
    chi_V(0) = 4 pi integral chi r^2 dr."""
    phi = 0.636
    r = np.linspace(0, 1.5, 1501)
    chi = theory.s2_void(r, 0.5, phi, 3) - (1 - phi) ** 2
    k = np.array([0.0, 0.5, 3.0, 9.0, 17.0])
    grid = spectral.spectral_density_from_autocovariance(r, chi, k)
    exact = spectral.overlapping_spectral_density(k, phi)
    np.testing.assert_allclose(grid, exact, rtol=1e-6, atol=1e-9)
    zero = 4 * math.pi * quad(lambda t: (theory.s2_void(t, 0.5, phi, 3) - (1 - phi) ** 2) * t * t, 0, 1)[0]
    assert exact[0] == pytest.approx(zero, rel=1e-9)
    assert spectral.smallest_reliable_k(10.0) == pytest.approx(2 * math.pi / 10)


def test_bin_means_and_centred_bins():
    k = np.array([0.1, 0.15, 0.3, 0.31, 0.5])
    v = np.array([1.0, 3.0, 5.0, 7.0, 9.0])
    mean, count, kmean = spectral.bin_means(k, v, [0.0, 0.2, 0.4])
    np.testing.assert_allclose(mean, [2.0, 6.0])
    np.testing.assert_allclose(count, [2, 2])
    np.testing.assert_allclose(kmean, [0.125, 0.305])
    mean, count, _ = spectral.centred_bin_means(k, v, [0.3, 0.5], 0.1)
    np.testing.assert_allclose(mean, [6.0, 9.0])
    with pytest.raises(ValueError, match="overlap"):
        spectral.centred_edges([0.3, 0.35], 0.1)


def test_direct_spectral_density_of_a_packing_matches_eq11_at_large_k():
    """For one periodic hard-sphere packing the two routes of Fig. 6 agree where the Eq. (11)
    cutoff does not matter (large k: chi_V(k) is dominated by the single-sphere term)."""
    from randmedia.describe import packings

    rng = np.random.default_rng(2)
    box = np.eye(3) * 8.0
    x = rsa_packing(rng, box, 250)
    rho = len(x) / 512.0
    _, _, kmag, S = spectral.structure_factor(x, box, 20.0)
    chi_direct = spectral.spectral_density_direct(kmag, S, rho)
    r = np.arange(0, packings.max_radius(box), 0.005)
    f = packings.correlation_functions(x, box, r)
    centres = np.array([12.0, 17.0])
    direct, _, kk = spectral.centred_bin_means(kmag, chi_direct, centres, 1.0)
    ft = spectral.spectral_density_from_autocovariance(r, f["S2"] - f["phi"] ** 2, kk)
    np.testing.assert_allclose(direct, ft, rtol=0.25)


def test_table_iv_labels_are_the_shells_of_the_liquid_cell():
    """Table IV's kD are m * 4 pi / L of the N = 10 000, phi = 0.478 cube, rounded; Table V's are not."""
    import pandas as pd

    from conftest import REPO

    table4 = pd.read_csv(REPO / "config/reference/mrj2016_table4_spectral_equilibrium.csv")["kD"]
    side = (10_000 * math.pi / 6 / 0.478) ** (1 / 3)
    centres, snapped = spectral.snap_to_shells(table4, np.eye(3) * side)
    assert snapped
    np.testing.assert_allclose(centres, np.arange(1, 32) * 4 * math.pi / side)
    assert np.all(np.abs(centres - table4) < 0.07)
    table5 = pd.read_csv(REPO / "config/reference/mrj2016_table5_spectral_mrj.csv")["kD"]
    assert not spectral.snap_to_shells(table5, np.eye(3) * 20.2)[1]
    assert not spectral.snap_to_shells(table4, np.eye(3) * 8.2)[1]  # another cell size
    assert not spectral.snap_to_shells(table4, np.diag([side, side, side + 1]))[1]  # not cubic


def test_table_binnings_of_the_liquid_cell():
    """The readings of Table IV's bins: ours, the single shell |n| = 2m (exactly the wavevectors
    with |n|^2 = 4 m^2), one grid spacing, contiguous bins of the table spacing, the labels."""
    side = 22.2
    labels = np.array([0.6, 1.1, 1.7])
    centres, snapped = spectral.snap_to_shells(labels, np.eye(3) * side)
    assert snapped
    binnings = spectral.table_binnings(labels, centres, np.eye(3) * side, 0.133)
    assert tuple(binnings) == spectral.TABLE_BINNINGS
    grid = 2 * math.pi / side
    assert binnings["grid_spacing"][1] == pytest.approx(grid)
    assert binnings["table_spacing"][1] == pytest.approx(2 * grid)
    np.testing.assert_array_equal(binnings["labels"][0], labels)
    # wavevectors of the cube (half space is irrelevant here: count both signs) and a value per vector
    n = np.array(list(itertools.product(range(-7, 8), repeat=3)), dtype=float)
    kmag = grid * np.linalg.norm(n, axis=1)
    values = (n ** 2).sum(axis=1)  # |n|^2, so each bin mean tells which shells it took
    means, counts, _ = spectral.binned_table_values(kmag, values, binnings)
    single = list(binnings).index("single_shell")
    for m in (1, 2, 3):
        assert counts[single, m - 1] == np.sum(values == 4 * m * m)
        assert means[single, m - 1] == 4 * m * m
    tiling = list(binnings).index("table_spacing")
    # contiguous bins: |n| in [2m - 1, 2m + 1)
    for m in (1, 2, 3):
        norm = np.sqrt(values)
        assert counts[tiling, m - 1] == np.sum((norm >= 2 * m - 1 - 1e-9) & (norm < 2 * m + 1 - 1e-9))
    # on a cell whose shells the centres are not, single_shell does not apply
    other = spectral.table_binnings(labels, labels, np.eye(3) * 20.0, 0.133)
    assert np.isnan(other["single_shell"][0]).all() and np.isnan(other["labels"][0]).all()
    means, counts, _ = spectral.binned_table_values(kmag, values, other)
    assert np.isnan(means[list(other).index("single_shell")]).all()
    assert (counts[list(other).index("labels")] == 0).all()


def test_spectral_samples_record_every_binning_and_ours_is_the_table():
    """The table's own bins (bin_width) are chi_table exactly; each convention is stored with
    its wavevector counts and widths (studies.mrj2016.spectral_samples)."""
    from randmedia.studies.mrj2016 import spectral_samples

    side = 6.0
    box = np.eye(3) * side
    rng = np.random.default_rng(5)
    configs = [(rsa_packing(rng, box, 60), box, 1.0) for _ in range(2)]
    labels = np.round(np.arange(1, 6) * 4 * math.pi / side, 1)
    ds = spectral_samples(configs, k_max=12.0, bin_width=0.2, table_k=labels, table_width=0.2, snap_table=True)
    assert ds.attrs["table_bins"].startswith("cubic-cell shells")
    assert list(ds["binning"].values) == list(spectral.TABLE_BINNINGS)
    np.testing.assert_array_equal(ds["chi_table_binning"].sel(binning="bin_width").values, ds["chi_table"].values)
    widths = ds["binning_width"].isel(sample=0)
    assert widths.sel(binning="grid_spacing") == pytest.approx(2 * math.pi / side)
    counts = ds["binning_count"].isel(sample=0)
    # the contiguous bins hold every wavevector from half a spacing below the first shell on
    assert (counts.sel(binning="table_spacing") >= counts.sel(binning="grid_spacing")).all()
    assert (counts.sel(binning="single_shell") > 0).all()


def test_table_binnings_of_a_cell_smaller_than_the_table_spacing():
    """Table V's 0.6 m on a cell of 5 D: one grid spacing (1.26/D) would overlap neighbours."""
    labels = np.arange(1, 6) * 0.6
    binnings = spectral.table_binnings(labels, labels, np.eye(3) * 5.0, 0.133)
    assert np.isnan(binnings["grid_spacing"][0]).all()
    assert not np.isnan(binnings["table_spacing"][0]).any()
    means, counts, _ = spectral.binned_table_values(np.array([0.6, 1.2]), np.array([1.0, 2.0]), binnings)
    assert means[list(binnings).index("bin_width")].tolist()[:2] == [1.0, 2.0]


def test_bin_sems_of_known_values():
    """sqrt(sum v^2 / 2) / M per bin; NaN where the bin is empty; one value is an SEM too."""
    k = np.array([0.1, 0.15, 0.3, 0.9])
    v = np.array([1.0, 3.0, 5.0, 7.0])
    sems = spectral.bin_sems(k, v, [0.0, 0.2, 0.4, 0.6])
    np.testing.assert_allclose(sems[:2], [math.sqrt(5.0) / 2, 5.0 / math.sqrt(2.0)])
    assert np.isnan(sems[2])


def test_within_bin_sem_of_uniform_points_is_their_spread_over_samples():
    """Known answer: for N uniform points S(k) has mean 1 and variance 1 - 1/N at every allowed
    k != 0, independent over a half space, so a bin of M wavevectors has SEM sqrt(1 - 1/N) / sqrt(M);
    bin_sems of one sample estimates it, and the SD of the bin means over 40 samples agrees
    (pooled over the bins; a missing factor 2 in bin_sems would give a ratio of 2)."""
    rng = np.random.default_rng(11)
    n, edges = 300, np.arange(2.0, 8.01, 0.5)
    means, sems = [], []
    for _ in range(40):
        positions = rng.random((n, 3)) @ TRICLINIC.T
        _, _, kmag, S = spectral.structure_factor(positions, TRICLINIC, 8.0)
        mean, count, _ = spectral.bin_means(kmag, S, edges)
        means.append(mean), sems.append(spectral.bin_sems(kmag, S, edges))
    means, sems = np.array(means), np.array(sems)
    assert count.min() >= 20
    exact = np.sqrt((1 - 1 / n) / count)
    # each sample's estimate scatters by ~1.1/sqrt(M); the rms over 40 samples by ~4 % (M >= 20)
    np.testing.assert_allclose(np.sqrt((sems ** 2).mean(axis=0)), exact, rtol=0.12)
    ratio = means.var(axis=0, ddof=1).sum() / (sems ** 2).mean(axis=0).sum()
    assert ratio == pytest.approx(1.0, abs=0.2)  # 12 bins, each variance +-23 %: pooled ~ +-8 %


def test_one_sample_of_a_disordered_system_has_the_within_bin_sem():
    """studies.mrj2016.summarize: the SEM of the spectral means is at least the samples' own
    within-bin errors combined, sqrt(sum sem_i^2) / n; one sample keeps its own; a lattice
    (expected_peaks) gets no such floor."""
    from randmedia.studies.mrj2016 import spectral_samples, summarize

    box = TRICLINIC
    rng = np.random.default_rng(3)
    labels = np.array([2.0, 4.0, 6.0])
    chunks = [spectral_samples([(rsa_packing(rng, box, 150), box, 1.0)], k_max=8.0, bin_width=0.5,
                               table_k=labels, table_width=0.5, first=i) for i in range(2)]
    one = summarize(chunks[:1], "spectral")
    own = one["chi_table_bin_sem"].isel(sample=0).values
    assert np.isfinite(own).all() and (own > 0).all()
    np.testing.assert_array_equal(one["chi_table_sem"].values, own)
    np.testing.assert_array_equal(one["chi_table_binning_sem"].values,
                                  one["chi_table_binning_bin_sem"].isel(sample=0).values)
    two = summarize(chunks, "spectral")
    floor = np.sqrt((two["chi_table_bin_sem"].values ** 2).sum(axis=0)) / 2
    spread = two["chi_table"].std("sample", ddof=1).values / math.sqrt(2)
    np.testing.assert_allclose(two["chi_table_sem"].values, np.fmax(spread, floor))
    lattice = spectral_samples([(rsa_packing(rng, box, 150), box, 1.0)], k_max=8.0, bin_width=0.5,
                               bragg=0)
    assert np.isnan(summarize([lattice], "spectral")["chi_sem"].values).all()
