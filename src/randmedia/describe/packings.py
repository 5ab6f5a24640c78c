"""Exact two-point correlation functions of finite periodic sphere packings (3D).

Klatt & Torquato, PRE 94, 022152 (2016), Appendix A: for N spheres of radius
R = D/2 in a periodic cell of volume V, the two-point function S2(r) of the
sphere phase, the surface-void function F_sv(r) and the surface-surface
function F_ss(r) are sums over the pair distances rho_ij:

    S2(r)      = phi p_ii(r) + (2 phi / N) sum_{i<j} p_ij(r)          (A1)
    F_sv^s(r)  = s   q_ii(r) + (2 s / N)   sum_{i<j} q_ij(r)          (A12)
    F_ss(r)    = s   a_ii(r) + (2 s / N)   sum_{i<j} a_ij(r)          (A16)

with the one-body terms p_ii = (2R - r)^2 (r + 4R) / (16 R^3) (A6),
q_ii = (2R - r) / (4R) (A13), a_ii = 1 / (2r) (A20) for r < 2R, and the
two-body kernels of Eqs. (A7), (A14), (A21). F_sv^s is the function with the
spheres as "void"; the paper's F_sv (matrix = void) is s - F_sv^s (Eq. 7).
The two-body parts are F*_sv = (2s/N) sum q_ij (B1) and F*_ss = (2s/N) sum
a_ij (B2); at contact they give the mean contact number z (B3, B4):
dF*_sv/dr(0) = s z / (8D), F*_ss(0+) = s z / (4D).

One form for all three kernels. Each two-body kernel is the average over
directions u of a convolution K(|c_j - c_i - r u|) of two sphere measures --
K_v(t) = lens volume of two balls (S2), K_h(t) = area of one sphere inside the
other ball (F_sv), K_J(t) = 2 pi R^2 / t (the density of the intersection
circle of two spheres, F_ss) -- normalized by v_R = 4 pi R^3 / 3 (p) or
a_R = 4 pi R^2 (q, a). The directional average of a radial function is

    < K(|rho - r u|) >_u = [W(rho + r) - W(|rho - r|)] / (2 rho r),
    W(d) = integral_0^min(d, 2R) t K(t) dt,

so that p_ij, q_ij, a_ij are [W(rho+r) - W(|rho-r|)] / (2 rho r v_R or a_R),
and the two-body parts of S2, F_sv^s and F_ss are all T_K(r) / (V r) with
T_K(r) = sum_{i<j} [W_K(rho_ij + r) - W_K(|rho_ij - r|)] / rho_ij. For
rho_ij >= D (hard spheres) this is exactly Eqs. (A7), (A14), (A21); unlike
them it stays exact for overlapping pairs (rho + r < D), which lets the
estimator be validated on Poisson configurations (its expectation is then the
constant phi^2 = eta^2, s phi, s^2 with eta = rho v_R -- see the tests).

Speed: W_K is a polynomial (degree 5, 3, 1), so T_K(r) is a sum over the pairs
with |rho - r| < D of polynomials in rho times 1/rho: with the pair distances
sorted once and prefix sums of rho^(m-1), m = 0..5, every radius costs a few
binary searches (O(P log P + n_r log P) for P pairs instead of O(P n_r)). The
prefix sums are compensated (Neumaier; double-double) and the per-radius
combination runs in numpy.longdouble, because the polynomial in rho (not in
rho - r) cancels by up to ((r + D)/D)^5; the result agrees with the direct
per-pair sum to ~1e-10 relative (tested). The prefix sums are kept only at the
window ends of the asked radii (one pass over the sorted distances: 12 doubles
per radius instead of per pair), so an N = 10 000 liquid out to r ~ 10 D (25
million pairs) needs little more than its distances (0.2 GB).

Validity. The pair sums need every pair closer than r + D exactly once, so
r < h_w - D (Eq. A8; h_w = half the smallest face distance of the cell, any
cell shape). Pair distances come from the fractional minimum image: for a
separation shorter than h_w, rounding the fractional coordinates gives the
nearest image in any triclinic cell (all other images are >= 2 h_w - |d|
away), so only pairs closer than the cutoff <= h_w are kept.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from randmedia.periodic import Cell

#: variables of a correlation-function dataset (per sample and r)
CORRELATION_VARIABLES = ("S2", "F_sv", "F_ss", "F_sv_two_body", "F_ss_two_body")


# --------------------------------------------------------------------------- pair distances


@njit(cache=True, inline="always")
def _nearest_image_d2(frac, box, i, j):
    """Squared distance of i and the nearest image of j by rounding fractional differences:
    exact whenever that distance is below the half width h_w (every fractional component
    of a vector shorter than h_w is below 1/2), which the cutoff <= h_w guarantees."""
    f0 = frac[j, 0] - frac[i, 0]
    f1 = frac[j, 1] - frac[i, 1]
    f2 = frac[j, 2] - frac[i, 2]
    f0 -= np.rint(f0)
    f1 -= np.rint(f1)
    f2 -= np.rint(f2)
    x = box[0, 0] * f0 + box[0, 1] * f1 + box[0, 2] * f2
    y = box[1, 0] * f0 + box[1, 1] * f1 + box[1, 2] * f2
    z = box[2, 0] * f0 + box[2, 1] * f1 + box[2, 2] * f2
    return x * x + y * y + z * z


@njit(cache=True)
def _count_pairs(frac, box, cutoff2):
    n = frac.shape[0]
    counts = np.zeros(n, dtype=np.int64)
    for i in range(n):
        c = 0
        for j in range(i + 1, n):
            if _nearest_image_d2(frac, box, i, j) < cutoff2:
                c += 1
        counts[i] = c
    return counts


@njit(cache=True)
def _fill_pairs(frac, box, cutoff2, offsets, out):
    n = frac.shape[0]
    for i in range(n):
        k = offsets[i]
        for j in range(i + 1, n):
            d2 = _nearest_image_d2(frac, box, i, j)
            if d2 < cutoff2:
                out[k] = math.sqrt(d2)
                k += 1


def pair_distances(positions, box, cutoff: float) -> np.ndarray:
    """Sorted nearest-image distances of all pairs i < j closer than ``cutoff`` <= h_w (3D).

    Parameters
    ----------
    positions : array_like, shape (n, 3)
        Sphere centres, in the units of ``box``.
    box : array_like, shape (3, 3)
        Periodic cell; columns are the lattice vectors.
    cutoff : float
        Distance cutoff, 0 < cutoff <= h_w (half the smallest face distance).

    Returns
    -------
    ndarray, shape (n_pairs,)
        Ascending pair distances.
    """
    cell = Cell(box)
    positions = np.asarray(positions, dtype=float)
    if cell.dim != 3 or positions.ndim != 2 or positions.shape[1] != 3:
        raise ValueError(f"need 3D positions (n, 3) and a 3x3 box, got {positions.shape}, {cell.box.shape}")
    if not 0 < cutoff <= cell.half_width * (1 + 1e-12):
        raise ValueError(f"cutoff must lie in (0, h_w = {cell.half_width:g}], got {cutoff:g}")
    frac = np.ascontiguousarray(cell.fractional(positions))
    box_c = np.ascontiguousarray(cell.box)
    counts = _count_pairs(frac, box_c, cutoff * cutoff)
    offsets = np.concatenate(([0], np.cumsum(counts)[:-1])).astype(np.int64)
    out = np.empty(int(counts.sum()), dtype=np.float64)
    _fill_pairs(frac, box_c, cutoff * cutoff, offsets, out)
    out.sort()
    return out


# --------------------------------------------------------------------------- kernels


def _kernel_polynomials(radius: float) -> dict[str, np.ndarray]:
    """Coefficients w_n of W_K(d) = sum_n w_n d^n = integral_0^d t K(t) dt, d <= 2R."""
    R = float(radius)
    w = {
        # K_v(t) = (pi/12)(4R + t)(2R - t)^2 = (pi/12)(16 R^3 - 12 R^2 t + t^3): lens volume
        "v": np.array([0.0, 0.0, 8 * R**3, -4 * R**2, 0.0, 1.0 / 5.0]) * (math.pi / 12.0),
        # K_h(t) = pi R (2R - t): area of a radius-R sphere inside a radius-R ball t away
        "h": np.array([0.0, 0.0, math.pi * R**2, -math.pi * R / 3.0, 0.0, 0.0]),
        # K_J(t) = 2 pi R^2 / t: density of the circle where two radius-R spheres t apart meet
        "J": np.array([0.0, 2.0 * math.pi * R**2, 0.0, 0.0, 0.0, 0.0]),
    }
    return w


def one_body_terms(r, radius: float) -> dict[str, np.ndarray]:
    """p_ii (A6), q_ii (A13), a_ii (A20): both points in / on the same sphere; 0 for r >= 2R."""
    r = np.asarray(r, dtype=float)
    R = float(radius)
    inside = r < 2 * R
    with np.errstate(divide="ignore"):
        a = np.where(inside, 1.0 / (2.0 * r), 0.0)
    return {
        "p": np.where(inside, (2 * R - r) ** 2 * (r + 4 * R) / (16 * R**3), 0.0),
        "q": np.where(inside, (2 * R - r) / (4 * R), 0.0),
        "a": a,
    }


@njit(cache=True)
def _compensated_prefix_at(rho, stops, hi, lo):
    """Prefix sums of rho^(m-1), m = 0..5, over rho[:stop] for each of the ascending ``stops``
    (in [0, n]), as double-double (hi + lo, Neumaier summation): one pass over rho."""
    n = rho.shape[0]
    n_stops = stops.shape[0]
    s = np.zeros(6)
    c = np.zeros(6)
    x = np.empty(6)
    q = 0
    for k in range(n + 1):
        while q < n_stops and stops[q] == k:
            for m in range(6):
                hi[m, q] = s[m]
                lo[m, q] = c[m]
            q += 1
        if q == n_stops or k == n:
            break
        value = rho[k]
        x[0] = 1.0 / value
        x[1] = 1.0
        x[2] = value
        x[3] = value * value
        x[4] = x[3] * value
        x[5] = x[4] * value
        for m in range(6):
            t = s[m] + x[m]
            if abs(s[m]) >= abs(x[m]):
                c[m] += (s[m] - t) + x[m]
            else:
                c[m] += (x[m] - t) + s[m]
            s[m] = t


class PairSums:
    """Fast exact T_K(r) = sum_{i<j} [W_K(rho_ij + r) - W_K(|rho_ij - r|)] / rho_ij for sorted rho.

    The compensated prefix sums are evaluated only where the windows of the asked radii begin
    and end (one pass over rho per new set of radii, kept for the next kernel), so memory is
    O(n_r) beyond the distances themselves and the time O(P + n_r log P)."""

    def __init__(self, distances: np.ndarray, radius: float):
        rho = np.ascontiguousarray(distances, dtype=np.float64)
        if rho.ndim != 1 or np.any(rho[1:] < rho[:-1]) or (rho.size and rho[0] <= 0):
            raise ValueError("pair distances must be a sorted 1D array of positive values")
        self.rho = rho
        self.radius = float(radius)
        self.w = {k: v.astype(np.longdouble) for k, v in _kernel_polynomials(radius).items()}
        self._stops = np.empty(0, dtype=np.int64)
        self._hi = np.empty((6, 0))
        self._lo = np.empty((6, 0))

    def _prefix(self, stops: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Double-double prefix sums (hi, lo), shape (6, stops.size), at the indices ``stops``."""
        if not np.isin(stops, self._stops).all():
            self._stops = np.union1d(self._stops, stops).astype(np.int64)
            self._hi = np.empty((6, self._stops.size))
            self._lo = np.empty((6, self._stops.size))
            _compensated_prefix_at(self.rho, self._stops, self._hi, self._lo)
        column = np.searchsorted(self._stops, stops)
        return self._hi[:, column], self._lo[:, column]

    @staticmethod
    def _coefficients(w, r, alpha, beta):
        """c[:, m] with sum_n w_n (alpha rho + beta r)^n = sum_m c_m rho^m, for each r."""
        c = np.zeros((r.size, 6), dtype=np.longdouble)
        for n in range(6):
            if w[n] == 0:
                continue
            for m in range(n + 1):
                c[:, m] += w[n] * math.comb(n, m) * alpha**m * (beta * r) ** (n - m)
        return c

    def _windows(self, bounds):
        """Sums of rho^(m-1) over rho in [lo, hi) for each (lo, hi) of ``bounds`` and each r,
        shape (n_r, 6) each, from the double-double prefix sums (accurate to rounding of the
        window sum itself)."""
        starts = [np.searchsorted(self.rho, np.asarray(lo, dtype=float), side="left") for lo, _ in bounds]
        ends = [np.searchsorted(self.rho, np.asarray(np.maximum(hi, lo), dtype=float), side="left")
                for lo, hi in bounds]
        self._prefix(np.concatenate(starts + ends).astype(np.int64))  # one pass for every window end
        windows = []
        for start, end in zip(starts, ends):
            hi_start, lo_start = self._prefix(start)  # looked up in the sums just made
            hi_end, lo_end = self._prefix(end)
            window = (hi_end - hi_start) + (lo_end - lo_start)
            windows.append(window.T.astype(np.longdouble))
        return windows

    def __call__(self, kernel: str, r) -> np.ndarray:
        r = np.atleast_1d(np.asarray(r, dtype=np.longdouble))
        if np.any(r <= 0):
            raise ValueError("PairSums needs r > 0 (r = 0 is the analytic limit)")
        w = self.w[kernel]
        two_r = np.longdouble(2 * self.radius)
        w2 = np.polynomial.polynomial.polyval(two_r, w)
        lo = np.maximum(r - two_r, 0)
        hi = r + two_r
        split = np.clip(two_r - r, lo, hi)  # rho + r < 2R below, clamped W(2R) above
        plus, const, below, above = self._windows(
            [(lo, split), (split, hi), (lo, np.minimum(r, hi)), (np.maximum(r, lo), hi)])
        total = np.einsum("rm,rm->r", self._coefficients(w, r, 1, 1), plus)
        total += w2 * const[:, 0]
        total -= np.einsum("rm,rm->r", self._coefficients(w, r, -1, 1), below)
        total -= np.einsum("rm,rm->r", self._coefficients(w, r, 1, -1), above)
        return total


