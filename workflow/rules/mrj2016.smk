# Klatt & Torquato, PRE 94, 022152 (2016): MRJ sphere packings II -- descriptors,
# comparison systems, figures and tables.
#
#   generate  overlapping spheres, fcc / bcc lattices (here); the equilibrium liquid
#             (hard_particles.smk: EQUILIBRIUM_SAMPLES) and the MRJ packings
#             (mrj2016_jammed.smk: MRJ_SAMPLES, MRJ_LARGE_SAMPLES) and the MD-like packings
#             of Ref. [29] (MRJ_MD_SAMPLES), included before.
#   describe  per chunk of samples: correlation (Appendix A), spectral (Sec. IV),
#             points (pore sizes, E_V, covering radius; Sec. V), windows (number
#             variance, f_R(N); Sec. VI); then one merged file per system and kind.
#   render    Figs. 1-13, Tables I-V, comparison.csv (+ comparison_notes.csv). The figure
#             rules mrj2016_figNN (one loop over MRJ2016_FIGURE_INPUTS, as in every paper) run
#             ../scripts/mrj2016/figure.py: params.figure selects the function of
#             randmedia.plot.mrj2016.FIGURES (figNN draws Fig. NN), params.settings holds
#             the config values it reads (convention: randmedia.plot.rule).
#
# A system with no samples in the config is left out of every descriptor, figure
# and table that would use it.

import csv
import math

MRJ2016 = config["mrj2016"]
M_OVERLAPPING = MRJ2016["overlapping"]
M_LATTICES = MRJ2016["lattices"]
M_DESCRIPTORS = MRJ2016["descriptors"]
M_SPECTRAL = MRJ2016["spectral"]
M_PORES = MRJ2016["pores"]
M_WINDOWS = MRJ2016["number_variance"]
M_FIGURES = MRJ2016.get("figures", {})
M_CHUNK = M_DESCRIPTORS["chunk_size"]

M_CONFIG = results_path("mrj2016/configs/{system}/sample{k}.nc")
M_REFERENCE = {
    "table2": "config/reference/mrj2016_table2_equilibrium.csv",
    "table3": "config/reference/mrj2016_table3_mrj.csv",
    "table4": "config/reference/mrj2016_table4_spectral_equilibrium.csv",
    "table5": "config/reference/mrj2016_table5_spectral_mrj.csv",
    "quoted": "config/reference/mrj2016_quoted_numbers.csv",
}


M_TABLE_K = {
    "equilibrium": _m_reference_column(M_REFERENCE["table4"], "kD"),
    "mrj_large": _m_reference_column(M_REFERENCE["table5"], "kD"),
}

M_SAMPLES = {
    "overlapping": [M_CONFIG.format(system="overlapping", k=k) for k in range(M_OVERLAPPING["n_samples"])],
    "fcc": [M_CONFIG.format(system="fcc", k=k) for k in range(M_LATTICES["n_samples"])],
    "bcc": [M_CONFIG.format(system="bcc", k=k) for k in range(M_LATTICES["n_samples"])],
}
for _system, _samples in (("equilibrium", EQUILIBRIUM_SAMPLES), ("mrj", MRJ_SAMPLES),
                          ("mrj_large", MRJ_LARGE_SAMPLES), ("mrj_md", MRJ_MD_SAMPLES)):
    if len(_samples) > 0:  # a config may set a system's sample count to 0 to leave it out
        M_SAMPLES[_system] = list(_samples)

#: descriptor kinds and the systems they are computed for (if present)
M_KINDS = {
    "correlation": ["equilibrium", "mrj", "mrj_large"],
    "spectral": ["overlapping", "equilibrium", "mrj", "mrj_large", "fcc", "bcc"],
    "points": ["overlapping", "equilibrium", "mrj", "mrj_md", "fcc", "bcc"],
    "windows": ["overlapping", "equilibrium", "mrj"],
}


#: {system} and {kind} of the describe rules (constrained on those rules, not globally)
M_SYSTEM_CONSTRAINT = "|".join(["overlapping", "fcc", "bcc", "equilibrium", *MRJ_JAMMED_SYSTEMS])
M_KIND_CONSTRAINT = "|".join(M_KINDS)


# --------------------------------------------------------------------------- generate


rule mrj2016_overlapping_samples:
    """Overlapping spheres at phi = 0.636: Poisson centres in a periodic cube (Sec. III A), all
    samples in one job (each from its own seeded generator; milliseconds per sample)."""
    input:
        code=script_sources("../scripts/mrj2016/overlapping_samples.py"),
    output:
        M_SAMPLES["overlapping"],
    params:
        phi=M_OVERLAPPING["phi"],
        n_mean=M_OVERLAPPING["n_mean"],
        seed=config["seed"],
    benchmark:
        results_path("mrj2016/benchmarks/overlapping_samples.tsv")
    log:
        results_path("mrj2016/logs/overlapping_samples.log"),
    threads: 1
    script:
        "../scripts/mrj2016/overlapping_samples.py"


