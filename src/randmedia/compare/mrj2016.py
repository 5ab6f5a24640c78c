"""Tables I-V and the comparison of Klatt & Torquato, PRE 94, 022152 (2016).

Inputs are the merged descriptor files of :mod:`randmedia.studies.mrj2016`
(names ``{kind}_{system}``). Tables hold *our* values at the paper's r/D and kD
with their SEM over samples; :func:`comparison` puts every published table cell
and quoted number (``config/reference/mrj2016_*.csv``) beside ours, plus rows
that check estimators against exact results (overlapping spheres, lattices,
Eq. 21). Tolerance of a row (:func:`randmedia.compare.tolerance`):

    k_sigma * sqrt(SEM_ours^2 + err_published^2) + rounding + systematic

* ``err_published``: the statistical error the paper states -- Table II: "mostly
  below 3e-4" for the correlation functions and 2e-5 .. 1e-7 for E_V; Table III:
  2e-4 and 5e-6 .. 1e-7 (we take the upper bounds, capped at the value for E_V);
  Tables IV-V: the SEM column; Sec. V B: 1e-3 for the pore moments; Fig. 13:
  1e-4 for F*_ss(D)/s^2.
* ``rounding``: half a unit of the last printed digit of the published value.
* ``systematic``: stated per row (zero unless said otherwise; e.g. a finite
  difference bias computed from the grid).

Rows that fail stay in the table; ``comparison_notes.csv`` lists each row's
error budget and, for failures, the reason we identified (e.g. our packings'
phi differs from the paper's; the binning convention near zeros of m(k)).
"""

from __future__ import annotations

import math
from decimal import Decimal

import numpy as np
import pandas as pd

from randmedia.compare import (checked_row, compare, comparison_frame, notes_frame,
                               read_reference)
from randmedia.io import read_dataset

#: published statistical errors (upper bounds stated in the captions of Tables II, III)
TABLE_ERRORS = {
    2: {"S2": 3e-4, "Fsv_over_s": 3e-4, "Fss_over_s2": 3e-4, "EV": 2e-5},
    3: {"S2": 2e-4, "Fsv_over_s": 2e-4, "Fss_over_s2": 2e-4, "EV": 5e-6},
}
TABLE_SYSTEMS = {2: "equilibrium", 3: "mrj", 4: "equilibrium", 5: "mrj_large"}
#: the packing fractions the paper gives: Tables II and III's captions; for its 14 packings of
#: N = 10 000 the label of Fig. 6's MRJ panel (Sec. IV: that panel's packings)
PAPER_PHI = {"equilibrium": 0.4780, "mrj": 0.6356, "mrj_large": 0.637}
#: numbers the paper prints only in a figure, which its transcribed quoted numbers
#: (config/reference/, a cell-by-cell copy of the published CSV) leave out: compared like them,
#: where this workflow makes the system (``_quoted_rows``)
FIGURE_LABELS = pd.DataFrame([
    {"quantity": "packing_fraction", "system": "mrj_large", "value": f"{PAPER_PHI['mrj_large']:g}", "unit": "1",
     "where": "Fig. 6 label (MRJ panel: the 14 packings of N = 10 000)"},
])
#: Gaussianity criterion of f_R(N) (see gaussian_radius)
GAUSSIAN_THRESHOLD = 0.15
GAUSSIAN_MIN_WINDOWS = 200
GAUSSIAN_MARGIN = 0.5  # D; the paper's "R > 1.5 D" is read off a figure


def rounding_margin(text: str) -> float:
    """Half a unit of the last printed digit of a number as printed ('2.26e-1' -> 5e-4)."""
    text = str(text).strip()
    if text.lower() in ("inf", "-inf", "nan", ""):
        return 0.0
    exponent = Decimal(text).as_tuple().exponent
    return 0.5 * 10.0 ** int(exponent)


def _load(inputs, kind, system):
    path = inputs.get(f"{kind}_{system}")
    return None if path is None else read_dataset(path)


def _value_at(ds, coord, name, x, atol=1e-9):
    """(mean, sem) of ``name`` at grid point ``x`` of ``coord`` (NaN if not on the grid)."""
    if ds is None:
        return math.nan, math.nan
    grid = ds[coord].values
    i = int(np.argmin(np.abs(grid - x)))
    if abs(grid[i] - x) > atol:
        return math.nan, math.nan
    return float(ds[f"{name}_mean"].values[i]), float(ds[f"{name}_sem"].values[i])


def _mean_sem(values):
    values = np.asarray(values, dtype=float)
    if values.size < 2:
        return float(values.mean()) if values.size else math.nan, math.nan
    return float(values.mean()), float(values.std(ddof=1) / math.sqrt(values.size))


