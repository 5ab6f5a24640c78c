"""Shared test configurations of the mrj2016 benchmarks (not a benchmark itself)."""

from __future__ import annotations

import numpy as np

from randmedia.generate.spheres import lattice_spheres


def jittered_fcc(n_cells: int, spacing: float, seed: int = 0):
    """fcc lattice with nearest-neighbour distance ``spacing`` D, each sphere displaced uniformly
    within a ball of radius (spacing - 1)/2: a hard-sphere packing (no overlaps) with
    N = 4 n_cells^3 and phi = 0.7405 / spacing^3, in a periodic cube."""
    rng = np.random.default_rng(seed)
    x, box = lattice_spheres("fcc", n_cells, diameter=spacing)
    u = rng.normal(size=x.shape)
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    x = x + u * (spacing - 1.0) / 2 * 0.999 * rng.random((len(x), 1)) ** (1 / 3)
    return x, box
