"""Tables of the HTML report (``snakemake --report``): CSV outputs as HTML pages, and the
Snakemake ``benchmark:`` files of a paper merged into one table.

Snakemake's report shows images, PDFs and HTML in its page, but offers a CSV only as a
download, so every table of a paper (``tables/*.csv``, ``comparison.csv``,
``comparison_notes.csv``, validation tables) is also rendered as a self-contained HTML page:
:func:`table_page` for any table, :func:`comparison_page` for a comparison (a summary line,
the rows that do not pass with their reasons from the notes first, then every row).
:func:`read_benchmarks` collects the benchmark files of a paper's jobs (one TSV per job,
written by Snakemake: wall time ``s``, ``cpu_time``, ``max_rss`` in MB, ...) by the rules'
benchmark patterns; :func:`benchmark_page` shows them per rule and per job.
"""

from __future__ import annotations

import html
import math
import re
from pathlib import Path
from typing import Mapping

import pandas as pd

from randmedia.io import atomic_output

__all__ = ["BENCHMARK_COLUMNS", "benchmark_page", "benchmark_summary", "comparison_page", "html_table",
           "read_benchmarks", "table_page", "write_page"]

#: columns of the merged benchmark table (Snakemake's benchmark columns we keep, in order)
BENCHMARK_COLUMNS = ("rule", "wildcards", "s", "cpu_time", "max_rss", "max_uss", "max_pss", "max_vms",
                     "io_in", "io_out", "mean_load", "file")
#: the columns Snakemake measures by sampling the job's processes (:func:`read_benchmarks`)
SAMPLED_COLUMNS = ("cpu_time", "max_rss", "max_uss", "max_pss", "max_vms", "io_in", "io_out", "mean_load")

_STYLE = """
body { font-family: system-ui, sans-serif; font-size: 13px; margin: 1em; color: #111; background: #fff; }
h1 { font-size: 17px; margin: 0 0 .3em 0; } h2 { font-size: 15px; margin: 1.2em 0 .3em 0; }
p { margin: .3em 0; max-width: 70em; }
table { border-collapse: collapse; margin: .4em 0; }
th, td { border: 1px solid #bbb; padding: 2px 6px; text-align: left; vertical-align: top; }
th { background: #eee; position: sticky; top: 0; }
td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
td.text { min-width: 24em; max-width: 50em; }  /* reasons wrap in a few lines, not many */
tr.failed td { background: #fbdada; }
.summary { font-weight: 600; }
"""


# --------------------------------------------------------------------------- HTML


def _cell(value) -> tuple[str, bool]:
    """(text, is_number) of one table cell."""
    if isinstance(value, (bool,)):
        return ("yes" if value else "no"), False
    if isinstance(value, float):
        if math.isnan(value):
            return "", True
        return f"{value:.6g}", True
    if isinstance(value, int):
        return str(value), True
    if value is None or (not isinstance(value, str) and pd.isna(value)):
        return "", False
    return str(value), False


def _failed_mask(frame: pd.DataFrame) -> pd.Series:
    """Rows whose ``passed`` column is false (none without that column)."""
    if "passed" not in frame.columns:
        return pd.Series(False, index=frame.index)
    passed = frame["passed"].map(lambda v: str(v).strip().lower() in ("true", "1", "yes"))
    return ~passed


def html_table(frame: pd.DataFrame, wide: tuple[str, ...] = ("reason",)) -> str:
    """``frame`` as an HTML table; rows with ``passed`` false get the class ``failed``, cells of
    the ``wide`` columns (long text) the class ``text``."""
    failed = _failed_mask(frame)
    head = "".join(f"<th>{html.escape(str(column))}</th>" for column in frame.columns)
    rows = []
    for (index, row), is_failed in zip(frame.iterrows(), failed):
        cells = []
        for column, value in zip(frame.columns, row.tolist()):
            text, number = _cell(value.item() if hasattr(value, "item") else value)
            kind = "num" if number else ("text" if column in wide else "")
            cells.append(f'<td class="{kind}">{html.escape(text)}</td>' if kind else f"<td>{html.escape(text)}</td>")
        rows.append(f'<tr{" class=failed" if is_failed else ""}>{"".join(cells)}</tr>')
    return f"<table><thead><tr>{head}</tr></thead><tbody>\n" + "\n".join(rows) + "\n</tbody></table>"


