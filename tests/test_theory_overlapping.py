"""Exact overlapping-disk/sphere S2 (Eqs. 32-33) against limits and Monte Carlo."""

import numpy as np
import pytest

from randmedia.theory.overlapping import s2_void, union_volume_ratio


@pytest.mark.parametrize("dim", [2, 3])
def test_limits(dim):
    assert union_volume_ratio(0.0, 1.0, dim) == pytest.approx(1.0)
    assert union_volume_ratio(2.0, 1.0, dim) == pytest.approx(2.0)
    assert union_volume_ratio(5.0, 1.0, dim) == 2.0
    assert s2_void(0.0, 1.0, 0.3, dim) == pytest.approx(0.7)
    assert s2_void(10.0, 1.0, 0.3, dim) == pytest.approx(0.49)


@pytest.mark.parametrize("dim", [2, 3])
@pytest.mark.parametrize("r", [0.3, 1.0, 1.7])
def test_union_volume_matches_monte_carlo(dim, r):
    rng = np.random.default_rng(4)
    n = 400_000
    points = rng.uniform(-1.0, 1.0 + r, size=(n, dim))
    points[:, 1:] = rng.uniform(-1.0, 1.0, size=(n, dim - 1))
    box = (2.0 + r) * 2.0 ** (dim - 1)
    first = np.sum(points**2, axis=1) <= 1.0
    second = np.sum((points - np.eye(dim)[0] * r) ** 2, axis=1) <= 1.0
    hits = first | second
    estimate = hits.mean() * box
    error = np.sqrt(hits.mean() * (1 - hits.mean()) / n) * box
    ball = np.pi if dim == 2 else 4 * np.pi / 3
    assert abs(estimate / ball - union_volume_ratio(r, 1.0, dim)) < 4 * error / ball


def test_bad_input():
    with pytest.raises(ValueError):
        union_volume_ratio(1.0, 1.0, dim=4)
    with pytest.raises(ValueError):
        s2_void(1.0, 1.0, 1.2)


# ---- surface functions, pore sizes, lineal path, chords (Eqs. 34-39 and their 3D forms)

import math  # noqa: E402

from scipy.spatial import cKDTree  # noqa: E402

from randmedia.theory import overlapping as ov  # noqa: E402
from randmedia.theory.balls import poisson_intensity, unit_ball_volume  # noqa: E402

R, PHI2 = 1.3, 0.3
ETA = -math.log(1 - PHI2)


def paper_2d(r):
    """Ma & Torquato 2020 Eqs. (34)-(39) for d = 2, typed in from the paper."""
    x = np.minimum(r / (2 * R), 1.0)
    theta = (r < 2 * R).astype(float)
    s2 = ov.s2_void(r, R, PHI2, 2)
    with np.errstate(divide="ignore", invalid="ignore"):
        fss_same = np.where(r < 2 * R, 2 * ETA / (np.pi * R) / (r * np.sqrt(1 - x * x)), 0.0)
    return {
        "s": 2 * ETA * (1 - PHI2) / R,
        "Fsv": 2 * ETA / R * (1 - np.arccos(x) / np.pi * theta) * s2,
        "Fss": s2 * (4 * ETA**2 / R**2 * (1 - np.arccos(x) / np.pi * theta) ** 2 + fss_same),
    }


def test_two_dimensional_forms_equal_the_papers_equations():
    r = np.array([0.05, 0.4, 1.0, 2.0, 2.5, 2.59, 2.61, 4.0])
    paper = paper_2d(r)
    assert ov.specific_surface(R, PHI2, 2) == pytest.approx(paper["s"])
    np.testing.assert_allclose(ov.surface_void(r, R, PHI2, 2), paper["Fsv"], rtol=1e-12)
    np.testing.assert_allclose(ov.surface_surface(r, R, PHI2, 2), paper["Fss"], rtol=1e-12)
    delta = np.linspace(0, 3, 7)
    phi1 = 1 - PHI2
    np.testing.assert_allclose(  # Eq. (37)
        ov.pore_size_density(delta, R, PHI2, 2),
        2 * ETA / R * (1 + delta / R) * phi1 ** (delta**2 / R**2 + 2 * delta / R), rtol=1e-12)
    z = np.linspace(0, 5, 6)
    np.testing.assert_allclose(ov.lineal_path_void(z, R, PHI2, 2),  # Eq. (38)
                               phi1 ** (1 + 2 * z / (np.pi * R)), rtol=1e-12)
    np.testing.assert_allclose(ov.chord_density_void(z, R, PHI2, 2),  # Eq. (39)
                               2 * ETA / (np.pi * R) * phi1 ** (2 * z / (np.pi * R)), rtol=1e-12)


