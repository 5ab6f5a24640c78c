"""Fits of Ma & Torquato, PRE 102, 043310 (2020): the lineal-path size L_w (Eq. 29)
and <R^2>/<R> (Eq. 30). Conventions (per-sample fits, SEM, chi^2/dof): :mod:`randmedia.fit`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from scipy.optimize import curve_fit

from randmedia.fit import FitResult

if TYPE_CHECKING:
    import xarray as xr


def lineal_path_length(z, lineal_path, phi1: float, sem=None, *,
                       min_fraction: float = 0.01) -> FitResult:
    """L_w of Ma & Torquato 2020, Eq. (29): L(z) = phi1 exp(-z / L_w), phi1 fixed.

    Fitted over the z with L(z) >= ``min_fraction`` * phi1 (beyond, the curve is
    dominated by the few longest chords). With ``sem`` the fit is weighted and
    its error statistical; without, unweighted (error from the residuals) and
    chi2_per_dof is NaN.

    Parameters
    ----------
    z : array_like
        Segment lengths, shape (n,) (pixels in the Debye workflow).
    lineal_path : array_like
        L(z), shape (n,).
    phi1 : float
        Volume fraction of the phase whose L is fitted (fixed prefactor).
    sem : array_like or None
        SEM of ``lineal_path``, shape (n,); None for an unweighted fit.
    min_fraction : float
        Lower cut: points with L(z) < min_fraction * phi1 are left out (default 0.01).

    Returns
    -------
    FitResult
        L_w (length unit of ``z``) with its error, chi2_per_dof and the number of points used.
    """
    z, lineal_path = np.asarray(z, dtype=float), np.asarray(lineal_path, dtype=float)
    weighted = sem is not None
    sem = np.asarray(sem, dtype=float) if weighted else np.ones_like(lineal_path)
    keep = (lineal_path >= min_fraction * phi1) & (sem > 0)
    if keep.sum() < 3:
        raise ValueError("fewer than 3 points with L(z) above the fit threshold")
    guess = -z[keep][-1] / np.log(lineal_path[keep][-1] / phi1) if z[keep][-1] > 0 else 1.0

    def model(x, length):
        return phi1 * np.exp(-x / length)

    (length,), covariance = curve_fit(model, z[keep], lineal_path[keep], p0=[guess],
                                      sigma=sem[keep] if weighted else None,
                                      absolute_sigma=weighted)
    residual = (lineal_path[keep] - model(z[keep], length)) / sem[keep]
    dof = max(1, keep.sum() - 1)
    chi2 = float(residual @ residual / dof) if weighted else float("nan")
    return FitResult(float(length), float(np.sqrt(covariance[0, 0])), chi2, int(keep.sum()))


def r2_over_r(lineal_length: float, phi1: float) -> float:
    """<R^2>/<R> of overlapping polydisperse disks with the same L_w (Eq. 30):
    L_w = -pi / (2 ln phi1) <R^2>/<R>."""
    return -2.0 * np.log(phi1) * lineal_length / np.pi


# --------------------------------------------------------------------------- Sec. V A


def formula_deviation(r, mean, sem, formula, *, r_min: float, r_max: float) -> dict:
    """How a parameter-free formula (Eqs. 24, 26) meets a sample-mean curve on r_min <= r <= r_max:
    chi^2/dof of the SEM-weighted residuals (dof = number of points: nothing is fitted),
    the largest and the mean relative deviation (curve / formula - 1).

    Parameters
    ----------
    r : array_like
        Radial bin positions, shape (n,).
    mean : array_like
        Sample-mean curve, shape (n,).
    sem : array_like
        Its SEM, shape (n,); points with sem <= 0 are left out.
    formula : callable
        formula(r) -> expected values (the parameter-free formula).
    r_min, r_max : float
        Comparison window, inclusive (length unit of ``r``).

    Returns
    -------
    dict
        ``chi2_per_dof``, ``n_points``, ``max_abs_rel_dev``, ``r_at_max`` (the r of that
        deviation) and ``mean_rel_dev``.
    """
    r, mean, sem = (np.asarray(v, dtype=float) for v in (r, mean, sem))
    keep = (r >= r_min) & (r <= r_max) & (sem > 0)
    if keep.sum() < 1:
        raise ValueError(f"no points with {r_min} <= r <= {r_max} and SEM > 0")
    expected = np.asarray(formula(r[keep]), dtype=float)
    z = (mean[keep] - expected) / sem[keep]
    relative = mean[keep] / expected - 1.0
    worst = int(np.argmax(np.abs(relative)))
    return {"chi2_per_dof": float(z @ z / z.size), "n_points": int(z.size),
            "max_abs_rel_dev": float(abs(relative[worst])), "r_at_max": float(r[keep][worst]),
            "mean_rel_dev": float(relative.mean())}


def logistic_slope(r, curve, *, r_min: float, r_max: float, scale_guess: float) -> float:
    """dF/dr at r = 0 of a logistic F(r) = A + B / (1 + exp(-r/b)) fitted (A, B, b free,
    unweighted least squares) to ``curve`` over r_min <= r <= r_max: B / (4 b).

    This is the estimator of the specific Euler characteristic chi/V = dF_sv/dr|_0 (Eq. 13).
    The logistic is the form Ma & Torquato found F_sv to follow (Sec. V A, "we fit the
    computed F_sv(r) by logistic functions"), with the origin at its midpoint as Eq. (24)
    has it; it is not forced to Eq. (24): A, B and b are free. r_min excludes the bins the
    interface deposit smears. A local polynomial is no alternative: F_sv bends over r ~ a and
    the slope of a quadratic over [1 px, a] is 25 % below that over [1 px, 2a] on Debye media.

    Parameters
    ----------
    r : array_like
        Radial bin positions, shape (n,).
    curve : array_like
        F_sv (or another curve) on ``r``, shape (n,).
    r_min, r_max : float
        Fit window, inclusive; at least 4 points required.
    scale_guess : float
        Initial logistic width b (e.g. a); b is bounded to [0.05, 50] * scale_guess.

    Returns
    -------
    float
        B / (4 b), units of curve / length.
    """
    r, curve = np.asarray(r, dtype=float), np.asarray(curve, dtype=float)
    keep = (r >= r_min) & (r <= r_max)
    if keep.sum() < 4:
        raise ValueError(f"fewer than 4 points with {r_min} <= r <= {r_max}")
    x, y = r[keep], curve[keep]

    def model(d, base, height, scale):
        return base + height / (1.0 + np.exp(-d / scale))

    start = [2 * y[0] - y[-1], 2 * (y[-1] - y[0]), scale_guess]
    (base, height, scale), _ = curve_fit(model, x, y, p0=start, maxfev=20000,
                                         bounds=([-np.inf, -np.inf, 0.05 * scale_guess],
                                                 [np.inf, np.inf, 50.0 * scale_guess]))
    return float(height / (4.0 * scale))


# --------------------------------------------------------------------------- Sec. V B


def pore_size_fit(delta, density, *, p0: float, p2: float | None, sem=None,
                  delta_max: float) -> tuple[FitResult, float]:
    """Fit Eq. (27), P = (p0 + 2 p1 delta) exp(-p1 delta^2 - p2 delta), to a pore-size density
    over 0 <= delta <= delta_max, p0 fixed. With ``p2`` given only p1 is free (the paper's fit,
    p2 = p0 = pi phi2 / a); with ``p2=None`` p2 is free too. Returns (FitResult of p1, p2).
    Weighted by ``sem`` when given (then chi2_per_dof is meaningful), else unweighted.

    Parameters
    ----------
    delta : array_like
        Pore-size bin positions, shape (n,) (pixels).
    density : array_like
        P(delta) on ``delta``, shape (n,).
    p0 : float
        Fixed prefactor of Eq. (27) (1/length).
    p2 : float or None
        Fixed p2 (1/length), or None to fit it.
    sem : array_like or None
        SEM of ``density``, shape (n,); None for an unweighted fit.
    delta_max : float
        Upper end of the fit window; at least 4 bins required.

    Returns
    -------
    tuple of (FitResult, float)
        p1 (1/length^2) as a FitResult, and p2 (the fitted value, or ``p2`` as given).
    """
    delta, density = np.asarray(delta, dtype=float), np.asarray(density, dtype=float)
    weighted = sem is not None
    sem = np.asarray(sem, dtype=float) if weighted else np.ones_like(density)
    keep = (delta <= delta_max) & (sem > 0)
    if keep.sum() < 4:
        raise ValueError(f"fewer than 4 pore-size bins below delta_max = {delta_max}")
    x, y, w = delta[keep], density[keep], sem[keep]
    guess_p2 = p0 if p2 is None else p2
    # initial p1 from F(delta) ~ exp(-p1 delta^2 - p2 delta) at the median of the range
    guess_p1 = max(1e-6, 1.0 / max(x[-1], 1e-9) ** 2)

    if p2 is None:
        def model(d, p1, q2):
            return (p0 + 2.0 * p1 * d) * np.exp(-p1 * d * d - q2 * d)
        start = [guess_p1, guess_p2]
    else:
        def model(d, p1):
            return (p0 + 2.0 * p1 * d) * np.exp(-p1 * d * d - p2 * d)
        start = [guess_p1]
    values, covariance = curve_fit(model, x, y, p0=start, sigma=w if weighted else None,
                                   absolute_sigma=weighted, maxfev=20000)
    residual = (y - model(x, *values)) / w
    dof = max(1, x.size - len(values))
    chi2 = float(residual @ residual / dof) if weighted else float("nan")
    fitted_p2 = float(values[1]) if p2 is None else float(p2)
    return (FitResult(float(values[0]), float(np.sqrt(covariance[0, 0])), chi2, int(x.size)),
            fitted_p2)


def p1_polynomial(phi2, p1, p1_err, a: float) -> dict:
    """Weighted least squares of a^2 p1 = c1 phi2 + c2 phi2^2 + c3 phi2^3 (the cubic quoted
    after Eq. 27) with weights 1/(a^2 p1_err)^2. Returns the coefficients, their covariance
    (from the stated errors, not rescaled) and chi^2/dof (dof = n - 3).

    Parameters
    ----------
    phi2 : array_like
        Volume fractions of phase 2, shape (n,), n >= 3.
    p1 : array_like
        Fitted p1 per volume fraction, shape (n,) (1/length^2).
    p1_err : array_like
        Standard errors of ``p1``, shape (n,), all > 0.
    a : float
        Correlation length of the media (length unit of 1/sqrt(p1)).

    Returns
    -------
    dict
        ``coefficients`` (3,), ``covariance`` (3, 3), ``chi2_per_dof`` (NaN when dof = 0)
        and ``dof``.
    """
    phi2, p1, p1_err = (np.asarray(v, dtype=float) for v in (phi2, p1, p1_err))
    if phi2.size < 3:
        raise ValueError("need at least 3 volume fractions for a cubic without constant term")
    if np.any(p1_err <= 0):
        raise ValueError("p1 errors must be > 0")
    design = np.column_stack([phi2, phi2**2, phi2**3])
    y, sigma = a * a * p1, a * a * p1_err
    weighted = design / sigma[:, None]
    normal = weighted.T @ weighted
    covariance = np.linalg.inv(normal)
    coefficients = covariance @ (weighted.T @ (y / sigma))
    residual = (y - design @ coefficients) / sigma
    dof = phi2.size - 3
    return {"coefficients": coefficients, "covariance": covariance,
            "chi2_per_dof": float(residual @ residual / dof) if dof > 0 else float("nan"),
            "dof": dof}


def eq27_normalization(p0: float, p1: float, p2: float) -> float:
    """integral_0^inf of Eq. (27) by quadrature (1 exactly when p0 = p2, for any p1 > 0).

    Parameters
    ----------
    p0 : float
        Prefactor of Eq. (27) (1/length).
    p1 : float
        Quadratic coefficient (1/length^2).
    p2 : float
        Linear coefficient (1/length).

    Returns
    -------
    float
        The integral of P(delta) over [0, inf).
    """
    from scipy.integrate import quad

    value, _ = quad(lambda d: (p0 + 2 * p1 * d) * np.exp(-p1 * d * d - p2 * d), 0.0, np.inf,
                    epsabs=0.0, epsrel=1e-12, limit=200)
    return float(value)


def wrapping_crossing(phi2, wraps_phase2, wraps_phase1, n_samples: int) -> tuple[float, float, float]:
    """Where the fraction of samples in which phase 2 wraps around the periodic image crosses
    1/2: (phi2_c, its statistical error, the spacing of the bracketing volume fractions).

    Debye media are constructed phase-inversion symmetric (phi2 and 1 - phi2 are the same
    construction with the phases swapped), so the phase-1 fraction at phi2 is the phase-2
    fraction at 1 - phi2; both are combined into one curve over phi2 and 1 - phi2 (the two
    estimates at phi2 = 1/2 averaged). The crossing is linearly interpolated between the
    two bracketing points; its error propagates the binomial errors sqrt(f (1 - f) / n) of
    those two fractions (f clipped to [1/(2n), 1 - 1/(2n)]). Between grid points the curve is
    not measured, so the bracket spacing is the honest resolution. (nan, nan, nan) if the
    curve never crosses 1/2.

    Parameters
    ----------
    phi2 : array_like
        Volume fractions of phase 2, shape (n,).
    wraps_phase2 : array_like
        Fraction of samples in which phase 2 wraps, per ``phi2``, shape (n,).
    wraps_phase1 : array_like
        Same for phase 1, shape (n,).
    n_samples : int
        Samples per volume fraction (for the binomial errors).

    Returns
    -------
    tuple of float
        (phi2_c, its error, bracket spacing); all NaN without a crossing.
    """
    phi2 = np.asarray(phi2, dtype=float)
    curve = {}
    for p, f2, f1 in zip(phi2, wraps_phase2, wraps_phase1):
        curve.setdefault(round(float(p), 12), []).append(float(f2))
        curve.setdefault(round(1.0 - float(p), 12), []).append(float(f1))
    x = np.array(sorted(curve))
    f = np.array([np.mean(curve[v]) for v in x])
    above = np.nonzero(f >= 0.5)[0]
    if above.size == 0 or above[0] == 0:
        return float("nan"), float("nan"), float("nan")
    k = above[0]
    x0, x1, f0, f1 = x[k - 1], x[k], f[k - 1], f[k]
    crossing = x0 + (0.5 - f0) / (f1 - f0) * (x1 - x0)
    clip = 1.0 / (2 * n_samples)
    sd0, sd1 = (np.sqrt(np.clip(v, clip, 1 - clip) * (1 - np.clip(v, clip, 1 - clip)) / n_samples)
                for v in (f0, f1))
    # d crossing / d f0 and d f1
    d0 = (x1 - x0) * (0.5 - f1) / (f1 - f0) ** 2
    d1 = -(x1 - x0) * (0.5 - f0) / (f1 - f0) ** 2
    return float(crossing), float(np.hypot(d0 * sd0, d1 * sd1)), float(x1 - x0)


def _relative_error(formula: float, simulated: float, sem: float) -> tuple[float, float]:
    """(formula - simulated) / simulated and its standard error from the SEM of simulated."""
    return (formula - simulated) / simulated, formula * sem / simulated**2


def surface_pore_fits(systems: dict, *, a: float, fits: dict) -> "xr.Dataset":
    """Every Sec. V A-B number of the Debye media, per phi2, from the level-set descriptors.

    ``systems`` maps phi2 -> (surface dataset, pore-size dataset) of
    :func:`randmedia.describe.surface.surface_functions` /
    :func:`randmedia.describe.pore_size.pore_size_functions`; ``fits`` is the config
    section ``debye2020.fits``. Values with errors are means and SEMs of per-sample
    quantities; chi^2/dof compare sample-mean curves with SEM-weighted residuals.

    Parameters
    ----------
    systems : dict
        phi2 -> (surface dataset, pore-size dataset), as above.
    a : float
        Correlation length of the media (pixels).
    fits : dict
        The ``debye2020.fits`` config section (fit windows and thresholds).

    Returns
    -------
    xarray.Dataset
        One row per phi2 (units in each variable's attrs, mostly pixels), the p1 cubic
        coefficients and covariances, and the percolation crossing in ``attrs``.
    """
    import xarray as xr

    from randmedia.stats import standard_error
    from randmedia.theory import debye_formulas as debye

    rows = []
    for phi2, (surface, pores) in sorted(systems.items()):
        row = {"phi2": phi2}
        r = surface["r"].values
        window = dict(r_min=fits["formula_r_min"], r_max=fits["formula_r_max_over_a"] * a)
        for name, formula in (("F_sv", debye.debye_surface_void), ("F_ss", debye.debye_surface_surface)):
            dev = formula_deviation(r, surface[name].values, surface[f"{name}_sem"].values,
                                    lambda x: formula(x, phi2, a), **window)
            row.update({f"{name}_chi2_per_dof": dev["chi2_per_dof"], f"{name}_n_points": dev["n_points"],
                        f"{name}_max_abs_rel_dev": dev["max_abs_rel_dev"],
                        f"{name}_r_at_max_dev": dev["r_at_max"],
                        f"{name}_mean_rel_dev": dev["mean_rel_dev"]})
        s = surface["s_samples"].values
        row.update(s=s.mean(), s_sem=standard_error(s), s_exact=debye.debye_specific_surface(a, phi2),
                   sigma=float(surface.attrs["sigma"]))
        # specific Euler characteristic: logistic slope of F_sv at r = 0 (Eq. 13), two windows
        slopes = {}
        for key in ("euler_fit_r_max_over_a", "euler_fit_r_max_alt_over_a"):
            slopes[key] = np.array([
                logistic_slope(r, curve, r_min=fits["euler_fit_r_min"], r_max=fits[key] * a,
                               scale_guess=a)
                for curve in surface["F_sv_samples"].values])
        main = slopes["euler_fit_r_max_over_a"]
        alternative = slopes["euler_fit_r_max_alt_over_a"]
        topo = surface["euler_samples"].values
        row.update(euler_slope=main.mean(), euler_slope_sem=standard_error(main),
                   euler_slope_window_shift=abs(alternative.mean() - main.mean()),
                   euler_topological=topo.mean(), euler_topological_sem=standard_error(topo),
                   euler_formula=debye.debye_euler_characteristic(phi2, a),
                   wraps_phase2=surface["wraps_phase2_samples"].values.mean(),
                   wraps_phase1=surface["wraps_phase1_samples"].values.mean(),
                   n_samples=surface.sizes["sample"])
        # pore sizes: Eq. (27) with p0 = p2 = pi phi2 / a, p1 free; then p2 free too
        p0 = np.pi * phi2 / a
        centres, F = pores["delta_bin"].values, pores["F"].values
        resolved = pores["delta"].values[F >= fits["pore_fit_F_min"]]
        delta_max = float(resolved[-1])
        per_sample = [pore_size_fit(centres, P, p0=p0, p2=p0, delta_max=delta_max)[0].value
                      for P in pores["P_samples"].values]
        free = [pore_size_fit(centres, P, p0=p0, p2=None, delta_max=delta_max)
                for P in pores["P_samples"].values]
        mean_fit, _ = pore_size_fit(centres, pores["P"].values, p0=p0, p2=p0,
                                    sem=pores["P_sem"].values, delta_max=delta_max)
        p1 = np.array(per_sample)
        p2_free = np.array([f[1] for f in free])
        # P(0): the first bin, [0, w]; it averages P over w, so the margin is what Eq. (27) with
        # the fitted p1 changes over half a bin (the next bins carry the level set's rounded
        # pixel steps, a few % at delta ~ 0.3-0.5 px, and would bias an extrapolation)
        p0_measured = pores["P_samples"].values[:, 0]
        width = float(pores["delta"].values[1] - pores["delta"].values[0])
        mean_delta = pores["mean_delta_samples"].values
        row.update(p0_formula=p0, p1=p1.mean(), p1_sem=standard_error(p1),
                   p1_chi2_per_dof=mean_fit.chi2_per_dof, pore_fit_delta_max=delta_max,
                   p2_free=p2_free.mean(), p2_free_sem=standard_error(p2_free),
                   p1_with_p2_free=np.mean([f[0].value for f in free]),
                   p0_measured=p0_measured.mean(), p0_measured_sem=standard_error(p0_measured),
                   p0_bin_margin=abs(float(debye.pore_size_density(0.5 * width, p0, p1.mean(), p0)) - p0),
                   eq27_normalization=eq27_normalization(p0, p1.mean(), p0),
                   mean_delta=mean_delta.mean(), mean_delta_sem=standard_error(mean_delta),
                   mean_delta_eq28=debye.debye_mean_pore_size(phi2, a))
        row["eq28_rel_error"], row["eq28_rel_error_sem"] = _relative_error(
            row["mean_delta_eq28"], row["mean_delta"], row["mean_delta_sem"])
        # second reading of "pore size" on pixels: void pixel centre to the nearest phase-2
        # pixel centre (the paper does not say how it sampled P(delta) from its images)
        centre = pores["mean_delta_pixel_centres_samples"].values
        row["mean_delta_pixel_centres"] = centre.mean()
        row["mean_delta_pixel_centres_sem"] = standard_error(centre)
        row["eq28_rel_error_pixel_centres"], row["eq28_rel_error_pixel_centres_sem"] = _relative_error(
            row["mean_delta_eq28"], row["mean_delta_pixel_centres"], row["mean_delta_pixel_centres_sem"])
        p1_centres = np.array([pore_size_fit(centres, P, p0=p0, p2=p0, delta_max=delta_max)[0].value
                               for P in pores["P_pixel_centres_samples"].values])
        row["p1_pixel_centres"] = p1_centres.mean()
        row["p1_pixel_centres_sem"] = standard_error(p1_centres)
        rows.append(row)

    phi2 = np.array([row["phi2"] for row in rows])

    def cubic_of(name):
        if phi2.size < 3:
            return np.full(3, np.nan), np.full((3, 3), np.nan), np.nan
        cubic = p1_polynomial(phi2, [row[name] for row in rows], [row[f"{name}_sem"] for row in rows], a)
        return cubic["coefficients"], cubic["covariance"], cubic["chi2_per_dof"]

    coefficients, covariance, chi2 = cubic_of("p1")
    centre_coefficients, centre_covariance, centre_chi2 = cubic_of("p1_pixel_centres")
    for row in rows:
        if np.all(np.isfinite(coefficients)):
            own = debye.mean_pore_size(float(debye.pore_p1(row["phi2"], a, coefficients)),
                                       np.pi * row["phi2"] / a)
        else:
            own = np.nan
        row["mean_delta_eq28_own_coefficients"] = own

    units = _SURFACE_PORE_UNITS
    data = {name: ("phi2", np.array([row[name] for row in rows], dtype=float),
                   {"units": units[name][0], "long_name": units[name][1]})
            for name in rows[0] if name != "phi2"}
    data["p1_coefficients"] = ("power", coefficients, {"units": "1", "long_name":
                               "c_k of a^2 p1 = c1 phi2 + c2 phi2^2 + c3 phi2^3 (SEM-weighted fit)"})
    data["p1_coefficients_covariance"] = (("power", "power_b"), covariance, {"units": "1", "long_name":
                                          "covariance of the c_k from the p1 standard errors"})
    data["p1_coefficients_pixel_centres"] = ("power", centre_coefficients, {"units": "1", "long_name":
                                             "c_k of the cubic fitted to p1_pixel_centres"})
    data["p1_coefficients_pixel_centres_covariance"] = (
        ("power", "power_b"), centre_covariance, {"units": "1", "long_name":
                                                  "covariance of the pixel-centre c_k"})
    return xr.Dataset(
        data,
        coords={"phi2": ("phi2", phi2, {"units": "1", "long_name": "volume fraction of phase 2"}),
                "power": ("power", [1, 2, 3], {"units": "1", "long_name": "power of phi2"}),
                "power_b": ("power_b", [1, 2, 3], {"units": "1", "long_name": "power of phi2"})},
        attrs={"a": a, "p1_cubic_chi2_per_dof": chi2, "p1_pixel_centres_cubic_chi2_per_dof": centre_chi2,
               **dict(zip(("percolation_crossing", "percolation_crossing_err",
                           "percolation_bracket"),
                          wrapping_crossing(phi2, data["wraps_phase2"][1], data["wraps_phase1"][1],
                                            int(min(row["n_samples"] for row in rows))))),
               **{f"fits_{k}": v for k, v in fits.items()}},
    )


_SURFACE_PORE_UNITS = {
    "F_sv_chi2_per_dof": ("1", "chi^2/dof of F_sv against Eq. (24) (SEM-weighted, no free parameter)"),
    "F_sv_n_points": ("1", "radial bins in the Eq. (24) comparison"),
    "F_sv_max_abs_rel_dev": ("1", "largest |F_sv / Eq. (24) - 1| in the window"),
    "F_sv_r_at_max_dev": ("pixel", "r of that largest deviation"),
    "F_sv_mean_rel_dev": ("1", "mean of F_sv / Eq. (24) - 1 over the window"),
    "F_ss_chi2_per_dof": ("1", "chi^2/dof of F_ss against Eq. (26) (SEM-weighted, no free parameter)"),
    "F_ss_n_points": ("1", "radial bins in the Eq. (26) comparison"),
    "F_ss_max_abs_rel_dev": ("1", "largest |F_ss / Eq. (26) - 1| in the window"),
    "F_ss_r_at_max_dev": ("pixel", "r of that largest deviation"),
    "F_ss_mean_rel_dev": ("1", "mean of F_ss / Eq. (26) - 1 over the window"),
    "s": ("1/pixel", "specific surface of the level sets, sample mean"),
    "s_sem": ("1/pixel", "standard error of s"),
    "s_exact": ("1/pixel", "s of Eq. (22), the tuning target"),
    "sigma": ("pixel", "tuned Gaussian width of the level sets"),
    "euler_slope": ("1/pixel^2", "specific Euler characteristic: logistic slope of F_sv at r = 0 (Eq. 13)"),
    "euler_slope_sem": ("1/pixel^2", "standard error of the slope over samples"),
    "euler_slope_window_shift": ("1/pixel^2", "|slope(alternative window) - slope| (stated systematic)"),
    "euler_topological": ("1/pixel^2", "Euler characteristic of phase 2 of the level set per area (bit quads)"),
    "euler_topological_sem": ("1/pixel^2", "standard error of the topological value"),
    "euler_formula": ("1/pixel^2", "pi (phi1 - phi2) phi1 phi2 / (4 a^2) (Sec. V A)"),
    "wraps_phase2": ("1", "fraction of samples in which phase 2 wraps around the periodic image"),
    "wraps_phase1": ("1", "fraction of samples in which phase 1 wraps around the periodic image"),
    "n_samples": ("1", "samples"),
    "p0_formula": ("1/pixel", "p0 = p2 = pi phi2 / a of Eq. (27)"),
    "p1": ("1/pixel^2", "p1 of Eq. (27) (p0 = p2 fixed), mean of per-sample fits"),
    "p1_sem": ("1/pixel^2", "standard error of p1"),
    "p1_chi2_per_dof": ("1", "chi^2/dof of Eq. (27) fitted to the sample-mean P (SEM-weighted)"),
    "pore_fit_delta_max": ("pixel", "largest delta of the Eq. (27) fit window"),
    "p2_free": ("1/pixel", "p2 of Eq. (27) fitted with p1 (p0 fixed), mean of per-sample fits"),
    "p2_free_sem": ("1/pixel", "standard error of the free p2"),
    "p1_with_p2_free": ("1/pixel^2", "p1 of the fit with p2 free"),
    "p0_measured": ("1/pixel", "P(0): the first P bin, 0 <= delta <= bin width"),
    "p0_bin_margin": ("1/pixel", "|Eq. (27)(half a bin) - p0|: what averaging over the first bin shifts"),
    "p0_measured_sem": ("1/pixel", "standard error of P(0)"),
    "eq27_normalization": ("1", "integral of Eq. (27) with p0 = p2 = pi phi2/a and the fitted p1"),
    "mean_delta": ("pixel", "mean pore size <delta> of the level sets, sample mean"),
    "mean_delta_sem": ("pixel", "standard error of <delta>"),
    "mean_delta_eq28": ("pixel", "<delta> of Eq. (28) with the paper's coefficients"),
    "eq28_rel_error": ("1", "(Eq. (28) - simulated <delta>) / simulated <delta>"),
    "eq28_rel_error_sem": ("1", "standard error of that relative error (from the SEM of <delta>)"),
    "mean_delta_eq28_own_coefficients": ("pixel", "<delta> of Eq. (28) with our fitted cubic"),
    "mean_delta_pixel_centres": ("pixel", "diagnostic: mean pixel-centre distance transform of the "
                                 "void (biased by about +1/2 pixel)"),
    "eq28_rel_error_pixel_centres": ("1", "(Eq. (28) - pixel-centre <delta>) / pixel-centre <delta>"),
    "mean_delta_pixel_centres_sem": ("pixel", "standard error of mean_delta_pixel_centres"),
    "eq28_rel_error_pixel_centres_sem": ("1", "standard error of eq28_rel_error_pixel_centres"),
    "p1_pixel_centres": ("1/pixel^2", "p1 of Eq. (27) fitted to the pixel-centre P(delta) (second reading)"),
    "p1_pixel_centres_sem": ("1/pixel^2", "standard error of p1_pixel_centres"),
}
