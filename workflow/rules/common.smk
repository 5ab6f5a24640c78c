# Shared helpers and environment of every rule.
import csv
import math
import os
import re
from pathlib import Path

from randmedia.blas_kernels import pin_blas_kernels
from randmedia.workflow_sources import SourceError, numba_cache_dir as _numba_cache_dir, script_sources as _script_sources

PACKAGE_DIR = Path(workflow.basedir) / "src" / "randmedia"

# Parallel jobs must not fail on HDF5 file locks (our writes are atomic
# renames), and share one numba cache per working directory and package content
# (numba_cache_dir: numba alone would keep a kernel's stale callees from other
# modules after an edit). numba writes its cache index and data files to a
# temporary name and renames them, so concurrent jobs compiling the same kernel
# do not corrupt the cache.
os.environ.setdefault("HDF5_USE_FILE_LOCKING", "FALSE")
os.environ.setdefault("NUMBA_CACHE_DIR", str(_numba_cache_dir(PACKAGE_DIR, ".cache/numba")))
# Every job runs with the same OpenBLAS kernels (Haswell on x86-64 CPUs with AVX2, unless
# OPENBLAS_CORETYPE is set), so that a packing's LP trajectory, chaotic in the last bit, hence the
# packing, is the same on every such CPU (randmedia.blas_kernels).
pin_blas_kernels()

#: where this run's outputs go (config key ``results_dir``): results/ for the paper config,
#: results/quick/ for config/quick.yaml, so that a quick run never replaces (deletes) hours of
#: paper-config outputs. Every output, log and benchmark path of every rule is results_path(...).
RESULTS = config["results_dir"].rstrip("/")


def results_path(relative):
    """``relative`` (e.g. "debye2020/comparison.csv", may hold {wildcards}) under this run's
    results folder (config ``results_dir``)."""
    return f"{RESULTS}/{relative}"


def script_sources(script):
    """The package modules (.py files) that the script ``script`` of a rule (a path relative
    to the rule's file, as written after its script keyword) can run: the transitive closure
    of its imports of randmedia (randmedia.workflow_sources). Every script rule lists them
    as its input ``code``, so that editing any of them reruns the rule and editing any other
    module reruns nothing; check_script_rules() (end of the Snakefile) enforces it."""
    path = Path(str(workflow.current_basedir)) / script
    try:
        return [str(f) for f in _script_sources(path, PACKAGE_DIR)]
    except SourceError as error:
        raise WorkflowError(f"sources of the script {script}: {error}")


def check_script_rules():
    """Every rule with a Python script has the input ``code`` = script_sources(its script)."""
    problems = []
    for spec in workflow.rules:
        name, script_name = spec.name, spec.script
        if not script_name or not str(script_name).endswith(".py"):
            continue
        script = Path(str(spec.basedir)) / script_name
        try:
            expected = sorted(str(f) for f in _script_sources(script, PACKAGE_DIR))
        except SourceError as error:
            problems.append(f"rule {name} -- {error}")
            continue
        code = spec.input.get("code")
        if code is None or callable(code):
            problems.append(f"rule {name} -- no static input `code` "
                            f"(add code=script_sources({str(script_name)!r}))")
        elif sorted(str(f) for f in ([code] if isinstance(code, str) else code)) != expected:
            problems.append(f"rule {name} -- input `code` is not script_sources({str(script_name)!r})")
    if problems:
        listing = "\n  ".join(problems)
        raise WorkflowError(f"package sources of script rules:\n  {listing}")



# --------------------------------------------------------------------------- HTML report
# (snakemake --report results/report.html; captions in workflow/report/, categories by paper)


def report_figure(path, paper, number, caption=None):
    """``path`` (a PNG of figure ``number`` of ``paper``) marked for the HTML report: category
    ``paper``, subcategory "Fig. NN" (zero-padded: the report sorts subcategories as text),
    caption workflow/report/{paper}/{caption or figNN.rst}."""
    caption = caption or f"fig{number:02d}.rst"
    return report(path, caption=f"../report/{paper}/{caption}", category=paper,
                  subcategory=f"Fig. {number:02d}")


def report_validation_figure(path, paper, caption):
    """A validation figure (beyond the paper's figures) in the report: subcategory Validation."""
    return report(path, caption=f"../report/{paper}/{caption}", category=paper,
                  subcategory="Validation")


