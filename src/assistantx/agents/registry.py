"""Choosing a reasoner: the embedded symbolic PPDR (default without an LLM), the LLM agents, or
the hybrid (the model reads the request, the symbolic PPDR carries it out).

Imports are lazy so that the CLI starts fast and a missing optional part names itself.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from typing import Literal

from assistantx.agents.base import Reasoner
from assistantx.core.office import Office
from assistantx.core.settings import Settings

ReasonerKind = Literal["symbolic", "llm", "hybrid"]
ReasonerFactory = Callable[[], Reasoner]

# name → "module:factory builder"; a builder takes (office, settings) and returns a factory.
REASONERS: dict[str, str] = {
    "symbolic": "assistantx.agents.symbolic:build_factory",
    "llm": "assistantx.agents.llm:build_factory",
    "hybrid": "assistantx.agents.hybrid:build_factory",
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
