#!/usr/bin/env bash
# Proof of profiles/slurm on a real (local, single-node) SLURM: `make slurm-check`.
#
# Installs and starts SLURM (profiles/slurm/local_slurm.sh), runs a small target of each
# paper on the quick config twice -- through the SLURM profile and locally -- in two
# fresh copies of the workflow, checks that every output is identical (netCDF data
# variables and coordinates, CSV files, byte for byte), and stops SLURM. Every step is
# bounded by a timeout; a hang is a failure.
set -euo pipefail
cd "$(dirname "$0")/../.."
REPO=$(pwd)
PYTHON=${PYTHON:-$REPO/.venv/bin/python}
WORK=$(mktemp -d /tmp/randmedia-slurm-check.XXXXXX)
TARGETS=(
    results/quick/debye2020/descriptors/media_phi0.3_S2.nc   # two Debye constructions + S2
    results/quick/sphere2019/descriptors/uddpar_a3_R5.nc     # a Monte Carlo fluid + cap statistics
    results/quick/mrj2016/configs/mrj/sample0.nc             # a strictly jammed packing (N = 100)
    results/quick/mrj2016/configs/overlapping/sample0.nc     # overlapping spheres
)
export SLURM_STATE=$WORK/slurm

cleanup() { profiles/slurm/local_slurm.sh stop >/dev/null 2>&1 || true; }
trap cleanup EXIT

"$PYTHON" -c "import snakemake_executor_plugin_slurm" 2>/dev/null \
    || timeout 300 "$PYTHON" -m pip install --quiet 'snakemake-executor-plugin-slurm>=2.8'
profiles/slurm/local_slurm.sh install
timeout 120 profiles/slurm/local_slurm.sh start

for run in local slurm; do
    mkdir -p "$WORK/$run"
    cp -r Snakefile workflow config profiles src "$WORK/$run/"
done
started=$(date +%s)
(cd "$WORK/local" && timeout 900 "$PYTHON" -m snakemake --cores 2 \
    --configfile config/quick.yaml -- "${TARGETS[@]}" > "$WORK/local.log" 2>&1) \
    || { tail -30 "$WORK/local.log"; echo "slurm-check: the local run failed"; exit 1; }
local_seconds=$(( $(date +%s) - started ))
started=$(date +%s)
(cd "$WORK/slurm" && timeout 1200 "$PYTHON" -m snakemake --profile profiles/slurm \
    --configfile config/quick.yaml -- "${TARGETS[@]}" > "$WORK/slurm.log" 2>&1) \
    || { tail -30 "$WORK/slurm.log"; echo "slurm-check: the SLURM run failed or hung (log: $WORK/slurm.log)"; exit 1; }
slurm_seconds=$(( $(date +%s) - started ))
jobs=$(grep -c "submitted with SLURM jobid" "$WORK/slurm.log" || true)

"$PYTHON" - "$WORK/local" "$WORK/slurm" <<'PY'
import sys
from pathlib import Path

from randmedia.io import read_dataset

local, slurm = map(Path, sys.argv[1:])
files = sorted(p.relative_to(local) for p in (local / "results").rglob("*") if p.is_file()
               and p.suffix in (".nc", ".csv"))
if not files:
    sys.exit("slurm-check: the local run made no outputs")
for relative in files:
    other = slurm / relative
    if not other.is_file():
        sys.exit(f"slurm-check: {relative} is missing from the SLURM run")
    if relative.suffix == ".csv":
        same = (local / relative).read_bytes() == other.read_bytes()
    else:
        a, b = read_dataset(local / relative), read_dataset(other)
        # provenance attrs (rule, git state, run times) may differ; the data may not
        same = set(a.variables) == set(b.variables) and all(
            a[name].equals(b[name]) for name in a.variables)
    if not same:
        sys.exit(f"slurm-check: {relative} differs between the local and the SLURM run")
print(f"slurm-check: {len(files)} output files identical (netCDF data and coordinates, CSV bytes)")
PY
echo "slurm-check: passed ($jobs SLURM jobs; local run ${local_seconds} s, SLURM run ${slurm_seconds} s)"
