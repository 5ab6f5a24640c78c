"""Canonical (NVT) Metropolis Monte Carlo of particles on the sphere of radius R (sphere2019, Sec. V).

N = round(rho 4 pi R^2) particles on the sphere; reduced units: LJ energy epsilon,
length d_LJ, temperature T* = k_B T / epsilon. Pair potentials on the *chord*
(Euclidean) distance r, Eqs. (11)-(12):

* ``lj``:     U_LJ = 4 epsilon [(d/r)^12 - (d/r)^6]                               Eq. (11)
* ``udd``:    U_LJ + alpha/r^3 [s_i.s_j - 3 (s_i.r)(s_j.r)/r^2], dipoles s = x/R   Eq. (12a)
  normal to the surface. On the sphere s_i.s_j = 1 - r^2/(2R^2),
  s_i.r = -r^2/(2R), s_j.r = +r^2/(2R) (r = x_j - x_i), so exactly
  U_dd = U_LJ + alpha/r^3 + alpha/(4 R^2 r): purely repulsive, with a Coulomb tail
  of strength alpha/(4R^2) (:func:`dipole_pair_energy` is the general vector form;
  the test checks the identity).
* ``udd_flipped``: Eq. (12a) with the sign of one s.r factor flipped (as if r_ij were
  used in one and r_ji in the other): bracket 1 - 5 r^2/(4R^2), so
  U_LJ + alpha/r^3 - 5 alpha/(4 R^2 r), whose tail is *attractive* -- the behaviour the
  paper's text ascribes to U_dd. A second reading of Eq. (12a), run beside it.
* ``uddpar``: U_LJ + alpha/r^3                                                    Eq. (12b)
* ``uddpar_cubed``: U_LJ + epsilon (alpha d/r)^3 = U_LJ + alpha^3/r^3: a second reading
  of Eq. (12b) in which alpha scales the dipole *length* (coupling alpha^3; alpha = 1
  is unchanged). Eq. (12b) as printed cannot produce the paper's ordered alpha = 3, 6
  states at T* = 5.2 (docs/sphere2019.md); this reading is run beside it as separate
  systems and compared in a second Table I row.
* ``udc``:    U_LJ + gamma/r^2                                                    Eq. (12c)
* ``ucc``:    U_LJ + beta/r                                                       Eq. (12d)

so every potential is 4 eps (r^-12 - r^-6) + c1/r + c2/r^2 + c3/r^3; ``epsilon = 0``
with coupling 0 is the ideal gas (used by the tests). No cutoff: all pairs interact
(a finite sphere has no periodic images).

Moves. A trial picks a particle uniformly and moves it along the great circle in a
uniformly random tangent direction by the geodesic length s = delta sqrt(u),
u ~ U(0, 1) (a displacement uniform in a tangent disk of radius delta, carried onto
the sphere by the exponential map). The proposal density depends only on the
geodesic distance between old and new position, so it is symmetric and the
Metropolis rule min(1, exp(-Delta U / T*)) samples exp(-U/T*) on the sphere. The
energy change costs O(N) pair evaluations in a numba loop (no Python per move);
``error_model="numpy"`` drops the division-by-zero checks so that LLVM vectorizes
it (SIMD division and square root; ~3x faster).

Run. Random uniform start; ``equilibration_sweeps`` sweeps (1 sweep = N trials),
the step delta adapted during the first ``tune_fraction`` of them towards
``target_acceptance`` (after every >= 2000 trials, by the factor acceptance/target
clipped to [0.7, 1.4]) and then frozen; then ``production_sweeps`` sweeps at the frozen step. Recorded: the
energy after every sweep (equilibration and production), the acceptance of every
sweep, the positions every ``frame_interval`` production sweeps, and -- after every
``count_interval`` production sweeps -- the numbers of particles in the caps about the three
orthogonal origins +x, +y, +z for each cap of ``cos_thresholds`` (the paper's
"three different coordinate origins", Sec. V). The running energy is updated by
Delta U and checked against an exact recount at the end of each phase.

Checkpoints: the whole state (positions, energy, step, random state, everything
recorded so far) is saved at chunk boundaries at most every ``checkpoint_seconds``
and resumed from, by the driver :class:`randmedia.resumable.ResumableRun` (which also
writes the progress lines); a resumed run is bit-identical to an uninterrupted one.
"""

