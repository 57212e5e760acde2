"""Choosing a reasoner: the embedded symbolic PPDR (default without an LLM), the LLM agents, or
the hybrid (the model reads the request, the symbolic PPDR carries it out).

Imports are lazy so that the CLI starts fast and a missing optional part names itself.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from typing import Literal

from assistantx.office import Office
from assistantx.ppdr.agents import Reasoner
from assistantx.settings import Settings

ReasonerKind = Literal["symbolic", "llm", "hybrid"]
ReasonerFactory = Callable[[], Reasoner]

# name → "module:factory builder"; a builder takes (office, settings) and returns a factory.
REASONERS: dict[str, str] = {
    "symbolic": "assistantx.symbolic:build_factory",
    "llm": "assistantx.ppdr.llm_agents:build_factory",
    "hybrid": "assistantx.ppdr.hybrid:build_factory",
}


def reasoner_factory(kind: str, office: Office, settings: Settings) -> ReasonerFactory:
    try:
        target = REASONERS[kind]
    except KeyError as exc:
        raise ValueError(f"unknown reasoner {kind!r}; choose from {', '.join(REASONERS)}") from exc
    module_name, _, attr = target.partition(":")
    builder = getattr(importlib.import_module(module_name), attr)
    factory: ReasonerFactory = builder(office, settings)
    return factory
