"""Linearized non-overlap constraints of a periodic sphere packing and their linear programs.

Shared by the sequential linear programs of :mod:`randmedia.generate.jammed` (the
fixed-cell inflation LP and the deformable-cell Torquato-Jiao LP) and the jamming test
(:mod:`randmedia.describe.jamming`).

Variables. A packing of n spheres of diameter D in the periodic cell whose
lattice vectors are the columns of ``box`` is deformed by a symmetric strain
epsilon (d(d+1)/2 components) of the cell and Cartesian displacements u_i of
the spheres; the new positions and cell are

    x_i' = (I + epsilon)(x_i + u_i),       box' = (I + epsilon) box,

so the fractional coordinates move by box^-1 u_i (Torquato & Jiao, PRE 82,
061302 (2010), Sec. III; there the displacements are written in lattice
coordinates, which is the same LP up to a change of variables). The variable
vector is ``[strain components (diagonal first, then a < b), u_0, u_1, ...]``.

Constraint of a pair. For the nearest-image separation r = x_j - x_i of a
pair at distance rho, |r'|^2 = |r + u_j - u_i + epsilon (r + u_j - u_i)|^2 is,
to first order in (u, epsilon),

    |r|^2 + 2 r.(u_j - u_i) + 2 r^T epsilon r  >=  D^2 ,

which, divided by 2 rho so that the row is in units of length along the unit
normal n = r / rho (its LP dual is then the contact force per unit pressure),
reads

    n.(u_j - u_i) + rho sum_{a<=b} w_ab n_a n_b epsilon_ab  >=  (D^2 - rho^2) / (2 rho),

with w_aa = 1 and w_ab = 2 for a < b. The objective is Tr epsilon, the first-
order relative change of the cell volume, det(I + epsilon) - 1.

What the linearization leaves out: |u_ij|^2 + 2 r^T epsilon u_ij + |epsilon
(r + u_ij)|^2 + 2 u_ij^T epsilon u_ij. Pure translations and pure strains
never make a linearly feasible pair overlap (the neglected squares are >= 0);
only the cross term 2 r^T epsilon u_ij can, by at most ~ 2 rho |epsilon| |u_ij|.
The construction removes those small overlaps by rescaling (see jammed.py).

Inflation rows (fixed cell; Artiaco, Diaz Hernandez Rojas, Parisi and
Ricci-Tersenghi, PRE 105, 055303 (2022), Eq. 2). With displacements s_i and a
common inflation factor Gamma of the squared diameter, |r + s_j - s_i|^2 >=
Gamma D^2 is linearized as rho^2 + 2 r.(s_j - s_i) >= Gamma D^2, i.e. after
division by 2 rho

    n.(s_j - s_i) - Gamma D^2 / (2 rho)  >=  -rho / 2 ,

a row that is *conservative*: the neglected term |s_j - s_i|^2 is >= 0, so any
feasible (s, Gamma) is free of overlaps with diameter sqrt(Gamma) D among the
listed pairs. Variables ``[s_0, s_1, ..., Gamma]``.
"""

from __future__ import annotations

import time
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType

import numpy as np
import scipy.sparse as sp

#: LP backends: HiGHS through ``highspy`` -- its newer interior point HiPO (``highs-hipo``:
#: augmented system, METIS ordering, no crossover: a point in the relative interior of the
#: optimal face; ``highs-hipo-vertex``: with crossover to a vertex), the older interior point
#: IPX + crossover to a vertex (``highs-ipm``) or alone (``highs-ipx``), dual simplex
#: (``highs-simplex``), the first-order primal-dual method PDLP (``highs-pdlp``: cost linear in
#: the size, feasible only to ~1e-7) -- and HiGHS' dual simplex through
#: ``scipy.optimize.linprog``. HiPO needs BLAS, METIS and AMD from the ``highspy-extras``
#: wheel of highspy's own version (pinned together in pyproject.toml); where they are
#: missing, HiGHS refuses the solver and :func:`solve` raises :class:`LPError` naming them.
BACKENDS = ("highs-hipo", "highs-hipo-vertex", "highs-ipm", "highs-ipx", "highs-simplex",
            "highs-pdlp", "scipy")