def phi_mean_sem(ds, smaller=None) -> tuple[float, float, str]:
    """(mean, SEM, note) of the packing fraction over the samples of ``ds`` (NaN, NaN if
    None). With one sample there is no SEM over samples; then the standard deviation of the
    ``smaller`` ensemble (the same protocol at N' spheres, >= 2 samples) scaled by
    (N' / N)^(1/2) stands in for it -- the central-limit rate for a mean over N spheres (a
    faster fall with N would make it an overestimate) -- and ``note`` says so; otherwise
    ``note`` is ""."""
    if ds is None:
        return math.nan, math.nan, ""
    mean, sem = _mean_sem(ds["eta"].values)
    if ds.sizes["sample"] >= 2 or smaller is None or smaller.sizes["sample"] < 2:
        return mean, sem, ""
    n, n_smaller = float(np.mean(ds["n"].values)), float(np.mean(smaller["n"].values))
    sd = float(np.std(smaller["eta"].values, ddof=1))
    sem = sd * math.sqrt(n_smaller / n)
    return mean, sem, (f"; one sample: its SEM is the SD of the N = {n_smaller:.0f} packings "
                       f"({sd:.2g}) x (N'/N)^1/2 = {sem:.2g}")


# --------------------------------------------------------------------------- tables


def table_correlation(inputs, params, number: int) -> pd.DataFrame:
    """Table II (equilibrium) or III (MRJ): S2, F_sv/s, F_ss/s^2, E_V at the paper's r/D.

    Parameters
    ----------
    inputs : Mapping[str, path]
        Input files: descriptor files named ``{kind}_{system}`` (``correlation_*`` and
        ``points_*`` are read) and ``reference``, the published table's CSV (its ``r_over_D``
        column gives the rows).
    params : dict
        Rule parameters; not used here (signature of :data:`TABLES`).
    number : int
        Table number, 2 or 3 (:data:`TABLE_SYSTEMS`).

    Returns
    -------
    pandas.DataFrame
        One row per r/D: ``S2``, ``Fsv_over_s``, ``Fss_over_s2``, ``EV`` with ``*_sem``; the
        r = inf row from phi (E_V NaN); NaN where r is off our grid.
    """
    system = TABLE_SYSTEMS[number]
    corr = _load(inputs, "correlation", system)
    pts = _load(inputs, "points", system)
    reference = read_reference(inputs["reference"], ["r_over_D"])
    rows = []
    for r in reference["r_over_D"].astype(float):
        row = {"r_over_D": r}
        if math.isinf(r):
            phi = corr["phi"].values
            s2 = _mean_sem(phi**2)
            fsv = _mean_sem(1.0 - phi)
            row.update(S2=s2[0], S2_sem=s2[1], Fsv_over_s=fsv[0], Fsv_over_s_sem=fsv[1],
                       Fss_over_s2=1.0, Fss_over_s2_sem=0.0, EV=math.nan, EV_sem=math.nan)
        else:
            for name, column in (("S2", "S2"), ("F_sv_over_s", "Fsv_over_s"), ("F_ss_over_s2", "Fss_over_s2")):
                mean, sem = _value_at(corr, "r", name, r)
                row[column], row[f"{column}_sem"] = mean, sem
            row["EV"], row["EV_sem"] = _value_at(pts, "r", "E_V", r)
        rows.append(row)
    return pd.DataFrame(rows)


def table_spectral(inputs, params, number: int) -> pd.DataFrame:
    """Table IV (equilibrium) or V (MRJ, N = 10 000): chi_V(k) at the paper's kD, SEM over samples.

    ``chiV_over_D3`` is the reading ``params["spectral_binning"]`` of the paper's bins
    (spectral.table_binnings; config mrj2016.tables.spectral_binning: grid_spacing, bins of
    width 2 pi / L centred on the shells, which reproduces all of Table IV, docs/mrj2016.md)
    where it applies to every row, else our bins of table_bin_width (column ``binning``
    says which); every reading is kept as columns chiV_binning_{name}_over_D3 (+ SEM).

    Parameters
    ----------
    inputs : Mapping[str, path]
        Input files: ``spectral_{system}`` and ``reference``, the published table's CSV (its
        ``kD`` column must equal the dataset's ``k_table``).
    params : dict
        Rule parameters; ``spectral_binning`` names the chosen reading (default
        ``"bin_width"``).
    number : int
        Table number, 4 or 5 (:data:`TABLE_SYSTEMS`).

    Returns
    -------
    pandas.DataFrame
        One row per kD: ``kD``, ``bin_centre_kD``, ``chiV_over_D3``, ``sem_over_D3``,
        ``wavevectors``, ``bin_width_over_D``, ``binning`` and the per-reading columns.
    """
    system = TABLE_SYSTEMS[number]
    spec = _load(inputs, "spectral", system)
    reference = read_reference(inputs["reference"], ["kD"])
    k_table = spec["k_table"].values
    if not np.allclose(k_table, reference["kD"].values):
        raise ValueError(f"{inputs[f'spectral_{system}']}: its k_table does not match {inputs['reference']}")
    counts = spec["k_table_count"].values.sum(axis=0)
    centre = spec["k_table_centre"].values if "k_table_centre" in spec else k_table
    table = pd.DataFrame({
        "kD": k_table,
        "bin_centre_kD": centre,
        "chiV_over_D3": spec["chi_table_mean"].values,
        "sem_over_D3": spec["chi_table_sem"].values,
        "wavevectors": counts.astype(int),
        "bin_width_over_D": spec.attrs["table_width"],
    })
    table["binning"] = "bin_width"
    if "chi_table_binning_mean" in spec:  # every reading of the paper's bins (spectral.table_binnings)
        for name in spec["binning"].values:
            values = spec["chi_table_binning_mean"].sel(binning=name).values
            table[f"{BINNING_PREFIX}{name}_over_D3"] = values
            table[f"{BINNING_PREFIX}{name}_sem_over_D3"] = spec["chi_table_binning_sem"].sel(binning=name).values
        reading = params.get("spectral_binning", "bin_width")
        chosen = spec["chi_table_binning_mean"].sel(binning=reading).values
        if np.isfinite(chosen).all():  # the configured reading applies to these cells
            table["chiV_over_D3"] = chosen
            table["sem_over_D3"] = spec["chi_table_binning_sem"].sel(binning=reading).values
            table["wavevectors"] = spec["binning_count"].sel(binning=reading).values.sum(axis=0).astype(int)
            table["bin_width_over_D"] = float(spec["binning_width"].sel(binning=reading).values.mean())
            table["binning"] = reading
    return table


