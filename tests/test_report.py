"""The HTML report (``snakemake --report``): table pages and benchmark merging
(randmedia.report), the report annotations of the rules (every figure wrapped in report()
with an existing caption that renders, every table of a paper turned into a report page,
every computing rule with a benchmark file), and, after the session's quick run, the report
itself: one self-contained file with every figure, table and caption."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path
from types import SimpleNamespace

import pandas as pd
import pytest

from conftest import QUICK_RESULTS, RESULTS_DIR, quick_config, run_snakemake
from randmedia import report
from randmedia.config import load_config, validate_config
from randmedia.record import PAPERS, STUDIES

#: rules with a script but no benchmark: the report pages and the record, which read the merged
#: benchmark files (their own time would be in no table)
NO_BENCHMARK = {f"{paper}_{rule}" for paper in STUDIES for rule in ("report_tables", "record")}


# --------------------------------------------------------------------------- randmedia.report


def test_read_benchmarks_matches_files_to_rules(tmp_path):
    folder = tmp_path / "results/p/benchmarks"
    folder.mkdir(parents=True)
    header = "s\th:m:s\tmax_rss\tmax_vms\tmax_uss\tmax_pss\tio_in\tio_out\tmean_load\tcpu_time\n"
    for name, seconds in (("describe_mrj_points.tsv", 2.5), ("describe_chunk_mrj_points_chunk1.tsv", 4.0),
                          ("fig03.tsv", 0.5), ("stray.tsv", 9.0)):
        (folder / name).write_text(header + f"{seconds}\t0:00:0{int(seconds)}\t120.5\t900\t100\t110\t0\t1\t95\t{seconds}\n")
    # a job first sampled after its process exited: Snakemake writes zeros (here the memory of a
    # zombie); its measurements are NaN, its wall time is kept
    (folder / "fig04.tsv").write_text(header + "0.5\t0:00:00\t0.00\t0.13\t0.00\t0.00\t0.00\t0.00\t0.00\t0.00\n")
    (folder / "notes.txt").write_text("not a benchmark")
    patterns = {"p_describe": "results/p/benchmarks/describe_{system,mrj|fcc}_{kind}.tsv",
                "p_describe_chunk": "results/p/benchmarks/describe_chunk_{system}_{kind}_chunk{c,\\d+}.tsv",
                "p_figure": "results/p/benchmarks/fig{nn}.tsv"}
    frame = report.read_benchmarks(patterns, root=tmp_path)
    assert tuple(frame.columns) == report.BENCHMARK_COLUMNS
    rows = {row["file"].rsplit("/", 1)[1]: row for row in frame.to_dict("records")}
    assert set(rows) == {"describe_mrj_points.tsv", "describe_chunk_mrj_points_chunk1.tsv", "fig03.tsv",
                         "fig04.tsv"}
    assert rows["fig04.tsv"]["s"] == 0.5
    assert all(math.isnan(rows["fig04.tsv"][column]) for column in report.SAMPLED_COLUMNS)
    assert rows["describe_chunk_mrj_points_chunk1.tsv"]["rule"] == "p_describe_chunk"
    assert rows["describe_chunk_mrj_points_chunk1.tsv"]["wildcards"] == "system=mrj, kind=points, c=1"
    assert rows["describe_mrj_points.tsv"]["wildcards"] == "system=mrj, kind=points"
    assert rows["fig03.tsv"]["s"] == 0.5 and rows["fig03.tsv"]["max_rss"] == 120.5
    summary = report.benchmark_summary(frame)
    assert list(summary["rule"]) == ["p_describe_chunk", "p_describe", "p_figure"]  # by total wall time
    assert summary.set_index("rule").loc["p_describe", "jobs"] == 1
    page = report.benchmark_page(frame, "p: run time", "results/p/benchmarks.csv")
    assert "4 jobs" in page and "p_describe_chunk" in page
    empty = report.read_benchmarks(patterns, root=tmp_path / "nothing")
    assert empty.empty and tuple(empty.columns) == report.BENCHMARK_COLUMNS


def test_comparison_page_lists_failures_first_with_reasons():
    comparison = pd.DataFrame({"quantity": ["a", "b", "c"], "key": ["r=1", "r=2", "x<y"],
                               "published": [1.0, 2.0, 3.0], "ours": [1.0, 2.5, float("nan")],
                               "ours_sem": [0.1, 0.1, float("nan")], "tolerance": [0.3, 0.3, 0.0],
                               "passed": [True, False, False]})
    notes = pd.DataFrame({"quantity": ["a", "b", "c"], "key": ["r=1", "r=2", "x<y"],
                          "reason": ["", "our packings are smaller", "not computed"]})
    page = report.comparison_page(comparison, "p: comparison.csv", "results/p/comparison.csv",
                                  notes=notes, notes_source="results/p/comparison_notes.csv")
    assert "1 of 3 rows pass; 2 do not." in page
    failures = page.split("<h2>Rows that do not pass</h2>")[1].split("<h2>Every row</h2>")[0]
    assert "our packings are smaller" in failures and "not computed" in failures
    assert "x&lt;y" in failures and "x<y" not in page  # escaped
    header = failures.split("</tr>")[0]
    assert header.index(">ours<") < header.index(">reason<")  # numbers first, the wide reason last
    assert page.count("<tr class=failed>") == 2  # highlighted among every row
    plain = report.table_page(comparison.drop(columns="passed"), "p: table", "t.csv")
    assert "3 rows." in plain and "class=failed" not in plain
    assert "1 of 3 rows pass." in report.table_page(comparison, "p: table", "t.csv")


# --------------------------------------------------------------------------- the rules

@pytest.fixture(scope="module")
def probes(parsed_workflow):
    """(workflow copy, {"paper": probe, "quick": probe}) of every rule (conftest.probe_rules)."""
    return parsed_workflow


def figure_subcategory(path: str) -> str:
    match = re.search(r"/figures/fig(\d\d)(_alpha_cubed)?\.png$", path)
    return f"Fig. {match.group(1)}" if match else "Validation"


@pytest.mark.parametrize("config", ["paper", "quick"])
def test_every_figure_is_in_the_report_with_a_caption(probes, config):
    """Every rule that writes a PNG marks it with report(): category = its paper, subcategory =
    the paper's figure (or Validation), a caption file that exists; every figure of the three
    papers is among them."""
    _, parsed = probes
    root = RESULTS_DIR[config]
    reported = set()
    for name, rule in parsed[config]["rules"].items():
        pngs = [path for path in rule["output"] if path.endswith(".png")]
        flags = {flag["path"]: flag for flag in rule["report"]}
        for path in pngs:
            assert path in flags, f"rule {name}: {path} is not marked with report()"
            flag = flags[path]
            paper = Path(path).relative_to(root).parts[0]
            assert flag["category"] == paper, (name, flag)
            subcategory = figure_subcategory(path)
            assert flag["subcategory"] == subcategory, (name, flag)
            assert flag["caption"] and Path(flag["caption"]).is_file(), (name, flag)
            reported.add(path)
    expected = {f"{root}/debye2020/figures/fig{n:02d}.png" for n in range(1, 13)}
    expected |= {f"{root}/mrj2016/figures/fig{n:02d}.png" for n in range(1, 14)}
    expected |= {f"{root}/sphere2019/figures/fig{n:02d}.png" for n in range(1, 9)}
    expected |= {f"{root}/sphere2019/figures/fig{n:02d}_alpha_cubed.png" for n in range(5, 9)}
    assert expected <= reported, expected - reported


@pytest.mark.parametrize("config", ["paper", "quick"])
def test_every_table_of_a_paper_has_a_report_page(probes, config):
    """Every CSV the default target asks for is an input of its paper's report-tables rule,
    whose pages are marked with report() with an existing caption of their own."""
    _, parsed = probes
    root = RESULTS_DIR[config]
    rules = parsed[config]["rules"]
    tables = [path for path in rules["all"]["input"] if path.endswith(".csv")
              and not path.endswith("/benchmarks.csv")]
    assert any(path.endswith("comparison_notes.csv") for path in tables)
    for paper in PAPERS:
        rule = rules[f"{paper}_report_tables"]
        own = [path for path in tables if path.startswith(f"{root}/{paper}/")]
        assert {"comparison.csv"} <= {Path(path).name for path in own}
        assert set(own) <= set(rule["input"])
        pages = {flag["path"]: flag for flag in rule["report"]}
        for path in own:
            page = f"{root}/{paper}/report/{Path(path).stem}.html"
            assert page in pages, (paper, path)
            assert pages[page]["category"] == paper and Path(pages[page]["caption"]).is_file()
            assert not pages[page]["caption"].endswith("/report/table.rst"), \
                f"{path}: write its caption workflow/report/{paper}/{Path(path).stem}.rst"
        assert f"{root}/{paper}/report/benchmarks.html" in pages
        assert set(pages) <= set(rules["all"]["input"])


def test_every_computing_rule_writes_a_benchmark(probes):
    """Every rule with a script writes results/{paper}/benchmarks/<job>.tsv (distinct patterns)."""
    _, parsed = probes
    patterns = {}
    for name, rule in parsed["paper"]["rules"].items():
        if rule["script"] is None or name in NO_BENCHMARK:
            continue
        paper = name.split("_")[0]
        assert rule["benchmark"], f"rule {name} has no benchmark"
        assert rule["benchmark"].startswith(f"results/{paper}/benchmarks/"), (name, rule["benchmark"])
        assert rule["benchmark"].endswith(".tsv")
        patterns[name] = rule["benchmark"]
    assert len(patterns) >= 50 and len(set(patterns.values())) == len(patterns)


#: the link targets Snakemake appends to every caption (snakemake.report.auto_report)
RST_LINKS = """

