"""Validation of the equilibrium hard-disk / hard-sphere samples (randmedia.generate.hard_particles).

Per-sample diagnostics (read from the sample files' attributes) and comparison rows:

* reduced pressure beta p / rho from the contact value against an accurate equation of
  state (:mod:`randmedia.theory.hard_spheres`). ours = mean of the per-sample estimates
  (each from the pair counts near contact since the previous sample; the estimator is
  linear in the counts, so the mean is unbiased), ours_sem = their standard error.
  Stated systematic margin: 1 % of the EOS value -- the acceptance criterion of the
  issue, covering the EOS's own accuracy (Henderson 0.03 % at phi = 0.3, Kolafa
  0.02 % of the virial series at phi <= 0.3), the spread of contact extrapolations
  (0.15 %, measured) and finite-N effects of the NVT ensemble (~0.2-0.3 % at N = 500).
* digitized area fraction of the hard-disk images against N pi R^2 / L^2: for a
  translation-invariant ensemble every pixel centre is covered with probability
  N pi R^2 / L^2 (disks do not overlap), so this is the exact expectation; margin 0.
* decorrelation: the normalized lag-one correlation of Fourier density modes between
  consecutive samples of a chain, at the smallest wavevectors 2 pi / L (long-wavelength
  fluctuations, the slowest collective modes behind S(0)) and near the first peak of
  S(k) (k D ~ 7, local structure), against 0, its value for independent samples; the
  standard error is that of independent complex-Gaussian modes. This checks, beyond the
  MSD >= D^2 rule, that the samples are statistically independent.
"""

from __future__ import annotations

from typing import Iterable, Sequence

import numpy as np
import pandas as pd

from randmedia.compare import compare
from randmedia.generate.hard_particles.contact import contact_fit
from randmedia.generate.hard_particles.settings import MCSettings
from randmedia.stats import standard_error

#: per-sample attributes copied into the diagnostics table (those present)
DIAGNOSTIC_ATTRS = ("sample", "chain", "sample_in_chain", "acceptance", "msd_since_previous",
                    "sweeps_since_previous", "contact_value", "reduced_pressure",
                    "eos_reduced_pressure", "phi2_digitized", "phi2_disks", "phi_particles",
                    "global_q6", "crystalline_fraction", "equilibration_msd",
                    "equilibration_sweeps", "sample_interval_sweeps", "step_over_diameter")

#: relative systematic margin of the pressure comparison (module docstring)
PRESSURE_MARGIN = 0.01


def diagnostics_frame(datasets: Iterable) -> pd.DataFrame:
    """One row per sample file with the attributes of :data:`DIAGNOSTIC_ATTRS`."""
    rows = [{key: ds.attrs[key] for key in DIAGNOSTIC_ATTRS if key in ds.attrs} for ds in datasets]
    return pd.DataFrame(rows).sort_values("sample").reset_index(drop=True)


def pooled_contact(datasets: Sequence, settings: MCSettings) -> dict:
    """The contact fit on the pair counts of all samples together (box and diameter from the
    first file; every file must describe the same system)."""
    first = datasets[0]
    box = np.diag(first["box"].values)
    n, diameter = int(first.attrs["n_particles"]), float(first.attrs["diameter"])
    hist = np.zeros(first.sizes["contact_bin"], dtype=np.int64)
    measurements = 0
    for ds in datasets:
        if int(ds.attrs["n_particles"]) != n or not np.allclose(np.diag(ds["box"].values), box):
            raise ValueError("samples of different systems cannot be pooled")
        hist += ds["contact_pairs"].values.astype(np.int64)
        measurements += int(ds.attrs["contact_measurements"])
    fit = contact_fit(hist, measurements, n, box, diameter, settings)
    fit.update({"histogram": hist, "measurements": measurements, "n_particles": n,
                "box": box, "diameter": diameter})
    return fit


def pressure_row(frame: pd.DataFrame, quantity: str, key: str, *, k_sigma: float) -> dict:
    """Mean per-sample contact-value pressure against the EOS value (module docstring).

    Parameters
    ----------
    frame : pandas.DataFrame
        Diagnostics (:func:`diagnostics_frame`) with ``reduced_pressure`` per sample and
        ``eos_reduced_pressure`` (first row used).
    quantity, key : str
        Row labels.
    k_sigma : float
        Multiple of the SEM in the tolerance.

    Returns
    -------
    dict
        One comparison row, systematic margin :data:`PRESSURE_MARGIN` x the EOS value.
    """
    eos = float(frame["eos_reduced_pressure"].iloc[0])
    z = frame["reduced_pressure"].to_numpy(float)
    return compare(quantity, key, eos, float(z.mean()), float(standard_error(z)),
                   k_sigma=k_sigma, systematic=PRESSURE_MARGIN * eos)


def digitized_fraction_row(frame: pd.DataFrame, quantity: str, key: str, *, k_sigma: float) -> dict:
    """Mean digitized disk fraction against its exact expectation N pi R^2 / L^2.

    Parameters
    ----------
    frame : pandas.DataFrame
        Diagnostics (:func:`diagnostics_frame`) with ``phi2_digitized`` per sample and
        ``phi2_disks`` = N pi R^2 / L^2 (first row used).
    quantity, key : str
        Row labels.
    k_sigma : float
        Multiple of the SEM in the tolerance.

    Returns
    -------
    dict
        One comparison row, no systematic margin.
    """
    values = frame["phi2_digitized"].to_numpy(float)
    return compare(quantity, key, float(frame["phi2_disks"].iloc[0]), float(values.mean()),
                   float(standard_error(values)), k_sigma=k_sigma)


