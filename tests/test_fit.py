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
