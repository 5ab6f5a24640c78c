"""randmedia.checkpoint: keyed, atomic checkpoints shared by every long-running generator."""

import logging

import numpy as np

from randmedia.checkpoint import array_digest, checkpoint_key, load_checkpoint, save_checkpoint

LOG = logging.getLogger("test_checkpoint")


def test_round_trip_restores_arrays_scalars_and_random_state(tmp_path):
    path = tmp_path / "run.checkpoint.npz"
    rng = np.random.default_rng(7)
    rng.random(5)
    image = np.arange(12).reshape(3, 4)
    save_checkpoint(path, "k1", {"image": image, "stage": 3, "energy": 1.25}, rng)
    expected_next = rng.random(4)

    fresh = np.random.default_rng(999)
    data = load_checkpoint(path, "k1", LOG, fresh)
    np.testing.assert_array_equal(data["image"], image)
    assert int(data["stage"]) == 3 and float(data["energy"]) == 1.25
    np.testing.assert_array_equal(fresh.random(4), expected_next)  # continues the saved stream


def test_other_key_or_broken_file_is_ignored_and_leaves_the_generator_alone(tmp_path, caplog):
    path = tmp_path / "run.checkpoint.npz"
    save_checkpoint(path, "k1", {"x": np.zeros(2)}, np.random.default_rng(1))
    rng = np.random.default_rng(5)
    before = rng.bit_generator.state
    with caplog.at_level(logging.WARNING):
        assert load_checkpoint(path, "another run", LOG, rng) is None
    assert "belongs to another run" in caplog.text
    assert rng.bit_generator.state == before

    path.write_bytes(b"not an npz file")
    with caplog.at_level(logging.WARNING):
        assert load_checkpoint(path, "k1", LOG, rng) is None
    assert "unreadable" in caplog.text
    assert load_checkpoint(tmp_path / "missing.npz", "k1", LOG) is None


def test_keys_change_with_every_part_and_ignore_keyword_order():
    a = np.arange(4.0)
    assert checkpoint_key(n=1, start=array_digest(a)) == checkpoint_key(start=array_digest(a), n=1)
    assert checkpoint_key(n=1, start=array_digest(a)) != checkpoint_key(n=2, start=array_digest(a))
    assert array_digest(a) != array_digest(a + 1e-12)
    assert array_digest(a[::2]) == array_digest(np.ascontiguousarray(a[::2]))
