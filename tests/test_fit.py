"""Fits: recover known parameters from synthetic curves with known noise."""

import numpy as np
import pytest

from randmedia.fit import FitResult, per_sample_mean
from randmedia.fit.debye2020 import lineal_path_length, r2_over_r


def test_lineal_path_length_recovers_known_value_within_its_error():
    rng = np.random.default_rng(3)
    z = np.arange(0.0, 60.0, 0.5)
    phi1, length, noise = 0.7, 12.5, 0.002
    curve = phi1 * np.exp(-z / length) + rng.normal(0.0, noise, z.size)
    fit = lineal_path_length(z, curve, phi1, np.full(z.size, noise))
    assert abs(fit.value - length) <= 3 * fit.error
    assert 0.5 < fit.chi2_per_dof < 1.5  # correct errors give chi2/dof ~ 1


def test_unweighted_fit_and_per_sample_mean():
    z = np.arange(0.0, 40.0, 0.5)
    fits = [lineal_path_length(z, 0.6 * np.exp(-z / L), 0.6) for L in (9.0, 10.0, 11.0)]
    assert [f.value for f in fits] == pytest.approx([9.0, 10.0, 11.0], rel=1e-6)
    assert np.isnan(fits[0].chi2_per_dof)
    mean, sem = per_sample_mean(fits)
    assert mean == pytest.approx(10.0) and sem == pytest.approx(1.0 / np.sqrt(3))
    with pytest.raises(ValueError):
        per_sample_mean([FitResult(1.0, 0.1, 1.0, 5)])


def test_r2_over_r_inverts_eq_30_for_monodisperse_disks():
    """Overlapping disks of radius R: L(z) = phi1^(1 + 2z/(pi R)) -> L_w = -pi R/(2 ln phi1)."""
    phi1, radius = 0.7, 10.0
    lineal_length = -np.pi * radius / (2 * np.log(phi1))
    assert r2_over_r(lineal_length, phi1) == pytest.approx(radius)


# --------------------------------------------------------------------------- Sec. V A-B fits

from randmedia.fit.debye2020 import (eq27_normalization, formula_deviation,  # noqa: E402
                                     logistic_slope, p1_polynomial, pore_size_fit, wrapping_crossing)
from randmedia.theory import debye_formulas as formulas  # noqa: E402


def test_formula_deviation_gives_chi2_near_one_for_correct_errors():
    rng = np.random.default_rng(5)
    r = np.linspace(0.5, 40.0, 400)
    truth = formulas.debye_surface_void(r, 0.3, 5.0)
    sem = np.full(r.size, 1e-3)
    result = formula_deviation(r, truth + rng.normal(0, 1e-3, r.size), sem,
                               lambda x: formulas.debye_surface_void(x, 0.3, 5.0), r_min=1.0, r_max=40.0)
    assert 0.8 < result["chi2_per_dof"] < 1.2 and result["n_points"] == np.sum(r >= 1.0)
    shifted = formula_deviation(r, 1.1 * truth, sem, lambda x: formulas.debye_surface_void(x, 0.3, 5.0),
                                r_min=1.0, r_max=40.0)
    assert shifted["max_abs_rel_dev"] == pytest.approx(0.1) and shifted["chi2_per_dof"] > 10


def test_logistic_slope_recovers_the_euler_characteristic_of_eq_24():
    """The slope of Eq. (24) at r = 0 is pi (phi1 - phi2) phi1 phi2 / (4 a^2) (Sec. V A)."""
    r = np.arange(0.0, 30.0, 0.5)
    for phi2 in (0.1, 0.3):
        curve = formulas.debye_surface_void(r, phi2, 5.0)
        slope = logistic_slope(r, curve, r_min=1.0, r_max=20.0, scale_guess=5.0)
        assert slope == pytest.approx(formulas.debye_euler_characteristic(phi2, 5.0), rel=1e-6)


