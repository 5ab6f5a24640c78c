"""Contacts, rattlers, isostaticity and the LP jamming test of periodic sphere packings.

Contacts. A pair is in contact when its gap (centre distance - D) is below
``gap_tolerance`` (a gap test; default 1e-9 D). For converged Torquato-Jiao
packings the gaps are bimodal: contacts close to ~1e-14 D, the smallest
non-contact gaps are ~1e-6 D and larger, so any tolerance between ~1e-11 and
~1e-7 gives the same network (the tests check this).

Rattlers (Donev, Torquato, Stillinger & Connelly, J. Comput. Phys. 197, 139
(2004); Atkinson, Stillinger & Torquato, PRE 88, 062208 (2013)): spheres that
are not held by the contact network. Found by iterating, until nothing changes,
the removal of every sphere that has fewer than d + 1 contacts with non-rattlers
or whose contact normals lie in an open hemisphere (then it can move away from
all its contacts: a tiny LP per sphere, max t s.t. n_k . v + t <= 0, |v_a| <= 1).

Isostaticity. The backbone (non-rattlers, N_b spheres, M contacts) of a strictly
jammed packing in a deformable periodic cell has d (N_b - 1) translational
degrees of freedom (the global translation removed) plus d (d + 1) / 2 strain
components, and it is held only if the M contact constraints together with the
volume constraint Tr epsilon <= 0 positively span that space, which needs

    M >= d (N_b - 1) + d (d + 1) / 2            (3D: M >= 3 N_b + 3).

Equality is exact isostaticity; then the mean contact number of the backbone is
z = 2 M / N_b = 2 d + (d (d + 1) - 2 d) / N_b (6 + 6 / N_b in 3D).
:func:`isostatic_excess` returns M minus the bound.

Jamming test (Donev et al. 2004, with the deformable cell of Torquato & Jiao
2010). The packing is strictly jammed if the only first-order motion
x = (u, epsilon) of the backbone that keeps every contact closed or opening,
n_k . (u_j - u_i) + rho n_k^T epsilon n_k >= 0, without increasing the volume,
Tr epsilon <= 0, is the trivial one (the displacement of one backbone sphere is
fixed: gauge). With B the matrix of those M + 1 rows this cone is
K = {x : B x >= 0}, and (Stiemke's alternative) K = {0} exactly when

  (a) B has full column rank n = d (N_b - 1) + d (d + 1) / 2 (no floppy mode), and
  (b) some strictly positive y has B^T y = 0 -- a self stress with positive force on
      every contact and positive pressure.

(b) is the LP min Tr epsilon over K (bounds |x| <= 1): its optimum must be 0 (the
volume cannot be lowered) and its duals are the contact forces per unit pressure;
HiGHS' interior point method (no crossover) converges to a strictly complementary
solution, so it finds strictly positive forces whenever they exist. (a) is checked
by the smallest eigenvalue of B^T B (inverse iteration on a sparse LU), which must
exceed ``rank_tolerance`` times the largest. ``load_test=True`` adds Donev's
direct LP test: maximize b.x and -b.x over K within the bounds for random b; a
non-zero ray of K has b.ray != 0 with probability one, so K = {0} iff every such
optimum is 0 (slower: the LPs are degenerate; used on small packings to
cross-check the certificate).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from randmedia.generate import packing_lp
from randmedia.periodic import Cell, pairs_within


@dataclass
class ContactNetwork:
    """Pairs (i < j) at gap < tolerance: separation vectors (i -> nearest image of j), gaps."""

    i: np.ndarray
    j: np.ndarray
    separation: np.ndarray
    gap: np.ndarray
    n_particles: int
    gap_tolerance: float

    @property
    def pairs(self) -> np.ndarray:
        return np.column_stack([self.i, self.j])

    def subset(self, keep: np.ndarray) -> "ContactNetwork":
        return ContactNetwork(self.i[keep], self.j[keep], self.separation[keep], self.gap[keep],
                              self.n_particles, self.gap_tolerance)


def contact_network(positions, box, diameter: float = 1.0,
                    gap_tolerance: float = 1e-9) -> ContactNetwork:
    """Every pair whose gap (distance - D) is below ``gap_tolerance`` D (a fraction of D).

    Parameters
    ----------
    positions : array_like, shape (n, d)
        Sphere centres, in the units of ``box``.
    box : array_like, shape (d, d)
        Periodic cell; columns are the lattice vectors.
    diameter : float, optional
        Sphere diameter D.
    gap_tolerance : float, optional
        Contact threshold as a fraction of D, in (0, 0.1): contact when distance < D (1 + tol).

    Returns
    -------
    ContactNetwork
        Contacting pairs; ``gap`` and ``gap_tolerance`` there are in the units of ``box``.
    """
    positions = np.asarray(positions, dtype=float)
    if not 0 < gap_tolerance < 0.1:
        raise ValueError(f"gap_tolerance must lie in (0, 0.1) D, got {gap_tolerance}")
    cell = Cell(box)
    cutoff = diameter * (1 + gap_tolerance)
    i, j, separation, distance = pairs_within(cell, positions, cutoff)
    return ContactNetwork(i, j, separation, distance - diameter, len(positions),
                          gap_tolerance * diameter)


def gap_histogram(positions, box, diameter: float = 1.0, decades=(-16, -1)):
    """Counts of pair gaps per decade, log10(gap/D) in [k, k+1) for k in decades (plus
    gaps below the first decade in the first bin): shows the contact / non-contact gap.

    Parameters
    ----------
    positions : array_like, shape (n, d)
        Sphere centres, in the units of ``box``.
    box : array_like, shape (d, d)
        Periodic cell; columns are the lattice vectors.
    diameter : float, optional
        Sphere diameter D.
    decades : tuple of int, optional
        (first, last) exponent of the gap range; pairs with gap / D <= 10^last are counted.

    Returns
    -------
    decade : ndarray of int
        Lower exponent k of each bin.
    counts : ndarray of int
        Pairs with log10(gap / D) in [k, k + 1) (the last bin also holds gap = 10^last D).
    """
    cell = Cell(box)
    _, _, _, distance = pairs_within(cell, np.asarray(positions, dtype=float),
                                     diameter * (1 + 10.0 ** decades[1]))
    gap = np.maximum((distance - diameter) / diameter, 10.0 ** decades[0])
    edges = np.arange(decades[0], decades[1] + 1)
    counts, _ = np.histogram(np.log10(gap), bins=edges)
    return edges[:-1], counts


def _locally_free(normals: np.ndarray) -> bool:
    """Can a sphere with these unit contact normals move away from all of them?
    (max t s.t. n_k . v + t <= 0, |v_a| <= 1, t <= 1; free if t > 1e-9)."""
    k, dim = normals.shape
    if k <= dim:
        return True
    matrix = np.hstack([-normals, -np.ones((k, 1))])  # -n.v - t >= 0
    cost = np.zeros(dim + 1)
    cost[-1] = 1.0
    lower = np.r_[-np.ones(dim), -1.0]
    upper = np.r_[np.ones(dim), 1.0]
    solution = packing_lp.solve(cost, matrix, np.zeros(k), lower, upper, backend="highs-simplex",
                                sense="max")
    return solution.objective > 1e-9


def find_rattlers(network: ContactNetwork) -> np.ndarray:
    """Boolean mask of rattlers (module docstring: < d+1 contacts, or all contact
    normals in an open hemisphere; iterated on the remaining network)."""
    n = network.n_particles
    dim = network.separation.shape[1] if network.separation.size else 3
    rattler = np.zeros(n, dtype=bool)
    normals = network.separation / np.linalg.norm(network.separation, axis=1)[:, None] \
        if network.separation.size else network.separation
    checked_free = np.zeros(n, dtype=bool)  # hemisphere test passed with the current contacts
    while True:
        alive = ~rattler[network.i] & ~rattler[network.j]
        count = (np.bincount(network.i[alive], minlength=n)
                 + np.bincount(network.j[alive], minlength=n))
        new = ~rattler & (count < dim + 1)
        if not new.any():
            for s in np.flatnonzero(~rattler & ~checked_free):
                mine = alive & ((network.i == s) | (network.j == s))
                own = np.where((network.i[mine] == s)[:, None], normals[mine], -normals[mine])
                if _locally_free(own):
                    new[s] = True
                else:
                    checked_free[s] = True
        if not new.any():
            return rattler
        rattler |= new
        # neighbours of removed spheres must be re-checked
        touched = np.zeros(n, dtype=bool)
        gone = alive & (new[network.i] | new[network.j])
        touched[network.i[gone]] = True
        touched[network.j[gone]] = True
        checked_free &= ~touched


def isostatic_bound(n_backbone: int, dim: int) -> int:
    """d (N_b - 1) + d (d + 1) / 2: the fewest contacts that can hold N_b spheres and the cell."""
    return dim * (n_backbone - 1) + dim * (dim + 1) // 2


def isostatic_excess(n_contacts: int, n_backbone: int, dim: int) -> int:
    """M - [d (N_b - 1) + d (d + 1) / 2]: 0 for an exactly isostatic backbone.

    Parameters
    ----------
    n_contacts : int
        Backbone contacts M.
    n_backbone : int
        Non-rattler spheres N_b.
    dim : int
        Dimension d.

    Returns
    -------
    int
        M minus the isostatic bound (:func:`isostatic_bound`).
    """
    return int(n_contacts) - isostatic_bound(n_backbone, dim)


@dataclass
class JammingAnalysis:
    """Contacts and rattlers of a packing and the result of the LP jamming test."""

    network: ContactNetwork          # every contact (gap test)
    rattler: np.ndarray              # bool per sphere
    backbone_contacts: np.ndarray    # bool per contact: both spheres non-rattlers
    forces: np.ndarray               # per contact: force per unit pressure (0 off the backbone)
    jammed: bool
    max_motion: float                # largest |x| of a random-load LP (0 if jammed or not run)
    min_trace: float                 # min Tr epsilon over the cone (0 when jammed)
    rank_ratio: float                # lambda_min / lambda_max of B^T B (> 0: no floppy mode)
    #: the cone LP's optimal motion (strain d x d, displacements n x d; rattlers 0): where
    #: min Tr epsilon < 0, a first-order motion that keeps every backbone contact closed or
    #: opening and lowers the volume (:func:`randmedia.generate.jammed.leave_vertex`)
    motion: tuple[np.ndarray, np.ndarray] | None = None

    @property
    def n_backbone(self) -> int:
        return int((~self.rattler).sum())

    @property
    def n_backbone_contacts(self) -> int:
        return int(self.backbone_contacts.sum())

    @property
    def rattler_fraction(self) -> float:
        return float(self.rattler.mean())

    @property
    def z_mean_backbone(self) -> float:
        """Mean contact number of the non-rattlers, 2 M / N_b."""
        return 2.0 * self.n_backbone_contacts / max(self.n_backbone, 1)

    @property
    def dim(self) -> int:
        return self.network.separation.shape[1]

    @property
    def isostatic_excess(self) -> int:
        return isostatic_excess(self.n_backbone_contacts, self.n_backbone, self.dim)

    @property
    def n_force_bearing(self) -> int:
        return int((self.forces > 1e-9 * max(self.forces.max(initial=0.0), 1e-300)).sum())


def _smallest_eigenvalue_ratio(matrix, iterations: int = 30) -> float:
    """lambda_min / lambda_max of B^T B (0 if it is numerically singular): power iteration for
    lambda_max, inverse iteration with a sparse LU of B^T B + 1e-14 lambda_max I for lambda_min.
    The LU orders B^T B's columns symmetrically (minimum degree on A^T + A): at N = 10 000 (a
    29 724-column B) it takes 194 CPU s and 1.7e8 nonzeros of L + U, against 947 s and 3.3e8
    with SuperLU's default COLAMD (docs/mrj2016.md, "N = 10 000").

    Resolution (docs/mrj2016.md): a floppy mode (two backbone contacts removed from a rigid
    packing) gives 0 - 3e-19; rigid packings give 9e-8 (N = 100) down to ~1e-11 (N = 2000)."""
    import scipy.sparse as sp
    from scipy.sparse.linalg import splu

    normal = (matrix.T @ matrix).tocsc()
    n = normal.shape[0]
    rng = np.random.default_rng(12345)
    vector = rng.standard_normal(n)
    for _ in range(iterations):  # power iteration: lambda_max
        vector = normal @ vector
        vector /= np.linalg.norm(vector)
    lam_max = float(vector @ (normal @ vector))
    shift = 1e-14 * lam_max
    try:
        lu = splu((normal + shift * sp.identity(n, format="csc")).tocsc(), permc_spec="MMD_AT_PLUS_A")
    except RuntimeError:  # exactly singular
        return 0.0
    vector = rng.standard_normal(n)
    for _ in range(iterations):  # inverse iteration: lambda_min
        vector = lu.solve(vector)
        norm = np.linalg.norm(vector)
        if not np.isfinite(norm) or norm == 0:
            return 0.0
        vector /= norm
    lam_min = float(vector @ (normal @ vector))
    return max(lam_min, 0.0) / lam_max


def analyse(positions, box, diameter: float = 1.0, *, gap_tolerance: float = 1e-9,
            rank_tolerance: float = 1e-12, force_tolerance: float = 1e-7,
            motion_tolerance: float = 1e-6, load_test: bool = False, n_loads: int = 2,
            seed: int = 0) -> JammingAnalysis:
    """Contacts, rattlers and the strict-jamming test (module docstring).

    Jammed when min Tr epsilon over the cone is > -``motion_tolerance``, every
    backbone contact carries a force > ``force_tolerance`` x the mean force, and
    lambda_min / lambda_max of B^T B > ``rank_tolerance`` (and, with ``load_test``,
    no random load moves anything by more than ``motion_tolerance``).

    Parameters
    ----------
    positions : array_like, shape (n, d)
        Sphere centres, in the units of ``box``.
    box : array_like, shape (d, d)
        Periodic cell; columns are the lattice vectors.
    diameter : float, optional
        Sphere diameter D.
    gap_tolerance : float, optional
        Contact threshold as a fraction of D (:func:`contact_network`).
    rank_tolerance : float, optional
        Lower bound on lambda_min / lambda_max of B^T B.
    force_tolerance : float, optional
        Every backbone force must exceed this fraction of the mean force.
    motion_tolerance : float, optional
        Bound on -min Tr epsilon and on the load-test motion.
    load_test : bool, optional
        Also run Donev's random-load LPs.
    n_loads : int, optional
        Random loads of the load test (each maximized and minimized).
    seed : int, optional
        Seed of the random loads.

    Returns
    -------
    JammingAnalysis
        Contacts, rattlers, forces per unit pressure and the test's outcome; fewer than 2
        backbone spheres: not jammed.
    """
    import scipy.sparse as sp

    positions = np.asarray(positions, dtype=float)
    n, dim = positions.shape
    network = contact_network(positions, box, diameter, gap_tolerance)
    rattler = find_rattlers(network)
    on_backbone = ~rattler[network.i] & ~rattler[network.j]
    forces = np.zeros(len(network.i))
    backbone = np.flatnonzero(~rattler)
    if backbone.size < 2:
        return JammingAnalysis(network, rattler, on_backbone, forces, False, np.inf, -np.inf, 0.0)
    index = np.full(n, -1, dtype=np.int64)
    index[backbone] = np.arange(backbone.size)
    contacts = network.subset(on_backbone)
    distance = np.linalg.norm(contacts.separation, axis=1)
    matrix = packing_lp.constraint_matrix(backbone.size, index[contacts.i], index[contacts.j],
                                          contacts.separation, distance)
    ns = packing_lp.n_strain(dim)
    gauge = np.ones(matrix.shape[1], dtype=bool)
    gauge[ns:ns + dim] = False  # the first backbone sphere does not move
    volume_row = np.zeros((1, matrix.shape[1]))
    volume_row[0, :dim] = -1.0
    cone = sp.vstack([matrix, sp.csr_matrix(volume_row)]).tocsr()[:, np.flatnonzero(gauge)]
    lower_rows = np.zeros(cone.shape[0])
    upper = np.ones(cone.shape[1])
    trace_cost = np.zeros(cone.shape[1])
    trace_cost[:dim] = 1.0
    trace = packing_lp.solve(trace_cost, cone, lower_rows, -upper, upper, backend="highs-ipx")
    # duals: A^T y = (1 + y_volume) grad Tr eps, so the forces per unit pressure are
    # y / (1 + y_volume) (then sum_k f_k rho_k n_k n_k^T = I)
    forces[on_backbone] = trace.row_dual[:-1] / (1.0 + trace.row_dual[-1])
    backbone_forces = forces[on_backbone]
    positive = backbone_forces.size > 0 and bool(
        (backbone_forces > force_tolerance * backbone_forces.mean()).all())
    rank_ratio = _smallest_eigenvalue_ratio(cone)
    max_motion = 0.0
    if load_test:
        rng = np.random.default_rng(seed)
        for _ in range(n_loads):
            load = rng.standard_normal(cone.shape[1])
            for sense in ("max", "min"):
                solution = packing_lp.solve(load, cone, lower_rows, -upper, upper,
                                            backend="highs-ipm", sense=sense)
                max_motion = max(max_motion, float(np.abs(solution.x).max()))
    jammed = (trace.objective > -motion_tolerance and positive and rank_ratio > rank_tolerance
              and max_motion < motion_tolerance)
    full = np.zeros(matrix.shape[1])
    full[np.flatnonzero(gauge)] = trace.x
    displacement = np.zeros((n, dim))
    displacement[backbone] = full[ns:].reshape(-1, dim)
    motion = (packing_lp.strain_matrix(full[:ns], dim), displacement)
    return JammingAnalysis(network, rattler, on_backbone, forces, bool(jammed), max_motion,
                           float(trace.objective), rank_ratio, motion)


# --------------------------------------------------------------------------- summaries

#: attributes of a packing file that the summary table reports
PACKING_ATTRS = ("system", "sample", "n_particles", "phi", "z_mean_nonrattlers", "rattler_fraction",
                 "n_contacts", "n_backbone_contacts", "isostatic_excess", "jammed", "Q6",
                 "crystal_fraction", "min_gap", "min_noncontact_gap", "n_lp")

#: columns averaged per system (mean and SEM over packings)
SUMMARY_COLUMNS = ("phi", "z_mean_nonrattlers", "rattler_fraction", "isostatic_excess", "jammed",
                   "Q6", "crystal_fraction", "n_lp")


def summary_table(records):
    """One row per packing, then per system a ``mean`` and a ``sem`` row (SEM over packings,
    :func:`randmedia.stats.standard_error`; NaN for a single packing). Wall-clock times stay
    in the packing files (attr ``seconds``): the table is identical for identical packings."""
    import pandas as pd

    from randmedia.stats import standard_error

    frame = pd.DataFrame.from_records(records)
    if frame.empty:
        raise ValueError("no packings to summarize")
    frame["sample"] = frame["sample"].astype(int)
    frame = frame.sort_values(["system", "sample"]).reset_index(drop=True)
    rows = []
    for system, group in frame.groupby("system", sort=True):
        mean = {"system": system, "sample": "mean", "n_particles": group["n_particles"].iloc[0]}
        sem = {"system": system, "sample": "sem", "n_particles": group["n_particles"].iloc[0]}
        for column in SUMMARY_COLUMNS:
            values = group[column].to_numpy(dtype=float)
            mean[column] = float(values.mean())
            sem[column] = float(standard_error(values))
        rows += [mean, sem]
    frame["sample"] = frame["sample"].astype(object)
    return pd.concat([frame, pd.DataFrame(rows)], ignore_index=True)
