# Ma & Torquato, PRE 102, 043310 (2020): Debye random media.
#
# * Sec. IV: Debye random media by the accelerated Yeong-Torquato construction
#   -> S2 and Delta S2 per volume fraction -> Figs. 1, 2;
# * Sec. V: chords and lineal path (Figs. 6, 7); surface correlation functions and
#   pore sizes on Ma-Torquato level sets tuned to the exact s (Figs. 3-5); fits;
# * Sec. VI: digitized overlapping disks (validation of every estimator against the
#   exact Eqs. 32-39) and equilibrium hard disks (images from hard_particles.smk,
#   included before this file) -> Figs. 8-12;
# * tables/numbers.csv, comparison.csv and comparison_notes.csv.
#
# Every figure rule (Figs. 1-12 and the two validation figures) runs
# ../scripts/debye2020/figure.py: params.figure selects the function of
# randmedia.plot.debye2020.FIGURES (figNN draws Fig. NN), params.settings holds the
# config values it reads (convention: randmedia.plot.rule).

import re

MEDIA = config["debye2020"]["media"]
CHORDS = config["debye2020"]["chords"]
MEDIA_CHORDS = results_path("debye2020/descriptors/media_phi{phi2}_chords.nc")
LINEAL_FITS = results_path("debye2020/fits/lineal_path.nc")
MEDIA_PHI2 = {f"{phi:g}": phi for phi in MEDIA["phi2"]}
MEDIA_SAMPLE = results_path("debye2020/media/phi{phi2}/sample{k}.nc")
MEDIA_S2 = results_path("debye2020/descriptors/media_phi{phi2}_S2.nc")

#: the media's {phi2} wildcard: one of the configured volume fractions
MEDIA_PHI2_CONSTRAINT = "|".join(re.escape(name) for name in MEDIA_PHI2)


rule debye2020_media_sample:
    """One Debye random medium (Sec. IV); checkpoints beside the output and resumes."""
    input:
        code=script_sources("../scripts/debye2020/media_sample.py"),
    output:
        MEDIA_SAMPLE,
    wildcard_constraints:
        phi2=MEDIA_PHI2_CONSTRAINT,
    params:
        phi2=lambda wildcards: MEDIA_PHI2[wildcards.phi2],
        L=MEDIA["L"],
        a=MEDIA["a"],
        lc=MEDIA["lc"],
        schedule=MEDIA["schedule"],
        seed=config["seed"],
    benchmark:
        results_path("debye2020/benchmarks/media_sample_phi{phi2}_sample{k}.tsv")
    log:
        results_path("debye2020/logs/media_phi{phi2}_sample{k}.log"),
    threads: 1
    resources:
        mem_mb=1000,
    script:
        "../scripts/debye2020/media_sample.py"


rule debye2020_media_s2:
    """S2 of the constructions at one phi2 (mean, SEM) and Delta S2 per sample."""
    input:
        samples=expand(MEDIA_SAMPLE, k=range(MEDIA["n_samples"]), allow_missing=True),
        code=script_sources("../scripts/debye2020/media_s2.py"),
    output:
        MEDIA_S2,
    wildcard_constraints:
        phi2=MEDIA_PHI2_CONSTRAINT,
    params:
        phi2=lambda wildcards: MEDIA_PHI2[wildcards.phi2],
        L=MEDIA["L"],
        a=MEDIA["a"],
        lc=MEDIA["lc"],
    benchmark:
        results_path("debye2020/benchmarks/media_s2_phi{phi2}.tsv")
    log:
        results_path("debye2020/logs/media_s2_phi{phi2}.log"),
    script:
        "../scripts/debye2020/media_s2.py"


