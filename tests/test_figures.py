"""The figure convention (randmedia.plot.rule): per paper a registry FIGURES of functions named
for their figures, one figure script per paper that every figure rule runs, and the helper that
draws and saves what a registry function returns."""

from __future__ import annotations

import logging

import numpy as np
from pathlib import Path
from types import SimpleNamespace

import pytest
from snakemake.iocontainers import Namedlist

from randmedia.plot import debye2020, mrj2016, rule, sphere2019
from randmedia.plot.style import figure

#: paper -> (plot module, number of figures of the paper)
PAPERS = {"debye2020": (debye2020, 12), "mrj2016": (mrj2016, 13), "sphere2019": (sphere2019, 8)}


@pytest.mark.parametrize("paper", sorted(PAPERS))
def test_every_figure_of_the_paper_has_a_function_named_for_it(paper):
    module, count = PAPERS[paper]
    numbers = {key for key in module.FIGURES if isinstance(key, int)}
    assert numbers == set(range(1, count + 1))
    for number in numbers:
        assert module.FIGURES[number].__name__ == f"fig{number:02d}"
        assert module.FIGURES[number] is getattr(module, f"fig{number:02d}")
    for key in set(module.FIGURES) - numbers:  # validation figures: named, not numbered
        assert isinstance(key, str) and module.FIGURES[key].__name__ == key


@pytest.mark.workflow
@pytest.mark.parametrize("config", ["paper", "quick"])
def test_every_figure_rule_runs_its_papers_figure_script(parsed_workflow, config):
    """A rule writing results/{paper}/figures/ or a validation figure drawn from descriptors runs
    workflow/scripts/{paper}/figure.py, and the rule's code holds its paper's plot module only."""
    workdir, probes = parsed_workflow
    rules = probes[config]["rules"]
    figure_rules = {name for name, spec in rules.items()
                    if any("/figures/" in path for path in spec["output"])}
    figure_rules |= {"debye2020_overlapping_disks_figure", "debye2020_overlapping_disks_level_set_figure"}
    assert len(figure_rules) == 12 + 13 + 8 + 2 + 5  # ... and the five of debye3d (beyond the papers)
    for name in figure_rules:
        paper = name.split("_")[0]
        spec = rules[name]
        assert Path(spec["script"]).resolve() == (workdir / "workflow" / "scripts" / paper / "figure.py").resolve(), name
        plots = {Path(path).name for path in spec["code"] if Path(path).parent.name == "plot"}
        assert plots == {"__init__.py", "rule.py", "style.py", f"{paper}.py"}, (name, plots)


def fake_job(tmp_path, key, outputs, inputs=None, settings=None):
    params = {"figure": key} if settings is None else {"figure": key, "settings": settings}
    files = {name: str(tmp_path / path) for name, path in outputs.items()}
    return SimpleNamespace(rule="test_figure", params=Namedlist(fromdict=params),
                           input=Namedlist(fromdict={"code": ["a.py"], **(inputs or {})}),
                           output=Namedlist(fromdict=files))


def test_draw_rule_figure_saves_what_the_function_returns(tmp_path):
    seen = {}

    def one(inputs, settings, log):
        seen.update(inputs=inputs, settings=settings)
        fig, ax = figure()
        ax.plot([0, 1], [settings["y"], 1])
        return fig

    def two(inputs, settings, log):
        return {name: figure()[0] for name in ("pdf", "alpha_cubed_pdf")}

    log = logging.getLogger("test_figures")
    job = fake_job(tmp_path, 1, {"pdf": "fig01.pdf", "png": "fig01.png"},
                   inputs={"data": "x.nc", "samples": ["s0.nc", "s1.nc"]}, settings={"y": 0.5})
    rule.draw_rule_figure({1: one}, job, log)
    assert seen == {"inputs": {"data": "x.nc", "samples": ["s0.nc", "s1.nc"]}, "settings": {"y": 0.5}}
    assert (tmp_path / "fig01.pdf").stat().st_size > 0 and (tmp_path / "fig01.png").stat().st_size > 0

    job = fake_job(tmp_path, 5, {"pdf": "fig05.pdf", "png": "fig05.png",
                                 "alpha_cubed_pdf": "fig05_alpha_cubed.pdf",
                                 "alpha_cubed_png": "fig05_alpha_cubed.png"})
    rule.draw_rule_figure({5: two}, job, log)
    assert {p.name for p in tmp_path.glob("fig05*")} == {
        "fig05.pdf", "fig05.png", "fig05_alpha_cubed.pdf", "fig05_alpha_cubed.png"}


