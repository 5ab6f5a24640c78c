"""Config validation: shipped configs pass, bad ones name the offending key."""

import copy

import pytest
import yaml

from bad_configs import BAD_CONFIGS, bad_config, quick_config
from conftest import REPO, SCHEMA
from randmedia.config import ConfigError, validate_config


@pytest.mark.parametrize("name", ["config.yaml", "quick.yaml"])
def test_shipped_configs_are_valid(name):
    with open(REPO / "config" / name) as handle:
        config = yaml.safe_load(handle)
    validate_config(config, SCHEMA)


def test_defaults_are_filled_in():
    config = quick_config()
    del config["comparison"]
    del config["debye2020"]["overlapping_disks"]["compare_r_max_over_R"]
    validate_config(config, SCHEMA)
    assert config["comparison"]["k_sigma"] == 3.0
    assert config["debye2020"]["overlapping_disks"]["compare_r_max_over_R"] == 4.0


def test_at_least_fifteen_bad_configs():
    assert len(BAD_CONFIGS) >= 15


@pytest.mark.parametrize("case_id, mutation, key", BAD_CONFIGS, ids=[c[0] for c in BAD_CONFIGS])
def test_bad_config_rejected_naming_key(case_id, mutation, key):
    config = bad_config(mutation)
    with pytest.raises(ConfigError) as error:
        validate_config(config, SCHEMA)
    assert f"'{key}" in str(error.value)


def test_valid_config_is_not_mutated_beyond_defaults():
    config = quick_config()
    before = copy.deepcopy(config)
    validate_config(config, SCHEMA)
    assert config == before  # quick.yaml already states every key


def test_schema_includes_are_resolved_and_bad_includes_named(tmp_path):
    from randmedia.config import load_schema

    schema = load_schema(SCHEMA)
    assert "$include" not in str(schema)
    assert schema["properties"]["debye2020"]["properties"]["media"]["required"]
    (tmp_path / "top.yaml").write_text("properties:\n  a:\n    $include: missing.yaml\n")
    with pytest.raises(FileNotFoundError, match="missing.yaml"):
        load_schema(tmp_path / "top.yaml")
    (tmp_path / "loop.yaml").write_text("properties:\n  a:\n    $include: loop.yaml\n")
    with pytest.raises(ValueError, match="cycle"):
        load_schema(tmp_path / "loop.yaml")
