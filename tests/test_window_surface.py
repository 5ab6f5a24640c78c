"""Window (minus-sampling) surface functions of 3D images: randmedia.describe.window_surface.

Exact checks (pair sums, interior field, slab, a ball away from the faces), the tuner, and a
small statistical check against exact overlapping-sphere F_sv / F_ss (dim = 3) and the
periodic estimator on the same periodic images; the seam of the periodic estimator on a
Poisson-plane window (docs/debye3d.md, 'Window surface functions').
"""

from __future__ import annotations

import numpy as np
import pytest

from randmedia.describe.chords import LevelSet
from randmedia.describe.surface import (SURFACE_3D, mean_specific_surface, surface_binning,
                                        surface_functions, tune_sigma)
from randmedia.describe.isosurface import interface_triangles, surface_density, triangle_areas
from randmedia.describe.window import window_binning
from randmedia.describe.window_surface import (_interior, interior_fields,
                                               mean_window_specific_surface, tune_sigma_window,
                                               window_correlations, window_level_set,
                                               window_specific_surface,
                                               window_surface_binning,
                                               window_surface_functions)
from randmedia.generate.balls import overlapping_balls_image
from randmedia.generate.poisson_planes import poisson_plane_image
from randmedia.numerics.gaussian import default_margin
from randmedia.theory import overlapping as ov


def test_window_correlations_equal_explicit_pair_sums():
    rng = np.random.default_rng(1)
    shape = (6, 5, 7)
    a, b = rng.random(shape), rng.random(shape)
    binning = window_binning(shape, 2.4, 1.0)
    got = window_correlations({"a": a, "b": b}, [("a", "b"), ("a", "a")], binning)
    for key, (f, g) in {("a", "b"): (a, b), ("a", "a"): (a, a)}.items():
        values = []
        for v in binning.displacements():
            src = tuple(slice(max(0, -d), n - max(0, d)) for d, n in zip(v, shape))
            dst = tuple(slice(max(0, d), n - max(0, -d)) for d, n in zip(v, shape))
            values.append((f[src] * g[dst]).sum() / np.prod([n - abs(d) for d, n in zip(v, shape)]))
        expected = np.bincount(binning.bin_of, weights=values) / binning.counts
        np.testing.assert_allclose(got[key], expected, rtol=1e-10, atol=1e-12)


def test_same_bins_as_the_periodic_estimator():
    m = 4
    periodic = surface_binning((96, 96, 96), m, 5.0, 0.5, "lattice")
    window = window_surface_binning((70, 72, 75), m, 5.0, 0.5)
    np.testing.assert_array_equal(window.counts, periodic.counts)
    np.testing.assert_allclose(window.r_mean, periodic.r_mean, rtol=1e-13)


