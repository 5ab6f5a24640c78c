"""Canonical Monte Carlo on the sphere (randmedia.generate.sphere_mc): potentials, energies,
the ideal gas, an exactly solvable N = 2 system, checkpoint/resume, bad parameters."""

from __future__ import annotations

import logging
import math

import numpy as np
import pytest
from scipy import integrate, stats

from randmedia.generate.sphere_mc import (MCSchedule, Potential, blocked_mean_and_error, delta_energy,
                                          dipole_pair_energy, integrated_autocorrelation_time,
                                          particle_number, run_fluid, total_energy)
from randmedia.generate.sphere_surface import uniform_points
from randmedia.theory.sphere_caps import cap_grid, cos_thresholds

THRESHOLDS = cos_thresholds(cap_grid(1.0, 8), 1.0)


def test_normal_dipoles_reduce_to_r3_plus_coulomb_tail():
    """Eq. (12a) with s = x/R on the sphere is exactly alpha/r^3 + alpha/(4 R^2 r)."""
    rng = np.random.default_rng(0)
    radius, alpha = 3.0, 1.7
    xi, xj = uniform_points(500, radius, rng), uniform_points(500, radius, rng)
    r = np.linalg.norm(xj - xi, axis=1)
    general = dipole_pair_energy(xi, xj, alpha)
    reduced = Potential("udd", alpha, epsilon=0.0).pair_energy(r, radius)
    np.testing.assert_allclose(general, reduced, rtol=1e-10)
    assert np.all(general > 0)  # radial dipoles repel at every separation


def test_second_reading_of_eq_12a_flips_one_factor_and_attracts_at_long_range():
    """udd_flipped: the vector form of Eq. (12a) with -r in one s.r factor equals
    alpha/r^3 - 5 alpha/(4 R^2 r), attractive beyond r = 2R/sqrt(5)."""
    rng = np.random.default_rng(7)
    radius, alpha = 3.0, 1.4
    xi, xj = uniform_points(500, radius, rng), uniform_points(500, radius, rng)
    si, sj = xi / radius, xj / radius
    rv = xj - xi
    r = np.linalg.norm(rv, axis=1)
    flipped = alpha / r**3 * (np.einsum("ij,ij->i", si, sj)
                              + 3.0 * np.einsum("ij,ij->i", si, rv) * np.einsum("ij,ij->i", sj, rv) / r**2)
    reduced = Potential("udd_flipped", alpha, epsilon=0.0).pair_energy(r, radius)
    np.testing.assert_allclose(reduced, flipped, rtol=1e-9)
    assert np.all((reduced < 0) == (r > 2 * radius / np.sqrt(5)))


def test_second_reading_of_eq_12b_cubes_the_coupling():
    """uddpar_cubed: epsilon (alpha d/r)^3 = alpha^3/r^3; alpha = 1 is the printed Eq. (12b)."""
    r = np.linspace(0.8, 4.0, 17)
    lj = Potential("lj", 0.0).pair_energy(r, 5.0)
    np.testing.assert_allclose(Potential("uddpar_cubed", 3.0).pair_energy(r, 5.0), lj + 27.0 / r**3, rtol=1e-14)
    np.testing.assert_allclose(Potential("uddpar_cubed", 1.0).pair_energy(r, 5.0),
                               Potential("uddpar", 1.0).pair_energy(r, 5.0), rtol=1e-14)


@pytest.mark.parametrize("name", ["lj", "udd", "udd_flipped", "uddpar", "uddpar_cubed", "udc", "ucc"])
def test_kernel_energies_match_the_numpy_pair_sum(name):
    rng = np.random.default_rng(1)
    radius = 2.5
    points = uniform_points(40, radius, rng)
    potential = Potential(name, 2.0)
    i, j = np.triu_indices(40, 1)
    r = np.linalg.norm(points[i] - points[j], axis=1)
    expected = potential.pair_energy(r, radius).sum()
    assert total_energy(points, potential, radius) == pytest.approx(expected, rel=1e-12)
    new = uniform_points(1, radius, rng)[0]
    moved = points.copy()
    moved[7] = new
    change = total_energy(moved, potential, radius) - total_energy(points, potential, radius)
    assert delta_energy(points, 7, new, potential, radius) == pytest.approx(change, rel=1e-9, abs=1e-9)


