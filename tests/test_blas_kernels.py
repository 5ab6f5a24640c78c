"""The OpenBLAS kernels the workflow pins for its jobs (randmedia.blas_kernels)."""
from __future__ import annotations

import os
import subprocess
import sys

import pytest

from randmedia.blas_kernels import PINNED_KERNELS, REQUIRED_FLAGS, VARIABLE, cpu_flags, pin_blas_kernels

AVX2_FLAGS = frozenset({"sse2", "avx", "avx2", "fma", "bmi2"})


def test_pins_the_haswell_kernels_on_an_x86_64_cpu_with_avx2_and_fma():
    environ = {"PATH": "/bin"}
    assert pin_blas_kernels(environ, flags=AVX2_FLAGS, machine="x86_64") == PINNED_KERNELS == "Haswell"
    assert environ == {"PATH": "/bin", VARIABLE: "Haswell"}


def test_keeps_the_users_choice():
    environ = {VARIABLE: "SkylakeX"}
    assert pin_blas_kernels(environ, flags=AVX2_FLAGS, machine="x86_64") == "SkylakeX"
    assert environ == {VARIABLE: "SkylakeX"}


@pytest.mark.parametrize("flags, machine", [
    (AVX2_FLAGS - {"fma"}, "x86_64"),   # AVX2 without FMA: the Haswell kernels would not run
    (frozenset({"sse2", "avx"}), "x86_64"),
    (frozenset(), "x86_64"),            # no /proc/cpuinfo
    (AVX2_FLAGS, "aarch64"),
], ids=["no-fma", "avx-only", "no-flags", "arm"])
def test_leaves_the_choice_to_openblas_where_the_cpu_cannot_run_the_pinned_kernels(flags, machine):
    environ = {}
    assert pin_blas_kernels(environ, flags=flags, machine=machine) is None
    assert environ == {}


def test_cpu_flags_reads_the_first_cpus_flags(tmp_path):
    cpuinfo = tmp_path / "cpuinfo"
    cpuinfo.write_text("processor\t: 0\nmodel name\t: Some CPU\nflags\t\t: fpu sse2 avx2 fma\n\n"
                       "processor\t: 1\nflags\t\t: fpu\n")
    assert cpu_flags(cpuinfo) == {"fpu", "sse2", "avx2", "fma"}
    assert cpu_flags(tmp_path / "missing") == frozenset()


@pytest.mark.skipif(not REQUIRED_FLAGS <= cpu_flags(), reason="this CPU cannot run the pinned kernels")
def test_openblas_loads_the_pinned_kernels_in_a_fresh_process():
    """What the pin relies on: numpy's OpenBLAS reads the variable when it loads."""
    environ = {key: value for key, value in os.environ.items() if key != VARIABLE}
    pin_blas_kernels(environ)
    result = subprocess.run([sys.executable, "-c", "import numpy"], capture_output=True, text=True,
                            env={**environ, "OPENBLAS_VERBOSE": "2"})
    assert result.returncode == 0, result.stderr
    assert f"Core: {PINNED_KERNELS}" in result.stdout + result.stderr
