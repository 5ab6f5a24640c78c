"""Hard disks and spheres: equations of state (randmedia.theory.hard_spheres) and the NVT
Monte Carlo generator (randmedia.generate.hard_particles)."""

from __future__ import annotations

import numpy as np
import pytest

from randmedia.theory import hard_spheres as eos

# --------------------------------------------------------------------------- equations of state


@pytest.mark.parametrize("dim, phi, tolerance", [(2, 0.1, 1e-4), (2, 0.3, 4e-4), (3, 0.1, 1e-4),
                                                 (3, 0.3, 3e-4)])
def test_default_eos_agrees_with_the_virial_series(dim, phi, tolerance):
    exact = eos.compressibility_factor(phi, dim, "virial")
    assert eos.compressibility_factor(phi, dim) == pytest.approx(exact, rel=tolerance)


def test_closed_forms_and_their_virial_coefficients():
    phi = 1e-3  # Z = 1 + B2 phi + B3 phi^2 + O(phi^3)
    for dim, name, b3 in ((3, "carnahan_starling", 10.0), (3, "kolafa", 10.0),
                          (2, "henderson", 3.125), (2, "santos", 4 - (2 * eos.CLOSE_PACKING[2] - 1)
                                                    / eos.CLOSE_PACKING[2] ** 2)):
        z = eos.compressibility_factor(phi, dim, name)
        b2 = 2.0 ** (dim - 1)
        assert (z - 1 - b2 * phi) / phi**2 == pytest.approx(b3, rel=3e-3), name
    assert eos.compressibility_factor(0.478, 3, "carnahan_starling") == pytest.approx(11.22966, abs=1e-4)
    # exact B3 of hard disks: 4 (4/3 - sqrt(3)/pi)
    assert eos.VIRIAL_COEFFICIENTS[2][1] == pytest.approx(4 * (4 / 3 - np.sqrt(3) / np.pi), rel=1e-9)


def test_contact_value_and_pressure_are_inverse():
    for dim, phi in ((2, 0.3), (3, 0.478)):
        g = eos.contact_value(phi, dim)
        assert eos.reduced_pressure_from_contact(phi, g, dim) == pytest.approx(
            eos.compressibility_factor(phi, dim))
    assert eos.contact_value(0.0, 3) == 1.0
    # Carnahan-Starling contact value (1 - phi/2)/(1 - phi)^3
    assert eos.contact_value(0.4, 3, "carnahan_starling") == pytest.approx(0.8 / 0.6**3)


def test_structure_factor_at_zero_wavenumber():
    phi = np.array([0.1, 0.3, 0.478])
    cs = (1 - phi) ** 4 / (1 + 4 * phi + 4 * phi**2 - 4 * phi**3 + phi**4)  # closed form of CS
    np.testing.assert_allclose(eos.structure_factor_zero(phi, 3, "carnahan_starling"), cs, rtol=1e-8)
    assert eos.structure_factor_zero(0.0, 2) == pytest.approx(1.0)
    # Henderson: d(phi Z)/d phi in closed form
    p = 0.3
    derivative = ((1 + 3 * p**2 / 8) * (1 - p) + 2 * p * (1 + p**2 / 8)) / (1 - p) ** 3
    assert eos.structure_factor_zero(p, 2) == pytest.approx(1 / derivative, rel=1e-8)
    # chi_V(0) = phi v1(D/2) S(0): liquid at 0.478, D = 1
    assert eos.spectral_density_zero(0.478, 3) == pytest.approx(
        0.478 * np.pi / 6 * eos.structure_factor_zero(0.478, 3))


def test_eos_refuses_bad_input():
    with pytest.raises(ValueError, match="close"):
        eos.compressibility_factor(0.75, 3)
    with pytest.raises(ValueError, match="dimension"):
        eos.compressibility_factor(0.3, 4)
    with pytest.raises(ValueError, match="unknown equation of state"):
        eos.compressibility_factor(0.3, 2, "carnahan_starling")
    with pytest.raises(ValueError, match="not converged"):
        eos.compressibility_factor(0.45, 3, "virial")


# --------------------------------------------------------------------------- Monte Carlo

from randmedia.describe.bond_order import crystalline_fraction, global_q6  # noqa: E402
from randmedia.generate.hard_particles.chain import HardParticleChain  # noqa: E402
from randmedia.generate.hard_particles.geometry import count_overlaps, cubic_box  # noqa: E402
from randmedia.generate.hard_particles.run import run_chain  # noqa: E402
from randmedia.generate.hard_particles.settings import MCSettings  # noqa: E402