#: HiGHS options of the HiPO backends: without crossover the solution is a point of the
#: optimal face's relative interior whose active rows are closed only to the interior point's
#: tolerances; at HiGHS' defaults (1e-8, 1e-7) the TJ polish then leaves its contacts open
#: by ~1e-8 D and no packing passes the jamming test at the 1e-9 D contact gap (N = 500,
#: seed 1: certified only at 1e-6 D); at these it passes as with a vertex (same phi to 4e-11)
HIPO_OPTIONS: Mapping[str, float] = MappingProxyType({
    "ipm_optimality_tolerance": 1e-12, "primal_feasibility_tolerance": 1e-10,
    "dual_feasibility_tolerance": 1e-10})
#: HiGHS options of IPX + crossover (``highs-ipm``): at HiGHS' default primal feasibility
#: tolerance (1e-7) the crossover's vertex may violate a row by ~2e-9 D (the N = 2000 packing
#: of record/packings/mrj2016_uncertified: a step applied there overlaps a pair by 1.8e-9 D and
#: its rescaling opens every contact by as much); the dual simplex's rows hold to 1e-11
IPM_OPTIONS: Mapping[str, float] = MappingProxyType({
    "primal_feasibility_tolerance": 1e-10, "dual_feasibility_tolerance": 1e-10})
#: the interior-point backends whose solution is not a vertex (no crossover)
INTERIOR_BACKENDS = ("highs-hipo", "highs-ipx")


def _highspy_version() -> str:
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("highspy")
    except PackageNotFoundError:  # pragma: no cover - highspy imported from a source tree
        return "unknown"


class LPError(RuntimeError):
    """An LP of a packing did not solve to optimality."""


def strain_components(dim: int) -> list[tuple[int, int]]:
    """(a, b) of each strain variable: the diagonal first, then a < b in row order."""
    if dim not in (2, 3):
        raise ValueError(f"dimension must be 2 or 3, got {dim}")
    return [(a, a) for a in range(dim)] + [(a, b) for a in range(dim) for b in range(a + 1, dim)]


def n_strain(dim: int) -> int:
    return dim * (dim + 1) // 2


def strain_matrix(values: np.ndarray, dim: int) -> np.ndarray:
    """The symmetric d x d strain from its d(d+1)/2 LP variables."""
    eps = np.zeros((dim, dim))
    for k, (a, b) in enumerate(strain_components(dim)):
        eps[a, b] = eps[b, a] = values[k]
    return eps


def constraint_matrix(n: int, i: np.ndarray, j: np.ndarray, separation: np.ndarray,
                      distance: np.ndarray, *, strain: bool = True) -> sp.csr_matrix:
    """Rows n.(u_j - u_i) + rho sum w_ab n_a n_b eps_ab of every pair (i, j) (module docstring).

    ``separation[m]`` is the nearest-image vector from sphere i[m] to sphere j[m]
    and ``distance[m]`` its length. Columns: the strain components (omitted when
    ``strain`` is False), then the d displacement components of each sphere.

    Parameters
    ----------
    n : int
        Number of spheres.
    i, j : ndarray of int, shape (m,)
        Sphere indices of the m listed pairs.
    separation : ndarray, shape (m, d)
        Nearest-image vector from sphere i[m] to sphere j[m] (unit of D).
    distance : ndarray, shape (m,)
        Its length rho.
    strain : bool, optional
        Include the d(d+1)/2 strain columns (default True).

    Returns
    -------
    scipy.sparse.csr_matrix, shape (m, ns + d n)
        One row per pair; ns = d(d+1)/2 if ``strain`` else 0.
    """
    separation = np.asarray(separation, dtype=float)
    m, dim = separation.shape
    normal = separation / distance[:, None]
    components = strain_components(dim) if strain else []
    ns = len(components)
    width = ns + 2 * dim
    cols = np.empty((m, width), dtype=np.int64)
    vals = np.empty((m, width))
    for k, (a, b) in enumerate(components):
        cols[:, k] = k
        vals[:, k] = distance * normal[:, a] * normal[:, b] * (1.0 if a == b else 2.0)
    for a in range(dim):
        cols[:, ns + a] = ns + dim * i + a
        vals[:, ns + a] = -normal[:, a]
        cols[:, ns + dim + a] = ns + dim * j + a
        vals[:, ns + dim + a] = normal[:, a]
    rows = np.repeat(np.arange(m), width)
    return sp.csr_matrix((vals.ravel(), (rows, cols.ravel())), shape=(m, ns + dim * n))