from __future__ import annotations

import logging
import math
import os
import time
from dataclasses import asdict, dataclass, field

import numpy as np
from numba import njit

from randmedia.checkpoint import array_digest, checkpoint_key
from randmedia.generate import refuse_invalid
from randmedia.resumable import ResumableRun
from randmedia.theory.sphere_caps import check_density, check_radius, first_cap_containing

POTENTIALS = ("lj", "udd", "udd_flipped", "uddpar", "uddpar_cubed", "udc", "ucc")


@dataclass(frozen=True)
class Potential:
    """A pair potential of Eqs. (11)-(12): ``name`` in :data:`POTENTIALS`, ``coupling``
    alpha (udd, udd_flipped, uddpar, uddpar_cubed), gamma (udc) or beta (ucc), LJ depth ``epsilon`` (0: no LJ).
    ``coupling`` has no default: it differs between the systems of ``sphere2019.fluids.systems``
    (tests/test_defaults.py)."""

    name: str
    coupling: float
    epsilon: float = 1.0

    def __post_init__(self):
        if self.name not in POTENTIALS:
            raise ValueError(f"unknown pair potential {self.name!r}; known: {', '.join(POTENTIALS)}")
        for key in ("coupling", "epsilon"):
            value = getattr(self, key)
            if not (isinstance(value, (int, float, np.floating, np.integer)) and not isinstance(value, bool)
                    and math.isfinite(value) and value >= 0):
                raise ValueError(f"potential {key} must be a finite number >= 0, got {value!r}")

    def coefficients(self, radius: float) -> tuple[float, float, float, float]:
        """(4 epsilon, c1, c2, c3) of 4 eps (r^-12 - r^-6) + c1/r + c2/r^2 + c3/r^3."""
        check_radius(radius)
        c = float(self.coupling)
        c1 = c2 = c3 = 0.0
        if self.name == "udd":
            c3, c1 = c, c / (4.0 * radius**2)
        elif self.name == "udd_flipped":
            c3, c1 = c, -5.0 * c / (4.0 * radius**2)
        elif self.name == "uddpar":
            c3 = c
        elif self.name == "uddpar_cubed":
            c3 = c**3
        elif self.name == "udc":
            c2 = c
        elif self.name == "ucc":
            c1 = c
        return 4.0 * float(self.epsilon), c1, c2, c3

    def pair_energy(self, r, radius: float) -> np.ndarray:
        """U(r) on the chord distance r (numpy reference, Eqs. 11-12)."""
        lj4, c1, c2, c3 = self.coefficients(radius)
        r = np.asarray(r, dtype=float)
        return lj4 * (r**-12 - r**-6) + c1 / r + c2 / r**2 + c3 / r**3


def dipole_pair_energy(xi: np.ndarray, xj: np.ndarray, alpha: float) -> np.ndarray:
    """Dipolar part of Eq. (12a) in its general vector form, dipoles s = x/|x| normal to the
    sphere: alpha/r^3 [s_i.s_j - 3 (s_i.r)(s_j.r)/r^2], r = x_j - x_i (rows are pairs).

    Parameters
    ----------
    xi, xj : ndarray, shape (m, 3) or (3,)
        Positions of the two particles of each pair (nonzero; their directions give the dipoles),
        in units of d_LJ.
    alpha : float
        Dipole coupling alpha (energy x length^3, reduced units).

    Returns
    -------
    ndarray, shape (m,)
        Dipolar pair energy of each pair, in units of epsilon.
    """
    xi, xj = np.atleast_2d(xi), np.atleast_2d(xj)
    si = xi / np.linalg.norm(xi, axis=1)[:, None]
    sj = xj / np.linalg.norm(xj, axis=1)[:, None]
    rv = xj - xi
    r2 = np.einsum("ij,ij->i", rv, rv)
    return alpha / r2**1.5 * (np.einsum("ij,ij->i", si, sj)
                              - 3.0 * np.einsum("ij,ij->i", si, rv) * np.einsum("ij,ij->i", sj, rv) / r2)


