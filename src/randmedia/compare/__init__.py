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

Notes. A row of :func:`compare` also keeps its error budget (``published_err``,
``rounding`` -- half a unit of the published value's last digit, a part of the
systematic margin -- and the rest of ``systematic``) and the reason the caller
identified should the row fail (``reason_if_failed``, written beside the row
builder and attached to the kind of row, not to one run's outcome). From those,
:func:`notes_frame` builds ``comparison_notes.csv`` (columns :data:`NOTE_COLUMNS`):
the budget, ``deviation_in_tolerances`` (the judged deviation over the tolerance,
so a row passes exactly when it is <= 1; NaN for a zero tolerance or a missing
value) and, for failing rows only, the reason ("not identified" if none was
given). Rows compared elsewhere (the columns of :data:`COLUMNS` only) get their
budget from :func:`checked_row`.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Iterable, Mapping

import pandas as pd

COLUMNS = ("quantity", "key", "published", "ours", "ours_sem", "tolerance", "passed")

#: columns of comparison_notes.csv, one row per comparison row (module docstring)
NOTE_COLUMNS = ("quantity", "key", "published_err", "rounding", "systematic",
                "deviation_in_tolerances", "reason")

#: the budget a row of :func:`compare` keeps beside :data:`COLUMNS`
BUDGET = ("published_err", "rounding", "systematic", "reason_if_failed")

#: reason of a failing row whose builder names none
NOT_IDENTIFIED = "not identified"

#: appended to the key of an upper-bound row (module docstring)
UPPER_BOUND_NOTE = " (upper bound: passed if ours <= published)"


def tolerance(ours_sem: float, *, k_sigma: float, published_err: float = 0.0,
              systematic: float = 0.0) -> float:
    """k_sigma x combined statistical error + systematic margin.

    Parameters
    ----------
    ours_sem : float
        Our standard error of the mean over samples.
    k_sigma : float
        Multiple of the combined statistical error; must be > 0.
    published_err : float, optional
        Error the paper quotes (0: none quoted, or an exact result); must be >= 0.
    systematic : float, optional
        Systematic margin added as it is; must be >= 0.

    Returns
    -------
    float
        ``k_sigma * sqrt(ours_sem^2 + published_err^2) + systematic``.
    """
    if k_sigma <= 0:
        raise ValueError(f"k_sigma must be > 0, got {k_sigma}")
    if systematic < 0 or published_err < 0:
        raise ValueError("published_err and systematic must be >= 0")
    return k_sigma * math.hypot(ours_sem, published_err) + systematic


def compare(quantity: str, key: str, published: float, ours: float, ours_sem: float, *,
            k_sigma: float, published_err: float = 0.0, rounding: float = 0.0,
            systematic: float = 0.0, upper_bound: bool = False, exact: bool = False,
            reason_if_failed: str = "") -> dict:
    """One comparison row: a dict with the keys of :data:`COLUMNS` and of :data:`BUDGET`
    (module docstring). The tolerance's margin is ``rounding + systematic``;
    ``upper_bound``: the published value bounds ours from above; ``exact``: the row passes
    only if ours equals the published value (e.g. an infinity), with tolerance 0.

    Parameters
    ----------
    quantity, key : str
        Name of the compared quantity and of the row within it (e.g. ``"r/R=0.5000"``);
        ``upper_bound`` appends :data:`UPPER_BOUND_NOTE` to the key.
    published : float
        Published (or exact) value.
    ours : float
        Our value; NaN (not computed) never passes.
    ours_sem : float
        Our standard error of the mean.
    k_sigma : float
        Multiple of the combined statistical error in the tolerance.
    published_err : float, optional
        Error the paper quotes (0 if none).
    rounding : float, optional
        Half a unit of the published value's last digit; part of the systematic margin.
    systematic : float, optional
        The rest of the systematic margin, stated by the caller.
    upper_bound : bool, optional
        Pass if ``ours - published <= tolerance`` (published value is a quality bound).
    exact : bool, optional
        Pass only if ``ours == published``; the tolerance is then 0.
    reason_if_failed : str, optional
        Reason identified should the row fail ("" for none), for comparison_notes.csv.

    Returns
    -------
    dict
        The row: keys of :data:`COLUMNS` then of :data:`BUDGET`.
    """
    tol = tolerance(ours_sem, k_sigma=k_sigma, published_err=published_err,
                    systematic=rounding + systematic)
    if exact:
        tol, passed = 0.0, bool(ours == published)
    else:
        deviation = ours - published if upper_bound else abs(ours - published)
        passed = bool(deviation <= tol)  # False for NaN
    return {
        "quantity": quantity,
        "key": key + UPPER_BOUND_NOTE if upper_bound else key,
        "published": float(published),
        "ours": float(ours),
        "ours_sem": float(ours_sem),
        "tolerance": float(tol),
        "passed": passed,
        "published_err": published_err,
        "rounding": rounding,
        "systematic": systematic,
        "reason_if_failed": reason_if_failed,
    }


def checked_row(row: Mapping, *, k_sigma: float, reason_if_failed: str = "") -> dict:
    """A row compared elsewhere (the columns of :data:`COLUMNS`, e.g. a generator's
    validation csv), kept as it is, with the budget :func:`notes_frame` needs: no published
    error or rounding, and as systematic margin the part of the tolerance beyond
    k_sigma x SEM.

    Parameters
    ----------
    row : Mapping
        A row with (at least) the keys of :data:`COLUMNS`; a non-finite ``ours_sem`` counts as 0.
    k_sigma : float
        The k_sigma the row's tolerance was built with.
    reason_if_failed : str, optional
        Reason identified should the row fail ("" for none).

    Returns
    -------
    dict
        The :data:`COLUMNS` of ``row`` plus the keys of :data:`BUDGET`.
    """
    sem = float(row["ours_sem"]) if math.isfinite(row["ours_sem"]) else 0.0
    return {**{column: row[column] for column in COLUMNS}, "published_err": 0.0, "rounding": 0.0,
            "systematic": max(0.0, float(row["tolerance"]) - k_sigma * sem),
            "reason_if_failed": reason_if_failed}


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


def notes_frame(rows: Iterable[Mapping]) -> pd.DataFrame:
    """The notes of comparison rows (those of :func:`compare` or :func:`checked_row`, in
    the order of the comparison table): exactly the columns of :data:`NOTE_COLUMNS`, one row
    per comparison row (module docstring)."""
    notes = []
    for row in rows:
        missing = [name for name in BUDGET if name not in row]
        if missing:
            raise ValueError(f"comparison row {row['quantity']!r} [{row['key']}] lacks its budget "
                             f"{missing} (build it with compare() or checked_row())")
        tol = float(row["tolerance"])
        deviation = row["ours"] - row["published"]
        if not str(row["key"]).endswith(UPPER_BOUND_NOTE):
            deviation = abs(deviation)
        passed = bool(row["passed"])
        notes.append({
            "quantity": row["quantity"], "key": row["key"],
            "published_err": row["published_err"], "rounding": row["rounding"],
            "systematic": row["systematic"],
            "deviation_in_tolerances": (deviation / tol if tol > 0 and math.isfinite(deviation)
                                        else math.nan),
            "reason": "" if passed else (row["reason_if_failed"] or NOT_IDENTIFIED),
        })
    return pd.DataFrame(notes, columns=list(NOTE_COLUMNS))


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
