"""Power-law exponents sigma^2_n(a) ~ a^delta (sphere2019, Eq. 10 and Table I).

Conventions (:mod:`randmedia.fit`): a :class:`~randmedia.fit.FitResult` with the
value, its statistical error, chi^2 per degree of freedom of the SEM-weighted
residuals and the number of points. A variance curve is not a per-sample
quantity, so instead of fitting each sample (block) separately -- which would fit
the logarithm of noisy per-block variances, a biased statistic -- the value is the
fit to the pooled curve and the error is the jackknife over blocks: the same fit
applied to each leave-one-block-out curve (stored by
:mod:`randmedia.describe.sphere_points`),

    error^2 = (B - 1)/B sum_i (delta_(i) - mean delta_(.))^2 .

The fit is ordinary least squares of ln sigma^2 on ln a over the grid points
a_min <= a <= a_max (the window of the scaling regime rho^(-1/2) << a < R; the
workflow states the window it used). The grid points of a cap-variance curve come
from the same configurations and are correlated, so chi^2/dof is a diagnostic only
(values far above 1 flag a curve that is not a power law in the window, e.g. the
oscillations of a lattice).

Window systematic. The paper states the scaling regime (rho^(-1/2) << a < R) but
not the window it fitted, so the same curve gives exponents that differ between
reasonable windows. :func:`sphere_exponents` refits every curve over a family of
windows (every lower end of ``window_family["a_min_rho_half"]`` with every upper end
of ``window_family["a_max_over_R"]``; windows with < 3 grid points or sigma^2 <= 0,
e.g. a lattice's sigma^2(R) = 0, are skipped) and records the largest deviation
max_w |delta_w - delta| from the main window: the measured systematic the Table I
comparison adds to the statistical tolerance (:mod:`randmedia.compare.sphere2019`).
"""

from __future__ import annotations

import numpy as np

from randmedia.fit import FitResult


def _inside(a: np.ndarray, a_min: float, a_max: float) -> np.ndarray:
    """Grid points inside [a_min, a_max] (ends included up to round-off)."""
    return (a >= a_min * (1 - 1e-12)) & (a <= a_max * (1 + 1e-12))


def window_mask(a, a_min: float, a_max: float) -> np.ndarray:
    """Grid points inside [a_min, a_max]; at least 3 are required.

    Parameters
    ----------
    a : array_like
        Cap base radii of the grid, shape (K,).
    a_min, a_max : float
        Window ends, a_min < a_max (same unit as ``a``).

    Returns
    -------
    numpy.ndarray
        Boolean mask, shape (K,).
    """
    a = np.asarray(a, dtype=float)
    if not a_min < a_max:
        raise ValueError(f"fit window needs a_min < a_max, got [{a_min:g}, {a_max:g}]")
    mask = _inside(a, a_min, a_max)
    if mask.sum() < 3:
        raise ValueError(f"fewer than 3 cap radii in the fit window [{a_min:g}, {a_max:g}]")
    return mask


def _log_log_slope(log_a: np.ndarray, values: np.ndarray) -> tuple[float, float]:
    if np.any(values <= 0) or not np.all(np.isfinite(values)):
        return float("nan"), float("nan")
    slope, intercept = np.polyfit(log_a, np.log(values), 1)
    return float(slope), float(intercept)


def _jackknife_error(estimates: np.ndarray) -> float:
    estimates = np.asarray(estimates, dtype=float)
    n = estimates.size
    if n < 2:
        raise ValueError("the jackknife needs at least 2 leave-one-out estimates")
    return float(np.sqrt((n - 1) / n * np.sum((estimates - estimates.mean()) ** 2)))


