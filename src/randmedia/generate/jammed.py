"""Strictly jammed sphere packings by the Torquato-Jiao sequential linear programming algorithm.

S. Torquato and Y. Jiao, PRE 82, 061302 (2010) (TJ): the adaptive-shrinking-cell
problem for spheres -- minimize the volume of a deformable periodic cell that
holds n non-overlapping spheres of diameter D -- solved as a sequence of linear
programs. Klatt & Torquato, PRE 94, 022152 (2016), analyse MRJ packings made
this way (n = 2000, phi = 0.6356, z = 6.00; 14 packings of n = 10 000 in Table V).

One TJ step (the LP is written out in :mod:`randmedia.generate.packing_lp`):

1. list the pairs closer than the influence-sphere distance D (1 + delta);
2. minimize Tr epsilon over the symmetric strain epsilon of the cell and the
   Cartesian displacements u_i, subject to the linearized non-overlap
   constraint of every listed pair and to the bounds
   |epsilon_aa| <= ``max_normal_strain``, |epsilon_ab| <= ``max_shear_strain``,
   |u_ia| <= Delta; the displacement of sphere 0 is fixed (it only removes the
   free global translation);
3. apply the exact update x_i <- (I + epsilon)(x_i + u_i), box <- (I + epsilon) box;
4. remove the overlaps the linearization leaves by rescaling the whole packing
   (positions and cell) by D / (smallest centre distance) -- TJ's "resize" --
   so that the closest pair touches and nothing overlaps;
5. reduce the cell basis (LLL, which keeps the lattice and only picks shorter,
   more orthogonal lattice vectors) so the cell never becomes too thin for the
   nearest-image pair search.

Translation bound. Delta is chosen so that no pair outside the influence sphere
can reach contact in one step: a pair at distance rho >= D (1 + delta) ends at
distance >= (1 - ||epsilon||_2)(rho - 2 sqrt(d) Delta), and ||epsilon||_2 <=
e_n + (d - 1) e_s (largest absolute row sum), so

    Delta = translation_fraction * [D (1 + delta) - D / (1 - e_n - (d - 1) e_s)] / (2 sqrt(d)).

Every overlap after a step therefore comes from the linearization alone
(second order in the step), and the full overlap check of step 4 covers all
pairs anyway.

Trust region. Near jamming a full-size step can lose more to the rescaling of
step 4 than the LP gained (the linearization error is second order in the
step), and phi then oscillates. Each step is therefore judged by the ratio of
the realized gain ln(phi_new / phi_old) to the LP's prediction -Tr epsilon: a
step that lowers phi is rejected, and the translation and strain bounds are
multiplied by a trust factor that is halved after a rejected step or a ratio
below 1/4 and doubled (up to 1) after a ratio above 3/4 (:func:`_next_trust`).
With ``shrink_with_trust`` the influence gap delta shrinks with the trust factor
too (strains and delta scaled, Delta recomputed from the formula above, so the
reach argument holds unchanged): the LP then lists only the pairs the smaller
step can close -- near jamming little more than the contacts -- instead of every
pair within the full influence sphere.

Convergence. The packing is converged when an LP with the full bounds cannot
lower the volume by more than ``tolerance`` (relative, -Tr epsilon <= tolerance;
that last step is applied only if solved to a vertex, whose active rows close the
contacts exactly -- after a first stage of interior points the polish often converges
at its first LP, and without that step its contacts would stay open by 1e-10 - 1e-9 D), when the packing fraction grew by less than
``tolerance`` over the last two accepted LPs (TJ's criterion on the cell
volume), or when the trust factor fell below ``MIN_TRUST`` = 1e-3 (no step
raises phi any more; smaller bounds make HiGHS fail numerically). Changes of phi below ``tolerance`` count as round-off:
such a step is accepted, not rejected. Near jamming the LP solves the linearized problem of the contact
network exactly, so the SLP converges quadratically: contacts close to
1e-14 - 1e-10 D (the last rescaling leaves them all at about its size) while the
smallest non-contact gaps stay ~1e-6 D or larger.

Final backend. An interior point without crossover (``highs-hipo``) solves each LP to a
point of the optimal face's relative interior, whose force-bearing rows are closed only to
the solver's tolerances: converged that way, 3 of 5 packings of N = 500 kept contacts open
by 1e-9 - 1e-8 D and passed the jamming test only from a 1e-8 D contact gap. With
``final_backend`` (a vertex backend) the construction goes on from that state until an LP
solved to a vertex converges too (a few LPs): its active rows are exact, as with a vertex
backend from the start. The LPs of the final phase are marked in the history (``final``).
A run that ends at ``max_lps`` (``at_max_lps="end"``) before its final phase began still
solves one LP with ``final_backend`` first, so the state it returns has closed contacts too.

Warm start. With the dual simplex (``highs-simplex``) each LP starts from the optimal basis
of the previous one, its rows matched by pair (:func:`packing_lp.carry_basis`); the basis is
part of the checkpoint. A start that needs too many iterations gives way to IPX + crossover
(:func:`packing_lp.warm_iteration_limit`; docs/mrj2016.md, "A warm-started dual simplex").

Start: random sequential addition at ``initial_phi``
(:func:`randmedia.generate.rsa.random_sequential_addition`). The construction is
deterministic given the start, so a run resumed from a checkpoint (saved at an LP
boundary by :class:`randmedia.resumable.ResumableRun`) reproduces the uninterrupted run bit
for bit.
"""

from __future__ import annotations

import logging
import math
import os
import time
from dataclasses import asdict, dataclass, field, replace