rule mrj2016_lattice_samples:
    """fcc / bcc lattice of touching spheres, randomly translated copies (Sec. V A)."""
    input:
        code=script_sources("../scripts/mrj2016/lattice_samples.py"),
    output:
        expand(results_path("mrj2016/configs/{{lattice}}/sample{k}.nc"), k=range(M_LATTICES["n_samples"])),
    wildcard_constraints:
        lattice="fcc|bcc",
    params:
        n_cells=lambda wildcards: M_LATTICES[f"{wildcards.lattice}_cells"],
        seed=config["seed"],
    benchmark:
        results_path("mrj2016/benchmarks/lattice_samples_{lattice}.tsv")
    log:
        results_path("mrj2016/logs/{lattice}_samples.log"),
    threads: 1
    script:
        "../scripts/mrj2016/lattice_samples.py"


# --------------------------------------------------------------------------- describe


rule mrj2016_describe_chunk:
    """One descriptor kind of one chunk of a system's samples (per-sample values)."""
    input:
        samples=m_chunk_samples,
        code=script_sources("../scripts/mrj2016/describe_chunk.py"),
    output:
        results_path("mrj2016/descriptors/{system}/{kind}_chunk{c}.nc"),
    wildcard_constraints:
        system=M_SYSTEM_CONSTRAINT,
        kind=M_KIND_CONSTRAINT,
        c=r"\d+",
    params:
        first=lambda wildcards: int(wildcards.c) * M_CHUNK,
        settings=lambda wildcards: m_describe_settings(wildcards.kind, wildcards.system),
    benchmark:
        results_path("mrj2016/benchmarks/describe_chunk_{system}_{kind}_chunk{c}.tsv")
    log:
        results_path("mrj2016/logs/{system}_{kind}_chunk{c}.log"),
    threads: 1
    resources:
        mem_mb=3000,
    script:
        "../scripts/mrj2016/describe_chunk.py"


rule mrj2016_describe:
    """One descriptor kind of one system: per-sample values, mean, SEM (+ Eq. 11 transform for
    correlation; pooled number variance and its fits for windows), merged over the chunks."""
    input:
        unpack(m_describe_inputs),
        code=script_sources("../scripts/mrj2016/describe_merge.py"),
    output:
        results_path("mrj2016/descriptors/{system}_{kind}.nc"),
    wildcard_constraints:
        system=M_SYSTEM_CONSTRAINT,
        kind=M_KIND_CONSTRAINT,
    params:
        settings=lambda wildcards: m_describe_settings(wildcards.kind, wildcards.system, merge=True),
    benchmark:
        results_path("mrj2016/benchmarks/describe_{system}_{kind}.tsv")
    log:
        results_path("mrj2016/logs/{system}_{kind}.log"),
    threads: 1
    resources:
        mem_mb=3000,
    script:
        "../scripts/mrj2016/describe_merge.py"


# --------------------------------------------------------------------------- render

MRJ2016_FIGURE_INPUTS = {
    1: {f"config_{s}": M_CONFIG.format(system=s, k=0) for s in ("overlapping", "equilibrium", "mrj")
        if m_have(s)},
    2: {},
    3: m_inputs([("correlation", "equilibrium"), ("correlation", "mrj")]),
    4: m_inputs([("correlation", "equilibrium"), ("correlation", "mrj")]),
    5: m_inputs([("correlation", "equilibrium"), ("correlation", "mrj")]),
    # the top panel: the N = 10 000 packings, or the N = 2000 ones when there are none
    6: m_inputs([("spectral", "equilibrium"), ("correlation", "equilibrium")]
                + ([("spectral", "mrj_large"), ("correlation", "mrj_large")] if m_have("mrj_large")
                   else [("spectral", "mrj"), ("correlation", "mrj")])),
    7: m_inputs([("points", s) for s in M_KINDS["points"]]),
    8: m_inputs([("points", s) for s in M_KINDS["points"]]),
    9: m_inputs([("windows", s) for s in ("overlapping", "equilibrium", "mrj")]),
    10: m_inputs([("windows", s) for s in ("overlapping", "equilibrium", "mrj")]),
    11: {},
    12: m_inputs([("correlation", "equilibrium"), ("correlation", "mrj")]),
    13: m_inputs([("correlation", "equilibrium"), ("correlation", "mrj")]),
}

