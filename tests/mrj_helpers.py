"""Small hard-sphere test packings and brute-force Monte Carlo references (mrj2016 tests)."""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree

from randmedia.periodic import Cell, padded_images

TRICLINIC = np.array([[7.0, 1.2, -0.6], [0.0, 6.6, 0.9], [0.0, 0.0, 7.3]])


def rsa_packing(rng, box, n, diameter=1.0, max_attempts=200_000):
    """Random sequential addition of n non-overlapping spheres in a periodic (triclinic) cell."""
    cell = Cell(box)
    kept = []
    for _ in range(max_attempts):
        if len(kept) == n:
            break
        candidate = cell.random_points(rng, 1)[0]
        if kept:
            separation = cell.minimum_image(np.array(kept) - candidate)
            if np.min(np.linalg.norm(separation, axis=1)) < diameter:
                continue
        kept.append(candidate)
    if len(kept) < n:
        raise RuntimeError("RSA did not reach the requested number of spheres")
    return np.array(kept)


def random_directions(rng, n):
    u = rng.normal(size=(n, 3))
    return u / np.linalg.norm(u, axis=1, keepdims=True)


def monte_carlo_correlations(positions, box, r, n_samples, rng, diameter=1.0):
    """Brute-force S2, F_sv^(s) (spheres as void) and F_ss at distance r by sampling.

    S2: uniform points x and directions u, both x and x + r u in spheres.
    F_sv^(s) = s P(x + r u in a sphere | x uniform on the interface).
    F_ss = s E[sum_j R / (2 r delta_j) 1{|R - delta_j| < r < R + delta_j}] for x uniform on
    the interface, delta_j = |x - c_j| (Eq. A19: the surface density met by the
    sphere of radius r about x; the one exact step, the rest is sampling).
    Returns (value, standard error) triples as a dict.
    """
    cell = Cell(box)
    R = diameter / 2.0
    n = len(positions)
    s = n * 4 * np.pi * R**2 / cell.volume
    images, _ = padded_images(cell, positions, min(r + diameter + 0.5, cell.face_distances.min()))
    tree = cKDTree(images)

    def in_spheres(points):
        d, _ = tree.query(points)
        return d < R

    def wrapped(points):
        return cell.wrap(points)

    x = cell.random_points(rng, n_samples)
    u = random_directions(rng, n_samples)
    both = in_spheres(x) & in_spheres(wrapped(x + r * u))
    # points on the interface: a random sphere, a random point on it
    centres = positions[rng.integers(0, n, n_samples)]
    on = centres + R * random_directions(rng, n_samples)
    hit = in_spheres(wrapped(on + r * random_directions(rng, n_samples)))
    # surface density met by the test sphere of radius r about the interface point
    pairs = cKDTree(wrapped(on)).sparse_distance_matrix(tree, r + R + 1e-9, output_type="ndarray")
    delta = pairs["v"]
    ok = (np.abs(R - delta) < r) & (r < R + delta)
    density = np.bincount(pairs["i"][ok], weights=R / (2 * r * delta[ok]), minlength=n_samples)

    def mean_se(values, factor=1.0):
        values = np.asarray(values, dtype=float)
        return factor * values.mean(), factor * values.std(ddof=1) / np.sqrt(values.size)

    return {"S2": mean_se(both), "F_sv_spheres": mean_se(hit, s), "F_ss": mean_se(density, s), "s": s}