def test_draw_rule_figure_names_a_mismatch(tmp_path):
    log = logging.getLogger("test_figures")
    job = fake_job(tmp_path, 3, {"pdf": "fig03.pdf", "png": "fig03.png"})
    with pytest.raises(KeyError, match="params.figure = 3"):
        rule.draw_rule_figure({1: None}, job, log)
    job = fake_job(tmp_path, 1, {"pdf": "a.pdf", "png": "a.png", "alpha_cubed_pdf": "b.pdf",
                                 "alpha_cubed_png": "b.png"})
    with pytest.raises(ValueError, match="alpha_cubed_pdf"):
        rule.draw_rule_figure({1: lambda inputs, settings, log: figure()[0]}, job, log)
    assert not list(tmp_path.glob("*.pdf"))


def test_empty_panels_finds_a_panel_with_reference_lines_only():
    from randmedia.plot.style import empty_panels, figure

    fig, axes = figure(nrows=3, ncols=1)
    axes[0].axvline(9.0)          # reference lines only: empty
    axes[0].axhline(0.5)
    axes[1].plot([0, 1, 2], [1, 2, 3])
    axes[2].errorbar([0, 1], [1, 2], yerr=[0.1, 0.1], fmt="x")
    assert empty_panels(fig) == [0]
    axes[0].plot([0, 1, 2, 3], [np.nan] * 4)  # a curve of NaNs is no data
    assert empty_panels(fig) == [0]


def test_labels_over_data_finds_a_legend_or_note_on_a_curve():
    from randmedia.plot.style import figure, labels_over_data

    fig, (top, bottom) = figure(nrows=2, ncols=1)
    x = np.linspace(0, 1, 50)
    top.plot(x, np.ones_like(x), label="flat at the top")     # runs under an upper-right legend
    top.set_ylim(0, 1.05)
    top.legend(loc="upper right")
    bottom.plot(x, x, label="diagonal")
    bottom.axhline(0.9, color="0.5")                            # a reference line: not data
    bottom.legend(loc="upper left")                              # the diagonal is low on the left
    bottom.text(0.5, 0.5, "note on the line")
    found = labels_over_data(fig)
    assert [(index, what) for index, what, _ in found] == [(0, "legend"), (1, "text 'note on the line'")]
    assert all(points > 0 for _, _, points in found)
    top.get_legend().remove()
    top.legend(loc="lower center")                              # below the flat curve: free
    bottom.texts[0].set_position((0.1, 0.8))
    assert labels_over_data(fig) == []


@pytest.mark.workflow
def test_no_figure_of_the_quick_run_has_an_empty_panel_or_a_label_over_data(quick_run):
    """Every figure job logs the panels that show no data (randmedia.plot.rule); the quick
    run's figures have none (mrj2016 Fig. 6 draws the N = 2000 MRJ packings when the config
    has no N = 10 000 ones). The same logs name legends and notes drawn over data: none."""
    from conftest import QUICK_RESULTS

    logs = sorted((quick_run / QUICK_RESULTS).glob("*/logs/*fig*.log"))
    assert logs, "no figure logs found"
    empty = [line for path in logs for line in path.read_text().splitlines()
             if "shows no data" in line or "data points" in line]
    assert not empty, "\n".join(empty)
