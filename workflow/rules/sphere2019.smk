# Hyperuniformity on spherical surfaces, PRE 100, 022107 (2019).
#
# generate: point patterns (Tegmark icosahedral grid, Fibonacci grid, uniform,
#           Poisson; Secs. III-IV) and canonical Monte Carlo fluids (Sec. V)
#           -> results/sphere2019/configs/{system}.nc
# describe: number variance in spherical caps (random centres; for the fluids also
#           the paper's three orthogonal origins per sweep), geodesic g2, sigma^2
#           from g2 by Eq. (4)/(5) -> results/sphere2019/descriptors/{system}.nc
# fit:      exponents delta of sigma^2 ~ a^delta -> results/sphere2019/fits/exponents.nc
# render:   Table I, comparison.csv (+ comparison_notes.csv), Monte Carlo run summary, Figs. 1-8;
#           every figure rule runs ../scripts/sphere2019/figure.py: params.figure selects the
#           function of randmedia.plot.sphere2019.FIGURES (figNN draws Fig. NN),
#           params.settings holds the config values it reads (convention: randmedia.plot.rule).

SPHERE = config["sphere2019"]
SPHERE_PATTERNS = SPHERE["patterns"]
SPHERE_FLUIDS = SPHERE["fluids"]
SPHERE_CAPS = SPHERE["caps"]
SPHERE_PATTERN_SYSTEMS = ["icosahedral", "fibonacci", "uniform", "poisson"]
SPHERE_FLUID_SYSTEMS = list(SPHERE_FLUIDS["systems"])
SPHERE_SYSTEMS = SPHERE_PATTERN_SYSTEMS + SPHERE_FLUID_SYSTEMS
SPHERE_CONFIG = results_path("sphere2019/configs/{system}.nc")
SPHERE_DESCRIPTOR = results_path("sphere2019/descriptors/{system}.nc")
SPHERE_FITS = results_path("sphere2019/fits/exponents.nc")
SPHERE_R15 = ["lj_R15", "udd_R15", "uddpar_a1_R15", "udc_R15", "ucc_R15"]
SPHERE_ALPHA = ["uddpar_a1_R5", "uddpar_a3_R5", "uddpar_a6_R5"]
# the second reading of Eq. (12b), epsilon (alpha d/r)^3 (alpha = 1 is the same system):
# Figs. 5-8 are drawn a second time for it, as figNN_alpha_cubed
SPHERE_ALPHA_CUBED = ["uddpar_a1_R5", "uddcubed_a3_R5", "uddcubed_a6_R5"]
# Fig. 8 (sigma^2 from g2) also shows the LJ fluid at R = 5 when it is configured
SPHERE_LJ_R5 = [s for s in ["lj_R5"] if s in SPHERE_FLUID_SYSTEMS]
SPHERE_FIG08 = SPHERE_LJ_R5 + SPHERE_ALPHA
SPHERE_FIG08_CUBED = SPHERE_LJ_R5 + SPHERE_ALPHA_CUBED
SPHERE_A_MIN_PLOT = SPHERE["fit"]["a_min_rho_half"] / SPHERE_FLUIDS["density"] ** 0.5


#: the keys of sphere2019.patterns each pattern reads (workflow/scripts/sphere2019/pattern.py),
#: so that e.g. fibonacci_points reruns the Fibonacci grid alone; the grids use no seed
SPHERE_PATTERN_KEYS = {
    "icosahedral": ["density", "icosahedral_resolution"],
    "fibonacci": ["density", "fibonacci_points"],
    "uniform": ["uncorrelated_R", "uncorrelated_points", "uncorrelated_configs"],
    "poisson": ["uncorrelated_R", "uncorrelated_points", "uncorrelated_configs",
                "poisson_n_theta", "poisson_n_phi"],
}