rule debye2020_media_chords:
    """L(z) and p(z) of the void phase of the constructions at one phi2 (Sec. V C-D)."""
    input:
        samples=expand(MEDIA_SAMPLE, k=range(MEDIA["n_samples"]), allow_missing=True),
        code=script_sources("../scripts/debye2020/chords.py"),
    output:
        MEDIA_CHORDS,
    wildcard_constraints:
        phi2=MEDIA_PHI2_CONSTRAINT,
    params:
        phi2=lambda wildcards: MEDIA_PHI2[wildcards.phi2],
        system=lambda wildcards: f"chords_media_phi{wildcards.phi2}",
        length=MEDIA["a"],
        chords=CHORDS,
        seed=config["seed"],
    benchmark:
        results_path("debye2020/benchmarks/media_chords_phi{phi2}.tsv")
    log:
        results_path("debye2020/logs/media_chords_phi{phi2}.log"),
    script:
        "../scripts/debye2020/chords.py"


rule debye2020_fit_lineal_path:
    """L_w of Eq. (29) per phi2 and <R^2>/<R> of Eq. (30)."""
    input:
        chords=expand(MEDIA_CHORDS, phi2=MEDIA_PHI2),
        code=script_sources("../scripts/debye2020/fit_lineal_path.py"),
    output:
        LINEAL_FITS,
    params:
        a=MEDIA["a"],
    benchmark:
        results_path("debye2020/benchmarks/fit_lineal_path.tsv")
    log:
        results_path("debye2020/logs/fit_lineal_path.log"),
    script:
        "../scripts/debye2020/fit_lineal_path.py"


DISKS = config["debye2020"]["overlapping_disks"]
DISKS_DIR = results_path(f"debye2020/overlapping_disks/phi{DISKS['phi2']:g}")
DISKS_S2 = results_path(f"debye2020/descriptors/overlapping_disks_phi{DISKS['phi2']:g}_S2.nc")
DISKS_FIGURE = results_path("debye2020/validation/overlapping_disks_S2.pdf")
DISKS_CHORDS = results_path(f"debye2020/descriptors/overlapping_disks_phi{DISKS['phi2']:g}_chords.nc")


rule debye2020_overlapping_disks_image:
    """One periodic digitized image of overlapping disks (phase 2 = disks)."""
    input:
        code=script_sources("../scripts/debye2020/overlapping_disks_image.py"),
    output:
        f"{DISKS_DIR}/sample{{k}}.nc",
    params:
        L=DISKS["L"],
        radius=DISKS["radius"],
        phi2=DISKS["phi2"],
        seed=config["seed"],
    benchmark:
        results_path("debye2020/benchmarks/overlapping_disks_image_sample{k}.tsv")
    log:
        results_path(f"debye2020/logs/overlapping_disks_image_{{k}}.log"),
    threads: 1
    script:
        "../scripts/debye2020/overlapping_disks_image.py"


rule debye2020_overlapping_disks_s2:
    """S2(r) of the void phase of every image: mean and SEM over samples."""
    input:
        samples=expand(f"{DISKS_DIR}/sample{{k}}.nc", k=range(DISKS["n_samples"])),
        code=script_sources("../scripts/debye2020/overlapping_disks_s2.py"),
    output:
        DISKS_S2,
    params:
        r_max=DISKS["s2_r_max_over_R"] * DISKS["radius"],
        L=DISKS["L"],
    benchmark:
        results_path("debye2020/benchmarks/overlapping_disks_s2.tsv")
    log:
        results_path("debye2020/logs/overlapping_disks_s2.log"),
    threads: 1
    script:
        "../scripts/debye2020/overlapping_disks_s2.py"


rule debye2020_overlapping_disks_figure:
    """Validation figure: simulated S2 against the exact Eqs. (32)-(33)."""
    input:
        s2=DISKS_S2,
        code=script_sources("../scripts/debye2020/figure.py"),
    output:
        pdf=DISKS_FIGURE,
        png=report_validation_figure(DISKS_FIGURE.replace(".pdf", ".png"), "debye2020",
                                     "validation_overlapping_disks_s2.rst"),
    params:
        figure="overlapping_disks_s2",
        settings={"radius": DISKS["radius"], "phi2": DISKS["phi2"],
                  "compare_r_max": DISKS["compare_r_max_over_R"] * DISKS["radius"]},
    benchmark:
        results_path("debye2020/benchmarks/overlapping_disks_figure.tsv")
    log:
        results_path("debye2020/logs/overlapping_disks_figure.log"),
    script:
        "../scripts/debye2020/figure.py"


