"""Defaults in one place (issue 27 §1): the JSON schema's ``default``, ``config/config.yaml``
(the papers' own parameters, authoritative) and the package's dataclass defaults agree key by key.

* Every leaf of config/config.yaml whose schema has a default (the leaf's own, or a mapping
  default of a section above it) has that value there; a schema shared by two sections that
  set a key differently therefore has no default for it.
* Every leaf config/config.yaml sets is required by its schema or defaulted there, so that
  deleting it from the config either stops the run or gives the same study.
* Every dataclass built from a config section (``Cls(**section)``) defaults each field to the
  value of its key in every section it is built from, or has no default for it.
"""

from __future__ import annotations

import dataclasses

import pytest
import yaml

from conftest import REPO, SCHEMA
from randmedia.config import load_schema
from randmedia.generate.hard_particles.settings import MCSettings
from randmedia.generate.inflation import InflationParameters
from randmedia.generate.lubachevsky_stillinger import LSParameters
from randmedia.generate.mrj import DiluteTJ, MRJProtocol
from randmedia.generate.sphere_mc import MCSchedule, Potential
from randmedia.generate.yeong_torquato import AnnealingSchedule

CONFIG = REPO / "config" / "config.yaml"

_ABSENT = object()


def _paper_config() -> dict:
    with open(CONFIG) as handle:
        return yaml.safe_load(handle)


def _child(schema: dict, key: str) -> dict | None:
    """The schema of ``key`` inside the object schema ``schema`` (a named property, else the
    schema of every entry of a section keyed by names), None if the schema names no such key."""
    if key in schema.get("properties", {}):
        return schema["properties"][key]
    entry = schema.get("additionalProperties")
    return entry if isinstance(entry, dict) else None


def _dotted(path) -> str:
    return ".".join(path)


def default_disagreements(schema: dict, value, path: tuple[str, ...] = ()) -> list[str]:
    """One line per leaf of ``value`` (a config) whose schema default differs from it.

    A default of a mapping (a section's ``default: {key: value, ...}``) is what the section
    becomes when it is absent; each of its leaves is compared with the config's leaf."""
    return list(dict.fromkeys(_disagreements(schema, value, path)))


def _disagreements(schema: dict, value, path: tuple[str, ...]) -> list[str]:
    problems = []
    if "default" in schema:
        problems += _compare_default(schema["default"], value, path)
    if isinstance(value, dict):
        for key, item in value.items():
            child = _child(schema, key)
            if child is not None:
                problems += _disagreements(child, item, path + (key,))
    return problems


def _compare_default(default, value, path) -> list[str]:
    if isinstance(default, dict) and isinstance(value, dict):
        problems = []
        for key, item in default.items():
            problems += _compare_default(item, value.get(key, _ABSENT), path + (key,))
        return problems
    if value is _ABSENT:
        return []  # the config leaves it out: the default applies, nothing disagrees
    if default != value or isinstance(default, bool) != isinstance(value, bool):
        return [f"{_dotted(path)}: schema default {default!r}, config.yaml {value!r}"]
    return []


def unguarded_leaves(schema: dict, value, path: tuple[str, ...] = (), required: bool = True) -> list[str]:
    """Leaves of ``value`` neither required by their schema nor defaulted there (deleting one
    from the config would silently leave the key unset)."""
    if isinstance(value, dict) and ("properties" in schema or isinstance(schema.get("additionalProperties"), dict)):
        needed = set(schema.get("required", ()))
        problems = []
        for key, item in value.items():
            child = _child(schema, key)
            if child is None:
                problems.append(f"{_dotted(path + (key,))}: not in the schema")
                continue
            named = key in schema.get("properties", {})
            problems += unguarded_leaves(child, item, path + (key,), key in needed or not named)
        return problems
    if "default" not in schema and not required:
        return [f"{_dotted(path)}: optional without a default"]
    return []


def test_the_walk_finds_a_planted_disagreement():
    schema = {"type": "object", "properties": {
        "a": {"type": "number", "default": 1.0},
        "b": {"type": "object", "default": {"c": 2}, "properties": {"c": {"type": "integer", "default": 2}}},
        "m": {"type": "object", "additionalProperties": {"type": "object", "properties": {
            "k": {"type": "number", "default": 1.0}}}},
        "o": {"type": "number"}}}
    config = {"a": 1.0, "b": {"c": 3}, "m": {"x": {"k": 1.0}, "y": {"k": 4.0}}, "o": 5}
    assert default_disagreements(schema, config) == [
        "b.c: schema default 2, config.yaml 3", "m.y.k: schema default 1.0, config.yaml 4.0"]
    assert unguarded_leaves(schema, config) == ["o: optional without a default"]