import numpy as np

from randmedia.generate import packing_lp, refuse_invalid
from randmedia.theory.balls import ball_volume
from randmedia.checkpoint import array_digest, checkpoint_key
from randmedia.periodic import Cell, pairs_within
from randmedia.periodic import min_pair_distance as _min_distance
from randmedia.resumable import ResumableRun

#: densest packing fractions (hexagonal in 2D, fcc in 3D): no packing exceeds them
MAX_PACKING_FRACTION = {2: math.pi / (2 * math.sqrt(3)), 3: math.pi / math.sqrt(18)}


class ConstructionError(RuntimeError):
    """The SLP did not converge within ``max_lps`` or produced an invalid packing."""


#: what :func:`jam` does after ``max_lps`` LPs without converging: "raise"
#: :class:`ConstructionError`, or "end" the construction and return its state (a stage that a
#: later stage goes on from, as the TJ code writes its packing after ``max_iterations``)
AT_MAX_LPS = ("raise", "end")


@dataclass(frozen=True)
class TJParameters:
    """Constants of the Torquato-Jiao SLP (module docstring; lengths in units of D)."""

    influence_gap: float = 0.25
    max_normal_strain: float = 0.01
    max_shear_strain: float = 0.01
    translation_fraction: float = 1.0
    tolerance: float = 1e-12
    max_lps: int = 20000
    backend: str = "highs-hipo"
    #: shrink the influence sphere with the trust factor (module docstring)
    shrink_with_trust: bool = False
    #: > 0: the translation bound is this fraction of D times the cell's linear size relative
    #: to the start, (V / V_0)^(1/d), instead of the reach formula -- the TJ code's bound
    #: ``trans_max``, which limits lattice coordinates (sdatkinson/TJ, test3d/parameters_3d.txt)
    translation_max: float = 0.0
    #: judge each step by its realized gain (module docstring); False: accept every step,
    #: as the TJ code does (its overlaps are removed by the rescaling alone)
    trust_region: bool = True
    #: > 0: also converged when the cell volume changed by at most this fraction of the
    #: *start* volume over two LPs (the TJ code's ``term_tol``, an absolute volume in units of
    #: its unit start cell)
    volume_tolerance_start: float = 0.0
    #: a backend that goes on from where ``backend`` converged, until it converges too (""
    #: none): after an interior point without crossover, a vertex backend closes the
    #: contacts to the LP's round-off (module docstring, "Convergence")
    final_backend: str = ""

    def __post_init__(self):
        checks = {
            "influence_gap": 0 < self.influence_gap <= 2,
            "max_normal_strain": 0 < self.max_normal_strain <= 0.1,
            "max_shear_strain": 0 < self.max_shear_strain <= 0.1,
            "translation_fraction": 0 < self.translation_fraction <= 1,
            "tolerance": 0 < self.tolerance < 1e-3,
            "max_lps": int(self.max_lps) == self.max_lps and self.max_lps >= 1,
            "backend": self.backend in packing_lp.BACKENDS,
            "translation_max": 0 <= self.translation_max <= 0.1,
            "volume_tolerance_start": 0 <= self.volume_tolerance_start < 1e-3,
            "final_backend": self.final_backend in ("",) + packing_lp.BACKENDS,
        }
        refuse_invalid("Torquato-Jiao parameters", checks, self)

    def translation_bound(self, dim: int, diameter: float = 1.0, cell_scale: float = 1.0) -> float:
        """Delta: the largest per-component displacement that keeps pairs beyond the
        influence sphere apart in one step, times ``translation_fraction``; with
        ``translation_max`` > 0 that fixed bound times ``cell_scale`` = (V / V_0)^(1/d)
        instead, refused if it exceeds the reach (then unlisted pairs could collide)."""
        norm = self.max_normal_strain + (dim - 1) * self.max_shear_strain
        if norm >= 1:
            raise ValueError("strain bounds too large: e_n + (d - 1) e_s must be < 1")
        reach = diameter * (1 + self.influence_gap) - diameter / (1 - norm)
        if reach <= 0:
            raise ValueError(
                f"influence_gap {self.influence_gap} too small for the strain bounds "
                f"(need (1 + delta)(1 - e_n - (d-1) e_s) > 1)")
        largest = reach / (2 * math.sqrt(dim))
        if self.translation_max > 0:
            fixed = self.translation_max * diameter * cell_scale
            if fixed > largest:
                raise ValueError(f"translation_max {self.translation_max} D exceeds the reach "
                                 f"{largest:.4g} D of the influence sphere and strain bounds")
            return self.translation_fraction * fixed
        return self.translation_fraction * largest


@dataclass
class JammedPacking:
    """A converged TJ packing and the record of its construction."""

    positions: np.ndarray
    box: np.ndarray
    diameter: float
    n_lp: int
    seconds: float      # wall time
    cpu_seconds: float  # CPU time of this process (steadier on a shared machine)
    lp_seconds: float
    history: dict = field(default_factory=dict)  # per LP: phi, trace, rescale, rows, seconds
    params: TJParameters = TJParameters()
    #: why the construction ended: "converged", or "max_lps" (only with ``at_max_lps="end"``)
    stop: str = "converged"

    @property
    def phi(self) -> float:
        return packing_fraction(self.positions, self.box, self.diameter)

    def construction_attrs(self) -> dict:
        """Constants of the construction, flat, for the packing file's attributes."""
        return {f"tj_{k}": v for k, v in asdict(self.params).items()}

    def lp_history(self) -> dict:
        """Per-LP record (:func:`tj_lp_history`, stage 1 = Torquato-Jiao)."""
        return tj_lp_history(self.history, stage=1)


