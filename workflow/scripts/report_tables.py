"""Rules {paper}_report_tables: the paper's CSV tables as HTML pages for the report
(comparison.csv with the reasons of comparison_notes.csv, when it exists), and the paper's
benchmark files merged into {results_dir}/{paper}/benchmarks.csv and a page."""
from randmedia.jobs import start_job

log = start_job(snakemake)

import pandas as pd

from randmedia import report
from randmedia.io import write_csv

paper, notes_path = snakemake.params.paper, snakemake.input.get("notes")
folder = f"{snakemake.config['results_dir'].rstrip('/')}/{paper}/"  # the run's results folder
notes = pd.read_csv(notes_path) if notes_path else None
for source, page in zip(snakemake.input.tables, snakemake.output.pages):
    frame = pd.read_csv(source)
    title = f"{paper}: {source.removeprefix(folder)}"
    if source == f"{folder}comparison.csv":
        text = report.comparison_page(frame, title, source, notes=notes, notes_source=notes_path)
    else:
        text = report.table_page(frame, title, source)
    report.write_page(text, page)
    log.info("%s -> %s (%d rows)", source, page, len(frame))

benchmarks = report.read_benchmarks(snakemake.params.benchmark_patterns)
write_csv(benchmarks, snakemake.output.benchmarks)
report.write_page(report.benchmark_page(benchmarks, f"{paper}: run time and memory per job",
                                        snakemake.output.benchmarks,
                                        pattern_note=f"Files: {folder}benchmarks/*.tsv "
                                                     "(one per job, present in the results folder)."),
                  snakemake.output.benchmark_page)
log.info("%d benchmark files of %d rules", len(benchmarks), benchmarks["rule"].nunique())