#: column prefix of Tables IV, V for chi_V under each bin convention (spectral.table_binnings)
BINNING_PREFIX = "chiV_binning_"


SUMMARY_ROWS = [
    # characteristic, symbol, unit, where defined
    ("volume fraction", "phi", "1", "Eq. (3)"),
    ("specific surface", "s", "1/D", "Eq. (4)"),
    ("number density", "rho", "1/D^3", "Sec. II B"),
    ("unit length of the point process", "lambda = rho^(-1/3)", "D", "Sec. II"),
    ("mean pore size", "<delta>", "D", "Eq. (18)"),
    ("second moment of the pore size", "<delta^2>", "D^2", "Eq. (19)"),
    ("covering radius", "R_c", "D", "Sec. V C"),
    ("covering radius", "R_c / lambda", "1", "Sec. V C"),
    ("mean contact number (two-body F*_ss at r -> 0)", "z (Eq. B4)", "1", "Eq. (B4)"),
    ("mean contact number (slope of F*_sv at r -> 0)", "z (Eq. B3)", "1", "Eq. (B3)"),
    ("two-body surface-surface function at r = D", "F*_ss(D)/s^2", "1", "Eq. (B2)"),
    ("number variance fit, R in lambda", "b2 (b2 R^2 + b3 R^3)", "1", "Fig. 10"),
    ("number variance fit, R in lambda", "b3 (b2 R^2 + b3 R^3)", "1", "Fig. 10"),
    ("number variance fit, R in lambda", "b2 (b2 R^2)", "1", "Fig. 10"),
    ("samples", "n", "1", ""),
    ("spheres per sample", "N", "1", ""),
]


def table_summary(inputs, params) -> pd.DataFrame:
    """Table I: the characteristics of Table I with our value per system (mean and SEM)."""
    from randmedia.theory.overlapping import specific_surface

    systems = ["overlapping", "equilibrium", "mrj", "mrj_large", "mrj_md", "fcc", "bcc"]
    rows = []

    def add(index, system, value, sem=math.nan, note=""):
        name, symbol, unit, where = SUMMARY_ROWS[index]
        rows.append({"characteristic": name, "symbol": symbol, "unit": unit, "definition": where,
                     "system": system, "value": value, "sem": sem, "note": note})

    phi_over = params["overlapping_phi"]
    for system in systems:
        data = {kind: _load(inputs, f"{kind}", system) for kind in ("correlation", "spectral", "points", "windows")}
        present = [d for d in data.values() if d is not None]
        if not present:
            continue
        base = present[0]
        rho = base["rho"].values
        if system == "overlapping":
            pts = data["points"]
            if pts is not None:
                mean, sem = _value_at(pts, "r", "E_V", 0.5)
                add(0, system, 1.0 - mean, sem, "1 - E_V(D/2) from the random points")
            add(1, system, specific_surface(0.5, phi_over, 3), 0.0, "exact 6 phi1 ln(1/phi1) / D")
        else:
            add(0, system, *_mean_sem(base["eta"].values), "N pi D^3 / (6 V)")
            add(1, system, *_mean_sem(6.0 * base["eta"].values), "6 phi / D")
        add(2, system, *_mean_sem(rho))
        add(3, system, float(np.mean(rho)) ** (-1.0 / 3.0), math.nan, "(mean rho)^(-1/3)")
        pts = data["points"]
        if pts is not None:
            add(4, system, *_mean_sem(pts["mean_pore_size"].values))
            add(5, system, *_mean_sem(pts["second_moment_pore_size"].values))
            add(6, system, *_mean_sem(pts["covering_radius"].values), "Voronoi vertices, mean over samples")
            add(7, system, *_mean_sem(pts["covering_radius"].values * pts["rho"].values ** (1 / 3)))
        corr = data["correlation"]
        if corr is not None:
            contact_r = corr.attrs.get("contact_r", math.nan)
            add(8, system, *_mean_sem(corr["z_B4"].values), f"at r = {contact_r:g} D")
            add(9, system, *_mean_sem(corr["z_B3"].values), f"at r = {contact_r:g} D")
            add(10, system, *_value_at(corr, "r", "F_ss_two_body_over_s2", 1.0))
        win = data["windows"]
        if win is not None:
            for model, indices in (("b2_b3", (11, 12)), ("b2", (13,))):
                if f"fit_{model}" in win:
                    for index, value, error in zip(indices, win[f"fit_{model}"].values,
                                                   win[f"fit_{model}_err"].values):
                        add(index, system, float(value), float(error),
                            f"R >= {win.attrs.get('fit_r_min', params.get('fit_r_min', ''))}; "
                            f"chi2/dof = {win.attrs[f'fit_{model}_chi2_per_dof']:.2f}")
        add(14, system, float(base.sizes["sample"]), math.nan)
        add(15, system, *_mean_sem(base["n"].values))
    if "overlapping" not in [r["system"] for r in rows]:
        add(1, "overlapping", specific_surface(0.5, phi_over, 3), 0.0, "exact")
    return pd.DataFrame(rows)


