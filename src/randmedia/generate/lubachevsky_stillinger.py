"""Fast compression of hard spheres by event-driven molecular dynamics with growing spheres.

The Lubachevsky-Stillinger (LS) algorithm (B. D. Lubachevsky and F. H. Stillinger,
J. Stat. Phys. 60, 561 (1990); M. Skoge, A. Donev, F. H. Stillinger and
S. Torquato, PRE 74, 041127 (2006)): N hard spheres of common diameter
sigma(t) = sigma_0 + g t move ballistically between collisions in a periodic cubic
(d = 3) or square (d = 2) box while their diameter grows at the rate g. At a
collision of spheres i and j (unit normal n from i to j, normal relative velocity
u_n = (v_j - v_i).n < g) the collision is elastic in the frame of the growing
surfaces, so the pair separates at 2 g - u_n:

    v_j <- v_j + (g - u_n) n,        v_i <- v_i - (g - u_n) n.

Growth heats the system; every ``sync_every`` x N events all spheres are brought to
the common time, their velocities are rescaled to k T = 1 (m = 1; total momentum
zero) and the reduced pressure of the interval is measured by the collision virial,

    Z = P V / (N k T) = 1 + sum_collisions sigma (g - u_n) / (d N k T dt)

(each collision transfers the momentum g - u_n along n at separation sigma). The
run stops when Z exceeds ``target_pressure``: the spheres are then a distance of
order sigma / Z from a jammed packing (free-volume argument), which the sequential
linear programs of :mod:`randmedia.generate.jammed` reach in a few steps.

The compression rate sets the jamming density: fast growth (g of order 0.1-1 in
units of the thermal speed per mean spacing rho^(-1/d)) jams the spheres near the
"lowest typical" density 0.634-0.636 of monodisperse spheres, slow growth lets them
rearrange towards 0.64-0.65 and crystallize (V. Baranau and U. Tallarek, Soft Matter
10, 3826 (2014); Skoge et al. 2006). The MRJ packings of Klatt & Torquato (2016)
have phi = 0.6356 (Torquato-Jiao algorithm); see :mod:`randmedia.generate.jammed`.

Units: the box has side L = N^(1/d) (number density 1), k T = m = 1, so times are in
units of rho^(-1/d) sqrt(m / k T). Events are handled with one predicted event per
sphere (its earliest collision or cell crossing) in an indexed binary heap;
collision counters invalidate predictions whose partner has collided since (the
standard single-event scheme, e.g. Rapaport, *The Art of Molecular Dynamics
Simulation*, ch. 14). Cells have a side of at least the largest diameter the
spheres can reach (the densest packing), so every collision partner lies in one of
the 3^d cells around a sphere. The cells are doubly linked lists of their own, not the
member table of :mod:`randmedia.cell_list`: a sphere's cell changes only at its
crossing events (tracked, not recomputed from a position that sits on the face). The kernels are numba-compiled, d-generic, and
deterministic: the same start and velocities give the same trajectory.
"""

from __future__ import annotations

import logging
import math
import time
from dataclasses import dataclass

import numpy as np
from numba import njit

from randmedia.generate import refuse_invalid
from randmedia.theory.balls import ball_volume

#: densest packing fractions (hexagonal in 2D, fcc in 3D): the spheres never outgrow them
_DENSEST = {2: math.pi / (2 * math.sqrt(3)), 3: math.pi / math.sqrt(18)}

_COLLISION, _CROSSING, _NONE = 0, 1, 2


class CompressionError(RuntimeError):
    """The event-driven compression did not reach its target pressure."""


