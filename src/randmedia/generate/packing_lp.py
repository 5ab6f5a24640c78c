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
from dataclasses import dataclass, replace
from types import MappingProxyType

import numpy as np
import scipy.sparse as sp

#: LP backends: HiGHS through ``highspy`` -- its newer interior point HiPO (``highs-hipo``:
#: augmented system, METIS ordering, no crossover: a point in the relative interior of the
#: optimal face; ``highs-hipo-vertex``: with crossover to a vertex), the older interior point
#: IPX + crossover to a vertex (``highs-ipm``) or alone (``highs-ipx``), dual simplex
#: (``highs-simplex``; in a sequence of LPs warm-started from the previous one's basis,
#: :func:`carry_basis`), the first-order primal-dual method PDLP (``highs-pdlp``: cost linear in
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
#: HiGHS options of the vertex backends, IPX + crossover (``highs-ipm``) and the dual simplex
#: (``highs-simplex``): at HiGHS' default primal feasibility tolerance (1e-7) the crossover's
#: vertex may violate a row by ~2e-9 D (the N = 2000 packing of
#: record/packings/mrj2016_uncertified: a step applied there overlaps a pair by 1.8e-9 D and
#: its rescaling opens every contact by as much), and a warm-started dual simplex by ~1e-7 D
#: (a polish at N = 2000 then ended with every contact open by more than 1e-9 D)
VERTEX_OPTIONS: Mapping[str, float] = MappingProxyType({
    "primal_feasibility_tolerance": 1e-10, "dual_feasibility_tolerance": 1e-10})
#: the interior-point backends whose solution is not a vertex (no crossover)
INTERIOR_BACKENDS = ("highs-hipo", "highs-ipx")
#: the backend that starts from the basis of the previous LP of a sequence when one is
#: given (:func:`carry_basis`): the dual simplex
WARM_BACKENDS = ("highs-simplex",)


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
    #: HiGHS' basis status of every column and row at a vertex (``HighsBasisStatus`` codes:
    #: 0 lower, 1 basic, 2 upper, 3 zero, 4 nonbasic); None without a basis
    col_status: np.ndarray | None = None
    row_status: np.ndarray | None = None
    #: why ``backend`` failed when :func:`solve_or_fallback` solved the LP with
    #: :func:`fallback` instead ("" when it did not)
    fallback_reason: str = ""


@dataclass(frozen=True)
class LPBasis:
    """The optimal basis of one LP of a sequence, its rows named by ``row_keys`` (a packing
    LP: i n + j of the pair (i, j) of each row), so that the next LP, whose rows are the pairs
    then listed, can start from it (:func:`carry_basis`)."""

    col_status: np.ndarray
    row_status: np.ndarray
    row_keys: np.ndarray


_BASIC = 1  # HighsBasisStatus.kBasic


def carry_basis(previous: LPBasis, row_keys: np.ndarray, n_cols: int) -> tuple[np.ndarray, np.ndarray]:
    """The start basis of an LP with the rows ``row_keys`` and ``n_cols`` columns from the
    optimal basis of the previous LP of the sequence: a row keeps its status where its key
    was a row before, a new row enters basic (its slack basic: the pair not in contact);
    the columns keep theirs. The count of basic variables may then differ from the row
    count (an "alien" basis): HiGHS repairs it before its dual simplex starts."""
    if len(previous.col_status) != n_cols:
        raise ValueError(f"carried basis has {len(previous.col_status)} columns, the LP {n_cols}")
    order = np.argsort(previous.row_keys, kind="stable")
    keys = previous.row_keys[order]
    where = np.clip(np.searchsorted(keys, row_keys), 0, max(len(keys) - 1, 0))
    found = (keys[where] == row_keys) if len(keys) else np.zeros(len(row_keys), bool)
    rows = np.full(len(row_keys), _BASIC, dtype=np.int8)
    rows[found] = previous.row_status[order][where[found]]
    return previous.col_status.astype(np.int8), rows