# --------------------------------------------------------------------------- decorrelation


def density_modes(positions: np.ndarray, box_lengths, k_over_d: float | None = None) -> np.ndarray:
    """Fourier density modes rho_k = sum_j exp(-i k.r_j) / sqrt(N) of one configuration.

    ``k_over_d`` None: the smallest wavevectors of the periodic box, k = 2 pi n / L with n
    the d unit vectors (the long-wavelength density fluctuations behind S(0)); else the
    3 d axis wavevectors with |k| D closest to ``k_over_d`` and its two neighbours (e.g.
    7, near the first peak of S(k) of the dense liquid), positions in units of D.

    Parameters
    ----------
    positions : ndarray, shape (N, d)
        Particle positions (units of D when ``k_over_d`` is given; same units as
        ``box_lengths``).
    box_lengths : array_like, shape (d,)
        Edge lengths of the periodic box.
    k_over_d : float or None, optional
        Target |k| D, or None for the smallest wavevectors.

    Returns
    -------
    ndarray of complex
        rho_k, one per wavevector: shape (d,) for None, else up to 3 d (axis multiples below 1
        are skipped).
    """
    positions = np.asarray(positions, dtype=float)
    box_lengths = np.asarray(box_lengths, dtype=float)
    dim = positions.shape[1]
    if k_over_d is None:
        n_vectors = np.eye(dim)
    else:
        vectors = []
        for axis in range(dim):
            m = max(1, round(k_over_d * box_lengths[axis] / (2 * np.pi)))
            for shift in (-1, 0, 1):
                if m + shift >= 1:
                    vector = np.zeros(dim)
                    vector[axis] = m + shift
                    vectors.append(vector)
        n_vectors = np.array(vectors)
    k = 2 * np.pi * n_vectors / box_lengths[None, :]
    return np.exp(-1j * positions @ k.T).sum(axis=0) / np.sqrt(len(positions))


def lag_one_correlation(chains: Sequence[Sequence[np.ndarray]]) -> tuple[float, float, int]:
    """Normalized correlation of density modes between consecutive samples of each chain.

    ``chains``: per chain, the mode vectors (:func:`density_modes`) of its samples in order.
    C = sum Re[rho_k(t) rho_k(t+1)^*] / sqrt(sum |rho_k(t)|^2 sum |rho_k(t+1)|^2) over the
    pairs and modes; for independent samples E[C] = 0 with standard error ~ 1/sqrt(pairs x
    modes) (each mode a complex Gaussian). Returns (C, that standard error, number of pairs).
    """
    products, first, second, pairs, modes = 0.0, 0.0, 0.0, 0, 0
    for chain in chains:
        for a, b in zip(chain[:-1], chain[1:]):
            products += float(np.sum((a * np.conj(b)).real))
            first += float(np.sum(np.abs(a) ** 2))
            second += float(np.sum(np.abs(b) ** 2))
            pairs += 1
            modes = len(a)
    if pairs == 0:
        return float("nan"), float("nan"), 0
    # Re(a b*) of two independent complex Gaussians has variance |a|^2 |b|^2 / 2
    return products / np.sqrt(first * second), 1.0 / np.sqrt(2.0 * pairs * modes), pairs


def decorrelation_rows(datasets: Sequence, quantity: str, *, k_sigma: float,
                       peak_k_over_d: float) -> list[dict]:
    """Comparison rows: lag-one correlation of density modes between consecutive samples of
    a chain (expected 0 for independent samples, the "published" value) at the smallest
    wavevectors and near the first peak of S(k). Positions are converted to units of D.

    Parameters
    ----------
    datasets : sequence of xarray.Dataset
        Sample files with ``position``, ``box`` and attributes ``chain``, ``sample``,
        ``diameter``; ordered here by (chain, sample).
    quantity : str
        Quantity label of the rows.
    k_sigma : float
        Multiple of the standard error in the tolerance.
    peak_k_over_d : float
        k D near the first peak of S(k) (passed as ``k_over_d`` to :func:`density_modes`).

    Returns
    -------
    list of dict
        Two comparison rows (k = 2 pi / L, then k D ~ ``peak_k_over_d``); the key gives the
        number of sample pairs.
    """
    by_chain: dict[int, list] = {}
    for ds in sorted(datasets, key=lambda d: (int(d.attrs["chain"]), int(d.attrs["sample"]))):
        diameter = float(ds.attrs["diameter"])
        box = np.diag(ds["box"].values) / diameter
        by_chain.setdefault(int(ds.attrs["chain"]), []).append((ds["position"].values / diameter, box))
    rows = []
    for label, k in (("k=2pi/L", None), (f"kD~{peak_k_over_d:g}", peak_k_over_d)):
        chains = [[density_modes(p, box, k) for p, box in chain] for chain in by_chain.values()]
        c, se, pairs = lag_one_correlation(chains)
        rows.append(compare(quantity, f"{label},pairs={pairs}", 0.0, c, se, k_sigma=k_sigma))
    return rows