def tj_lp_history(history: dict, stage: int) -> dict:
    """Per-LP record of a :func:`jam` history: ``stage`` (the caller's code of the stage),
    phi after the LP, the LP's predicted relative volume decrease -Tr epsilon, rows, solve
    seconds (empty arrays for an empty history)."""
    phi = np.asarray(history.get("phi", []), dtype=float)
    return {"stage": np.full(len(phi), stage, dtype=np.int8), "phi": phi,
            "predicted": -np.asarray(history.get("trace", []), dtype=float),
            "rows": np.asarray(history.get("rows", []), dtype=np.int64),
            "solve_seconds": np.asarray(history.get("seconds", []), dtype=float)}


def packing_fraction(positions: np.ndarray, box: np.ndarray, diameter: float = 1.0) -> float:
    """Packing fraction n v1(D/2) / |det box| of n spheres in a periodic cell.

    Parameters
    ----------
    positions : array_like, shape (n, d)
        Sphere centres (only the shape is used).
    box : ndarray, shape (d, d)
        Periodic cell, columns the lattice vectors.
    diameter : float, optional
        Sphere diameter D (default 1), same unit as ``box``.

    Returns
    -------
    float
        The packing fraction phi.
    """
    positions = np.asarray(positions)
    return positions.shape[0] * ball_volume(diameter / 2.0, positions.shape[1]) / abs(np.linalg.det(box))


def validate_packing_input(n: int, phi: float, dim: int, diameter: float = 1.0) -> None:
    """Refuse impossible packings: n < 2, non-positive sizes, phi above the densest packing.

    Parameters
    ----------
    n : int
        Number of spheres (an integer >= 2).
    phi : float
        Target packing fraction, in (0, MAX_PACKING_FRACTION[dim]].
    dim : int
        Dimension d, 2 or 3.
    diameter : float, optional
        Sphere diameter D (> 0; default 1).

    Raises
    ------
    ValueError
        For any refused input.
    """
    if dim not in MAX_PACKING_FRACTION:
        raise ValueError(f"dimension must be 2 or 3, got {dim}")
    if int(n) != n or n < 2:
        raise ValueError(f"a packing needs at least 2 spheres, got n = {n}")
    if not diameter > 0:
        raise ValueError(f"sphere diameter must be > 0, got {diameter}")
    if not 0 < phi <= MAX_PACKING_FRACTION[dim]:
        raise ValueError(f"packing fraction {phi} impossible in {dim}D: must lie in "
                         f"(0, {MAX_PACKING_FRACTION[dim]:.6f}] (densest packing)")


# --------------------------------------------------------------------------- cell reduction


def reduce_cell(box: np.ndarray, delta: float = 0.75) -> np.ndarray:
    """LLL-reduced basis (columns) of the lattice spanned by the columns of ``box``.

    Same lattice, same volume and orientation (det > 0); shorter, nearly orthogonal
    vectors, which keeps the half width h_w of the cell close to its best value.
    """
    basis = np.array(box, dtype=float).T.copy()  # rows = lattice vectors
    dim = basis.shape[0]

    def gram_schmidt(b):
        ortho = np.zeros_like(b)
        mu = np.zeros((dim, dim))
        for i in range(dim):
            ortho[i] = b[i]
            for j in range(i):
                mu[i, j] = b[i] @ ortho[j] / (ortho[j] @ ortho[j])
                ortho[i] = ortho[i] - mu[i, j] * ortho[j]
        return ortho, mu

    k = 1
    for _ in range(1000):
        if k >= dim:
            break
        for j in range(k - 1, -1, -1):
            _, mu = gram_schmidt(basis)
            q = round(mu[k, j])
            if q:
                basis[k] -= q * basis[j]
        ortho, mu = gram_schmidt(basis)
        if ortho[k] @ ortho[k] >= (delta - mu[k, k - 1] ** 2) * (ortho[k - 1] @ ortho[k - 1]):
            k += 1
        else:
            basis[[k, k - 1]] = basis[[k - 1, k]]
            k = max(k - 1, 1)
    reduced = basis.T
    if np.linalg.det(reduced) < 0:
        reduced[:, 0] = -reduced[:, 0]
    return reduced


# --------------------------------------------------------------------------- one step


def remove_overlaps(positions: np.ndarray, box: np.ndarray, diameter: float):
    """Rescale positions and cell by D / (smallest centre distance) if that is < D.

    Returns (positions, box, factor); afterwards no centre distance is below D
    (the factor is nudged up by ulps until that holds in floating point).

    Parameters
    ----------
    positions : ndarray, shape (n, d)
        Sphere centres, in the unit of ``diameter``.
    box : ndarray, shape (d, d)
        Periodic cell, columns the lattice vectors.
    diameter : float
        Sphere diameter D.

    Returns
    -------
    positions : ndarray, shape (n, d)
        Rescaled centres (the input unchanged if nothing overlaps).
    box : ndarray, shape (d, d)
        Rescaled cell.
    factor : float
        The scale factor (>= 1; 1.0 if nothing overlapped).
    """
    cell = Cell(box)
    closest = _min_distance(cell, positions, diameter)
    if closest >= diameter:
        return positions, box, 1.0
    factor = diameter / closest
    while True:
        new_positions, new_box = positions * factor, box * factor
        if _min_distance(Cell(new_box), new_positions, diameter) >= diameter:
            return new_positions, new_box, factor
        factor = np.nextafter(factor, np.inf)


