# Ma & Torquato, PRE 102, 043310 (2020): Debye random media.
#
# Built so far: the overlapping-disk slice of Sec. VI A -- digitized Boolean
# model images -> S2 of the void phase (FFT estimator) -> validation figure
# and comparison rows against the exact Eqs. (32)-(33).
# The Debye generator, the other descriptors and Figs. 1-12 are issue #3.

DISKS = config["debye2020"]["overlapping_disks"]
DISKS_DIR = f"results/debye2020/overlapping_disks/phi{DISKS['phi2']:g}"
DISKS_S2 = f"results/debye2020/descriptors/overlapping_disks_phi{DISKS['phi2']:g}_S2.nc"
DISKS_FIGURE = "results/debye2020/validation/overlapping_disks_S2.pdf"


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


rule debye2020_comparison:
    """results/debye2020/comparison.csv: every computed value against its reference."""
    input:
        s2=DISKS_S2,
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
    DISKS_FIGURE,
    DISKS_FIGURE.replace(".pdf", ".png"),
]


rule debye2020:
    """Everything of debye2020 built so far."""
    input:
        DEBYE2020_TARGETS,