@dataclass(frozen=True)
class LSParameters:
    """Constants of the LS compression (module docstring).

    ``growth_rate`` g: d sigma / dt in units of rho^(-1/d) sqrt(k T / m);
    ``target_pressure``: stop when the reduced pressure Z = PV/(NkT) exceeds it;
    ``sync_every``: events per sphere between velocity rescalings (and pressure
    measurements); ``max_events_per_sphere``: give up after this many events per sphere.
    """

    growth_rate: float = 0.1
    slowdown_pressure: float = 50.0
    target_pressure: float = 1.0e4
    sync_every: float = 20.0
    max_events_per_sphere: float = 2.0e5

    def __post_init__(self):
        checks = {
            "growth_rate": 0 < self.growth_rate <= 10,
            "slowdown_pressure": self.slowdown_pressure >= 1,
            "target_pressure": 10 <= self.target_pressure <= 1e12,
            "sync_every": 1 <= self.sync_every <= 1e4,
            "max_events_per_sphere": self.max_events_per_sphere >= 100,
        }
        refuse_invalid("Lubachevsky-Stillinger parameters", checks, self)


# --------------------------------------------------------------------------- heap


@njit(cache=True)
def _heap_swap(heap, where, a, b):
    ia, ib = heap[a], heap[b]
    heap[a], heap[b] = ib, ia
    where[ib], where[ia] = a, b


@njit(cache=True)
def _heap_fix(heap, where, key, i):
    """Restore the heap order after key[i] changed (sift up, then down)."""
    p = where[i]
    while p > 0:
        parent = (p - 1) // 2
        if key[heap[parent]] <= key[heap[p]]:
            break
        _heap_swap(heap, where, parent, p)
        p = parent
    n = heap.shape[0]
    while True:
        left = 2 * p + 1
        if left >= n:
            break
        child = left
        if left + 1 < n and key[heap[left + 1]] < key[heap[left]]:
            child = left + 1
        if key[heap[p]] <= key[heap[child]]:
            break
        _heap_swap(heap, where, p, child)
        p = child


# --------------------------------------------------------------------------- kinematics


@njit(cache=True)
def _collision_time(r2, rv, v2, sigma, growth):
    """Time until |r + v t| = sigma + g t (first root >= 0), inf if never.

    a t^2 + 2 b t + c = 0 with a = v^2 - g^2, b = r.v - sigma g, c = r^2 - sigma^2;
    the root c / (-b + sqrt(b^2 - a c)) is the smaller positive one for every sign
    of a and is free of cancellation.
    """
    c = r2 - sigma * sigma
    b = rv - sigma * growth
    if c <= 0.0:  # touching (round-off): collide now if approaching
        return 0.0 if b < 0.0 else np.inf
    a = v2 - growth * growth
    disc = b * b - a * c
    if disc < 0.0:
        return np.inf
    den = -b + math.sqrt(disc)
    if den <= 0.0:
        return np.inf
    return c / den


@njit(cache=True)
def _advance(i, t, pos, vel, tloc):
    dt = t - tloc[i]
    if dt != 0.0:
        for a in range(pos.shape[1]):
            pos[i, a] += vel[i, a] * dt
        tloc[i] = t


@njit(cache=True)
def _cell_flat(cellc, i, nc):
    flat = 0
    for a in range(cellc.shape[1]):
        flat = flat * nc + cellc[i, a]
    return flat


@njit(cache=True)
def _cell_insert(i, flat, head, nxt, prv):
    nxt[i] = head[flat]
    prv[i] = -1
    if head[flat] >= 0:
        prv[head[flat]] = i
    head[flat] = i


@njit(cache=True)
def _cell_remove(i, flat, head, nxt, prv):
    if prv[i] >= 0:
        nxt[prv[i]] = nxt[i]
    else:
        head[flat] = nxt[i]
    if nxt[i] >= 0:
        prv[nxt[i]] = prv[i]


