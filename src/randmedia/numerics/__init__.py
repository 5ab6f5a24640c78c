"""Shared numerics at the bottom of the package, beside :mod:`randmedia.theory`: what the
generators and the descriptors both use, so that neither imports the other.

* :mod:`randmedia.numerics.checks` -- the argument checks of the formulas and generators
  (dimension, fraction, positive length), one message per kind of bad value;
* :mod:`randmedia.numerics.radial` -- periodic autocorrelation by FFT and the radial bins of
  the lattice displacements (:class:`~randmedia.numerics.radial.RadialBinning`), used by the
  Yeong-Torquato construction and by the two-point descriptors alike;
* :mod:`randmedia.numerics.gaussian` -- the truncation of the Gaussian filters of the level
  sets and the interior margin it implies for windows.

Layers import downward only: theory and numerics, then generate, describe, fit, compare,
plot, workflow. Nothing here imports another part of :mod:`randmedia`.
"""
