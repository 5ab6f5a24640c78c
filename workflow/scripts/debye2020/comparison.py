"""Rule debye2020_comparison: results/debye2020/comparison.csv."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

from randmedia.compare import comparison_frame  # noqa: E402
from randmedia.compare.debye2020 import overlapping_disks_s2_rows  # noqa: E402
from randmedia.describe.two_phase import TWO_POINT  # noqa: E402
from randmedia.io import read_dataset, write_csv  # noqa: E402

params = dict(snakemake.params.items())  # noqa: F821
s2 = read_dataset(snakemake.input.s2, TWO_POINT, attrs=["r_max", "bin_width"])  # noqa: F821
rows = overlapping_disks_s2_rows(
    s2, radius=params["radius"], phi2=params["phi2"], image_shape=(params["L"], params["L"]),
    compare_r_max=params["compare_r_max"], k_sigma=params["k_sigma"],
)
frame = comparison_frame(rows)
log.info("%d rows, %d passed", len(frame), int(frame["passed"].sum()))
write_csv(frame, snakemake.output[0])  # noqa: F821
