"""config/README.md: generated from the schemas, up to date, and naming every configured key."""

import difflib
import re

import pytest
import yaml

from conftest import REPO
from randmedia.config_reference import MAP_ENTRY, REGENERATE, config_reference, main

README = REPO / "config" / "README.md"


def _documented_keys(text: str) -> list[str]:
    """The key paths of config/README.md: the first cell of every row of its key tables (those
    whose header starts with "| key |"; not the tables of named entries)."""
    keys, in_key_table = [], False
    for line in text.splitlines():
        if not line.startswith("|"):
            in_key_table = False
        elif line.startswith("| key |"):
            in_key_table = True
        elif in_key_table and (match := re.match(r"\| `([^`]+)` \| ", line)):
            keys.append(match.group(1))
    return keys


def _leaf_paths(node, path=()):
    """Dotted paths of every leaf (a value that is not a mapping; lists are leaves)."""
    if isinstance(node, dict) and node:
        for key, value in node.items():
            yield from _leaf_paths(value, path + (str(key),))
    else:
        yield ".".join(path)


def test_config_readme_is_up_to_date(monkeypatch):
    monkeypatch.chdir(REPO)  # the generator names the files relative to the repository root
    expected, current = config_reference(), README.read_text(encoding="utf-8")
    if current != expected:
        diff = "".join(list(difflib.unified_diff(current.splitlines(True), expected.splitlines(True),
                                                 "config/README.md", "generated"))[:40])
        pytest.fail(f"config/README.md is out of date (schema or config/config.yaml changed); "
                    f"regenerate with `{REGENERATE}`:\n{diff}")
    assert REGENERATE in current.split("\n## ")[0], "the header must say how to regenerate the file"
    assert main(["--check"]) == 0


@pytest.mark.parametrize("config_file", ["config.yaml", "quick.yaml"])
def test_every_configured_leaf_key_is_documented(config_file):
    keys = _documented_keys(README.read_text(encoding="utf-8"))
    assert len(keys) == len(set(keys)), "a key documented twice"
    patterns = [re.compile(re.escape(key).replace(re.escape(MAP_ENTRY), r"[^.]+") + r"\Z") for key in keys]
    config = yaml.safe_load((REPO / "config" / config_file).read_text(encoding="utf-8"))
    leaves = list(_leaf_paths(config))
    assert len(leaves) > 50
    missing = [leaf for leaf in leaves if not any(p.match(leaf) for p in patterns)]
    assert not missing, f"config/{config_file} keys absent from config/README.md: {missing}"


def test_generator_renders_types_defaults_ranges_and_named_entries(tmp_path):
    (tmp_path / "part.schema.yaml").write_text(yaml.safe_dump({
        "type": "object", "default": {}, "description": "A part.",
        "properties": {"w": {"type": "number", "exclusiveMinimum": 0, "maximum": 1, "default": 0.5,
                             "description": "weight | share"}}}))
    (tmp_path / "root.schema.yaml").write_text(yaml.safe_dump({
        "type": "object", "required": ["n", "named"],
        "properties": {
            "n": {"type": "integer", "minimum": 2, "description": "count"},
            "mode": {"enum": ["a", "b"], "default": "a"},
            "sigma": {"oneOf": [{"type": "number", "minimum": 0}, {"const": "tuned"}], "default": "tuned"},
            "xs": {"type": "array", "minItems": 1, "uniqueItems": True,
                   "items": {"type": "number", "exclusiveMinimum": 0, "exclusiveMaximum": 1}},
            "part": {"$ref": "part.schema.yaml"},
            "named": {"type": "object", "propertyNames": {"pattern": "^[a-z]+$"},
                      "additionalProperties": {"type": "object", "required": ["R"],
                                               "properties": {"R": {"type": "number"}}}}}}, sort_keys=False))
    (tmp_path / "config.yaml").write_text("n: 3\nxs: [0.5]\nnamed: {one: {R: 1.5}}\n")
    text = config_reference(tmp_path / "root.schema.yaml", tmp_path / "config.yaml")
    rows = {cells[0].strip("` "): [c.strip() for c in cells[1:]]
            for cells in (line.strip("|").split(" | ") for line in text.splitlines()
                          if line.startswith("| `") and "|---" not in line)}
    assert rows["n"] == ["integer", "required", "x >= 2", "`3`", "count"]
    assert rows["mode"][:4] == ["string", "`a`", "one of `a`, `b`", "(default)"]
    assert rows["sigma"][:4] == ["number or string", "`tuned`", "number x >= 0 or `tuned`", "(default)"]
    assert rows["xs"][:4] == ["list of number", "—", "each item: 0 < x < 1; at least 1 item; no repeats",
                              "`[0.5]`"]
    assert rows["part.w"][:4] == ["number", "`0.5`", "0 < x <= 1", "(default)"]
    assert "weight \\| share" in text  # a pipe in a description does not break the table
    assert rows[f"named.{MAP_ENTRY}.R"][:4] == ["number", "required", "any", "per entry"]
    assert "| `one` | `1.5` |" in text  # the entries config.yaml defines
    assert "### `part`" not in text and "## `part`" in text
    assert "Optional section: when absent, every key below takes its default. A part." in text
