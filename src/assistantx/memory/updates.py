"""Typed memory updates (defined in ``assistantx.updates``, below the Memory Unit)."""

from assistantx.updates import (
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
