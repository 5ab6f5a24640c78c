# Beyond the papers (issue 13, docs/debye3d.md): three-dimensional Debye random media.
#
# * Yeong-Torquato constructions of the Debye S2 (Ma & Torquato 2020, Eq. 21) on periodic
#   N^3 voxels, Poisson-plane tessellations with the same S2 (non-periodic windows) and
#   digitized overlapping spheres (exact 3D descriptors: the estimators' validation);
# * per system: S2 against the exact one (Delta S2 of the constructions), level-set surface
#   functions, pores and chords (window estimators for the windows);
# * `snakemake debye3d`: not part of `all` (the papers); the system table is
#   randmedia.config.debye3d_systems.

import re

from randmedia.config import debye3d_systems
from randmedia.studies.debye3d import LEVEL_SET_KINDS as DEBYE3D_LEVEL_SET_KINDS
from randmedia.studies.debye3d import WINDOW_KINDS as DEBYE3D_WINDOW_KINDS

DEBYE3D_SYSTEMS = debye3d_systems(config["debye3d"])
DEBYE3D_SAMPLE = results_path("debye3d/{system}/sample{k}.nc")
DEBYE3D_S2 = results_path("debye3d/descriptors/{system}_S2.nc")


#: per system: its sample files, and what makes one sample -- the system's parameters without
#: the sample count and the descriptor ranges (more samples or other ranges leave the existing
#: samples alone)
DEBYE3D_SAMPLES = {name: expand(DEBYE3D_SAMPLE, system=name, k=range(p["n_samples"]))
                   for name, p in DEBYE3D_SYSTEMS.items()}
DEBYE3D_GENERATOR_PARAMS = {name: {key: value for key, value in p.items()
                                   if key not in ("n_samples", "s2_r_max")}
                            for name, p in DEBYE3D_SYSTEMS.items()}
#: chords walk the surface functions' level set when config debye3d.chords.sigma is "tuned"
DEBYE3D_CHORDS_TUNED = config["debye3d"]["chords"]["sigma"] == "tuned"


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
        system=lambda wildcards: DEBYE3D_GENERATOR_PARAMS[wildcards.system],
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
        samples=lambda wildcards: DEBYE3D_SAMPLES[wildcards.system],
        code=script_sources("../scripts/debye3d/s2.py"),
    output:
        DEBYE3D_S2,
    wildcard_constraints:
        system=DEBYE3D_SYSTEM,
    params:
        system=lambda wildcards: DEBYE3D_SYSTEMS[wildcards.system],
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
        samples=lambda wildcards: DEBYE3D_SAMPLES[wildcards.system],
        code=script_sources("../scripts/debye3d/level_set.py"),
    output:
        surface=DEBYE3D_SURFACE,
        pores=DEBYE3D_PORES,
    wildcard_constraints:
        system=DEBYE3D_LEVEL_SET_SYSTEM,
    params:
        system=lambda wildcards: DEBYE3D_SYSTEMS[wildcards.system],
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


DEBYE3D_WINDOW_SYSTEMS = [name for name, p in DEBYE3D_SYSTEMS.items() if p["kind"] in DEBYE3D_WINDOW_KINDS]


rule debye3d_window_surface:
    """F_sv, F_ss and s of a Poisson-plane system's windows by minus-sampling (tuned to the exact s)."""
    input:
        samples=lambda wildcards: DEBYE3D_SAMPLES[wildcards.system],
        code=script_sources("../scripts/debye3d/window_surface.py"),
    output:
        DEBYE3D_SURFACE,
    wildcard_constraints:
        system="|".join(re.escape(name) for name in DEBYE3D_WINDOW_SYSTEMS) or "no-window-system",
    params:
        system=lambda wildcards: DEBYE3D_SYSTEMS[wildcards.system],
        interface=config["debye3d"]["interface"],
    benchmark:
        results_path("debye3d/benchmarks/window_surface_{system}.tsv")
    log:
        results_path("debye3d/logs/window_surface_{system}.log"),
    threads: 1
    resources:
        mem_mb=6000,
    script:
        "../scripts/debye3d/window_surface.py"


rule debye3d_window_pores:
    """F(delta), P(delta), <delta> of a Poisson-plane system's windows (reduced-sample estimator)
    on the level set of its window surface functions."""
    input:
        samples=lambda wildcards: DEBYE3D_SAMPLES[wildcards.system],
        surface=DEBYE3D_SURFACE,
        code=script_sources("../scripts/debye3d/window_pores.py"),
    output:
        DEBYE3D_PORES,
    wildcard_constraints:
        system="|".join(re.escape(name) for name in DEBYE3D_WINDOW_SYSTEMS) or "no-window-system",
    params:
        system=lambda wildcards: DEBYE3D_SYSTEMS[wildcards.system],
        interface=config["debye3d"]["interface"],
        seed=config["seed"],
    benchmark:
        results_path("debye3d/benchmarks/window_pores_{system}.tsv")
    log:
        results_path("debye3d/logs/window_pores_{system}.log"),
    threads: 1
    resources:
        mem_mb=6000,
    script:
        "../scripts/debye3d/window_pores.py"


