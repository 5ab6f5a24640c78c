"""The certified gap tolerance of a packing (randmedia.describe.jamming_resolution)."""

import math

import pytest

from randmedia.describe import bond_order
from randmedia.describe.jamming_resolution import LADDER_COLUMNS, certified_from_ladder, certified_gap_tolerance, gap_ladder


def test_fcc_at_contact_is_certified_at_the_first_tolerance():
    assert certified_gap_tolerance(*bond_order.cubic_lattice("fcc", 2)) == 1e-9


def test_expanded_fcc_is_certified_once_its_gaps_count_as_contacts():
    """fcc expanded by 1 + 3e-8: every neighbour gap is 3e-8 D, so no contact exists below
    that tolerance and the lattice is strictly jammed from 1e-7 D on."""
    positions, box = bond_order.cubic_lattice("fcc", 2)
    factor = 1 + 3e-8
    assert certified_gap_tolerance(positions * factor, box * factor) == pytest.approx(1e-7)
    # the ladder may start above the configured tolerance when the caller knows it fails there
    assert certified_gap_tolerance(positions * factor, box * factor, first_rung=1) == pytest.approx(1e-7)
    assert certified_gap_tolerance(positions * factor, box * factor, first_rung=3) == pytest.approx(1e-6)


def test_simple_cubic_is_never_certified():
    """Simple cubic shears freely; its next neighbours (sqrt(2) D) lie beyond any tolerance."""
    assert math.isnan(certified_gap_tolerance(*bond_order.cubic_lattice("sc", 3)))


def test_bad_ladder_is_refused():
    with pytest.raises(ValueError, match="max_tolerance"):
        certified_gap_tolerance(*bond_order.cubic_lattice("fcc", 2), gap_tolerance=1e-3,
                                max_tolerance=1e-5)


def test_ladder_reports_each_rung_up_to_the_first_pass():
    """Expanded fcc (gaps 3e-8 D): no pair at 1e-9 and 1e-8 D, so no backbone there; at 1e-7 D
    every sphere has its 12 neighbours, M = 6 N contacts against the isostatic d (N - 1) + 6,
    forces all positive, and the test passes -- the ladder stops there."""
    positions, box = bond_order.cubic_lattice("fcc", 2)
    factor = 1 + 3e-8
    rows = gap_ladder(positions * factor, box * factor)
    assert [row["gap_tolerance"] for row in rows] == pytest.approx([1e-9, 1e-8, 1e-7])
    assert all(set(row) == set(LADDER_COLUMNS) for row in rows)
    for row in rows[:2]:
        assert row["n_pairs"] == 0 and row["n_backbone"] == 0 and not row["jammed"]
        assert row["isostatic_excess"] is None and row["min_trace"] is None
    last, n = rows[-1], len(positions)
    assert last["jammed"] and last["n_pairs"] == 6 * n and last["n_backbone"] == n
    assert last["isostatic_excess"] == 6 * n - (3 * (n - 1) + 6)
    assert last["min_trace"] > -1e-6 and last["min_force_ratio"] > 0 and last["rank_ratio"] > 1e-12
    assert certified_from_ladder(rows) == pytest.approx(1e-7)


def test_ladder_of_a_floppy_lattice_fails_every_rung():
    """Simple cubic has a backbone at every rung (its 6 contacts per sphere close at D) but
    shears freely: every rung up to 1e-4 D fails, none certifies."""
    rows = gap_ladder(*bond_order.cubic_lattice("sc", 3))
    # exactly the decimal rungs (as the certificate file prints them), not 1.0000000000000001e-07
    assert [row["gap_tolerance"] for row in rows] == [1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4]
    assert not any(row["jammed"] for row in rows)
    assert all(row["n_backbone"] == 27 and row["n_pairs"] == 81 for row in rows)
    assert math.isnan(certified_from_ladder(rows))
