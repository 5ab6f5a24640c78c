"""Does a phase of a periodic image percolate? Clusters that wrap around the torus.

On a finite periodic image the honest finite-size signature of percolation is
a cluster that *wraps*: it connects to its own periodic copy, i.e. contains a
closed path with a non-zero winding number (Newman & Ziff, PRE 64, 016706
(2001)). Clusters are labelled with 4-connectivity on the grid (the fine grid
of a level set, where the smooth field leaves no diagonal ambiguity worth the
name); labels touching across the periodic boundary are joined, each label
carrying the lattice shift of its copy; a label reached twice with different
shifts closes a wrapping loop in the direction of the shift difference.
Dimension-generic (any number of axes).
"""

from __future__ import annotations

from collections import defaultdict, deque

import numpy as np
from scipy import ndimage


def wrapping_directions(region: np.ndarray) -> np.ndarray:
    """For each axis of the periodic boolean grid ``region``, whether some cluster of it wraps
    around the torus along that axis (bool array of length ndim)."""
    region = np.asarray(region, dtype=bool)
    labels, n = ndimage.label(region)  # face connectivity
    ndim = region.ndim
    wraps = np.zeros(ndim, dtype=bool)
    if n == 0:
        return wraps
    # periodic contacts: last slice of an axis touches the first slice, shift +1 along it
    edges = defaultdict(set)
    for axis in range(ndim):
        first = np.take(labels, 0, axis=axis).ravel()
        last = np.take(labels, -1, axis=axis).ravel()
        both = (first > 0) & (last > 0)
        shift = tuple(1 if a == axis else 0 for a in range(ndim))
        for a, b in set(zip(last[both].tolist(), first[both].tolist())):
            edges[a].add((b, shift))
            edges[b].add((a, tuple(-s for s in shift)))
    offset = {}
    for start in edges:
        if start in offset:
            continue
        offset[start] = (0,) * ndim
        queue = deque([start])
        while queue:
            u = queue.popleft()
            for v, shift in edges[u]:
                expected = tuple(o + s for o, s in zip(offset[u], shift))
                if v not in offset:
                    offset[v] = expected
                    queue.append(v)
                elif offset[v] != expected:
                    wraps |= np.array([e != o for e, o in zip(expected, offset[v])])
    return wraps
