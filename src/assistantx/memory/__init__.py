"""The Memory Unit: long-term belief graph, per-instruction short-term memory, one renderer."""

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
