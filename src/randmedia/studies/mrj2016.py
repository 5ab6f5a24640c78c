"""Klatt & Torquato 2016 (mrj2016): per-sample descriptor datasets of its periodic sphere
configurations, and their merge into one file per system and descriptor kind.

The estimators live in :mod:`~randmedia.describe.packings` (Appendix A),
:mod:`~randmedia.describe.spectral` (Sec. IV) and :mod:`~randmedia.describe.points`
(Secs. V-VI). Here each is run over a list of configurations (one chunk of a
system's samples) into an xarray Dataset with a ``sample`` dimension, and the
chunks of a system are concatenated and summarized: ``{name}_mean`` and
``{name}_sem`` (standard error over samples, :mod:`~randmedia.describe.averages`)
for every per-sample curve.

Every function takes configurations as (positions, box, diameter) triples in
units of D; Monte Carlo estimators take one numpy Generator per sample.

Why here and not in :mod:`randmedia.describe`: describe/ holds estimators any
configuration or paper can use. This module is the paper's protocol -- its four
descriptor kinds and the config sections each reads, the paper's grids and table
wavenumbers (Figs. 6, 9; Tables II-V), the seeds keyed by ``"mrj2016"``, the
variable names :mod:`randmedia.compare.mrj2016` and :mod:`randmedia.plot.mrj2016`
read -- the describe-stage counterpart of those two per-paper modules, run by the
rules ``mrj2016_describe_chunk`` and ``mrj2016_describe``.
"""

from __future__ import annotations

import math
from typing import Iterable, Sequence

import numpy as np
import xarray as xr

from randmedia.describe import packings, points, spectral
from randmedia.describe.averages import nan_mean_sem
from randmedia.progress import Progress

#: variables of each kind that are averaged over samples (mean + SEM added by :func:`merge`)
AVERAGED = {
    "correlation": packings.CORRELATION_VARIABLES + ("F_sv_over_s", "F_ss_over_s2",
                                                   "F_sv_two_body_over_s", "F_ss_two_body_over_s2"),
    "spectral": ("chi", "S", "chi_table", "chi_table_binning"),
    "points": ("E_V", "F"),
}

#: suffix of a spectral variable's per-sample within-bin SEM (:func:`spectral.bin_sems`)
WITHIN_SEM = "_bin_sem"


def load_configuration(path):
    """(positions, box, diameter) of one PARTICLE_CONFIG file (units D, diameter attr)."""
    from randmedia.generate import PARTICLE_CONFIG
    from randmedia.io import DataFileError, read_dataset

    ds = read_dataset(path, PARTICLE_CONFIG, attrs=["diameter"])
    positions, box = ds["position"].values, ds["box"].values
    if positions.shape[1] != 3 or box.shape != (3, 3):
        raise DataFileError(f"{path}: expected a 3D configuration, got positions {positions.shape}, "
                            f"box {box.shape}")
    return positions, box, float(ds.attrs["diameter"])


def _sample_coord(n, first=0):
    return ("sample", np.arange(first, first + n), {"units": "1", "long_name": "sample index"})


def _meta(units, long_name):
    return {"units": units, "long_name": long_name}


def _scalars(configs):
    """phi (as if the spheres did not overlap), rho, n, volume, h_w per sample."""
    from randmedia.periodic import Cell

    rows = []
    for positions, box, diameter in configs:
        cell = Cell(box)
        n = len(positions)
        rows.append((n * math.pi * diameter**3 / 6 / cell.volume, n / cell.volume, n, cell.volume,
                     cell.half_width))
    a = np.array(rows, dtype=float)
    return {
        "eta": (("sample",), a[:, 0], _meta("1", "N v_D / V (packing fraction if no overlaps)")),
        "rho": (("sample",), a[:, 1], _meta("1/D^3", "number density N / V")),
        "n": (("sample",), a[:, 2], _meta("1", "number of spheres")),
        "volume": (("sample",), a[:, 3], _meta("D^3", "cell volume")),
        "half_width": (("sample",), a[:, 4], _meta("D", "half the smallest face distance h_w")),
    }


# --------------------------------------------------------------------------- correlation functions