def leave_vertex(positions: np.ndarray, box: np.ndarray, strain: np.ndarray, displacement: np.ndarray,
                 diameter: float = 1.0, *, contact_gap: float = 1e-9, reach: float = 0.02):
    """Move a packing along a first-order motion until its first new contact.

    A polish can stop at a degenerate vertex: an isostatic contact network with a contact that
    bears no load is one contact short of rigid, and the motion that opens that contact and
    lowers the volume (the jamming test's cone LP, :mod:`randmedia.describe.jamming`) is
    blocked, within the TJ LP, by a near pair only 10^-9 - 10^-8 D away, so each LP gains less
    than the polish's tolerance. This takes that motion x = (``strain`` epsilon,
    ``displacement`` u) exactly as far as the first pair it closes allows: with
    rate_k = n_k . (u_j - u_i) + rho_k n_k^T epsilon n_k the first-order change of the gap
    g_k of pair k (the row of :func:`randmedia.generate.packing_lp.constraint_matrix`), the
    step is s = min g_k / (-rate_k) over the pairs within D (1 + ``reach``) that close
    (rate_k < 0) and are not contacts (g_k > ``contact_gap`` D); then
    x_i <- (I + s epsilon)(x_i + s u_i), box <- (I + s epsilon) box, and the overlaps left
    (second order in s, and contacts not in the motion's rows) are removed by rescaling as
    in a TJ step. A polish from there closes the new contact network.

    Parameters
    ----------
    positions : ndarray, shape (n, d)
        Non-overlapping centres.
    box : ndarray, shape (d, d)
        Periodic cell, columns the lattice vectors.
    strain, displacement : ndarray, shapes (d, d) and (n, d)
        The first-order motion (in the LP's normalization, |x| <= 1).
    diameter : float, optional
        D.
    contact_gap : float, optional
        Gaps up to this fraction of D are contacts (they do not limit the step).
    reach : float, optional
        Pairs closer than D (1 + reach) are checked; s is capped at ``reach`` D over the
        largest closing rate when none of them closes.

    Returns
    -------
    positions, box : ndarray
        The moved, overlap-free packing (cell LLL-reduced, centres wrapped).
    step : float
        s.
    """
    positions = np.asarray(positions, dtype=float)
    dim = positions.shape[1]
    i, j, separation, distance = pairs_within(Cell(box), positions, diameter * (1.0 + reach))
    normal = separation / distance[:, None]
    rate = (np.einsum("ma,ma->m", normal, displacement[j] - displacement[i])
            + distance * np.einsum("ma,ab,mb->m", normal, strain, normal))
    gap = distance - diameter
    closing = (rate < 0.0) & (gap > contact_gap * diameter)
    if closing.any():
        step = float(np.min(gap[closing] / -rate[closing]))
    else:
        step = reach * diameter / max(float(np.abs(rate).max(initial=0.0)), 1.0)
    deformation = np.eye(dim) + step * strain
    moved = (positions + step * displacement) @ deformation.T
    new_box = deformation @ box
    moved, new_box, _ = remove_overlaps(moved, new_box, diameter)
    new_box = reduce_cell(new_box)
    return Cell(new_box).wrap(moved), new_box, step


