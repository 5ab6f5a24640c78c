"""The 3D Yeong-Torquato construction (issue 13, docs/debye3d.md): convergence to the Debye
target, checkpoint/resume, checkpoints that name the dimension, input checks before work."""

import functools
import logging

import numpy as np
import pytest

from conftest import kill_and_resume
from randmedia.checkpoint import array_digest, checkpoint_key
from randmedia.describe.two_phase import s2_discrepancy, two_point_function
from randmedia.generate.yeong_torquato import (AnnealingSchedule, _checkpoint_key, _Geometry,
                                               construct, image_shape, tracked_target)
from randmedia.theory.debye import debye_s2

# 24^3 voxels, a = 2, l_c = 9 (4.5 a): ~1 s per construction
N, A, CUTOFF = 24, 2.0, 9.0
SHAPE = (N, N, N)


def debye(phi2, a=A):
    return functools.partial(debye_s2, phi2=phi2, a=a)


def build(phi2=0.3, seed=1, shape=SHAPE, cutoff=CUTOFF, **kwargs):
    schedule = kwargs.pop("schedule", AnnealingSchedule(long_range_stages=0))
    return construct(debye(phi2), phi2, shape, cutoff, np.random.default_rng(seed), schedule,
                     **kwargs)


@pytest.mark.parametrize("phi2", [0.2, 0.5, 0.75])
def test_three_dimensional_construction_reaches_the_debye_target(phi2):
    """Delta S2 over 0 < r <= l_c against phi2^2 + phi1 phi2 e^(-r/a) after the default
    schedule. Measured (5 seeds each, phi2 = 0.2 / 0.5 / 0.7): at most 7.0 / 6.6 / 6.3 x 10^-6
    (32^3, l_c = 12: at most 5.5 x 10^-6); the bound 2 x 10^-5 leaves a 3x margin and
    is 10x below the issue's 2 x 10^-4. (phi2 = 0.75: 0.25 N^3 is an integer. Otherwise
    the image holds round(phi N^3) tracked voxels, and for phi2 > 1/2 the S2 of phase 2
    -- the complement -- is off the target by 2 |phi - round(phi N^3)/N^3| <= 1/N^3 more
    than the tracked phase's, 2.9e-5 at 24^3 and phi2 = 0.7; 1e-7 at 128^3.)"""
    result = build(phi2)
    assert result.image.shape == SHAPE and result.image.dtype == np.uint8
    assert result.image.sum() == round(phi2 * N**3)  # phi2 exactly conserved
    assert result.delta_s2 <= 2e-5
    phi = min(phi2, 1 - phi2)  # trials per stage scale with N^3 (the 2D driver: N^2)
    assert result.stats["trials"] == 40 * (int(40 * phi * (1 - phi) * N**3) // 40)
    # the construction's S2 (FFT) equals the exact integer recount from shell counts ...
    exact = _Geometry(SHAPE, CUTOFF).s2(result.image.ravel())  # (counts of image == 1: phase 2)
    np.testing.assert_allclose(result.s2, exact, atol=1e-14)
    # ... and the independent estimator gives the same Delta S2 against the Debye target
    fft = two_point_function(result.image[np.newaxis], phase=1, r_max=CUTOFF)
    assert s2_discrepancy(fft, debye(phi2), SHAPE)[0] == pytest.approx(result.delta_s2, abs=1e-14)


def test_three_dimensional_fast_and_scanning_constructions_are_identical():
    """The driver's 3D path with shell counts, batched updates and pending-flip cells
    (3 x 3 x 3 cells) follows the ball scan's trajectory to the same image."""
    schedule = AnnealingSchedule(trials_per_pixel=10, tolerance=1.0, long_range_stages=0)
    slow = build(shape=(16, 17, 18), cutoff=5.0, schedule=schedule, scan=True)
    for batch in (7, 4096):
        fast = build(shape=(16, 17, 18), cutoff=5.0, schedule=schedule, batch=batch)
        np.testing.assert_array_equal(fast.image, slow.image)
        assert fast.stats["accepted"] == slow.stats["accepted"] > 0


def test_square_image_given_as_a_shape_is_the_same_construction():
    """L and (L, L) are the same 2D construction, bit for bit."""
    schedule = AnnealingSchedule(trials_per_pixel=10, tolerance=1.0, long_range_stages=0)
    by_side = construct(debye(0.3), 0.3, 40, 8.0, np.random.default_rng(3), schedule)
    by_shape = construct(debye(0.3), 0.3, (40, 40), 8.0, np.random.default_rng(3), schedule)
    np.testing.assert_array_equal(by_side.image, by_shape.image)


def test_checkpoint_keys_name_the_dimension():
    """An L x L image keeps the former 2D driver's key (its checkpoints stay valid); a 3D
    (or non-square) image is keyed by its shape, so no two dimensions share a key."""
    rng, target = np.random.default_rng(0), np.arange(4.0)
    schedule = AnnealingSchedule(long_range_stages=0)
    former = checkpoint_key(phi2=0.3, L=N, lc=CUTOFF, schedule=schedule.__dict__, scan=False,
                            target=array_digest(target), rng=rng.bit_generator.state)
    keys = {shape: _checkpoint_key(0.3, shape, CUTOFF, target, schedule, rng, False)
            for shape in [(N, N), (N, N, N), (N, N, N + 1), (N, N + 1)]}
    assert keys[(N, N)] == former
    assert len(set(keys.values())) == 4


class _StopAt(logging.Handler):
    """Raise KeyboardInterrupt at the log line of stage ``stage`` (after earlier stages
    were checkpointed)."""

    def __init__(self, stage):
        super().__init__()
        self.mark = f"; stage {stage}/"

    def emit(self, record):
        if self.mark in record.getMessage():
            raise KeyboardInterrupt


def _interrupted(tmp_path, stage, **kwargs):
    log = logging.getLogger(f"test_debye3d_yt_{stage}")
    log.setLevel(logging.INFO)
    handler = _StopAt(stage)
    log.addHandler(handler)
    checkpoint = tmp_path / "c.npz"
    try:
        with pytest.raises(KeyboardInterrupt):
            build(checkpoint=checkpoint, checkpoint_seconds=0.0, log=log, **kwargs)
    finally:
        log.removeHandler(handler)
    assert checkpoint.exists()
    return checkpoint


def test_a_three_dimensional_checkpoint_is_not_taken_for_a_two_dimensional_one(tmp_path, caplog):
    """Same phi2, l_c, target, schedule and seed; only the dimension differs: the 2D run
    ignores the 3D checkpoint (warns, starts afresh, same image as without it), and the
    3D run still resumes from it."""
    checkpoint = _interrupted(tmp_path, 6)
    copy = tmp_path / "copy.npz"
    copy.write_bytes(checkpoint.read_bytes())
    plain = build(shape=N)
    with caplog.at_level(logging.WARNING):
        flat = build(shape=N, checkpoint=copy)
    assert "belongs to another run" in caplog.text
    np.testing.assert_array_equal(flat.image, plain.image)
    caplog.clear()
    with caplog.at_level(logging.INFO):
        build(checkpoint=checkpoint)
    assert "resumed from" in caplog.text and "belongs to another run" not in caplog.text


def test_three_dimensional_interrupted_construction_resumes_to_the_same_image(tmp_path, caplog):
    whole = build(0.4, seed=8)
    checkpoint = _interrupted(tmp_path, 9, phi2=0.4, seed=8)
    with caplog.at_level(logging.INFO):
        resumed = build(0.4, seed=8, checkpoint=checkpoint, log=logging.getLogger("resume3d"))
    assert "resumed from" in caplog.text
    np.testing.assert_array_equal(resumed.image, whole.image)
    # the counts cover the whole construction; per_stage only this process's stages
    assert (resumed.stats["trials"], resumed.stats["accepted"]) == (whole.stats["trials"],
                                                                    whole.stats["accepted"])
    assert len(resumed.stats["per_stage"]) < len(whole.stats["per_stage"])
    assert not checkpoint.exists()


RESUMABLE = """
import functools, logging, sys
import numpy as np
from randmedia.generate.yeong_torquato import AnnealingSchedule, construct
from randmedia.theory.debye import debye_s2
logging.basicConfig(level=logging.INFO, stream=sys.stdout)
schedule = AnnealingSchedule(trials_per_pixel=400, long_range_stages=0)
result = construct(functools.partial(debye_s2, phi2=0.3, a=2.0), 0.3, (24, 24, 24), 9.0,
                   np.random.default_rng(12), schedule, checkpoint=sys.argv[1],
                   checkpoint_seconds=0.0)
np.save(sys.argv[2], result.image)
"""


def test_three_dimensional_killed_construction_resumes_to_the_same_image(tmp_path):
    """SIGKILL after a few checkpointed stages, then rerun: the same image as a run that
    was never interrupted (tests/conftest.py: kill_and_resume)."""
    stdout, resumed, whole = kill_and_resume(RESUMABLE, "; stage ", 3, tmp_path)
    assert "YT 24x24x24: " in stdout and "trials/s, ETA" in stdout  # progress
    assert resumed.shape == (24, 24, 24)
    np.testing.assert_array_equal(resumed, whole)


def _never_called(r):
    raise AssertionError("the target was evaluated: work started before the input check")


@pytest.mark.parametrize("side, cutoff, message", [
    ((24,), 5.0, "must be \\(ny, nx\\) or \\(nz, ny, nx\\)"),
    ((24, 24, 24, 24), 5.0, "must be \\(ny, nx\\) or \\(nz, ny, nx\\)"),
    ((24, 24, 3), 1.0, "integers >= 4"),
    ((24.0, 24, 24), 5.0, "integers >= 4"),
    ((24, 24, True), 5.0, "integers >= 4"),
    ("24", 5.0, "L must be an integer"),
    ((40, 40, 20), 10.0, "l_c < L/2 = 10 \\(L the shortest side of the 40x40x20 image\\)"),
    ((24, 24, 24), 12.0, "l_c < L/2 = 12"),
    ((24, 24, 24), 0.5, "1 <= l_c"),
])
def test_bad_shapes_fail_before_any_work(side, cutoff, message):
    with pytest.raises(ValueError, match=message):
        construct(_never_called, 0.3, side, cutoff, np.random.default_rng(0),
                  AnnealingSchedule(long_range_stages=0))


def test_image_shape_of_a_side_or_a_shape():
    assert image_shape(24) == (24, 24)
    assert image_shape(np.int64(24)) == (24, 24)
    assert image_shape((24, 25, 26)) == (24, 25, 26)
    assert image_shape([np.int32(8), 9]) == (8, 9)


def test_shell_counts_take_the_smallest_type_and_the_targets_match_the_bins():
    """uint8 while a shell holds <= 255 voxels (2D up to l_c ~ 40, 3D up to l_c ~ 4),
    uint16 beyond (3D up to l_c ~ 72: 128^3 at l_c = 32 holds 12 146 in its fullest
    shell, 128 MiB of counts)."""
    assert _Geometry((24, 24), 9.0).stencil.count_dtype == np.uint8
    big = _Geometry((128, 128, 128), 32.0)
    assert big.stencil.count_dtype == np.uint16
    assert big.stencil.largest_shell == 12146
    assert big.stencil.counts_bytes() == 128**3 * 32 * 2
    phi, target = tracked_target(debye(0.3, a=4.0), 0.3, big.binning)
    assert phi == 0.3 and target[0] == pytest.approx(0.3)