def test_interior_field_is_the_periodic_field():
    """A periodic image padded periodically by the margin: inside the margin the window's
    filtered field is the periodic one (the reflecting boundary never reaches it)."""
    rng = np.random.default_rng(5)
    image = overlapping_balls_image(rng, 12, 2.5, 0.3, 3)
    sigma, m = 0.5, 2
    margin = default_margin(sigma, m)
    pad = -(-margin // m)
    padded = np.pad(image, pad, mode="wrap")
    window = window_level_set(padded, sigma, m).fine[pad * m:-pad * m, pad * m:-pad * m,
                                                     pad * m:-pad * m]
    periodic = LevelSet.build(image, 0, sigma, m, "pixels").fine
    np.testing.assert_allclose(window, periodic, rtol=0, atol=1e-12)


def test_slab_has_one_interface_and_the_periodic_estimator_two():
    """Void below z = 8 voxels, solid above, in a 16^3 window: the window sees one plane
    (s = 1 / interior height), the periodic estimator also the seam (s = 2/16)."""
    image = np.zeros((16, 16, 16), dtype=np.uint8)
    image[8:] = 1
    sigma, m = 0.5, 4
    margin = default_margin(sigma, m)
    assert margin == 12  # int(4 * 0.5 * 4 + 0.5) + 4 sub-voxels = 3 voxels
    height = (16 * m - 2 * margin) / m
    assert window_specific_surface(image[None][0], sigma, m) == pytest.approx(1 / height, rel=1e-10)
    assert mean_specific_surface(image[None], sigma, m) == pytest.approx(2 / 16, rel=1e-10)


def test_ball_inside_the_interior_keeps_its_whole_area():
    """A ball away from the faces: the same field under either boundary mode, so the interior
    area equals the periodic estimator's whole area."""
    image = np.zeros((20, 20, 20), dtype=np.uint8)
    z, y, x = np.indices(image.shape) + 0.5
    image[(x - 10.2) ** 2 + (y - 9.7) ** 2 + (z - 10.1) ** 2 < 4.5**2] = 1
    sigma, m = 0.45, 2
    density, void, margin = interior_fields(image, sigma, m)
    periodic = mean_specific_surface(image[None], sigma, m) * 20**3
    assert density.sum() * (1 / m) ** 3 == pytest.approx(periodic, rel=1e-10)
    assert periodic == pytest.approx(4 * np.pi * 4.5**2, rel=0.05)


def test_tune_sigma_default_is_unchanged_and_window_tuner_recovers_sigma():
    rng = np.random.default_rng(7)
    disks = np.array([overlapping_balls_image(rng, 40, 3.0, 0.3, 2) for _ in range(2)])
    default = tune_sigma(disks, 0.15, supersample=4, bracket=(0.2, 1.5), xtol=1e-2)
    explicit = tune_sigma(disks, 0.15, supersample=4, bracket=(0.2, 1.5), xtol=1e-2,
                          specific_surface=lambda st, s: mean_specific_surface(st, s, 4))
    assert default == explicit
    image = overlapping_balls_image(np.random.default_rng(8), 20, 3.0, 0.3, 3)[None]
    margin = default_margin(0.8, 2)
    target = mean_window_specific_surface(image, 0.5, 2, margin)
    sigma, s = tune_sigma_window(image, target, supersample=2, bracket=(0.3, 0.8), xtol=1e-3)
    assert sigma == pytest.approx(0.5, abs=5e-3)
    assert s == pytest.approx(target, rel=1e-2)


@pytest.fixture(scope="module")
def spheres():
    """6 periodic 28^3 overlapping-sphere images (R = 3, phi2 = 0.3); sigma tuned (window
    estimator) to the exact s; both estimators at that sigma."""
    rng = np.random.default_rng(2024)
    images = np.array([overlapping_balls_image(rng, 28, 3.0, 0.3, 3) for _ in range(6)])
    sigma, _ = tune_sigma_window(images, ov.specific_surface(3.0, 0.3, 3), supersample=2,
                                 bracket=(0.3, 0.7), xtol=1e-2)
    kw = dict(sigma=sigma, supersample=2, r_max=6.0, bin_width=0.5)
    return window_surface_functions(images, **kw), surface_functions(images, **kw)


def test_dataset_layout(spheres):
    window, periodic = spheres
    for name, spec in SURFACE_3D.items():
        if name == "euler_samples":
            continue
        assert window[name].dims == spec.dims
        assert window[name].attrs["units"] == spec.units
    assert window.attrs["estimator"] == "window"
    assert window.attrs["margin"] == default_margin(window.attrs["sigma"], 2)
    np.testing.assert_allclose(window.r, periodic.r, rtol=1e-13)


@pytest.mark.parametrize("name", ["F_sv", "F_ss"])
def test_window_agrees_with_periodic_and_exact_on_spheres(spheres, name):
    """Paired window - periodic within 4 paired SEM + 2 % (the interior is a sub-volume);
    both within 3 SEM + 4 % of the exact 3D Boolean model (level-set systematic ~1-2 %,
    docs/debye3d.md; at 2 sub-voxels per voxel and R = 3 a little more), 1 voxel <= r."""
    window, periodic = spheres
    r = window.r.values
    exact = {"F_sv": ov.surface_void, "F_ss": ov.surface_surface}[name](r, 3.0, 0.3, dim=3)
    keep = r >= 1.0
    d = window[f"{name}_samples"].values - periodic[f"{name}_samples"].values
    sem_d = d.std(axis=0, ddof=1) / np.sqrt(d.shape[0])
    assert np.all(np.abs(d.mean(0))[keep] <= 4 * sem_d[keep] + 0.02 * exact[keep])
    for ds in (window, periodic):
        dev = np.abs(ds[name].values - exact)
        assert np.all(dev[keep] <= 3 * ds[f"{name}_sem"].values[keep] + 0.04 * exact[keep])


def test_seam_of_the_periodic_estimator_on_poisson_planes():
    """On a Poisson-plane window the periodic level set has a sheet of interface in the cubes
    that wrap: 0.87 (2 sub-voxels) or 0.77 (4 sub-voxels, 48^3) times the area of the voxel
    faces whose two sides across the seam differ (the level set cuts the staircase's
    corners). The window estimator excludes it: its interior M is the periodic level set's
    M on the same box (only the threshold differs)."""
    rng = np.random.default_rng(13)
    side, a, sigma, m = 28, 3.0, 0.45, 2
    for _ in range(2):
        image = poisson_plane_image(rng, (side,) * 3, a, 0.3)
        periodic = LevelSet.build(image, 0, sigma, m, "pixels")
        triangles = interface_triangles(periodic)
        seam = (triangles > side - 0.5 / m).any(axis=(1, 2))
        faces = sum(np.count_nonzero(np.take(image, 0, axis=k) != np.take(image, -1, axis=k))
                    for k in range(3))
        assert 0.65 * faces < triangle_areas(triangles[seam]).sum() < 1.0 * faces
        density, _, margin = interior_fields(image, sigma, m)
        full = surface_density(triangles, periodic.fine.shape, periodic.spacing)
        assert density.mean() == pytest.approx(_interior(full, margin).mean(), rel=5e-3)