TABLES = {
    1: table_summary,
    2: lambda inputs, params: table_correlation(inputs, params, 2),
    3: lambda inputs, params: table_correlation(inputs, params, 3),
    4: lambda inputs, params: table_spectral(inputs, params, 4),
    5: lambda inputs, params: table_spectral(inputs, params, 5),
}


# --------------------------------------------------------------------------- comparison


class Rows:
    """Collects comparison rows with their budget and reason for a failure
    (:func:`randmedia.compare.compare`); ``notes_frame(rows.rows)`` gives the notes."""

    def __init__(self, k_sigma: float):
        self.k_sigma = k_sigma
        self.rows = []

    def add(self, quantity, key, published, ours, ours_sem=math.nan, *, published_err=0.0,
            rounding=0.0, systematic=0.0, reason_if_failed="", exact_match=False):
        """A missing SEM (NaN, e.g. one sample or a configured value) adds nothing to the
        tolerance; the row keeps it as NaN. ``exact_match``: e.g. F_ss(0) = inf passes only
        if ours is the same infinity.

        Parameters
        ----------
        quantity, key : str
            Row labels.
        published, ours : float
            Published and our value.
        ours_sem : float, optional
            Our SEM; NaN (default) adds nothing to the tolerance.
        published_err, rounding, systematic : float, optional
            Error budget (:func:`randmedia.compare.compare`).
        reason_if_failed : str, optional
            Reason identified should the row fail.
        exact_match : bool, optional
            Passed as ``exact`` to :func:`randmedia.compare.compare`.
        """
        sem = 0.0 if not np.isfinite(ours_sem) else float(ours_sem)
        row = compare(quantity, key, published, ours, sem, k_sigma=self.k_sigma,
                      published_err=published_err, rounding=rounding, systematic=systematic,
                      exact=exact_match, reason_if_failed=reason_if_failed)
        row["ours_sem"] = float(ours_sem)
        self.rows.append(row)

    def add_checked(self, frame: pd.DataFrame, reason_if_failed: str):
        """Rows already compared elsewhere (:func:`randmedia.compare.checked_row`)."""
        self.rows += [checked_row(row, k_sigma=self.k_sigma, reason_if_failed=reason_if_failed)
                      for row in frame.to_dict("records")]


def _phi_reason(system, corr):
    if corr is None:
        return f"system {system} not computed"
    phi = float(np.mean(corr["eta"].values))
    paper = PAPER_PHI[system]
    return (f"our {system} samples have phi = {phi:.4f} (paper {paper}); "
            f"{corr.sizes['sample']} samples of N = {float(np.mean(corr['n'].values)):.0f}")


