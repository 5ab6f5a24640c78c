"""Rule debye2020_media_sample: one Debye random medium by the accelerated YT construction."""
from randmedia.jobs import start_job

log = start_job(snakemake)

import functools
from pathlib import Path

from randmedia.generate import phase_image_dataset
from randmedia.generate.yeong_torquato import AnnealingSchedule, construct
from randmedia.io import write_dataset
from randmedia.seeding import sample_rng, sample_seed
from randmedia.theory.debye import debye_s2

params = dict(snakemake.params.items())
index = int(snakemake.wildcards.k)
phi2 = params["phi2"]
seed = sample_seed(params["seed"], "debye2020", f"debye_phi{phi2:g}", index)
output = Path(snakemake.output[0])
result = construct(
    functools.partial(debye_s2, phi2=phi2, a=params["a"]), phi2, params["L"], params["lc"],
    sample_rng(seed), AnnealingSchedule(**params["schedule"]),
    checkpoint=output.with_name(f".{output.stem}.checkpoint.npz"), log=log,
)
log.info("converged: Delta S2 = %.3g after %d trials (%d accepted) in %.1f s",
         result.delta_s2, result.stats["trials"], result.stats["accepted"], result.stats["seconds"])
dataset = phase_image_dataset(result.image, {
    "phi2": phi2, "a": params["a"], "lc": params["lc"], "L": params["L"], "sample": index,
    "delta_S2": result.delta_s2, "trials": result.stats["trials"],
    "accepted": result.stats["accepted"], "construction_seconds": result.stats["seconds"],
    "construction_cpu_seconds": result.stats["cpu_seconds"],
})
write_dataset(dataset, output, rule=snakemake.rule, seed=seed,
              config={**params, "sample": index})