def correlation_samples(configs: Sequence, *, r_step: float, r_max: float, contact_r: float,
                        first: int = 0, progress: Progress | None = None) -> xr.Dataset:
    """Appendix-A S2, F_sv, F_ss, F*_sv, F*_ss and contact numbers of each configuration.

    Grid r = 0, r_step, ... <= r_max; a sample's values are NaN where r >= h_w - D
    of its cell (Eq. A8), so that samples of different cells share one grid.

    Parameters
    ----------
    configs : sequence of (positions, box, diameter)
        Configurations in units of D: positions (n, 3), box (3, 3), diameter.
    r_step : float
        Spacing of the r grid (D).
    r_max : float
        Largest r of the grid (D).
    contact_r : float
        Gap below which two spheres count as in contact for ``n_within`` (D).
    first : int
        Index of the first sample (the ``sample`` coordinate starts there; default 0).
    progress : Progress or None
        Stepped once per configuration; None for no progress log.

    Returns
    -------
    xarray.Dataset
        Variables on (sample, r) and per-sample scalars, units in their attrs; attrs ``kind`` =
        "correlation" and ``contact_r``.
    """
    r = np.arange(int(math.floor(r_max / r_step + 1e-9)) + 1) * r_step
    out = {name: [] for name in packings.CORRELATION_VARIABLES}
    extra = {name: [] for name in ("phi", "s", "z_B3", "z_B4", "n_within")}
    for positions, box, diameter in configs:
        valid = r < packings.max_radius(box, diameter) - 1e-12
        values = packings.correlation_functions(positions, box, r[valid], diameter)
        for name in packings.CORRELATION_VARIABLES:
            full = np.full(r.shape, np.nan)
            full[valid] = values[name]
            out[name].append(full)
        extra["phi"].append(values["phi"])
        extra["s"].append(values["s"])
        contacts = packings.contact_number(positions, box, diameter, contact_r)
        for name in ("z_B3", "z_B4", "n_within"):
            extra[name].append(contacts[name])
        _step(progress)
    per = {name: np.array(v) for name, v in out.items()}
    s = np.array(extra["s"])[:, None]
    per["F_sv_over_s"] = per["F_sv"] / s
    per["F_ss_over_s2"] = per["F_ss"] / s**2
    per["F_sv_two_body_over_s"] = per["F_sv_two_body"] / s
    per["F_ss_two_body_over_s2"] = per["F_ss_two_body"] / s**2
    meta = {
        "S2": ("1", "two-point correlation function of the sphere phase (Eq. A1)"),
        "F_sv": ("1/D", "surface-void correlation function, matrix = void (Eqs. A12, 7)"),
        "F_ss": ("1/D^2", "surface-surface correlation function (Eq. A16)"),
        "F_sv_two_body": ("1/D", "two-body part F*_sv (Eq. B1)"),
        "F_ss_two_body": ("1/D^2", "two-body part F*_ss (Eq. B2)"),
        "F_sv_over_s": ("1", "F_sv / s"), "F_ss_over_s2": ("1", "F_ss / s^2"),
        "F_sv_two_body_over_s": ("1", "F*_sv / s"), "F_ss_two_body_over_s2": ("1", "F*_ss / s^2"),
    }
    data = {name: (("sample", "r"), per[name], _meta(*meta[name])) for name in per}
    data.update(_scalars(configs))
    scalar_meta = {"phi": ("1", "packing fraction N v_D / V"), "s": ("1/D", "specific surface N a_D / V"),
                   "z_B3": ("1", "mean contact number from the slope of F*_sv (Eq. B3)"),
                   "z_B4": ("1", "mean contact number from F*_ss(0+) (Eq. B4)"),
                   "n_within": ("1", "2 x number of pairs with gap < contact_r, per sphere")}
    for name, values in extra.items():
        data[name] = (("sample",), np.array(values, dtype=float), _meta(*scalar_meta[name]))
    return xr.Dataset(data, coords={"r": ("r", r, _meta("D", "distance r")),
                                    "sample": _sample_coord(len(per["S2"]), first)},
                      attrs={"kind": "correlation", "contact_r": float(contact_r)})


def autocovariance_transform(ds: xr.Dataset, k) -> xr.Dataset:
    """Eq. (11) per sample: chi_V(k) from chi_V(r) = S2(r) - phi^2 up to the grid's r_max."""
    r = ds["r"].values
    chi_r = ds["S2"].values - ds["phi"].values[:, None] ** 2
    k = np.asarray(k, dtype=float)
    chi_k = spectral.spectral_density_from_autocovariance(r, chi_r, k)
    out = xr.Dataset(
        {"chi_ft": (("sample", "k_ft"), chi_k,
                    _meta("D^3", "spectral density by the Fourier transform of chi_V(r) (Eq. 11)"))},
        coords={"k_ft": ("k_ft", k, _meta("1/D", "wavenumber k")), "sample": ds["sample"]},
        attrs={"r_cut": float(r[-1]), "k_min_reliable": spectral.smallest_reliable_k(float(r[-1]))},
    )
    return out


def _step(progress: Progress | None) -> None:
    if progress is not None:
        progress.step()


# --------------------------------------------------------------------------- spectral density


