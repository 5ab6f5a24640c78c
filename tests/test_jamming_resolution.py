"""The certified gap tolerance of a packing (randmedia.describe.jamming_resolution)."""

import math

import pytest

from randmedia.describe import bond_order
from randmedia.describe.jamming_resolution import certified_gap_tolerance


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
