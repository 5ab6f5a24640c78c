"""Helpers of the mrj2016 comparison: rounding margins, Gaussianity radius, lattices."""

import math

import numpy as np
import pytest

from randmedia.compare.mrj2016 import gaussian_radius, rounding_margin
from randmedia.generate import spheres
from randmedia.theory.balls import poisson_intensity


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
    rho = poisson_intensity(0.636, 0.5, 3)
    assert rho == pytest.approx(-math.log(1 - 0.636) / (math.pi / 6))
    assert box[0, 0] ** 3 * rho == pytest.approx(1000)
    assert abs(len(x) - 1000) < 5 * math.sqrt(1000)
    assert np.all((x >= 0) & (x < box[0, 0]))
    x2, _ = spheres.overlapping_spheres(np.random.default_rng(0), 0.636, 1000)
    np.testing.assert_array_equal(x, x2)



def test_spectral_table_takes_the_configured_reading_of_the_bins_where_it_applies(tmp_path, monkeypatch):
    """Table IV's chi_V is the configured reading (grid_spacing) when it applies to every row,
    else our bins of table_bin_width; every reading stays as a column."""
    import pandas as pd
    import xarray as xr

    from randmedia.compare.mrj2016 import BINNING_PREFIX, table_spectral
    from randmedia.describe.spectral import TABLE_BINNINGS

    kD = [0.6, 1.1]
    reference = tmp_path / "table4.csv"
    pd.DataFrame({"kD": kD, "chiV_over_D3": [1.0, 2.0], "sem_over_D3": [0.1, 0.1]}).to_csv(reference, index=False)

    def spec(grid_values):
        values = np.ones((2, len(TABLE_BINNINGS), 2))  # (sample, binning, k)
        values[:, TABLE_BINNINGS.index("grid_spacing")] = grid_values
        ds = xr.Dataset({"chi_table_mean": ("k_table", [1.0, 1.0]), "chi_table_sem": ("k_table", [0.0, 0.0]),
                         "k_table_count": (("sample", "k_table"), np.ones((2, 2))),
                         "chi_table_binning_mean": (("binning", "k_table"), values.mean(axis=0)),
                         "chi_table_binning_sem": (("binning", "k_table"), np.zeros((len(TABLE_BINNINGS), 2))),
                         "binning_count": (("sample", "binning", "k_table"), np.full(values.shape, 3.0)),
                         "binning_width": (("sample", "binning"), np.full((2, len(TABLE_BINNINGS)), 0.3))},
                        coords={"k_table": kD, "binning": list(TABLE_BINNINGS)}, attrs={"table_width": 0.133})
        path = tmp_path / "spectral.nc"
        ds.to_netcdf(path)
        return str(path)

    import randmedia.compare.mrj2016 as module

    for grid_values, expected, reading in (([5.0, 6.0], [5.0, 6.0], "grid_spacing"),
                                           ([np.nan, np.nan], [1.0, 1.0], "bin_width")):
        path = spec(grid_values)
        monkeypatch.setattr(module, "_load", lambda inputs, kind, system, path=path: xr.open_dataset(path))
        table = table_spectral({"reference": reference}, {"spectral_binning": "grid_spacing"}, 4)
        assert table["chiV_over_D3"].tolist() == expected and (table["binning"] == reading).all()
        assert f"{BINNING_PREFIX}grid_spacing_over_D3" in table and f"{BINNING_PREFIX}labels_over_D3" in table


def test_eq11_note_of_one_sample_says_it_has_no_sem():
    """The reason of a failing Table V row quotes Eq. (11) of our S2; with one sample (Table V's
    first N = 10 000 packing) there is no SEM over samples, and the note says so instead of nan."""
    import xarray as xr

    from randmedia.compare.mrj2016 import _eq11_note

    k = np.array([8.9, 9.1])
    one = xr.Dataset({"chi_ft_mean": ("k_ft", [1e-5, 2e-5]), "chi_ft_sem": ("k_ft", [np.nan, np.nan])},
                     coords={"k_ft": k})
    assert _eq11_note(one, 9.0) == "; Eq. (11) of our S2 gives 1.5e-05 D^3 (one sample: no SEM over samples) at this kD"
    two = one.assign(chi_ft_sem=("k_ft", [1e-6, 1e-6]))
    assert _eq11_note(two, 9.0).endswith("1.5e-05 +- 1e-06 D^3 at this kD")


def _phi_ensemble(phis, n):
    """Packings of n spheres with packing fractions phis (what phi_mean_sem reads)."""
    import xarray as xr

    return xr.Dataset({"eta": ("sample", phis), "n": ("sample", [n] * len(phis))})


def test_phi_of_one_large_packing_takes_its_sem_from_the_smaller_ensemble():
    """The Fig. 6 row (N = 10 000, phi = 0.637): with one packing its SEM is the SD of the
    N = 2000 ensemble scaled by (2000 / 10 000)^(1/2), and the note says so; with two or more,
    the SEM over the packings themselves."""
    from randmedia.compare.mrj2016 import phi_mean_sem

    small = _phi_ensemble([0.634, 0.636, 0.635], 2000)
    mean, sem, note = phi_mean_sem(_phi_ensemble([0.6370], 10000), small)
    assert mean == 0.6370 and sem == pytest.approx(0.001 * math.sqrt(0.2))
    assert "one sample" in note and "0.00045" in note
    mean, sem, note = phi_mean_sem(_phi_ensemble([0.6370, 0.6360], 10000), small)
    assert (mean, note) == (pytest.approx(0.6365), "") and sem == pytest.approx(0.0005)
    assert math.isnan(phi_mean_sem(None, small)[0])
    assert math.isnan(phi_mean_sem(_phi_ensemble([0.637], 10000), None)[1])


def test_fig6_label_is_compared_where_the_large_packings_are_made(monkeypatch, tmp_path):
    """The N = 10 000 packings' phi against Fig. 6's label 0.637, which the transcribed quoted
    numbers leave out: one row when mrj_large has samples (its SEM from the N = 2000 ensemble),
    none when it has none; a packing off by 3e-3 fails."""
    from randmedia.compare import comparison_frame
    from randmedia.compare import mrj2016 as compare_mrj

    reference = tmp_path / "quoted.csv"
    reference.write_text("quantity,system,value,unit,where\n")
    data = {("correlation", "mrj"): _phi_ensemble([0.634, 0.636, 0.635], 2000)}
    monkeypatch.setattr(compare_mrj, "_load", lambda inputs, kind, system: data.get((kind, system)))

    def rows(phi_large, n_large):
        data[("spectral", "mrj_large")] = _phi_ensemble([phi_large], 10000)
        collected = compare_mrj.Rows(k_sigma=3.0)
        compare_mrj._quoted_rows(collected, reference, {}, {"n_samples": {"mrj": 3, "mrj_large": n_large}})
        return comparison_frame(collected.rows)

    assert rows(0.6373, 0).empty
    frame = rows(0.6373, 1)
    assert frame[["quantity", "key"]].values.tolist() == [["packing_fraction", "mrj_large"]]
    assert frame["published"].iloc[0] == 0.637 and frame["ours"].iloc[0] == 0.6373
    assert frame["ours_sem"].iloc[0] == pytest.approx(0.001 * math.sqrt(0.2))
    assert frame["passed"].iloc[0]
    assert not rows(0.640, 1)["passed"].iloc[0]
