"""Config validation: shipped configs pass, bad ones name the offending key."""

import copy

import pytest

from bad_configs import BAD_CONFIGS, bad_config
from conftest import REPO, SCHEMA, quick_config
from randmedia.config import ConfigError, load_config, merge_config, validate_config


def test_shipped_configs_are_valid():
    validate_config(load_config(REPO / "config" / "config.yaml"), SCHEMA)
    validate_config(quick_config(), SCHEMA)


def test_quick_config_holds_only_the_keys_it_changes():
    """config/quick.yaml is an overlay: every value it states differs from the paper config's
    (a key repeated with the paper's value would silently stop following config.yaml)."""
    paper = load_config(REPO / "config" / "config.yaml")
    repeated = []

    def walk(base, overlay, path):
        for key, value in overlay.items():
            assert key in base, f"quick.yaml key {'.'.join(path + (key,))} is not in config.yaml"
            if isinstance(value, dict):
                walk(base[key], value, path + (key,))
            elif value == base[key]:
                repeated.append(".".join(path + (key,)))

    walk(paper, load_config(REPO / "config" / "quick.yaml"), ())
    assert not repeated, repeated


def test_merge_follows_snakemake_configfile_semantics():
    base = {"a": {"b": 1, "c": [1, 2], "d": {"e": 3}}, "f": 4}
    merged = merge_config(base, {"a": {"c": [5], "d": {"g": 6}}, "h": 7})
    assert merged == {"a": {"b": 1, "c": [5], "d": {"e": 3, "g": 6}}, "f": 4, "h": 7}
    assert base == {"a": {"b": 1, "c": [1, 2], "d": {"e": 3}}, "f": 4}


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
    assert config == before  # config.yaml (under the quick overlay) states every key


def test_schema_file_refs_are_resolved_and_bad_refs_named(tmp_path):
    """Each paper's section is a standard JSON-Schema $ref to its file; validation resolves it
    (defaults inside referenced files are filled in), a missing file is named before any
    validation, and the inlined reading copy refuses a cycle."""
    from randmedia.config import load_schema, schema_registry

    schema = load_schema(SCHEMA)
    assert "$ref" not in str(schema) and "$include" not in str(schema)
    assert schema["properties"]["debye2020"]["properties"]["media"]["required"]
    root, registry = schema_registry(SCHEMA)
    assert root["properties"]["debye2020"] == {"$ref": "debye2020.schema.yaml"}
    config = quick_config()
    del config["mrj2016"]["mrj"]["polish"]  # a section of a referenced file, with defaults
    validate_config(config, SCHEMA)
    assert config["mrj2016"]["mrj"]["polish"]["tolerance"] > 0
    (tmp_path / "top.yaml").write_text("properties:\n  a:\n    $ref: missing.yaml\n")
    with pytest.raises(FileNotFoundError, match="missing.yaml"):
        schema_registry(tmp_path / "top.yaml")
    (tmp_path / "loop.yaml").write_text("properties:\n  a:\n    $ref: loop.yaml\n")
    with pytest.raises(ValueError, match="cycle"):
        load_schema(tmp_path / "loop.yaml")
