"""Scaled-particle pore-size functions (randmedia.theory.scaled_particle): identities, the
papers' formulas, and our own Monte Carlo of equilibrium hard disks and spheres."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from scipy.integrate import quad
from scipy.spatial import cKDTree

from randmedia.generate.hard_particles.geometry import cubic_box
from randmedia.generate.hard_particles.run import run_chain
from randmedia.generate.hard_particles.settings import MCSettings
from randmedia.theory import scaled_particle as spt
from randmedia.theory.hard_spheres import specific_surface

REFERENCE = Path(__file__).resolve().parents[1] / "config" / "reference"


def test_carnahan_starling_gives_torquatos_3d_coefficients():
    p = 0.478
    expected = [(1 + p + p**2 - p**3) / (1 - p) ** 3, p * (3 * p**2 - 4 * p - 3) / (2 * (1 - p) ** 3),
                p**2 * (2 - p) / (2 * (1 - p) ** 3)]
    np.testing.assert_allclose(spt.gv_coefficients(p, 3, "carnahan_starling"), expected, rtol=1e-12)


def test_2d_coefficients_from_the_contact_value():
    p, c = 0.3, 0.436
    a0, a1 = spt.gv_coefficients(p, 2, contact=(1 - c * p) / (1 - p) ** 2)
    assert a0 == pytest.approx((1 + 0.128 * p) / (1 - p) ** 2)
    assert a1 == pytest.approx(-0.564 * p / (1 - p) ** 2)
    a0, a1, a2 = spt.eq41_coefficients(p)  # Henderson: c = 7/16
    assert (a0, a1, a2) == pytest.approx(((1 + p / 8) / (1 - p) ** 2, -(9 / 16) * p / (1 - p) ** 2,
                                          -(a0 + 4 * a1)))


@pytest.mark.parametrize("dim, phi", [(2, 0.3), (2, 0.6), (3, 0.2), (3, 0.478)])
def test_normalization_origin_and_continuity(dim, phi):
    diameter = 2.0
    radius = diameter / 2
    total = quad(lambda d: float(spt.pore_size_density(d, phi, dim, diameter)), 0, np.inf)[0]
    assert total == pytest.approx(1.0, abs=1e-9)
    assert spt.pore_size_ccdf(0.0, phi, dim, diameter) == pytest.approx(1.0)
    s = specific_surface(radius, phi, dim)  # Eq. 40 in 2D: 2 phi2 / R
    assert spt.pore_size_density(0.0, phi, dim, diameter) == pytest.approx(s / (1 - phi))
    eps = 1e-9
    for f in (spt.exclusion_probability, spt.gv):
        below, above = f(np.array([radius - eps, radius + eps]), phi, dim, diameter)
        assert below == pytest.approx(above, rel=1e-6)
    assert spt.gv(diameter, phi, dim, diameter) == pytest.approx(
        spt.contact_value(phi, dim))
    # exact for r <= R (mrj2016 Eq. 21): 1 - rho v1(r)
    r = np.linspace(0, radius, 5)
    np.testing.assert_allclose(spt.exclusion_probability(r, phi, dim, diameter),
                               1 - phi * (r / radius) ** dim)
    first, second = spt.pore_size_moments(phi, dim, diameter)
    mean = quad(lambda d: d * float(spt.pore_size_density(d, phi, dim, diameter)), 0, np.inf)[0]
    assert first == pytest.approx(mean, rel=1e-7)
    assert second > first**2


def test_eq41_as_printed_equals_the_general_form():
    delta = np.linspace(0, 30, 31)
    np.testing.assert_allclose(spt.eq41_pore_size_density(delta, 0.3, 10.0),
                               spt.pore_size_density(delta, 0.3, 2, 20.0), rtol=1e-12)


def test_sphere_moments_near_the_quoted_values():
    """mrj2016 Sec. V B quotes <delta> = 0.098 D and <delta^2> = 0.014 D^2 (MC, error < 1e-3)
    and says they agree with the analytical approximation: ours 0.0989 D, 0.0145 D^2."""
    first, second = spt.pore_size_moments(0.478, 3)
    assert first == pytest.approx(0.098, abs=0.0015)
    assert second == pytest.approx(0.014, abs=0.0008)


def test_bad_input():
    with pytest.raises(ValueError, match="dimension"):
        spt.gv_coefficients(0.3, 4)
    with pytest.raises(ValueError, match="packing fraction"):
        spt.exclusion_probability(0.5, 1.2, 3)
    with pytest.raises(ValueError, match="pore sizes"):
        spt.pore_size_ccdf(-0.1, 0.3, 2)


# --------------------------------------------------------------------------- against Monte Carlo


def _nearest_centre_distances(samples, box, n_points, rng):
    distances = []
    for sample in samples:
        tree = cKDTree(sample.positions, boxsize=box)
        points = rng.random((n_points, len(box))) * box
        distances.append(tree.query(points)[0])
    return np.concatenate(distances)


def test_hard_sphere_liquid_exclusion_probability_and_pore_moments():
    """Our liquid (N = 256, phi = 0.478): E_V(r) against the paper's Table II (their MC) and
    the scaled-particle curve; pore-size moments against the quoted 0.098 D, 0.014 D^2."""
    settings = MCSettings(equilibration_msd=1.5, sample_msd=0.3, measure_every=10, contact_range=0.1,
                          contact_order=3)
    box = cubic_box(256, 0.478, 3)
    result = run_chain(256, box, 1.0, 12, np.random.default_rng(21), settings)
    r = _nearest_centre_distances(result.samples, box, 40000, np.random.default_rng(2))
    table = pd.read_csv(REFERENCE / "mrj2016_table2_equilibrium.csv").dropna(subset=["EV"])
    table = table[(table["r_over_D"] > 0.5) & (table["r_over_D"] <= 0.72)]
    for x, published in zip(table["r_over_D"], table["EV"]):
        ours = np.mean(r > x)
        assert ours == pytest.approx(published, rel=0.05), x
        assert ours == pytest.approx(float(spt.exclusion_probability(x, 0.478, 3)), rel=0.06), x
    pores = r[r > 0.5] - 0.5
    first, second = spt.pore_size_moments(0.478, 3)
    assert pores.mean() == pytest.approx(0.098, abs=0.003)
    assert pores.mean() == pytest.approx(first, rel=0.03)
    assert np.mean(pores**2) == pytest.approx(0.014, abs=0.001)
    assert np.mean(pores**2) == pytest.approx(second, rel=0.06)


def test_hard_disk_pore_sizes_against_eq41():
    settings = MCSettings(equilibration_msd=2.0, sample_msd=1.0, measure_every=5, contact_range=0.1,
                          contact_order=3)
    box = cubic_box(400, 0.3, 2)
    result = run_chain(400, box, 1.0, 30, np.random.default_rng(22), settings)
    r = _nearest_centre_distances(result.samples, box, 20000, np.random.default_rng(3))
    pores = r[r > 0.5] - 0.5
    for delta in (0.1, 0.25, 0.5, 0.75):
        assert np.mean(pores > delta) == pytest.approx(
            float(spt.pore_size_ccdf(delta, 0.3, 2)), rel=0.05), delta
    first, _ = spt.pore_size_moments(0.3, 2)
    assert pores.mean() == pytest.approx(first, rel=0.03)
