# Ma & Torquato, PRE 102, 043310 (2020): Debye random media.
#
# Built so far:
# * Sec. IV: Debye random media by the accelerated Yeong-Torquato construction
#   -> S2 and Delta S2 per volume fraction -> Figs. 1, 2 and tables/numbers.csv;
# * Sec. VI A slice: digitized overlapping disks -> S2 of the void phase (FFT
#   estimator) -> validation figure and comparison rows against Eqs. (32)-(33).
# The other descriptors, fits and Figs. 3-12 are the rest of issue #3.

import re

MEDIA = config["debye2020"]["media"]
CHORDS = config["debye2020"]["chords"]
MEDIA_CHORDS = "results/debye2020/descriptors/media_phi{phi2}_chords.nc"
LINEAL_FITS = "results/debye2020/fits/lineal_path.nc"
MEDIA_PHI2 = {f"{phi:g}": phi for phi in MEDIA["phi2"]}
MEDIA_SAMPLE = "results/debye2020/media/phi{phi2}/sample{k}.nc"
MEDIA_S2 = "results/debye2020/descriptors/media_phi{phi2}_S2.nc"


wildcard_constraints:
    phi2="|".join(re.escape(name) for name in MEDIA_PHI2),


rule debye2020_media_sample:
    """One Debye random medium (Sec. IV); checkpoints beside the output and resumes."""
    input:
        package_sources("generate/yeong_torquato.py", "generate/__init__.py",
                        "theory/debye.py", "describe/two_phase.py", "seeding.py"),
    output:
        MEDIA_SAMPLE,
    params:
        phi2=lambda wildcards: MEDIA_PHI2[wildcards.phi2],
        L=MEDIA["L"],
        a=MEDIA["a"],
        lc=MEDIA["lc"],
        schedule=MEDIA["schedule"],
        seed=config["seed"],
    log:
        "results/debye2020/logs/media_phi{phi2}_sample{k}.log",
    threads: 1
    resources:
        mem_mb=1000,
    script:
        "../scripts/debye2020/media_sample.py"


rule debye2020_media_s2:
    """S2 of the constructions at one phi2 (mean, SEM) and Delta S2 per sample."""
    input:
        samples=expand(MEDIA_SAMPLE, k=range(MEDIA["n_samples"]), allow_missing=True),
        code=package_sources("describe/two_phase.py", "theory/debye.py"),
    output:
        MEDIA_S2,
    params:
        phi2=lambda wildcards: MEDIA_PHI2[wildcards.phi2],
        L=MEDIA["L"],
        a=MEDIA["a"],
        lc=MEDIA["lc"],
    log:
        "results/debye2020/logs/media_s2_phi{phi2}.log",
    script:
        "../scripts/debye2020/media_s2.py"


rule debye2020_fig01:
    """Fig. 1: one construction per volume fraction."""
    input:
        samples=expand(MEDIA_SAMPLE, phi2=MEDIA_PHI2, k=0),
        code=package_sources("plot/style.py", "plot/debye2020.py"),
    output:
        pdf="results/debye2020/figures/fig01.pdf",
        png="results/debye2020/figures/fig01.png",
    params:
        a=MEDIA["a"],
    log:
        "results/debye2020/logs/fig01.log",
    script:
        "../scripts/debye2020/fig01.py"


rule debye2020_fig02:
    """Fig. 2: S2 of the constructions against the targets."""
    input:
        s2=expand(MEDIA_S2, phi2=MEDIA_PHI2),
        code=package_sources("plot/style.py", "plot/debye2020.py"),
    output:
        pdf="results/debye2020/figures/fig02.pdf",
        png="results/debye2020/figures/fig02.png",
    params:
        lc=MEDIA["lc"],
    log:
        "results/debye2020/logs/fig02.log",
    script:
        "../scripts/debye2020/fig02.py"


rule debye2020_media_chords:
    """L(z) and p(z) of the void phase of the constructions at one phi2 (Sec. V C-D)."""
    input:
        samples=expand(MEDIA_SAMPLE, k=range(MEDIA["n_samples"]), allow_missing=True),
        code=package_sources("describe/chords.py", "seeding.py"),
    output:
        MEDIA_CHORDS,
    params:
        phi2=lambda wildcards: MEDIA_PHI2[wildcards.phi2],
        system=lambda wildcards: f"chords_media_phi{wildcards.phi2}",
        length=MEDIA["a"],
        chords=CHORDS,
        seed=config["seed"],
    log:
        "results/debye2020/logs/media_chords_phi{phi2}.log",
    script:
        "../scripts/debye2020/chords.py"


rule debye2020_fit_lineal_path:
    """L_w of Eq. (29) per phi2 and <R^2>/<R> of Eq. (30)."""
    input:
        chords=expand(MEDIA_CHORDS, phi2=MEDIA_PHI2),
        code=package_sources("fit/__init__.py", "fit/debye2020.py"),
    output:
        LINEAL_FITS,
    params:
        a=MEDIA["a"],
    log:
        "results/debye2020/logs/fit_lineal_path.log",
    script:
        "../scripts/debye2020/fit_lineal_path.py"


rule debye2020_fig06:
    """Fig. 6: lineal-path function and fitted L_w."""
    input:
        chords=expand(MEDIA_CHORDS, phi2=MEDIA_PHI2),
        fits=LINEAL_FITS,
        code=package_sources("plot/style.py", "plot/debye2020.py"),
    output:
        pdf="results/debye2020/figures/fig06.pdf",
        png="results/debye2020/figures/fig06.png",
    params:
        a=MEDIA["a"],
        figure="fig06_lineal_path",
    log:
        "results/debye2020/logs/fig06.log",
    script:
        "../scripts/debye2020/fig06_07.py"