def particle_number(radius: float, density: float) -> int:
    """N = round(rho 4 pi R^2) (paper: rho = 0.5; R = 15 -> 1414, R = 5 -> 157)."""
    check_radius(radius)
    check_density(density)
    n = int(round(density * 4.0 * math.pi * radius**2))
    if n < 2:
        raise ValueError(f"rho 4 pi R^2 = {density * 4 * math.pi * radius**2:.3g} gives fewer than 2 "
                         "particles; increase R or rho")
    return n


# --------------------------------------------------------------------------- kernels


@njit(cache=True, inline="always", error_model="numpy")
def _pair(r2, lj4, c1, c2, c3):
    inv2 = 1.0 / r2
    inv6 = inv2 * inv2 * inv2
    inv1 = math.sqrt(inv2)
    return lj4 * inv6 * (inv6 - 1.0) + inv1 * (c1 + inv1 * (c2 + inv1 * c3))


@njit(cache=True, error_model="numpy")
def _delta_energy(x, y, z, i, nx, ny, nz, lj4, c1, c2, c3, scratch):
    """U(new position of i) - U(old position of i), summed over all j != i.

    Two passes, both deterministic without fastmath: the pair-energy changes of all j go
    elementwise into ``scratch`` (a loop with no reduction, which LLVM vectorizes with exact
    IEEE sqrt/division), then they are added in a fixed order by four independent
    accumulators (j mod 4 lanes, combined as (a0 + a1) + (a2 + a3)). Every run and every
    compilation adds the same numbers in the same order, so energies are bit-identical
    (fastmath reassociation made them depend on inlining and the cache)."""
    ox, oy, oz = x[i], y[i], z[i]
    n = x.size
    for j in range(n):
        dxn, dyn, dzn = x[j] - nx, y[j] - ny, z[j] - nz
        dxo, dyo, dzo = x[j] - ox, y[j] - oy, z[j] - oz
        scratch[j] = (_pair(dxn * dxn + dyn * dyn + dzn * dzn, lj4, c1, c2, c3)
                      - _pair(dxo * dxo + dyo * dyo + dzo * dzo, lj4, c1, c2, c3))
    scratch[i] = 0.0  # the self term (r = 0 in the old position) is not a pair
    a0 = a1 = a2 = a3 = 0.0
    j = 0
    while j + 3 < n:
        a0 += scratch[j]
        a1 += scratch[j + 1]
        a2 += scratch[j + 2]
        a3 += scratch[j + 3]
        j += 4
    while j < n:
        a0 += scratch[j]
        j += 1
    return (a0 + a1) + (a2 + a3)


@njit(cache=True, error_model="numpy")
def _total_energy(x, y, z, lj4, c1, c2, c3):
    total = 0.0
    for i in range(x.size):
        xi, yi, zi = x[i], y[i], z[i]
        for j in range(i + 1, x.size):
            dx, dy, dz = x[j] - xi, y[j] - yi, z[j] - zi
            total += _pair(dx * dx + dy * dy + dz * dz, lj4, c1, c2, c3)
    return total


@njit(cache=True)
def _axis_cap_counts(x, y, z, radius, cos_thresholds, out):
    """out[k, c] = number of particles in the cap about axis k (+x, +y, +z) with
    cos(angle) >= cos_thresholds[c] (thresholds decreasing = caps growing)."""
    n_caps = cos_thresholds.size
    for k in range(3):
        for c in range(n_caps):
            out[k, c] = 0
    hist = np.zeros((3, n_caps + 1), dtype=np.int64)
    for i in range(x.size):
        for k in range(3):
            value = (x[i] if k == 0 else (y[i] if k == 1 else z[i])) / radius
            hist[k, first_cap_containing(cos_thresholds, value)] += 1
    for k in range(3):
        running = 0
        for c in range(n_caps):
            running += hist[k, c]
            out[k, c] = running