def pair_kernel(kernel: str, rho, r, radius: float) -> np.ndarray:
    """[W_K(rho + r) - W_K(|rho - r|)] / (2 rho r): the direction-averaged kernel of one pair.

    Divided by v_R (kernel "v") it is p_ij (A7), by a_R ("h", "J") q_ij (A14) and
    a_ij (A21). Direct per-pair form, used for validation and for small r.

    Parameters
    ----------
    kernel : {"v", "h", "J"}
        K_v (lens volume, S2), K_h (F_sv) or K_J (F_ss); module docstring.
    rho : array_like
        Pair centre distances (> 0).
    r : array_like
        Radial distances (> 0); broadcast with ``rho``.
    radius : float
        Sphere radius R = D/2.

    Returns
    -------
    ndarray
        The direction-averaged kernel, shape of ``rho`` and ``r`` broadcast; not yet divided
        by v_R or a_R.
    """
    w = _kernel_polynomials(radius)[kernel]
    rho, r = np.broadcast_arrays(np.asarray(rho, dtype=float), np.asarray(r, dtype=float))

    def W(d):
        return np.polynomial.polynomial.polyval(np.minimum(d, 2 * radius), w)

    return (W(rho + r) - W(np.abs(rho - r))) / (2.0 * rho * r)


# --------------------------------------------------------------------------- correlation functions