rule debye3d_chords:
    """L(z) and p(z) of the void of a system, lines in many directions (clipped to the window's
    interior for the Poisson-plane windows)."""
    input:
        samples=lambda wildcards: DEBYE3D_SAMPLES[wildcards.system],
        surface=lambda wildcards: [DEBYE3D_SURFACE.format(system=wildcards.system)] if DEBYE3D_CHORDS_TUNED else [],
        code=script_sources("../scripts/debye3d/chords.py"),
    output:
        DEBYE3D_CHORDS,
    wildcard_constraints:
        system="|".join(re.escape(name) for name in DEBYE3D_LEVEL_SET_SYSTEMS + DEBYE3D_WINDOW_SYSTEMS),
    params:
        system=lambda wildcards: DEBYE3D_SYSTEMS[wildcards.system],
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


DEBYE3D_FIGURES = ("media", "s2", "surface", "pores", "chords")
#: each figure's PDF and the PNG beside it
DEBYE3D_FIGURE_OUTPUTS = {
    name: {"pdf": DEBYE3D_FIGURE.format(name=name),
           "png": report_validation_figure(DEBYE3D_FIGURE.format(name=name)[: -len(".pdf")] + ".png",
                                           "debye3d", f"{name}.rst")}
    for name in DEBYE3D_FIGURES}


#: each figure's inputs and the config values its function (randmedia.plot.debye3d.FIGURES)
#: reads; the rules debye3d_figure_{name} are written by the loop below
DEBYE3D_FIGURE_INPUTS = {
    "media": {"samples": expand(DEBYE3D_SAMPLE, system=DEBYE3D_DEBYE_SYSTEMS, k=0)},  # mid-planes
    "s2": {"s2": expand(DEBYE3D_S2, system=DEBYE3D_SYSTEMS)},  # chi_V against the exact one
    **{name: {"descriptors": expand(files, system=DEBYE3D_LEVEL_SET_SYSTEMS + DEBYE3D_WINDOW_SYSTEMS)}
       for name, files in (("surface", DEBYE3D_SURFACE), ("pores", DEBYE3D_PORES),
                           ("chords", DEBYE3D_CHORDS))},
}
DEBYE3D_FIGURE_PARAMS = {"media": {"a": config["debye3d"]["media"]["a"]}}

for _name in DEBYE3D_FIGURES:

    rule:
        name:
            f"debye3d_figure_{_name}"
        input:
            **DEBYE3D_FIGURE_INPUTS[_name],
            code=script_sources("../scripts/debye3d/figure.py"),
        output:
            **DEBYE3D_FIGURE_OUTPUTS[_name],
        params:
            figure=_name,
            settings=DEBYE3D_FIGURE_PARAMS.get(_name, {}),
        benchmark:
            results_path(f"debye3d/benchmarks/figure_{_name}.tsv")
        log:
            results_path(f"debye3d/logs/figure_{_name}.log"),
        script:
            "../scripts/debye3d/figure.py"


rule debye3d_comparison:
    """Every system against exact values, the issue's goals and the 3D conjectures."""
    input:
        s2=expand(DEBYE3D_S2, system=DEBYE3D_SYSTEMS),
        surface=expand(DEBYE3D_SURFACE, system=DEBYE3D_LEVEL_SET_SYSTEMS + DEBYE3D_WINDOW_SYSTEMS),
        pores=expand(DEBYE3D_PORES, system=DEBYE3D_LEVEL_SET_SYSTEMS),
        chords=expand(DEBYE3D_CHORDS, system=DEBYE3D_LEVEL_SET_SYSTEMS + DEBYE3D_WINDOW_SYSTEMS),
        code=script_sources("../scripts/debye3d/comparison.py"),
    output:
        comparison=results_path("debye3d/comparison.csv"),
        notes=results_path("debye3d/comparison_notes.csv"),
    params:
        k_sigma=config["comparison"]["k_sigma"],
    benchmark:
        results_path("debye3d/benchmarks/comparison.tsv")
    log:
        results_path("debye3d/logs/comparison.log"),
    script:
        "../scripts/debye3d/comparison.py"


DEBYE3D_TARGETS = [
    *expand(DEBYE3D_S2, system=DEBYE3D_SYSTEMS),
    *[str(path) for name in DEBYE3D_FIGURES for path in DEBYE3D_FIGURE_OUTPUTS[name].values()],
    *rules.debye3d_comparison.output,
]


rule debye3d:
    """Every output of the 3D Debye study (beyond the papers), with its report pages."""
    input:
        DEBYE3D_TARGETS,
        # rule debye3d_report_tables (report.smk, included after this file)
        lambda wildcards: REPORT_PAGES["debye3d"],