.. _Workflow: javascript:show_panel('workflow')
.. _Statistics: javascript:show_panel('statistics')
{% for cat in categories %}
.. _{{ cat }}: javascript:app.showCategory('{{ cat|urlencode }}')
{% endfor %}
"""


def render_caption(path: Path, snakemake) -> str:
    """A caption as Snakemake's report renders it: Jinja2 (its options, its appended link
    targets of the categories), then docutils (warnings become system messages)."""
    from docutils.core import publish_parts
    from jinja2 import Environment

    text = Environment(trim_blocks=True, lstrip_blocks=True).from_string(path.read_text() + RST_LINKS).render(
        snakemake=snakemake, categories=PAPERS, files=[])
    return publish_parts(text, writer="html", settings_overrides={"report_level": 2})["html_body"]


@pytest.mark.parametrize("config", ["paper", "quick"])
def test_captions_render_without_errors(probes, config):
    """Every caption (and the workflow description with the config) renders through Jinja2 and
    docutils with no system message; a figure's caption names its figure."""
    workdir, parsed = probes
    settings = quick_config(workdir) if config == "quick" else load_config(workdir / "config" / "config.yaml")
    validate_config(settings, workdir / "workflow" / "schemas" / "config.schema.yaml")  # defaults filled
    description = render_caption(Path(parsed[config]["report_text"]), SimpleNamespace(config=settings))
    assert "system-message" not in description and "Parameters of this run" in description
    assert f'"seed": {settings["seed"]}' in description  # the whole config
    count = 0
    for name, rule in parsed[config]["rules"].items():
        for flag in rule["report"]:
            snakemake = SimpleNamespace(config=settings, rule=name, wildcards=SimpleNamespace(),
                                        params=SimpleNamespace(paper=name.split("_")[0]))
            html = render_caption(Path(flag["caption"]), snakemake)
            assert "system-message" not in html, (flag["caption"], html)
            assert len(re.sub(r"<[^>]+>", "", html).strip()) > 80, flag["caption"]
            figure = re.search(r"/figures/fig(\d\d)", flag["path"])
            if figure:
                assert re.search(rf"Fig\. {int(figure.group(1))}\b", html), flag["caption"]
            count += 1
    assert count >= 60


