"""How a packing system of config section ``mrj2016.mrj`` reads its stage constants: the one
home of the merge that the workflow (the packing rules' params, common.smk) and the tests of the
kept packings share.

The section holds the shared stages (``dilute``, ``compression``, ``inflation``, ``polish``,
``contacts``, ``route``) and one subsection per system (``mrj``, ``mrj_large``, ``mrj_md``) that may
override them: mrj_large has its own ``polish`` and ``contacts`` keys, mrj_md its own ``route`` and
``compression`` (workflow/schemas/mrj2016.jammed.schema.yaml).
"""
from __future__ import annotations

from randmedia.config import MRJ_ROUTE_STAGES


def system_stage(section: dict, system: str, key: str):
    """``key`` of ``section`` as ``system``'s packings use it: the shared value with the
    system's own keys of that name over it (a mapping merged key by key, anything else
    replaced)."""
    own = section[system].get(key)
    if isinstance(own, dict):
        return {**section[key], **own}
    return section[key] if own is None else own


def route_stage(section: dict, system: str, key: str) -> dict:
    """``system``'s ``key`` stage (:func:`system_stage`) if its route runs that stage
    (:data:`randmedia.config.MRJ_ROUTE_STAGES`: a packing's params hold only these), {} otherwise."""
    route = system_stage(section, system, "route")
    return system_stage(section, system, key) if key in MRJ_ROUTE_STAGES[route] else {}
