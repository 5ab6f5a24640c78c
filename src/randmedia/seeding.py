"""One reproducible random stream per sample.

The seed of a sample is derived from (config seed, paper, system, sample
index) with :class:`numpy.random.SeedSequence`, so a sample's numbers depend
neither on how many cores run the workflow nor on the order of its jobs, and
two systems never share a stream. The derived integer is what the data files
record as ``seed``: ``numpy.random.default_rng(seed)`` regenerates the sample.
"""

from __future__ import annotations

import zlib

import numpy as np


def _name_key(name: str) -> int:
    # crc32 is stable across Python processes (unlike hash()).
    return zlib.crc32(name.encode("utf-8"))


def sample_seed(base_seed: int, paper: str, system: str, index: int) -> int:
    """Integer seed (< 2**63, fits a netCDF int64 attribute) for one sample.

    Parameters
    ----------
    base_seed : int
        Seed of the whole workflow (>= 0).
    paper : str
        Paper key (e.g. "mrj2016").
    system : str
        System name within the paper.
    index : int
        Sample index (>= 0).

    Returns
    -------
    int
        Seed derived by numpy SeedSequence from (base_seed, paper, system, index).
    """
    if base_seed < 0 or index < 0:
        raise ValueError(f"seed and sample index must be >= 0, got {base_seed}, {index}")
    sequence = np.random.SeedSequence(
        entropy=base_seed, spawn_key=(_name_key(paper), _name_key(system), index)
    )
    return int(sequence.generate_state(1, np.uint64)[0] >> np.uint64(1))


def sample_rng(seed: int) -> np.random.Generator:
    """The generator a sample with recorded ``seed`` was drawn from."""
    return np.random.default_rng(seed)