#: the config values each figure's function (randmedia.plot.mrj2016.FIGURES) reads: a figure
#: gets only its own, so that e.g. figures.render_side reruns Fig. 1 alone
_M_PHI = {"overlapping_phi": M_OVERLAPPING["phi"]}
MRJ2016_FIGURE_PARAMS = {
    1: {"figures": M_FIGURES},
    2: {},
    3: _M_PHI,
    4: _M_PHI,
    5: _M_PHI,
    6: {**_M_PHI, "spectral": {"k_max": M_SPECTRAL["k_max"]}},
    7: _M_PHI,
    8: _M_PHI,
    9: {**_M_PHI, "windows": {"fit_r_min": M_WINDOWS["fit_r_min"]}},
    10: {"windows": {"fit_r_min": M_WINDOWS["fit_r_min"]}},
    11: {},
    12: _M_PHI,
    13: _M_PHI,
}


for _number in MRJ2016_FIGURE_INPUTS:

    rule:
        name:
            f"mrj2016_fig{_number:02d}"
        input:
            **MRJ2016_FIGURE_INPUTS[_number],
            code=script_sources("../scripts/mrj2016/figure.py"),
        output:
            **figure_outputs("mrj2016", _number, in_report=True),
        params:
            figure=_number,
            settings=MRJ2016_FIGURE_PARAMS[_number],
        benchmark:
            results_path(f"mrj2016/benchmarks/fig{_number:02d}.tsv")
        log:
            results_path(f"mrj2016/logs/fig{_number:02d}.log"),
        script:
            "../scripts/mrj2016/figure.py"


M_TABLE_INPUTS = {
    1: m_inputs([(kind, s) for kind in M_KINDS for s in M_KINDS[kind]]),
    2: m_inputs([("correlation", "equilibrium"), ("points", "equilibrium")]),
    3: m_inputs([("correlation", "mrj"), ("points", "mrj")]),
    4: m_inputs([("spectral", "equilibrium")]),
    5: m_inputs([("spectral", "mrj_large")]),
}
#: tables whose system exists
M_TABLES = [1] + [n for n, system in ((2, "equilibrium"), (3, "mrj"), (4, "equilibrium"),
                                      (5, "mrj_large")) if m_have(system)]


rule mrj2016_table:
    """Table N of the paper with our values (and SEM) at the paper's r/D or kD."""
    input:
        unpack(lambda wildcards: M_TABLE_INPUTS[int(wildcards.n)]),
        reference=lambda wildcards: M_REFERENCE.get(f"table{wildcards.n}", M_REFERENCE["quoted"]),
        code=script_sources("../scripts/mrj2016/table.py"),
    output:
        results_path("mrj2016/tables/table{n}.csv"),
    params:
        overlapping_phi=M_OVERLAPPING["phi"],
        spectral_binning=MRJ2016["tables"]["spectral_binning"],
    benchmark:
        results_path("mrj2016/benchmarks/table{n}.tsv")
    log:
        results_path("mrj2016/logs/table{n}.log"),
    wildcard_constraints:
        n="[1-5]",
    script:
        "../scripts/mrj2016/table.py"


rule mrj2016_comparison:
    """comparison.csv: every table cell and quoted number against ours (+ comparison_notes.csv)."""
    input:
        unpack(lambda wildcards: M_TABLE_INPUTS[1]),
        tables=expand(results_path("mrj2016/tables/table{n}.csv"), n=M_TABLES),
        references=list(M_REFERENCE.values()),
        equilibrium_validation=EQUILIBRIUM_TARGETS[3],
        code=script_sources("../scripts/mrj2016/comparison.py"),
    output:
        comparison=results_path("mrj2016/comparison.csv"),
        notes=results_path("mrj2016/comparison_notes.csv"),
    params:
        k_sigma=config["comparison"]["k_sigma"],
        overlapping_phi=M_OVERLAPPING["phi"],
        spectral=M_SPECTRAL,
        windows=M_WINDOWS,
        n_samples={system: len(samples) for system, samples in M_SAMPLES.items()},
    benchmark:
        results_path("mrj2016/benchmarks/comparison.tsv")
    log:
        results_path("mrj2016/logs/comparison.log"),
    script:
        "../scripts/mrj2016/comparison.py"


M_FIGURES_OUT = [path for n in MRJ2016_FIGURE_INPUTS for path in figure_outputs("mrj2016", n).values()]
M_TABLES_OUT = [results_path(f"mrj2016/tables/table{n}.csv") for n in M_TABLES]

MRJ2016_TARGETS = (
    M_FIGURES_OUT + M_TABLES_OUT
    + [results_path("mrj2016/comparison.csv"), results_path("mrj2016/comparison_notes.csv")]
    + EQUILIBRIUM_TARGETS
    + JAMMED_TARGETS
)


rule mrj2016:
    """Everything of mrj2016: Figs. 1-13, Tables I-V, comparison."""
    input:
        MRJ2016_TARGETS,


for _n in M_TABLES:

    rule:
        name:
            f"mrj2016_table{_n}"
        input:
            results_path(f"mrj2016/tables/table{_n}.csv"),
