"""Typed updates to long-term memory, each carrying the evidence that justifies it."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field


class _Update(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)
    evidence: str = Field(min_length=1, max_length=1000, description="what was observed")


class AvailabilityUpdate(_Update):
    kind: Literal["availability"] = "availability"
    person: str
    available: bool | None = Field(description="None resets to unknown")


class OwnershipUpdate(_Update):
    kind: Literal["ownership"] = "ownership"
    person: str
    item_type: str
    owns: bool


class ItemLocationUpdate(_Update):
    kind: Literal["item_location"] = "item_location"
    item: str = Field(description="item id, e.g. stapler:zhang")
    holder: str = Field(description="a person id, 'locker', or a location id")


MemoryUpdate = Annotated[
    AvailabilityUpdate | OwnershipUpdate | ItemLocationUpdate, Field(discriminator="kind")
]


class AppliedUpdate(BaseModel):
    """An update as recorded in memory: when, from which instruction, what changed."""

    time: float
    instruction_id: str | None = None
    update: MemoryUpdate
    changed: bool = Field(description="False when memory already held this fact")