def _brute_force_min_distance(positions, box):
    d = positions[:, None, :] - positions[None, :, :]
    d -= box * np.round(d / box)
    r = np.sqrt((d**2).sum(-1))
    r[np.diag_indices(len(positions))] = np.inf
    return r.min()


@pytest.fixture(scope="module")
def liquid_3d():
    """N = 256 spheres at phi = 0.478 (simple cubic start), 16 samples 0.3 D^2 apart."""
    settings = MCSettings(equilibration_msd=1.5, sample_msd=0.3, measure_every=2, contact_range=0.1,
                          contact_order=3)
    box = cubic_box(256, 0.478, 3)
    return run_chain(256, box, 1.0, 16, np.random.default_rng(11), settings)


def test_no_overlaps_ever(liquid_3d):
    box = liquid_3d.box_lengths
    for sample in liquid_3d.samples:
        assert count_overlaps(sample.positions, box, 1.0) == 0
        assert _brute_force_min_distance(sample.positions, box) >= 1.0
        assert np.all((sample.positions >= 0) & (sample.positions < box))


def test_liquid_pressure_matches_the_equation_of_state(liquid_3d):
    """Contact-value pressure of a small equilibrated liquid within 1 % of the accurate EOS.
    Statistical error: SEM over the 16 samples (~0.4 %); the pooled fit is compared."""
    z = np.array([s.diagnostics["reduced_pressure"] for s in liquid_3d.samples])
    sem = z.std(ddof=1) / np.sqrt(len(z))
    expected = eos.compressibility_factor(liquid_3d.phi, 3)
    assert sem < 0.006 * expected
    assert liquid_3d.contact["reduced_pressure"] == pytest.approx(expected, rel=0.01)
    assert z.mean() == pytest.approx(expected, rel=0.01)


def test_liquid_is_melted_and_samples_are_decorrelated(liquid_3d):
    eq = liquid_3d.equilibration
    assert "lattice" in eq["start"] and eq["equilibration_msd"] >= 1.5
    assert 0.2 < eq["acceptance"] < 0.3  # tuned towards 0.25, then frozen
    for sample in liquid_3d.samples:
        assert sample.diagnostics["msd_since_previous"] >= 0.3
        # liquid: Q6 ~ 0.9 / sqrt(N) = 0.055 (bonds are correlated; random points 0.44 / sqrt(N));
        # crystals: fcc 0.57, bcc 0.51
        assert global_q6(sample.positions, np.diag(liquid_3d.box_lengths)) < 0.1
        assert crystalline_fraction(sample.positions, np.diag(liquid_3d.box_lengths)) < 0.05


def test_two_disks_sample_the_uniform_measure():
    """Detailed balance: two hard disks on a torus are uniform over the allowed region, so
    their minimum-image distance has density prop. to r on D < r < L/2 (exact)."""
    side = 4.0
    settings = MCSettings(equilibration_msd=1.0, sample_msd=1.0, block_sweeps=5, measure_every=5,
                          contact_range=0.1, contact_order=3)
    result = run_chain(2, [side, side], 1.0, 3000, np.random.default_rng(3), settings)
    r = np.array([np.linalg.norm(_minimum_image(s.positions[1] - s.positions[0], side))
                  for s in result.samples])
    assert r.min() >= 1.0
    inner = np.sort(r[r < side / 2])
    cdf = (inner**2 - 1.0) / ((side / 2) ** 2 - 1.0)
    ks = np.max(np.abs(cdf - np.arange(1, len(inner) + 1) / len(inner)))
    # fraction of the allowed area within L/2: (pi (L/2)^2 - pi D^2) / (L^2 - pi D^2)
    fraction = (np.pi * (side / 2) ** 2 - np.pi) / (side**2 - np.pi)
    assert np.mean(r < side / 2) == pytest.approx(fraction, abs=4 * np.sqrt(fraction / len(r)))
    assert ks < 1.63 / np.sqrt(len(inner))  # KS at the 1 % level


def _minimum_image(d, side):
    return d - side * np.round(d / side)


def test_low_density_pressure_against_the_exact_virial_series():
    """phi = 0.1 spheres (RSA start): Z within 1 % of the converged virial series."""
    settings = MCSettings(equilibration_msd=1.0, sample_msd=0.5, measure_every=1,
                             contact_range=0.2, contact_order=3)
    box = cubic_box(200, 0.1, 3)
    result = run_chain(200, box, 1.0, 60, np.random.default_rng(4), settings, start="rsa")
    assert result.equilibration["start"].startswith("random sequential addition")
    exact = eos.compressibility_factor(0.1, 3, "virial")
    assert result.contact["reduced_pressure"] == pytest.approx(exact, rel=0.01)