rule debye2020_overlapping_disks_chords:
    """L(z), p(z) of the void phase of the overlapping-disk images (validation, Eqs. 38-39)."""
    input:
        samples=expand(f"{DISKS_DIR}/sample{{k}}.nc", k=range(DISKS["n_samples"])),
        code=script_sources("../scripts/debye2020/chords.py"),
    output:
        DISKS_CHORDS,
    params:
        phi2=DISKS["phi2"],
        system="chords_overlapping_disks",
        length=DISKS["radius"],
        chords=CHORDS,
        seed=config["seed"],
    benchmark:
        results_path("debye2020/benchmarks/overlapping_disks_chords.tsv")
    log:
        results_path("debye2020/logs/overlapping_disks_chords.log"),
    script:
        "../scripts/debye2020/chords.py"


# --------------------------------------------------------------------------- level sets

INTERFACE = config["debye2020"]["interface"]
FITS = config["debye2020"]["fits"]
LEVEL_SET_SURFACE = results_path("debye2020/descriptors/{system}_surface.nc")
LEVEL_SET_PORES = results_path("debye2020/descriptors/{system}_pores.nc")
SURFACE_PORE_FITS = results_path("debye2020/fits/surface_pores.nc")
DISKS_SYSTEM = f"overlapping_disks_phi{DISKS['phi2']:g}"
COMPARISON_PHI2 = f"{DISKS['phi2']:g}"  # Sec. VI: all three models at this phi2
# Equilibrium hard disks come from hard_particles.smk (included before this file):
# HARD_DISKS_SAMPLES, a list of results/debye2020/hard_disks/phi0.3/sample{k}.nc.
HARD_DISKS_SYSTEM = f"hard_disks_{Path(HARD_DISKS_SAMPLES[0]).parent.name}"

LEVEL_SET_SYSTEMS = {
    f"media_phi{name}": {
        "samples": expand(MEDIA_SAMPLE, phi2=name, k=range(MEDIA["n_samples"])),
        "target": {"model": "debye", "phi2": phi, "a": MEDIA["a"]},
    }
    for name, phi in MEDIA_PHI2.items()
}
LEVEL_SET_SYSTEMS[DISKS_SYSTEM] = {
    "samples": expand(f"{DISKS_DIR}/sample{{k}}.nc", k=range(DISKS["n_samples"])),
    "target": {"model": "overlapping_disks", "phi2": DISKS["phi2"], "radius": DISKS["radius"]},
}
LEVEL_SET_SYSTEMS[HARD_DISKS_SYSTEM] = {
    "samples": list(HARD_DISKS_SAMPLES),
    "target": {"model": "hard_disks"},  # radius, phi2 from the files' attributes
}


rule debye2020_level_set:
    """F_sv, F_ss, s, Euler characteristic, wrapping (Sec. V A) and F, P, <delta> (Sec. V B) of
    one system's images, on level sets whose Gaussian width is tuned to the exact s."""
    input:
        samples=lambda wildcards: LEVEL_SET_SYSTEMS[wildcards.system]["samples"],
        code=script_sources("../scripts/debye2020/level_set.py"),
    output:
        surface=LEVEL_SET_SURFACE,
        pores=LEVEL_SET_PORES,
    wildcard_constraints:
        system="|".join(re.escape(name) for name in LEVEL_SET_SYSTEMS),
    params:
        system=lambda wildcards: wildcards.system,
        target=lambda wildcards: LEVEL_SET_SYSTEMS[wildcards.system]["target"],
        interface=INTERFACE,
        seed=config["seed"],
    benchmark:
        results_path("debye2020/benchmarks/level_set_{system}.tsv")
    log:
        results_path("debye2020/logs/level_set_{system}.log"),
    threads: 1
    resources:
        mem_mb=3000,
    script:
        "../scripts/debye2020/level_set.py"


