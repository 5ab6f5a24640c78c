# Beyond the papers (issue 13, docs/debye3d.md): three-dimensional Debye random media.
#
# * Yeong-Torquato constructions of the Debye S2 (Ma & Torquato 2020, Eq. 21) on periodic
#   N^3 voxels, Poisson-plane tessellations with the same S2 (non-periodic windows) and
#   digitized overlapping spheres (exact 3D descriptors: the estimators' validation);
# * per system: S2 against the exact one (Delta S2 of the constructions);
# * `snakemake debye3d`: not part of `all` (the papers); the system table is
#   randmedia.studies.debye3d.systems.

import re

from randmedia.studies.debye3d import LEVEL_SET_KINDS as DEBYE3D_LEVEL_SET_KINDS
from randmedia.studies.debye3d import systems as debye3d_systems

DEBYE3D_SYSTEMS = debye3d_systems(config["debye3d"])
DEBYE3D_SAMPLE = results_path("debye3d/{system}/sample{k}.nc")
DEBYE3D_S2 = results_path("debye3d/descriptors/{system}_S2.nc")


def debye3d_samples(wildcards):
    """The sample files of the wildcard's system."""
    n = DEBYE3D_SYSTEMS[wildcards.system]["n_samples"]
    return expand(DEBYE3D_SAMPLE, system=wildcards.system, k=range(n))


def debye3d_params(wildcards):
    """The wildcard's system parameters (randmedia.studies.debye3d.systems)."""
    return DEBYE3D_SYSTEMS[wildcards.system]


def debye3d_generator_params(wildcards):
    """What makes one sample: the system's parameters without the sample count and the
    descriptor ranges (more samples or other ranges leave the existing samples alone)."""
    return {key: value for key, value in DEBYE3D_SYSTEMS[wildcards.system].items()
            if key not in ("n_samples", "s2_r_max")}


#: the {system} wildcard of these rules: one of the table's systems (a per-rule constraint:
#: mrj2016 has {system} wildcards of its own)
DEBYE3D_SYSTEM = "|".join(re.escape(name) for name in DEBYE3D_SYSTEMS)


rule debye3d_sample:
    """One 3D medium: construction (checkpointed, resumes), Poisson-plane window or spheres."""
    input:
        code=script_sources("../scripts/debye3d/sample.py"),
    output:
        DEBYE3D_SAMPLE,
    wildcard_constraints:
        system=DEBYE3D_SYSTEM,
    params:
        system=debye3d_generator_params,
        seed=config["seed"],
    benchmark:
        results_path("debye3d/benchmarks/sample_{system}_sample{k}.tsv")
    log:
        results_path("debye3d/logs/sample_{system}_sample{k}.log"),
    threads: 1
    resources:
        mem_mb=2000,
    script:
        "../scripts/debye3d/sample.py"


rule debye3d_s2:
    """S2 of the void of a system's samples against the exact S2; Delta S2 of the constructions."""
    input:
        samples=debye3d_samples,
        code=script_sources("../scripts/debye3d/s2.py"),
    output:
        DEBYE3D_S2,
    wildcard_constraints:
        system=DEBYE3D_SYSTEM,
    params:
        system=debye3d_params,
    benchmark:
        results_path("debye3d/benchmarks/s2_{system}.tsv")
    log:
        results_path("debye3d/logs/s2_{system}.log"),
    script:
        "../scripts/debye3d/s2.py"


DEBYE3D_SURFACE = results_path("debye3d/descriptors/{system}_surface.nc")
DEBYE3D_PORES = results_path("debye3d/descriptors/{system}_pores.nc")
DEBYE3D_CHORDS = results_path("debye3d/descriptors/{system}_chords.nc")
#: the periodic systems, which get the level-set descriptors (randmedia.studies.debye3d)
DEBYE3D_LEVEL_SET_SYSTEMS = [name for name, p in DEBYE3D_SYSTEMS.items()
                             if p["kind"] in DEBYE3D_LEVEL_SET_KINDS]
DEBYE3D_LEVEL_SET_SYSTEM = "|".join(re.escape(name) for name in DEBYE3D_LEVEL_SET_SYSTEMS)


rule debye3d_level_set:
    """F_sv, F_ss, s, wrapping and pore sizes of a periodic system on level sets tuned to the exact s."""
    input:
        samples=debye3d_samples,
        code=script_sources("../scripts/debye3d/level_set.py"),
    output:
        surface=DEBYE3D_SURFACE,
        pores=DEBYE3D_PORES,
    wildcard_constraints:
        system=DEBYE3D_LEVEL_SET_SYSTEM,
    params:
        system=debye3d_params,
        interface=config["debye3d"]["interface"],
        seed=config["seed"],
    benchmark:
        results_path("debye3d/benchmarks/level_set_{system}.tsv")
    log:
        results_path("debye3d/logs/level_set_{system}.log"),
    threads: 1
    resources:
        mem_mb=6000,
    script:
        "../scripts/debye3d/level_set.py"


