"""Per-paper protocols of the describe stage: which estimators of :mod:`randmedia.describe`
run on which configurations of a paper, with which seeds, into which per-sample
datasets and merged summaries. Their outputs feed the per-paper modules
:mod:`randmedia.compare` and :mod:`randmedia.plot`."""
