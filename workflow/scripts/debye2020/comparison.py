"""Rule debye2020_comparison: results/debye2020/comparison.csv."""
from randmedia.jobs import start_job

log = start_job(snakemake)  # noqa: F821

from randmedia.compare import comparison_frame, read_reference  # noqa: E402
from randmedia.compare.debye2020 import (lineal_size_rows, overlapping_disks_chord_rows,  # noqa: E402
                                         overlapping_disks_s2_rows)
from randmedia.describe.chords import CHORDS  # noqa: E402
from randmedia.describe.two_phase import TWO_POINT  # noqa: E402
from randmedia.io import read_dataset, write_csv  # noqa: E402

params = dict(snakemake.params.items())  # noqa: F821
inputs = snakemake.input  # noqa: F821
s2 = read_dataset(inputs.s2, TWO_POINT, attrs=["r_max", "bin_width"])
rows = overlapping_disks_s2_rows(
    s2, radius=params["radius"], phi2=params["phi2"], image_shape=(params["L"], params["L"]),
    compare_r_max=params["compare_r_max"], k_sigma=params["k_sigma"],
)
rows += overlapping_disks_chord_rows(
    read_dataset(inputs.disk_chords, CHORDS), radius=params["radius"], phi2=params["phi2"],
    compare_z_max=params["compare_r_max"], k_sigma=params["k_sigma"],
)
reference = read_reference(inputs.quoted, ["quantity", "value"])
rows += lineal_size_rows(read_dataset(inputs.fits), reference, k_sigma=params["k_sigma"])
frame = comparison_frame(rows)
log.info("%d rows, %d passed", len(frame), int(frame["passed"].sum()))
write_csv(frame, snakemake.output[0])  # noqa: F821
