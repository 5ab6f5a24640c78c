"""Rule debye2020_comparison: results/debye2020/comparison.csv and comparison_notes.csv."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from randmedia.compare import COLUMNS, checked_row, comparison_frame, notes_frame, read_reference
from randmedia.compare.debye2020 import (REASON_HARD_DISKS, construction_rows, lineal_size_rows,
                                         overlapping_disks_chord_rows, overlapping_disks_pore_rows,
                                         overlapping_disks_s2_rows, overlapping_disks_surface_rows,
                                         parameter_rows, surface_pore_rows)
from randmedia.describe.chords import CHORDS
from randmedia.describe.pore_size import PORES
from randmedia.describe.surface import SURFACE
from randmedia.describe.two_phase import TWO_POINT
from randmedia.io import VariableSpec, read_dataset, write_csv

params = dict(snakemake.params.items())
inputs = snakemake.input
k_sigma = params["k_sigma"]
disks = params["overlapping_disks"]
radius, phi2 = disks["radius"], disks["phi2"]
reference = read_reference(inputs.quoted, ["quantity", "value"])
s2 = read_dataset(inputs.s2, TWO_POINT, attrs=["r_max", "bin_width"])
rows = overlapping_disks_s2_rows(
    s2, radius=radius, phi2=phi2, image_shape=(disks["L"], disks["L"]),
    compare_r_max=params["compare_r_max"], k_sigma=k_sigma,
)
rows += overlapping_disks_chord_rows(
    read_dataset(inputs.disk_chords, CHORDS), radius=radius, phi2=phi2,
    compare_z_max=params["compare_r_max"], k_sigma=k_sigma,
)
surface = read_dataset(inputs.disk_surface, SURFACE,
                       attrs=["supersample", "image_side", "r_max", "bin_width"])
rows += overlapping_disks_surface_rows(surface, radius=radius, phi2=phi2,
                                       compare_r_max=params["compare_r_max"],
                                       r_min=params["formula_r_min"], k_sigma=k_sigma)
rows += overlapping_disks_pore_rows(read_dataset(inputs.disk_pores, PORES, attrs=["delta_bin_width"]),
                                    radius=radius, phi2=phi2, k_sigma=k_sigma)
rows += lineal_size_rows(read_dataset(inputs.fits), reference, k_sigma=k_sigma)
rows += parameter_rows(reference, params["media"], disks, params["hard_disks_phi2"])
spec = {"delta_S2": VariableSpec(("sample",), "1"), "delta_S2_full": VariableSpec(("sample",), "1")}
media_s2 = {}
for path in inputs.media_s2:
    ds = read_dataset(path, spec, attrs=["phi2"])
    media_s2[float(ds.attrs["phi2"])] = ds
rows += construction_rows(reference, media_s2, k_sigma=k_sigma)
fits = read_dataset(inputs.surface_pore_fits,
                    attrs=["percolation_crossing", "percolation_crossing_err", "percolation_bracket"])
rows += surface_pore_rows(reference, fits, a=params["media"]["a"], k_sigma=k_sigma)
# equilibrium hard disks: contact-value pressure against the 2D equation of state, decorrelation
rows += [checked_row(row, k_sigma=k_sigma, reason_if_failed=REASON_HARD_DISKS)
         for row in read_reference(inputs.hard_disks_validation, COLUMNS).to_dict("records")]
frame = comparison_frame(rows)
log.info("%d rows, %d passed", len(frame), int(frame["passed"].sum()))
for _, row in frame[~frame["passed"]].iterrows():
    log.info("not passed: %s [%s]: published %.5g, ours %.5g +- %.2g (tolerance %.2g)", row["quantity"],
             row["key"], row["published"], row["ours"], row["ours_sem"], row["tolerance"])
write_csv(frame, snakemake.output.comparison)
write_csv(notes_frame(rows), snakemake.output.notes)
