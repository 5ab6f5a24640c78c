"""The figure convention of the three papers, and the body of every figure rule.

The plot module of a paper (:mod:`randmedia.plot.debye2020`, :mod:`randmedia.plot.mrj2016`,
:mod:`randmedia.plot.sphere2019`) ends with a registry ``FIGURES = {key: function}``; the key
is the paper's figure number (or, for a validation figure beyond the paper, a name). Each
function is named for its figure (``fig05`` draws Fig. 5) and takes ``(inputs, settings,
log)``: the rule's named input files (a path, or a list of paths, each), the config values
the figure reads (the rule's ``params.settings``; a figure gets only its own, so that a
config change reruns only the figures that use it) and the job's logger. It reads its files
and returns the matplotlib figure; a figure drawn twice (sphere2019: for both readings of
Eq. 12b) returns ``{output name: figure}``.

Every figure rule of a paper runs the paper's one script ``workflow/scripts/{paper}/figure.py``
with ``params: figure=key, settings={...}``; the script imports the paper's plot module (so
the rule's input ``code``, derived from the script's imports, holds it) and calls
:func:`draw_rule_figure`, which saves figNN.pdf and figNN.png atomically
(:func:`randmedia.plot.style.save_figure`).
"""

from __future__ import annotations

from randmedia.plot.style import empty_panels, labels_over_data, save_figure


def draw_rule_figure(figures: dict, snakemake, log) -> None:
    """Draw ``figures[snakemake.params.figure](inputs, settings, log)`` and save each figure it
    returns (a figure: output ``pdf``; a dict: the outputs it names) as PDF and the PNG beside it.

    ``inputs`` are the rule's named inputs except ``code`` (a path, or a list of paths for a
    list input); ``settings`` is ``snakemake.params.settings`` (empty if the rule has none).

    Parameters
    ----------
    figures : dict
        The plot module's ``FIGURES`` registry, key -> figure function.
    snakemake : snakemake.script.Snakemake
        The rule's ``snakemake`` object (``params.figure``, ``params.settings``, ``input``, ``output``).
    log : logging.Logger
        The job's logger, passed to the figure function.
    """
    key = snakemake.params.figure
    if key not in figures:
        raise KeyError(f"rule {snakemake.rule}: params.figure = {key!r} is not a key of the registry "
                       f"(keys: {sorted(figures, key=str)})")
    draw = figures[key]
    inputs = {name: str(value) if isinstance(value, str) else [str(path) for path in value]
              for name, value in snakemake.input.items() if name != "code"}
    settings = dict(snakemake.params.get("settings") or {})
    drawn = draw(inputs, settings, log)
    if not isinstance(drawn, dict):
        drawn = {"pdf": drawn}
    pdfs = {name: str(path) for name, path in snakemake.output.items() if str(path).endswith(".pdf")}
    if set(drawn) != set(pdfs):
        raise ValueError(f"rule {snakemake.rule}: {draw.__module__}.{draw.__name__} drew {sorted(drawn)}, "
                         f"the rule's PDF outputs are {sorted(pdfs)}")
    for name, fig in drawn.items():
        log.info("%s.%s -> %s", draw.__module__, draw.__name__, pdfs[name])
        for index in empty_panels(fig):  # read by tests/test_figures.py on the quick run's logs
            log.warning("%s: panel %d of %d shows no data", pdfs[name], index + 1, len(fig.axes))
        for index, what, points in labels_over_data(fig):  # read by the same test
            log.warning("%s: panel %d of %d: %s lies over %d data points", pdfs[name], index + 1,
                        len(fig.axes), what, points)
        save_figure(fig, pdfs[name])