def spectral_samples(configs: Sequence, *, k_max: float, bin_width: float, table_k=(),
                     table_width: float | None = None, eps: float = 1e-9, nthreads: int = 1,
                     first: int = 0, bragg=None, snap_table: bool = False,
                     progress: Progress | None = None) -> xr.Dataset:
    """Direct spectral density (Eq. 14) on all allowed wavevectors, binned per sample.

    Fine bins [i w, (i+1) w) of width ``bin_width`` up to k_max (Fig. 6), and
    bins of ``table_width`` centred on ``table_k`` (Tables IV, V; with ``snap_table`` on the
    cubic cell's shells that the labels round, see spectral.snap_to_shells). ``bragg``
    (optional): expected Bragg wavevector magnitudes of a lattice; then the
    number of wavevectors with S > N/2 and the extreme S values are recorded.

    Parameters
    ----------
    configs : sequence of (positions, box, diameter)
        Configurations in units of D.
    k_max : float
        Largest wavenumber (1/D).
    bin_width : float
        Width of the fine |k| bins (1/D).
    table_k : array_like
        Tabulated kD of the paper's tables; empty for none.
    table_width : float or None
        Width of the table bins (1/D); None: ``bin_width``.
    eps : float
        NUFFT tolerance of :func:`randmedia.describe.spectral.structure_factor` (default 1e-9).
    nthreads : int
        NUFFT threads (default 1).
    first : int
        Index of the first sample (default 0).
    bragg : int or None
        Expected number of Bragg wavevectors of a lattice up to k_max (stored as attr
        ``expected_peaks``); None for a disordered system.
    snap_table : bool
        Centre the table bins on the cubic cell's shells (default False).
    progress : Progress or None
        Stepped once per configuration.

    Returns
    -------
    xarray.Dataset
        Per-sample binned chi and S on (sample, k), table values on (sample, k_table) when
        ``table_k`` is given, peak statistics per sample; units in the variables' attrs.
    """
    edges = np.arange(0.0, k_max + 0.5 * bin_width, bin_width)
    edges = edges[edges <= k_max + 1e-12]
    table_k = np.asarray(table_k, dtype=float)
    table_labels = table_k
    snapped = False
    if table_k.size and snap_table and configs:  # Table IV: exact shells of the cubic cell
        table_k, snapped = spectral.snap_to_shells(table_k, configs[0][1])
        if snapped and any(not np.allclose(spectral.snap_to_shells(table_labels, box)[0], table_k)
                           for _, box, _ in configs):
            raise ValueError("samples of one system have different cells: cannot snap the table's kD")
    table_width = bin_width if table_width is None else table_width
    chi, S, counts, kmean, chi_table, table_counts = [], [], [], [], [], []
    chi_binnings, binning_counts, binning_widths = [], [], []
    within = {name: [] for name in AVERAGED["spectral"]}  # bin_sems per sample
    bragg_rows = []
    for positions, box, diameter in configs:
        _, _, kmag, Sk = spectral.structure_factor(positions, box, k_max, eps=eps, nthreads=nthreads)
        rho = len(positions) / abs(np.linalg.det(box))
        chik = spectral.spectral_density_direct(kmag, Sk, rho, diameter)
        mean_chi, count, km = spectral.bin_means(kmag, chik, edges)
        mean_S, _, _ = spectral.bin_means(kmag, Sk, edges)
        chi.append(mean_chi), S.append(mean_S), counts.append(count), kmean.append(km)
        within["chi"].append(spectral.bin_sems(kmag, chik, edges))
        within["S"].append(spectral.bin_sems(kmag, Sk, edges))
        if table_k.size:
            binnings = spectral.table_binnings(table_labels, table_k, box, table_width)
            means, numbers, sems = spectral.binned_table_values(kmag, chik, binnings)
            own = list(binnings).index("bin_width")  # the table's own bins: table_width on table_k
            chi_table.append(means[own]), table_counts.append(numbers[own])
            within["chi_table"].append(sems[own]), within["chi_table_binning"].append(sems)
            chi_binnings.append(means), binning_counts.append(numbers)
            binning_widths.append([width for _, width in binnings.values()])
        n = len(positions)
        peaks = Sk > 0.5 * n
        bragg_rows.append((peaks.sum(), Sk[peaks].min() / n if peaks.any() else np.nan,
                           Sk[~peaks].max() / n if (~peaks).any() else np.nan))
        _step(progress)
    centres = 0.5 * (edges[:-1] + edges[1:])
    data = {
        "chi": (("sample", "k"), np.array(chi), _meta("D^3", "spectral density rho m(k)^2 S(k) (Eq. 14), bin mean")),
        "S": (("sample", "k"), np.array(S), _meta("1", "structure factor S(k), bin mean")),
        "k_count": (("sample", "k"), np.array(counts), _meta("1", "allowed wavevectors (half space) in the bin")),
        "k_mean": (("sample", "k"), np.array(kmean), _meta("1/D", "mean |k| of the wavevectors in the bin")),
        "n_peaks": (("sample",), np.array([b[0] for b in bragg_rows], float),
                    _meta("1", "wavevectors with S(k) > N/2 (Bragg peaks of a lattice)")),
        "S_peak_min": (("sample",), np.array([b[1] for b in bragg_rows]), _meta("1", "smallest S/N over peaks")),
        "S_off_max": (("sample",), np.array([b[2] for b in bragg_rows]), _meta("1", "largest S/N off the peaks")),
    }
    coords = {"k": ("k", centres, _meta("1/D", "bin centre of |k|")),
              "k_lo": ("k", edges[:-1], _meta("1/D", "lower bin edge")),
              "sample": _sample_coord(len(chi), first)}
    if table_k.size:
        data["chi_table"] = (("sample", "k_table"), np.array(chi_table),
                             _meta("D^3", f"spectral density, bins of width {table_width:g}/D centred on k_table"))
        data["k_table_count"] = (("sample", "k_table"), np.array(table_counts), _meta("1", "wavevectors in the bin"))
        coords["k_table"] = ("k_table", table_labels, _meta("1/D", "tabulated kD of the paper"))
        data["k_table_centre"] = (("k_table",), table_k,
                                  _meta("1/D", "centre of our bin for the tabulated kD"))
        data["chi_table_binning"] = (("sample", "binning", "k_table"), np.array(chi_binnings),
                                     _meta("D^3", "spectral density at the tabulated kD under each bin "
                                                  "convention (spectral.table_binnings; NaN: not applicable)"))
        data["binning_count"] = (("sample", "binning", "k_table"), np.array(binning_counts),
                                 _meta("1", "wavevectors in the bin of each convention"))
        data["binning_width"] = (("sample", "binning"), np.array(binning_widths),
                                 _meta("1/D", "bin width of each convention"))
        coords["binning"] = ("binning", list(spectral.TABLE_BINNINGS),
                             _meta("1", "bin convention for the tabulated kD (spectral.table_binnings)"))
    for name, values in within.items():
        if values:
            dims, units = data[name][0], data[name][2]["units"]
            data[f"{name}{WITHIN_SEM}"] = (dims, np.array(values), _meta(
                units, "standard error of the bin mean within the sample (spectral.bin_sems: "
                       "exponential S(k), independent wavevectors)"))
    data.update(_scalars(configs))
    attrs = {"kind": "spectral", "k_max": float(k_max), "bin_width": float(bin_width),
             "table_width": float(table_width), "nufft_eps": float(eps),
             "table_bins": "cubic-cell shells the labels round" if snapped else "centred on the labels"}
    if bragg is not None:
        attrs["expected_peaks"] = int(bragg)
    return xr.Dataset(data, coords=coords, attrs=attrs)


