"""The Memory Unit: long-term belief graph, per-instruction short-term memory, one renderer.

Names are loaded from their modules on first use (PEP 562): importing one submodule, as
``office show`` does with ``memory.graph``, no longer loads the resolver and the language
tools (lemminflect, numpy) with it.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from assistantx.core.lazy import exports

if TYPE_CHECKING:
    from assistantx.core.dialogue import DialogueTurn
    from assistantx.memory.graph import LOCKER, Availability, LongTermMemory
    from assistantx.memory.render import render_long_term, render_memory, render_short_term
    from assistantx.memory.resolve import Resolver
    from assistantx.memory.short_term import EmbodiedState, IssuedCode, ShortTermMemory
    from assistantx.memory.updates import (
        AppliedUpdate,
        AvailabilityUpdate,
        ItemLocationUpdate,
        MemoryUpdate,
        OwnershipUpdate,
    )

_WHERE = {
    "DialogueTurn": "assistantx.core.dialogue",
    "LOCKER": "assistantx.memory.graph",
    "Availability": "assistantx.memory.graph",
    "LongTermMemory": "assistantx.memory.graph",
    "render_long_term": "assistantx.memory.render",
    "render_memory": "assistantx.memory.render",
    "render_short_term": "assistantx.memory.render",
    "Resolver": "assistantx.memory.resolve",
    "EmbodiedState": "assistantx.memory.short_term",
    "IssuedCode": "assistantx.memory.short_term",
    "ShortTermMemory": "assistantx.memory.short_term",
    "AppliedUpdate": "assistantx.memory.updates",
    "AvailabilityUpdate": "assistantx.memory.updates",
    "ItemLocationUpdate": "assistantx.memory.updates",
    "MemoryUpdate": "assistantx.memory.updates",
    "OwnershipUpdate": "assistantx.memory.updates",
}


__getattr__ = exports(__name__, _WHERE)


__all__ = [
    "LOCKER",
    "AppliedUpdate",
    "Availability",
    "AvailabilityUpdate",
    "DialogueTurn",
    "EmbodiedState",
    "IssuedCode",
    "ItemLocationUpdate",
    "LongTermMemory",
    "MemoryUpdate",
    "OwnershipUpdate",
    "Resolver",
    "ShortTermMemory",
    "render_long_term",
    "render_memory",
    "render_short_term",
]
