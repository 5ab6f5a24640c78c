"""Rule debye2020_numbers: results/debye2020/tables/numbers.csv."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

import pandas as pd  # noqa: E402

from randmedia.compare.debye2020 import construction_numbers, lineal_numbers  # noqa: E402
from randmedia.describe.two_phase import TWO_POINT  # noqa: E402
from randmedia.io import VariableSpec, read_dataset, write_csv  # noqa: E402

spec = {**TWO_POINT, "delta_S2": VariableSpec(("sample",), "1"),
        "delta_S2_full": VariableSpec(("sample",), "1")}
s2 = {}
for path in snakemake.input.s2:  # noqa: F821
    ds = read_dataset(path, spec, attrs=["phi2"])
    s2[float(ds.attrs["phi2"])] = ds
fits = read_dataset(snakemake.input.fits)  # noqa: F821
write_csv(pd.concat([construction_numbers(s2), lineal_numbers(fits)], ignore_index=True),
          snakemake.output[0])  # noqa: F821