# --------------------------------------------------------------------------- pore sizes, E_V


def points_samples(configs: Sequence, rngs: Sequence[np.random.Generator], *, n_matrix_points: int,
                   bin_width: float, d_max: float, batch: int = 1_000_000, first: int = 0,
                   covering: bool = True, log=None, progress: Progress | None = None) -> xr.Dataset:
    """E_V(r), F(delta), <delta>, <delta^2>, covering radius of each configuration (Sec. V).

    ``covering=False`` skips the exact covering radius (NaN), e.g. for Poisson
    centres, where it is a property of the finite sample only.

    Parameters
    ----------
    configs : sequence of (positions, box, diameter)
        Configurations in units of D.
    rngs : sequence of numpy.random.Generator
        One generator per configuration.
    n_matrix_points : int
        Uniform points are drawn until this many lie in the matrix (d > R).
    bin_width : float
        Width of the distance histogram (D); the sphere radius must be a multiple of it.
    d_max : float
        Range of the histogram (D); farther distances count as ``overflow``.
    batch : int
        Points drawn per batch (default 1 000 000).
    first : int
        Index of the first sample (default 0).
    covering : bool
        Compute the exact covering radius (default True); False stores NaN.
    log : logging.Logger or None
        Logs one line per sample when given.
    progress : Progress or None
        Stepped once per configuration.

    Returns
    -------
    xarray.Dataset
        E_V on (sample, r), F on (sample, delta) and per-sample scalars, units in their attrs.
    """
    edges = points.distance_bins(bin_width, d_max)
    E_V, F, rows = [], [], []
    for index, ((positions, box, diameter), rng) in enumerate(zip(configs, rngs)):
        st = points.nearest_distance_statistics(positions, box, diameter, rng, n_matrix_points, edges,
                                                batch=batch)
        ev = points.exclusion_from_histogram(st["hist"], st["n_points"], st["overflow"])
        radius = diameter / 2.0
        i_R = int(round(radius / bin_width))
        if not math.isclose(edges[i_R], radius, rel_tol=0, abs_tol=1e-9):
            raise ValueError(f"sphere radius {radius} is not a multiple of bin_width {bin_width}")
        delta_edges = edges[i_R:] - radius
        F.append(ev[i_R:] / ev[i_R])
        E_V.append(ev)
        rows.append((st["n_points"], st["n_matrix"], st["sum_delta"] / st["n_matrix"],
                     st["sum_delta2"] / st["n_matrix"], st["max_distance"],
                     points.covering_radius(positions, box) if covering else math.nan,
                     st["overflow"]))
        if log is not None:
            log.info("sample %d: %d points (%d in the matrix), <delta> = %.5f D, covering radius %.4f D",
                     first + index, st["n_points"], st["n_matrix"], rows[-1][2], rows[-1][5])
        _step(progress)
    a = np.array(rows, dtype=float)
    data = {
        "E_V": (("sample", "r"), np.array(E_V), _meta("1", "exclusion probability E_V(r) = P(nearest centre > r)")),
        "F": (("sample", "delta"), np.array(F), _meta("1", "complementary cumulative pore-size distribution F(delta) (Eq. 17)")),
        "n_points": (("sample",), a[:, 0], _meta("1", "uniform random points drawn")),
        "n_matrix": (("sample",), a[:, 1], _meta("1", "random points in the matrix (d > R)")),
        "mean_pore_size": (("sample",), a[:, 2], _meta("D", "<delta> over matrix points (Eq. 18)")),
        "second_moment_pore_size": (("sample",), a[:, 3], _meta("D^2", "<delta^2> over matrix points (Eq. 19)")),
        "max_distance": (("sample",), a[:, 4], _meta("D", "largest nearest-centre distance sampled")),
        "covering_radius": (("sample",), a[:, 5], _meta("D", "covering radius from the Voronoi vertices")),
        "overflow": (("sample",), a[:, 6], _meta("1", "points beyond the last histogram edge")),
    }
    data.update(_scalars(configs))
    coords = {"r": ("r", edges, _meta("D", "distance r")),
              "delta": ("delta", delta_edges, _meta("D", "pore size delta")),
              "sample": _sample_coord(len(E_V), first)}
    return xr.Dataset(data, coords=coords, attrs={"kind": "points", "bin_width": float(bin_width),
                                                  "n_matrix_points": int(n_matrix_points)})