def power_law_exponent(a, sigma2, leave_out, *, a_min: float, a_max: float,
                       sem=None) -> FitResult:
    """delta of sigma2 ~ a^delta in [a_min, a_max] with its jackknife error (module docstring).

    ``leave_out``: (B, K) leave-one-block-out curves on the same grid ``a`` (K,);
    ``sem``: SEM of sigma2 (for chi^2/dof; NaN without it).

    Parameters
    ----------
    a : array_like
        Cap base radii, shape (K,).
    sigma2 : array_like
        Pooled variance curve, shape (K,).
    leave_out : array_like
        Leave-one-block-out curves, shape (B, K).
    a_min, a_max : float
        Fit window (unit of ``a``).
    sem : array_like or None
        SEM of ``sigma2``, shape (K,), or None.

    Returns
    -------
    FitResult
        delta, its jackknife error, chi2_per_dof (NaN without ``sem``) and the points used.
    """
    a, sigma2 = np.asarray(a, float), np.asarray(sigma2, float)
    leave_out = np.asarray(leave_out, float)
    if sigma2.shape != a.shape or leave_out.ndim != 2 or leave_out.shape[1] != a.size:
        raise ValueError("sigma2 must match a, and leave_out must have shape (blocks, len(a))")
    mask = window_mask(a, a_min, a_max)
    log_a = np.log(a[mask])
    slope, intercept = _log_log_slope(log_a, sigma2[mask])
    if not np.isfinite(slope):
        raise ValueError("sigma^2 must be > 0 throughout the fit window")
    error = _jackknife_error([_log_log_slope(log_a, curve[mask])[0] for curve in leave_out])
    chi2 = float("nan")
    if sem is not None:
        relative = np.asarray(sem, float)[mask] / sigma2[mask]
        if np.all(relative > 0):
            residual = (np.log(sigma2[mask]) - (slope * log_a + intercept)) / relative
            chi2 = float(residual @ residual / max(1, mask.sum() - 2))
    return FitResult(value=slope, error=error, chi2_per_dof=chi2, n_points=int(mask.sum()))


def window_mean(a, values, leave_out, *, a_min: float, a_max: float) -> FitResult:
    """Mean of ``values`` (e.g. sigma^2/(rho s)) over the window, with the jackknife error
    from the leave-one-block-out curves (a zero-parameter fit: chi^2/dof is NaN).

    Parameters
    ----------
    a : array_like
        Cap base radii, shape (K,).
    values : array_like
        Curve to average, shape (K,).
    leave_out : array_like
        Its leave-one-block-out curves, shape (B, K).
    a_min, a_max : float
        Window (unit of ``a``).

    Returns
    -------
    FitResult
        The window mean, its jackknife error, NaN chi2_per_dof and the points used.
    """
    a, values = np.asarray(a, float), np.asarray(values, float)
    leave_out = np.asarray(leave_out, float)
    mask = window_mask(a, a_min, a_max)
    error = _jackknife_error(leave_out[:, mask].mean(axis=1))
    return FitResult(value=float(values[mask].mean()), error=error, chi2_per_dof=float("nan"),
                     n_points=int(mask.sum()))


def window_family_exponents(a, sigma2, *, rho: float, radius: float,
                            a_min_rho_half, a_max_over_R) -> np.ndarray:
    """delta of the pooled curve over every window [m / rho^(1/2), x R] of the family
    (m in ``a_min_rho_half``, x in ``a_max_over_R``); windows with < 3 grid points or
    sigma^2 <= 0 inside are skipped (module docstring, "Window systematic").

    Parameters
    ----------
    a : array_like
        Cap base radii, shape (K,).
    sigma2 : array_like
        Pooled variance curve, shape (K,).
    rho : float
        Number density (1/length^2).
    radius : float
        Sphere radius R.
    a_min_rho_half : iterable of float
        Lower window ends in units of rho^(-1/2).
    a_max_over_R : iterable of float
        Upper window ends in units of R.

    Returns
    -------
    numpy.ndarray
        delta of each usable window, shape (n_windows,).
    """
    a, sigma2 = np.asarray(a, float), np.asarray(sigma2, float)
    deltas = []
    for low in a_min_rho_half:
        for high in a_max_over_R:
            mask = _inside(a, low / np.sqrt(rho), high * radius)
            if mask.sum() < 3:  # (an empty or inverted window has no points)
                continue
            slope = _log_log_slope(np.log(a[mask]), sigma2[mask])[0]
            if np.isfinite(slope):
                deltas.append(slope)
    return np.array(deltas)


