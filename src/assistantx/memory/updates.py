"""Typed memory updates (defined in ``assistantx.core.updates``, below the Memory Unit)."""

from assistantx.core.updates import (
    AppliedUpdate,
    AvailabilityUpdate,
    ItemLocationUpdate,
    MemoryUpdate,
    OwnershipUpdate,
)

__all__ = [
    "AppliedUpdate",
    "AvailabilityUpdate",
    "ItemLocationUpdate",
    "MemoryUpdate",
    "OwnershipUpdate",
]
