"""Rule debye3d_sample: one 3D medium of a system -- a Yeong-Torquato construction of the
Debye S2 (Eq. 21; periodic), a Poisson-plane tessellation with the same S2 (window), or
digitized overlapping spheres (periodic; the estimators' exact reference)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

import functools
from pathlib import Path

from randmedia.generate.voxel_images import voxel_image_dataset
from randmedia.io import write_dataset
from randmedia.seeding import sample_rng, sample_seed

params = dict(snakemake.params.system)
index = int(snakemake.wildcards.k)
system = snakemake.wildcards.system
kind, phi2, side = params["kind"], params["phi2"], params["N"]
seed = sample_seed(snakemake.params.seed, "debye3d", system, index)
rng = sample_rng(seed)
output = Path(snakemake.output[0])
attrs = {"kind": kind, "phi2": phi2, "N": side, "sample": index}
if kind == "yt":
    from randmedia.generate.yeong_torquato import AnnealingSchedule, construct
    from randmedia.theory.debye import debye_s2

    result = construct(
        functools.partial(debye_s2, phi2=phi2, a=params["a"]), phi2, (side,) * 3, params["lc"],
        rng, AnnealingSchedule(**params["schedule"]),
        checkpoint=output.with_name(f".{output.stem}.checkpoint.npz"), log=log,
    )
    stats = result.stats
    log.info("converged: Delta S2 = %.3g after %d trials (%d accepted) in %.1f s",
             result.delta_s2, stats["trials"], stats["accepted"], stats["seconds"])
    image = result.image
    attrs.update({"a": params["a"], "lc": params["lc"], "delta_S2": result.delta_s2,
                  "trials": stats["trials"], "accepted": stats["accepted"],
                  "construction_seconds": stats["seconds"],
                  "construction_cpu_seconds": stats["cpu_seconds"]})
elif kind == "planes":
    from randmedia.generate.poisson_planes import poisson_plane_image

    image = poisson_plane_image(rng, (side,) * 3, params["a"], phi2)
    attrs["a"] = params["a"]
elif kind == "spheres":
    from randmedia.generate.balls import overlapping_balls_image

    image = overlapping_balls_image(rng, side, params["radius"], phi2, 3)
    attrs["radius"] = params["radius"]
else:
    raise ValueError(f"unknown debye3d system kind {kind!r}")
log.info("%s sample %d: seed %d, realized phi2 = %.4f", system, index, seed, image.mean())
write_dataset(voxel_image_dataset(image, attrs, periodic=kind != "planes"), output,
              rule=snakemake.rule, seed=seed, config={**params, "sample": index})