def test_ideal_gas_samples_the_uniform_distribution():
    """All couplings zero: every move is accepted and the positions are uniform on the sphere
    (checks the move proposal is symmetric: a biased one drifts the density)."""
    radius, n = 1.0, 20
    schedule = MCSchedule(equilibration_sweeps=200, production_sweeps=40000, frame_interval=40,
                          count_interval=1, tune_fraction=0.0, initial_step=0.4)
    run = run_fluid(Potential("lj", 0.0, epsilon=0.0), radius, n / (4 * math.pi), 1.0, schedule,
                    np.random.default_rng(2), THRESHOLDS)
    assert run.stats["acceptance_production"] == 1.0
    points = run.frames.reshape(-1, 3) / radius
    assert np.allclose(np.linalg.norm(points, axis=1), 1.0)
    for coordinate in points.T:  # each Cartesian coordinate of a uniform point is U(-1, 1)
        assert stats.kstest(coordinate, "uniform", args=(-1, 2)).pvalue > 1e-3
    longitude = np.arctan2(points[:, 1], points[:, 0])
    assert stats.kstest(longitude, "uniform", args=(-np.pi, 2 * np.pi)).pvalue > 1e-3


def _two_particle_mean_energy(potential, radius, temperature):
    """<U> of N = 2 on the sphere: with particle 1 fixed, dA = 2 pi r dr for the chord r."""
    def weight(r):
        return np.exp(-potential.pair_energy(r, radius) / temperature) * r

    lo = 0.05  # below: Boltzmann weight < 1e-300 for these potentials
    norm = integrate.quad(weight, lo, 2 * radius, limit=200)[0]
    first = integrate.quad(lambda r: potential.pair_energy(r, radius) * weight(r), lo, 2 * radius,
                           limit=200)[0]
    return first / norm


@pytest.mark.parametrize("potential, radius, temperature", [
    (Potential("lj", 1.0), 1.0, 1.0),
    (Potential("ucc", 2.0), 1.5, 0.8),
    (Potential("udd", 1.0), 1.2, 0.5),
])
def test_two_particles_reproduce_the_exact_mean_energy(potential, radius, temperature):
    exact = _two_particle_mean_energy(potential, radius, temperature)
    schedule = MCSchedule(equilibration_sweeps=2000, production_sweeps=200000, frame_interval=1000,
                          count_interval=1)
    run = run_fluid(potential, radius, 2 / (4 * math.pi * radius**2), temperature, schedule,
                    np.random.default_rng(3), THRESHOLDS)
    energies = run.energy[schedule.equilibration_sweeps:]
    mean, error = blocked_mean_and_error(energies, 50)
    assert abs(mean - exact) < 4 * error, (mean, error, exact)
    assert error < 0.02 * max(1.0, abs(exact))  # the test has power


def test_fluid_run_records_and_equilibrates():
    radius = 3.0
    schedule = MCSchedule(equilibration_sweeps=400, production_sweeps=2000, frame_interval=100,
                          count_interval=2)
    thresholds = cos_thresholds(cap_grid(radius, 10), radius)
    run = run_fluid(Potential("uddpar", 1.0), radius, 0.5, 5.2, schedule, np.random.default_rng(4),
                    thresholds)
    n = particle_number(radius, 0.5)
    assert run.frames.shape == (20, n, 3) and not np.isnan(run.frames).any()
    assert run.axis_counts.shape == (1000, 3, 10)
    assert np.all(run.axis_counts[:, :, -1] <= n) and np.all(np.diff(run.axis_counts, axis=2) >= 0)
    assert run.energy.shape == (2400,) and not np.isnan(run.energy).any()
    assert abs(run.stats["acceptance_production"] - 0.4) < 0.1
    assert run.stats["energy_drift_production"] < 1e-10
    final = total_energy(run.frames[-1], Potential("uddpar", 1.0), radius)
    assert run.energy[-1] == pytest.approx(final, rel=1e-9)
    assert 0.5 <= run.stats["tau_energy_sweeps"] < 50


