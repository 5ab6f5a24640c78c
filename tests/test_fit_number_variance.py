"""Fits of the number variance (Fig. 10): b2 R^2 + b3 R^3 and b2 R^2 with jackknife errors."""

import numpy as np
import pytest

from randmedia.fit.number_variance import evaluate, fit_number_variance


def synthetic_moments(rng, b2, b3, radii, n_samples=40, throws=200):
    """Per-sample power sums of Gaussian counts with variance b2 R^2 + b3 R^3 and mean 5 R^3."""
    n, s1, s2 = [], [], []
    for _ in range(n_samples):
        counts = rng.normal(5 * radii**3, np.sqrt(b2 * radii**2 + b3 * radii**3), size=(throws, len(radii)))
        n.append(np.full(len(radii), throws, float))
        s1.append(counts.sum(0))
        s2.append((counts**2).sum(0))
    return np.array(n), np.array(s1), np.array(s2)


def test_fits_recover_known_coefficients_within_their_jackknife_errors():
    rng = np.random.default_rng(0)
    radii = np.linspace(0.5, 4.0, 15)
    moments = synthetic_moments(rng, 1.3, 0.6, radii)
    fit = fit_number_variance(radii, *moments, model="b2_b3", r_min=1.0)
    assert fit.names == ("b2", "b3") and fit.n_points == int((radii >= 1.0).sum())
    assert abs(fit.values[0] - 1.3) < 4 * fit.errors[0]
    assert abs(fit.values[1] - 0.6) < 4 * fit.errors[1]
    assert 0 < fit.chi2_per_dof < 3
    # a pure R^2 fit of R^3 data is bad
    parabola = fit_number_variance(radii, *moments, model="b2", r_min=1.0)
    assert parabola.chi2_per_dof > 10 * fit.chi2_per_dof
    np.testing.assert_allclose(evaluate(fit, radii), 1.3 * radii**2 + 0.6 * radii**3, rtol=0.1)


def test_length_unit_rescales_the_coefficients():
    rng = np.random.default_rng(1)
    radii = np.linspace(0.5, 4.0, 12)
    moments = synthetic_moments(rng, 2.0, 0.0, radii)
    in_D = fit_number_variance(radii, *moments, model="b2", r_min=1.0)
    in_lambda = fit_number_variance(radii, *moments, model="b2", r_min=1.0, length=0.5)
    assert in_lambda.values[0] == pytest.approx(in_D.values[0] * 0.25, rel=1e-9)
    assert abs(in_D.values[0] - 2.0) < 4 * in_D.errors[0]


def test_bad_input():
    radii = np.linspace(0.5, 2, 5)
    moments = synthetic_moments(np.random.default_rng(2), 1, 1, radii, n_samples=5)
    with pytest.raises(ValueError, match="model"):
        fit_number_variance(radii, *moments, model="b4", r_min=1.0)
    with pytest.raises(ValueError, match="fewer than"):
        fit_number_variance(radii, *moments, model="b2_b3", r_min=1.9)