# --------------------------------------------------------------------------- windows


def window_radii(half_width: float, step: float, extra=()) -> np.ndarray:
    """Uniform radii step, 2 step, ... <= h_w, united with ``extra`` (those <= h_w).

    Parameters
    ----------
    half_width : float
        h_w, the largest radius (D).
    step : float
        Grid spacing (D).
    extra : array_like
        Further radii to include (those > h_w are dropped).

    Returns
    -------
    numpy.ndarray
        Sorted unique radii (rounded to 12 decimals), shape (n,).
    """
    grid = np.arange(1, int(math.floor(half_width / step + 1e-9)) + 1) * step
    extra = np.asarray(extra, dtype=float)
    return np.unique(np.round(np.concatenate([grid, extra[extra <= half_width]]), 12))


def windows_samples(configs: Sequence, rngs: Sequence[np.random.Generator], *, radius_step: float,
                    fR_radii, phi_B: float, max_windows: int, first: int = 0,
                    progress: Progress | None = None) -> xr.Dataset:
    """Window counts N(R) (Sec. VI) of each configuration.

    Radii: step, 2 step, ... and ``fR_radii``, up to the largest h_w of the
    chunk; a sample uses those <= its own h_w (others: zero throws). Stored
    per sample and radius: throws, sum N, sum N^2; and at each ``fR_radii``
    (<= h_w) the distribution of N (Fig. 9).

    Parameters
    ----------
    configs : sequence of (positions, box, diameter)
        Configurations in units of D.
    rngs : sequence of numpy.random.Generator
        One generator per configuration (window centres).
    radius_step : float
        Spacing of the radius grid (D).
    fR_radii : array_like
        Radii (D) at which the count distribution f_R(N) is stored.
    phi_B : float
        Fraction in (0, 1] of the cell volume the windows of one radius may cover in total
        (:func:`randmedia.describe.points.throws_per_radius`).
    max_windows : int
        Largest number of windows per radius and sample.
    first : int
        Index of the first sample (default 0).
    progress : Progress or None
        Stepped once per configuration.

    Returns
    -------
    xarray.Dataset
        n_throws, sum_N ... sum_N4 on (sample, R), count_hist on (sample, R_f, N), per-sample scalars.
    """
    from randmedia.periodic import Cell

    cells = [Cell(box) for _, box, _ in configs]
    radii = window_radii(max(c.half_width for c in cells), radius_step, fR_radii)
    fR_radii = np.array([R for R in np.asarray(fR_radii, dtype=float) if R <= radii[-1] + 1e-12])
    fR_index = [int(np.argmin(np.abs(radii - R))) for R in fR_radii]
    moments, dists = [], []
    for (positions, box, diameter), rng, cell in zip(configs, rngs, cells):
        use = radii <= cell.half_width * (1 + 1e-12)
        n_R = points.throws_per_radius(cell.volume, radii[use], phi_B, max_windows)
        centres = cell.random_points(rng, int(n_R.max()))
        counts = points.window_counts(positions, box, centres, radii[use], n_R)
        m = points.window_moments(counts)
        row = np.zeros((5, len(radii)))
        row[:, use] = m["n_throws"], m["sum_N"], m["sum_N2"], m["sum_N3"], m["sum_N4"]
        moments.append(row)
        dists.append([counts[: n_R[i], i] if use[i] else np.zeros(0, dtype=np.int64) for i in fR_index])
        _step(progress)
    n_max = max((int(c.max()) for d in dists for c in d if c.size), default=0) + 1
    hist = np.zeros((len(dists), len(fR_index), n_max))
    for s, d in enumerate(dists):
        for j, c in enumerate(d):
            if c.size:
                hist[s, j] = np.bincount(c, minlength=n_max)
    mom = np.array(moments, dtype=float)
    data = {
        "n_throws": (("sample", "R"), mom[:, 0], _meta("1", "windows thrown for this radius (phi_B rule)")),
        "sum_N": (("sample", "R"), mom[:, 1], _meta("1", "sum of N(R) over the windows")),
        "sum_N2": (("sample", "R"), mom[:, 2], _meta("1", "sum of N(R)^2 over the windows")),
        "sum_N3": (("sample", "R"), mom[:, 3], _meta("1", "sum of N(R)^3 over the windows")),
        "sum_N4": (("sample", "R"), mom[:, 4], _meta("1", "sum of N(R)^4 over the windows")),
        "count_hist": (("sample", "R_f", "N"), hist, _meta("1", "windows with exactly N centres")),
    }
    data.update(_scalars(configs))
    coords = {"R": ("R", radii, _meta("D", "window radius")),
              "R_f": ("R_f", fR_radii, _meta("D", "window radius of the count distributions")),
              "N": ("N", np.arange(n_max), _meta("1", "number of centres in the window")),
              "sample": _sample_coord(len(moments), first)}
    return xr.Dataset(data, coords=coords, attrs={"kind": "windows", "phi_B": float(phi_B),
                                                  "max_windows": int(max_windows),
                                                  "radius_step": float(radius_step)})


