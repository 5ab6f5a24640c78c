"""Rules {paper}_record: the paper's final outputs copied into its record folder with run.json
(randmedia.record)."""
from randmedia.jobs import start_job

log = start_job(snakemake)

from pathlib import Path

import pandas as pd

import randmedia
from randmedia import record

REPO = Path(randmedia.__file__).resolve().parents[2]  # the checkout whose commit is recorded

paper = snakemake.params.paper
prefix = f"{snakemake.config['results_dir'].rstrip('/')}/{paper}/"  # the run's results folder
sources = {path.removeprefix(prefix): path
           for path in [*snakemake.input.tables, *snakemake.input.figures]}
comparison = pd.read_csv(snakemake.input.comparison)
benchmarks = pd.read_csv(snakemake.input.benchmarks)
folder = record.write_record(
    snakemake.output[0], sources, benchmarks,
    lambda files: record.run_info(paper, snakemake.config, REPO, comparison,
                                  benchmarks, files))
problems = record.check_record(folder, Path("config/reference"),
                               require_commit=False)
for problem in problems:
    log.warning("record check: %s", problem)
log.info("%s: %d files, comparison %s", folder, len(sources) + 2, record.comparison_summary(comparison))