# --------------------------------------------------------------------------- the report


def report_data(text: str, name: str):
    """The JSON the report assigns to ``var name`` in its data scripts (one line each)."""
    match = re.search(rf'^\s*var {name} = ([{{"].*);\s*$', text, re.MULTILINE)
    assert match, name
    return json.loads(match.group(1))


@pytest.mark.workflow
def test_report_of_the_quick_run(quick_run, tmp_path):
    """snakemake --report after the quick run: one self-contained HTML file with every figure
    (PNG) and table page of the three papers, each with its caption, organised by paper, the
    run's parameters in the description; the benchmark tables cover the jobs' files."""
    target = tmp_path / "report.html"
    result = run_snakemake(quick_run, "--report", str(target), "--configfile", "config/quick.yaml")
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]
    text = target.read_text()
    assert not re.search(r"<(script|img|link)[^>]+(src|href)=\"?https?:", text)  # nothing fetched
    results = report_data(text, "results")
    categories = report_data(text, "categories")
    assert set(categories) == set(PAPERS)
    expected = ([f"{QUICK_RESULTS}/debye2020/figures/fig{n:02d}.png" for n in range(1, 13)]
                + [f"{QUICK_RESULTS}/mrj2016/figures/fig{n:02d}.png" for n in range(1, 14)]
                + [f"{QUICK_RESULTS}/sphere2019/figures/fig{n:02d}.png" for n in range(1, 9)]
                + [f"{QUICK_RESULTS}/sphere2019/figures/fig{n:02d}_alpha_cubed.png" for n in range(5, 9)])
    for path in expected:
        assert path in results, path
        entry = results[path]
        assert entry["mime_type"] == "image/png" and entry["data_uri"].startswith("data:image/png")
        number = int(re.search(r"fig(\d\d)", path).group(1))
        assert re.search(rf"Fig\. {number}\b", entry["caption"]), (path, entry["caption"][:200])
        assert path in categories[Path(path).relative_to(QUICK_RESULTS).parts[0]][f"Fig. {number:02d}"]
    tables = [p for p in (quick_run / QUICK_RESULTS).glob("*/tables/*.csv")]
    tables += [quick_run / f"{QUICK_RESULTS}/{paper}/comparison.csv" for paper in PAPERS]
    # the papers' (test_record.py's `record` also runs debye3d, which the default report leaves out)
    tables += [path for paper in PAPERS for path in (quick_run / QUICK_RESULTS / paper).glob("comparison_notes.csv")]
    assert len(tables) >= 10
    for table in tables:
        paper = table.relative_to(quick_run / QUICK_RESULTS).parts[0]
        page = f"{QUICK_RESULTS}/{paper}/report/{table.stem}.html"
        assert page in results and results[page]["mime_type"] == "text/html", page
        assert results[page]["caption"].strip(), page
    comparison = (quick_run / QUICK_RESULTS / "mrj2016/report/comparison.html").read_text()
    notes = pd.read_csv(quick_run / QUICK_RESULTS / "mrj2016/comparison_notes.csv")
    assert "rows pass" in comparison
    for reason in notes.loc[notes["reason"].fillna("") != "", "reason"].head(3):
        assert reason.split(" ")[0] in comparison
    description = report_data(text, "workflow_desc")
    assert "Parameters of this run" in description and "mrj_large" in description
    for paper in PAPERS:
        merged = pd.read_csv(quick_run / f"{QUICK_RESULTS}/{paper}/benchmarks.csv")
        files = sorted(p.relative_to(quick_run).as_posix()
                       for p in (quick_run / f"{QUICK_RESULTS}/{paper}/benchmarks").glob("*.tsv"))
        assert sorted(merged["file"]) == files and len(files) >= 10
        # every job sampled at least once has a resident set; only a job of a few seconds can
        # end before Snakemake's first sample (every 0.5 s in a job's first 30 s)
        sampled = merged["max_rss"].notna()
        assert (merged["s"] >= 0).all() and (merged.loc[sampled, "max_rss"] > 0).all()
        assert (merged.loc[~sampled, "s"] < 5).all() and sampled.mean() > 0.5
        assert merged["rule"].str.contains(rf"^{paper}_fig|^{paper}_figure$").any()
        assert f"{QUICK_RESULTS}/{paper}/report/benchmarks.html" in results