def debye3d_chords_level_set(wildcards):
    """The surface file whose tuned level set the lines walk ("tuned" sigma), else nothing."""
    if config["debye3d"]["chords"]["sigma"] == "tuned":
        return [DEBYE3D_SURFACE.format(system=wildcards.system)]
    return []


rule debye3d_chords:
    """L(z) and p(z) of the void of a periodic system, lines in many directions."""
    input:
        samples=debye3d_samples,
        surface=debye3d_chords_level_set,
        code=script_sources("../scripts/debye3d/chords.py"),
    output:
        DEBYE3D_CHORDS,
    wildcard_constraints:
        system=DEBYE3D_LEVEL_SET_SYSTEM,
    params:
        system=debye3d_params,
        chords=config["debye3d"]["chords"],
        seed=config["seed"],
    benchmark:
        results_path("debye3d/benchmarks/chords_{system}.tsv")
    log:
        results_path("debye3d/logs/chords_{system}.log"),
    threads: 1
    resources:
        mem_mb=2000,
    script:
        "../scripts/debye3d/chords.py"


DEBYE3D_FIGURE = results_path("debye3d/figures/{name}.pdf")
DEBYE3D_DEBYE_SYSTEMS = [name for name, p in DEBYE3D_SYSTEMS.items() if p["kind"] != "spheres"]


def debye3d_figure_outputs(name):
    """{name}.pdf and the PNG beside it."""
    pdf = DEBYE3D_FIGURE.format(name=name)
    return {"pdf": pdf, "png": pdf[: -len(".pdf")] + ".png"}


rule debye3d_figure_media:
    """Mid-plane slices of sample 0 of every Debye system."""
    input:
        samples=expand(DEBYE3D_SAMPLE, system=DEBYE3D_DEBYE_SYSTEMS, k=0),
        code=script_sources("../scripts/debye3d/figure.py"),
    output:
        **debye3d_figure_outputs("media"),
    params:
        figure="media",
        settings={"a": config["debye3d"]["media"]["a"]},
    log:
        results_path("debye3d/logs/figure_media.log"),
    script:
        "../scripts/debye3d/figure.py"


rule debye3d_figure_s2:
    """chi_V of every system against the exact one."""
    input:
        s2=expand(DEBYE3D_S2, system=DEBYE3D_SYSTEMS),
        code=script_sources("../scripts/debye3d/figure.py"),
    output:
        **debye3d_figure_outputs("s2"),
    params:
        figure="s2",
    log:
        results_path("debye3d/logs/figure_s2.log"),
    script:
        "../scripts/debye3d/figure.py"


DEBYE3D_FIGURES = ("media", "s2", "surface", "pores", "chords")


for _name, _files in (("surface", DEBYE3D_SURFACE), ("pores", DEBYE3D_PORES), ("chords", DEBYE3D_CHORDS)):

    rule:
        name:
            f"debye3d_figure_{_name}"
        input:
            descriptors=expand(_files, system=DEBYE3D_LEVEL_SET_SYSTEMS),
            code=script_sources("../scripts/debye3d/figure.py"),
        output:
            **debye3d_figure_outputs(_name),
        params:
            figure=_name,
        log:
            results_path(f"debye3d/logs/figure_{_name}.log"),
        script:
            "../scripts/debye3d/figure.py"


rule debye3d_comparison:
    """Every system against exact values, the issue's goals and the 3D conjectures."""
    input:
        s2=expand(DEBYE3D_S2, system=DEBYE3D_SYSTEMS),
        surface=expand(DEBYE3D_SURFACE, system=DEBYE3D_LEVEL_SET_SYSTEMS),
        pores=expand(DEBYE3D_PORES, system=DEBYE3D_LEVEL_SET_SYSTEMS),
        chords=expand(DEBYE3D_CHORDS, system=DEBYE3D_LEVEL_SET_SYSTEMS),
        code=script_sources("../scripts/debye3d/comparison.py"),
    output:
        comparison=results_path("debye3d/comparison.csv"),
        notes=results_path("debye3d/comparison_notes.csv"),
    params:
        k_sigma=config["comparison"]["k_sigma"],
    log:
        results_path("debye3d/logs/comparison.log"),
    script:
        "../scripts/debye3d/comparison.py"


DEBYE3D_TARGETS = [
    *expand(DEBYE3D_S2, system=DEBYE3D_SYSTEMS),
    *[path for name in DEBYE3D_FIGURES for path in debye3d_figure_outputs(name).values()],
    *rules.debye3d_comparison.output,
]


rule debye3d:
    """Every output of the 3D Debye study (beyond the papers)."""
    input:
        DEBYE3D_TARGETS,
