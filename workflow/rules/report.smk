# The HTML report: `snakemake --report results/report.html` (with the run's --configfile),
# after a complete run. Included after the papers' rule files.
#
# * Figures: the rules that draw them mark their PNG with report() (report_figure,
#   report_validation_figure in common.smk); captions in workflow/report/{paper}/.
# * Tables: the report offers a CSV only as a download, so one job per paper,
#   {paper}_report_tables, renders every CSV among the paper's targets (tables,
#   comparison.csv, comparison_notes.csv, validation tables) as an HTML page
#   results/{paper}/report/{name}.html, failing comparison rows first with their reasons.
# * Run time and memory: every job that computes something writes a Snakemake benchmark
#   file results/{paper}/benchmarks/{rule}[_{wildcards}].tsv; the same job merges the
#   paper's benchmark files into results/{paper}/benchmarks.csv and a page.
#
# The job reads every target of its paper (so it runs after all of the paper's jobs and
# sees their benchmark files) and reruns, in seconds, whenever one of them changes;
# nothing depends on it but `all`, so it never makes another job rerun.

import re

from randmedia.record import PAPERS

#: the targets of each paper (their CSV files become report pages); debye3d, the 3D study beyond
#: the papers, has the same pages and a record (record.smk) but is not part of `all`
REPORT_PAPERS = {
    "debye2020": DEBYE2020_TARGETS,
    "mrj2016": MRJ2016_TARGETS,
    "sphere2019": SPHERE2019_TARGETS,
    "debye3d": DEBYE3D_TARGETS,
}

#: the report pages of each entry of REPORT_PAPERS
REPORT_PAGES = {}

for _paper, _targets in REPORT_PAPERS.items():
    # the paper's CSV targets and every CSV its comparison rule writes (comparison_notes.csv)
    _tables = [path for path in _targets if path.endswith(".csv")]
    _tables += [str(path) for path in getattr(rules, f"{_paper}_comparison").output
                if str(path).endswith(".csv") and str(path) not in _tables]
    _pages = {path: report_table(path, _paper) for path in _tables}
    assert len({name for name, _, _ in _pages.values()}) == len(_pages), f"two {_paper} tables share a name"
    _notes = results_path(f"{_paper}/comparison_notes.csv")

    rule:
        name:
            f"{_paper}_report_tables"
        input:
            tables=_tables,
            # every other target of the paper: this job runs after all of the paper's jobs
            targets=[path for path in _targets if path not in _tables],
            # the reasons of failing comparison rows, where the paper's comparison writes them
            **({"notes": _notes} if _notes in _tables else {}),
            code=script_sources("../scripts/report_tables.py"),
        output:
            pages=[report(results_path(f"{_paper}/report/{name}.html"), caption=f"../report/{caption}",
                          category=_paper, subcategory=subcategory)
                   for name, caption, subcategory in _pages.values()],
            benchmarks=results_path(f"{_paper}/benchmarks.csv"),
            benchmark_page=report(results_path(f"{_paper}/report/benchmarks.html"),
                                  caption="../report/benchmarks.rst", category=_paper,
                                  subcategory="Run time and memory"),
        params:
            paper=_paper,
            benchmark_patterns=report_benchmark_patterns(_paper),
        log:
            results_path(f"{_paper}/logs/report_tables.log"),
        script:
            "../scripts/report_tables.py"

    REPORT_PAGES[_paper] = [results_path(f"{_paper}/report/{name}.html") for name, _, _ in _pages.values()]
    REPORT_PAGES[_paper] += [results_path(f"{_paper}/benchmarks.csv"), results_path(f"{_paper}/report/benchmarks.html")]

#: the report pages of the default target `all` (the three papers)
REPORT_TARGETS = [path for paper in PAPERS for path in REPORT_PAGES[paper]]