def _page(title: str, body: str) -> str:
    return (f'<!doctype html>\n<html lang="en"><head><meta charset="utf-8">'
            f"<title>{html.escape(title)}</title><style>{_STYLE}</style></head>\n"
            f"<body>\n<h1>{html.escape(title)}</h1>\n{body}\n</body></html>\n")


def _source(path) -> str:
    return f"<p>Source: <code>{html.escape(str(path))}</code></p>"


def table_page(frame: pd.DataFrame, title: str, source) -> str:
    """A table (any CSV) as an HTML page; with a ``passed`` column, a pass count first and
    the rows that do not pass highlighted.

    Parameters
    ----------
    frame : pandas.DataFrame
        The table.
    title : str
        Page title.
    source : str or os.PathLike
        Path of the CSV, shown on the page.

    Returns
    -------
    str
        The HTML page.
    """
    parts = [_source(source), f"<p>{len(frame)} rows.</p>"]
    if "passed" in frame.columns:
        failed = _failed_mask(frame)
        parts[1] = f'<p class="summary">{int((~failed).sum())} of {len(frame)} rows pass.</p>'
    parts.append(html_table(frame))
    return _page(title, "\n".join(parts))


def comparison_page(comparison: pd.DataFrame, title: str, source,
                    notes: pd.DataFrame | None = None, notes_source=None) -> str:
    """A comparison (columns quantity, key, published, ours, ours_sem, tolerance, passed) as
    an HTML page: the pass count, the rows that do not pass (with their deviation in units of
    the tolerance and their reason when ``notes`` -- comparison_notes.csv -- are given, matched
    on quantity and key), then every row (with all columns of the notes) with the failures
    highlighted.

    Parameters
    ----------
    comparison : pandas.DataFrame
        Rows of comparison.csv.
    title : str
        Page title.
    source : str or os.PathLike
        Path of comparison.csv, shown on the page.
    notes : pandas.DataFrame, optional
        Rows of comparison_notes.csv (reasons), joined on quantity and key.
    notes_source : str or os.PathLike, optional
        Path of the notes, shown when ``notes`` are given.

    Returns
    -------
    str
        The HTML page.
    """
    failed = _failed_mask(comparison)
    parts = [_source(source) if notes is None else
             f"<p>Sources: <code>{html.escape(str(source))}</code>, "
             f"<code>{html.escape(str(notes_source))}</code> (reasons, error budget)</p>",
             f'<p class="summary">{int((~failed).sum())} of {len(comparison)} rows pass; '
             f"{int(failed.sum())} do not.</p>"]
    joined = comparison
    if notes is not None and {"quantity", "key"} <= set(notes.columns):
        extra = notes.drop_duplicates(["quantity", "key"])
        joined = comparison.merge(extra, on=["quantity", "key"], how="left", suffixes=("", "_note"))
    if failed.any():  # the numbers right after the row's name, the (wide) reason last: a
        # 1400 px window then shows published and ours without scrolling sideways
        failures = joined[failed.to_numpy()]
        columns = ["quantity", "key", "published", "ours", "ours_sem", "tolerance"]
        columns += ["deviation_in_tolerances"] if "deviation_in_tolerances" in failures.columns else []
        columns += ["reason"] if "reason" in failures.columns else []
        parts += ["<h2>Rows that do not pass</h2>", html_table(failures[columns])]
    parts += ["<h2>Every row</h2>", html_table(joined)]
    return _page(title, "\n".join(parts))


def write_page(text: str, path) -> Path:
    """Write an HTML page atomically."""
    path = Path(path)
    with atomic_output(path) as tmp:
        tmp.write_text(text, encoding="utf-8")
    return path


# --------------------------------------------------------------------------- benchmarks


def _pattern_regex(pattern: str) -> re.Pattern:
    """A Snakemake file pattern (``{name}`` or ``{name,regex}`` wildcards) as a regex."""
    parts, position = [], 0
    for match in re.finditer(r"\{([A-Za-z_]\w*)(?:,([^{}]*))?\}", pattern):
        parts.append(re.escape(pattern[position:match.start()]))
        parts.append(f"(?P<{match.group(1)}>{match.group(2) or '.+'})")
        position = match.end()
    parts.append(re.escape(pattern[position:]))
    return re.compile("".join(parts))


