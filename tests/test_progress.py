"""Progress lines of long per-sample loops (randmedia.progress) and of the mrj2016 describe jobs."""

import logging

import numpy as np

from mrj_helpers import rsa_packing
from randmedia.progress import Progress


def test_progress_logs_count_rate_and_eta(caplog):
    log = logging.getLogger("test_progress")
    progress = Progress(3, "pore sizes", log, unit="images")
    with caplog.at_level(logging.INFO, logger="test_progress"):
        for _ in range(3):
            progress.step()
    lines = [r.getMessage() for r in caplog.records]
    assert len(lines) == 3
    assert lines[0].startswith("pore sizes: 1/3 images,") and "images/s" in lines[0] and "ETA" in lines[0]
    assert lines[-1].endswith("ETA 0 s")
    Progress(2, "silent").step()  # without a logger: nothing, no error


def test_every_describe_kind_reports_each_sample(caplog):
    from randmedia.studies.mrj2016 import describe

    box = np.eye(3) * 5.0
    rng = np.random.default_rng(3)
    configs = [(rsa_packing(rng, box, 30), box, 1.0) for _ in range(2)]
    settings = {
        "correlation": {"descriptors": {"r_step": 0.1, "r_max": 1.0, "contact_r": 1e-4}},
        "spectral": {"spectral": {"k_max": 6.0, "bin_width": 0.2, "table_bin_width": 0.2, "nufft_eps": 1e-9}},
        "points": {"seed": 1, "pores": {"matrix_points": 2000, "bin_width": 0.01, "d_max": 2.0}},
        "windows": {"seed": 1, "windows": {"radius_step": 0.5, "fR_radii": [1.0], "phi_B": 0.8,
                                           "max_windows": 200}},
    }
    log = logging.getLogger("test_describe_progress")
    for kind, given in settings.items():
        caplog.clear()
        with caplog.at_level(logging.INFO, logger="test_describe_progress"):
            describe(kind, "mrj", configs, first=0, log=log, **given)
        lines = [r.getMessage() for r in caplog.records if r.getMessage().startswith(f"mrj {kind}: ")]
        assert [line.split(",")[0] for line in lines] == [f"mrj {kind}: 1/2 samples", f"mrj {kind}: 2/2 samples"], kind


def test_tj_eta_never_runs_past_max_lps(caplog):
    """Near jamming phi barely grows: the extrapolation to phi = 0.64 would give an ETA of
    10^5-10^6 s (the old defect); the total is capped at max_lps and the line says so."""
    from randmedia.generate.jammed import _report

    log = logging.getLogger("test_tj_eta")
    progress = Progress(None, "TJ", log, unit="LPs", start=120)
    phis = list(0.637 + 1e-9 * np.arange(120))  # growth 1e-9 per LP: 3e6 LPs to 0.64
    history = {"phi": phis, "trace": [-1e-9] * 120, "rescale": [1.0] * 120, "rows": [9000] * 120,
               "seconds": [8.0] * 120, "cpu": [8.0] * 120}
    with caplog.at_level(logging.INFO, logger="test_tj_eta"):
        _report(progress, history, 3, max_lps=500)
    line = caplog.records[-1].getMessage()
    assert line.startswith("TJ: 121/500 LPs,") and line.endswith("ETA = the bound max_lps = 500")
    # far from jamming the estimate is kept: 0.6119 -> 0.64 at 1e-4 per LP is 281 + 50 LPs more
    history["phi"] = list(0.60 + 1e-4 * np.arange(120))
    _report(progress, history, 3, max_lps=500)
    assert progress.total == 120 + 331