# --------------------------------------------------------------------------- one kind, one set of samples


KINDS = ("correlation", "spectral", "points", "windows")


#: the config sections (keyword arguments of :func:`describe`) each kind needs
KIND_SETTINGS = {"correlation": ("descriptors",), "spectral": ("spectral",),
                 "points": ("pores", "seed"), "windows": ("windows", "seed")}


def describe(kind: str, system: str, configs: Sequence, *, first: int, seed: int | None = None,
             descriptors: dict | None = None, spectral: dict | None = None, table_k=(),
             pores: dict | None = None, windows: dict | None = None, nthreads: int = 1, log=None):
    """Per-sample dataset of one descriptor ``kind`` of ``configs`` (samples first, first + 1, ...)
    of ``system``, with the config values it used. Only the kind's own sections are needed
    (:data:`KIND_SETTINGS`; ``table_k`` for spectral); the others are ignored. Monte Carlo
    kinds draw from one generator per sample, seeded from
    (seed, "mrj2016", f"{system}/{kind}", sample index).

    Parameters
    ----------
    kind : str
        One of :data:`KINDS`.
    system : str
        System name (e.g. ``"mrj"``, ``"fcc"``); keys the seeds and selects the Bragg count (fcc, bcc),
        table snapping (equilibrium) and the covering radius (all but overlapping).
    configs : sequence of (positions, box, diameter)
        The chunk's configurations, in units of D.
    first : int
        Sample index of ``configs[0]``.
    seed : int or None
        Base seed (points, windows).
    descriptors, spectral, pores, windows : dict or None
        Config sections (correlation, spectral, points, windows kinds).
    table_k : array_like
        Tabulated kD of the paper (spectral).
    nthreads : int
        NUFFT threads (spectral; default 1).
    log : logging.Logger or None
        Logger for progress and per-sample lines.

    Returns
    -------
    tuple of (xarray.Dataset, dict)
        The per-sample dataset and the config values used.
    """
    from randmedia.seeding import sample_rng, sample_seed

    if kind not in KINDS:
        raise ValueError(f"kind must be one of {KINDS}, got {kind!r}")
    given = {"seed": seed, "descriptors": descriptors, "spectral": spectral, "pores": pores,
             "windows": windows}
    missing = [name for name in KIND_SETTINGS[kind] if given[name] is None]
    if missing:
        raise ValueError(f"describe({kind!r}) needs {missing}")
    indices = range(first, first + len(configs))
    used = {"system": system, "kind": kind, "first": first}
    progress = Progress(len(configs), f"{system} {kind}", log)
    if kind == "correlation":
        used.update(descriptors)
        dataset = correlation_samples(configs, r_step=descriptors["r_step"], r_max=descriptors["r_max"],
                                      contact_r=descriptors["contact_r"], first=first, progress=progress)
    elif kind == "spectral":
        from randmedia.generate.spheres import bragg_peak_count

        used.update(spectral, table_k=list(table_k))
        bragg = bragg_peak_count(system, spectral["k_max"]) if system in ("fcc", "bcc") else None
        dataset = spectral_samples(configs, k_max=spectral["k_max"], bin_width=spectral["bin_width"],
                                   table_k=table_k, table_width=spectral["table_bin_width"],
                                   eps=spectral["nufft_eps"], nthreads=nthreads, first=first, bragg=bragg,
                                   snap_table=system == "equilibrium", progress=progress)
    elif kind == "points":
        used.update(pores, seed=seed)
        rngs = [sample_rng(sample_seed(seed, "mrj2016", f"{system}/points", k)) for k in indices]
        dataset = points_samples(configs, rngs, n_matrix_points=pores["matrix_points"],
                                 bin_width=pores["bin_width"], d_max=pores["d_max"], first=first,
                                 covering=system != "overlapping", log=log, progress=progress)
    else:
        used.update(windows, seed=seed)
        rngs = [sample_rng(sample_seed(seed, "mrj2016", f"{system}/windows", k)) for k in indices]
        dataset = windows_samples(configs, rngs, radius_step=windows["radius_step"],
                                  fR_radii=windows["fR_radii"], phi_B=windows["phi_B"],
                                  max_windows=windows["max_windows"], first=first, progress=progress)
    dataset.attrs["system"] = system
    return dataset, used