def fallback(backend: str) -> str:
    """The backend that decides an LP ``backend`` failed to solve although it is feasible (a
    numerical failure, or a warm-started dual simplex past :func:`warm_iteration_limit`):
    IPX + crossover after HiPO and the dual simplex, the dual simplex after anything else."""
    return "highs-ipm" if backend.startswith("highs-hipo") or backend in WARM_BACKENDS else "highs-simplex"


def solve_or_fallback(cost: np.ndarray, matrix: sp.spmatrix, row_lower: np.ndarray,
                      col_lower: np.ndarray, col_upper: np.ndarray, *, backend: str,
                      **options) -> LPSolution:
    """:func:`solve` for an LP known to be feasible (x = 0 is, in every packing LP): when
    ``backend`` fails (:class:`LPError`: a numerical failure, or a warm start past its limit),
    the LP is solved again by :func:`fallback` (``backend``), and the solution's
    ``fallback_reason`` says why -- the caller logs it, since the retry can cost far more (IPX +
    crossover: ~20 min at N = 10 000 where HiPO takes ~40 s). ``options``: those of
    :func:`solve` (a ``start_basis`` is given to the first attempt only)."""
    try:
        return solve(cost, matrix, row_lower, col_lower, col_upper, backend=backend, **options)
    except LPError as error:
        options.pop("start_basis", None)
        second = fallback(backend)
        solution = solve(cost, matrix, row_lower, col_lower, col_upper, backend=second, **options)
        return replace(solution, fallback_reason=f"{error}; solved by {second}")


def warm_iteration_limit(n_rows: int) -> int:
    """Iterations a warm-started dual simplex may take before IPX + crossover solves the LP
    instead (:func:`fallback`): half the row count. After a large step the carried basis is a
    poor start (measured at N = 2000, ~9000 rows: 62 000 iterations, 209 s, where IPX +
    crossover takes ~9 s); an LP near the previous one needs tens to hundreds."""
    return max(100, n_rows // 2)


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
          sense: str = "min", start_basis: tuple[np.ndarray, np.ndarray] | None = None) -> LPSolution:
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
    start_basis : (col_status, row_status), optional
        A basis to start from (:func:`carry_basis`); used by the backends of
        :data:`WARM_BACKENDS` only.

    Returns
    -------
    LPSolution
        Primal x, row duals, column duals (None for the scipy backend), objective (of the
        given sense), wall and CPU seconds, iteration counts, and the basis of a vertex
        backend (``col_status``, ``row_status``).
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
            for name, value in VERTEX_OPTIONS.items():
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
        for name, value in VERTEX_OPTIONS.items():
            highs.setOptionValue(name, value)
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
    if start_basis is not None and backend in WARM_BACKENDS:
        basis = highspy.HighsBasis()
        basis.col_status = [highspy.HighsBasisStatus(int(v)) for v in start_basis[0]]
        basis.row_status = [highspy.HighsBasisStatus(int(v)) for v in start_basis[1]]
        basis.valid, basis.alien = True, True
        highs.setBasis(basis)
        highs.setOptionValue("simplex_iteration_limit", warm_iteration_limit(csc.shape[0]))
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
    col_status = row_status = None
    if backend not in INTERIOR_BACKENDS:
        final_basis = highs.getBasis()
        if final_basis.valid:
            col_status = np.array([int(v) for v in final_basis.col_status], dtype=np.int8)
            row_status = np.array([int(v) for v in final_basis.row_status], dtype=np.int8)
    simplex, pdlp = int(info.simplex_iteration_count), int(info.pdlp_iteration_count)
    return LPSolution(np.array(solution.col_value), np.array(solution.row_dual),
                      sign * float(info.objective_function_value), time.perf_counter() - tic,
                      ipm + simplex + pdlp, time.process_time() - cpu,
                      col_dual=sign * np.array(solution.col_dual), ipm_iterations=ipm + pdlp,
                      crossover_iterations=crossover, simplex_iterations=simplex,
                      col_status=col_status, row_status=row_status)
