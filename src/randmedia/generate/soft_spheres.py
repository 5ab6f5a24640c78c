"""Fast compression of a sphere packing by energy minimization of soft spheres (FIRE).

Used only to bring large packings (system ``mrj_large``) close to jamming quickly
before the Torquato-Jiao LPs finish them (:func:`randmedia.generate.jammed.jam`),
because one TJ LP of 10 000 spheres costs minutes (benchmarks/mrj_tj.py).

Model (O'Hern, Silbert, Liu & Nagel, PRE 68, 011306 (2003)): spheres of diameter D
in a periodic cubic cell interact by the harmonic repulsion
V(r) = (1 - r/D)^2 / 2 for r < D. The cell is shrunk affinely to the target packing
fraction ``phi`` and the energy is minimized by FIRE (Bitzek et al., PRL 97, 170201
(2006); standard constants: N_min = 5, f_inc = 1.1, f_dec = 0.5, alpha_start = 0.1,
f_alpha = 0.99, dt_max = 10 dt_0) until the largest net force is below
``force_tolerance`` (units of the force scale 1/D). Afterwards the configuration is
rescaled by D / (smallest centre distance), i.e. the overlaps are removed exactly
as after a TJ step, which gives a hard-sphere packing slightly below ``phi``.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from randmedia.generate.rsa import ball_volume


@njit(cache=True)
def _forces(positions, side, n_cells, head, nxt, offsets, forces):
    """Harmonic forces of all overlapping pairs (cell list of a cubic box); returns energy."""
    n, dim = positions.shape
    forces[:] = 0.0
    head[:] = -1
    cell_of = np.empty(n, dtype=np.int64)
    for p in range(n):
        flat = 0
        for a in range(dim):
            f = positions[p, a] / side
            f -= math.floor(f)
            k = min(int(f * n_cells), n_cells - 1)
            flat = flat * n_cells + k
        cell_of[p] = flat
        nxt[p] = head[flat]
        head[flat] = p
    energy = 0.0
    index = np.empty(dim, dtype=np.int64)
    for p in range(n):
        rest = cell_of[p]
        for a in range(dim - 1, -1, -1):
            index[a] = rest % n_cells
            rest //= n_cells
        for o in range(offsets.shape[0]):
            flat = 0
            for a in range(dim):
                flat = flat * n_cells + (index[a] + offsets[o, a]) % n_cells
            q = head[flat]
            while q >= 0:
                if q > p:
                    r2 = 0.0
                    d = np.empty(dim)
                    for a in range(dim):
                        d[a] = positions[q, a] - positions[p, a]
                        d[a] -= side * np.rint(d[a] / side)
                        r2 += d[a] * d[a]
                    if r2 < 1.0:
                        r = math.sqrt(r2)
                        overlap = 1.0 - r
                        energy += 0.5 * overlap * overlap
                        for a in range(dim):
                            push = overlap * d[a] / r
                            forces[q, a] += push
                            forces[p, a] -= push
                q = nxt[q]
    return energy


@njit(cache=True)
def _fire(positions, side, n_cells, offsets, force_tolerance, max_steps, dt0):
    n, dim = positions.shape
    head = np.empty(n_cells**dim, dtype=np.int64)
    nxt = np.empty(n, dtype=np.int64)
    forces = np.zeros((n, dim))
    velocity = np.zeros((n, dim))
    dt, dt_max, alpha, since_negative = dt0, 10.0 * dt0, 0.1, 0
    energy = _forces(positions, side, n_cells, head, nxt, offsets, forces)
    for step in range(max_steps):
        fmax = 0.0
        for p in range(n):
            for a in range(dim):
                fmax = max(fmax, abs(forces[p, a]))
        if fmax < force_tolerance:
            return energy, step, fmax
        power = 0.0
        vnorm = 0.0
        fnorm = 0.0
        for p in range(n):
            for a in range(dim):
                power += forces[p, a] * velocity[p, a]
                vnorm += velocity[p, a] ** 2
                fnorm += forces[p, a] ** 2
        vnorm, fnorm = math.sqrt(vnorm), math.sqrt(fnorm)
        if power > 0:
            for p in range(n):
                for a in range(dim):
                    velocity[p, a] = ((1 - alpha) * velocity[p, a]
                                      + alpha * forces[p, a] / max(fnorm, 1e-300) * vnorm)
            since_negative += 1
            if since_negative > 5:
                dt = min(dt * 1.1, dt_max)
                alpha *= 0.99
        else:
            velocity[:] = 0.0
            since_negative = 0
            dt *= 0.5
            alpha = 0.1
        # semi-implicit Euler (unit masses)
        for p in range(n):
            for a in range(dim):
                velocity[p, a] += dt * forces[p, a]
                positions[p, a] += dt * velocity[p, a]
        energy = _forces(positions, side, n_cells, head, nxt, offsets, forces)
    return energy, max_steps, -1.0


def compress(positions: np.ndarray, box: np.ndarray, phi: float, *, force_tolerance: float = 1e-10,
             max_steps: int = 2_000_000, diameter: float = 1.0):
    """Shrink the cubic cell to ``phi``, minimize the soft-sphere energy, remove overlaps.

    Returns (positions, box, info) with info = dict(energy, steps, phi_soft); raises
    RuntimeError if FIRE does not converge within ``max_steps``.
    """
    positions = np.array(positions, dtype=float) / diameter
    box = np.asarray(box, dtype=float) / diameter
    n, dim = positions.shape
    if not np.allclose(box, np.eye(dim) * box[0, 0]):
        raise ValueError("soft-sphere compression needs a cubic cell")
    side_old = box[0, 0]
    side = (n * ball_volume(dim) / phi) ** (1.0 / dim)
    positions *= side / side_old
    n_cells = max(1, int(side))
    if n_cells < 3:
        raise ValueError(f"{n} spheres at phi = {phi} make a cell of {side:.2f} D: too small")
    offsets = np.array(np.meshgrid(*[[-1, 0, 1]] * dim, indexing="ij")).reshape(dim, -1).T
    energy, steps, fmax = _fire(positions, side, n_cells, offsets.astype(np.int64),
                                force_tolerance, int(max_steps), 0.1)
    if fmax < 0:
        raise RuntimeError(f"FIRE did not converge in {max_steps} steps (energy {energy:.3g})")
    from randmedia.generate.jammed import remove_overlaps
    from randmedia.periodic import Cell

    cubic = np.eye(dim) * side
    positions = Cell(cubic).wrap(positions)
    positions, cubic, _ = remove_overlaps(positions, cubic, 1.0)
    return positions * diameter, cubic * diameter, {"energy": energy, "steps": steps,
                                                    "phi_soft": phi}