def figure_outputs(paper, number, second_reading=False, in_report=False):
    """Output files of figure ``number`` of ``paper`` (made by {paper}_figNN): figNN.pdf and
    figNN.png under its figures/ folder; with ``second_reading`` (sphere2019) also
    figNN_alpha_cubed (the same figure for the second reading of its Eq. 12b); with
    ``in_report`` (rule outputs) the PNGs are marked for the HTML report (report_figure)."""
    stem = results_path(f"{paper}/figures/fig{number:02d}")
    files = {ext: f"{stem}.{ext}" for ext in ("pdf", "png")}
    if second_reading:
        files.update({f"alpha_cubed_{ext}": f"{stem}_alpha_cubed.{ext}" for ext in ("pdf", "png")})
    if in_report:  # the PNGs marked for the HTML report
        files["png"] = report_figure(files["png"], paper, number)
        if second_reading:
            files["alpha_cubed_png"] = report_figure(files["alpha_cubed_png"], paper, number,
                                                     caption="alpha_cubed.rst")
    return files


_ROMAN = {1: "I", 2: "II", 3: "III", 4: "IV", 5: "V"}


def report_table(path, paper):
    """(page name, caption file under workflow/report/, subcategory) of the report page of the
    CSV ``path`` of ``paper`` (rules {paper}_report_tables, report.smk)."""
    name = Path(path).stem
    folder = Path(path).parent.name
    table = re.fullmatch(r"table(\d)", name)
    if name in ("comparison", "comparison_notes") and folder == paper:
        return name, f"{name}.rst", "Comparison"
    if table and folder == "tables":
        return name, f"{paper}/{name}.rst", f"Table {_ROMAN[int(table.group(1))]}"
    if folder == "validation":
        return name, f"{paper}/validation_{name}.rst", "Validation"
    caption = f"{paper}/{name}.rst"
    if not (Path(workflow.basedir) / "workflow" / "report" / caption).is_file():
        caption = "table.rst"  # a table without a caption of its own (tests/test_report.py lists them)
    return name, caption, "Tables"


def report_benchmark_patterns(paper):
    """{rule: benchmark pattern} of every rule defined so far whose benchmark files lie in
    the run's {results_dir}/{paper}/benchmarks/."""
    return {rule.name: str(rule.benchmark) for rule in workflow.rules
            if rule.benchmark is not None and str(rule.benchmark).startswith(results_path(f"{paper}/benchmarks/"))}


# --------------------------------------------------------------------------- debye2020 helpers
# (called by the rules of workflow/rules/debye2020.smk; they read that file's constants)


# LEVEL_SET_SURFACE, LEVEL_SET_PORES: defined in debye2020.smk (included after this file)
def level_set_files(system):
    return {"surface": LEVEL_SET_SURFACE.format(system=system),
            "pores": LEVEL_SET_PORES.format(system=system)}


# DISKS_SYSTEM, HARD_DISKS_SYSTEM: defined in debye2020.smk (included after this file)
def comparison_models():
    """The Sec. VI comparison systems (overlapping and equilibrium hard disks)."""
    return [DISKS_SYSTEM, HARD_DISKS_SYSTEM]


# COMPARISON_PHI2, DISKS_SYSTEM, HARD_DISKS_SYSTEM, MEDIA_CHORDS, DISKS_CHORDS: defined in debye2020.smk (included after this file)
def section6_inputs(number):
    """Inputs of Figs. 9-12: the comparison-phi2 media, overlapping and hard disks."""
    media = level_set_files(f"media_phi{COMPARISON_PHI2}")
    disks = level_set_files(DISKS_SYSTEM)
    if number == 9:
        files = {"media_surface": media["surface"], "disks_surface": disks["surface"]}
    elif number == 10:
        files = {"media_pores": media["pores"], "disks_pores": disks["pores"]}
    else:
        files = {"media_chords": MEDIA_CHORDS.format(phi2=COMPARISON_PHI2),
                 "disks_chords": DISKS_CHORDS}
    hard = level_set_files(HARD_DISKS_SYSTEM)
    files["hard_surface"] = hard["surface"]
    if number == 10:
        files["hard_pores"] = hard["pores"]
    return files


# --------------------------------------------------------------------------- mrj2016 helpers
# (called by the rules of workflow/rules/mrj2016.smk; they read that file's constants)


def _m_reference_column(path, column):
    with open(path) as handle:
        return [float(row[column]) for row in csv.DictReader(handle)]


# M_SAMPLES: defined in mrj2016.smk (included after this file)
def m_have(system):
    return system in M_SAMPLES


# M_KINDS: defined in mrj2016.smk (included after this file)
def m_systems(kind):
    return [s for s in M_KINDS[kind] if m_have(s)]


# M_SAMPLES, M_CHUNK: defined in mrj2016.smk (included after this file)
def m_n_chunks(system):
    return math.ceil(len(M_SAMPLES[system]) / M_CHUNK)


# M_CHUNK, M_SAMPLES: defined in mrj2016.smk (included after this file)
def m_chunk_samples(wildcards):
    first = int(wildcards.c) * M_CHUNK
    return M_SAMPLES[wildcards.system][first: first + M_CHUNK]