rule debye2020_fig07:
    """Fig. 7: matrix chord-length density."""
    input:
        chords=expand(MEDIA_CHORDS, phi2=MEDIA_PHI2),
        fits=LINEAL_FITS,
        code=package_sources("plot/style.py", "plot/debye2020.py"),
    output:
        pdf="results/debye2020/figures/fig07.pdf",
        png="results/debye2020/figures/fig07.png",
    params:
        a=MEDIA["a"],
        figure="fig07_chord_density",
    log:
        "results/debye2020/logs/fig07.log",
    script:
        "../scripts/debye2020/fig06_07.py"


rule debye2020_numbers:
    """tables/numbers.csv: our counterparts of the numbers quoted in the text."""
    input:
        s2=expand(MEDIA_S2, phi2=MEDIA_PHI2),
        fits=LINEAL_FITS,
        code=package_sources("compare/debye2020.py"),
    output:
        "results/debye2020/tables/numbers.csv",
    log:
        "results/debye2020/logs/numbers.log",
    script:
        "../scripts/debye2020/numbers.py"

DISKS = config["debye2020"]["overlapping_disks"]
DISKS_DIR = f"results/debye2020/overlapping_disks/phi{DISKS['phi2']:g}"
DISKS_S2 = f"results/debye2020/descriptors/overlapping_disks_phi{DISKS['phi2']:g}_S2.nc"
DISKS_FIGURE = "results/debye2020/validation/overlapping_disks_S2.pdf"
DISKS_CHORDS = f"results/debye2020/descriptors/overlapping_disks_phi{DISKS['phi2']:g}_chords.nc"


rule debye2020_overlapping_disks_image:
    """One periodic digitized image of overlapping disks (phase 2 = disks)."""
    input:
        package_sources("generate/disks.py", "seeding.py"),
    output:
        f"{DISKS_DIR}/sample{{k}}.nc",
    params:
        L=DISKS["L"],
        radius=DISKS["radius"],
        phi2=DISKS["phi2"],
        seed=config["seed"],
    log:
        f"results/debye2020/logs/overlapping_disks_image_{{k}}.log",
    threads: 1
    script:
        "../scripts/debye2020/overlapping_disks_image.py"


rule debye2020_overlapping_disks_s2:
    """S2(r) of the void phase of every image: mean and SEM over samples."""
    input:
        samples=expand(f"{DISKS_DIR}/sample{{k}}.nc", k=range(DISKS["n_samples"])),
        code=package_sources("describe/two_phase.py"),
    output:
        DISKS_S2,
    params:
        r_max=DISKS["s2_r_max_over_R"] * DISKS["radius"],
        L=DISKS["L"],
    log:
        "results/debye2020/logs/overlapping_disks_s2.log",
    threads: 1
    script:
        "../scripts/debye2020/overlapping_disks_s2.py"


rule debye2020_overlapping_disks_figure:
    """Validation figure: simulated S2 against the exact Eqs. (32)-(33)."""
    input:
        s2=DISKS_S2,
        code=package_sources("plot/style.py", "plot/debye2020.py", "theory/overlapping.py"),
    output:
        pdf=DISKS_FIGURE,
        png=DISKS_FIGURE.replace(".pdf", ".png"),
    params:
        radius=DISKS["radius"],
        phi2=DISKS["phi2"],
        compare_r_max=DISKS["compare_r_max_over_R"] * DISKS["radius"],
    log:
        "results/debye2020/logs/overlapping_disks_figure.log",
    script:
        "../scripts/debye2020/overlapping_disks_figure.py"


rule debye2020_overlapping_disks_chords:
    """L(z), p(z) of the void phase of the overlapping-disk images (validation, Eqs. 38-39)."""
    input:
        samples=expand(f"{DISKS_DIR}/sample{{k}}.nc", k=range(DISKS["n_samples"])),
        code=package_sources("describe/chords.py", "seeding.py"),
    output:
        DISKS_CHORDS,
    params:
        phi2=DISKS["phi2"],
        system="chords_overlapping_disks",
        length=DISKS["radius"],
        chords=CHORDS,
        seed=config["seed"],
    log:
        "results/debye2020/logs/overlapping_disks_chords.log",
    script:
        "../scripts/debye2020/chords.py"


rule debye2020_comparison:
    """results/debye2020/comparison.csv: every computed value against its reference."""
    input:
        s2=DISKS_S2,
        disk_chords=DISKS_CHORDS,
        fits=LINEAL_FITS,
        quoted="config/reference/debye2020_quoted_numbers.csv",
        code=package_sources("compare/__init__.py", "compare/debye2020.py", "theory/overlapping.py"),
    output:
        "results/debye2020/comparison.csv",
    params:
        radius=DISKS["radius"],
        phi2=DISKS["phi2"],
        L=DISKS["L"],
        compare_r_max=DISKS["compare_r_max_over_R"] * DISKS["radius"],
        k_sigma=config["comparison"]["k_sigma"],
    log:
        "results/debye2020/logs/comparison.log",
    script:
        "../scripts/debye2020/comparison.py"


DEBYE2020_TARGETS = [
    "results/debye2020/comparison.csv",
    "results/debye2020/tables/numbers.csv",
    "results/debye2020/figures/fig01.pdf",
    "results/debye2020/figures/fig01.png",
    "results/debye2020/figures/fig02.pdf",
    "results/debye2020/figures/fig02.png",
    "results/debye2020/figures/fig06.pdf",
    "results/debye2020/figures/fig06.png",
    "results/debye2020/figures/fig07.pdf",
    "results/debye2020/figures/fig07.png",
    DISKS_FIGURE,
    DISKS_FIGURE.replace(".pdf", ".png"),
]


rule debye2020:
    """Everything of debye2020 built so far."""
    input:
        DEBYE2020_TARGETS,
