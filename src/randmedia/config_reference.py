"""``config/README.md``: every configuration key, generated from the JSON schemas.

The schema ``workflow/schemas/config.schema.yaml`` and the files it names by ``$ref`` (one per
paper section) are the single source of what a key means and which values it accepts; this
module walks them (:func:`randmedia.config.load_schema`, every ``$ref`` inlined) and writes one
Markdown table per configuration section: key path, type, schema default, allowed values,
value in ``config/config.yaml`` and description. A section with constraints between keys (the
checks of :data:`randmedia.config.CROSS_CHECKS`) says so under its heading.

Regenerate after changing a schema or ``config/config.yaml`` (from the repository root)::

    .venv/bin/python -m randmedia.config_reference

``tests/test_config_reference.py`` fails while ``config/README.md`` differs from what this
module generates.
"""

from __future__ import annotations

import argparse
import inspect
import re
import sys
from dataclasses import dataclass, field
from pathlib import Path

import yaml

from randmedia.config import CROSS_CHECKS, load_schema

__all__ = ["DEFAULT_CONFIG", "DEFAULT_OUTPUT", "DEFAULT_SCHEMA", "MAP_ENTRY", "REGENERATE",
           "config_reference", "write_config_reference"]

#: paths relative to the repository root (the working directory of the workflow)
DEFAULT_SCHEMA = Path("workflow/schemas/config.schema.yaml")
DEFAULT_CONFIG = Path("config/config.yaml")
DEFAULT_OUTPUT = Path("config/README.md")

#: the one-line command that regenerates config/README.md
REGENERATE = ".venv/bin/python -m randmedia.config_reference"

#: the path segment standing for any entry name of a section keyed by names
MAP_ENTRY = "<name>"

_MISSING = object()


@dataclass
class _Section:
    path: tuple[str, ...]
    schema: dict
    status: str
    rows: list[tuple[str, ...]] = field(default_factory=list)
    entries: dict | None = None  # config.yaml's entries of a section keyed by names


# --------------------------------------------------------------------------- formatting


def _literal(value) -> str:
    """A YAML-like literal (flow style) of a default or config value."""
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_literal(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{k}: {_literal(v)}" for k, v in value.items()) + "}"
    return str(value)


def _code(text: str) -> str:
    return f"`{text}`"


def _cell(text: str) -> str:
    """Text for a Markdown table cell: one line, pipes escaped."""
    return " ".join(str(text).split()).replace("|", "\\|")


def _type_name(value) -> str:
    return {bool: "boolean", int: "integer", float: "number", str: "string"}.get(type(value), "value")


def _type(schema: dict) -> str:
    """The type of a key as a user reads it (``list of number``, ``number or string``...)."""
    for alternative in ("oneOf", "anyOf"):
        if alternative in schema:
            names = []
            for option in schema[alternative]:
                name = _type(option)
                if name not in names:
                    names.append(name)
            return " or ".join(names)
    kind = schema.get("type")
    if isinstance(kind, list):
        return " or ".join(kind)
    if kind == "array":
        items = schema.get("items")
        return f"list of {_type(items)}" if isinstance(items, dict) else "list"
    if kind is not None:
        return kind
    if "const" in schema:
        return _type_name(schema["const"])
    if "enum" in schema:
        names = sorted({_type_name(v) for v in schema["enum"]})
        return " or ".join(names)
    return "any"


def _bounds(schema: dict) -> str:
    low = next(((op, schema[key]) for key, op in (("minimum", "<="), ("exclusiveMinimum", "<"))
                if key in schema), None)
    high = next(((op, schema[key]) for key, op in (("maximum", "<="), ("exclusiveMaximum", "<"))
                 if key in schema), None)
    if low and high:
        return f"{_literal(low[1])} {low[0]} x {high[0]} {_literal(high[1])}"
    if low:
        return f"x {'>=' if low[0] == '<=' else '>'} {_literal(low[1])}"
    if high:
        return f"x {high[0]} {_literal(high[1])}"
    return ""