def _table_rows(rows: Rows, table_path, reference_path, number: int, inputs):
    system = TABLE_SYSTEMS[number]
    ours = pd.read_csv(table_path)
    published = pd.read_csv(reference_path, dtype=str)
    corr = _load(inputs, "correlation", system)
    if corr is None:
        corr = _load(inputs, "spectral", system)
    base_reason = _phi_reason(system, corr)
    if number in (2, 3):
        r_cut = float(corr["r"].values[-1]) if corr is not None and "r" in corr.coords else math.nan
        for i, text_r in enumerate(published["r_over_D"]):
            r = float(text_r)
            for column in ("S2", "Fsv_over_s", "Fss_over_s2", "EV"):
                text = published[column].iloc[i]
                if pd.isna(text):
                    continue  # blank cell of the paper's table
                value = float(text)
                mine = float(ours[column].iloc[i])
                sem = float(ours[f"{column}_sem"].iloc[i])
                err = TABLE_ERRORS[number][column]
                if column == "EV":
                    err = min(err, value)
                reason = base_reason
                if not math.isinf(r) and r > r_cut:
                    reason = f"r beyond our grid (h_w - D = {r_cut:.2f} D in our smallest cell)"
                rows.add(f"table{number}_{column}", f"r/D={text_r}", value, mine, sem,
                         published_err=0.0 if math.isinf(value) else err,
                         rounding=rounding_margin(text), exact_match=math.isinf(value),
                         reason_if_failed=reason)
    else:
        reading = str(ours["binning"].iloc[0]) if "binning" in ours else "bin_width"
        narrow = f"{BINNING_PREFIX}bin_width_over_D3"
        second = reading != "bin_width" and narrow in ours
        for i, text_k in enumerate(published["kD"]):
            k = float(text_k)
            text = published["chiV_over_D3"].iloc[i]
            near_zero = min(abs(k - z) for z in FORM_FACTOR_ZEROS) < ZERO_NEIGHBOURHOOD
            reason = base_reason
            if near_zero:
                reason = ("bin next to a zero of m(k): the value depends on the paper's (unstated) "
                          f"bin placement{_eq11_note(corr, k)}; " + base_reason)
            rows.add(f"table{number}_chiV_over_D3", f"kD={text_k}", float(text),
                     float(ours["chiV_over_D3"].iloc[i]), float(ours["sem_over_D3"].iloc[i]),
                     published_err=float(published["sem_over_D3"].iloc[i]),
                     rounding=rounding_margin(text), reason_if_failed=reason)
            if second:  # the second reading: our bins of table_bin_width centred on the same kD
                rows.add(f"table{number}_chiV_over_D3_narrow_bins", f"kD={text_k}", float(text),
                         float(ours[narrow].iloc[i]), float(ours[f"{BINNING_PREFIX}bin_width_sem_over_D3"].iloc[i]),
                         published_err=float(published["sem_over_D3"].iloc[i]),
                         rounding=rounding_margin(text),
                         reason_if_failed=("second reading (bins of table_bin_width instead of one grid "
                                           "spacing 2 pi / L): " + reason))


def _eq11_note(corr, k: float) -> str:
    """", Eq. (11) of our S2 gives ..." at kD = k: the other estimator of chi_V (correlation
    data of the system, when present)."""
    if corr is None or "chi_ft_mean" not in corr:
        return ""
    k_ft = corr["k_ft"].values
    value = float(np.interp(k, k_ft, corr["chi_ft_mean"].values))
    sem = float(np.interp(k, k_ft, corr["chi_ft_sem"].values))
    error = f"+- {sem:.2g} D^3" if np.isfinite(sem) else "D^3 (one sample: no SEM over samples)"
    return f"; Eq. (11) of our S2 gives {value:.3g} {error} at this kD"


#: zeros of the sphere form factor m(k) (k D) below k D = 20, and the distance from them
#: within which a bin's mean depends strongly on its placement
FORM_FACTOR_ZEROS = (8.987, 15.451)
ZERO_NEIGHBOURHOOD = 0.35


def gaussian_radius(R, skewness, kurtosis, throws, *, threshold=GAUSSIAN_THRESHOLD,
                    min_windows=GAUSSIAN_MIN_WINDOWS) -> float:
    """Smallest R from which on |skewness| and |excess kurtosis| of N(R) stay <= threshold
    (radii with at least ``min_windows`` pooled windows); NaN if none.

    Parameters
    ----------
    R : array_like
        Window radii (increasing; units of D).
    skewness, kurtosis : array_like
        Skewness and excess kurtosis of N(R) per radius.
    throws : array_like
        Number of pooled windows per radius.
    threshold : float, optional
        Bound on |skewness| and |excess kurtosis|.
    min_windows : int, optional
        Radii with fewer pooled windows are ignored.

    Returns
    -------
    float
        The radius (units of ``R``); NaN if the largest used radius fails the criterion or no
        radius is used.
    """
    R, skewness, kurtosis, throws = (np.asarray(a, dtype=float) for a in (R, skewness, kurtosis, throws))
    use = throws >= min_windows
    ok = (np.abs(skewness) <= threshold) & (np.abs(kurtosis) <= threshold)
    R, ok = R[use], ok[use]
    if not ok.size or not ok[-1]:
        return math.nan
    bad = np.flatnonzero(~ok)
    return float(R[bad[-1] + 1]) if bad.size else float(R[0])