# --------------------------------------------------------------------------- merge


def merge(chunks: Iterable[xr.Dataset]) -> xr.Dataset:
    """Concatenate per-sample chunk datasets along ``sample`` and add mean / SEM curves."""
    chunks = list(chunks)
    if not chunks:
        raise ValueError("no chunks to merge")
    kind = chunks[0].attrs.get("kind")
    if any(c.attrs.get("kind") != kind for c in chunks):
        raise ValueError("chunks of different kinds cannot be merged")
    provenance = ("randmedia_version", "git_commit", "git_dirty", "rule", "seed", "config_json",
                  "sample_files")
    if kind == "windows":  # radii and count ranges differ between chunks: outer join, zeros
        ds = xr.concat(chunks, dim="sample", data_vars="minimal", coords="minimal",
                       compat="override", join="outer", fill_value=0.0,
                       combine_attrs="drop_conflicts")
        for name, long_name in (("R", "window radius"), ("R_f", "window radius of the count distributions"),
                                ("N", "number of centres in the window")):
            ds[name].attrs.update(_meta("D" if name != "N" else "1", long_name))
    else:
        ds = xr.concat(chunks, dim="sample", data_vars="minimal", coords="minimal",
                       compat="override", join="exact", combine_attrs="drop_conflicts")
    for key in provenance:
        ds.attrs.pop(key, None)
    ds = ds.sortby("sample")
    for name in AVERAGED.get(kind, ()):
        if name not in ds:
            continue
        values = ds[name].values
        dims = ds[name].dims[1:]
        mean, sem = nan_mean_sem(values)
        ds[f"{name}_mean"] = (dims, mean, {**ds[name].attrs,
                                           "long_name": ds[name].attrs["long_name"] + ", mean over samples"})
        ds[f"{name}_sem"] = (dims, sem, {**ds[name].attrs,
                                         "long_name": ds[name].attrs["long_name"] + ", SEM over samples"})
    ds.attrs["n_samples"] = int(ds.sizes["sample"])
    return ds


#: wavenumber step (1/D) of the Eq. (11) transform curve
K_FT_STEP = 0.02


def summarize(chunks: Iterable[xr.Dataset], kind: str, *, spectral: dict | None = None,
              windows: dict | None = None) -> xr.Dataset:
    """The merged file of one system and descriptor kind (rule mrj2016_describe).

    * correlation: grid trimmed to the r valid in every sample; Eq. (11)
      transform per sample (mean, SEM) on k = 0.02, 0.04, ... <= k_max;
    * windows: pooled number variance and jackknife SEM (Sec. VI B), skewness
      and excess kurtosis of N(R), pooled f_R(N) at R_f, and the fits
      b2 R^2 + b3 R^3 and b2 R^2 in units of lambda = rho^(-1/3) over R >= fit_r_min;
    * spectral, points: concatenation, mean and SEM; the SEM is at least the samples' own
      errors combined (spectral: within-bin, :func:`spectral.bin_sems`, for a disordered
      system; points: binomial), so one sample has an SEM too.

    ``spectral`` (only its ``k_max``) is needed for correlation, ``windows`` for windows.

    Parameters
    ----------
    chunks : iterable of xarray.Dataset
        Per-sample chunk datasets of one system and kind.
    kind : str
        Their descriptor kind (one of :data:`KINDS`).
    spectral : dict or None
        The spectral config section (``k_max``, 1/D); needed for ``"correlation"``.
    windows : dict or None
        The windows config section (``fit_r_min``, D); needed for ``"windows"``.

    Returns
    -------
    xarray.Dataset
        The merged dataset, with the mean / SEM curves and the kind's summaries.
    """
    needed = {"correlation": ("spectral", spectral), "windows": ("windows", windows)}.get(kind)
    if needed is not None and needed[1] is None:
        raise ValueError(f"summarize({kind!r}) needs {needed[0]!r}")
    chunks = list(chunks)
    if chunks and kind == "correlation":
        valid = np.all([~np.isnan(c["S2"].values).any(axis=0) for c in chunks], axis=0)
        n_valid = int(np.argmin(valid)) if not valid.all() else valid.size
        if n_valid < 3:
            raise ValueError("fewer than 3 radii valid in every sample (cells too small for "
                             "Appendix A: r < h_w - D)")
        chunks = [c.isel(r=slice(0, n_valid)) for c in chunks]
    ds = merge(chunks)
    if ds.attrs.get("kind") != kind:
        raise ValueError(f"chunks are of kind {ds.attrs.get('kind')!r}, expected {kind!r}")
    if kind == "correlation":
        k = np.arange(1, int(math.floor(spectral["k_max"] / K_FT_STEP + 1e-9)) + 1) * K_FT_STEP
        ft = autocovariance_transform(ds, k)
        ds["chi_ft"] = ft["chi_ft"]
        mean, sem = nan_mean_sem(ft["chi_ft"].values)
        ds["chi_ft_mean"] = (("k_ft",), mean, _meta("D^3", "Eq. (11) spectral density, mean over samples"))
        ds["chi_ft_sem"] = (("k_ft",), sem, _meta("D^3", "Eq. (11) spectral density, SEM over samples"))
        ds.attrs.update(r_cut=ft.attrs["r_cut"], k_min_reliable=ft.attrs["k_min_reliable"])
    if kind == "points":
        # SEM floor: the pooled estimate of a fraction of N_total uniform points has at least the
        # binomial error sqrt(E (1 - E) / N_total) (configurations add variance, never remove it);
        # with few samples the SEM over samples can fall below it by chance
        n_total = float(ds["n_points"].values.sum())
        for name in ("E_V", "F"):
            mean = ds[f"{name}_mean"].values
            scale = n_total if name == "E_V" else float(ds["n_matrix"].values.sum())
            floor = np.sqrt(np.clip(mean * (1 - mean), 0, None) / scale)
            ds[f"{name}_sem"].values[:] = np.fmax(ds[f"{name}_sem"].values, floor)
            ds[f"{name}_sem"].attrs["long_name"] += " (at least the binomial error of the pooled points)"
    if kind == "spectral" and "expected_peaks" not in ds.attrs:
        # SEM floor of a disordered system: the within-bin errors of the samples combined,
        # sqrt(sum_i sem_i^2) / n (spectral.bin_sems); with one sample it is the only SEM
        for name in AVERAGED["spectral"]:
            if f"{name}{WITHIN_SEM}" not in ds:
                continue
            own = ds[f"{name}{WITHIN_SEM}"].values
            valid = np.isfinite(own)
            with np.errstate(invalid="ignore", divide="ignore"):
                floor = np.sqrt((np.where(valid, own, 0.0) ** 2).sum(axis=0)) / valid.sum(axis=0)
            ds[f"{name}_sem"].values[:] = np.fmax(ds[f"{name}_sem"].values, floor)
            ds[f"{name}_sem"].attrs["long_name"] += " (at least the samples' within-bin errors combined)"
    if kind == "windows":
        _summarize_windows(ds, windows)
        ds.attrs["fit_r_min"] = float(windows["fit_r_min"])
    return ds