@pytest.mark.workflow
def test_report_with_the_3d_study_when_asked_by_name(quick_run, tmp_path):
    """debye3d is not part of `all`: after `snakemake debye3d` its figures and pages are in a
    report asked for with `-- all debye3d` (the front page's instruction), not in the default one."""
    result = run_snakemake(quick_run, "debye3d", "--cores", "2", "--configfile", "config/quick.yaml")
    assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-5000:]
    categories = {}
    for name, targets in (("default", ()), ("with_3d", ("--", "all", "debye3d"))):
        target = tmp_path / f"{name}.html"
        result = run_snakemake(quick_run, "--report", str(target), "--configfile", "config/quick.yaml", *targets)
        assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]
        categories[name] = report_data(target.read_text(), "categories")
    assert "debye3d" not in categories["default"]
    assert set(categories["with_3d"]) == set(STUDIES)
    entries = categories["with_3d"]["debye3d"]
    assert f"{QUICK_RESULTS}/debye3d/figures/s2.png" in entries["Validation"]
    assert f"{QUICK_RESULTS}/debye3d/report/comparison.html" in entries["Comparison"]
    assert "debye3d" in (workflow_text := (Path(quick_run) / "workflow/report/workflow.rst").read_text())
    assert "-- all debye3d" in workflow_text