def max_radius(box, diameter: float = 1.0) -> float:
    """Largest r for which Appendix A holds in this cell: h_w - D (Eq. A8)."""
    return Cell(box).half_width - diameter


def correlation_functions(positions, box, r, diameter: float = 1.0) -> dict[str, np.ndarray]:
    """S2, F_sv (matrix void), F_ss and the two-body parts F*_sv, F*_ss of one packing.

    Exact Appendix-A formulas for the given configuration (Eqs. A1, A12, A16,
    B1, B2), valid for 0 <= r < h_w - D. At r = 0 the values are the limits
    r -> 0+: S2 = phi, F_sv = s/2, F_ss = inf; the two-body parts there count
    only overlapping pairs (zero for a packing without exact contacts).
    Returns arrays over r plus the scalars phi, s, rho, n, volume.

    Parameters
    ----------
    positions : array_like, shape (n, 3)
        Sphere centres, in the units of ``box``.
    box : array_like, shape (3, 3)
        Periodic cell; columns are the lattice vectors.
    r : ndarray, shape (n_r,)
        Distances >= 0, all below h_w - D (units of ``box``).
    diameter : float, optional
        Sphere diameter D.

    Returns
    -------
    dict
        ``S2``, ``F_sv``, ``F_ss``, ``F_sv_two_body``, ``F_ss_two_body``: arrays of shape
        (n_r,) (S2 dimensionless, F_sv in 1/length, F_ss in 1/length^2); scalars ``phi``,
        ``s`` (1/length), ``rho`` (1/volume), ``n``, ``volume``.
    """
    positions = np.asarray(positions, dtype=float)
    cell = Cell(box)
    r = np.asarray(r, dtype=float)
    if r.ndim != 1 or np.any(r < 0):
        raise ValueError("r must be a 1D array of distances >= 0")
    r_limit = cell.half_width - diameter
    if r.max() >= r_limit:
        raise ValueError(f"Appendix A holds for r < h_w - D = {r_limit:.4g} D in this cell; "
                         f"asked for r = {r.max():.4g}")
    R = diameter / 2.0
    n = positions.shape[0]
    volume = cell.volume
    v_R, a_R = 4.0 * math.pi * R**3 / 3.0, 4.0 * math.pi * R**2
    phi, s = n * v_R / volume, n * a_R / volume
    rho = pair_distances(positions, cell.box, min(r.max() + diameter, cell.half_width))
    positive = r > 0
    two_body = {kernel: np.zeros(r.shape) for kernel in ("v", "h", "J")}
    if positive.any():
        sums = PairSums(rho, R)
        rp = r[positive]
        for kernel in ("v", "h", "J"):
            two_body[kernel][positive] = np.asarray(sums(kernel, rp), dtype=float) / (volume * rp)
    if not positive.all():  # limit r -> 0: sum over pairs with rho < 2R of 2 K(rho), / V
        close = rho[rho < 2 * R]
        for kernel in ("v", "h", "J"):
            two_body[kernel][~positive] = 2.0 * np.sum(_kernel_values(kernel, close, R)) / volume
    one = one_body_terms(r, R)
    F_sv_spheres = s * one["q"] + two_body["h"]
    return {
        "S2": phi * one["p"] + two_body["v"],
        "F_sv": s - F_sv_spheres,
        "F_ss": s * one["a"] + two_body["J"],
        "F_sv_two_body": two_body["h"],
        "F_ss_two_body": two_body["J"],
        "phi": phi, "s": s, "rho": n / volume, "n": n, "volume": volume,
    }


