"""Jamming in a fixed periodic cell by iterated inflation linear programs (iLP).

Artiaco, Diaz Hernandez Rojas, Parisi and Ricci-Tersenghi, PRE 105, 055303 (2022)
(the CALiPPSO algorithm). One step:

1. list the pairs closer than the cutoff c = D (1 + 4 sqrt(d) l), where l is the bound
   on each displacement component;
2. maximize the common inflation factor Gamma of the squared diameter over the
   displacements s_i, subject to the conservative linearized constraints
   rho^2 + 2 r.(s_j - s_i) >= Gamma D^2 of the listed pairs
   (:func:`randmedia.generate.packing_lp.inflation_matrix`), |s_ia| <= l,
   Gamma <= (1 + 2 sqrt(d) l)^2, s_0 = 0 (the global translation);
3. move the spheres, x_i <- x_i + s_i, and rescale positions and cell by
   D / (smallest centre distance), so that the closest pair touches.

Why the step is exact. The neglected term |s_j - s_i|^2 is >= 0, so the listed pairs end
at least sqrt(Gamma) D apart; a pair beyond the cutoff starts >= c apart, moves closer by
at most 2 sqrt(d) l and so ends >= D (1 + 2 sqrt(d) l) >= sqrt(Gamma) D apart. No step
creates an overlap, none is rejected, and the packing fraction never decreases; step 3
removes only the solver's round-off (feasibility tolerance ~1e-9 D). The realized gain
ln(phi_new / phi_old) / d equals sqrt(Gamma) - 1 up to that round-off.

Bounds (as CALiPPSO's ``bounds_and_cutoff``, with smaller values measured to converge
faster from a compressed start: README). Far from jamming (sqrt(Gamma) - 1 >
``switch_inflation``) the bound is ``displacement_bound``; near it,
``final_displacement_bound``: moves a few times the gaps left by the compression keep
each LP in the basin of the nearest jammed state, while much larger ones let the LP
rearrange the packing and creep, and much smaller ones make the bound bind.
Convergence: sqrt(Gamma) - 1 < ``tolerance``, or phi grew by less than ``tolerance``
(relative) over the last ``stall_lps`` LPs -- the LP solutions carry round-off of
~1e-11 in sqrt(Gamma) (HiGHS' interior point with crossover), below which no inflation
is measurable. Then the packing is collectively jammed in its cell and the row duals
are its contact forces (Artiaco et al., Sec. II B); the largest move of a sphere of
the force-bearing backbone (>= d + 1 rows with a positive dual) is recorded.

Creep: a rare packing keeps a collective sliding motion that the fixed cell does not
stop; each LP then moves a group of spheres by the bound and gains only sqrt(Gamma) - 1 ~
1e-7 (paper-config MRJ sample 9, N = 2000: phi 0.63570 after 10 LPs, 0.636313 after 781,
still inflating). After ``max_lps`` LPs the stage therefore ends unconverged
(:func:`stop_reason` "max_lps") and the caller hands the packing to a method that can also
deform the cell (the Torquato-Jiao polish of :mod:`randmedia.generate.mrj`), which gains
10-50x more per LP on such a motion. The packing is then *not* certified collectively
jammed by this stage. ``max_lps`` lies above the LP count of every converging packing
measured, so it changes none of them.

Every LP is recorded (:data:`STEP_RECORD_KEYS`): the inflation sqrt(Gamma) - 1 it
predicted, the gain it realized, the rows, the displacement components at their bound
(of backbone spheres and of all) with the sum of their reduced costs (what the bound
costs in Gamma), the model-build and solve times and the solver's iteration counts.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np

from randmedia.generate import packing_lp, refuse_invalid
from randmedia.periodic import Cell, min_pair_distance, pairs_within

#: keys of the per-LP record of :func:`inflation_step`
STEP_RECORD_KEYS = ("inflation", "realized", "rows", "at_bound", "backbone_at_bound",
                    "bound_dual_sum", "max_backbone_move", "n_backbone", "build_seconds",
                    "solve_seconds", "cpu", "ipm_iterations", "crossover_iterations",
                    "simplex_iterations", "bound")


@dataclass(frozen=True)
class InflationParameters:
    """Constants of the fixed-cell iLP (module docstring; lengths in units of D)."""

    displacement_bound: float = 0.005
    final_displacement_bound: float = 0.001
    switch_inflation: float = 1.0e-5
    tolerance: float = 1.0e-10
    stall_lps: int = 5
    max_lps: int = 200
    backend: str = "highs-hipo"

    def __post_init__(self):
        checks = {
            "displacement_bound": 0 < self.displacement_bound <= 0.2,
            "final_displacement_bound": 0 < self.final_displacement_bound <= self.displacement_bound,
            "switch_inflation": 0 < self.switch_inflation < 1,
            "tolerance": 0 < self.tolerance < 1e-3,
            "stall_lps": int(self.stall_lps) == self.stall_lps and self.stall_lps >= 2,
            "max_lps": int(self.max_lps) == self.max_lps and self.max_lps >= 1,
            "backend": self.backend in packing_lp.BACKENDS and self.backend != "scipy",
        }
        refuse_invalid("inflation-LP parameters", checks, self)

    def bound(self, inflation: float) -> float:
        """Displacement bound of the next LP after an LP that predicted ``inflation``."""
        return self.displacement_bound if inflation > self.switch_inflation \
            else self.final_displacement_bound


def cutoff_for(bound: float, dim: int, diameter: float = 1.0) -> float:
    """Pairs beyond D (1 + 4 sqrt(d) l) cannot touch after a step (module docstring).

    Parameters
    ----------
    bound : float
        Displacement bound l per component, in units of D.
    dim : int
        Dimension d.
    diameter : float, optional
        Sphere diameter D (default 1).

    Returns
    -------
    float
        The pair cutoff c = D (1 + 4 sqrt(d) l), in the unit of ``diameter``.
    """
    return diameter * (1.0 + 4.0 * math.sqrt(dim) * bound)


def inflation_step(positions: np.ndarray, box: np.ndarray, bound: float, *,
                   diameter: float = 1.0, backend: str = "highs-hipo", threads: int = 1):
    """One iLP step (module docstring) with displacement bound ``bound``.

    Returns (positions, box, record): the moved packing rescaled so that its closest pair
    touches, and the per-LP record (:data:`STEP_RECORD_KEYS`).

    Parameters
    ----------
    positions : ndarray, shape (n, d)
        Sphere centres, non-overlapping, in the unit of ``diameter``.
    box : ndarray, shape (d, d)
        Periodic cell, columns the lattice vectors.
    bound : float
        Displacement bound l per component; the cutoff must not exceed the cell half width.
    diameter : float, optional
        Sphere diameter D (default 1).
    backend : str, optional
        LP solver backend of :func:`randmedia.generate.packing_lp.solve` (default "highs-hipo").
    threads : int, optional
        Solver threads (default 1).

    Returns
    -------
    positions : ndarray, shape (n, d)
        Moved, wrapped and rescaled centres.
    box : ndarray, shape (d, d)
        The rescaled cell.
    record : dict
        Keys :data:`STEP_RECORD_KEYS`.
    """
    n, dim = positions.shape
    cell = Cell(box)
    cutoff = cutoff_for(bound, dim, diameter)
    if cutoff > cell.half_width:
        raise ValueError(f"the pair cutoff D (1 + 4 sqrt(d) l) = {cutoff:.4g} for the displacement "
                         f"bound l = {bound:g} exceeds the cell half width {cell.half_width:.4g}: "
                         f"too few spheres ({n}) for this bound")
    tic = time.perf_counter()
    i, j, separation, distance = pairs_within(cell, positions, cutoff)
    matrix = packing_lp.inflation_matrix(n, i, j, separation, distance, diameter)
    cost = np.zeros(dim * n + 1)
    cost[-1] = 1.0
    lower = np.full(dim * n + 1, -bound)
    upper = np.full(dim * n + 1, bound)
    lower[:dim] = upper[:dim] = 0.0  # sphere 0 fixed: the global translation
    lower[-1], upper[-1] = 0.0, (1.0 + 2.0 * math.sqrt(dim) * bound) ** 2
    rhs = -distance / 2.0
    build = time.perf_counter() - tic
    # s = 0, Gamma = (closest distance / D)^2 is feasible: a failure is the solver's, not an
    # infeasible LP, and packing_lp.fallback decides
    solution = packing_lp.solve_or_fallback(cost, matrix, rhs, lower, upper, backend=backend,
                                            threads=threads, sense="max")
    moves = solution.x[:-1].reshape(n, dim)
    gamma = float(solution.x[-1])
    forces = solution.row_dual
    bearing = forces > 1e-9 * max(float(forces.max(initial=0.0)), 1e-300)
    rows_per_sphere = np.bincount(i[bearing], minlength=n) + np.bincount(j[bearing], minlength=n)
    backbone = rows_per_sphere >= dim + 1
    at_bound = np.abs(moves) >= bound * (1.0 - 1e-9)
    at_bound[0] = False
    bound_dual = np.abs(solution.col_dual[:-1].reshape(n, dim)) if solution.col_dual is not None \
        else np.zeros_like(moves)
    moved = cell.wrap(positions + moves)
    closest = min_pair_distance(cell, moved, cutoff)
    factor = diameter / closest
    new_positions, new_box = moved * factor, box * factor
    record = {
        "inflation": math.sqrt(max(gamma, 0.0)) - 1.0,
        "realized": closest / diameter - 1.0,
        "rows": len(i),
        "at_bound": int(at_bound.sum()),
        "backbone_at_bound": int(at_bound[backbone].sum()),
        "bound_dual_sum": float(bound_dual[at_bound].sum()),
        "max_backbone_move": float(np.abs(moves[backbone]).max()) if backbone.any() else 0.0,
        "n_backbone": int(backbone.sum()),
        "build_seconds": build,
        "solve_seconds": solution.seconds,
        "cpu": solution.cpu_seconds,
        "ipm_iterations": solution.ipm_iterations,
        "crossover_iterations": solution.crossover_iterations,
        "simplex_iterations": solution.simplex_iterations,
        "bound": bound,
        "fallback": solution.fallback_reason,
    }
    return new_positions, new_box, record


def stop_reason(inflations, phis, params: InflationParameters) -> str | None:
    """Why the iLP stage ends after these per-LP histories, or None to go on (module
    docstring): "no inflation" (the last LP predicts sqrt(Gamma) - 1 < ``tolerance``) or
    "stalled" (phi grew by at most ``tolerance`` relative over ``stall_lps`` LPs): collectively
    jammed; "max_lps" (``max_lps`` LPs done without either): unconverged, e.g. a sliding
    motion the fixed cell does not stop.

    Parameters
    ----------
    inflations : sequence of float
        Per-LP predicted inflation sqrt(Gamma) - 1, oldest first.
    phis : sequence of float
        Packing fraction after each LP, oldest first.
    params : InflationParameters
        Supplies ``tolerance``, ``stall_lps`` and ``max_lps``.

    Returns
    -------
    str or None
        "no inflation", "stalled", "max_lps", or None.
    """
    if not phis:
        return None
    if inflations[-1] < params.tolerance:
        return "no inflation"
    k = params.stall_lps
    if len(phis) > k and phis[-1] - phis[-1 - k] <= params.tolerance * phis[-1]:
        return "stalled"
    if len(phis) >= params.max_lps:
        return "max_lps"
    return None