def test_pore_size_fit_recovers_p1_and_free_p2():
    rng = np.random.default_rng(9)
    a, phi2 = 5.0, 0.3
    p0 = np.pi * phi2 / a
    p1 = 0.4 / a**2
    delta = np.arange(0.125, 20.0, 0.25)
    noise = 2e-3
    curve = formulas.pore_size_density(delta, p0, p1, p0) + rng.normal(0, noise, delta.size)
    fit, p2 = pore_size_fit(delta, curve, p0=p0, p2=p0, sem=np.full(delta.size, noise), delta_max=15.0)
    assert p2 == p0 and abs(fit.value - p1) < 3 * fit.error
    assert 0.6 < fit.chi2_per_dof < 1.5
    clean = formulas.pore_size_density(delta, p0, p1, 1.1 * p0)
    fit_free, p2_free = pore_size_fit(delta, clean, p0=p0, p2=None, delta_max=15.0)
    assert p2_free == pytest.approx(1.1 * p0, rel=1e-5) and fit_free.value == pytest.approx(p1, rel=1e-5)


def test_p1_polynomial_recovers_known_coefficients():
    rng = np.random.default_rng(1)
    phi2 = np.array([0.1, 0.2, 0.3, 0.4, 0.5])
    a = 5.0
    truth = np.array([1.05, -2.41, 4.16])
    err = np.full(phi2.size, 2e-3)
    p1 = (truth[0] * phi2 + truth[1] * phi2**2 + truth[2] * phi2**3) / a**2
    noisy = p1 + rng.normal(0, 1, phi2.size) * err
    result = p1_polynomial(phi2, noisy, err, a)
    errors = np.sqrt(np.diag(result["covariance"]))
    assert np.all(np.abs(result["coefficients"] - truth) < 3.5 * errors) and result["dof"] == 2
    exact = p1_polynomial(phi2, p1, err, a)
    np.testing.assert_allclose(exact["coefficients"], truth, rtol=1e-9)


def test_eq27_is_normalized_exactly_when_p0_equals_p2():
    assert eq27_normalization(0.2, 0.03, 0.2) == pytest.approx(1.0, abs=1e-10)
    assert eq27_normalization(0.2, 0.001, 0.2) == pytest.approx(1.0, abs=1e-10)
    assert abs(eq27_normalization(0.25, 0.03, 0.2) - 1.0) > 1e-3


def test_mean_pore_size_is_eq_28_and_the_integral_of_F():
    from scipy.integrate import quad
    from scipy.special import erf

    a = 5.0
    for phi2 in (0.1, 0.3, 0.5):
        q = 1.05 * phi2 - 2.41 * phi2**2 + 4.16 * phi2**3
        eq28 = a * np.sqrt(np.pi) * np.exp(np.pi**2 * phi2**2 / (4 * q)) / (2 * np.sqrt(q)) * (
            1 - erf(np.pi * phi2 / (2 * np.sqrt(q))))
        assert formulas.debye_mean_pore_size(phi2, a) == pytest.approx(eq28, rel=1e-10)
        p1, p2 = q / a**2, np.pi * phi2 / a
        integral, _ = quad(lambda d: formulas.pore_size_ccdf(d, p1, p2), 0, np.inf)
        assert formulas.mean_pore_size(p1, p2) == pytest.approx(integral, rel=1e-9)


def test_wrapping_crossing():
    crossing, err, bracket = wrapping_crossing([0.1, 0.3, 0.5], [0.0, 0.0, 0.8], [1.0, 1.0, 0.6], 10)
    # combined curve: 0.1 -> 0, 0.3 -> 0, 0.5 -> 0.7, 0.7 -> 1, 0.9 -> 1: crosses between 0.3 and 0.5
    assert crossing == pytest.approx(0.3 + 0.5 / 0.7 * 0.2) and err > 0 and bracket == pytest.approx(0.2)
    assert np.isnan(wrapping_crossing([0.1], [0.0], [0.0], 10)[0])