rule sphere2019_pattern:
    """A point pattern on the sphere (Secs. III-IV, Appendix)."""
    input:
        code=script_sources("../scripts/sphere2019/pattern.py"),
    output:
        results_path("sphere2019/configs/{system}.nc"),
    wildcard_constraints:
        system="|".join(SPHERE_PATTERN_SYSTEMS),
    params:
        patterns=lambda wildcards: {key: SPHERE_PATTERNS[key]
                                    for key in SPHERE_PATTERN_KEYS[wildcards.system]},
        seed=lambda wildcards: None if wildcards.system in ("icosahedral", "fibonacci") else config["seed"],
    benchmark:
        results_path("sphere2019/benchmarks/pattern_{system}.tsv")
    log:
        results_path("sphere2019/logs/config_{system}.log"),
    threads: 1
    script:
        "../scripts/sphere2019/pattern.py"


rule sphere2019_fluid:
    """Canonical Monte Carlo of one fluid on the sphere (Sec. V); checkpoints beside the
    output and resumes."""
    input:
        code=script_sources("../scripts/sphere2019/fluid.py"),
    output:
        results_path("sphere2019/configs/{system}.nc"),
    wildcard_constraints:
        system="|".join(SPHERE_FLUID_SYSTEMS),
    params:
        fluid=lambda wildcards: SPHERE_FLUIDS["systems"][wildcards.system],
        run=lambda wildcards: SPHERE_FLUIDS["runs"][SPHERE_FLUIDS["systems"][wildcards.system]["run"]],
        density=SPHERE_FLUIDS["density"],
        temperature=SPHERE_FLUIDS["temperature"],
        target_acceptance=SPHERE_FLUIDS["target_acceptance"],
        tune_fraction=SPHERE_FLUIDS["tune_fraction"],
        initial_step=SPHERE_FLUIDS["initial_step"],
        checkpoint_seconds=SPHERE_FLUIDS["checkpoint_seconds"],
        n_a=SPHERE_CAPS["n_a"],
        seed=config["seed"],
    benchmark:
        results_path("sphere2019/benchmarks/fluid_{system}.tsv")
    log:
        results_path("sphere2019/logs/config_{system}.log"),
    threads: 1
    resources:
        mem_mb=2000,
    script:
        "../scripts/sphere2019/fluid.py"


rule sphere2019_describe:
    """Number variance in caps (both window-centre variants), g2 and Eq. (4)/(5)."""
    input:
        config=SPHERE_CONFIG,
        code=script_sources("../scripts/sphere2019/describe.py"),
    output:
        SPHERE_DESCRIPTOR,
    wildcard_constraints:
        system="|".join(SPHERE_SYSTEMS),
    params:
        caps=SPHERE_CAPS,
        seed=config["seed"],
    benchmark:
        results_path("sphere2019/benchmarks/describe_{system}.tsv")
    log:
        results_path("sphere2019/logs/describe_{system}.log"),
    threads: 2
    script:
        "../scripts/sphere2019/describe.py"


rule sphere2019_fit:
    """Exponents delta of sigma^2 ~ a^delta for every system (Eq. 10, Table I)."""
    input:
        descriptors=sphere_descriptors(SPHERE_SYSTEMS),
        code=script_sources("../scripts/sphere2019/fit.py"),
    output:
        SPHERE_FITS,
    params:
        fit=SPHERE["fit"],
    benchmark:
        results_path("sphere2019/benchmarks/fit.tsv")
    log:
        results_path("sphere2019/logs/fit.log"),
    script:
        "../scripts/sphere2019/fit.py"


rule sphere2019_table1:
    """Table I (ours beside the published exponents) and the Monte Carlo run summary."""
    input:
        fits=SPHERE_FITS,
        descriptors=sphere_descriptors(SPHERE_FLUID_SYSTEMS),
        reference="config/reference/sphere2019_table1_exponents.csv",
        code=script_sources("../scripts/sphere2019/table1.py"),
    output:
        table=results_path("sphere2019/tables/table1.csv"),
        runs=results_path("sphere2019/tables/mc_runs.csv"),
    benchmark:
        results_path("sphere2019/benchmarks/table1.tsv")
    log:
        results_path("sphere2019/logs/table1.log"),
    script:
        "../scripts/sphere2019/table1.py"