@njit(cache=True)
def _predict(i, t, pos, vel, tloc, cellc, head, nxt, nc, width, side, sigma0, growth,
             ev_time, ev_kind, ev_partner, ev_count, count, heap, where, offsets):
    """Earliest event of sphere i after t (i is moved to t); updates a partner whose own
    predicted event is later."""
    d = pos.shape[1]
    _advance(i, t, pos, vel, tloc)
    best = np.inf
    kind = _NONE
    partner = -1
    extra = 0
    for a in range(d):  # leaving the cell
        v = vel[i, a]
        if v > 0.0:
            dt = ((cellc[i, a] + 1) * width - pos[i, a]) / v
            direction = 1
        elif v < 0.0:
            dt = (cellc[i, a] * width - pos[i, a]) / v
            direction = -1
        else:
            continue
        if dt < 0.0:
            dt = 0.0
        if dt < best:
            best, kind, partner, extra = dt, _CROSSING, a, direction
    sigma = sigma0 + growth * t
    half = 0.5 * side
    for o in range(offsets.shape[0]):
        flat = 0
        for a in range(d):
            c = cellc[i, a] + offsets[o, a]
            if c < 0:
                c += nc
            elif c >= nc:
                c -= nc
            flat = flat * nc + c
        k = head[flat]
        while k >= 0:
            if k != i:
                dtk = t - tloc[k]
                r2 = 0.0
                rv = 0.0
                v2 = 0.0
                for a in range(d):
                    r = pos[k, a] + vel[k, a] * dtk - pos[i, a]
                    if r > half:
                        r -= side
                    elif r < -half:
                        r += side
                    v = vel[k, a] - vel[i, a]
                    r2 += r * r
                    rv += r * v
                    v2 += v * v
                dt = _collision_time(r2, rv, v2, sigma, growth)
                if dt < best:
                    best, kind, partner, extra = dt, _COLLISION, k, count[k]
            k = nxt[k]
    ev_time[i] = t + best
    ev_kind[i] = kind
    ev_partner[i] = partner
    ev_count[i] = extra
    _heap_fix(heap, where, ev_time, i)
    if kind == _COLLISION and t + best < ev_time[partner]:
        ev_time[partner] = t + best
        ev_kind[partner] = _COLLISION
        ev_partner[partner] = i
        ev_count[partner] = count[i]
        _heap_fix(heap, where, ev_time, partner)


@njit(cache=True)
def _predict_all(t, pos, vel, tloc, cellc, head, nxt, nc, width, side, sigma0, growth,
                 ev_time, ev_kind, ev_partner, ev_count, count, heap, where, offsets):
    n = pos.shape[0]
    for i in range(n):
        ev_time[i] = np.inf
        heap[i] = i
        where[i] = i
    for i in range(n):
        _predict(i, t, pos, vel, tloc, cellc, head, nxt, nc, width, side, sigma0, growth,
                 ev_time, ev_kind, ev_partner, ev_count, count, heap, where, offsets)


@njit(cache=True)
def _run_events(n_events, pos, vel, tloc, cellc, head, nxt, prv, nc, width, side, sigma0,
                growth, ev_time, ev_kind, ev_partner, ev_count, count, heap, where, offsets):
    """Process n_events events; returns (time of the last event, collisions, virial sum
    sum sigma (g - u_n))."""
    d = pos.shape[1]
    t = ev_time[heap[0]]
    collisions = 0
    virial = 0.0
    half = 0.5 * side
    normal = np.empty(d)
    for _ in range(n_events):
        i = heap[0]
        t = ev_time[i]
        kind = ev_kind[i]
        if kind == _COLLISION:
            k = ev_partner[i]
            if count[k] != ev_count[i]:  # the partner collided since: predict again
                _predict(i, t, pos, vel, tloc, cellc, head, nxt, nc, width, side, sigma0,
                         growth, ev_time, ev_kind, ev_partner, ev_count, count, heap, where,
                         offsets)
                continue
            _advance(i, t, pos, vel, tloc)
            _advance(k, t, pos, vel, tloc)
            r2 = 0.0
            for a in range(d):
                r = pos[k, a] - pos[i, a]
                if r > half:
                    r -= side
                elif r < -half:
                    r += side
                normal[a] = r
                r2 += r * r
            norm = math.sqrt(r2)
            un = 0.0
            for a in range(d):
                normal[a] /= norm
                un += (vel[k, a] - vel[i, a]) * normal[a]
            delta = growth - un
            if delta > 0.0:
                for a in range(d):
                    vel[k, a] += delta * normal[a]
                    vel[i, a] -= delta * normal[a]
                virial += (sigma0 + growth * t) * delta
            count[i] += 1
            count[k] += 1
            collisions += 1
            _predict(i, t, pos, vel, tloc, cellc, head, nxt, nc, width, side, sigma0, growth,
                     ev_time, ev_kind, ev_partner, ev_count, count, heap, where, offsets)
            _predict(k, t, pos, vel, tloc, cellc, head, nxt, nc, width, side, sigma0, growth,
                     ev_time, ev_kind, ev_partner, ev_count, count, heap, where, offsets)
        elif kind == _CROSSING:
            _advance(i, t, pos, vel, tloc)
            a = ev_partner[i]
            direction = ev_count[i]
            old = _cell_flat(cellc, i, nc)
            _cell_remove(i, old, head, nxt, prv)
            c = cellc[i, a] + direction
            if direction > 0:
                pos[i, a] = c * width
                if c == nc:
                    c = 0
                    pos[i, a] = 0.0
            else:
                pos[i, a] = cellc[i, a] * width
                if c < 0:
                    c = nc - 1
                    pos[i, a] = side
            cellc[i, a] = c
            _cell_insert(i, _cell_flat(cellc, i, nc), head, nxt, prv)
            _predict(i, t, pos, vel, tloc, cellc, head, nxt, nc, width, side, sigma0, growth,
                     ev_time, ev_kind, ev_partner, ev_count, count, heap, where, offsets)
        else:  # a sphere at rest with no collision ahead: nothing can happen any more
            break
    return t, collisions, virial