def tj_step(positions: np.ndarray, box: np.ndarray, params: TJParameters, diameter: float = 1.0,
            threads: int = 1, trust: float = 1.0, start_volume: float | None = None,
            basis: packing_lp.LPBasis | None = None):
    """One LP of the TJ construction (steps 1-4 of the module docstring), with the
    translation and strain bounds multiplied by ``trust`` (<= 1).

    Returns (positions, box, record) with record = dict(trace, rescale, rows, seconds,
    iterations).

    Parameters
    ----------
    positions : ndarray, shape (n, d)
        Non-overlapping sphere centres, in the unit of ``diameter``.
    box : ndarray, shape (d, d)
        Periodic cell, columns the lattice vectors.
    params : TJParameters
        Bounds, influence gap and LP backend.
    diameter : float, optional
        Sphere diameter D (default 1).
    threads : int, optional
        Solver threads (default 1).
    trust : float, optional
        Trust factor in (0, 1] (default 1); with ``params.shrink_with_trust`` it scales the
        influence gap and strain bounds instead.
    start_volume : float, optional
        Cell volume V_0 at the start of the construction: scales ``params.translation_max``
        by (V / V_0)^(1/d) (default: the current volume, scale 1).
    basis : packing_lp.LPBasis, optional
        The optimal basis of the previous LP of the construction: a backend of
        :data:`packing_lp.WARM_BACKENDS` starts from it (:func:`packing_lp.carry_basis`).

    Returns
    -------
    positions : ndarray, shape (n, d)
        Deformed, moved, overlap-free centres, wrapped into the reduced cell.
    box : ndarray, shape (d, d)
        New cell, LLL-reduced (:func:`reduce_cell`).
    record : dict
        Per-LP record (``trace`` = Tr epsilon, ``rescale``, ``rows``, timings, iteration
        counts, bound statistics) and ``basis``, the LP's optimal :class:`packing_lp.LPBasis`
        (None from an interior point).
    """
    n, dim = positions.shape
    if params.shrink_with_trust and trust < 1.0:
        params = replace(params, influence_gap=params.influence_gap * trust,
                         max_normal_strain=params.max_normal_strain * trust,
                         max_shear_strain=params.max_shear_strain * trust)
        trust = 1.0
    cell = Cell(box)
    cutoff = diameter * (1 + params.influence_gap)
    if cutoff > cell.half_width:
        raise ConstructionError(
            f"influence sphere D(1 + delta) = {cutoff:g} exceeds the cell half width "
            f"{cell.half_width:g}: too few spheres ({n}) for this influence_gap")
    tic = time.perf_counter()
    i, j, separation, distance = pairs_within(cell, positions, cutoff)
    matrix = packing_lp.constraint_matrix(n, i, j, separation, distance)
    ns = packing_lp.n_strain(dim)
    cost = np.zeros(ns + dim * n)
    cost[:dim] = 1.0
    volume = abs(np.linalg.det(box))
    scale = (volume / start_volume) ** (1.0 / dim) if start_volume else 1.0
    delta = params.translation_bound(dim, diameter, scale)
    upper = np.full(ns + dim * n, delta * trust)
    upper[:dim] = params.max_normal_strain * trust
    upper[dim:ns] = params.max_shear_strain * trust
    upper[ns:ns + dim] = 0.0  # sphere 0 fixed: removes the free global translation
    bound = packing_lp.gap_bound(distance, diameter)
    if bound.max(initial=0.0) > 1e-12 * diameter:
        raise ConstructionError(f"overlap of {bound.max():.3g} D before an LP (bug)")
    bound = np.minimum(bound, 0.0)  # round-off overlaps (< 1e-12 D) count as contacts
    row_keys = i.astype(np.int64) * n + j
    start_basis = None
    if basis is not None and params.backend in packing_lp.WARM_BACKENDS:
        start_basis = packing_lp.carry_basis(basis, row_keys, len(cost))
    build = time.perf_counter() - tic
    # the LP's clocks include an abandoned first attempt (a warm start past its iteration limit)
    lp_wall, lp_cpu = time.perf_counter(), time.process_time()
    # x = 0 is feasible: a failure is numerical (seen with IPX at tiny trust factors, and once
    # with HiPO at N = 10 000) or a warm start past its limit, and packing_lp.fallback decides
    solution = packing_lp.solve_or_fallback(cost, matrix, bound, -upper, upper, backend=params.backend,
                                            threads=threads, start_basis=start_basis)
    lp_wall, lp_cpu = time.perf_counter() - lp_wall, time.process_time() - lp_cpu
    deformation = np.eye(dim) + packing_lp.strain_matrix(solution.x[:ns], dim)
    moved = (positions + solution.x[ns:].reshape(n, dim)) @ deformation.T
    new_box = deformation @ box
    moved, new_box, factor = remove_overlaps(moved, new_box, diameter)
    new_box = reduce_cell(new_box)
    moved = Cell(new_box).wrap(moved)
    at_bound = np.abs(solution.x) >= upper * (1.0 - 1e-9)
    at_bound[upper == 0.0] = False
    duals = np.abs(solution.col_dual) if solution.col_dual is not None else np.zeros_like(upper)
    record = {"trace": float(solution.x[:dim].sum()), "rescale": factor, "rows": len(i),
              "seconds": lp_wall, "cpu": lp_cpu,
              "iterations": solution.iterations,
              "at_bound": int(at_bound[ns:].sum()), "strain_at_bound": int(at_bound[:ns].sum()),
              "bound_dual_sum": float(duals[at_bound].sum()), "build_seconds": build,
              "ipm_iterations": solution.ipm_iterations,
              "crossover_iterations": solution.crossover_iterations,
              "simplex_iterations": solution.simplex_iterations,
              "fallback": solution.fallback_reason,
              "basis": None if solution.col_status is None else
              packing_lp.LPBasis(solution.col_status, solution.row_status, row_keys)}
    return moved, new_box, record


# --------------------------------------------------------------------------- the construction


_HISTORY_KEYS = ("phi", "trace", "rescale", "rows", "seconds", "cpu", "iterations", "trust", "final",
                 "accepted", "at_bound", "strain_at_bound", "bound_dual_sum", "build_seconds",
                 "ipm_iterations", "crossover_iterations", "simplex_iterations")
#: the construction stops when the trust factor falls below this (no step improves phi)
MIN_TRUST = 1e-3


def _next_trust(trust: float, predicted: float, actual: float,
                noise: float = 0.0) -> tuple[bool, float]:
    """Trust-region rule of the SLP: (accept the step?, trust factor of the next LP).

    ``predicted`` = -Tr epsilon, the LP's first-order relative volume decrease;
    ``actual`` = ln(phi_new / phi_old) after the overlaps were removed. A step that lowers
    phi by more than ``noise`` (the convergence tolerance: changes below it are round-off)
    is rejected and the bounds halved; an accepted step that realizes less than a quarter
    of its prediction halves them, more than three quarters doubles them (up to the
    configured bounds).
    """
    if actual < -noise:
        return False, trust / 2
    if predicted <= noise:
        return True, trust
    ratio = actual / predicted
    if ratio < 0.25:
        return True, trust / 2
    if ratio > 0.75:
        return True, min(1.0, 2 * trust)
    return True, trust


