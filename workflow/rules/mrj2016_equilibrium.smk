# Klatt & Torquato, PRE 94, 022152 (2016): the equilibrium hard-sphere liquid
# at phi = 0.478 (system `equilibrium`) by NVT Monte Carlo
# (randmedia.generate.hard_particles, d-generic). Included before mrj2016.smk.
#
# Names for the other rule files:
#   MRJ2016_EQUILIBRIUM  the config section mrj2016.equilibrium
#   EQUILIBRIUM_SAMPLES  every sample: results/mrj2016/configs/equilibrium/sample{k}.nc
#                        (PARTICLE_CONFIG: position, box in units of D = 1; attr diameter)
#   EQUILIBRIUM_TARGETS  validation: contact-value pressure vs the EOS, Q6, decorrelation
# One job per Markov chain writes that chain's samples k = chain * samples_per_chain + j
# (one rule per chain: mrj2016_equilibrium_chain{c}); it checkpoints beside them.

MRJ2016_EQUILIBRIUM = config["mrj2016"]["equilibrium"]
EQUILIBRIUM_DIR = results_path("mrj2016/configs/equilibrium")
EQUILIBRIUM_PER_CHAIN = MRJ2016_EQUILIBRIUM["samples_per_chain"]
EQUILIBRIUM_SAMPLES = [
    f"{EQUILIBRIUM_DIR}/sample{k}.nc"
    for k in range(MRJ2016_EQUILIBRIUM["n_chains"] * EQUILIBRIUM_PER_CHAIN)
]
EQUILIBRIUM_VALIDATION = results_path("mrj2016/validation/equilibrium")
EQUILIBRIUM_TARGETS = [
    f"{EQUILIBRIUM_VALIDATION}_eos.pdf",
    f"{EQUILIBRIUM_VALIDATION}_eos.png",
    f"{EQUILIBRIUM_VALIDATION}_diagnostics.csv",
    f"{EQUILIBRIUM_VALIDATION}_comparison.csv",
]

for _chain in range(MRJ2016_EQUILIBRIUM["n_chains"]):

    rule:
        name:
            f"mrj2016_equilibrium_chain{_chain}"
        input:
            code=script_sources("../scripts/mrj2016/equilibrium_chain.py"),
        output:
            EQUILIBRIUM_SAMPLES[_chain * EQUILIBRIUM_PER_CHAIN:(_chain + 1) * EQUILIBRIUM_PER_CHAIN],
        params:
            chain=_chain,
            phi=MRJ2016_EQUILIBRIUM["phi"],
            n_particles=MRJ2016_EQUILIBRIUM["n_particles"],
            samples_per_chain=EQUILIBRIUM_PER_CHAIN,
            eos=MRJ2016_EQUILIBRIUM["eos"],
            mc=MRJ2016_EQUILIBRIUM["mc"],
            checkpoint_seconds=MRJ2016_EQUILIBRIUM["checkpoint_seconds"],
            seed=config["seed"],
        benchmark:
            results_path(f"mrj2016/benchmarks/equilibrium_chain{_chain}.tsv")
        log:
            results_path(f"mrj2016/logs/equilibrium_chain{_chain}.log"),
        threads: 1
        resources:
            mem_mb=1000,
        script:
            "../scripts/mrj2016/equilibrium_chain.py"


rule mrj2016_equilibrium_validation:
    """Contact-value pressure of the liquid against the EOS; per-sample diagnostics
    (acceptance, MSD between samples, global Q6, crystal-like fraction)."""
    input:
        samples=EQUILIBRIUM_SAMPLES,
        code=script_sources("../scripts/mrj2016/equilibrium_validation.py"),
    output:
        pdf=EQUILIBRIUM_TARGETS[0],
        png=report_validation_figure(EQUILIBRIUM_TARGETS[1], "mrj2016", "validation_equilibrium_eos.rst"),
        diagnostics=EQUILIBRIUM_TARGETS[2],
        comparison=EQUILIBRIUM_TARGETS[3],
    params:
        phi=MRJ2016_EQUILIBRIUM["phi"],
        eos=MRJ2016_EQUILIBRIUM["eos"],
        mc=MRJ2016_EQUILIBRIUM["mc"],
        k_sigma=config["comparison"]["k_sigma"],
    benchmark:
        results_path("mrj2016/benchmarks/equilibrium_validation.tsv")
    log:
        results_path("mrj2016/logs/equilibrium_validation.log"),
    script:
        "../scripts/mrj2016/equilibrium_validation.py"


rule mrj2016_equilibrium:
    """Every sample of the equilibrium hard-sphere liquid and its validation."""
    input:
        EQUILIBRIUM_SAMPLES,
        EQUILIBRIUM_TARGETS,
