"""Argument checks shared by the closed forms (:mod:`randmedia.theory`) and the generators:
one wording per kind of bad value, naming the argument and what was expected."""

from __future__ import annotations

__all__ = ["check_dim", "check_fraction", "check_positive"]


def check_dim(dim: int, allowed: tuple[int, ...] = (2, 3)) -> None:
    """Raise ValueError unless the dimension ``dim`` is one of ``allowed`` (default 2 or 3).

    Parameters
    ----------
    dim : int
        Dimension d.
    allowed : tuple of int, optional
        The dimensions the caller handles.
    """
    if dim not in allowed:
        raise ValueError(f"dimension must be {' or '.join(str(d) for d in allowed)}, got {dim!r}")


def check_fraction(value: float, name: str = "phi2") -> None:
    """Raise ValueError unless 0 < ``value`` < 1 (a volume or packing fraction).

    Parameters
    ----------
    value : float
        The fraction.
    name : str, optional
        Its name in the message (default ``phi2``).
    """
    if not 0.0 < value < 1.0:
        raise ValueError(f"{name} must lie in (0, 1), got {value}")


def check_positive(value: float, name: str) -> None:
    """Raise ValueError unless ``value`` > 0 (a length, a density; NaN is refused too).

    Parameters
    ----------
    value : float
        The value.
    name : str
        Its name in the message.
    """
    if not value > 0:
        raise ValueError(f"{name} must be > 0, got {value}")