def _quoted_rows(rows: Rows, reference_path, inputs, params):
    from randmedia.generate.spheres import lattice_packing_fraction
    from randmedia.theory.overlapping import specific_surface

    quoted = pd.read_csv(reference_path, dtype=str)
    made = FIGURE_LABELS["system"].map(lambda system: params["n_samples"].get(system, 0) > 0)
    quoted = pd.concat([quoted, FIGURE_LABELS[made]], ignore_index=True)
    data = {}

    def get(kind, system):
        if (kind, system) not in data:
            data[kind, system] = _load(inputs, kind, system)
        return data[kind, system]

    def any_of(system):
        for kind in ("correlation", "points", "windows", "spectral"):
            if get(kind, system) is not None:
                return get(kind, system)
        return None

    for _, q in quoted.iterrows():
        quantity, system, text = q["quantity"], q["system"], q["value"]
        value = float(text)
        rnd = rounding_margin(text)
        key = system
        mean, sem, err, reason, systematic = math.nan, math.nan, 0.0, "", 0.0
        base = system.split("_")[0] if system.startswith("overlapping") else system
        if quantity in ("packing_fraction", "specific_surface") and base in ("mrj", "equilibrium"):
            ds = any_of(base)
            if ds is not None:
                factor = 6.0 if quantity == "specific_surface" else 1.0
                mean, sem = _mean_sem(factor * ds["eta"].values)
            reason = _phi_reason(base, ds)
        elif quantity == "packing_fraction" and system == "mrj_large":
            # the paper labels its N = 10 000 MRJ packings phi = 0.637 (Fig. 6)
            ds = any_of(system)
            mean, sem, note = phi_mean_sem(ds, any_of("mrj"))
            reason = _phi_reason(system, ds) + note
        elif quantity == "specific_surface" and base == "overlapping":
            mean, sem = specific_surface(0.5, params["overlapping_phi"], 3), 0.0
            reason = "exact formula at our phi"
        elif quantity in ("mean_pore_size", "second_moment_pore_size"):
            pts = get("points", base)
            if pts is not None:
                mean, sem = _mean_sem(pts[quantity].values)
            err = 1e-3
            reason = _phi_reason(base, any_of(base)) if base != "overlapping" else "statistical"
        elif quantity.startswith("covering_radius"):
            pts = get("points", system)
            if pts is not None:
                rc = pts["covering_radius"].values
                if quantity.endswith("lambda"):
                    rc = rc * pts["rho"].values ** (1.0 / 3.0)
                mean, sem = _mean_sem(rc)
        elif quantity == "lambda_over_D":
            ds = any_of(system)
            if ds is not None:
                mean = float(np.mean(ds["rho"].values)) ** (-1.0 / 3.0)
                sem = float(np.std(ds["rho"].values, ddof=1) / math.sqrt(ds.sizes["sample"])
                            / 3.0 * mean / np.mean(ds["rho"].values)) if ds.sizes["sample"] > 1 else math.nan
            reason = _phi_reason(system, ds)
        elif quantity == "mean_contact_number":
            corr = get("correlation", system)
            for label, name in (("Eq. B4", "z_B4"), ("Eq. B3", "z_B3")):
                m, s = _mean_sem(corr[name].values) if corr is not None else (math.nan, math.nan)
                contact_r = corr.attrs.get("contact_r", math.nan) if corr is not None else math.nan
                rows.add(quantity, f"{system} ({label}, r = {contact_r:g} D)", value, m, s, rounding=rnd,
                         reason_if_failed=f"our MRJ packings' contacts within {contact_r:g} D; "
                                          + _phi_reason(system, corr))
            continue
        elif quantity == "Fss_two_body_at_D_over_s2":
            corr = get("correlation", system)
            mean, sem = _value_at(corr, "r", "F_ss_two_body_over_s2", 1.0)
            err = 1e-4
            reason = _phi_reason(system, corr)
        elif quantity == "gaussian_number_distribution_from_R_over_D":
            for sys in ("equilibrium", "mrj"):
                win = get("windows", sys)
                m = math.nan
                if win is not None:
                    m = gaussian_radius(win["R"].values, win["skewness"].values,
                                        win["excess_kurtosis"].values, win["throws_total"].values)
                rows.add(quantity, f"{sys} (|skewness|, |excess kurtosis| <= {GAUSSIAN_THRESHOLD})",
                         value, m, math.nan, systematic=GAUSSIAN_MARGIN,
                         reason_if_failed="criterion for 'well approximated by a Gaussian' is ours; "
                                          "the paper reads it off Fig. 9")
            continue
        elif quantity == "test_ball_coverage_phiB":
            mean, sem, reason = params["windows"]["phi_B"], 0.0, "our configured value differs"
        elif quantity == "spectral_density_bin_width":
            mean, sem, reason = params["spectral"]["bin_width"], 0.0, "our configured value differs"
        elif quantity in ("fcc_packing_fraction", "bcc_packing_fraction"):
            ds = any_of(system)
            mean, sem = (_mean_sem(ds["eta"].values) if ds is not None
                         else (lattice_packing_fraction(system), 0.0))
        elif quantity == "md_packing_fraction":
            # system mrj_md: LS (event-driven MD) compressions, strictly jammed by the same LPs;
            # its growth rate is the decade (0.1, 0.01, 0.001) whose packings end nearest Ref.
            # [29]'s phi, so this row checks that choice, not an independent prediction
            pts = get("points", "mrj_md")
            if pts is not None:
                mean, sem = _mean_sem(pts["eta"].values)
            reason = ("not reproduced: no mrj_md packings in this configuration" if pts is None else
                      "our LS growth rate (a decade grid) does not land on Ref. [29]'s phi")
        elif quantity == "packings_analyzed":
            target = {"mrj_N2000": "mrj", "equilibrium_N10000": "equilibrium",
                      "mrj_N10000_spectral": "mrj_large"}[system]
            mean, sem = float(params["n_samples"].get(target, 0)), 0.0
            reason = f"our configuration generates {mean:.0f} {target} samples"
        else:
            reason = "no computation of ours for this quantity"
        rows.add(quantity, key, value, mean, sem, published_err=err, rounding=rnd,
                 systematic=systematic, reason_if_failed=reason or "not identified")