def inflation_matrix(n: int, i: np.ndarray, j: np.ndarray, separation: np.ndarray,
                     distance: np.ndarray, diameter: float = 1.0) -> sp.csr_matrix:
    """Rows n.(s_j - s_i) - Gamma D^2 / (2 rho) of every pair (module docstring): the
    fixed-cell rows of :func:`constraint_matrix` plus the column of Gamma.

    Columns: the d displacement components of each sphere, then Gamma. The right-hand
    side is ``-distance / 2``.

    Parameters
    ----------
    n : int
        Number of spheres.
    i, j : ndarray of int, shape (m,)
        Sphere indices of the m listed pairs.
    separation : ndarray, shape (m, d)
        Nearest-image vector from sphere i[m] to sphere j[m] (unit of D).
    distance : ndarray, shape (m,)
        Its length rho.
    diameter : float, optional
        Sphere diameter D (default 1).

    Returns
    -------
    scipy.sparse.csr_matrix, shape (m, d n + 1)
        One row per pair.
    """
    displacement = constraint_matrix(n, i, j, separation, distance, strain=False)
    gamma = sp.csr_matrix((-diameter**2 / (2.0 * np.asarray(distance, dtype=float)))[:, None])
    return sp.hstack([displacement, gamma], format="csr")


def gap_bound(distance: np.ndarray, diameter: float) -> np.ndarray:
    """Right-hand side (D^2 - rho^2) / (2 rho) of each pair's constraint (<= 0 without overlap)."""
    return (diameter**2 - distance**2) / (2.0 * distance)


@dataclass
class LPSolution:
    """Primal solution x, row duals (>= 0: force per unit pressure on each row), column
    duals (reduced costs: the price of each variable's bound), objective and cost."""

    x: np.ndarray
    row_dual: np.ndarray
    objective: float
    seconds: float
    iterations: int
    cpu_seconds: float = 0.0
    col_dual: np.ndarray | None = None
    ipm_iterations: int = 0
    crossover_iterations: int = 0
    simplex_iterations: int = 0


def fallback(backend: str) -> str:
    """The backend that decides an LP ``backend`` failed to solve although it is feasible (a
    numerical failure): IPX + crossover after HiPO, the dual simplex after anything else."""
    return "highs-ipm" if backend.startswith("highs-hipo") else "highs-simplex"


def check_backends(*backends: str) -> None:
    """Refuse, before any work, a backend that is unknown or that this highspy cannot run
    (HiPO without the matching ``highspy-extras``): one tiny LP per HiPO backend."""
    for backend in backends:
        if backend not in BACKENDS:
            raise ValueError(f"unknown LP backend {backend!r}; expected one of {BACKENDS}")
        if backend.startswith("highs-hipo"):
            solve(np.array([1.0]), sp.csr_matrix(np.ones((1, 1))), np.array([1.0]), np.array([0.0]),
                  np.array([2.0]), backend=backend)