def jam(positions: np.ndarray, box: np.ndarray, params: TJParameters = TJParameters(), *,
        diameter: float = 1.0, checkpoint: str | os.PathLike | None = None,
        checkpoint_seconds: float = 60.0, log: logging.Logger | None = None,
        log_seconds: float = 15.0, threads: int = 1, at_max_lps: str = "raise") -> JammedPacking:
    """Compress a non-overlapping packing to a strictly jammed one by TJ steps (module docstring).

    Parameters
    ----------
    positions : array (n, d)
        Start packing (no overlaps), d = 2 or 3.
    box : array (d, d)
        Its periodic cell, lattice vectors as columns.
    params : TJParameters
        Constants of the SLP.
    diameter : float
        D.
    checkpoint : path, optional
        File the state is saved to (at LP boundaries, at most every ``checkpoint_seconds``)
        and resumed from if it exists and belongs to the same start and parameters (``max_lps``
        aside; a file with more LPs than ``max_lps`` is refused: ValueError); removed on
        success. Saving, resuming and progress are :class:`randmedia.resumable.ResumableRun`'s.
    log, log_seconds
        Progress (LPs, rate, phi, Tr epsilon, rescale, rows, ETA) at most every ``log_seconds``.
    threads : int
        HiGHS threads.
    at_max_lps : {"raise", "end"}
        After ``params.max_lps`` LPs without convergence: raise, or end and return the state
        with ``stop`` = "max_lps" (:data:`AT_MAX_LPS`) -- with a ``final_backend``, after one
        more LP solved by it (the final phase's first, unless that phase had begun), so the
        contacts are closed at a vertex. Neither it nor ``params.max_lps`` is part of the
        checkpoint's key: they change where a run ends, not its LPs.

    Returns
    -------
    JammedPacking
        The packing and the per-LP record; the same whether or not the run was resumed.

    Raises
    ------
    ConstructionError
        If not converged after ``params.max_lps`` LPs and ``at_max_lps`` is "raise".
    """
    log = log or logging.getLogger(__name__)
    if at_max_lps not in AT_MAX_LPS:
        raise ValueError(f"at_max_lps must be one of {AT_MAX_LPS}, got {at_max_lps!r}")
    positions = np.array(positions, dtype=float)
    box = np.array(box, dtype=float)
    n, dim = positions.shape
    validate_packing_input(n, packing_fraction(positions, box, diameter), dim, diameter)
    closest = _min_distance(Cell(box), positions, diameter)
    if closest < diameter * (1 - 1e-12):
        raise ValueError(f"the start packing overlaps: closest centre distance {closest:.6g} < D = "
                         f"{diameter:g}")
    start_volume = abs(np.linalg.det(box))
    run = ResumableRun(checkpoint, _checkpoint_key(positions, box, params, diameter), log,
                       checkpoint_seconds=checkpoint_seconds, log_seconds=log_seconds)
    state = run.resume(_restore)
    basis = None  # the optimal basis of the last LP, where its backend gives one
    if state is not None:  # saved at an LP boundary, exactly as the step left it
        positions, box, history, basis = state
        first_phase = len(history["phi"]) - int(np.sum(history["final"]))
        if first_phase > params.max_lps:
            raise ValueError(
                f"checkpoint {checkpoint} holds {first_phase} LPs before any final phase, more than "
                f"max_lps = {params.max_lps}: resumed, the run would end past its cap, unlike a fresh "
                "run. Raise max_lps, resume from a copy with at most max_lps LPs (kept checkpoints "
                "are in the record's git history), or remove the file to start afresh")
        log.info("resumed from %s after %d LPs (phi = %.6f)", checkpoint, len(history["phi"]),
                 history["phi"][-1] if history["phi"] else float("nan"))
    else:
        history = {name: [] for name in _HISTORY_KEYS + ("trust_next",)}
        box = reduce_cell(box)
        positions = Cell(box).wrap(positions)
    trust = history["trust_next"][-1] if history["trust_next"] else 1.0
    jammed = False  # the LP with the full bounds cannot lower the volume
    stop = "converged"
    # in the final phase (final_backend) once its first LP is in the history
    final = bool(history["final"]) and bool(history["final"][-1])
    progress = run.progress(None, "TJ", "LPs", done=len(history["phi"]))

    def finished() -> bool:
        nonlocal final, jammed, trust, stop
        done = converged()
        if not done and len(history["phi"]) >= params.max_lps:
            if at_max_lps == "raise":
                accepted = phase_phis()
                change = (accepted[-1] - accepted[-3]) / accepted[-1] if len(accepted) >= 3 else np.nan
                raise ConstructionError(
                    f"TJ did not converge within max_lps = {params.max_lps} LPs (phi = "
                    f"{packing_fraction(positions, box, diameter):.6f}, last relative change "
                    f"{change:.3g} > tolerance {params.tolerance:g})")
            if params.final_backend and not final:
                # one LP solved to a vertex before the end: its active rows close the contacts
                # the interior points left open (~1e-10 D), so a jamming test of the state
                # reads a closed contact network (module docstring, "Convergence")
                log.warning("not converged after max_lps = %d LPs (phi = %.6f, last Tr epsilon "
                            "%.3g): one LP with %s, then the construction ends", params.max_lps,
                            history["phi"][-1], history["trace"][-1], params.final_backend)
                final, jammed, trust = True, False, 1.0
                return False
            stop = "max_lps"
            log.warning("not converged after %d LPs (max_lps = %d; phi = %.6f, last Tr epsilon "
                        "%.3g): the construction ends here", len(history["phi"]), params.max_lps,
                        history["phi"][-1], history["trace"][-1])
            return True
        if done:
            if final or not params.final_backend:
                return True
            log.info("converged with %s after %d LPs; going on with %s", params.backend,
                     len(history["phi"]), params.final_backend)
            final, jammed, trust = True, False, 1.0
        return False

    def phase_phis() -> list:
        """phi after each accepted LP of the current phase."""
        return [phi for phi, ok, last in zip(history["phi"], history["accepted"], history["final"])
                if ok and bool(last) == final]

    def converged() -> bool:
        if jammed:
            return True
        accepted = phase_phis()
        if len(accepted) >= 3 and abs(accepted[-1] - accepted[-3]) <= params.tolerance * accepted[-1]:
            return True
        if params.volume_tolerance_start > 0 and len(accepted) >= 3:
            # |V_t - V_(t-2)| / V_0 with V = n v_1 / phi and V_0 = start_volume
            spheres = n * ball_volume(diameter / 2.0, dim)
            if abs(spheres / accepted[-1] - spheres / accepted[-3]) <= params.volume_tolerance_start * start_volume:
                return True
        if trust < MIN_TRUST:
            log.info("trust factor below %g: no LP step raises phi any more", MIN_TRUST)
            return True
        return False

    def step() -> None:
        nonlocal positions, box, trust, jammed, basis
        phi_old = packing_fraction(positions, box, diameter)
        step_params = replace(params, backend=params.final_backend) if final else params
        new_positions, new_box, record = tj_step(positions, box, step_params, diameter, threads, trust,
                                                 start_volume, basis)
        basis = record.pop("basis")
        if record["fallback"]:
            log.warning("LP %d: %s", len(history["phi"]) + 1, record["fallback"])
        record["final"] = int(final)
        phi_new = packing_fraction(new_positions, new_box, diameter)
        if -record["trace"] <= params.tolerance and trust == 1.0:
            # the LP with the full bounds cannot lower the volume: jammed (TJ's criterion). A
            # step solved to a vertex is still applied: its active rows close the contacts an
            # earlier stage left open (by ~1e-10 - 1e-9 D after interior points; it moves nothing
            # else), unless that would lower phi beyond round-off. An interior point's step is not
            close = (step_params.backend not in packing_lp.INTERIOR_BACKENDS
                     and phi_new >= phi_old * (1.0 - params.tolerance))
            if close:
                positions, box = new_positions, new_box
            for name in _HISTORY_KEYS + ("trust_next",):
                history[name].append({**record, "phi": phi_new if close else phi_old, "trust": trust,
                                      "accepted": 1, "trust_next": trust}[name])
            log.info("the LP cannot lower the volume (Tr epsilon = %.3g): jammed",
                     record["trace"])
            jammed = True
            return
        ok, next_trust = _next_trust(trust, -record["trace"], math.log(phi_new / phi_old),
                                     params.tolerance) if params.trust_region else (True, 1.0)
        if ok:
            positions, box = new_positions, new_box
        record.update(phi=phi_new if ok else phi_old, trust=trust, accepted=int(ok),
                      trust_next=next_trust)
        trust = next_trust
        for name in _HISTORY_KEYS + ("trust_next",):
            history[name].append(record[name])
        _report(progress, history, dim, params.max_lps)

    run.loop(step, finished, lambda: _checkpoint_arrays(positions, box, history, basis))
    log.info("%s after %d LPs in %.1f s (%.1f s CPU): phi = %.6f",
             "converged" if stop == "converged" else "ended at max_lps", len(history["phi"]),
             run.seconds, run.cpu_seconds, history["phi"][-1])
    run.finish()
    return JammedPacking(positions=positions, box=box, diameter=diameter, n_lp=len(history["phi"]),
                         seconds=run.seconds, cpu_seconds=run.cpu_seconds,
                         lp_seconds=float(np.sum(history["seconds"])),
                         history={k: np.asarray(v) for k, v in history.items()}, params=params,
                         stop=stop)