def _validation_rows(rows: Rows, inputs, params):
    """Estimators against exact results: overlapping spheres, lattices, Eq. (21), S2 limits."""
    from randmedia.generate.spheres import lattice_covering_radius
    from randmedia.theory import overlapping as theory
    from randmedia.theory.balls import poisson_intensity

    phi = params["overlapping_phi"]
    radius = 0.5
    pts = _load(inputs, "points", "overlapping")
    if pts is not None:
        rho = poisson_intensity(phi, radius, 3)
        for r in (0.2, 0.4, 0.5, 0.6, 0.8, 1.0):
            mean, sem = _value_at(pts, "r", "E_V", r)
            rows.add("validation_overlapping_E_V", f"r/D={r:g}", float(theory.exclusion_probability(r, rho, 3)),
                     mean, sem, reason_if_failed="statistical (3 SEM) or estimator bias")
        for delta in (0.05, 0.1, 0.2, 0.3):
            mean, sem = _value_at(pts, "delta", "F", delta)
            rows.add("validation_overlapping_F", f"delta/D={delta:g}",
                     float(theory.pore_size_complementary_cdf(delta, radius, phi, 3)), mean, sem,
                     reason_if_failed="statistical (3 SEM) or estimator bias")
        for n, name in ((1, "mean_pore_size"), (2, "second_moment_pore_size")):
            rows.add(f"validation_overlapping_{name}", f"phi={phi:g}", theory.pore_size_moment(n, radius, phi, 3),
                     *_mean_sem(pts[name].values), reason_if_failed="statistical (3 SEM) or estimator bias")
    win = _load(inputs, "windows", "overlapping")
    if win is not None:
        rho = poisson_intensity(phi, radius, 3)
        R = win["R"].values
        for target in (0.5, 1.0, 1.5, 2.0, 2.5, 3.0):
            i = int(np.argmin(np.abs(R - target)))
            if abs(R[i] - target) > 1e-9:
                continue
            rows.add("validation_overlapping_number_variance", f"R/D={target:g}",
                     rho * 4.0 * math.pi * target**3 / 3.0, float(win["number_variance"].values[i]),
                     float(win["number_variance_sem"].values[i]),
                     reason_if_failed="statistical (3 SEM, jackknife) or throws bias")
    for lattice in ("fcc", "bcc"):
        pts = _load(inputs, "points", lattice)
        exact = lattice_covering_radius(lattice)
        if pts is not None:
            rows.add(f"validation_{lattice}_covering_radius_voronoi", "R_c/D", exact,
                     float(pts["covering_radius"].values.max()), 0.0, systematic=1e-9)
            # no random point may lie farther than the covering radius from a centre
            rows.add(f"validation_{lattice}_sampled_distance_beyond_covering_radius", "max(d) - R_c (D)",
                     0.0, float(max(pts["max_distance"].values.max() - exact, 0.0)), 0.0, systematic=1e-9)
        spec = _load(inputs, "spectral", lattice)
        if spec is not None:
            rows.add(f"validation_{lattice}_bragg_peaks", "count (half space)",
                     float(spec.attrs.get("expected_peaks", math.nan)), float(spec["n_peaks"].values.min()),
                     0.0, reason_if_failed="peak count differs from the reciprocal lattice")
            rows.add(f"validation_{lattice}_S_at_peaks_over_N", "min", 1.0,
                     float(spec["S_peak_min"].values.min()), 0.0, systematic=1e-6)
            rows.add(f"validation_{lattice}_S_off_peaks_over_N", "max", 0.0,
                     float(spec["S_off_max"].values.max()), 0.0, systematic=1e-6)
    pts = _load(inputs, "points", "equilibrium")
    if pts is not None:  # the liquid against scaled-particle theory (an approximation, Sec. V A-B)
        from randmedia.theory import scaled_particle

        phi_liquid = float(np.mean(pts["eta"].values))
        note = "scaled-particle theory is an approximation (Refs. [39,77,78])"
        moments = scaled_particle.pore_size_moments(phi_liquid, 3)
        for n, name in ((0, "mean_pore_size"), (1, "second_moment_pore_size")):
            rows.add(f"check_equilibrium_{name}_vs_scaled_particle", f"phi={phi_liquid:.4f}",
                     float(moments[n]), *_mean_sem(pts[name].values), reason_if_failed=note)
        for r in (0.6, 0.7, 0.8):
            mean, sem = _value_at(pts, "r", "E_V", r)
            rows.add("check_equilibrium_E_V_vs_scaled_particle", f"r/D={r:g}",
                     float(scaled_particle.exclusion_probability(r, phi_liquid, 3)), mean, sem,
                     reason_if_failed=note)
    for system in ("equilibrium", "mrj"):
        pts = _load(inputs, "points", system)
        corr = _load(inputs, "correlation", system)
        if pts is not None:  # Eq. (21): E_V = 1 - rho 4 pi r^3 / 3 for r <= R (hard spheres)
            rho = float(np.mean(pts["rho"].values))
            for r in (0.2, 0.4, 0.5):
                mean, sem = _value_at(pts, "r", "E_V", r)
                rows.add(f"validation_{system}_E_V_eq21", f"r/D={r:g}", 1.0 - rho * 4 * math.pi * r**3 / 3,
                         mean, sem, reason_if_failed="statistical (3 SEM)")
        if corr is not None:  # S2'(0) = -s/4 (Sec. III B); one-sided difference, bias from the exact p_ii
            r1 = float(corr["r"].values[1])
            slope = (corr["S2"].values[:, 1] - corr["S2"].values[:, 0]) / r1 / corr["s"].values
            # finite-difference bias: one-body r1^2/12 (from p_ii, Eq. A6) plus the two-body
            # term of spheres at contact, phi z r1^2/4 in S2 (Eq. A7 at rho = D), i.e. z r1/24
            # in the slope over s, with z <= 12 (kissing number)
            bias = r1**2 / 12.0 + 12.0 * r1 / 24.0
            rows.add(f"validation_{system}_S2_slope_over_s", f"r=0..{r1:g}D", -0.25, *_mean_sem(slope),
                     systematic=bias, reason_if_failed="not identified")


