"""Figures: one style (:mod:`randmedia.plot.style`) and per-paper figure functions."""