@pytest.mark.parametrize("dim", [2, 3])
def test_limits_and_identities(dim):
    s = ov.specific_surface(R, PHI2, dim)
    phi1 = 1 - PHI2
    assert ov.surface_void(0.0, R, PHI2, dim) == pytest.approx(s / 2)
    assert ov.surface_void(10 * R, R, PHI2, dim) == pytest.approx(s * phi1)
    assert ov.surface_surface(10 * R, R, PHI2, dim) == pytest.approx(s**2)
    # small-r divergence of F_ss: (d-1) omega_{d-1} s / (d omega_d r)
    r = 1e-7
    omega = unit_ball_volume
    assert ov.surface_surface(r, R, PHI2, dim) * r == pytest.approx(
        (dim - 1) * omega(dim - 1) * s / (dim * omega(dim)), rel=1e-5)
    # Eq. (7): S2'(0) = -omega_{d-1} s / (d omega_d) (-s/pi in 2D, -s/4 in 3D)
    h = 1e-7
    slope = (ov.s2_void(h, R, PHI2, dim) - ov.s2_void(0.0, R, PHI2, dim)) / h
    assert slope == pytest.approx(-omega(dim - 1) * s / (dim * omega(dim)), rel=1e-5)
    # pore sizes: P(0) = s / phi1; normalized; Eq. (20) mean chord
    assert ov.pore_size_density(0.0, R, PHI2, dim) == pytest.approx(s / phi1)
    delta = np.linspace(0, 20 * R, 200_001)
    assert np.trapezoid(ov.pore_size_density(delta, R, PHI2, dim), delta) == pytest.approx(1, abs=1e-8)
    assert 1 / ov.chord_rate(R, PHI2, dim) == pytest.approx(
        omega(dim) * dim * phi1 / (omega(dim - 1) * s))
    assert ov.pore_size_moment(1, R, PHI2, dim) == pytest.approx(
        np.trapezoid(ov.pore_size_complementary_cdf(delta, R, PHI2, dim), delta), rel=1e-8)


def test_klatt_torquato_overlapping_sphere_numbers():
    """phi = 0.636, D = 1: s = 6 phi1 ln(1/phi1) = 2.21/D (Sec. III A)."""
    assert ov.specific_surface(0.5, 0.636, 3) == pytest.approx(
        6 * 0.364 * math.log(1 / 0.364))
    assert round(ov.specific_surface(0.5, 0.636, 3), 2) == 2.21


def test_three_dimensional_surface_void_and_pore_size_match_monte_carlo():
    """Boolean model of spheres in periodic boxes: sample interface points (uniform on the
    uncovered parts of the sphere surfaces) and void points, and check F_sv(r)/s and F(delta).
    Estimates are averaged over independent boxes; the tolerance is 4 SEM over boxes."""
    rng = np.random.default_rng(11)
    radius, phi2, side, boxes = 0.5, 0.4, 6.0, 12
    rho = poisson_intensity(phi2, radius, 3)
    distances, deltas = (0.2, 0.6, 1.5), (0.05, 0.15, 0.3)
    fsv, cdf = np.empty((boxes, 3)), np.empty((boxes, 3))
    for b in range(boxes):
        centres = rng.uniform(0, side, size=(rng.poisson(rho * side**3), 3))
        tree = cKDTree(centres, boxsize=side)
        n = 20_000
        normals = rng.normal(size=(n, 3))
        normals /= np.linalg.norm(normals, axis=1)[:, None]
        surface = (centres[rng.integers(len(centres), size=n)] + radius * (1 - 1e-9) * normals) % side
        surface = surface[tree.query_ball_point(surface, radius, return_length=True) == 1]
        directions = rng.normal(size=surface.shape)
        directions /= np.linalg.norm(directions, axis=1)[:, None]
        for k, r in enumerate(distances):
            hits = tree.query_ball_point((surface + r * directions) % side, radius, return_length=True)
            fsv[b, k] = np.mean(hits == 0)
        gap = tree.query(rng.uniform(0, side, size=(20_000, 3)))[0] - radius
        gap = gap[gap > 0]
        cdf[b] = [np.mean(gap > d) for d in deltas]
    s = ov.specific_surface(radius, phi2, 3)
    exact_fsv = ov.surface_void(np.array(distances), radius, phi2, 3) / s
    exact_cdf = ov.pore_size_complementary_cdf(np.array(deltas), radius, phi2, 3)
    sem = lambda a: a.std(axis=0, ddof=1) / np.sqrt(boxes)  # noqa: E731
    assert np.all(np.abs(fsv.mean(axis=0) - exact_fsv) < 4 * sem(fsv)), (fsv.mean(0), exact_fsv)
    assert np.all(np.abs(cdf.mean(axis=0) - exact_cdf) < 4 * sem(cdf)), (cdf.mean(0), exact_cdf)


def test_bad_arguments_are_rejected():
    with pytest.raises(ValueError, match="dim"):
        ov.surface_void(1.0, 1.0, 0.3, dim=4)
    with pytest.raises(ValueError, match="radius"):
        ov.specific_surface(0.0, 0.3, 2)
    with pytest.raises(ValueError, match="phi2"):
        ov.pore_size_density(0.1, 1.0, 1.0, 2)
    with pytest.raises(ValueError, match="pore sizes"):
        ov.pore_size_complementary_cdf(-0.1, 1.0, 0.3, 2)