def comparison(inputs, tables, params, checked_rows: pd.DataFrame | None = None):
    """(comparison frame, notes frame) of every table cell, quoted number and validation row;
    ``checked_rows`` (already compared, e.g. the equilibrium liquid's pressure against its
    equation of state) are appended as they are.

    Parameters
    ----------
    inputs : Mapping[str, path]
        Merged descriptor files named ``{kind}_{system}``.
    tables : list of path
        Our table CSVs, whose names end in ``table{n}.csv``; a Table II-V without ours gets
        published cells with NaN ours.
    params : dict
        Rule parameters: ``k_sigma``, ``overlapping_phi``, ``windows["phi_B"]``,
        ``spectral["bin_width"]``, ``n_samples`` (system -> count).
    checked_rows : pandas.DataFrame, optional
        Rows compared elsewhere, with the columns of :data:`randmedia.compare.COLUMNS`.

    Returns
    -------
    tuple of pandas.DataFrame
        (comparison frame, notes frame). The reference CSVs are read from
        ``config/reference/`` relative to the working directory.
    """
    rows = Rows(params["k_sigma"])
    references = {2: "config/reference/mrj2016_table2_equilibrium.csv",
                  3: "config/reference/mrj2016_table3_mrj.csv",
                  4: "config/reference/mrj2016_table4_spectral_equilibrium.csv",
                  5: "config/reference/mrj2016_table5_spectral_mrj.csv"}
    by_number = {int(str(path).rsplit("table", 1)[1].split(".")[0]): path for path in tables}
    for number, reference in references.items():
        if number in by_number:
            _table_rows(rows, by_number[number], reference, number, inputs)
        else:  # the system is not part of this workflow: the cells stay, unmatched
            published = pd.read_csv(reference, dtype=str)
            columns = ["S2", "Fsv_over_s", "Fss_over_s2", "EV"] if number in (2, 3) else ["chiV_over_D3"]
            coord = "r_over_D" if number in (2, 3) else "kD"
            for i, key in enumerate(published[coord]):
                for column in columns:
                    text = published[column].iloc[i]
                    if not pd.isna(text):
                        rows.add(f"table{number}_{column}", f"{'r/D' if number < 4 else 'kD'}={key}",
                                 float(text), math.nan, reason_if_failed=f"system {TABLE_SYSTEMS[number]} not in this workflow")
    _quoted_rows(rows, "config/reference/mrj2016_quoted_numbers.csv", inputs, params)
    _validation_rows(rows, inputs, params)
    if checked_rows is not None:
        rows.add_checked(checked_rows, "see the generator's validation files (results/mrj2016/validation/)")
    return comparison_frame(rows.rows), notes_frame(rows.rows)