def sphere_exponents(descriptors: dict, *, a_min_rho_half: float, a_max_over_R: float,
                     window_family: dict | None = None):
    """delta per system from sphere2019 descriptor files (system -> Dataset of
    :mod:`randmedia.describe.sphere_points`): fit window a in [a_min_rho_half / rho^(1/2),
    a_max_over_R * R]; delta for both window-centre variants (NaN where a file has only
    random centres), the window mean of sigma^2/(rho s), and the window systematic of
    delta over ``window_family`` ({"a_min_rho_half": [...], "a_max_over_R": [...]}; the
    main window alone when None; module docstring).

    Parameters
    ----------
    descriptors : dict
        System name -> descriptor Dataset (attrs ``R``, ``density``, ``mean_n_points``,
        ``ensemble``; variables ``sigma2``, ``sigma2_sem``, ``sigma2_jackknife``, ``cap_area``).
    a_min_rho_half : float
        Lower end of the main window in units of rho^(-1/2).
    a_max_over_R : float
        Upper end of the main window in units of R.
    window_family : dict or None
        Windows for the systematic, as above; None: the main window only.

    Returns
    -------
    xarray.Dataset
        One entry per system (dimension ``system``), variables described in their attrs.
    """
    import xarray as xr

    family = window_family or {"a_min_rho_half": [a_min_rho_half], "a_max_over_R": [a_max_over_R]}
    names = sorted(descriptors)
    columns: dict[str, list] = {key: [] for key in (
        "delta", "delta_err", "delta_chi2_per_dof", "delta_three_origins", "delta_three_origins_err",
        "fit_a_min", "fit_a_max", "fit_points", "delta_window_min", "delta_window_max",
        "window_systematic", "windows_used", "scaled_mean", "scaled_mean_err", "R", "density",
        "n_particles", "ensemble")}
    for name in names:
        ds = descriptors[name]
        radius, rho = float(ds.attrs["R"]), float(ds.attrs["density"])
        a_min, a_max = a_min_rho_half / np.sqrt(rho), a_max_over_R * radius
        a = ds["a"].values
        results = {}
        for variant in ds["variant"].values:
            sel = ds.sel(variant=variant)
            results[str(variant)] = power_law_exponent(
                a, sel["sigma2"].values, sel["sigma2_jackknife"].values, a_min=a_min, a_max=a_max,
                sem=sel["sigma2_sem"].values)
        main = results["random_centres"]
        origins = results.get("three_origins")
        sel = ds.sel(variant="random_centres")
        family_deltas = np.append(window_family_exponents(
            a, sel["sigma2"].values, rho=rho, radius=radius, **family), main.value)
        scale = rho * ds["cap_area"].values
        level = window_mean(a, sel["sigma2"].values / scale, sel["sigma2_jackknife"].values / scale,
                            a_min=a_min, a_max=a_max)
        for key, value in (("delta", main.value), ("delta_err", main.error),
                           ("delta_chi2_per_dof", main.chi2_per_dof),
                           ("delta_three_origins", origins.value if origins else np.nan),
                           ("delta_three_origins_err", origins.error if origins else np.nan),
                           ("fit_a_min", a_min), ("fit_a_max", a_max), ("fit_points", main.n_points),
                           ("delta_window_min", family_deltas.min()),
                           ("delta_window_max", family_deltas.max()),
                           ("window_systematic", np.abs(family_deltas - main.value).max()),
                           ("windows_used", family_deltas.size - 1),
                           ("scaled_mean", level.value), ("scaled_mean_err", level.error),
                           ("R", radius), ("density", rho),
                           ("n_particles", float(ds.attrs["mean_n_points"])),
                           ("ensemble", str(ds.attrs["ensemble"]))):
            columns[key].append(value)
    meta = {
        "delta": "exponent delta of sigma^2_n ~ a^delta (random window centres)",
        "delta_err": "jackknife error of delta over blocks",
        "delta_chi2_per_dof": "chi^2 per degree of freedom of the log-log fit (diagnostic)",
        "delta_three_origins": "delta from the three orthogonal origins per sweep (paper's protocol)",
        "delta_three_origins_err": "jackknife error of delta_three_origins",
        "fit_a_min": "lower end of the fit window (a_min_rho_half / rho^(1/2))",
        "fit_a_max": "upper end of the fit window (a_max_over_R * R)",
        "fit_points": "cap radii in the fit window",
        "delta_window_min": "smallest delta over the window family (and the main window)",
        "delta_window_max": "largest delta over the window family (and the main window)",
        "window_systematic": "max |delta_w - delta| over the window family (comparison margin)",
        "windows_used": "windows of the family with >= 3 cap radii and sigma^2 > 0",
        "scaled_mean": "window mean of sigma^2/(rho s)",
        "scaled_mean_err": "jackknife error of scaled_mean",
        "R": "sphere radius", "density": "number density rho (or <rho>)",
        "n_particles": "(mean) number of points", "ensemble": "canonical or grand_canonical",
    }
    data = {key: (("system",), np.array(values), {"units": "1", "long_name": meta[key]})
            for key, values in columns.items()}
    return xr.Dataset(data, coords={"system": ("system", names, {"units": "1", "long_name": "system"})},
                      attrs={"a_min_rho_half": a_min_rho_half, "a_max_over_R": a_max_over_R,
                             "window_family_a_min_rho_half": list(family["a_min_rho_half"]),
                             "window_family_a_max_over_R": list(family["a_max_over_R"])})
