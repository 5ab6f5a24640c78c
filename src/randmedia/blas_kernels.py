"""The OpenBLAS kernels the workflow's jobs run with, pinned so that a packing is the same on
every x86-64 CPU with AVX2.

OpenBLAS (numpy's, and the one ``highspy-extras`` gives HiGHS' HiPO) picks its kernels by CPU
when it loads, and the LP trajectory of an MRJ packing is chaotic in the last bit: from the quick
packing's seed the AVX-512 kernels made 396 LPs, the Haswell kernels 432, the Prescott kernels 387
(docs/mrj2016.md, *LP solver*). So the workflow (workflow/rules/common.smk) pins the Haswell
kernels, which every x86-64 CPU with AVX2 and FMA runs, for every job it starts (``OPENBLAS_CORETYPE``, read by OpenBLAS when it
loads in the job's process). A value the user set is kept; on a CPU without AVX2 or FMA (or not
x86-64) nothing is pinned and OpenBLAS chooses, so a packing made there is another draw of the
same ensemble rather than the same packing.
"""
from __future__ import annotations

import os
import platform
from collections.abc import MutableMapping
from pathlib import Path

#: the environment variable OpenBLAS reads when it loads
VARIABLE = "OPENBLAS_CORETYPE"
#: the pinned kernels (tests/data's quick packing was made with them)
PINNED_KERNELS = "Haswell"
#: the instruction sets the pinned kernels need
REQUIRED_FLAGS = frozenset({"avx2", "fma"})
_X86_64 = ("x86_64", "amd64")


def cpu_flags(cpuinfo: Path = Path("/proc/cpuinfo")) -> frozenset[str]:
    """The instruction-set flags of the first CPU in ``cpuinfo`` (empty where there is none)."""
    try:
        text = cpuinfo.read_text()
    except OSError:
        return frozenset()
    for line in text.splitlines():
        if line.startswith("flags"):
            return frozenset(line.split(":", 1)[1].split())
    return frozenset()


def pin_blas_kernels(environ: MutableMapping[str, str] | None = None, *,
                     flags: frozenset[str] | None = None, machine: str | None = None) -> str | None:
    """Set ``OPENBLAS_CORETYPE`` to :data:`PINNED_KERNELS` in ``environ`` (default: this
    process's environment, which the jobs it starts inherit) where the CPU runs them.

    Returns the kernels the jobs will use: the user's value if one is set, the pinned ones,
    or None (an unsuitable CPU: OpenBLAS chooses). ``flags`` and ``machine`` default to this
    machine's (:func:`cpu_flags`, :func:`platform.machine`)."""
    environ = os.environ if environ is None else environ
    if environ.get(VARIABLE):
        return environ[VARIABLE]
    machine = platform.machine() if machine is None else machine
    flags = cpu_flags() if flags is None else flags
    if machine.lower() not in _X86_64 or not REQUIRED_FLAGS <= flags:
        return None
    environ[VARIABLE] = PINNED_KERNELS
    return PINNED_KERNELS