@njit(cache=True, error_model="numpy")
def _sweeps(x, y, z, radius, beta, lj4, c1, c2, c3, step, n_sweeps, rng, tune,
            target_acceptance, energy, energies, acceptances, cos_thresholds, counts,
            first_count, count_every):
    """Run ``n_sweeps`` sweeps of N trial moves in place. Records the energy and acceptance
    after every sweep into energies[s], acceptances[s], and the axis-cap counts after the
    sweeps s = first_count + m * count_every into counts[m] (m < counts.shape[0]).
    With ``tune`` the step is adapted after each sweep. Returns (energy, step, accepted)."""
    n = x.size
    scratch = np.empty(n)
    accepted_total = 0
    max_step = math.pi * radius
    window_accepted = 0
    window_trials = 0
    for sweep in range(n_sweeps):
        accepted = 0
        for _ in range(n):
            i = min(int(rng.random() * n), n - 1)
            px, py, pz = x[i] / radius, y[i] / radius, z[i] / radius
            # orthonormal tangent basis (e1, e2) at p
            if abs(pz) < 0.9:
                hx, hy, hz = 0.0, 0.0, 1.0
            else:
                hx, hy, hz = 1.0, 0.0, 0.0
            e1x, e1y, e1z = hy * pz - hz * py, hz * px - hx * pz, hx * py - hy * px
            norm = math.sqrt(e1x * e1x + e1y * e1y + e1z * e1z)
            e1x, e1y, e1z = e1x / norm, e1y / norm, e1z / norm
            e2x, e2y, e2z = py * e1z - pz * e1y, pz * e1x - px * e1z, px * e1y - py * e1x
            omega = 2.0 * math.pi * rng.random()
            angle = step * math.sqrt(rng.random()) / radius
            co, so = math.cos(omega), math.sin(omega)
            tx, ty, tz = co * e1x + so * e2x, co * e1y + so * e2y, co * e1z + so * e2z
            ca, sa = math.cos(angle), math.sin(angle)
            qx, qy, qz = ca * px + sa * tx, ca * py + sa * ty, ca * pz + sa * tz
            norm = radius / math.sqrt(qx * qx + qy * qy + qz * qz)
            qx, qy, qz = qx * norm, qy * norm, qz * norm
            d_energy = _delta_energy(x, y, z, i, qx, qy, qz, lj4, c1, c2, c3, scratch)
            if d_energy > 0.0:
                if rng.random() >= math.exp(-beta * d_energy):
                    continue
            x[i], y[i], z[i] = qx, qy, qz
            energy += d_energy
            accepted += 1
        accepted_total += accepted
        rate = accepted / n
        energies[sweep] = energy
        acceptances[sweep] = rate
        if sweep >= first_count and (sweep - first_count) % count_every == 0:
            m = (sweep - first_count) // count_every
            if m < counts.shape[0]:
                _axis_cap_counts(x, y, z, radius, cos_thresholds, counts[m])
        if tune:
            window_accepted += accepted
            window_trials += n
            if window_trials >= 2000:  # adapt on >= 2000 trials: the rate of one sweep is noisy
                factor = max(0.7, min(1.4, (window_accepted / window_trials) / target_acceptance))
                step = min(max_step, max(1e-4, step * factor))
                window_accepted = 0
                window_trials = 0
    return energy, step, accepted_total


def total_energy(positions: np.ndarray, potential: Potential, radius: float) -> float:
    """Exact total energy of one configuration (numba, O(N^2)).

    Parameters
    ----------
    positions : ndarray, shape (N, 3)
        Points on the sphere, in units of d_LJ.
    potential : Potential
        Pair potential of Eqs. (11)-(12).
    radius : float
        Sphere radius R, in units of d_LJ (enters the udd / udd_flipped coefficients).

    Returns
    -------
    float
        Sum of the pair energies over all pairs, in units of epsilon.
    """
    lj4, c1, c2, c3 = potential.coefficients(radius)
    x, y, z = (np.ascontiguousarray(positions[:, k], dtype=np.float64) for k in range(3))
    return float(_total_energy(x, y, z, lj4, c1, c2, c3))


