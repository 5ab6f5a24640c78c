"""Periodic cells: wrapping, minimum images and pair search in orthogonal and triclinic cells."""

import itertools

import numpy as np
import pytest
from scipy.spatial import cKDTree

from randmedia.periodic import Cell, pairs_within

TRICLINIC = np.array([[6.0, 1.5, -0.8], [0.0, 5.5, 1.2], [0.0, 0.0, 6.2]])


def brute_force_pairs(cell, positions, cutoff):
    """All pairs with an image closer than cutoff, by scanning 9^d images."""
    shifts = np.array(list(itertools.product(range(-4, 5), repeat=cell.dim)), float) @ cell.box.T
    found = {}
    for i, j in itertools.combinations(range(len(positions)), 2):
        images = positions[j] + shifts - positions[i]
        close = np.linalg.norm(images, axis=1) < cutoff
        assert close.sum() <= 1
        if close.any():
            found[(i, j)] = images[close][0]
    return found


@pytest.mark.parametrize("box", [np.diag([5.0, 6.0, 7.0]), TRICLINIC,
                                 np.array([[4.0, 2.0], [0.0, 3.5]])], ids=["ortho", "tri3", "tri2"])
def test_pairs_within_equals_brute_force(box):
    cell = Cell(box)
    rng = np.random.default_rng(1)
    positions = cell.random_points(rng, 60) + 3.0 * rng.normal(size=(60, cell.dim))  # unwrapped
    cutoff = cell.half_width
    i, j, sep, dist = pairs_within(cell, positions, cutoff)
    expected = brute_force_pairs(cell, positions, cutoff)
    assert sorted(zip(i.tolist(), j.tolist())) == sorted(expected)
    for a, b, s in zip(i, j, sep):
        np.testing.assert_allclose(s, expected[(a, b)], atol=1e-9)
    np.testing.assert_allclose(dist, np.linalg.norm(sep, axis=1))


def test_pairs_within_matches_periodic_kdtree_in_orthogonal_box():
    sides = np.array([10.0, 12.0, 11.0])
    cell = Cell.orthogonal(sides)
    positions = cell.random_points(np.random.default_rng(2), 500)
    i, j, _, dist = pairs_within(cell, positions, 3.0)
    reference = cKDTree(positions, boxsize=sides).query_pairs(3.0, output_type="ndarray")
    assert sorted(map(tuple, reference.tolist())) == sorted(zip(i.tolist(), j.tolist()))


def test_minimum_image_is_shortest_in_triclinic_cell():
    cell = Cell(TRICLINIC)
    rng = np.random.default_rng(3)
    d = rng.normal(scale=8.0, size=(200, 3))
    best = cell.minimum_image(d)
    shifts = np.array(list(itertools.product(range(-7, 8), repeat=3)), float) @ cell.box.T
    brute = np.array([np.min(np.linalg.norm(x + shifts, axis=1)) for x in d])
    np.testing.assert_allclose(np.linalg.norm(best, axis=1), brute, atol=1e-12)
    # still an image of the original separation
    frac = cell.fractional(best - d)
    np.testing.assert_allclose(frac, np.rint(frac), atol=1e-9)


def test_cell_geometry_and_wrap():
    cell = Cell(TRICLINIC)
    assert cell.volume == pytest.approx(np.linalg.det(TRICLINIC))
    # inscribed-ball radius: the face distance is volume / area of the opposite face
    areas = [np.linalg.norm(np.cross(TRICLINIC[:, a], TRICLINIC[:, b]))
             for a, b in ((1, 2), (2, 0), (0, 1))]
    assert cell.half_width == pytest.approx(min(cell.volume / A for A in areas) / 2)
    wrapped = cell.wrap(np.random.default_rng(4).normal(scale=20, size=(100, 3)))
    f = cell.fractional(wrapped)
    assert np.all((f >= 0) & (f < 1))


@pytest.mark.parametrize("box, message", [
    (np.eye(4), "2x2 or 3x3"),
    (np.zeros((3, 3)), "linearly independent"),
    (np.diag([1.0, 1.0, -1.0]), "right-handed"),
])
def test_bad_cells_rejected(box, message):
    with pytest.raises(ValueError, match=message):
        Cell(box)


def test_cutoff_beyond_half_width_rejected():
    cell = Cell.cubic(4.0)
    with pytest.raises(ValueError, match="h_w"):
        pairs_within(cell, np.zeros((2, 3)), 2.5)
