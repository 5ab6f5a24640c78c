"""Kept certificates: taken back only for the same packing, contact options and code."""

from __future__ import annotations

import numpy as np
import pandas as pd

from randmedia.describe import bond_order
from randmedia.describe.jamming_resolution import LADDER_COLUMNS, gap_ladder
from randmedia.kept_certificates import (certificate_key, keep_ladder, kept_certificate_path, kept_ladder,
                                         ladder_sources)

CONTACTS = {"gap_tolerance": 1e-9, "max_tolerance": 1e-4}


def _code(folder, text="def analyse(): pass\n"):
    module = folder / "randmedia" / "describe" / "jamming.py"
    module.parent.mkdir(parents=True, exist_ok=True)
    module.write_text(text)
    return [module]


def test_a_kept_ladder_is_taken_back_only_for_its_own_key(tmp_path):
    positions, box = bond_order.cubic_lattice("fcc", 2)
    code = _code(tmp_path / "checkout")
    key = certificate_key(positions, box, 1.0, CONTACTS, code)
    path = kept_certificate_path(tmp_path / "kept", "mrj", 4)
    assert path == tmp_path / "kept" / "mrj" / "sample4.certificate.json"
    assert kept_ladder(path, key) is None  # nothing kept yet
    # expanded fcc: two rungs without pairs, then certified at 1e-7 D (numpy scalars inside)
    ladder = gap_ladder(positions * (1 + 3e-8), box * (1 + 3e-8), **CONTACTS)
    keep_ladder(path, key, ladder)
    taken = kept_ladder(path, key)
    # the certificate file written from the kept ladder equals the one written from the computed
    assert pd.DataFrame(taken, columns=list(LADDER_COLUMNS)).to_csv() == \
        pd.DataFrame(ladder, columns=list(LADDER_COLUMNS)).to_csv()
    # the same modules in another checkout: the same key
    assert certificate_key(positions, box, 1.0, CONTACTS, _code(tmp_path / "elsewhere")) == key
    moved = positions.copy()
    moved[0, 0] += 1e-15
    for other in (certificate_key(moved, box, 1.0, CONTACTS, code),
                  certificate_key(positions, box * 1.5, 1.0, CONTACTS, code),
                  certificate_key(positions, box, 1.01, CONTACTS, code),
                  certificate_key(positions, box, 1.0, {**CONTACTS, "gap_tolerance": 1e-8}, code),
                  certificate_key(positions, box, 1.0, CONTACTS, _code(tmp_path / "edited", "# edited\n"))):
        assert other != key
        assert kept_ladder(path, other) is None


def test_an_unreadable_kept_certificate_is_not_taken_back_and_is_replaced(tmp_path):
    positions, box = bond_order.cubic_lattice("fcc", 2)
    key = certificate_key(positions, box, 1.0, CONTACTS, _code(tmp_path))
    path = kept_certificate_path(tmp_path / "kept", "mrj_large", 0)
    path.parent.mkdir(parents=True)
    path.write_text('{"key": {"packing_sha256": ')  # truncated
    assert kept_ladder(path, key) is None
    ladder = [{"gap_tolerance": 1e-9, "n_pairs": np.int64(3), "min_trace": np.float64(-1.5),
               "jammed": np.bool_(False), "isostatic_excess": None}]
    keep_ladder(path, key, ladder)
    assert kept_ladder(path, key) == [{"gap_tolerance": 1e-9, "n_pairs": 3, "min_trace": -1.5,
                                       "jammed": False, "isostatic_excess": None}]
    assert not list(path.parent.glob(".*partial*"))  # written atomically, nothing left over


def test_the_key_covers_the_code_of_the_test_and_not_the_jobs_plumbing():
    """ladder_sources: the jamming test's modules (and what they import), not the modules that
    read, log or keep (editing those cannot change a ladder, so it keeps the kept ladders)."""
    names = {"/".join(path.parts[-2:]) for path in ladder_sources()}
    assert {"describe/jamming_resolution.py", "describe/jamming.py", "generate/packing_lp.py",
            "randmedia/periodic.py"} <= names
    assert not names & {"randmedia/jobs.py", "randmedia/kept_certificates.py",
                        "randmedia/kept_configurations.py", "randmedia/workflow_sources.py"}


def test_an_uncertified_packing_is_kept_in_the_uncertified_folder(tmp_path):
    """A certificate is kept beside its packing: under keep_dir if certified, else under
    keep_dir + UNCERTIFIED_SUFFIX (randmedia.kept_configurations.kept_path)."""
    from randmedia.kept_configurations import kept_path

    keep_dir = tmp_path / "packings" / "mrj2016"
    for certified, folder in ((True, "mrj2016"), (False, "mrj2016_uncertified")):
        packing = kept_path(keep_dir, "mrj_large", 0, certified=certified)
        assert packing == tmp_path / "packings" / folder / "mrj_large" / "sample0.nc"
        assert kept_certificate_path(str(keep_dir), "mrj_large", 0, certified=certified) == \
            packing.with_name("sample0.certificate.json")