def _allowed(schema: dict) -> str:
    """The values a key accepts: bounds, enumerations, patterns, list constraints."""
    for alternative in ("oneOf", "anyOf"):
        if alternative in schema:
            parts = []
            for option in schema[alternative]:
                text = _allowed(option)
                if "const" in option or "enum" in option:
                    parts.append(text)
                else:
                    parts.append(f"{_type(option)} {text}" if text else f"any {_type(option)}")
            return " or ".join(parts)
    parts = []
    if "const" in schema:
        parts.append(_code(_literal(schema["const"])))
    if "enum" in schema:
        parts.append("one of " + ", ".join(_code(_literal(v)) for v in schema["enum"]))
    bounds = _bounds(schema)
    if bounds:
        parts.append(bounds)
    if "multipleOf" in schema:
        parts.append(f"multiple of {_literal(schema['multipleOf'])}")
    if "pattern" in schema:
        parts.append(f"matches {_code(schema['pattern'])}")
    for key, text in (("minLength", "at least {} characters"), ("maxLength", "at most {} characters")):
        if key in schema:
            parts.append(text.format(schema[key]))
    if schema.get("type") == "array":
        items = schema.get("items")
        if isinstance(items, dict) and _allowed(items):
            parts.append(f"each item: {_allowed(items)}")
        if "minItems" in schema and "maxItems" in schema and schema["minItems"] == schema["maxItems"]:
            parts.append(f"exactly {schema['minItems']} items")
        else:
            if "minItems" in schema:
                parts.append(f"at least {schema['minItems']} item{'s' * (schema['minItems'] != 1)}")
            if "maxItems" in schema:
                parts.append(f"at most {schema['maxItems']} items")
        if schema.get("uniqueItems"):
            parts.append("no repeats")
    return "; ".join(parts)


def _default(schema: dict, required: bool) -> str:
    if "default" in schema:
        return _code(_literal(schema["default"]))
    return "required" if required else "—"


# --------------------------------------------------------------------------- walking


def _is_section(schema: dict) -> bool:
    return "properties" in schema or isinstance(schema.get("additionalProperties"), dict)


def _lookup(config, path):
    node = config
    for key in path:
        if not isinstance(node, dict) or key not in node:
            return _MISSING
        node = node[key]
    return node


def _status(schema: dict, required: bool) -> str:
    if required:
        return "Required section."
    if schema.get("default") == {}:
        return "Optional section: when absent, every key below takes its default."
    if "default" in schema:
        return f"Optional section (default {_code(_literal(schema['default']))})."
    return "Optional section (no default)."


def _walk(schema: dict, path: tuple[str, ...], required: bool, config, in_map: bool) -> list[_Section]:
    """Sections below and including ``schema`` (an object), depth first in schema order."""
    section = _Section(path, schema, _status(schema, required))
    below: list[_Section] = []
    if "properties" in schema:
        needed = set(schema.get("required", ()))
        for name, child in schema["properties"].items():
            child_path = path + (name,)
            if _is_section(child):
                below += _walk(child, child_path, name in needed, config, in_map)
                continue
            if in_map:
                value = "per entry"
            else:
                found = _lookup(config, child_path)
                value = ("(default)" if "default" in child else "—") if found is _MISSING \
                    else _code(_literal(found))
            section.rows.append((_code(".".join(child_path)), _type(child), _default(child, name in needed),
                                 _allowed(child) or "any", value, child.get("description", "")))
    entry = schema.get("additionalProperties")
    if isinstance(entry, dict) and "properties" not in schema:
        found = None if in_map else _lookup(config, path)
        section.entries = found if isinstance(found, dict) else {}
        entry_section = _walk(entry, path + (MAP_ENTRY,), True, config, True)
        entry_section[0].status = "One entry (every field below) per name."
        below = entry_section + below
    return [section] + below


# --------------------------------------------------------------------------- rendering


def _cross_checks(path: tuple[str, ...]) -> str:
    check = CROSS_CHECKS.get(".".join(path))
    if check is None:
        return ""
    doc = " ".join((inspect.getdoc(check) or "").split())
    return (f"Checked together with other keys before any job runs (`randmedia.config.{check.__name__}`): "
            f"{doc}")


