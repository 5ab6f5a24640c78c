# Reproduction of three papers on disordered structure; see README.md.
#
#   snakemake                      everything that exists, paper-fidelity config
#   snakemake --configfile config/quick.yaml        same DAG, small parameters
#   snakemake debye2020            one paper (named targets: README.md)
#   snakemake debye3d              beyond the papers: 3D Debye media (not part of `all`)
#
# The merged config is validated against workflow/schemas/config.schema.yaml
# (defaults filled in) before any job is scheduled.

from pathlib import Path

from snakemake.utils import min_version

from randmedia.config import validate_config

# the Snakemake this workflow is tested with (requirements.lock: 9.27.1)
min_version("9.27")


configfile: "config/config.yaml"


# `snakemake --report results/report.html`: this page, the figures and tables (workflow/rules/report.smk)
report: "workflow/report/workflow.rst"


validate_config(config, Path(workflow.basedir) / "workflow" / "schemas" / "config.schema.yaml")


# sample indices are numbers in every rule (other wildcards are constrained by their rules)
wildcard_constraints:
    k=r"\d+",


include: "workflow/rules/common.smk"
include: "workflow/rules/hard_particles.smk"
include: "workflow/rules/debye2020.smk"
include: "workflow/rules/mrj2016_jammed.smk"
include: "workflow/rules/mrj2016.smk"
include: "workflow/rules/sphere2019.smk"
include: "workflow/rules/debye3d.smk"
include: "workflow/rules/report.smk"
include: "workflow/rules/record.smk"


rule all:
    default_target: True
    input:
        DEBYE2020_TARGETS,
        MRJ2016_TARGETS,
        SPHERE2019_TARGETS,
        REPORT_TARGETS,


# every script rule lists its script's package modules as input `code` (common.smk)
check_script_rules()
