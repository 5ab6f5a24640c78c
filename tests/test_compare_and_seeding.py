"""Comparison framework and per-sample seeding."""

import math

import numpy as np
import pytest

from conftest import REPO
from randmedia.compare import (COLUMNS, compare, comparison_frame, judged_deviation, read_reference,
                               tolerance)
from randmedia.seeding import sample_seed


def test_tolerance_combines_errors_and_systematic():
    assert tolerance(0.3, k_sigma=3, published_err=0.4, systematic=0.1) == pytest.approx(1.6)
    with pytest.raises(ValueError):
        tolerance(0.1, k_sigma=0)


def test_passed_is_exactly_deviation_within_tolerance():
    edge = compare("q", "k", 1.0, 1.5, 0.25, k_sigma=2.0)
    assert edge["tolerance"] == 0.5 and edge["passed"] is True
    beyond = compare("q", "k", 1.0, 1.5000001, 0.25, k_sigma=2.0)
    assert beyond["passed"] is False
    missing = compare("q", "k", 1.0, math.nan, 0.1, k_sigma=3.0)
    assert missing["passed"] is False


def test_upper_bound_rows_pass_below_the_published_value_only():
    below = compare("q", "k", 2e-4, 1e-6, 1e-7, k_sigma=3.0, upper_bound=True)
    assert below["passed"] is True
    edge = compare("q", "k", 1.0, 1.5, 0.25, k_sigma=2.0, upper_bound=True)
    assert edge["passed"] is True
    assert compare("q", "k", 1.0, 1.5000001, 0.25, k_sigma=2.0, upper_bound=True)["passed"] is False
    assert compare("q", "k", 1.0, math.nan, 0.1, k_sigma=3.0, upper_bound=True)["passed"] is False
    frame = comparison_frame([below, edge, compare("q", "k", 1.0, 0.2, 0.1, k_sigma=3.0)])
    np.testing.assert_allclose(judged_deviation(frame), [1e-6 - 2e-4, 0.5, 0.8])


def test_frame_has_contract_columns():
    frame = comparison_frame([compare("q", "k", 1.0, 1.1, 0.1, k_sigma=3.0)])
    assert tuple(frame.columns) == COLUMNS


def test_reference_tables_are_shipped_and_readable(tmp_path):
    for path in sorted((REPO / "config" / "reference").glob("*.csv")):
        assert len(read_reference(path, [])) > 0, path
    with pytest.raises(ValueError, match="missing columns"):
        read_reference(REPO / "config" / "reference" / "mrj2016_table3_mrj.csv", ["nope"])
    with pytest.raises(FileNotFoundError, match="does not exist"):
        read_reference(tmp_path / "x.csv", [])


def test_seeds_are_reproducible_distinct_and_fit_int64():
    seeds = {sample_seed(1, paper, system, k)
             for paper in ("debye2020", "mrj2016") for system in ("a", "b") for k in range(50)}
    assert len(seeds) == 200
    assert sample_seed(1, "debye2020", "a", 3) == sample_seed(1, "debye2020", "a", 3)
    assert all(0 <= s < 2**63 for s in seeds)
    assert np.random.default_rng(sample_seed(1, "p", "s", 0)).random() == \
        np.random.default_rng(sample_seed(1, "p", "s", 0)).random()