rule debye2020_fit_surface_pores:
    """Eqs. (24), (26) against F_sv, F_ss; Eq. (27) fits, the p1 cubic and Eq. (28); the
    specific Euler characteristic (Eq. 13); wrapping fractions -- per phi2 of the media."""
    input:
        surface=[level_set_files(f"media_phi{name}")["surface"] for name in MEDIA_PHI2],
        pores=[level_set_files(f"media_phi{name}")["pores"] for name in MEDIA_PHI2],
        code=script_sources("../scripts/debye2020/fit_surface_pores.py"),
    output:
        SURFACE_PORE_FITS,
    params:
        a=MEDIA["a"],
        fits=FITS,
    benchmark:
        results_path("debye2020/benchmarks/fit_surface_pores.tsv")
    log:
        results_path("debye2020/logs/fit_surface_pores.log"),
    script:
        "../scripts/debye2020/fit_surface_pores.py"


rule debye2020_numbers:
    """tables/numbers.csv: our counterparts of the numbers quoted in the text, and more."""
    input:
        s2=expand(MEDIA_S2, phi2=MEDIA_PHI2),
        fits=LINEAL_FITS,
        surface_pore_fits=SURFACE_PORE_FITS,
        models_surface=[level_set_files(name)["surface"] for name in comparison_models()],
        models_pores=[level_set_files(name)["pores"] for name in comparison_models()],
        code=script_sources("../scripts/debye2020/numbers.py"),
    output:
        results_path("debye2020/tables/numbers.csv"),
    benchmark:
        results_path("debye2020/benchmarks/numbers.tsv")
    log:
        results_path("debye2020/logs/numbers.log"),
    script:
        "../scripts/debye2020/numbers.py"


rule debye2020_comparison:
    """results/debye2020/comparison.csv: every computed value against its reference (+ comparison_notes.csv)."""
    input:
        s2=DISKS_S2,
        disk_chords=DISKS_CHORDS,
        disk_surface=level_set_files(DISKS_SYSTEM)["surface"],
        disk_pores=level_set_files(DISKS_SYSTEM)["pores"],
        fits=LINEAL_FITS,
        media_s2=expand(MEDIA_S2, phi2=MEDIA_PHI2),
        surface_pore_fits=SURFACE_PORE_FITS,
        hard_disks_validation=HARD_DISKS_TARGETS[3],
        quoted="config/reference/debye2020_quoted_numbers.csv",
        code=script_sources("../scripts/debye2020/comparison.py"),
    output:
        comparison=results_path("debye2020/comparison.csv"),
        notes=results_path("debye2020/comparison_notes.csv"),
    params:
        overlapping_disks=DISKS,
        media={key: MEDIA[key] for key in ("a", "lc", "L", "phi2", "n_samples")},
        hard_disks_phi2=HARD_DISKS["phi2"],
        compare_r_max=DISKS["compare_r_max_over_R"] * DISKS["radius"],
        formula_r_min=FITS["formula_r_min"],
        k_sigma=config["comparison"]["k_sigma"],
    benchmark:
        results_path("debye2020/benchmarks/comparison.tsv")
    log:
        results_path("debye2020/logs/comparison.log"),
    script:
        "../scripts/debye2020/comparison.py"


# --------------------------------------------------------------------------- figures

MEDIA_LEVEL_SET = [level_set_files(f"media_phi{name}") for name in MEDIA_PHI2]
LEVEL_SET_FIGURE = results_path("debye2020/validation/overlapping_disks_level_set.pdf")


SECTION6_PARAMS = {"a": MEDIA["a"], "radius": DISKS["radius"], "phi2": DISKS["phi2"]}


