"""randmedia.resumable: the one driver of checkpointed, logged, resumable runs (rules 1-4 of
its docstring), independent of any generator."""

import logging

import numpy as np
import pytest

from randmedia.progress import Progress
from randmedia.resumable import ResumableRun

LOG = logging.getLogger("test_resumable")


def _count_to(n, path, rng, stop_after=None, checkpoint_seconds=0.0):
    """A toy run: adds one random draw per step until ``n`` steps are done."""
    run = ResumableRun(path, "toy", LOG, rng=rng, checkpoint_seconds=checkpoint_seconds)
    state = run.resume(lambda data: {"k": int(data["k"]), "draws": list(data["draws"])})
    state = state or {"k": 0, "draws": []}

    def step():
        if stop_after is not None and state["k"] == stop_after:
            raise KeyboardInterrupt
        state["draws"].append(rng.random())
        state["k"] += 1

    run.loop(step, lambda: state["k"] >= n, lambda: {"k": state["k"], "draws": np.array(state["draws"])})
    run.finish()
    return state["draws"], run


def test_killed_run_resumes_bit_identically_and_removes_its_checkpoint(tmp_path):
    path = tmp_path / "toy.npz"
    whole, _ = _count_to(10, path, np.random.default_rng(3))
    assert not path.exists()
    with pytest.raises(KeyboardInterrupt):
        _count_to(10, path, np.random.default_rng(3), stop_after=6)
    assert path.exists()
    resumed, run = _count_to(10, path, np.random.default_rng(3))
    assert resumed == whole and not path.exists()
    assert run.seconds >= run.run_seconds and run.cpu_seconds >= run.run_cpu_seconds


def test_saves_only_when_due_and_keeps_the_final_state_on_request(tmp_path):
    path = tmp_path / "toy.npz"
    with pytest.raises(KeyboardInterrupt):  # an hour between saves: nothing saved yet
        _count_to(10, path, np.random.default_rng(3), stop_after=6, checkpoint_seconds=3600.0)
    assert not path.exists()
    run = ResumableRun(path, "toy", LOG)
    run.finish({"k": 10})
    assert ResumableRun(path, "toy", LOG).resume()["k"] == 10
    with pytest.raises(ValueError, match="reserved"):
        run.save({"elapsed": 1.0})
    ResumableRun(None, "toy", LOG).finish({"k": 1})  # without a checkpoint: nothing, no error


def test_an_incomplete_checkpoint_starts_afresh_with_the_random_state_untouched(tmp_path, caplog):
    path = tmp_path / "toy.npz"
    ResumableRun(path, "toy", LOG, rng=np.random.default_rng(99)).save({"other": 1})
    rng = np.random.default_rng(3)
    before = rng.bit_generator.state
    with caplog.at_level(logging.WARNING):
        assert ResumableRun(path, "toy", LOG, rng=rng).resume(lambda data: data["k"]) is None
    assert "is incomplete" in caplog.text
    assert rng.bit_generator.state == before


def test_progress_lines_at_most_every_so_often_unless_forced(caplog):
    progress = Progress(None, "toy", LOG, unit="steps", every=3600.0)
    with caplog.at_level(logging.INFO, logger="test_resumable"):
        for _ in range(5):
            progress.step(detail=lambda: 1 / 0)  # never built: no line is due
        progress.step(force=True, total=8, detail=lambda: "last")
        progress.total = None
        progress.step(force=True)
    lines = [r.getMessage() for r in caplog.records]
    assert len(lines) == 2
    assert lines[0].startswith("toy: 6/8 steps,") and lines[0].endswith("; last") and "ETA" in lines[0]
    assert lines[1].startswith("toy: 7 steps,") and "ETA" not in lines[1]
