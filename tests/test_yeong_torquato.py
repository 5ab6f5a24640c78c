"""Accelerated Yeong-Torquato construction: exactness, convergence, symmetry, resume."""

import dataclasses
import functools
import hashlib

import numpy as np
import pytest

from conftest import SCHEMA, kill_and_resume
from randmedia.config import load_schema
from randmedia.describe.two_phase import s2_discrepancy, two_point_function
from randmedia.generate.yeong_torquato import (AnnealingSchedule, ConstructionError, _anneal,
                                               _Geometry, construct, tracked_target)
from randmedia.theory.debye import debye_s2

SIDE, A, CUTOFF = 48, 3.0, 12.0


def debye(phi2, a=A):
    return functools.partial(debye_s2, phi2=phi2, a=a)


def build(phi2=0.3, seed=1, side=SIDE, cutoff=CUTOFF, **kwargs):
    schedule = kwargs.pop("schedule", AnnealingSchedule(long_range_stages=0))
    return construct(debye(phi2), phi2, side, cutoff, np.random.default_rng(seed), schedule,
                     **kwargs)


# Digests of constructions made by commit e000202 (the 2D construction with its own
# shell-count kernels, before it moved onto randmedia.generate.yt_stencil): the same seeds
# must keep giving these images, accepted-swap counts and Delta S2 (bit-identical
# trajectories). sha256 of the phase-2 image bytes (uint8, C order), first 16 hex digits.
REFERENCE_CONSTRUCTIONS = [
    # (phi2, L, l_c, seed, schedule), image digest, (trials, accepted, stages,
    # long-range stages, long-range accepted), Delta S2, energy
    ((0.3, 48, 12.0, 1, {"long_range_stages": 0}), "5168dd0b38d40914", (19320, 1018, 40, 0, 0),
     8.65173443963703e-05, 1.4984730119141728e-07),
    ((0.7, 60, 9.0, 3, {"long_range_stages": 0}), "aa36f0daa26d503f", (30240, 1617, 40, 0, 0),
     3.2808299036966394e-05, 1.3138451380964547e-08),
    ((0.3, 61, 8.0, 2, {"long_range_stages": 2}), "efe4ed2f359cb1fa", (32802, 1788, 40, 2, 159),
     0.00014820924878178147, 4.033605755954557e-07),
]


@pytest.mark.parametrize("case, digest, counts, delta_s2, energy", REFERENCE_CONSTRUCTIONS,
                         ids=["one-cell", "bucketed-complement", "long-range"])
def test_same_images_as_the_reference_commit(case, digest, counts, delta_s2, energy):
    phi2, side, cutoff, seed, schedule = case
    result = build(phi2, seed=seed, side=side, cutoff=cutoff,
                   schedule=AnnealingSchedule(**schedule))
    image = np.ascontiguousarray(result.image, dtype=np.uint8)
    assert hashlib.sha256(image.tobytes()).hexdigest()[:16] == digest
    keys = ("trials", "accepted", "stages", "long_range_stages", "long_range_accepted")
    assert tuple(result.stats[k] for k in keys) == counts
    assert result.delta_s2 == pytest.approx(delta_s2, rel=1e-9)
    assert result.energy == pytest.approx(energy, rel=1e-9)


@pytest.mark.parametrize("interface_only", [False, True], ids=["all-voxels", "interface"])
def test_three_dimensional_trials_keep_exact_counts_and_follow_the_scan(interface_only):
    """The trial loop is d-generic: on a 3D image (4-5 pending-flip cells per axis, small
    batches, so bucketed lookups and many flushes) the incremental shell counts and
    S2 - target stay those of the current image, and the disk-scan baseline follows the
    same trajectory."""
    shape, cutoff, phi2 = (14, 15, 16), 5.0, 0.3
    geometry = _Geometry(shape, cutoff)
    n = int(np.prod(shape))
    start = np.zeros(n, dtype=np.uint8)
    start[np.random.default_rng(0).permutation(n)[:round(phi2 * n)]] = 1
    _, target = tracked_target(debye(phi2, a=2.0), phi2, geometry.binning)
    runs = {}
    for scan in (False, True):
        image = start.copy()
        h = geometry.shell_counts(image, scan)
        diff = geometry.s2(image)[1:] - target[1:]
        accepted = _anneal(image, h, diff, 4000, 2e-6, interface_only, scan,
                           np.random.default_rng(1), 16, *geometry.kernel_args())
        runs[scan] = image, accepted
        if not scan:
            np.testing.assert_array_equal(h, geometry.shell_counts(image))
        np.testing.assert_allclose(diff, geometry.s2(image)[1:] - target[1:], rtol=0, atol=1e-12)
        assert image.sum() == round(phi2 * n)
    np.testing.assert_array_equal(runs[False][0], runs[True][0])
    assert runs[False][1] == runs[True][1] > 100


