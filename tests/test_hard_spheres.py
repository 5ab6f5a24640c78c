"""Hard disks and spheres: equations of state (randmedia.theory.hard_spheres) and the NVT
Monte Carlo generator (randmedia.generate.hard_spheres)."""

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


def test_eos_refuses_bad_input():
    with pytest.raises(ValueError, match="close"):
        eos.compressibility_factor(0.75, 3)
    with pytest.raises(ValueError, match="dimension"):
        eos.compressibility_factor(0.3, 4)
    with pytest.raises(ValueError, match="unknown equation of state"):
        eos.compressibility_factor(0.3, 2, "carnahan_starling")
    with pytest.raises(ValueError, match="not converged"):
        eos.compressibility_factor(0.45, 3, "virial")