rule sphere2019_comparison:
    """results/sphere2019/comparison.csv: a row per Table I entry (+ comparison_notes.csv)."""
    input:
        table=results_path("sphere2019/tables/table1.csv"),
        code=script_sources("../scripts/sphere2019/comparison.py"),
    output:
        comparison=results_path("sphere2019/comparison.csv"),
        notes=results_path("sphere2019/comparison_notes.csv"),
    params:
        k_sigma=config["comparison"]["k_sigma"],
        rounding_margin=SPHERE["fit"]["rounding_margin"],
    benchmark:
        results_path("sphere2019/benchmarks/comparison.tsv")
    log:
        results_path("sphere2019/logs/comparison.log"),
    script:
        "../scripts/sphere2019/comparison.py"


#: each figure's inputs (the alpha_cubed ones: the second reading of Eq. 12b, drawn as
#: figNN_alpha_cubed) and the config values its function (randmedia.plot.sphere2019.FIGURES)
#: reads; the rules sphere2019_figNN (Figs. 1-8) are written by the loop below
SPHERE2019_FIGURE_INPUTS = {
    1: {},  # the spherical-cap window
    2: {"configs": expand(SPHERE_CONFIG, system=["icosahedral", "fibonacci"]),  # grids
        "descriptors": sphere_descriptors(["icosahedral", "fibonacci"])},
    3: {"configs": expand(SPHERE_CONFIG, system=["poisson", "uniform"]),  # Eqs. (6), (7)
        "descriptors": sphere_descriptors(["poisson", "uniform"])},
    4: {"descriptors": sphere_descriptors(SPHERE_R15)},  # R = 15 fluids, inset sigma^2*(a)
    5: {"descriptors": sphere_descriptors(SPHERE_ALPHA),  # R = 5, alpha = 1, 3, 6
        "alpha_cubed": sphere_descriptors(SPHERE_ALPHA_CUBED)},
    6: {"configs": expand(SPHERE_CONFIG, system=SPHERE_ALPHA),  # snapshots
        "alpha_cubed": expand(SPHERE_CONFIG, system=SPHERE_ALPHA_CUBED)},
    7: {"descriptors": sphere_descriptors(SPHERE_FIG08),  # geodesic g2 (and LJ when configured)
        "alpha_cubed": sphere_descriptors(SPHERE_FIG08_CUBED)},
    8: {"descriptors": sphere_descriptors(SPHERE_FIG08),  # sigma^2 from g2 by Eq. (4)
        "alpha_cubed": sphere_descriptors(SPHERE_FIG08_CUBED)},
}
SPHERE2019_FIGURE_PARAMS = {4: {"a_min": SPHERE_A_MIN_PLOT}, 5: {"a_min": SPHERE_A_MIN_PLOT}}

for _number in SPHERE2019_FIGURE_INPUTS:

    rule:
        name:
            f"sphere2019_fig{_number:02d}"
        input:
            **SPHERE2019_FIGURE_INPUTS[_number],
            code=script_sources("../scripts/sphere2019/figure.py"),
        output:
            **figure_outputs("sphere2019", _number, second_reading=_number >= 5, in_report=True),
        params:
            figure=_number,
            settings=SPHERE2019_FIGURE_PARAMS.get(_number, {}),
        benchmark:
            results_path(f"sphere2019/benchmarks/fig{_number:02d}.tsv")
        log:
            results_path(f"sphere2019/logs/fig{_number:02d}.log"),
        script:
            "../scripts/sphere2019/figure.py"


SPHERE2019_FIGURES = [path for n in SPHERE2019_FIGURE_INPUTS
                      for path in figure_outputs("sphere2019", n, second_reading=n >= 5).values()]
SPHERE2019_TARGETS = [
    results_path("sphere2019/comparison.csv"),
    results_path("sphere2019/comparison_notes.csv"),
    results_path("sphere2019/tables/table1.csv"),
    results_path("sphere2019/tables/mc_runs.csv"),
] + SPHERE2019_FIGURES


rule sphere2019:
    """Everything of sphere2019: Table I, comparison, run summary, Figs. 1-8."""
    input:
        SPHERE2019_TARGETS,