def _report(progress, history, dim, max_lps: int) -> None:
    """Progress line after an LP. The total (hence the ETA) is an estimate, never beyond
    ``max_lps``, where the run stops in any case: the LPs to compress at the current per-LP
    growth of phi up to a typical jamming density (0.64 in 3D, 0.84 in 2D), plus ~50 LPs of
    final convergence. Near jamming (the MRJ polish ends at phi ~ 0.637 with growth ~0) the
    extrapolation diverges, so there the total is ``max_lps`` and the ETA an upper bound."""
    done = len(history["phi"])
    phi = history["phi"][-1]
    recent = np.asarray(history["phi"][-20:])
    growth = (recent[-1] - recent[0]) / max(len(recent) - 1, 1)
    target = 0.64 if dim == 3 else 0.84
    remaining = 50 + (max(target - phi, 0.0) / growth if growth > 0 else 0.0)
    total = min(max_lps, done + int(round(remaining)))
    progress.step(1, total=total, detail=lambda: (
        f"phi = {phi:.6f}, Tr eps = {history['trace'][-1]:.3g}, rescale - 1 = "
        f"{history['rescale'][-1] - 1:.2g}, {history['rows'][-1]} rows (last LP solve "
        f"{history['seconds'][-1]:.2f} s, {history['cpu'][-1]:.2f} s CPU)"
        + (f"; ETA = the bound max_lps = {max_lps}" if total == max_lps else "")))


# --------------------------------------------------------------------------- checkpoints


def constants_without_cap(params) -> dict:
    """A stage's constants (a dataclass with a ``max_lps``) as its checkpoint key holds them:
    less ``max_lps``, which changes where a run ends, not its LPs (so a run resumes under a
    changed cap; one already past a lowered cap is refused by the stage)."""
    return {name: value for name, value in asdict(params).items() if name != "max_lps"}


def _checkpoint_key(positions, box, params, diameter) -> str:
    """Identifies a construction: its start configuration and constants
    (:func:`constants_without_cap`)."""
    return checkpoint_key(params=constants_without_cap(params), diameter=diameter,
                          start=array_digest(positions, box))