def test_long_range_stages_constrain_s2_out_to_half_the_box():
    """After convergence on 0 < r <= l_c, two stages on bins out to 0.49 L bring the mean
    |S2 - target| over all bins 0 < r < L/2 down several-fold and keep the l_c range
    converged; the disk-scan baseline follows the same trajectory."""
    side, cutoff, phi2 = 61, 8.0, 0.3
    plain = build(phi2, seed=2, side=side, cutoff=cutoff)
    schedule = AnnealingSchedule(long_range_stages=2)
    far = build(phi2, seed=2, side=side, cutoff=cutoff, schedule=schedule)

    def full_range(image):
        s2 = two_point_function(image[np.newaxis], phase=1, r_max=side // 2 - 1)
        return s2_discrepancy(s2, debye(phi2), image.shape)[0]

    assert far.stats["long_range_stages"] == 2 and far.stats["long_range_accepted"] > 0
    assert far.delta_s2 <= 2e-4
    assert full_range(far.image) < full_range(plain.image) / 3
    scanned = build(phi2, seed=2, side=side, cutoff=cutoff, schedule=schedule, scan=True)
    np.testing.assert_array_equal(scanned.image, far.image)


def test_construction_interrupted_in_a_long_range_stage_resumes_to_the_same_image(tmp_path):
    import logging

    class Interrupt(logging.Handler):
        def emit(self, record):
            if record.getMessage().startswith("long-range stage 2/"):
                raise KeyboardInterrupt

    schedule = AnnealingSchedule(long_range_stages=3)
    whole = build(seed=6, side=61, cutoff=8.0, schedule=schedule)
    log = logging.getLogger("test_yt_interrupt")
    log.setLevel(logging.INFO)
    handler = Interrupt()
    log.addHandler(handler)
    checkpoint = tmp_path / "c.npz"
    with pytest.raises(KeyboardInterrupt):
        build(seed=6, side=61, cutoff=8.0, schedule=schedule, checkpoint=checkpoint,
              checkpoint_seconds=0.0, log=log)
    log.removeHandler(handler)
    assert checkpoint.exists()
    resumed = build(seed=6, side=61, cutoff=8.0, schedule=schedule, checkpoint=checkpoint, log=log)
    np.testing.assert_array_equal(resumed.image, whole.image)
    assert not checkpoint.exists()
    # the stats count the whole construction, the part before the interruption included
    for name in ("trials", "accepted", "stages", "long_range_stages", "long_range_accepted"):
        assert resumed.stats[name] == whole.stats[name], name
    assert resumed.stats["long_range_accepted"] > 0
    assert len(resumed.stats["per_stage"]) < len(whole.stats["per_stage"])  # this process's stages
    assert resumed.stats["cpu_seconds"] > 0


@pytest.mark.parametrize("side, cutoff", [(SIDE, CUTOFF), (60, 9.0), (20, 8.0)],
                         ids=["one-cell", "bucketed", "window-near-the-ring"])
def test_fast_and_disk_scan_constructions_are_identical(side, cutoff):
    """O(bins) trials with deferred, batched count updates (any batch size) and the O(l_c^2)
    scan follow the same trajectory to the same image. 60 / 9 px gives a 6 x 6 grid of
    pending-flip cells (the bucketed lookup); 48 / 12 px a single cell; 20 / 8 px leaves 3 px
    of the ring outside a pixel's window (7 cells of 2-3 px; the former layout, 5 cells of
    3 px and a last one of 5 px, met that cell at both ends of a window and raised)."""
    schedule = AnnealingSchedule(trials_per_pixel=10, tolerance=1.0, long_range_stages=0)
    slow = build(schedule=schedule, scan=True, side=side, cutoff=cutoff)
    for batch in (2, 7, 4096):
        fast = build(schedule=schedule, batch=batch, side=side, cutoff=cutoff)
        np.testing.assert_array_equal(fast.image, slow.image)
        assert fast.stats["accepted"] == slow.stats["accepted"] > 0


@pytest.mark.parametrize("phi2", [0.1, 0.3, 0.5])
def test_converges_and_matches_independent_estimator(phi2):
    result = build(phi2)
    assert result.image.sum() == round(phi2 * SIDE * SIDE)  # phi2 exactly conserved
    assert result.delta_s2 <= 2e-4
    # the construction's S2 (FFT) equals the exact integer recount from shell counts
    exact = _Geometry((SIDE, SIDE), CUTOFF).s2(result.image.ravel())  # phase 2 is tracked for phi2 <= 1/2
    np.testing.assert_allclose(result.s2, exact, atol=1e-14)
    fft = two_point_function(result.image[np.newaxis], phase=1, r_max=CUTOFF)
    recomputed = s2_discrepancy(fft, debye(phi2), result.image.shape)[0]
    assert recomputed == pytest.approx(result.delta_s2, abs=1e-14)


def test_phase_inversion_symmetry():
    """phi2 and 1 - phi2 run the same code: complementary images for the same seed, the
    same Delta S2 (of the tracked phase); the S2 of phase 2 is the exact complement,
    S2' = 1 - 2 phi + S2 with the image's own fraction phi (691 of 48^2 pixels, not 0.3)."""
    low, high = build(0.3, seed=4), build(0.7, seed=4)
    np.testing.assert_array_equal(high.image, 1 - low.image)
    assert high.delta_s2 == pytest.approx(low.delta_s2, rel=1e-9)  # (targets: 1 - 0.7 vs 0.3)
    assert high.energy == pytest.approx(low.energy, rel=1e-9)
    assert high.s2[0] == 1 - low.s2[0] == 1 - 691 / SIDE**2
    np.testing.assert_allclose(high.s2[1:], 1 - 2 * low.s2[0] + low.s2[1:], rtol=0, atol=1e-14)
    np.testing.assert_allclose(high.s2, _Geometry((SIDE, SIDE), CUTOFF).s2(high.image.ravel()),
                               rtol=0, atol=1e-14)
    np.testing.assert_allclose(high.target[1:], 1 - 2 * 0.3 + low.target[1:], rtol=0, atol=1e-14)


def test_same_seed_same_image_different_seed_different_image():
    np.testing.assert_array_equal(build(seed=3).image, build(seed=3).image)
    assert not np.array_equal(build(seed=3).image, build(seed=5).image)


def test_unconverged_construction_fails_loudly():
    schedule = AnnealingSchedule(trials_per_pixel=0.5, tolerance=1e-9, max_extra_stages=0,
                                 long_range_stages=0)
    with pytest.raises(ConstructionError, match="did not converge"):
        build(schedule=schedule)


@pytest.mark.parametrize("kwargs, message", [
    ({"cutoff": 24.0}, "l_c must satisfy"),
    ({"cutoff": 30.0}, "l_c must satisfy"),
    ({"side": 48.5}, "L must be an integer"),
    ({"side": 2}, "L must be an integer"),
])
def test_rejects_bad_geometry(kwargs, message):
    with pytest.raises(ValueError, match=message):
        build(**kwargs)


@pytest.mark.parametrize("phi2", [0.0, 1.0, -0.2, 1.5])
def test_rejects_bad_volume_fraction(phi2):
    with pytest.raises(ValueError, match="phi2 must lie in"):
        construct(lambda r: np.zeros_like(r), phi2, SIDE, CUTOFF, np.random.default_rng(0),
                  AnnealingSchedule(long_range_stages=0))


def test_rejects_bad_length_scale_and_inconsistent_target():
    with pytest.raises(ValueError, match="a must be > 0"):
        debye_s2(1.0, 0.3, 0.0)
    with pytest.raises(ValueError, match="must equal phi2"):
        construct(debye(0.2), 0.3, SIDE, CUTOFF, np.random.default_rng(0),
                  AnnealingSchedule(long_range_stages=0))


def test_schema_defaults_equal_package_defaults():
    """The schedule schema and AnnealingSchedule default the same keys to the same values;
    long_range_stages, which debye2020 and debye3d set differently, has no default in
    either (tests/test_defaults.py compares both with config/config.yaml)."""
    schema = load_schema(SCHEMA)
    properties = schema["properties"]["debye2020"]["properties"]["media"]["properties"]
    defaults = {k: v["default"] for k, v in properties["schedule"]["properties"].items() if "default" in v}
    package = {f.name: f.default for f in dataclasses.fields(AnnealingSchedule)
               if f.default is not dataclasses.MISSING}
    assert defaults == package
    assert set(properties["schedule"]["properties"]) - set(defaults) == {"long_range_stages"}


RESUMABLE = """
import functools, logging, sys
import numpy as np
from randmedia.generate.yeong_torquato import AnnealingSchedule, construct
from randmedia.theory.debye import debye_s2
logging.basicConfig(level=logging.INFO, stream=sys.stdout)
schedule = AnnealingSchedule(trials_per_pixel=200, n_stages=40, long_range_stages=0)
result = construct(functools.partial(debye_s2, phi2=0.3, a=4.0), 0.3, 101, 24.0,
                   np.random.default_rng(12), schedule, checkpoint=sys.argv[1],
                   checkpoint_seconds=0.0)
np.save(sys.argv[2], result.image)
"""


def test_killed_construction_resumes_to_the_same_image(tmp_path):
    """SIGKILL after a few checkpointed stages, then rerun: the same image as a run that
    was never interrupted (tests/conftest.py: kill_and_resume)."""
    _, resumed, whole = kill_and_resume(RESUMABLE, "stage ", 5, tmp_path)
    np.testing.assert_array_equal(resumed, whole)