def _table(header: list[str], rows: list[list[str]]) -> list[str]:
    """A Markdown table: the header line, its rule, one line per row of cells."""
    return (["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
            + ["| " + " | ".join(cells) + " |" for cells in rows])


def _map_lines(section: _Section) -> list[str]:
    schema = section.schema
    names = schema.get("propertyNames", {}).get("pattern")
    lines = ["Entries keyed by name"
             + (f" (names match {_code(names)})" if names else "")
             + (f", at least {schema['minProperties']}" if "minProperties" in schema else "")
             + f"; each entry's fields are the keys `{'.'.join(section.path)}.{MAP_ENTRY}.*` below."]
    entries = section.entries or {}
    if entries:
        fields = list(schema["additionalProperties"].get("properties", {}))
        rows = [[_code(name)] + [_code(_literal(entry[f])) if isinstance(entry, dict) and f in entry
                                 else "(default)" for f in fields]
                for name, entry in entries.items()]
        lines += ["", "Entries in config/config.yaml:", ""] + _table(["name"] + fields, rows)
    return lines


def _section_lines(section: _Section) -> list[str]:
    depth = len(section.path)
    title = ".".join(section.path) if section.path else "top level"
    lines = ["#" * (2 if depth <= 1 else 3) + f" `{title}`" if section.path else "## Top level", ""]
    description = " ".join(section.schema.get("description", "").split())
    text = " ".join(part for part in (section.status if section.path else "", description) if part)
    if text:
        lines += [text, ""]
    checks = _cross_checks(section.path)
    if checks:
        lines += [checks, ""]
    if section.entries is not None:
        lines += _map_lines(section) + [""]
    if section.rows:
        lines += _table(["key", "type", "default", "allowed", "config.yaml", "description"],
                        [[_cell(c) for c in row] for row in section.rows]) + [""]
    return lines


def _header(schema_path: Path, config_path: Path) -> list[str]:
    return [
        "# Configuration reference",
        "",
        f"Generated from `{schema_path.as_posix()}` (and the files it names by `$ref`) and "
        f"`{config_path.as_posix()}`; do not edit by hand. Regenerate from the repository root "
        f"after changing either: `{REGENERATE}`",
        "",
        "How a configuration is put together: `snakemake` reads `config/config.yaml` (the papers' own "
        "parameters); every `--configfile` given (e.g. `config/quick.yaml`, small parameters for the "
        "whole DAG in minutes) is merged over it, mappings key by key and every other value (lists "
        "included) replaced. The merged configuration is validated against the schema before any job "
        "runs: keys absent from it take the schema default, an unknown key or a value outside its range "
        "stops the run with a message naming the key, and the constraints between keys listed under "
        "their sections are checked next (`randmedia.config`).",
        "",
        "Columns: **key** — dotted path (`" + MAP_ENTRY + "` stands for any entry name of a section keyed "
        "by names); **default** — the schema default, filled in when the key is absent (`required`: "
        "every configuration must set it; `—`: optional without default); **allowed** — the values the "
        "schema accepts; **config.yaml** — the value in `config/config.yaml` (`(default)`: not set "
        "there, the default applies); lengths are in each paper's units (see the descriptions).",
        "",
    ]


def config_reference(schema_path: str | Path = DEFAULT_SCHEMA, config_path: str | Path = DEFAULT_CONFIG) -> str:
    """The Markdown text of ``config/README.md``.

    Parameters
    ----------
    schema_path : str or Path
        Root schema of the configuration (its ``$ref`` files are read from the same folder).
    config_path : str or Path
        The default configuration whose values fill the ``config.yaml`` column.

    Returns
    -------
    str
        Header, then one section per configuration object (heading, description, cross-key
        checks, table of its keys), in schema order.
    """
    schema_path, config_path = Path(schema_path), Path(config_path)
    schema = load_schema(schema_path)
    with open(config_path) as handle:
        config = yaml.safe_load(handle) or {}
    lines = _header(schema_path, config_path)
    index = []
    sections = _walk(schema, (), True, config, False)
    for section in sections[1:]:
        if len(section.path) == 1:
            index.append(f"[`{section.path[0]}`](#{_anchor(section.path[0])})")
    if index:
        lines += ["Sections: " + ", ".join(index) + ".", ""]
    for section in sections:
        lines += _section_lines(section)
    return "\n".join(lines).rstrip("\n") + "\n"


def _anchor(title: str) -> str:
    """GitHub's anchor of a heading whose text is ``title`` in backticks."""
    return re.sub(r"[^a-z0-9_ -]", "", title.lower()).replace(" ", "-")


def write_config_reference(output: str | Path = DEFAULT_OUTPUT, schema_path: str | Path = DEFAULT_SCHEMA,
                           config_path: str | Path = DEFAULT_CONFIG) -> Path:
    """Write :func:`config_reference` to ``output`` (atomically: a temporary file renamed)."""
    output = Path(output)
    text = config_reference(schema_path, config_path)
    partial = output.with_name(f".{output.name}.partial")
    partial.write_text(text, encoding="utf-8")
    partial.replace(output)
    return output


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m randmedia.config_reference", description=__doc__.split("\n")[0])
    parser.add_argument("--schema", type=Path, default=DEFAULT_SCHEMA)
    parser.add_argument("--config", type=Path, default=DEFAULT_CONFIG)
    parser.add_argument("--output", type=Path, default=DEFAULT_OUTPUT)
    parser.add_argument("--check", action="store_true",
                        help="write nothing; exit 1 if OUTPUT differs from the generated text")
    args = parser.parse_args(argv)
    if args.check:
        current = args.output.read_text(encoding="utf-8") if args.output.is_file() else ""
        if current != config_reference(args.schema, args.config):
            print(f"{args.output} is out of date; regenerate: {REGENERATE}", file=sys.stderr)
            return 1
        return 0
    print(write_config_reference(args.output, args.schema, args.config))
    return 0


if __name__ == "__main__":
    sys.exit(main())
