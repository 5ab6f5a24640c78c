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
import time

import numpy as np

from randmedia.describe.jamming import analyse


#: columns of :func:`gap_ladder`'s rows (the certificate file of a packing)
LADDER_COLUMNS = ("gap_tolerance", "n_pairs", "n_backbone", "isostatic_excess", "min_trace",
                  "min_force_ratio", "rank_ratio", "jammed", "cpu_seconds")


def _ladder_tolerances(gap_tolerance: float, max_tolerance: float, first_rung: int) -> list[float]:
    """``gap_tolerance x 10^m`` for m = ``first_rung`` ... while <= ``max_tolerance``, each
    rounded to 12 significant digits (1e-9 x 10^2 is 1e-07, not 1.0000000000000001e-07)."""
    if not 0 < gap_tolerance <= max_tolerance < 0.1:
        raise ValueError(f"need 0 < gap_tolerance ({gap_tolerance}) <= max_tolerance "
                         f"({max_tolerance}) < 0.1 D")
    steps = int(math.floor(math.log10(max_tolerance / gap_tolerance) + 1e-9))
    return [float(f"{gap_tolerance * 10.0 ** m:.12g}") for m in range(first_rung, steps + 1)]


def gap_ladder(positions, box, diameter: float = 1.0, *, gap_tolerance: float = 1e-9,
               max_tolerance: float = 1e-4, first_rung: int = 0, **analyse_options) -> list[dict]:
    """The strict-jamming test on each rung ``gap_tolerance x 10^m <= max_tolerance``
    (m = ``first_rung``, ...), up to the first rung where it passes (module docstring).

    Parameters are those of :func:`certified_gap_tolerance`.

    Returns
    -------
    list of dict
        One row per rung tried, with :data:`LADDER_COLUMNS`: the tolerance (fraction of D);
        the pairs closer than it; the backbone spheres (non-rattlers, 0 when fewer than 2) and
        their isostatic excess M - [d (N_b - 1) + d (d + 1) / 2] (None without a backbone);
        min Tr epsilon over the cone, the smallest backbone force over the mean and
        lambda_min / lambda_max of B^T B (None without a backbone); whether the test passed;
        the CPU seconds of the rung. Only the last row can have ``jammed`` True.
    """
    positions = np.asarray(positions, dtype=float)
    rows = []
    for tolerance in _ladder_tolerances(gap_tolerance, max_tolerance, first_rung):
        tic = time.process_time()
        analysis = analyse(positions, box, diameter, gap_tolerance=tolerance, **analyse_options)
        has_backbone = analysis.n_backbone >= 2
        forces = analysis.forces[analysis.backbone_contacts]
        rows.append({
            "gap_tolerance": tolerance, "n_pairs": len(analysis.network.i),
            "n_backbone": analysis.n_backbone if has_backbone else 0,
            "isostatic_excess": analysis.isostatic_excess if has_backbone else None,
            "min_trace": analysis.min_trace if has_backbone else None,
            "min_force_ratio": float(forces.min() / forces.mean()) if has_backbone and forces.size else None,
            "rank_ratio": analysis.rank_ratio if has_backbone else None,
            "jammed": bool(analysis.jammed), "cpu_seconds": time.process_time() - tic})
        if analysis.jammed:
            break
    return rows


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
    return certified_from_ladder(gap_ladder(positions, box, diameter, gap_tolerance=gap_tolerance,
                                            max_tolerance=max_tolerance, first_rung=first_rung,
                                            **analyse_options))


def certified_from_ladder(rows) -> float:
    """The tolerance of the rung where the test passed (:func:`gap_ladder`'s rows, or a
    certificate file's), NaN if none did."""
    passed = [float(row["gap_tolerance"]) for row in rows if bool(row["jammed"])]
    return min(passed) if passed else math.nan
