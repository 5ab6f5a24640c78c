"""d-generic shell counts of the accelerated Yeong-Torquato construction (the 2D
construction runs on them; the 3D one of issue 13, docs/debye3d.md, will).

The construction (Ma & Torquato 2020, Sec. IV; :mod:`randmedia.generate.yeong_torquato`)
keeps, for every voxel x, the shell counts

    h_x[b] = sum_{v in bin b} I(x + v),      bins b = 1 .. n_b of the estimator
                                              (:class:`randmedia.numerics.radial.RadialBinning`),

so that a swap trial on the energy of Eq. (23) costs O(n_b)
(Delta C_b = 2 (h_q[b] - h_p[b]) - 2 [|p - q| in b]) and only an accepted swap pays
for updating h within l_c of the two flipped voxels.
This module holds those counts for 2D and 3D images alike (a 2D image is one layer,
nz = 1, whose stencil has dz = 0 only):

* :class:`Stencil`: the displacements 0 < |v| <= l_c in (dz, dy, dx) row-major order,
  their bin columns, runs of consecutive dx per stencil line (dz, dy), and a column
  table indexed by the squared length |v|^2 (bin = rint(sqrt(|v|^2)), the same float
  operation as RadialBinning; ~l_c^2 entries, in L1/L2 cache where a (2 l_c + 1)^3 table
  would not be), whose last entry -1 takes every longer displacement after a clamp.
* :func:`shell_counts`: h from scratch by FFT, one bin at a time.
* :func:`apply_flips` (:func:`apply_flips_kernel` for jitted callers): add
  signs[k] to h around each flipped voxel, image line (z, y) by line so that the
  counts of one line stay in cache while every flip whose stencil crosses it
  updates it. Only source lines that hold flips are visited: for a stencil layer dz
  the source lines within reach in y form one contiguous (or wrapped: two) block of
  the line-sorted flips, so the per-batch overhead is O(nz ny (2 l_c + 1)), not
  O(lines x runs). Measured (random flips, loaded machine; docs/debye3d.md): 2.9 ns
  per count increment at 128^3, l_c = 32, 4096 flips, vs 22-25 ns voxel by voxel; with
  unsigned indices and the sign in the counts' type, 0.69x (128^3) and 0.76x (256^3,
  l_c = 40) of that kernel's time, ~1.2-1.5 ns.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from randmedia.numerics.radial import RadialBinning

#: the shell-count types, smallest first: a count lies in [0, largest shell], so the
#: smallest unsigned type holding the fullest shell holds every count (uint8 up to 255 voxels
#: per shell: 2D l_c <~ 40; uint16 up to 65535: 3D l_c <= 72)
COUNT_TYPES = (np.uint8, np.uint16, np.uint32)


def count_dtype(largest_shell: int) -> np.dtype:
    """The smallest unsigned integer type holding every shell count (0..largest_shell).

    A batch adds its flips in any order, so a count may pass through values outside
    [0, largest_shell] before the batch ends; unsigned arithmetic wraps modulo 2^bits
    (numba stores truncate), so the counts are exact again once the batch is applied."""
    for dtype in COUNT_TYPES:
        if largest_shell <= np.iinfo(dtype).max:
            return np.dtype(dtype)
    raise ValueError(f"a shell of {largest_shell} voxels is more than uint32 counts can hold")


def _as_3d_shape(shape) -> tuple[int, int, int]:
    shape = tuple(int(n) for n in shape)
    if len(shape) not in (2, 3) or min(shape) < 1:
        raise ValueError(f"expected an image shape (ny, nx) or (nz, ny, nx), got {shape}")
    return (1,) * (3 - len(shape)) + shape


class Stencil:
    """Displacements 0 < |v| <= cutoff of an image of ``shape`` and their bins (see module)."""

    def __init__(self, shape, cutoff: float):
        self.shape = tuple(int(n) for n in shape)
        self.shape3 = _as_3d_shape(self.shape)
        self.binning = RadialBinning.build(self.shape, cutoff)
        vectors = self.binning.displacements()
        keep = self.binning.bin_of > 0
        vectors = np.concatenate([np.zeros((int(keep.sum()), 3 - len(self.shape)), dtype=np.int64),
                                  vectors[keep]], axis=1)
        order = np.lexsort((vectors[:, 2], vectors[:, 1], vectors[:, 0]))
        self.offsets = np.ascontiguousarray(vectors[order], dtype=np.int64)  # (m, 3) as (dz, dy, dx)
        self.column = np.ascontiguousarray((self.binning.bin_of[keep] - 1)[order], dtype=np.int64)
        self.n_columns = int(self.binning.counts.size - 1)
        self.largest_shell = int(self.binning.counts[1:].max())
        self.count_dtype = count_dtype(self.largest_shell)
        self.cutoff = int(math.floor(cutoff))
        c = self.cutoff
        # column by squared length: bin = rint(sqrt(d2)) as in RadialBinning (bin width 1);
        # the last entry (-1) is one past the longest displacement, so that a lookup
        # column_of_d2[min(d2, d2_limit)] needs no branch for displacements beyond l_c
        d2 = (self.offsets**2).sum(axis=1)
        self.d2_limit = int(d2.max()) + 1
        self.column_of_d2 = np.full(self.d2_limit + 1, -1, dtype=np.int64)
        self.column_of_d2[d2] = self.column
        # runs of consecutive dx in one stencil line (dz, dy); the origin splits line (0, 0)
        o = self.offsets
        breaks = np.flatnonzero((np.diff(o[:, 0]) != 0) | (np.diff(o[:, 1]) != 0)
                                | (np.diff(o[:, 2]) != 1)) + 1
        lo = np.concatenate([[0], breaks]).astype(np.int64)
        hi = np.concatenate([breaks, [len(o)]]).astype(np.int64)
        self.run_lo, self.run_hi = lo, hi
        self.run_dx0 = np.ascontiguousarray(o[lo, 2])
        # runs of stencil line (dz, dy): run_first[dz + c, dy + c] .. + run_count[...]
        self.run_first = np.zeros((2 * c + 1, 2 * c + 1), dtype=np.int64)
        self.run_count = np.zeros((2 * c + 1, 2 * c + 1), dtype=np.int64)
        for r in range(len(lo) - 1, -1, -1):
            self.run_first[o[lo[r], 0] + c, o[lo[r], 1] + c] = r
            self.run_count[o[lo[r], 0] + c, o[lo[r], 1] + c] += 1
        # reach in y of each stencil layer dz (-1: layer empty, e.g. dz != 0 in 2D)
        self.reach_y = np.full(2 * c + 1, -1, dtype=np.int64)
        for dz in np.unique(o[:, 0]):
            self.reach_y[dz + c] = np.abs(o[o[:, 0] == dz, 1]).max()
        # flat offset in h (voxel-major, n_columns per voxel) of entry u from its run's start
        run_start = np.repeat(lo, hi - lo)
        self.run_address = (self.column + (np.arange(len(o)) - run_start) * self.n_columns).astype(np.int64)

    def counts_bytes(self) -> int:
        """Bytes of the shell counts h of every voxel (n_voxels x n_columns of count_dtype)."""
        return int(np.prod(self.shape)) * self.n_columns * self.count_dtype.itemsize

    def kernel_arrays(self):
        """The arrays :func:`apply_flips_kernel` takes after ``n_flips``, in its argument order."""
        return (self.cutoff, self.reach_y, self.run_first, self.run_count, self.run_lo, self.run_hi,
                self.run_dx0, self.run_address)


def shell_counts(image: np.ndarray, stencil: Stencil) -> np.ndarray:
    """h[x, c] = number of tracked voxels (image == 1) at displacements of bin c + 1 from
    voxel x (x raveled in C order), shape (n_voxels, n_columns), of the smallest type
    holding the fullest shell (``stencil.count_dtype``): per bin, the periodic
    correlation of the image with the bin's shell by FFT, rounded (FFT error ~1e-10)."""
    import scipy.fft

    image = np.asarray(image)
    if image.shape != stencil.shape:
        raise ValueError(f"image shape {image.shape} != stencil shape {stencil.shape}")
    shape, d = stencil.shape, len(stencil.shape)
    h = np.empty((image.size, stencil.n_columns), dtype=stencil.count_dtype)
    spectrum = scipy.fft.rfftn(image.astype(np.float64))
    shell = np.zeros(shape)
    index = tuple(stencil.offsets[:, 3 - d + a] % shape[a] for a in range(d))
    order = np.argsort(stencil.column, kind="stable")
    starts = np.searchsorted(stencil.column[order], np.arange(stencil.n_columns + 1))
    for c in range(stencil.n_columns):
        members = order[starts[c]:starts[c + 1]]
        where = tuple(i[members] for i in index)
        shell[where] = 1.0
        # sum_v shell(v) I(x + v) = IFFT(FFT(I) conj(FFT(shell))); the shell is symmetric
        counts = scipy.fft.irfftn(spectrum * np.conj(scipy.fft.rfftn(shell)), s=shape)
        h[:, c] = np.rint(counts).reshape(-1)
        shell[where] = 0.0
    return h


