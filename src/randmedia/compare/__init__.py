"""Our values against published (or exact) ones, with tolerances from statistics.

A comparison row has the columns of :data:`COLUMNS`. The tolerance is

    tolerance = k_sigma * sqrt(ours_sem^2 + published_err^2) + systematic,

with ``ours_sem`` our standard error of the mean over samples,
``published_err`` the error the paper quotes (0 when it quotes none, and for
exact results), and ``systematic`` a margin whose origin the caller states
(e.g. a bias bound computed from theory). ``passed`` is exactly
``|ours - published| <= tolerance``; a missing value (NaN) never passes. A
published value that is a quality bound rather than a measurement (e.g. "the
discrepancies are as small as 2 x 10^-4") is compared with ``upper_bound=True``:
``passed`` is then ``ours - published <= tolerance``, and the row's key says so.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Iterable, Mapping

import pandas as pd

COLUMNS = ("quantity", "key", "published", "ours", "ours_sem", "tolerance", "passed")

#: appended to the key of an upper-bound row (module docstring)
UPPER_BOUND_NOTE = " (upper bound: passed if ours <= published)"


def tolerance(ours_sem: float, *, k_sigma: float, published_err: float = 0.0,
              systematic: float = 0.0) -> float:
    """k_sigma x combined statistical error + systematic margin."""
    if k_sigma <= 0:
        raise ValueError(f"k_sigma must be > 0, got {k_sigma}")
    if systematic < 0 or published_err < 0:
        raise ValueError("published_err and systematic must be >= 0")
    return k_sigma * math.hypot(ours_sem, published_err) + systematic


def compare(quantity: str, key: str, published: float, ours: float, ours_sem: float, *,
            k_sigma: float, published_err: float = 0.0, systematic: float = 0.0,
            upper_bound: bool = False) -> dict:
    """One comparison row (a dict with the keys of :data:`COLUMNS`); ``upper_bound``: the
    published value bounds ours from above (module docstring)."""
    tol = tolerance(ours_sem, k_sigma=k_sigma, published_err=published_err, systematic=systematic)
    deviation = ours - published if upper_bound else abs(ours - published)
    return {
        "quantity": quantity,
        "key": key + UPPER_BOUND_NOTE if upper_bound else key,
        "published": float(published),
        "ours": float(ours),
        "ours_sem": float(ours_sem),
        "tolerance": float(tol),
        "passed": bool(deviation <= tol),  # False for NaN
    }


def judged_deviation(frame: pd.DataFrame) -> pd.Series:
    """The deviation ``passed`` was judged on, per row of a comparison table: ours -
    published for upper-bound rows (key ending in :data:`UPPER_BOUND_NOTE`), else |ours -
    published|; ``passed == (judged_deviation <= tolerance)`` holds for every row."""
    signed = frame["ours"] - frame["published"]
    return signed.where(frame["key"].str.endswith(UPPER_BOUND_NOTE), signed.abs())


def comparison_frame(rows: Iterable[Mapping]) -> pd.DataFrame:
    """Rows as a DataFrame with exactly the columns of :data:`COLUMNS`, in order."""
    frame = pd.DataFrame(list(rows), columns=list(COLUMNS))
    # ours / ours_sem may be NaN (not computed); the rest must be present
    missing = [c for c in COLUMNS if c not in ("ours", "ours_sem") and frame[c].isna().any()]
    if missing:
        raise ValueError(f"comparison rows lack values in columns {missing}")
    return frame


def read_reference(path: str | Path, required_columns: Iterable[str]) -> pd.DataFrame:
    """Read a published-values CSV from ``config/reference/``, checking its columns."""
    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(f"{path}: reference table does not exist")
    frame = pd.read_csv(path)
    missing = [c for c in required_columns if c not in frame.columns]
    if missing:
        raise ValueError(f"{path}: missing columns {missing} (has {list(frame.columns)})")
    return frame
