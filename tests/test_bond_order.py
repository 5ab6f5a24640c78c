"""Steinhardt bond order (randmedia.describe.bond_order) on lattices and random points."""

from __future__ import annotations

import numpy as np
import pytest

from randmedia.describe.bond_order import (crystal_like, crystalline_fraction, cubic_lattice,
                                           global_q6, global_ql, local_q6, spherical_harmonics)
from randmedia.periodic import Cell, pairs_within


@pytest.mark.parametrize("kind, cells, q6", [("fcc", 4, 0.574524), ("bcc", 5, 0.510688),
                                             ("sc", 6, 0.353553)])
def test_lattices_have_the_known_q6(kind, cells, q6):
    positions, box = cubic_lattice(kind, cells)
    assert global_q6(positions, box) == pytest.approx(q6, abs=1e-6)
    np.testing.assert_allclose(local_q6(positions, box), q6, atol=1e-6)


def test_q4_of_fcc_and_bcc():
    for kind, q4 in (("fcc", 0.190941), ("bcc", 0.036370)):
        positions, box = cubic_lattice(kind, 4)
        assert global_ql(positions, box, l=4) == pytest.approx(q4, abs=1e-5)


def test_triclinic_cell_and_rotation_invariance():
    """fcc in its primitive (triclinic) cell, and rotated with its cell: Q6 unchanged."""
    primitive = np.array([[0, .5, .5], [.5, 0, .5], [.5, .5, 0]]).T * np.sqrt(2.0)
    n = 6
    grid = np.stack(np.meshgrid(*[np.arange(n)] * 3, indexing="ij"), -1).reshape(-1, 3)
    positions, box = grid @ primitive.T, primitive * n
    assert global_q6(positions, box) == pytest.approx(0.574524, abs=1e-6)
    angle = 0.7
    rotation = np.array([[np.cos(angle), -np.sin(angle), 0], [np.sin(angle), np.cos(angle), 0],
                         [0, 0, 1]]) @ np.array([[1, 0, 0], [0, np.cos(0.3), -np.sin(0.3)],
                                                 [0, np.sin(0.3), np.cos(0.3)]])
    assert global_q6(positions @ rotation.T, rotation @ box) == pytest.approx(0.574524, abs=1e-6)
    assert crystalline_fraction(positions @ rotation.T, rotation @ box) == 1.0


def test_random_points_q6_scales_as_inverse_root_of_bond_count():
    """Uncorrelated bonds: E[Q6^2] = 1 / N_b (module docstring)."""
    rng = np.random.default_rng(5)
    n, density = 1500, 0.9
    side = (n / density) ** (1 / 3)
    box = np.eye(3) * side
    q2, bonds, fractions = [], [], []
    for _ in range(30):
        points = rng.random((n, 3)) * side
        q2.append(global_q6(points, box) ** 2)
        bonds.append(len(pairs_within(Cell(box), points, 1.4)[0]))
        fractions.append(crystalline_fraction(points, box))
    # the mean of 30 draws of a chi^2_13 / 13 variable has relative SEM sqrt(2/13/30) = 7 %
    assert np.mean(q2) * np.mean(bonds) == pytest.approx(1.0, abs=0.25)
    assert max(fractions) < 0.01


def test_perturbed_crystal_is_still_crystal_like_and_melting_is_detected():
    rng = np.random.default_rng(1)
    positions, box = cubic_lattice("fcc", 5)
    shaken = positions + rng.normal(scale=0.05, size=positions.shape)
    assert crystalline_fraction(shaken, box) > 0.95
    assert global_q6(shaken, box) > 0.3  # thermal noise lowers Q6 (0.37 here), far above ~0.02
    gas = rng.random(positions.shape) * box[0, 0]
    assert crystalline_fraction(gas, box) < 0.01


def test_spherical_harmonics_are_orthonormal():
    rng = np.random.default_rng(2)
    vectors = rng.normal(size=(400000, 3))
    y = spherical_harmonics(6, vectors)
    np.testing.assert_allclose(4 * np.pi * np.mean(np.abs(y) ** 2, axis=0), 1.0, atol=0.02)
    assert abs(4 * np.pi * np.mean(y[:, 2] * np.conj(y[:, 3]))) < 0.02


def test_bad_input_rejected():
    positions, box = cubic_lattice("fcc", 2)
    with pytest.raises(ValueError, match="half"):
        global_q6(positions, box, cutoff=2.0)
    with pytest.raises(ValueError, match="3D"):
        global_q6(positions[:, :2], np.eye(2) * 3)
    with pytest.raises(ValueError, match="diameter"):
        global_q6(positions, box, diameter=0)
    with pytest.raises(ValueError, match="bond_threshold"):
        crystal_like(positions, box, bond_threshold=2)
    with pytest.raises(ValueError, match="same position"):
        spherical_harmonics(6, np.zeros((1, 3)))