def _checkpoint_arrays(positions, box, history, basis: packing_lp.LPBasis | None = None) -> dict:
    """What a checkpoint holds (the driver adds its clocks ``elapsed`` and ``cpu``): the
    state, the per-LP history and the last LP's basis, if any, so that a warm-started
    backend resumes from the basis it would have had."""
    arrays = {"positions": positions, "box": box,
              **{f"history_{k}": np.asarray(v) for k, v in history.items()}}
    if basis is not None:
        arrays.update(basis_col=basis.col_status, basis_row=basis.row_status, basis_keys=basis.row_keys)
    return arrays


def _restore(data: dict):
    """(positions, box, history, basis) from a checkpoint's arrays (KeyError if one is missing;
    basis None if none was saved)."""
    history = {k: data[f"history_{k}"].tolist() for k in _HISTORY_KEYS + ("trust_next",)}
    basis = (packing_lp.LPBasis(data["basis_col"], data["basis_row"], data["basis_keys"])
             if "basis_keys" in data else None)
    return data["positions"], data["box"], history, basis


# --------------------------------------------------------------------------- output file


def packing_dataset(packing: JammedPacking, analysis, attrs: dict):
    """The file contract of a packing (:func:`randmedia.generate.particle_config_dataset`:
    ``position``, ``box``, D) plus its contact network, rattlers and construction record.

    ``analysis`` is a :class:`randmedia.describe.jamming.JammingAnalysis` of the packing.
    Variables: ``contact`` (contact, pair) sphere indices of every contact (gap test),
    ``contact_gap`` and ``contact_force`` (force per unit pressure from the jamming
    test's duals; 0 for contacts of rattlers), ``rattler`` (particle) and ``phi_history``
    (lp): the packing fraction after each LP.

    Parameters
    ----------
    packing : JammedPacking
        The converged packing (positions, box, diameter and construction record).
    analysis : JammingAnalysis
        Contact network, forces, rattlers and jamming test of ``packing``.
    attrs : dict
        Extra global attributes (override the computed ones of the same name).

    Returns
    -------
    xarray.Dataset
        The particle-configuration contract plus the variables listed above and the LP history
        (``lp_stage``, ``lp_predicted``, ``lp_rows``; solve times in attr ``lp_solve_seconds``).
    """
    from randmedia.generate import particle_config_dataset

    network = analysis.network
    cell = Cell(packing.box)
    _, _, _, near = pairs_within(cell, packing.positions,
                                 packing.diameter * (1 + min(0.01, 0.5 * (cell.half_width - 1))))
    gaps = near / packing.diameter - 1.0
    noncontact = gaps[gaps >= network.gap_tolerance / packing.diameter]
    record = {
        "phi": packing.phi,
        "n_lp": packing.n_lp,
        "seconds": packing.seconds,
        "cpu_seconds": packing.cpu_seconds,
        "lp_seconds": packing.lp_seconds,
        "n_contacts": len(network.i),
        "n_backbone_contacts": analysis.n_backbone_contacts,
        "n_backbone": analysis.n_backbone,
        "n_rattlers": int(analysis.rattler.sum()),
        "rattler_fraction": analysis.rattler_fraction,
        "z_mean_nonrattlers": analysis.z_mean_backbone,
        "isostatic_excess": analysis.isostatic_excess,
        "jammed": int(analysis.jammed),
        "jamming_min_trace": analysis.min_trace,
        "jamming_rank_ratio": analysis.rank_ratio,
        "gap_tolerance": network.gap_tolerance,
        "min_gap": float(gaps.min()) if gaps.size else np.nan,
        "max_contact_gap": float(network.gap.max() / packing.diameter) if network.gap.size else np.nan,
        "min_noncontact_gap": float(noncontact.min()) if noncontact.size else np.nan,
        **packing.construction_attrs(),
        **attrs,
    }
    dataset = particle_config_dataset(packing.positions, packing.box, packing.diameter, record)
    dataset["contact"] = (("contact", "pair"), network.pairs.astype(np.int64),
                          {"units": "1", "long_name": "indices of the two spheres in contact"})
    dataset["contact_gap"] = (("contact",), network.gap / packing.diameter,
                              {"units": "D", "long_name": "gap (centre distance - D) of the contact"})
    dataset["contact_force"] = (("contact",), analysis.forces,
                                {"units": "1/D",
                                 "long_name": "contact force / (pressure x cell volume), from the "
                                              "duals of the jamming test (0 for rattler contacts)"})
    dataset["rattler"] = (("particle",), analysis.rattler.astype(np.uint8),
                          {"units": "1", "long_name": "1 = rattler (not held by the contacts)"})
    lps = packing.lp_history()
    dataset["phi_history"] = (("lp",), lps["phi"],
                              {"units": "1", "long_name": "packing fraction after each LP"})
    dataset["lp_stage"] = (("lp",), lps["stage"],
                           {"units": "1", "long_name": "stage of the LP: 0 = inflation in the "
                                                       "fixed cell, 1 = Torquato-Jiao (deformable cell)"})
    dataset["lp_predicted"] = (("lp",), lps["predicted"],
                               {"units": "1", "long_name": "first-order gain in ln(phi) the LP "
                                                           "predicted (d (sqrt(Gamma) - 1) or -Tr epsilon)"})
    dataset["lp_rows"] = (("lp",), lps["rows"], {"units": "1", "long_name": "constraint rows of the LP"})
    # Timings are run metadata, not data: the same seed must give identical data
    # variables on any machine, so the per-LP wall times go into an attribute.
    dataset.attrs["lp_solve_seconds"] = np.asarray(lps["solve_seconds"], dtype=float)
    dataset = dataset.assign_coords(
        pair=("pair", np.arange(2), {"units": "1", "long_name": "sphere of the contact"}))
    return dataset

