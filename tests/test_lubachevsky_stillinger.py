"""Event-driven compression of growing hard spheres (randmedia.generate.lubachevsky_stillinger).

Known answers: the collision time of two spheres in closed form; energy conservation
of elastic collisions at fixed diameter; the equation of state of equilibrium hard
spheres (Carnahan-Starling, 3D) and hard disks (Henderson-type EOS of
randmedia.theory.hard_spheres, 2D) from the collision virial at fixed diameter; no
overlap ever; the same seed gives the same packing.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from randmedia.generate import lubachevsky_stillinger as ls
from randmedia.generate.rsa import random_sequential_addition
from randmedia.periodic import Cell, pairs_within
from randmedia.theory.hard_spheres import compressibility_factor


def min_distance(positions, box, cutoff=1.2):
    _, _, _, distance = pairs_within(Cell(box), positions, cutoff)
    return distance.min()


@pytest.mark.parametrize("growth", [0.0, 0.3])
def test_collision_time_solves_the_contact_equation(growth):
    rng = np.random.default_rng(4)
    for _ in range(200):
        r = rng.normal(size=3) * 2
        v = rng.normal(size=3)
        sigma = 0.5
        if r @ r <= sigma**2:
            continue
        t = ls._collision_time(r @ r, r @ v, v @ v, sigma, growth)
        if np.isfinite(t):
            assert t >= 0
            assert np.linalg.norm(r + v * t) == pytest.approx(sigma + growth * t, rel=1e-9)
            # no earlier contact: the distance minus the diameter is positive before t
            for s in np.linspace(0, t, 20)[:-1]:
                assert np.linalg.norm(r + v * s) > sigma + growth * s - 1e-12
        else:
            assert v @ v > growth**2  # slower relative motion than growth always meets
            times = np.linspace(0, 50, 2001)
            gaps = np.linalg.norm(r[None] + v[None] * times[:, None], axis=1) - sigma - growth * times
            assert gaps.min() > 0


def test_elastic_collisions_conserve_energy_at_fixed_diameter():
    positions, box = random_sequential_addition(np.random.default_rng(1), 200, 0.3)
    side = 200 ** (1 / 3)
    scale = side / box[0, 0]
    system = ls.GrowingSpheres(np.random.default_rng(2), 200, 3, growth_rate=0.0,
                               positions=positions * scale, sigma0=scale)
    for _ in range(3):
        system.run(20 * 200)
        assert system.kinetic_before_rescale == pytest.approx(3 * 200, rel=1e-10)
        assert system.collisions > 0
    assert system.min_distance() >= system.sigma * (1 - 1e-10)


@pytest.mark.parametrize("dim, phi, n", [(3, 0.35, 500), (2, 0.5, 400)])
def test_fixed_diameter_pressure_matches_the_equation_of_state(dim, phi, n):
    """Z from the collision virial over many intervals against the EOS (CS in 3D); the
    tolerance is 3 standard errors of the interval means plus 1 % for the EOS."""
    system = ls.GrowingSpheres(np.random.default_rng(4), n, dim, growth_rate=0.2)
    while system.phi < phi:  # grow from the Poisson start, then freeze the diameter
        system.run(n // 10)
    system.set_growth(0.0)
    assert system.phi == pytest.approx(phi, abs=0.005)
    for _ in range(20):  # equilibrate
        system.run(20 * n)
    pressures = np.array([system.run(20 * n) for _ in range(60)])
    expected = float(compressibility_factor(system.phi, dim))
    sem = pressures.std(ddof=1) / math.sqrt(len(pressures))
    assert abs(pressures.mean() - expected) < 3 * sem + 0.01 * expected, (pressures.mean(), expected, sem)


@pytest.mark.parametrize("dim", [2, 3])
def test_compression_reaches_the_target_pressure_without_overlaps(dim):
    params = ls.LSParameters(growth_rate=0.1, slowdown_pressure=50, target_pressure=1e3)
    positions, box, info = ls.compress(np.random.default_rng(7), 300, dim, params)
    assert info["pressure"] >= 1e3
    assert positions.shape == (300, dim)
    assert min_distance(positions, box) >= 1 - 1e-9
    phi = 300 * (math.pi / 6 if dim == 3 else math.pi / 4) / np.linalg.det(box)
    assert phi == pytest.approx(info["phi"], rel=1e-12)
    assert (0.60 < phi < 0.66) if dim == 3 else (0.78 < phi < 0.91)
    again, _, _ = ls.compress(np.random.default_rng(7), 300, dim, params)
    np.testing.assert_array_equal(positions, again)


def test_faster_growth_jams_looser():
    """The protocol sets the density (module docstring): one seed, three growth rates."""
    phis = []
    for growth in (1.0, 0.1, 0.01):
        params = ls.LSParameters(growth_rate=growth, slowdown_pressure=100, target_pressure=1e3)
        phis.append(ls.compress(np.random.default_rng(11), 500, 3, params)[2]["phi"])
    assert phis[0] < phis[1] < phis[2], phis


@pytest.mark.parametrize("kwargs, message", [
    (dict(growth_rate=0.0), "growth_rate"),
    (dict(target_pressure=1.0), "target_pressure"),
    (dict(slowdown_pressure=0.5), "slowdown_pressure"),
])
def test_bad_parameters_are_refused(kwargs, message):
    with pytest.raises(ValueError, match=message):
        ls.LSParameters(**kwargs)


def test_too_few_spheres_for_the_cell_list_are_refused():
    with pytest.raises(ValueError, match="too few"):
        ls.GrowingSpheres(np.random.default_rng(0), 20, 3)


def test_unreachable_target_fails_clearly():
    params = ls.LSParameters(growth_rate=0.1, slowdown_pressure=10, target_pressure=1e12,
                             max_events_per_sphere=200)
    with pytest.raises(ls.CompressionError, match="target Z"):
        ls.compress(np.random.default_rng(0), 100, 3, params)