def _summarize_windows(ds: xr.Dataset, windows: dict) -> None:
    from randmedia.fit.number_variance import fit_number_variance

    moments = [ds[name].values for name in ("n_throws", "sum_N", "sum_N2")]
    mean, var, mean_sem, var_sem = points.pooled_number_variance(*moments)
    skew, kurt = points.pooled_shape(*moments, ds["sum_N3"].values, ds["sum_N4"].values)
    ds["N_mean"] = (("R",), mean, _meta("1", "pooled mean number of centres in the window"))
    ds["N_mean_sem"] = (("R",), mean_sem, _meta("1", "jackknife SEM of the pooled mean"))
    ds["number_variance"] = (("R",), var, _meta("1", "number variance sigma_N^2(R), pooled sample variance"))
    ds["number_variance_sem"] = (("R",), var_sem, _meta("1", "jackknife SEM of the number variance"))
    ds["skewness"] = (("R",), skew, _meta("1", "skewness of N(R), pooled"))
    ds["excess_kurtosis"] = (("R",), kurt, _meta("1", "excess kurtosis of N(R), pooled"))
    ds["throws_total"] = (("R",), ds["n_throws"].values.sum(axis=0), _meta("1", "windows over all samples"))
    hist = ds["count_hist"].values.sum(axis=0)
    with np.errstate(invalid="ignore", divide="ignore"):
        ds["count_probability"] = (("R_f", "N"), hist / hist.sum(axis=1, keepdims=True),
                                   _meta("1", "pooled f_R(N): fraction of windows with N centres"))
    lam = float(np.mean(ds["rho"].values)) ** (-1.0 / 3.0)
    ds.attrs["lambda"] = lam
    for model in ("b2_b3", "b2"):
        try:
            fit = fit_number_variance(ds["R"].values, *moments, model=model,
                                      r_min=windows["fit_r_min"], length=lam)
        except ValueError as exc:  # too few radii / samples (tiny test configurations)
            ds.attrs[f"fit_{model}_error"] = str(exc)
            continue
        ds.coords[f"param_{model}"] = (f"param_{model}", list(fit.names),
                                       _meta("1", "coefficient name"))
        ds[f"fit_{model}"] = ((f"param_{model}",), np.array(fit.values),
                              _meta("1", f"coefficients {fit.names} of the {model} fit, R in units of lambda"))
        ds[f"fit_{model}_err"] = ((f"param_{model}",), np.array(fit.errors),
                                  _meta("1", "jackknife errors of the coefficients"))
        ds.attrs[f"fit_{model}_chi2_per_dof"] = fit.chi2_per_dof
        ds.attrs[f"fit_{model}_n_points"] = fit.n_points
