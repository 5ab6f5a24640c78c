"""Closed forms: the Debye-media formulas of Sec. V (Eqs. 24-28) and the hard-disk forms of
Sec. VI B (Eqs. 40, 42, 43): limits, identities and invariances the paper states."""

import numpy as np
import pytest
from scipy.integrate import quad

from randmedia.theory import debye_formulas as formulas
from randmedia.theory import hard_disks, hard_spheres
from randmedia.theory.debye import debye_s2
from randmedia.theory.debye_formulas import debye_specific_surface


@pytest.mark.parametrize("phi2", [0.1, 0.3, 0.5, 0.8])
def test_eq_24_limits_and_eq_25(phi2):
    a = 5.0
    s = debye_specific_surface(a, phi2)
    assert formulas.debye_surface_void(0.0, phi2, a) == pytest.approx(s / 2)  # Eq. (12)
    assert formulas.debye_surface_void(1e4, phi2, a) == pytest.approx(s * (1 - phi2))  # Eq. (14)
    r = np.linspace(0.1, 30, 50)
    void_s2 = 1 - 2 * phi2 + debye_s2(r, phi2, a)  # S2 of phase 1 from S2 of phase 2
    eq25 = np.pi * phi2 / a / (1 + np.exp(-r / a)) * void_s2
    np.testing.assert_allclose(formulas.debye_surface_void(r, phi2, a), eq25, rtol=1e-12)


def test_eq_26_limits_and_phase_inversion():
    a, phi2 = 5.0, 0.3
    s = debye_specific_surface(a, phi2)
    assert formulas.debye_surface_surface(1e4, phi2, a) == pytest.approx(s**2)  # Eq. (16)
    r = 1e-6
    assert formulas.debye_surface_surface(r, phi2, a) * r == pytest.approx(s / np.pi, rel=1e-5)
    x = np.linspace(0.1, 20, 30)
    np.testing.assert_allclose(formulas.debye_surface_surface(x, phi2, a),
                               formulas.debye_surface_surface(x, 1 - phi2, a), rtol=1e-12)


def test_euler_characteristic_is_the_slope_of_eq_24():
    a, phi2, h = 5.0, 0.2, 1e-6
    slope = (formulas.debye_surface_void(h, phi2, a) - formulas.debye_surface_void(0.0, phi2, a)) / h
    assert slope == pytest.approx(formulas.debye_euler_characteristic(phi2, a), rel=1e-5)
    assert formulas.debye_euler_characteristic(0.5, a) == 0.0


def test_model_specific_surface_dispatch():
    assert formulas.model_specific_surface("debye", phi2=0.3, a=5.0) == pytest.approx(np.pi * 0.21 / 5)
    assert formulas.model_specific_surface("hard_disks", phi2=0.3, radius=10.0) == pytest.approx(0.06)
    with pytest.raises(ValueError, match="radius"):
        formulas.model_specific_surface("overlapping_disks", phi2=0.3)
    with pytest.raises(ValueError, match="unknown model"):
        formulas.model_specific_surface("spheres", phi2=0.3, a=1.0)


def test_hard_disk_lineal_path_and_chords_are_consistent():
    """Eq. (43) is (l_C/phi1) L''(z) of Eq. (42) (Eq. 19), normalized, with mean chord
    pi phi1 / s (Eq. 20) for s of Eq. (40); L(0) = phi1."""
    radius, phi2 = 10.0, 0.3
    phi1 = 1 - phi2
    s = hard_spheres.specific_surface(radius, phi2, 2)  # Eq. (40)
    assert hard_disks.lineal_path_void(0.0, radius, phi2) == pytest.approx(phi1)
    total, _ = quad(lambda z: hard_disks.chord_density_void(z, radius, phi2), 0, np.inf)
    mean, _ = quad(lambda z: z * hard_disks.chord_density_void(z, radius, phi2), 0, np.inf)
    assert total == pytest.approx(1.0) and mean == pytest.approx(np.pi * phi1 / s)
    z, h = 7.0, 1e-3
    second = (hard_disks.lineal_path_void(z + h, radius, phi2) - 2 * hard_disks.lineal_path_void(z, radius, phi2)
              + hard_disks.lineal_path_void(z - h, radius, phi2)) / h**2
    assert mean / phi1 * second == pytest.approx(hard_disks.chord_density_void(z, radius, phi2), rel=1e-5)
    with pytest.raises(ValueError):
        hard_spheres.specific_surface(10.0, 1.2, 2)


def test_3d_conjectures_eqs_44_45_as_printed_and_their_limits():
    from randmedia.theory import debye_formulas as formulas

    phi2, a = 0.3, 4.0
    phi1 = 1 - phi2
    r = np.array([0.5, 1.0, 4.0, 9.0])
    decay = np.exp(-r / a)
    s2_void = phi1 * phi2 * decay + phi1**2
    np.testing.assert_allclose(formulas.debye_surface_void(r, phi2, a, dim=3),
                               4 * phi2 / a / (1 + decay) * s2_void, rtol=1e-14)  # Eq. (44)
    np.testing.assert_allclose(formulas.debye_surface_surface(r, phi2, a, dim=3),
                               16 / a**2 * phi1**2 * phi2**2 + 2 / (a * r) * phi1 * phi2 * decay
                               + decay / (2 * a**2 * (1 + decay)) * abs(phi2 - phi1), rtol=1e-14)  # (45)
    s = formulas.debye_specific_surface(a, phi2, dim=3)
    assert s == pytest.approx(4 * phi1 * phi2 / a)
    assert formulas.debye_surface_void(0.0, phi2, a, dim=3) == pytest.approx(s / 2)
    assert formulas.debye_surface_void(1e4, phi2, a, dim=3) == pytest.approx(s * phi1)
    assert formulas.debye_surface_surface(1e4, phi2, a, dim=3) == pytest.approx(s * s)
    tiny = 1e-7
    assert tiny * formulas.debye_surface_surface(tiny, phi2, a, dim=3) == pytest.approx(s / 2, rel=1e-5)
    assert formulas.debye_specific_surface(a, phi2) == pytest.approx(np.pi * phi1 * phi2 / a)
    with pytest.raises(ValueError, match="dim"):
        formulas.debye_surface_surface(r, phi2, a, dim=4)
