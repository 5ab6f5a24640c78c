"""Rule debye2020_numbers: results/debye2020/tables/numbers.csv."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

from randmedia.compare.debye2020 import construction_numbers  # noqa: E402
from randmedia.describe.two_phase import TWO_POINT  # noqa: E402
from randmedia.io import VariableSpec, read_dataset, write_csv  # noqa: E402

spec = {**TWO_POINT, "delta_S2": VariableSpec(("sample",), "1"),
        "delta_S2_full": VariableSpec(("sample",), "1")}
s2 = {}
for path in snakemake.input.s2:  # noqa: F821
    ds = read_dataset(path, spec, attrs=["phi2"])
    s2[float(ds.attrs["phi2"])] = ds
write_csv(construction_numbers(s2), snakemake.output[0])  # noqa: F821