def test_schema_defaults_equal_the_paper_config():
    """Deleting a key from config/config.yaml gives the same study (issue 27 §1)."""
    problems = default_disagreements(load_schema(SCHEMA), _paper_config())
    assert not problems, "schema defaults that differ from config/config.yaml:\n  " + "\n  ".join(problems)


def test_every_paper_key_is_required_or_defaulted():
    problems = unguarded_leaves(load_schema(SCHEMA), _paper_config())
    assert not problems, "\n  ".join(["config/config.yaml keys the schema neither requires nor defaults:"]
                                     + problems)


# --------------------------------------------------------------------------- dataclasses

#: dataclass -> the config sections it is built from (``Cls(**section)``; ``*``: every entry
#: of a section keyed by names). A field whose key is in none of them is not a config key.
BUILT_FROM = {
    MCSettings: ["debye2020.hard_disks.mc", "mrj2016.equilibrium.mc"],
    AnnealingSchedule: ["debye2020.media.schedule", "debye3d.media.schedule"],
    LSParameters: ["mrj2016.mrj.compression"],
    InflationParameters: ["mrj2016.mrj.inflation"],
    DiluteTJ: ["mrj2016.mrj.dilute"],
    MCSchedule: ["sphere2019.fluids", "sphere2019.fluids.runs.*"],
    Potential: ["sphere2019.fluids.systems.*"],
}


def _sections(config: dict, dotted: str) -> list[tuple[str, dict]]:
    """(path, section) for a dotted path; ``*`` stands for every entry name."""
    found = [("", config)]
    for key in dotted.split("."):
        step = []
        for path, node in found:
            names = list(node) if key == "*" else [key]
            step += [(f"{path}.{name}".lstrip("."), node[name]) for name in names]
        found = step
    return found


def _default(field: dataclasses.Field):
    if field.default is not dataclasses.MISSING:
        return field.default
    if field.default_factory is not dataclasses.MISSING:
        return field.default_factory()
    return _ABSENT


def dataclass_disagreements(instance_or_class, sections: list[tuple[str, dict]]) -> list[str]:
    """One line per field whose default (or, for an instance, value) differs from its key in
    one of ``sections``; fields without a default are fine."""
    problems = []
    for field in dataclasses.fields(instance_or_class):
        if isinstance(instance_or_class, type):
            value = _default(field)
        else:
            value = getattr(instance_or_class, field.name)
        if value is _ABSENT:
            continue
        for path, section in sections:
            if field.name in section and section[field.name] != value:
                problems.append(f"{getattr(instance_or_class, '__name__', type(instance_or_class).__name__)}."
                                f"{field.name} = {value!r}, config.yaml {path}.{field.name} = "
                                f"{section[field.name]!r}")
    return problems


@pytest.mark.parametrize("cls", list(BUILT_FROM), ids=[c.__name__ for c in BUILT_FROM])
def test_dataclass_defaults_equal_the_paper_config(cls):
    config = _paper_config()
    sections = [found for dotted in BUILT_FROM[cls] for found in _sections(config, dotted)]
    fields = {f.name for f in dataclasses.fields(cls)}
    assert any(fields & set(section) for _, section in sections), f"{cls.__name__}: no config key"
    problems = dataclass_disagreements(cls, sections)
    assert not problems, "\n  ".join([f"{cls.__name__} defaults that differ from config/config.yaml:"]
                                     + problems)


def test_mrj_protocol_defaults_are_the_paper_config():
    """MRJProtocol() is the protocol of mrj2016.mrj: its stages' constants (compression,
    inflation, polish, dilute) and route equal config/config.yaml's."""
    config = _paper_config()["mrj2016"]["mrj"]
    protocol = MRJProtocol()
    problems = []
    for stage in ("compression", "inflation", "polish", "dilute"):
        problems += dataclass_disagreements(getattr(protocol, stage), [(f"mrj2016.mrj.{stage}", config[stage])])
    if protocol.route != config["route"]:
        problems.append(f"MRJProtocol.route = {protocol.route!r}, config.yaml {config['route']!r}")
    assert not problems, "\n  ".join(["MRJProtocol() differs from config/config.yaml:"] + problems)


# TJParameters keeps generic Torquato-Jiao defaults (its tests make packings from RSA starts
# with them); the polish of the paper config is MRJProtocol().polish, compared above.
