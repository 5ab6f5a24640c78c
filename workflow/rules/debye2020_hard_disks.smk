# Ma & Torquato, PRE 102, 043310 (2020), Sec. VI B: equilibrium hard disks at
# phi2 = 0.3 by NVT Monte Carlo (randmedia.generate.hard_particles, the same
# d-generic code as the mrj2016 hard-sphere liquid), digitized to images.
# Included before debye2020.smk, whose descriptor rules read these samples.
#
# Names for the other rule files:
#   HARD_DISKS          the config section debye2020.hard_disks
#   HARD_DISKS_SAMPLES  every image: results/debye2020/hard_disks/phi{phi2:g}/sample{k}.nc
#                       (variables phase (y, x) uint8, 1 = disks; position, box in pixels)
#   HARD_DISKS_TARGETS  validation: contact-value pressure vs the 2D EOS, diagnostics
# One job per Markov chain writes that chain's samples k = chain * samples_per_chain + j
# (one rule per chain: debye2020_hard_disks_chain{c}); it checkpoints beside them.

HARD_DISKS = config["debye2020"]["hard_disks"]
HARD_DISKS_DIR = results_path(f"debye2020/hard_disks/phi{HARD_DISKS['phi2']:g}")
HARD_DISKS_PER_CHAIN = HARD_DISKS["samples_per_chain"]
HARD_DISKS_SAMPLES = [
    f"{HARD_DISKS_DIR}/sample{k}.nc"
    for k in range(HARD_DISKS["n_chains"] * HARD_DISKS_PER_CHAIN)
]
HARD_DISKS_VALIDATION = results_path("debye2020/validation/hard_disks")
HARD_DISKS_TARGETS = [
    f"{HARD_DISKS_VALIDATION}_eos.pdf",
    f"{HARD_DISKS_VALIDATION}_eos.png",
    f"{HARD_DISKS_VALIDATION}_diagnostics.csv",
    f"{HARD_DISKS_VALIDATION}_comparison.csv",
]

for _chain in range(HARD_DISKS["n_chains"]):

    rule:
        name:
            f"debye2020_hard_disks_chain{_chain}"
        input:
            code=script_sources("../scripts/debye2020/hard_disks_chain.py"),
        output:
            HARD_DISKS_SAMPLES[_chain * HARD_DISKS_PER_CHAIN:(_chain + 1) * HARD_DISKS_PER_CHAIN],
        params:
            chain=_chain,
            phi2=HARD_DISKS["phi2"],
            L=HARD_DISKS["L"],
            radius=HARD_DISKS["radius"],
            samples_per_chain=HARD_DISKS_PER_CHAIN,
            mc=HARD_DISKS["mc"],
            checkpoint_seconds=HARD_DISKS["checkpoint_seconds"],
            seed=config["seed"],
        benchmark:
            results_path(f"debye2020/benchmarks/hard_disks_chain{_chain}.tsv")
        log:
            results_path(f"debye2020/logs/hard_disks_chain{_chain}.log"),
        threads: 1
        resources:
            mem_mb=1000,
        script:
            "../scripts/debye2020/hard_disks_chain.py"


rule debye2020_hard_disks_validation:
    """Contact-value pressure of the hard-disk chains against the 2D EOS; per-sample
    diagnostics (acceptance, MSD between samples, digitized area fraction)."""
    input:
        samples=HARD_DISKS_SAMPLES,
        code=script_sources("../scripts/debye2020/hard_disks_validation.py"),
    output:
        pdf=HARD_DISKS_TARGETS[0],
        png=report_validation_figure(HARD_DISKS_TARGETS[1], "debye2020", "validation_hard_disks_eos.rst"),
        diagnostics=HARD_DISKS_TARGETS[2],
        comparison=HARD_DISKS_TARGETS[3],
    params:
        phi2=HARD_DISKS["phi2"],
        radius=HARD_DISKS["radius"],
        mc=HARD_DISKS["mc"],
        k_sigma=config["comparison"]["k_sigma"],
    benchmark:
        results_path("debye2020/benchmarks/hard_disks_validation.tsv")
    log:
        results_path("debye2020/logs/hard_disks_validation.log"),
    script:
        "../scripts/debye2020/hard_disks_validation.py"


rule debye2020_hard_disks:
    """Every equilibrium hard-disk image and its validation (Sec. VI B)."""
    input:
        HARD_DISKS_SAMPLES,
        HARD_DISKS_TARGETS,