def read_benchmarks(patterns: Mapping[str, str], root=".") -> pd.DataFrame:
    """Every benchmark file under ``root`` that matches the benchmark pattern of a rule
    (``patterns``: rule name -> pattern, relative to ``root``), one row per file: the rule, the
    job's wildcards (``name=value, ...``), Snakemake's measurements (:data:`BENCHMARK_COLUMNS`)
    and the file. A file matching several patterns goes to the pattern with the longest literal
    part (the most specific).

    Snakemake samples a job's processes (every 0.5 s in its first 30 s); a job that ends before
    the first sample gets NA, and one first sampled after its process exited (a zombie) gets
    zeros. A resident set of 0 is never a running process, so such a row's measurements of the
    process (memory, I/O, load, CPU time) are NaN here -- not sampled -- and only its wall time
    ``s`` is kept."""
    root = Path(root)
    compiled = sorted(((rule, _pattern_regex(pattern), pattern) for rule, pattern in patterns.items()),
                      key=lambda item: -len(re.sub(r"\{[^{}]*\}", "", item[2])))
    directories = {Path(re.split(r"\{", pattern)[0]).parent if "{" in pattern else Path(pattern).parent
                   for pattern in patterns.values()}
    rows = []
    for directory in sorted(directories):
        for path in sorted((root / directory).glob("*.tsv")) if (root / directory).is_dir() else []:
            relative = path.relative_to(root).as_posix()
            for rule, regex, _ in compiled:
                match = regex.fullmatch(relative)
                if match:
                    break
            else:
                continue
            measured = pd.read_csv(path, sep="\t")
            for record in measured.to_dict("records"):
                row = {"rule": rule, "wildcards": ", ".join(f"{k}={v}" for k, v in match.groupdict().items()),
                       "file": relative}
                row.update({column: record.get(column, math.nan) for column in BENCHMARK_COLUMNS
                            if column not in row})
                if pd.to_numeric(row["max_rss"], errors="coerce") == 0:  # sampled after it exited
                    row.update({column: math.nan for column in SAMPLED_COLUMNS})
                rows.append(row)
    frame = pd.DataFrame(rows, columns=list(BENCHMARK_COLUMNS))
    return frame.sort_values(["rule", "file"], kind="stable").reset_index(drop=True)


def benchmark_summary(frame: pd.DataFrame) -> pd.DataFrame:
    """Per rule: number of jobs, total and largest wall time (s), total CPU time (s), largest
    peak resident memory (MB); rules by total wall time, largest first."""
    numeric = frame.assign(**{c: pd.to_numeric(frame[c], errors="coerce") for c in ("s", "cpu_time", "max_rss")})
    summary = numeric.groupby("rule").agg(jobs=("s", "size"), wall_s_total=("s", "sum"),
                                          wall_s_max=("s", "max"), cpu_s_total=("cpu_time", "sum"),
                                          max_rss_MB=("max_rss", "max"))
    return summary.sort_values("wall_s_total", ascending=False).reset_index()


def benchmark_page(frame: pd.DataFrame, title: str, source, pattern_note: str = "") -> str:
    """Benchmarks of a paper's jobs: totals, per rule, then every job.

    Parameters
    ----------
    frame : pandas.DataFrame
        Snakemake benchmarks, one row per job (columns rule, s, cpu_time, max_rss, ...).
    title : str
        Page title.
    source : str or os.PathLike
        Path of the benchmarks CSV, shown on the page.
    pattern_note : str, optional
        Text appended to the explanation of the columns (HTML-escaped).

    Returns
    -------
    str
        The HTML page.
    """
    total = pd.to_numeric(frame["s"], errors="coerce").sum()
    cpu = pd.to_numeric(frame["cpu_time"], errors="coerce").sum()
    parts = [_source(source),
             f'<p class="summary">{len(frame)} jobs; wall time summed over jobs {total:.1f} s, '
             f"CPU time {cpu:.1f} s.</p>",
             "<p>Wall time <code>s</code> and <code>cpu_time</code> in seconds, memory "
             "(<code>max_rss</code>: peak resident set, <code>max_uss</code>, <code>max_pss</code>, "
             "<code>max_vms</code>) in MB, <code>io_in</code>/<code>io_out</code> in MB, "
             "<code>mean_load</code> in % of one core, as measured by Snakemake for each job "
             "(the job's process and its children). " + html.escape(pattern_note) + "</p>",
             "<h2>Per rule</h2>", html_table(benchmark_summary(frame)),
             "<h2>Every job</h2>", html_table(frame)]
    return _page(title, "\n".join(parts))

