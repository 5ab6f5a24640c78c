"""Spectral density chi_V(k) of sphere packings, two ways (Klatt & Torquato 2016, Sec. IV).

1. **Direct** (Eqs. 13-15): for non-overlapping spheres of diameter D the
   Fourier transform of J = I - phi factorizes into the form factor of one
   sphere and the centres' structure factor,

       chi_V(k) = |J(k)|^2 / V = rho m(k)^2 S(k),   S(k) = |sum_j exp(-i k.x_j)|^2 / N,   (14)
       m(k) = (pi D / k)^(d/2) J_{d/2}(k D / 2)     (15; -> v_D = pi D^3/6 as k -> 0, d = 3),

   on *every* wavevector of the periodic cell, k = 2 pi B^-T n (n integer,
   B = box, columns the lattice vectors, any triclinic shape), 0 < |k| <= k_max.
   The sums over particles are one type-1 non-uniform FFT (finufft) of the
   fractional coordinates 2 pi f_j onto the integer modes
   |n_i| <= k_max |a_i| / (2 pi) (a_i the lattice vectors; this box contains
   every n with |k| <= k_max), so the cost is O(N + M log M) for M modes
   instead of O(N M) for the direct sum. S(k) = S(-k), so only one of each
   pair +-n is kept (the first non-zero integer coordinate positive).
   Estimates are binned in |k| (bin width 0.133/D in the paper); per sample
   the mean over the wavevectors in a bin, then mean and SEM over samples.
   A bin mean also carries its error *within* one sample (:func:`bin_sems`):
   in a disordered system the density mode at each k is a sum of many
   phases, so S(k) is exponentially distributed (variance = mean^2) and
   modes not related by k -> -k are independent to O(1/N); the bin mean of
   M values v_k then has variance sum_k E[v_k]^2 / M^2, estimated by
   sum_k v_k^2 / (2 M^2) (E v^2 = 2 (E v)^2). It is what one sample (Table V's
   first N = 10 000 packing) can say about its own noise.

2. **Fourier transform of the autocovariance** (Eq. 11):
   chi_V(k) = (4 pi / k) integral_0^r_c [S2(r) - phi^2] r sin(k r) dr, with
   S2 the exact Appendix-A function of each sample (phi its own packing
   fraction) on a uniform grid, composite Simpson rule, *hard cutoff* at
   r_c = h_w - D (the largest r where S2 is known). The cutoff convolves the
   spectrum with the transform of a ball of radius r_c, whose main lobe has
   half width ~ 2 pi / r_c: estimates at k < k_min = 2 pi / r_c are not
   reliable (Sec. IV: "a cutoff is assumed ... which induces a minimal
   absolute value k of the wave vector that is reliable") and are not plotted.

Overlapping spheres: Eq. (11) of the exact autocovariance
chi_V(r) = S2_void(r) - phi1^2 (zero for r >= D), by adaptive quadrature.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit
from scipy.integrate import quad, simpson
from scipy.optimize import brentq
from scipy.special import gamma, jv

from randmedia.periodic import Cell


# --------------------------------------------------------------------------- form factor


def sphere_form_factor(k, diameter: float = 1.0, dim: int = 3) -> np.ndarray:
    """m(k) = (pi D / k)^(d/2) J_{d/2}(k D / 2) (Eq. 15); m(0) = volume of the d-ball.

    Parameters
    ----------
    k : array_like
        Wavenumbers |k| (1/length).
    diameter : float, optional
        Sphere diameter D.
    dim : int, optional
        Dimension d.

    Returns
    -------
    ndarray
        m(k) (length^d), shape of ``k``; the ball volume where k D < 1e-6.
    """
    k = np.asarray(k, dtype=float)
    volume = math.pi ** (dim / 2) / gamma(1 + dim / 2) * (diameter / 2) ** dim
    with np.errstate(divide="ignore", invalid="ignore"):
        value = (math.pi * diameter / k) ** (dim / 2) * jv(dim / 2, k * diameter / 2)
    small = k * diameter < 1e-6
    return np.where(small, volume, value)


def form_factor_zeros(k_max: float, diameter: float = 1.0, dim: int = 3) -> np.ndarray:
    """Zeros of m(k) in (0, k_max]: k D / 2 = zeros of J_{d/2} (the dashed lines of Fig. 6).

    Parameters
    ----------
    k_max : float
        Largest wavenumber searched (1/length).
    diameter : float, optional
        Sphere diameter D.
    dim : int, optional
        Dimension d.

    Returns
    -------
    ndarray
        Ascending zeros k (1/length).
    """
    x = np.linspace(1e-6, k_max * diameter / 2, max(200, int(50 * k_max * diameter)))
    f = jv(dim / 2, x)
    roots = [brentq(lambda t: jv(dim / 2, t), a, b, xtol=1e-14)
             for a, b, fa, fb in zip(x[:-1], x[1:], f[:-1], f[1:]) if fa * fb < 0]
    return 2.0 * np.array(roots) / diameter


# --------------------------------------------------------------------------- wavevectors


def mode_bounds(box, k_max: float) -> np.ndarray:
    """M_i = floor(k_max |a_i| / 2 pi): every n with |2 pi B^-T n| <= k_max has |n_i| <= M_i."""
    cell = Cell(box)
    lengths = np.linalg.norm(cell.box, axis=0)
    return np.floor(k_max * lengths / (2.0 * math.pi) + 1e-12).astype(int)


def allowed_wavevectors(box, k_max: float):
    """Integer vectors n (half space, n != 0) and k = 2 pi B^-T n with |k| <= k_max.

    Returns (n (M, d) int, k (M, d), |k| (M,)), ordered lexicographically in n.
    """
    cell = Cell(box)
    if cell.dim != 3:
        raise ValueError("allowed_wavevectors is implemented for d = 3")
    bounds = mode_bounds(cell.box, k_max)
    metric = 4.0 * math.pi**2 * cell.inverse @ cell.inverse.T  # |k|^2 = n^T G n
    a, b, c = (np.arange(-m, m + 1, dtype=float) for m in bounds)
    k2 = (metric[0, 0] * a[:, None, None] ** 2 + metric[1, 1] * b[None, :, None] ** 2
          + metric[2, 2] * c[None, None, :] ** 2
          + 2 * metric[0, 1] * a[:, None, None] * b[None, :, None]
          + 2 * metric[0, 2] * a[:, None, None] * c[None, None, :]
          + 2 * metric[1, 2] * b[None, :, None] * c[None, None, :])
    inside = k2 <= k_max * k_max * (1 + 1e-12)
    # half space: n_1 > 0, or n_1 = 0 and n_2 > 0, or n_1 = n_2 = 0 and n_3 > 0
    m1, m2, m3 = bounds
    inside[:m1] = False
    inside[m1, :m2] = False
    inside[m1, m2, : m3 + 1] = False
    flat = np.flatnonzero(inside)
    n = np.stack(np.unravel_index(flat, inside.shape), axis=1) - bounds
    k = (2.0 * math.pi) * (n.astype(float) @ cell.inverse)  # rows: k = 2 pi B^-T n
    return n, k, np.sqrt(k2.ravel()[flat])


# --------------------------------------------------------------------------- structure factor


def structure_factor(positions, box, k_max: float, *, eps: float = 1e-9, nthreads: int = 1,
                     upsampfac: float = 1.25):
    """S(k) of the centres on all allowed wavevectors 0 < |k| <= k_max (half space), by NUFFT.

    Returns (n, k, |k|, S). finufft's tolerance ``eps`` bounds the error of each
    Fourier sum relative to sum |c_j| = N; S = |F|^2 / N. The low upsampling
    factor 1.25 (instead of 2) halves the cost at the same tolerance for
    eps >= 1e-11 (finufft documentation).

    Parameters
    ----------
    positions : array_like, shape (n, 3)
        Centres, in the units of ``box``.
    box : array_like, shape (3, 3)
        Periodic cell; columns are the lattice vectors.
    k_max : float
        Largest |k| (1/length, units of ``box``).
    eps : float, optional
        finufft tolerance.
    nthreads : int, optional
        finufft threads.
    upsampfac : float, optional
        finufft upsampling factor.

    Returns
    -------
    n : ndarray of int, shape (M, 3)
        Integer mode vectors (half space, lexicographic).
    k : ndarray, shape (M, 3)
        Wavevectors 2 pi B^-T n.
    kmag : ndarray, shape (M,)
        |k|.
    S : ndarray, shape (M,)
        Structure factor.
    """
    import finufft

    cell = Cell(box)
    positions = np.asarray(positions, dtype=float)
    if positions.ndim != 2 or positions.shape[1] != cell.dim:
        raise ValueError(f"positions must have shape (n, {cell.dim}), got {positions.shape}")
    if cell.dim != 3:
        raise ValueError("structure_factor is implemented for d = 3")
    n_vec, k_vec, kmag = allowed_wavevectors(cell.box, k_max)
    bounds = mode_bounds(cell.box, k_max)
    frac = cell.fractional(positions)
    x = np.ascontiguousarray((2.0 * math.pi * (frac - np.floor(frac))).T)
    strengths = np.ones(len(positions), dtype=np.complex128)
    modes = tuple(int(2 * m + 1) for m in bounds)
    grid = finufft.nufft3d1(x[0], x[1], x[2], strengths, modes, eps=eps, isign=-1,
                            nthreads=int(nthreads), upsampfac=upsampfac)
    fourier = grid[tuple((n_vec + bounds).T)]  # mode n sits at index n + M (modeord 0)
    return n_vec, k_vec, kmag, np.abs(fourier) ** 2 / len(positions)


@njit(cache=True)
def _direct_sums(positions, k, out_re, out_im):
    for m in range(k.shape[0]):
        re = 0.0
        im = 0.0
        for j in range(positions.shape[0]):
            phase = k[m, 0] * positions[j, 0] + k[m, 1] * positions[j, 1] + k[m, 2] * positions[j, 2]
            re += math.cos(phase)
            im -= math.sin(phase)
        out_re[m] = re
        out_im[m] = im


def structure_factor_direct(positions, k) -> np.ndarray:
    """S(k) = |sum_j exp(-i k.x_j)|^2 / N by the direct O(N M) sum (validation reference)."""
    positions = np.ascontiguousarray(positions, dtype=np.float64)
    k = np.ascontiguousarray(np.atleast_2d(k), dtype=np.float64)
    re, im = np.empty(len(k)), np.empty(len(k))
    _direct_sums(positions, k, re, im)
    return (re * re + im * im) / len(positions)


def spectral_density_direct(kmag, S, rho: float, diameter: float = 1.0) -> np.ndarray:
    """chi_V(k) = rho m(k)^2 S(k) (Eq. 14) for non-overlapping spheres, in units of D^3.

    Parameters
    ----------
    kmag : array_like
        Wavenumbers |k| (1/D when lengths are in D).
    S : array_like
        Structure factor at ``kmag``.
    rho : float
        Number density of the centres.
    diameter : float, optional
        Sphere diameter D.

    Returns
    -------
    ndarray
        chi_V(k), shape of ``kmag`` and ``S`` broadcast.
    """
    return rho * sphere_form_factor(kmag, diameter) ** 2 * np.asarray(S)


# --------------------------------------------------------------------------- binning


def bin_means(kmag, values, edges):
    """Per-bin mean of ``values`` over the wavevectors with |k| in [edges[i], edges[i+1]).

    Returns (mean (NaN in empty bins), count, mean |k| of the bin).

    Parameters
    ----------
    kmag : array_like, shape (M,)
        |k| of the wavevectors.
    values : array_like, shape (M,)
        Value per wavevector.
    edges : array_like, shape (n_bins + 1,)
        Ascending bin edges; |k| outside [edges[0], edges[-1]) is not used.

    Returns
    -------
    mean, count, kmean : ndarray, shape (n_bins,)
        Per bin.
    """
    kmag, values, edges = (np.asarray(a, dtype=float) for a in (kmag, values, edges))
    index = np.searchsorted(edges, kmag, side="right") - 1
    inside = (index >= 0) & (index < len(edges) - 1)
    nbins = len(edges) - 1
    count = np.bincount(index[inside], minlength=nbins).astype(float)
    total = np.bincount(index[inside], weights=values[inside], minlength=nbins)
    ksum = np.bincount(index[inside], weights=kmag[inside], minlength=nbins)
    with np.errstate(invalid="ignore", divide="ignore"):
        return total / count, count, ksum / count


def bin_sems(kmag, values, edges):
    """Standard error of each :func:`bin_means` mean within one sample: sqrt(sum v^2 / 2) / M
    over the M values v in the bin (NaN in empty bins).

    The model (module docstring): each value is exponentially distributed about its own mean
    (S(k) of a disordered system, so also chi_V = rho m^2 S) and the wavevectors of one half
    space are independent. Exact for uniform random points up to O(1/N); it holds at one
    wavevector too (M = 1), and a bin whose mean varies across it (next to a zero of m(k)) is
    not inflated by that variation, unlike the spread of the values. Not for lattices (S is
    not random there). Measured against the SD over samples of the bin means (Table V's bins,
    11 MRJ packings of N = 2000; 40 Poisson samples): ratio 1.03 and 1.04 (geometric means
    over the 32 bins, each ratio +-22 % and +-11 % from the samples alone); docs/mrj2016.md.

    Parameters
    ----------
    kmag, values, edges
        As :func:`bin_means`.

    Returns
    -------
    ndarray, shape (n_bins,)
        Per bin.
    """
    mean_square, count, _ = bin_means(kmag, np.asarray(values, dtype=float) ** 2, edges)
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.sqrt(mean_square / (2.0 * count))


def centred_edges(centres, width: float):
    """Edges [c - w/2, c + w/2) of bins centred on ``centres`` (must not overlap)."""
    centres = np.asarray(centres, dtype=float)
    if np.any(np.diff(centres) < width - 1e-12):
        raise ValueError(f"bins of width {width:g} centred on {centres} would overlap")
    return centres - width / 2, centres + width / 2


def centred_bin_means(kmag, values, centres, width: float):
    """Means of ``values`` in bins of ``width`` centred on ``centres`` (e.g. a table's kD).

    Parameters
    ----------
    kmag : array_like, shape (M,)
        |k| of the wavevectors.
    values : array_like, shape (M,)
        Value per wavevector.
    centres : array_like, shape (n_centres,)
        Ascending bin centres (bins must not overlap).
    width : float
        Bin width (units of ``kmag``).

    Returns
    -------
    mean, count, kmean : ndarray, shape (n_centres,)
        As :func:`bin_means`.
    """
    edges, stride = _convention_edges("centred", np.asarray(centres, dtype=float), width)
    mean, count, kmean = bin_means(kmag, values, edges)
    return mean[::stride], count[::stride], kmean[::stride]


def snap_to_shells(labels, box, step: int = 2):
    """Bin centres for a table whose kD column labels consecutive shells of a cubic cell.

    Table IV of Klatt & Torquato lists kD = 0.6, 1.1, 1.7, 2.3, 2.8, ..., 17.6: the m-th
    entry is m * 2 (2 pi / L) of the cubic cell of the N = 10 000 liquid (L ~ 22.2 D),
    rounded to one decimal. If the labels are m = 1, 2, 3, ... times step * 2 pi / L of the
    (cubic) ``box``, each within a quarter of that spacing, those multiples are returned
    (and True); otherwise the labels themselves (and False) -- e.g. Table V, whose 0.6 m
    are not multiples of an MRJ cell's 2 pi / L, or cells of another size.

    Parameters
    ----------
    labels : array_like
        Printed kD values of the table (1/D).
    box : array_like, shape (d, d)
        Periodic cell (columns the lattice vectors, lengths in D).
    step : int, optional
        Shells of 2 pi / L per table entry.

    Returns
    -------
    centres : ndarray
        The multiples m step 2 pi / L, or ``labels`` unchanged.
    snapped : bool
        Whether the labels were snapped.
    """
    labels = np.asarray(labels, dtype=float)
    cell = Cell(box)
    sides = np.diag(cell.box)
    if not (np.allclose(cell.box, np.diag(sides)) and np.allclose(sides, sides[0])):
        return labels, False
    spacing = step * 2.0 * math.pi / sides[0]
    m = np.round(labels / spacing)
    if np.array_equal(m, np.arange(1, labels.size + 1)) and np.all(np.abs(labels - m * spacing) < spacing / 4):
        return m * spacing, True
    return labels, False


#: the bin conventions of :func:`table_binnings`, in this order (the first is the table's own)
TABLE_BINNINGS = ("bin_width", "single_shell", "grid_spacing", "table_spacing", "labels")


def table_binnings(labels, centres, box, bin_width: float) -> dict[str, tuple[np.ndarray, float]]:
    """Plausible readings of "chi_V at the tabulated kD", as {name: (bin centres, width)}.

    A table that lists chi_V(k) at wavenumbers k_i without saying how its values were binned
    (Klatt & Torquato, Tables IV, V) can mean any of these means over the allowed wavevectors;
    they differ most next to the zeros of the form factor m(k), where chi_V varies by orders
    of magnitude within a bin. ``centres`` are our bin centres for the ``labels`` (the printed
    kD, or the cubic-cell shells they round, :func:`snap_to_shells`); ``box`` the cell.

    * ``bin_width``: width ``bin_width`` centred on ``centres`` (the table's own row);
    * ``single_shell``: only the wavevectors with |k| equal to the centre (width 10^-3 of the
      grid spacing; a cubic cell's |k| = (2 pi / L) |n| with integer |n|^2, so this is the one
      shell |n| = centre L / 2 pi) -- NaN centres unless the centres are such shells;
    * ``grid_spacing``: width 2 pi / L (L the cube root of the cell volume; NaN centres if
      that is wider than the spacing of the centres);
    * ``table_spacing``: contiguous bins tiling k, edges halfway between neighbouring centres
      (and half a spacing beyond the first and last), each bin [lower, upper) with a shell on
      an edge counted in the bin above (edges lowered by 10^-9 relative: on a cubic cell the
      edges of Table IV's bins fall on the shells |n| = 2m + 1 exactly);
    * ``labels``: width ``bin_width`` centred on the printed ``labels`` (NaN if they are the
      centres).
    NaN centres mean the convention does not apply (its means are NaN).

    Parameters
    ----------
    labels : array_like, shape (n_centres,)
        Printed kD of the table.
    centres : array_like, shape (n_centres,)
        Our bin centres for the labels (ascending).
    box : array_like, shape (d, d)
        Periodic cell; columns are the lattice vectors.
    bin_width : float
        Width of the ``bin_width`` and ``labels`` conventions (1/length).

    Returns
    -------
    dict
        {name: (centres, width)} for the names of :data:`TABLE_BINNINGS`, in that order.
    """
    labels = np.asarray(labels, dtype=float)
    centres = np.asarray(centres, dtype=float)
    cell_box = Cell(box).box
    grid = 2.0 * math.pi / abs(np.linalg.det(cell_box)) ** (1.0 / len(cell_box))
    n_shell = centres / grid
    on_shells = bool(np.allclose(n_shell ** 2, np.round(n_shell ** 2), atol=1e-6))
    spacing = float(np.min(np.diff(centres))) if centres.size > 1 else grid
    nan = np.full_like(centres, np.nan)
    return {
        "bin_width": (centres, float(bin_width)),
        "single_shell": (centres if on_shells else nan, 1e-3 * grid),
        # bins wider than the spacing of the centres would overlap (a small cell): not applicable
        "grid_spacing": (centres if grid <= spacing + 1e-12 else nan, grid),
        "table_spacing": (centres, spacing),
        "labels": (nan if np.allclose(labels, centres) else labels, float(bin_width)),
    }


def _convention_edges(name: str, centres, width: float):
    """(edges, stride) of one convention of :func:`table_binnings`: its bins are
    [edges[stride i], edges[stride i + 1])."""
    if name == "table_spacing":  # contiguous; a shell on an edge counts in the bin above
        middle = 0.5 * (centres[1:] + centres[:-1])
        edges = np.concatenate([[centres[0] - (middle[0] - centres[0]) if middle.size else centres[0] - width / 2],
                                middle,
                                [centres[-1] + (centres[-1] - middle[-1]) if middle.size else centres[-1] + width / 2]])
        return edges * (1.0 - 1e-9), 1
    lo, hi = centred_edges(centres, width)
    edges = np.empty(2 * len(lo))
    edges[0::2], edges[1::2] = lo, hi
    return edges, 2


def binned_table_values(kmag, values, binnings: dict[str, tuple[np.ndarray, float]]):
    """(means, counts, sems), each (len(binnings), n_centres): :func:`bin_means` and
    :func:`bin_sems` of ``values`` under each convention of :func:`table_binnings` (NaN mean
    and SEM, zero count where it does not apply).

    Parameters
    ----------
    kmag : array_like, shape (M,)
        |k| of the wavevectors.
    values : array_like, shape (M,)
        Value per wavevector (e.g. chi_V).
    binnings : dict
        {name: (centres, width)} from :func:`table_binnings`.

    Returns
    -------
    means, counts, sems : ndarray, shape (len(binnings), n_centres)
        Per convention and centre.
    """
    means, counts, sems = [], [], []
    for name, (centres, width) in binnings.items():
        if np.isnan(centres).all():
            means.append(np.full(centres.shape, np.nan)), counts.append(np.zeros(centres.shape))
            sems.append(np.full(centres.shape, np.nan))
            continue
        edges, stride = _convention_edges(name, centres, width)
        mean, count, _ = bin_means(kmag, values, edges)
        means.append(mean[::stride]), counts.append(count[::stride])
        sems.append(bin_sems(kmag, values, edges)[::stride])
    return np.array(means), np.array(counts), np.array(sems)


# --------------------------------------------------------------------------- Eq. (11)


def spectral_density_from_autocovariance(r, chi, k) -> np.ndarray:
    """chi_V(k) = (4 pi / k) integral_0^r_max chi(r) r sin(k r) dr (Eq. 11), Simpson on the grid r.

    ``r`` must be a uniform grid from 0; ``chi`` has r as its last axis (samples
    first is fine). Hard cutoff at r[-1] (see the module docstring for k_min).

    Parameters
    ----------
    r : array_like, shape (n_r,)
        Uniform grid from 0 (length).
    chi : array_like, shape (..., n_r)
        Autocovariance S2(r) - phi^2 on ``r``.
    k : array_like
        Wavenumbers (1/length), 0 allowed.

    Returns
    -------
    ndarray, shape (..., n_k)
        chi_V(k) (length^3).
    """
    r = np.asarray(r, dtype=float)
    chi = np.asarray(chi, dtype=float)
    k = np.atleast_1d(np.asarray(k, dtype=float))
    if r[0] != 0 or not np.allclose(np.diff(r), r[1] - r[0], rtol=1e-9, atol=1e-12):
        raise ValueError("r must be a uniform grid starting at 0")
    integrand = chi[..., None, :] * (r * np.sin(np.outer(k, r)))  # (..., k, r)
    with np.errstate(divide="ignore", invalid="ignore"):
        value = 4.0 * math.pi * simpson(integrand, x=r, axis=-1) / k
    zero = k == 0
    if zero.any():
        value[..., zero] = 4.0 * math.pi * simpson(chi * r * r, x=r, axis=-1)[..., None]
    return value


def smallest_reliable_k(r_cut: float) -> float:
    """k_min = 2 pi / r_c for a transform cut off at r_c."""
    return 2.0 * math.pi / r_cut


def overlapping_spectral_density(k, phi: float, diameter: float = 1.0) -> np.ndarray:
    """Exact chi_V(k) of overlapping spheres by Eq. (11): chi_V(r) = S2_void(r) - phi1^2, 0 for r >= D.

    Parameters
    ----------
    k : array_like
        Wavenumbers (1/length), 0 allowed.
    phi : float
        Volume fraction of the spheres (phi1 = 1 - phi the void's).
    diameter : float, optional
        Sphere diameter D.

    Returns
    -------
    ndarray, shape (n_k,)
        chi_V(k) (length^3).
    """
    from randmedia.theory.overlapping import s2_void

    radius = diameter / 2
    phi1 = 1.0 - phi

    def chi(r):
        return float(s2_void(r, radius, phi, 3)) - phi1 * phi1

    out = []
    for kk in np.atleast_1d(np.asarray(k, dtype=float)):
        if kk == 0:
            value = quad(lambda r: chi(r) * r * r, 0, diameter, epsabs=0, epsrel=1e-11)[0]
        else:
            value = quad(lambda r: chi(r) * r * math.sin(kk * r), 0, diameter, epsabs=0,
                         epsrel=1e-11, limit=200)[0] / kk
        out.append(4.0 * math.pi * value)
    return np.array(out)