@njit(cache=True, boundscheck=False)
def apply_flips_kernel(h, nz, ny, nx, flips, signs, n_flips, cutoff, reach_y, run_first, run_count,
                       run_lo, run_hi, run_dx0, run_address):
    """Add signs[k] to h[x, column] of every voxel x within the stencil of flips[k], k < n_flips
    (see the module docstring for the loop order; the arrays after ``n_flips`` are
    :meth:`Stencil.kernel_arrays`). For jitted callers; :func:`apply_flips` checks its input.

    Parameters
    ----------
    h : ndarray, shape (nz * ny * nx, n_columns)
        Shell counts (C-contiguous, ``Stencil.count_dtype``), updated in place.
    nz, ny, nx : int
        Image shape (nz = 1 for a 2D image).
    flips : ndarray of int64
        Raveled indices of the flipped voxels.
    signs : ndarray of int16
        +1 (voxel became tracked) or -1 per flip.
    n_flips : int
        Number of leading entries of ``flips`` / ``signs`` to apply.
    cutoff, reach_y, run_first, run_count, run_lo, run_hi, run_dx0, run_address
        The stencil tables of :meth:`Stencil.kernel_arrays`.
    """
    n_columns = h.shape[1]
    flat = h.reshape(-1)
    n_lines = nz * ny
    first = np.zeros(n_lines + 1, dtype=np.int64)  # flips of line l: entries first[l]:first[l+1]
    for k in range(n_flips):
        first[flips[k] // nx + 1] += 1
    for r in range(n_lines):
        first[r + 1] += first[r]
    # the flips sorted by line (counting sort, stable): row in its layer, column and sign, so
    # that the loop below divides by nothing (a division per flip and line cost ~8 % in 2D)
    sorted_y = np.empty(n_flips, dtype=np.int64)
    sorted_x = np.empty(n_flips, dtype=np.int64)
    # the sign in the counts' own type (-1 wraps to 2^bits - 1), so that the update is an
    # add of two equal unsigned types, truncated on store: exact modulo 2^bits
    sorted_sign = np.empty(n_flips, dtype=h.dtype)
    fill = first[:n_lines].copy()
    for k in range(n_flips):
        line = flips[k] // nx
        sorted_y[fill[line]] = line % ny
        sorted_x[fill[line]] = flips[k] - line * nx
        sorted_sign[fill[line]] = signs[k]
        fill[line] += 1
    line_size = nx * n_columns
    for line in range(n_lines):
        z = line // ny
        y = line - z * ny
        line_base = line * nx
        for dz in range(-cutoff, cutoff + 1):
            w = reach_y[dz + cutoff]
            if w < 0:
                continue
            z0 = z - dz  # layer of the flips whose stencil layer dz lands on layer z
            if z0 < 0:
                z0 += nz
            elif z0 >= nz:
                z0 -= nz
            layer = z0 * ny
            for part in range(2):  # source rows [y - w, y + w] as at most two unwrapped blocks
                if part == 0:
                    a = max(y - w, 0)
                    b = min(y + w, ny - 1)
                    unwrap = 0
                elif y - w < 0:
                    a = y - w + ny
                    b = ny - 1
                    unwrap = -ny  # a source row y0 there lies at y0 - ny
                elif y + w >= ny:
                    a = 0
                    b = y + w - ny
                    unwrap = ny
                else:
                    break
                for e in range(first[layer + a], first[layer + b + 1]):
                    dy = y - (sorted_y[e] + unwrap)
                    r0 = run_first[dz + cutoff, dy + cutoff]
                    x0 = sorted_x[e]
                    sign = sorted_sign[e]
                    for run in range(r0, r0 + run_count[dz + cutoff, dy + cutoff]):
                        lo = run_lo[run]
                        hi = run_hi[run]
                        x_first = x0 + run_dx0[run]  # image column of the run's first voxel
                        start = lo + max(0, -x_first)
                        stop = min(hi, lo + nx - x_first)
                        base = (line_base + x_first) * n_columns
                        # unsigned indices: numba skips the negative-index wrap (-25 % per
                        # increment with the unsigned sign, docs/debye3d.md)
                        for u in range(start, stop):
                            flat[np.uint64(base + run_address[u])] += sign
                        for u in range(lo, start):  # wrapped on the left
                            flat[np.uint64(base + line_size + run_address[u])] += sign
                        for u in range(stop, hi):  # wrapped on the right
                            flat[np.uint64(base - line_size + run_address[u])] += sign


def apply_flips(h: np.ndarray, stencil: Stencil, flips: np.ndarray, signs: np.ndarray,
                n_flips: int | None = None) -> None:
    """In place: h[x, column(x - f)] += sign for every flip f (raveled voxel index) and every
    voxel x of its stencil; the first ``n_flips`` entries of ``flips``/``signs`` (all by
    default).

    Parameters
    ----------
    h : ndarray, shape (n_voxels, n_columns)
        Shell counts of ``stencil.count_dtype`` (:func:`shell_counts`), updated in place.
    stencil : Stencil
        Stencil of the image shape and cutoff.
    flips : array_like of int
        Raveled voxel indices of the flips.
    signs : array_like of int
        +1 or -1 per flip.
    n_flips : int, optional
        Number of leading entries to apply (default: all).
    """
    flips = np.ascontiguousarray(flips, dtype=np.int64)
    signs = np.ascontiguousarray(signs, dtype=np.int16)
    n = flips.size if n_flips is None else int(n_flips)
    if h.shape != (int(np.prod(stencil.shape)), stencil.n_columns) or h.dtype != stencil.count_dtype:
        raise ValueError(f"h must be {stencil.count_dtype} of shape (n_voxels, n_columns) = "
                         f"({int(np.prod(stencil.shape))}, {stencil.n_columns}), got {h.dtype} {h.shape}")
    nz, ny, nx = stencil.shape3
    apply_flips_kernel(h, nz, ny, nx, flips, signs, n, *stencil.kernel_arrays())