#: each figure's inputs and the config values its function (randmedia.plot.debye2020.FIGURES)
#: reads; the rules debye2020_figNN (Figs. 1-12) are written by the loop below
DEBYE2020_FIGURE_INPUTS = {
    1: {"samples": expand(MEDIA_SAMPLE, phi2=MEDIA_PHI2, k=0)},  # one construction per phi2
    2: {"s2": expand(MEDIA_S2, phi2=MEDIA_PHI2)},  # S2 against the targets
    3: {"surface": [files["surface"] for files in MEDIA_LEVEL_SET]},  # F_sv with Eq. (24)
    4: {"surface": [files["surface"] for files in MEDIA_LEVEL_SET]},  # F_ss with Eq. (26)
    # P(delta) phi1/s with Eq. (27); <delta>(phi2) with Eq. (28)
    5: {"pores": [files["pores"] for files in MEDIA_LEVEL_SET], "fits": SURFACE_PORE_FITS},
    6: {"chords": expand(MEDIA_CHORDS, phi2=MEDIA_PHI2), "fits": LINEAL_FITS},  # L(z), fitted L_w
    7: {"chords": expand(MEDIA_CHORDS, phi2=MEDIA_PHI2), "fits": LINEAL_FITS},  # matrix chords
    8: {"samples": [f"{DISKS_DIR}/sample0.nc", HARD_DISKS_SAMPLES[0]]},  # one image per model
    # Sec. VI, the three models at the comparison phi2: chi_V, F_sv, F_ss; P(delta); L(z); p(z)
    **{number: section6_inputs(number) for number in (9, 10, 11, 12)},
}
DEBYE2020_FIGURE_PARAMS = {
    **{number: {"a": MEDIA["a"]} for number in (1, 3, 4, 5, 6, 7)},
    2: {"lc": MEDIA["lc"]},
    8: {"titles": ["overlapping disks", "equilibrium hard disks"]},
    **{number: SECTION6_PARAMS for number in (9, 10, 11, 12)},
}

for _number in DEBYE2020_FIGURE_INPUTS:

    rule:
        name:
            f"debye2020_fig{_number:02d}"
        input:
            **DEBYE2020_FIGURE_INPUTS[_number],
            code=script_sources("../scripts/debye2020/figure.py"),
        output:
            **figure_outputs("debye2020", _number, in_report=True),
        params:
            figure=_number,
            settings=DEBYE2020_FIGURE_PARAMS[_number],
        benchmark:
            results_path(f"debye2020/benchmarks/fig{_number:02d}.tsv")
        log:
            results_path(f"debye2020/logs/fig{_number:02d}.log"),
        script:
            "../scripts/debye2020/figure.py"


rule debye2020_overlapping_disks_level_set_figure:
    """Validation figure: level-set F_sv, F_ss, F, P of overlapping disks against Eqs. (35)-(37)."""
    input:
        **level_set_files(DISKS_SYSTEM),
        code=script_sources("../scripts/debye2020/figure.py"),
    output:
        pdf=LEVEL_SET_FIGURE,
        png=report_validation_figure(LEVEL_SET_FIGURE.replace(".pdf", ".png"), "debye2020",
                                     "validation_overlapping_disks_level_set.rst"),
    params:
        figure="overlapping_disks_level_set",
        settings={"radius": DISKS["radius"], "phi2": DISKS["phi2"]},
    benchmark:
        results_path("debye2020/benchmarks/overlapping_disks_level_set_figure.tsv")
    log:
        results_path("debye2020/logs/overlapping_disks_level_set_figure.log"),
    script:
        "../scripts/debye2020/figure.py"


DEBYE2020_TARGETS = HARD_DISKS_TARGETS + [
    results_path("debye2020/comparison.csv"),
    results_path("debye2020/comparison_notes.csv"),
    results_path("debye2020/tables/numbers.csv"),
    DISKS_FIGURE,
    DISKS_FIGURE.replace(".pdf", ".png"),
    LEVEL_SET_FIGURE,
    LEVEL_SET_FIGURE.replace(".pdf", ".png"),
] + [path for number in DEBYE2020_FIGURE_INPUTS
     for path in figure_outputs("debye2020", number).values()]


rule debye2020:
    """Everything of debye2020."""
    input:
        DEBYE2020_TARGETS,
