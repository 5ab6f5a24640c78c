"""The periodic cell-list layer (randmedia.cell_list) against brute force: neighbour cells,
member tables, overlap test, image-cell walks, in 2D and 3D boxes down to 1-3 cells per side
(where periodic images of cells coincide)."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from randmedia import cell_list as cl
from randmedia.generate.hard_particles.kernels import _overlaps
from randmedia.periodic import Cell, min_pair_distance


def brute_min_image(d, lengths):
    return d - lengths * np.rint(d / lengths)


def table_for(pos3, lengths3, dim, cutoff):
    ncell = np.ones(3, dtype=np.int64)
    for k in range(dim):
        ncell[k] = max(1, int(math.floor(lengths3[k] / cutoff)))
    table = cl.MemberTable(ncell, len(pos3), cl.CELL_CAPACITY[dim])
    assert cl.build_members(pos3, lengths3, table.ncell, table.members, table.count, table.cell_of,
                            table.slot_of)
    return table


def random_setup(rng, dim, cells_per_side, n):
    """Box with the given cells per side for cutoff 1 (third axis a dummy 1 in 2D)."""
    lengths = cells_per_side + rng.random(dim) * 0.9  # floor(L / 1) = cells per side
    lengths3 = np.ones(3)
    lengths3[:dim] = lengths
    pos3 = np.zeros((n, 3))
    pos3[:, :dim] = rng.random((n, dim)) * lengths
    return lengths, lengths3, pos3


@pytest.mark.parametrize("dim", [2, 3])
@pytest.mark.parametrize("n_side", [1, 2, 3, 4])
def test_neighbour_cells_are_the_distinct_periodic_neighbours(dim, n_side):
    ncell = np.array([n_side, n_side, n_side + 1] if dim == 3 else [n_side, n_side, 1],
                     dtype=np.int64)
    out = np.empty(27, dtype=np.int64)
    for c in range(int(np.prod(ncell))):
        c0, c1, c2 = cl.cell_triple(c, ncell)
        assert cl.flat_index(c0, c1, c2, ncell) == c
        expected = {cl.flat_index((c0 + a) % ncell[0], (c1 + b) % ncell[1], (c2 + e) % ncell[2], ncell)
                    for a, b, e in itertools.product((-1, 0, 1), repeat=3)}
        n = cl.neighbour_cells(c, ncell, out)
        found = list(out[:n])
        assert len(found) == len(set(found))  # coinciding images listed once
        assert set(found) == expected
        assert n == np.prod(np.minimum(ncell, 3))


def test_cell_index_clips_the_upper_face_and_minimum_image_is_nearest():
    ncell = np.array([3, 4, 1], dtype=np.int64)
    box = np.array([3.0, 4.0, 1.0])
    assert cl.cell_coordinate(1.0, 3) == 2
    assert cl.cell_index(np.nextafter(3.0, 0), 0.0, 0.0, box, ncell) == cl.flat_index(2, 0, 0, ncell)
    assert cl.cell_index(1.5, 3.999, 0.0, box, ncell) == cl.flat_index(1, 3, 0, ncell)
    rng = np.random.default_rng(0)
    for d in rng.uniform(-2.99, 2.99, 200):
        m = cl.minimum_image(d, 3.0)
        assert abs(m) <= 1.5 and math.isclose((m - d) / 3.0, round((m - d) / 3.0), abs_tol=1e-12)
    for a in range(-7, 8):
        shift, wrapped = cl.periodic_cell(a, 3)
        assert 0 <= wrapped < 3 and shift * 3 + wrapped == a


@pytest.mark.parametrize("dim", [2, 3])
@pytest.mark.parametrize("cells_per_side", [1, 2, 3, 5])
def test_pairs_through_the_member_table_equal_brute_force(dim, cells_per_side):
    """Every pair whose nearest image is closer than the cutoff 1 is found exactly once in the
    3^d neighbour cells (one cell per side: a box shorter than 2 cutoffs), and the
    hard-particle overlap test on the member table agrees with brute force at random points."""
    rng = np.random.default_rng(10 * dim + cells_per_side)
    lengths, lengths3, pos3 = random_setup(rng, dim, cells_per_side, 40)
    cutoff = 1.0
    table = table_for(pos3, lengths3, dim, cutoff)
    assert np.all(table.ncell[:dim] == cells_per_side)
    scratch = np.empty(27, dtype=np.int64)
    found = []
    for i in range(len(pos3)):
        c = cl.cell_index(pos3[i, 0], pos3[i, 1], pos3[i, 2], lengths3, table.ncell)
        assert c == table.cell_of[i]
        n = cl.neighbour_cells(c, table.ncell, scratch)
        for cell in scratch[:n]:
            for j in table.members[cell, : table.count[cell]]:
                d = brute_min_image(pos3[j, :dim] - pos3[i, :dim], lengths)
                if j > i and d @ d < cutoff**2:
                    found.append((i, int(j)))
    d = pos3[None, :, :dim] - pos3[:, None, :dim]
    r2 = np.sum(brute_min_image(d, lengths) ** 2, axis=-1)
    expected = [(i, j) for i, j in zip(*np.nonzero(np.triu(r2 < cutoff**2, 1)))]
    assert sorted(found) == sorted(expected)
    # overlap test at random points (and skipping a particle)
    for _ in range(200):
        q = np.zeros(3)
        q[:dim] = rng.random(dim) * lengths
        skip = int(rng.integers(-1, len(pos3)))
        got = _overlaps(skip, q[0], q[1], q[2], pos3, lengths3, table.ncell, table.members,
                        table.count, cutoff**2, scratch)
        dq = np.sum(brute_min_image(pos3[:, :dim] - q[:dim], lengths) ** 2, axis=1)
        if skip >= 0:
            dq[skip] = np.inf
        assert got == bool(np.any(dq < cutoff**2))


def test_insert_and_remove_keep_the_member_table_consistent():
    rng = np.random.default_rng(3)
    ncell = np.array([3, 3, 2], dtype=np.int64)
    n = 30
    table = cl.MemberTable(ncell, n, 64)
    inside = {}
    for step in range(500):
        i = int(rng.integers(n))
        if i in inside:
            cl.remove(i, table.members, table.count, table.cell_of, table.slot_of)
            del inside[i]
        else:
            c = int(rng.integers(18))
            assert cl.insert(i, c, table.members, table.count, table.cell_of, table.slot_of)
            inside[i] = c
        for c in range(18):
            members = set(table.members[c, : table.count[c]].tolist())
            assert members == {k for k, v in inside.items() if v == c}
        for k, c in inside.items():
            assert table.members[table.cell_of[k], table.slot_of[k]] == k
    full = cl.MemberTable(np.array([2, 1, 1]), 5, 2)
    assert cl.insert(0, 0, full.members, full.count, full.cell_of, full.slot_of)
    assert cl.insert(1, 0, full.members, full.count, full.cell_of, full.slot_of)
    assert not cl.insert(2, 0, full.members, full.count, full.cell_of, full.slot_of)
    assert full.count[0] == 2


@pytest.mark.parametrize("box", [
    np.diag([2.0, 2.5, 3.0]),                                         # 1 cell per side
    np.array([[2.0, 0.9, 0.3], [0.0, 2.2, 0.5], [0.0, 0.0, 1.8]]),    # small triclinic
    np.array([[5.0, 1.0, 0.5], [0.0, 4.5, -0.8], [0.0, 0.0, 4.0]]),   # 2-3 cells per side
])
def test_image_cell_walk_finds_every_periodic_image_once(box):
    """Sorted cells + periodic_cell / image_cell: all images of all points within r of a query,
    r up to 1.5 box widths (several images of the same point), equal to brute force."""
    rng = np.random.default_rng(7)
    cell = Cell(box)
    x = rng.random((25, 3)) @ box.T
    cells = cl.SortedCells(x, box, target_per_cell=3.0)
    assert np.all(cells.n_cells <= 3)
    r = 1.5 * cell.face_distances.max()
    images = np.array(list(itertools.product(range(-4, 5), repeat=3)), dtype=float) @ box.T
    for q in cells.query_fractional(rng.random((6, 3)) @ box.T):
        qc = box @ q
        c = [cl.cell_coordinate(q[k], cells.n_cells[k]) for k in range(3)]
        e = [int(math.ceil(r / cells.cell_width[k])) + 1 for k in range(3)]
        found = []
        for d in itertools.product(*(range(-ek, ek + 1) for ek in e)):
            (s0, w0), (s1, w1), (s2, w2) = (cl.periodic_cell(c[k] + d[k], cells.n_cells[k])
                                            for k in range(3))
            flat, *sh = cl.image_cell(cells.box, s0, s1, s2, w0, w1, w2, cells.n_cells, qc)
            disp = cells.cart[cells.start[flat]:cells.start[flat + 1]] + np.array(sh)
            found.extend(np.linalg.norm(disp, axis=1)[np.linalg.norm(disp, axis=1) < r])
        wrapped = cell.wrap(x)
        all_d = np.linalg.norm(wrapped[:, None, :] + images[None, :, :] - qc, axis=-1).ravel()
        np.testing.assert_allclose(np.sort(found), np.sort(all_d[all_d < r]), rtol=0, atol=1e-12)


def test_min_pair_distance_equals_brute_force():
    rng = np.random.default_rng(5)
    box = np.diag([6.0, 7.0, 5.0])
    x = rng.random((50, 3)) @ box.T
    d = x[None] - x[:, None]
    r = np.sqrt(np.sum(brute_min_image(d, np.diag(box)) ** 2, axis=-1))
    r[np.diag_indices(50)] = np.inf
    assert min_pair_distance(Cell(box), x, 2.4) == pytest.approx(r.min(), abs=1e-12)
    assert min_pair_distance(Cell(box), x, 1e-6) == np.inf