def m_merged(system, kind):
    return results_path(f"mrj2016/descriptors/{system}_{kind}.nc")


def m_inputs(pairs):
    """Named inputs {kind_system: merged file} for the (kind, system) pairs that exist."""
    return {f"{kind}_{system}": m_merged(system, kind) for kind, system in pairs
            if system in m_systems(kind)}


# M_DESCRIPTORS, M_SPECTRAL, M_TABLE_K, M_PORES, M_WINDOWS: defined in mrj2016.smk (included after this file)
def m_describe_settings(kind, system, merge=False):
    """The config values a describe job of one kind uses, and nothing else (so that changing
    another kind's keys reruns none of its jobs): keyword arguments of
    randmedia.studies.mrj2016.describe (and, for the merge, of summarize).
    descriptors.chunk_size only sets how samples are split into jobs (the chunk files and
    `first`), not any value; number_variance.fit_r_min is used by the merge alone."""
    if kind == "correlation":
        settings = {"descriptors": {key: value for key, value in M_DESCRIPTORS.items()
                                    if key != "chunk_size"}}
        if merge:  # the Eq. (11) transform runs on k <= spectral.k_max
            settings["spectral"] = {"k_max": M_SPECTRAL["k_max"]}
        return settings
    if kind == "spectral":
        return {"spectral": M_SPECTRAL, "table_k": M_TABLE_K.get(system, [])}
    if kind == "points":
        return {"pores": M_PORES, "seed": config["seed"]}
    if merge:
        return {"windows": M_WINDOWS, "seed": config["seed"]}
    return {"windows": {key: value for key, value in M_WINDOWS.items() if key != "fit_r_min"},
            "seed": config["seed"]}


# M_SAMPLES: defined in mrj2016.smk (included after this file)
def m_describe_inputs(wildcards):
    """The chunk files of a system with several chunks; its samples when they form one chunk
    (then the merge job computes them itself: one job instead of two)."""
    if m_n_chunks(wildcards.system) == 1:
        return {"samples": M_SAMPLES[wildcards.system]}
    return {"chunks": expand(results_path("mrj2016/descriptors/{system}/{kind}_chunk{c}.nc"),
                             system=wildcards.system, kind=wildcards.kind,
                             c=range(m_n_chunks(wildcards.system)))}


# --------------------------------------------------------------------------- sphere2019 helpers
# (called by the rules of workflow/rules/sphere2019.smk; they read that file's constants)


# SPHERE_DESCRIPTOR: defined in sphere2019.smk (included after this file)
def sphere_descriptors(systems):
    return expand(SPHERE_DESCRIPTOR, system=systems)


# --------------------------------------------------------------------------- record (record.smk)

from randmedia.config import load_config as _load_config, validate_config
from randmedia.mrj_stages import route_stage as mrj_route_stage, system_stage as mrj_stage
from randmedia.record import paper_config as _paper_config

#: the paper-fidelity configuration (config/config.yaml alone, defaults filled in)
_PAPER_CONFIG = _load_config(Path(workflow.basedir) / "config" / "config.yaml")
validate_config(_PAPER_CONFIG, Path(workflow.basedir) / "workflow" / "schemas" / "config.schema.yaml")


def record_root(paper):
    """record/ when the run's configuration of ``paper`` is the paper's own (its section,
    seed, comparison as in config/config.yaml), {results_dir}/record/ otherwise: a quick or
    extended run never overwrites the committed record."""
    same = _paper_config(config, paper) == _paper_config(_PAPER_CONFIG, paper)
    return "record" if same else results_path("record")


# --------------------------------------------------------------------------- mrj2016 packings

#: what makes a packing (the rule's params but the run-only ones): the stages, contacts, order cutoff
_PACKING_KEYS = ("route", "dilute", "compression", "inflation", "polish", "contacts", "bond_order_cutoff")


# MRJ_JAMMED: defined in mrj2016_jammed.smk (read when the rule asks, after all includes)
def mrj_keep_dir(system):
    """record/packings/mrj2016 when this config makes the same packings of ``system`` as the paper
    config (same seed, size and packing parameters -- whatever its sample counts, so a larger
    ensemble adds to the kept packings), {results_dir}/record/packings/mrj2016 otherwise."""
    paper = _PAPER_CONFIG["mrj2016"]["mrj"]
    same = (config["seed"] == _PAPER_CONFIG["seed"]
            and MRJ_JAMMED[system]["n_particles"] == paper[system]["n_particles"]
            and all(mrj_stage(MRJ_JAMMED, system, key) == mrj_stage(paper, system, key)
                    for key in _PACKING_KEYS))
    return "record/packings/mrj2016" if same else results_path("record/packings/mrj2016")
