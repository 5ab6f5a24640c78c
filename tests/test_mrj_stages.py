"""A packing system's stage constants over the shared ones (randmedia.mrj_stages)."""
from __future__ import annotations

from randmedia.mrj_stages import route_stage, system_stage

SECTION = {
    "route": "dilute",
    "dilute": {"max_lps": 5000, "translation": 0.01},
    "compression": {"growth_rate": 0.1, "stop_pressure": 1e4},
    "inflation": {"max_lps": 200},
    "polish": {"backend": "highs-ipm", "max_lps": 750},
    "mrj": {"n_particles": 2000},
    "mrj_large": {"n_particles": 10000, "polish": {"backend": "highs-hipo"}},
    "mrj_md": {"n_particles": 2000, "route": "compression", "compression": {"growth_rate": 1e-3}},
}


def test_a_systems_own_keys_go_over_the_shared_ones_key_by_key():
    assert system_stage(SECTION, "mrj", "polish") == {"backend": "highs-ipm", "max_lps": 750}
    assert system_stage(SECTION, "mrj_large", "polish") == {"backend": "highs-hipo", "max_lps": 750}
    assert system_stage(SECTION, "mrj_md", "compression") == {"growth_rate": 1e-3, "stop_pressure": 1e4}
    # a value that is no mapping is replaced
    assert system_stage(SECTION, "mrj", "route") == "dilute"
    assert system_stage(SECTION, "mrj_md", "route") == "compression"
    # the shared section is left as it was
    assert SECTION["polish"] == {"backend": "highs-ipm", "max_lps": 750}


def test_a_system_carries_only_the_stages_its_route_runs():
    assert route_stage(SECTION, "mrj", "dilute") == {"max_lps": 5000, "translation": 0.01}
    assert route_stage(SECTION, "mrj", "compression") == {} == route_stage(SECTION, "mrj", "inflation")
    assert route_stage(SECTION, "mrj_md", "dilute") == {}
    assert route_stage(SECTION, "mrj_md", "inflation") == {"max_lps": 200}
    assert route_stage(SECTION, "mrj_md", "compression")["growth_rate"] == 1e-3