@njit(cache=True)
def _synchronize(t, pos, vel, tloc):
    for i in range(pos.shape[0]):
        _advance(i, t, pos, vel, tloc)


# --------------------------------------------------------------------------- driver


def packing_fraction_of(n: int, dim: int, side: float, sigma: float) -> float:
    """Packing fraction n v1(sigma/2) / side^d of n spheres of diameter sigma in a cubic box.

    Parameters
    ----------
    n : int
        Number of spheres.
    dim : int
        Dimension d.
    side : float
        Box side L (same unit as ``sigma``).
    sigma : float
        Sphere diameter.

    Returns
    -------
    float
        The packing fraction phi.
    """
    return n * ball_volume(sigma / 2.0, dim) / side**dim


class GrowingSpheres:
    """The state of an LS run: N spheres of diameter sigma(t) = sigma_0 + g t in the periodic
    box of side N^(1/d) (module docstring). :meth:`run` advances it by one interval of
    ``sync_every`` x N events and measures the interval's reduced pressure.

    ``positions`` (n, d) with diameter ``sigma0`` (non-overlapping), or None for N uniform
    random points (sigma0 = 0); velocities Maxwell-Boltzmann at k T = 1 from ``rng``.
    ``growth_rate`` may be 0 (equilibrium hard spheres at fixed diameter).
    """

    def __init__(self, rng: np.random.Generator, n: int, dim: int = 3, *,
                 growth_rate: float = 0.1, positions: np.ndarray | None = None,
                 sigma0: float = 0.0):
        if dim not in _DENSEST:
            raise ValueError(f"dimension must be 2 or 3, got {dim}")
        if int(n) != n or n < 2:
            raise ValueError(f"need at least 2 spheres, got n = {n}")
        if not growth_rate >= 0:
            raise ValueError(f"growth_rate must be >= 0, got {growth_rate}")
        n = int(n)
        self.n, self.dim = n, dim
        self.side = float(n) ** (1.0 / dim)
        self.sigma_max = (_DENSEST[dim] * self.side**dim / (n * ball_volume(0.5, dim))) ** (1.0 / dim)
        self.nc = int(self.side / self.sigma_max)
        if self.nc < 3:
            raise ValueError(f"{n} spheres are too few for the cell list of the LS compression "
                             f"(box side {self.side:.3g} < 3 x the largest diameter "
                             f"{self.sigma_max:.3g})")
        self.width = self.side / self.nc
        if positions is None:
            if sigma0 != 0.0:
                raise ValueError("a random (Poisson) start needs sigma0 = 0")
            pos = rng.random((n, dim)) * self.side
        else:
            pos = np.array(positions, dtype=float) % self.side
            if pos.shape != (n, dim):
                raise ValueError(f"positions must have shape ({n}, {dim}), got {pos.shape}")
        if not 0.0 <= sigma0 < self.sigma_max:
            raise ValueError(f"sigma0 must lie in [0, {self.sigma_max:.4g}), got {sigma0}")
        vel = rng.standard_normal((n, dim))
        vel -= vel.mean(axis=0)
        vel *= math.sqrt(dim * n / (vel**2).sum())
        self.pos, self.vel = np.ascontiguousarray(pos), np.ascontiguousarray(vel)
        self.cellc = np.minimum((pos / self.width).astype(np.int64), self.nc - 1)
        self.head = np.full(self.nc**dim, -1, dtype=np.int64)
        self.nxt = np.full(n, -1, dtype=np.int64)
        self.prv = np.full(n, -1, dtype=np.int64)
        for i in range(n):
            _cell_insert(i, _cell_flat(self.cellc, i, self.nc), self.head, self.nxt, self.prv)
        self.tloc = np.zeros(n)
        self.ev_time = np.full(n, np.inf)
        self.ev_kind = np.zeros(n, dtype=np.int64)
        self.ev_partner = np.zeros(n, dtype=np.int64)
        self.ev_count = np.zeros(n, dtype=np.int64)
        self.count = np.zeros(n, dtype=np.int64)
        self.heap = np.arange(n, dtype=np.int64)
        self.where = np.arange(n, dtype=np.int64)
        offsets = np.array(np.meshgrid(*[[-1, 0, 1]] * dim, indexing="ij")).reshape(dim, -1).T
        self.offsets = np.ascontiguousarray(offsets, dtype=np.int64)
        self.time = 0.0
        self.sigma0 = float(sigma0)  # sigma(t) = sigma0 + growth t (sigma0 rebased on changes)
        self.growth = float(growth_rate)
        self.events = self.collisions = 0
        self.kinetic_before_rescale = float(dim * n)
        self._predict_all()

    @property
    def sigma(self) -> float:
        return self.sigma0 + self.growth * self.time

    @property
    def phi(self) -> float:
        return packing_fraction_of(self.n, self.dim, self.side, self.sigma)

    def set_growth(self, growth_rate: float) -> None:
        """Change the growth rate from now on (sigma stays continuous)."""
        sigma = self.sigma
        self.growth = float(growth_rate)
        self.sigma0 = sigma - self.growth * self.time
        self._predict_all()

    def _predict_all(self):
        _predict_all(self.time, self.pos, self.vel, self.tloc, self.cellc, self.head, self.nxt,
                     self.nc, self.width, self.side, self.sigma0, self.growth, self.ev_time,
                     self.ev_kind, self.ev_partner, self.ev_count, self.count, self.heap,
                     self.where, self.offsets)

    def run(self, n_events: int) -> float:
        """Process ``n_events`` events, bring every sphere to the time of the last one,
        rescale the velocities to k T = 1; returns the interval's reduced pressure Z."""
        t_start = self.time
        t, hits, virial = _run_events(int(n_events), self.pos, self.vel, self.tloc, self.cellc,
                                      self.head, self.nxt, self.prv, self.nc, self.width,
                                      self.side, self.sigma0, self.growth, self.ev_time,
                                      self.ev_kind, self.ev_partner, self.ev_count, self.count,
                                      self.heap, self.where, self.offsets)
        self.time = float(t)
        self.events += int(n_events)
        self.collisions += int(hits)
        _synchronize(self.time, self.pos, self.vel, self.tloc)
        self.kinetic_before_rescale = float((self.vel**2).sum())
        temperature = self.kinetic_before_rescale / (self.dim * self.n)
        dt = self.time - t_start
        pressure = 1.0 + virial / (self.dim * self.n * temperature * dt) if dt > 0 else np.inf
        self.vel -= self.vel.mean(axis=0)
        self.vel *= math.sqrt(self.dim * self.n / float((self.vel**2).sum()))
        self._predict_all()
        return pressure

    def min_distance(self) -> float:
        """Smallest centre distance (nearest images; all pairs within 1.5 sigma)."""
        from randmedia.periodic import Cell, min_pair_distance

        cell = Cell(np.eye(self.dim) * self.side)
        return min_pair_distance(cell, self.pos % self.side,
                                 min(1.5 * max(self.sigma, 1e-9), cell.half_width))