def solve(cost: np.ndarray, matrix: sp.spmatrix, row_lower: np.ndarray, col_lower: np.ndarray,
          col_upper: np.ndarray, *, backend: str = "highs-ipm", threads: int = 1,
          sense: str = "min") -> LPSolution:
    """Optimize cost.x subject to matrix x >= row_lower and col_lower <= x <= col_upper.

    ``backend``: one of :data:`BACKENDS`. ``threads`` = 1 keeps the
    solution bit-reproducible. Raises :class:`LPError` unless optimal.

    Parameters
    ----------
    cost : ndarray, shape (k,)
        Objective coefficients.
    matrix : scipy.sparse matrix, shape (m, k)
        Constraint rows.
    row_lower : ndarray, shape (m,)
        Lower bounds of the rows (no upper bounds).
    col_lower, col_upper : ndarray, shape (k,)
        Bounds of the variables.
    backend : str, optional
        Solver (default "highs-ipm").
    threads : int, optional
        Solver threads (default 1).
    sense : str, optional
        "min" (default) or "max".

    Returns
    -------
    LPSolution
        Primal x, row duals, column duals (None for the scipy backend), objective (of the
        given sense), wall and CPU seconds, iteration counts.
    """
    if backend not in BACKENDS:
        raise ValueError(f"unknown LP backend {backend!r}; expected one of {BACKENDS}")
    if sense not in ("min", "max"):
        raise ValueError(f"sense must be 'min' or 'max', got {sense!r}")
    sign = 1.0 if sense == "min" else -1.0
    cost = sign * np.asarray(cost, dtype=float)
    tic, cpu = time.perf_counter(), time.process_time()
    if backend == "scipy":
        from scipy.optimize import linprog

        res = linprog(cost, A_ub=-sp.csr_matrix(matrix), b_ub=-np.asarray(row_lower, dtype=float),
                      bounds=np.column_stack([col_lower, col_upper]), method="highs-ds")
        if res.status != 0:
            raise LPError(f"LP not solved to optimality: {res.message}")
        return LPSolution(res.x, -res.ineqlin.marginals, sign * res.fun,
                          time.perf_counter() - tic, int(res.nit), time.process_time() - cpu)
    import highspy

    highs = highspy.Highs()
    highs.setOptionValue("output_flag", False)
    highs.setOptionValue("threads", int(threads))
    if backend in ("highs-ipm", "highs-ipx"):
        highs.setOptionValue("solver", "ipx")
        highs.setOptionValue("run_crossover", "on" if backend == "highs-ipm" else "off")
        if backend == "highs-ipm":
            for name, value in IPM_OPTIONS.items():
                highs.setOptionValue(name, value)
    elif backend in ("highs-hipo", "highs-hipo-vertex"):
        # HiGHS' default hipo_system "choose" picks the normal equations for these LPs, which
        # the dense column (Gamma, or the strain of TJ) fills: 96-213 s instead of 2.5-4 s per
        # LP at N = 2000 (docs/mrj2016.md, "LP solver")
        highs.setOptionValue("solver", "hipo")
        highs.setOptionValue("hipo_system", "augmented")
        highs.setOptionValue("hipo_ordering", "metis")
        highs.setOptionValue("run_crossover", "on" if backend == "highs-hipo-vertex" else "off")
        for name, value in HIPO_OPTIONS.items():
            highs.setOptionValue(name, value)
    elif backend == "highs-pdlp":
        highs.setOptionValue("solver", "pdlp")
    else:
        highs.setOptionValue("solver", "simplex")
        highs.setOptionValue("simplex_strategy", 1)  # dual simplex
    lp = highspy.HighsLp()
    csc = sp.csc_matrix(matrix)
    lp.num_col_ = csc.shape[1]
    lp.num_row_ = csc.shape[0]
    lp.col_cost_ = cost
    lp.col_lower_ = np.asarray(col_lower, dtype=float)
    lp.col_upper_ = np.asarray(col_upper, dtype=float)
    lp.row_lower_ = np.asarray(row_lower, dtype=float)
    lp.row_upper_ = np.full(csc.shape[0], highspy.kHighsInf)
    lp.a_matrix_.format_ = highspy.MatrixFormat.kColwise
    lp.a_matrix_.start_ = csc.indptr
    lp.a_matrix_.index_ = csc.indices
    lp.a_matrix_.value_ = csc.data
    highs.passModel(lp)
    run_status = highs.run()
    status = highs.getModelStatus()
    if status != highspy.HighsModelStatus.kOptimal:
        unavailable = (backend.startswith("highs-hipo") and run_status == highspy.HighsStatus.kError
                       and status == highspy.HighsModelStatus.kNotset)
        raise LPError(
            f"LP backend {backend!r}: HiPO is unavailable in this highspy build (install "
            f"highspy-extras of highspy's own version, {_highspy_version()}; both are pinned in "
            f"pyproject.toml)" if unavailable else
            f"LP not solved to optimality ({backend}): {highs.modelStatusToString(status)}")
    solution = highs.getSolution()
    info = highs.getInfo()
    ipm, crossover = int(info.ipm_iteration_count), int(info.crossover_iteration_count)
    simplex, pdlp = int(info.simplex_iteration_count), int(info.pdlp_iteration_count)
    return LPSolution(np.array(solution.col_value), np.array(solution.row_dual),
                      sign * float(info.objective_function_value), time.perf_counter() - tic,
                      ipm + simplex + pdlp, time.process_time() - cpu,
                      col_dual=sign * np.array(solution.col_dual), ipm_iterations=ipm + pdlp,
                      crossover_iterations=crossover, simplex_iterations=simplex)