def test_hard_disks_pressure_matches_the_2d_equation_of_state():
    """400 disks at phi = 0.3 (the debye2020 density), quadratic contact fit over 0.2 D:
    within 1 % of Henderson's EOS; SEM over 500 samples ~0.3 %."""
    settings = MCSettings(equilibration_msd=2.0, sample_msd=1.0, measure_every=1,
                             contact_range=0.2, contact_order=2)
    box = cubic_box(400, 0.3, 2)
    result = run_chain(400, box, 1.0, 500, np.random.default_rng(5), settings)
    z = np.array([s.diagnostics["reduced_pressure"] for s in result.samples])
    expected = eos.compressibility_factor(0.3, 2)
    assert z.std(ddof=1) / np.sqrt(len(z)) < 0.004 * expected
    assert z.mean() == pytest.approx(expected, rel=0.01)
    assert result.contact["reduced_pressure"] == pytest.approx(expected, rel=0.01)
    assert result.samples[0].positions.shape == (400, 2)


def test_rsa_start_with_compression_reaches_the_target():
    box = cubic_box(64, 0.45, 3)
    settings = MCSettings(equilibration_msd=0.5, sample_msd=0.2, measure_every=5, contact_range=0.1,
                          contact_order=3)
    result = run_chain(64, box, 1.0, 2, np.random.default_rng(6), settings, start="rsa")
    assert result.equilibration["compression_sweeps"] > 0
    assert count_overlaps(result.samples[-1].positions, box, 1.0) == 0


def test_same_seed_same_chain_and_resume_after_interruption(tmp_path, monkeypatch):
    box = cubic_box(100, 0.4, 3)
    settings = MCSettings(equilibration_msd=0.5, sample_msd=0.2, measure_every=5, contact_range=0.1,
                          contact_order=3)
    first = run_chain(100, box, 1.0, 4, np.random.default_rng(7), settings)
    second = run_chain(100, box, 1.0, 4, np.random.default_rng(7), settings)
    for a, b in zip(first.samples, second.samples):
        np.testing.assert_array_equal(a.positions, b.positions)
    # interrupted chain: checkpoint at every block, "killed" after 60 units of work
    checkpoint = tmp_path / "chain.npz"
    original = HardParticleChain.advance
    calls = {"n": 0}

    def dying_advance(self):
        calls["n"] += 1
        if calls["n"] > 60:
            raise KeyboardInterrupt("simulated kill")
        original(self)

    monkeypatch.setattr(HardParticleChain, "advance", dying_advance)
    with pytest.raises(KeyboardInterrupt):
        run_chain(100, box, 1.0, 4, np.random.default_rng(7), settings,
                     checkpoint=checkpoint, checkpoint_seconds=0.0)
    assert checkpoint.is_file()
    monkeypatch.setattr(HardParticleChain, "advance", original)
    resumed = run_chain(100, box, 1.0, 4, np.random.default_rng(7), settings,
                           checkpoint=checkpoint, checkpoint_seconds=0.0)
    assert not checkpoint.exists()
    for a, b in zip(first.samples, resumed.samples):
        np.testing.assert_array_equal(a.positions, b.positions)
        assert a.diagnostics == b.diagnostics


@pytest.mark.parametrize("args, match", [
    ((1, [5.0, 5.0, 5.0], 1.0), "at least N = 2"),
    ((10, [5.0, 5.0, 5.0], 0.0), "diameter"),
    ((10, [5.0, 5.0, -5.0], 1.0), "box side"),
    ((10, [2.0, 2.0, 2.0], 1.0), "every box side"),
    ((120, [5.0, 5.0, 5.0], 1.0), "stable fluid branch"),
    ((60, [5.0, 5.0], 1.0), "stable fluid branch"),
    ((10, [5.0], 1.0), "2 or 3"),
])
def test_impossible_input_is_refused(args, match):
    with pytest.raises(ValueError, match=match):
        run_chain(*args, 1, np.random.default_rng(0),
                  MCSettings(sample_msd=1.0, measure_every=5, contact_range=0.1, contact_order=3))
    with pytest.raises(ValueError):
        MCSettings(target_acceptance=1.5, sample_msd=1.0, measure_every=5, contact_range=0.1,
                   contact_order=3)