def delta_energy(positions: np.ndarray, i: int, new: np.ndarray, potential: Potential,
                 radius: float) -> float:
    """Energy change of moving particle i to ``new`` (the kernel used by the moves).

    Parameters
    ----------
    positions : ndarray, shape (N, 3)
        Current points on the sphere, in units of d_LJ.
    i : int
        Index of the moved particle.
    new : ndarray, shape (3,)
        Its trial position.
    potential : Potential
        Pair potential of Eqs. (11)-(12).
    radius : float
        Sphere radius R, in units of d_LJ.

    Returns
    -------
    float
        U(after) - U(before), in units of epsilon.
    """
    lj4, c1, c2, c3 = potential.coefficients(radius)
    x, y, z = (np.ascontiguousarray(positions[:, k], dtype=np.float64) for k in range(3))
    return float(_delta_energy(x, y, z, int(i), float(new[0]), float(new[1]), float(new[2]),
                               lj4, c1, c2, c3, np.empty(x.size)))


# --------------------------------------------------------------------------- driver


@dataclass(frozen=True)
class MCSchedule:
    """Lengths of a run, in sweeps (1 sweep = N trial moves); see the module docstring.

    The defaults are those of the config section ``sphere2019.fluids``; the run lengths,
    ``count_interval`` included, differ between its ``runs`` and have none
    (tests/test_defaults.py)."""

    equilibration_sweeps: int
    production_sweeps: int
    frame_interval: int
    count_interval: int
    target_acceptance: float = 0.4
    tune_fraction: float = 0.5
    initial_step: float = 0.5
    chunk_sweeps: int = 0  # sweeps per kernel call in equilibration (0: frame_interval)

    def __post_init__(self):
        checks = {
            "equilibration_sweeps": isinstance(self.equilibration_sweeps, int) and self.equilibration_sweeps >= 1,
            "production_sweeps": isinstance(self.production_sweeps, int) and self.production_sweeps >= 2,
            "frame_interval": isinstance(self.frame_interval, int) and 1 <= self.frame_interval <= max(1, self.production_sweeps),
            "count_interval": isinstance(self.count_interval, int) and 1 <= self.count_interval <= max(1, self.production_sweeps // 2),
            "target_acceptance": 0 < self.target_acceptance < 1,
            "tune_fraction": 0 <= self.tune_fraction <= 1,
            "initial_step": self.initial_step > 0,
            "chunk_sweeps": isinstance(self.chunk_sweeps, int) and self.chunk_sweeps >= 0,
        }
        refuse_invalid("Monte Carlo schedule values", checks, self)

    @property
    def n_frames(self) -> int:
        return self.production_sweeps // self.frame_interval

    @property
    def n_counts(self) -> int:
        """Production sweeps after which the three-origin cap counts are recorded."""
        return self.production_sweeps // self.count_interval


@dataclass
class MCRun:
    """A finished run: stored frames and what was recorded on the way (module docstring)."""

    frames: np.ndarray            # (n_frames, N, 3)
    energy: np.ndarray            # (equilibration + production sweeps,) total energy after each sweep
    acceptance: np.ndarray        # (equilibration + production sweeps,)
    axis_counts: np.ndarray       # (production sweeps / count_interval, 3, n_caps) uint16
    step: float                   # frozen step delta (geodesic length)
    stats: dict = field(default_factory=dict)


def integrated_autocorrelation_time(series, window_factor: float = 5.0) -> float:
    """tau_int = 1/2 + sum_{t>=1} rho(t) with Sokal's automatic window (smallest W with
    W >= window_factor * tau_int(W)); in units of the series spacing. A series of
    independent values has tau_int = 1/2; frames 2 tau_int apart are independent."""
    values = np.asarray(series, dtype=float)
    if values.ndim != 1 or values.size < 4:
        raise ValueError("need a 1D series of at least 4 values")
    values = values - values.mean()
    n = values.size
    if not np.any(values):
        return 0.5
    spectrum = np.fft.rfft(values, 2 * n)
    acf = np.fft.irfft(spectrum * np.conj(spectrum))[:n]
    acf /= acf[0]
    tau = 0.5
    for w in range(1, n):
        tau += acf[w]
        if w >= window_factor * tau:
            break
    return float(max(tau, 0.5))


def blocked_mean_and_error(series, n_blocks: int = 20) -> tuple[float, float]:
    """Mean of a correlated series and its error from ``n_blocks`` contiguous block means."""
    values = np.asarray(series, dtype=float)
    usable = values.size - values.size % n_blocks
    blocks = values[:usable].reshape(n_blocks, -1).mean(axis=1)
    return float(values.mean()), float(blocks.std(ddof=1) / math.sqrt(n_blocks))


def run_fluid(potential: Potential, radius: float, density: float, temperature: float,
              schedule: MCSchedule, rng: np.random.Generator, cos_thresholds: np.ndarray, *,
              checkpoint: str | os.PathLike | None = None, checkpoint_seconds: float = 60.0,
              log: logging.Logger | None = None, log_seconds: float = 10.0) -> MCRun:
    """Canonical MC of N = round(rho 4 pi R^2) particles on the sphere (module docstring).

    Parameters
    ----------
    potential : Potential
        Pair potential, Eqs. (11)-(12).
    radius, density, temperature : float
        R, rho and T* of the system (reduced units).
    schedule : MCSchedule
        Sweeps of equilibration and production, recording intervals, step tuning.
    rng : numpy.random.Generator
        The run's only source of randomness.
    cos_thresholds : array
        Non-increasing cosines of the cap half-angles whose particle counts are recorded.
    checkpoint : path, optional
        File the state is saved to at chunk boundaries (at most every ``checkpoint_seconds``)
        and resumed from if it belongs to this run; removed when the run is done.
    log, log_seconds
        Progress lines (sweeps, rate, ETA, acceptance, step, U/N) at most every ``log_seconds``.

    Returns
    -------
    MCRun
        Frames, energy and acceptance per sweep, cap counts, frozen step and run statistics;
        the same whether or not the run was killed and resumed.
    """
    check_radius(radius)
    check_density(density)
    if not (temperature > 0 and math.isfinite(temperature)):
        raise ValueError(f"temperature T* must be a finite number > 0, got {temperature!r}")
    thresholds = np.ascontiguousarray(cos_thresholds, dtype=np.float64)
    if thresholds.ndim != 1 or np.any(np.diff(thresholds) > 0) or np.any(np.abs(thresholds) > 1):
        raise ValueError("cos_thresholds must be a non-increasing 1D array in [-1, 1] (caps growing)")
    log = log or logging.getLogger(__name__)
    n = particle_number(radius, density)
    if n > np.iinfo(np.uint16).max:
        raise ValueError(f"N = {n} exceeds the uint16 cap counts (65535)")
    lj4, c1, c2, c3 = potential.coefficients(radius)
    beta = 1.0 / temperature
    n_eq, n_prod = schedule.equilibration_sweeps, schedule.production_sweeps
    # equilibration chunks hold at least one tuning window (2000 trials)
    chunk_eq = max(schedule.chunk_sweeps or schedule.frame_interval, -(-2000 // n))
    n_tune = int(round(schedule.tune_fraction * n_eq))

    key = _checkpoint_key(potential, radius, density, temperature, schedule, thresholds, rng)
    run = ResumableRun(checkpoint, key, log, rng=rng, checkpoint_seconds=checkpoint_seconds,
                       log_seconds=log_seconds)
    state = run.resume(_restore)
    if state is None:
        start = rng.standard_normal((n, 3))
        start *= radius / np.linalg.norm(start, axis=1)[:, None]
        state = {
            "sweep": 0, "step": float(schedule.initial_step),
            "x": start[:, 0].copy(), "y": start[:, 1].copy(), "z": start[:, 2].copy(),
            "energy": np.full(n_eq + n_prod, np.nan), "acceptance": np.full(n_eq + n_prod, np.nan),
            "axis_counts": np.zeros((schedule.n_counts, 3, thresholds.size), dtype=np.uint16),
            "frames": np.full((schedule.n_frames, n, 3), np.nan),
            "running_energy": float("nan"), "drift": np.full(2, np.nan),
        }
        state["running_energy"] = float(_total_energy(state["x"], state["y"], state["z"],
                                                      lj4, c1, c2, c3))
    else:
        log.info("resumed from %s at sweep %d", checkpoint, state["sweep"])
    x, y, z = state["x"], state["y"], state["z"]
    counts_buffer = np.zeros((0, 3, thresholds.size), dtype=np.int64)
    total = n_eq + n_prod
    pair_evaluations_per_sweep = 2.0 * n * (n - 1)
    progress = run.progress(total, f"MC {potential.name} N = {n}", "sweeps", done=state["sweep"])

    def chunk() -> None:
        """Sweeps up to the next chunk boundary (tuning window, phase end or frame)."""
        sweep = state["sweep"]
        producing = sweep >= n_eq
        if producing:
            length = schedule.frame_interval - (sweep - n_eq) % schedule.frame_interval
            length = min(length, total - sweep)
        else:
            length = min(chunk_eq, n_eq - sweep)
            if sweep < n_tune:
                length = min(length, n_tune - sweep)
        tune = (not producing) and sweep < n_tune
        energies = np.empty(length)
        acceptances = np.empty(length)
        every = schedule.count_interval
        if producing:
            done = sweep - n_eq  # production sweeps done before this chunk
            first_global = -(-(done + 1) // every) * every  # first recorded sweep number >= done + 1
            first_count = first_global - done - 1  # its local index in this chunk
            n_records = max(0, (length - 1 - first_count) // every + 1) if first_count < length else 0
            first_record = first_global // every - 1
            counts = np.zeros((n_records, 3, thresholds.size), dtype=np.int64)
        else:
            first_count, first_record, counts = 0, 0, counts_buffer
        tic = time.perf_counter()
        energy, step, _ = _sweeps(x, y, z, float(radius), beta, lj4, c1, c2, c3, state["step"], length,
                                  rng, tune, schedule.target_acceptance, state["running_energy"],
                                  energies, acceptances, thresholds, counts, first_count, every)
        elapsed = time.perf_counter() - tic
        state["running_energy"], state["step"] = float(energy), float(step)
        state["energy"][sweep:sweep + length] = energies
        state["acceptance"][sweep:sweep + length] = acceptances
        if producing:
            stop = min(first_record + counts.shape[0], schedule.n_counts)
            state["axis_counts"][first_record:stop] = counts[: stop - first_record]
            done = sweep - n_eq + length
            if done % schedule.frame_interval == 0 and done // schedule.frame_interval <= schedule.n_frames:
                state["frames"][done // schedule.frame_interval - 1] = np.column_stack([x, y, z])
        state["sweep"] = sweep + length
        if not producing and state["sweep"] < n_eq:
            # the random start has near-overlaps with huge energies: recount after every
            # equilibration chunk so that the running sum does not carry their round-off
            state["running_energy"] = float(_total_energy(x, y, z, lj4, c1, c2, c3))
        if state["sweep"] == n_eq or state["sweep"] == total:
            # exact recount at the end of each phase: the running energy must agree
            exact = float(_total_energy(x, y, z, lj4, c1, c2, c3))
            phase = 0 if state["sweep"] == n_eq else 1
            state["drift"][phase] = abs(exact - state["running_energy"]) / max(1.0, abs(exact))
            state["running_energy"] = exact
            if state["sweep"] == n_eq:
                state["energy"][n_eq - 1] = exact
        progress.step(length, force=state["sweep"] in (n_tune, n_eq, total), detail=lambda: (
            f"{'production' if producing else 'equilibration'}, "
            f"{length / max(elapsed, 1e-12) * pair_evaluations_per_sweep:.3g} pair evaluations/s, "
            f"acceptance {float(np.mean(acceptances)):.3f}, step {state['step']:.4f}, "
            f"U/N = {state['running_energy'] / n:.5g}"))

    run.loop(chunk, lambda: state["sweep"] >= total, lambda: {name: state[name] for name in _ARRAYS + _SCALARS})
    stats = _run_statistics(state, schedule, n, pair_evaluations_per_sweep, run.seconds)
    run.finish()
    return MCRun(frames=state["frames"], energy=state["energy"], acceptance=state["acceptance"],
                 axis_counts=state["axis_counts"], step=state["step"], stats=stats)


def _run_statistics(state: dict, schedule: MCSchedule, n: int, pairs_per_sweep: float,
                    seconds: float) -> dict:
    """Correlation times and equilibration checks of a finished run (``seconds``: its wall time)."""
    n_eq = schedule.equilibration_sweeps
    production = state["energy"][n_eq:]
    half = production.size // 2
    n_blocks = max(2, min(20, half // 2))
    first = blocked_mean_and_error(production[:half], n_blocks)
    second = blocked_mean_and_error(production[half:2 * half], n_blocks)
    z_halves = (first[0] - second[0]) / max(math.hypot(first[1], second[1]), 1e-300)
    counts = state["axis_counts"].astype(float)
    tau_caps = schedule.count_interval * np.array([
        np.mean([integrated_autocorrelation_time(counts[:, k, c]) for k in range(3)])
        for c in range(counts.shape[2])
    ]) if counts.shape[0] >= 4 else np.full(counts.shape[2], np.nan)
    tau_energy = integrated_autocorrelation_time(production) if production.size >= 4 else float("nan")
    return {
        "n_particles": n,
        "seconds": seconds,
        "pair_evaluations": pairs_per_sweep * (schedule.equilibration_sweeps + schedule.production_sweeps),
        "acceptance_production": float(np.mean(state["acceptance"][n_eq:])),
        "acceptance_equilibration": float(np.mean(state["acceptance"][:n_eq])),
        "energy_drift_equilibration": float(state["drift"][0]),
        "energy_drift_production": float(state["drift"][1]),
        "tau_energy_sweeps": float(tau_energy),
        "tau_caps_sweeps": tau_caps,
        "energy_halves_z": float(z_halves),
        "energy_per_particle": float(production.mean() / n),
        "energy_per_particle_error": float(blocked_mean_and_error(production, n_blocks * 2 if production.size >= 4 * n_blocks else n_blocks)[1] / n),
        "schedule": asdict(schedule),
    }


# --------------------------------------------------------------------------- checkpoints


def _checkpoint_key(potential, radius, density, temperature, schedule, thresholds, rng) -> str:
    """Identifies a run: potential, system, schedule, caps and the random state it starts from.
    ``checkpoint_format`` 2: the wall clock is the driver's ``elapsed`` (format 1 saved ``seconds``),
    so a checkpoint of the former format belongs to another run and is not misread."""
    return checkpoint_key(potential=asdict(potential), R=radius, rho=density, T=temperature,
                          schedule=asdict(schedule), caps=array_digest(thresholds),
                          rng=rng.bit_generator.state, checkpoint_format=2)


_ARRAYS = ("x", "y", "z", "energy", "acceptance", "axis_counts", "frames", "drift")
_SCALARS = ("sweep", "step", "running_energy")


def _restore(data: dict) -> dict:
    """The run's state from a checkpoint's arrays (KeyError if one is missing)."""
    state = {name: data[name] for name in _ARRAYS}
    state["sweep"] = int(data["sweep"])
    for name in ("step", "running_energy"):
        state[name] = float(data[name])
    return state