def _kernel_values(kernel, t, R):
    t = np.asarray(t, dtype=float)
    if kernel == "v":
        return math.pi / 12.0 * (4 * R + t) * (2 * R - t) ** 2
    if kernel == "h":
        return math.pi * R * (2 * R - t)
    return 2.0 * math.pi * R**2 / t


def contact_number(positions, box, diameter: float = 1.0, r: float = 1e-3) -> dict[str, float]:
    """Mean contact number from the two-body parts at small r (Eqs. B3, B4).

    z_B4 = F*_ss(r) 4D / s and z_B3 = F*_sv(r) 8D / (s r) (the slope of F*_sv at
    0 estimated by F*_sv(r)/r, F*_sv(0) = 0). Both count a pair with gap
    g = rho - D < r with weight (1 - g/r) (B4) or (1 - g/r)^2 (B3) [Appendix B:
    "if the functions are evaluated only at finite radial distances, slight
    deviations can appear"]; ``n_within`` is the plain number of pairs with
    gap < r per sphere times 2. Evaluated pair by pair (few pairs are closer
    than D + r), so it is exact for any small r > 0.

    Parameters
    ----------
    positions : array_like, shape (n, 3)
        Sphere centres, in the units of ``box``.
    box : array_like, shape (3, 3)
        Periodic cell; columns are the lattice vectors.
    diameter : float, optional
        Sphere diameter D.
    r : float, optional
        Small evaluation distance (> 0, units of ``box``).

    Returns
    -------
    dict
        ``z_B3``, ``z_B4`` and ``n_within`` (floats).
    """
    if not r > 0:
        raise ValueError(f"r must be > 0, got {r}")
    cell = Cell(box)
    positions = np.asarray(positions, dtype=float)
    n = positions.shape[0]
    R = diameter / 2.0
    rho = pair_distances(positions, cell.box, min(diameter + r, cell.half_width))
    s = n * 4.0 * math.pi * R**2 / cell.volume
    a_R = 4.0 * math.pi * R**2
    F_sv = 2.0 * s / n * np.sum(pair_kernel("h", rho, r, R)) / a_R
    F_ss = 2.0 * s / n * np.sum(pair_kernel("J", rho, r, R)) / a_R
    return {
        "z_B3": F_sv * 8.0 * diameter / (s * r),
        "z_B4": F_ss * 4.0 * diameter / s,
        "n_within": 2.0 * np.count_nonzero(rho < diameter + r) / n,
    }