def compress(rng: np.random.Generator, n: int, dim: int = 3,
             params: LSParameters = LSParameters(), *, positions: np.ndarray | None = None,
             sigma0: float = 0.0, log: logging.Logger | None = None,
             log_seconds: float = 15.0) -> tuple[np.ndarray, np.ndarray, dict]:
    """Grow N hard spheres by LS event-driven MD until the reduced pressure exceeds
    ``params.target_pressure`` (module docstring): at ``params.growth_rate`` until the
    pressure reaches ``params.slowdown_pressure``, then at that rate times
    slowdown_pressure / pressure (set after every interval).

    Start as in :class:`GrowingSpheres`. Returns (positions, box, info) in units of the
    final diameter (D = 1; box = L I with L the box side over the final diameter) and
    info = dict(phi, pressure, events, collisions, time, seconds, pressure_history,
    phi_history). Raises :class:`CompressionError` if the pressure target is not reached
    within ``params.max_events_per_sphere`` events per sphere.

    Parameters
    ----------
    rng : numpy.random.Generator
        Source of the start (random points if ``positions`` is None) and the velocities.
    n : int
        Number of spheres N (>= 2; enough for 3 cells per box side).
    dim : int, optional
        Dimension d, 2 or 3 (default 3).
    params : LSParameters, optional
        Growth rate, slowdown and target pressures, sync interval, event limit.
    positions : ndarray, shape (n, d), optional
        Non-overlapping start in the LS box of side N^(1/d) (number density 1); None for
        uniform random points.
    sigma0 : float, optional
        Diameter of the start, in the LS box units (0 for a random start; default 0).
    log : logging.Logger, optional
        Receives progress lines (default: this module's logger).
    log_seconds : float, optional
        Seconds between progress lines (default 15).

    Returns
    -------
    positions : ndarray, shape (n, d)
        Centres in units of the final diameter, wrapped into [0, L).
    box : ndarray, shape (d, d)
        L I, L the box side over the final diameter.
    info : dict
        phi, pressure, events, collisions, time, seconds and the per-interval arrays
        pressure_history and phi_history.
    """
    log = log or logging.getLogger(__name__)
    system = GrowingSpheres(rng, n, dim, growth_rate=params.growth_rate, positions=positions,
                            sigma0=sigma0)
    chunk = max(1, int(params.sync_every * system.n))
    max_events = int(params.max_events_per_sphere * system.n)
    pressures, phis = [], []
    started = last_log = time.perf_counter()
    while True:
        pressure = system.run(chunk)
        pressures.append(pressure)
        phis.append(system.phi)
        now = time.perf_counter()
        if now - last_log >= log_seconds:
            log.info("LS: phi = %.5f, Z = %.4g, %.3g collisions (%.3g per s)", system.phi,
                     pressure, system.collisions, system.collisions / max(now - started, 1e-9))
            last_log = now
        if pressure >= params.target_pressure:
            break
        if system.events >= max_events or system.sigma >= system.sigma_max:
            raise CompressionError(
                f"LS compression stopped at phi = {system.phi:.5f}, Z = {pressure:.3g} after "
                f"{system.events} events (target Z = {params.target_pressure:g})")
        # near jamming the growth slows down as 1 / Z (quasi-static approach)
        system.set_growth(params.growth_rate * min(1.0, params.slowdown_pressure / pressure))
    sigma = system.sigma
    info = {"phi": system.phi, "pressure": pressure, "events": system.events,
            "collisions": system.collisions, "time": system.time,
            "seconds": time.perf_counter() - started,
            "pressure_history": np.asarray(pressures), "phi_history": np.asarray(phis)}
    return (system.pos % system.side) / sigma, np.eye(system.dim) * (system.side / sigma), info