def test_count_interval_samples_the_same_trajectory():
    radius = 2.0
    thresholds = cos_thresholds(cap_grid(radius, 6), radius)
    runs = [run_fluid(Potential("ucc", 1.0), radius, 0.5, 5.2,
                      MCSchedule(20, 60, 10, count_interval=k), np.random.default_rng(5), thresholds)
            for k in (1, 3)]
    np.testing.assert_array_equal(runs[0].axis_counts[2::3], runs[1].axis_counts)
    np.testing.assert_array_equal(runs[0].frames, runs[1].frames)


class _Abort(Exception):
    pass


class _KillAfter(logging.Logger):
    """A logger that aborts the run at its n-th progress message (a kill between chunks)."""

    def __init__(self, n):
        super().__init__("kill")
        self.left = n

    def info(self, *args, **kwargs):
        self.left -= 1
        if self.left == 0:
            raise _Abort


def test_killed_run_resumes_bit_identically(tmp_path):
    radius = 2.0
    thresholds = cos_thresholds(cap_grid(radius, 6), radius)
    schedule = MCSchedule(equilibration_sweeps=40, production_sweeps=200, frame_interval=10, count_interval=1)
    reference = run_fluid(Potential("udc", 1.0), radius, 0.5, 5.2, schedule, np.random.default_rng(6),
                          thresholds)
    checkpoint = tmp_path / "run.checkpoint.npz"
    with pytest.raises(_Abort):
        run_fluid(Potential("udc", 1.0), radius, 0.5, 5.2, schedule, np.random.default_rng(6),
                  thresholds, checkpoint=checkpoint, checkpoint_seconds=0.0, log=_KillAfter(12),
                  log_seconds=0.0)
    assert checkpoint.is_file()
    resumed = run_fluid(Potential("udc", 1.0), radius, 0.5, 5.2, schedule, np.random.default_rng(6),
                        thresholds, checkpoint=checkpoint, log_seconds=0.0)
    assert not checkpoint.exists()
    for name in ("frames", "energy", "acceptance", "axis_counts"):
        np.testing.assert_array_equal(getattr(reference, name), getattr(resumed, name), err_msg=name)
    # a checkpoint of another run is not used
    other = MCSchedule(equilibration_sweeps=40, production_sweeps=200, frame_interval=20, count_interval=1)
    with pytest.raises(_Abort):
        run_fluid(Potential("udc", 1.0), radius, 0.5, 5.2, schedule, np.random.default_rng(6),
                  thresholds, checkpoint=checkpoint, checkpoint_seconds=0.0, log=_KillAfter(12),
                  log_seconds=0.0)
    fresh = run_fluid(Potential("udc", 1.0), radius, 0.5, 5.2, other, np.random.default_rng(6),
                      thresholds, checkpoint=checkpoint)
    assert fresh.frames.shape[0] == 10


def test_autocorrelation_time_of_known_processes():
    rng = np.random.default_rng(7)
    assert integrated_autocorrelation_time(rng.standard_normal(20000)) == pytest.approx(0.5, abs=0.05)
    phi, x = 0.9, np.zeros(200000)  # AR(1): tau_int = (1 + phi) / (2 (1 - phi)) = 9.5
    noise = rng.standard_normal(x.size)
    for t in range(1, x.size):
        x[t] = phi * x[t - 1] + noise[t]
    assert integrated_autocorrelation_time(x) == pytest.approx(9.5, rel=0.1)


@pytest.mark.parametrize("call, message", [
    (lambda: particle_number(0.0, 0.5), "sphere radius R"),
    (lambda: particle_number(-5.0, 0.5), "sphere radius R"),
    (lambda: particle_number(5.0, 0.0), "number density rho"),
    (lambda: particle_number(5.0, -0.5), "number density rho"),
    (lambda: particle_number(0.1, 0.5), "fewer than 2 particles"),
    (lambda: Potential("yukawa", 1.0), "unknown pair potential 'yukawa'"),
    (lambda: Potential("ucc", -1.0), "coupling"),
    (lambda: cos_thresholds([1.0, 6.0], 5.0), "exceeds R"),
    (lambda: MCSchedule(10, 100, 0, 1), "frame_interval"),
    (lambda: run_fluid(Potential("lj", 1.0), 2.0, 0.5, 0.0, MCSchedule(1, 10, 5, 1), np.random.default_rng(0),
                       THRESHOLDS), "temperature"),
])
def test_bad_parameters_are_rejected_with_a_clear_message(call, message):
    with pytest.raises(ValueError, match=message):
        call()
