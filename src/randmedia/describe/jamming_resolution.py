"""At which contact gap tolerance a packing passes the strict-jamming test.

:func:`randmedia.describe.jamming.analyse` certifies a packing as strictly jammed
for one contact definition (pairs with gap < ``gap_tolerance``). A sequential-LP
packing is converged only to the precision of its last LPs: its contacts close to
gaps of ~1e-12 .. 1e-10 D, and a contact of the isostatic network may carry no
force (the self stress is degenerate), so the first-order test fails at 1e-9 D
while the motion it finds is blocked by pairs a little further apart. How far
apart is what this module measures: the smallest tolerance of the ladder
``gap_tolerance x 10^m`` (m = 0, 1, ...) at which the test passes -- the
*certified gap tolerance* of the packing. 1e-9 D (the configured value) means
strictly jammed as the paper's packings are; 1e-6 D means jammed once pairs
closer than 1e-6 D count as contacts, i.e. any unjamming motion of the packing
is shorter than ~1e-6 D. NaN: not certified up to ``max_tolerance``.
"""

from __future__ import annotations

import math

from randmedia.describe.jamming import analyse


def certified_gap_tolerance(positions, box, diameter: float = 1.0, *,
                            gap_tolerance: float = 1e-9, max_tolerance: float = 1e-4,
                            first_rung: int = 0, **analyse_options) -> float:
    """The smallest ``gap_tolerance x 10^m <= max_tolerance`` at which
    :func:`~randmedia.describe.jamming.analyse` reports the packing strictly jammed
    (module docstring), NaN if none; ``analyse_options`` (rank, force and motion
    tolerances) are passed on unchanged. ``first_rung``: the first m tried (1 when the
    caller already knows the test fails at ``gap_tolerance``, e.g. from the packing's
    stored ``jammed`` attribute).

    Parameters
    ----------
    positions : array_like, shape (n, d)
        Sphere centres, in the units of ``box``.
    box : array_like, shape (d, d)
        Periodic cell; columns are the lattice vectors.
    diameter : float, optional
        Sphere diameter D.
    gap_tolerance : float, optional
        First rung of the ladder, fraction of D (> 0).
    max_tolerance : float, optional
        Largest tolerance tried, fraction of D (< 0.1).
    first_rung : int, optional
        First exponent m tried.
    **analyse_options
        Further keyword arguments of :func:`~randmedia.describe.jamming.analyse`.

    Returns
    -------
    float
        The certified gap tolerance (fraction of D), NaN if none up to ``max_tolerance``.
    """
    if not 0 < gap_tolerance <= max_tolerance < 0.1:
        raise ValueError(f"need 0 < gap_tolerance ({gap_tolerance}) <= max_tolerance "
                         f"({max_tolerance}) < 0.1 D")
    steps = int(math.floor(math.log10(max_tolerance / gap_tolerance) + 1e-9))
    for m in range(first_rung, steps + 1):
        tolerance = gap_tolerance * 10.0 ** m
        if analyse(positions, box, diameter, gap_tolerance=tolerance, **analyse_options).jammed:
            return tolerance
    return math.nan
