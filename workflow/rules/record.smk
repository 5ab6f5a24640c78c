# The record of a paper-config run (randmedia.record): `snakemake record` runs what is out of
# date and copies each paper's small final outputs (comparison, notes, tables, figures as PNG,
# runtimes, run.json) to record/{paper}/ and the status table to record/README.md; also the
# 3D study beyond the papers (record/debye3d/), which `snakemake record` runs although `all`
# does not. Included after report.smk (it reads each paper's merged benchmarks.csv).
#
# Only the paper's own configuration is recorded under record/ (record_root, common.smk); any other
# configuration writes results/record/, so a quick or extended run never overwrites the
# committed record.

RECORD_FOLDERS = {paper: f"{record_root(paper)}/{paper}" for paper in REPORT_PAPERS}

for _paper, _targets in REPORT_PAPERS.items():
    _csv = [str(path) for path in getattr(rules, f"{_paper}_report_tables").input.tables]

    rule:
        name:
            f"{_paper}_record"
        input:
            comparison=results_path(f"{_paper}/comparison.csv"),
            notes=results_path(f"{_paper}/comparison_notes.csv"),
            tables=sorted(set(_csv)),
            figures=[path for path in _targets if path.endswith(".png")],
            benchmarks=results_path(f"{_paper}/benchmarks.csv"),
            # every other target: the record is made after all of the paper's jobs
            targets=[path for path in _targets if not path.endswith((".csv", ".png"))],
            code=script_sources("../scripts/record.py"),
        output:
            directory(RECORD_FOLDERS[_paper]),
        params:
            paper=_paper,
        log:
            results_path(f"{_paper}/logs/record.log"),
        script:
            "../scripts/record.py"


rule record:
    """Every paper's record and the status table (record/README.md, or results/record/ for a
    configuration other than the papers')."""
    input:
        list(RECORD_FOLDERS.values()),
    output:
        # one status table per root: results/record/ when any paper's config differs
        results_path("record/README.md") if any(record_root(paper) != "record" for paper in REPORT_PAPERS)
        else "record/README.md",
    log:
        results_path("logs/record.log"),
    run:
        from randmedia.record import write_status

        for root in sorted({str(Path(folder).parent) for folder in RECORD_FOLDERS.values()}):
            write_status(root)
