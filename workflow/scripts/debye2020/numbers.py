"""Rule debye2020_numbers: results/debye2020/tables/numbers.csv."""
from randmedia.jobs import start_job

log = start_job(snakemake)

import pandas as pd

from randmedia.compare.debye2020 import (construction_numbers, level_set_numbers,
                                         lineal_numbers, surface_pore_numbers)
from randmedia.describe.pore_size import PORES
from randmedia.describe.surface import SURFACE
from randmedia.describe.two_phase import TWO_POINT
from randmedia.io import VariableSpec, read_dataset, write_csv

inputs = snakemake.input
spec = {**TWO_POINT, "delta_S2": VariableSpec(("sample",), "1"),
        "delta_S2_full": VariableSpec(("sample",), "1")}
s2 = {}
for path in inputs.s2:
    ds = read_dataset(path, spec, attrs=["phi2"])
    s2[float(ds.attrs["phi2"])] = ds
tables = [construction_numbers(s2), lineal_numbers(read_dataset(inputs.fits)),
          surface_pore_numbers(read_dataset(inputs.surface_pore_fits, attrs=["a"]))]
for surface_path, pores_path in zip(inputs.models_surface, inputs.models_pores):
    surface = read_dataset(surface_path, SURFACE,
                           attrs=["system", "model", "phi2", "sigma", "s_exact", "length_scale"])
    tables.append(level_set_numbers(surface.attrs["system"], surface, read_dataset(pores_path, PORES)))
write_csv(pd.concat(tables, ignore_index=True), snakemake.output[0])
