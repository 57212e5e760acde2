"""``GET /v1/offices``: the offices a token may use, which replica runs each, and its health;
``GET /v1/replicas`` (the operator): the replicas sharing the database, their health and the
offices each runs (empty without a database: one process, no replicas)."""

from __future__ import annotations

import asyncio
import dataclasses

from fastapi import APIRouter, Request
from pydantic import BaseModel, Field

from assistantx.service.offices.directory import Offices
from assistantx.service.offices.routing import office_of

router = APIRouter(prefix="/v1", tags=["offices"])


class OfficeOut(BaseModel):
    id: str = Field(description="the office's id in URLs: /v1/offices/{id}/...")
    name: str
    replica: str | None = Field(description="the replica running it; null: none at present")
    here: bool = Field(description="whether the replica answering runs it")
    status: str = Field(description="ready, starting, elsewhere (another replica) or unassigned")


@router.get("/offices", response_model=list[OfficeOut])
async def list_offices(request: Request) -> list[OfficeOut]:
    """Every office the caller's token holds for (the deployment operator: all of them)."""
    offices: Offices = request.app.state.offices
    slots = offices.offices_of(request.headers.get("authorization"))
    return [OfficeOut(**entry) for entry in offices.listing(slots)]


class ReplicaOut(BaseModel):
    id: str = Field(description="the replica's name (ASSISTANTX_REPLICA_ID, else generated)")
    here: bool = Field(description="whether it is the replica answering")
    up: bool = Field(description="its heartbeat (one office: its lease) is live")
    heartbeat_age_s: float | None = Field(
        description="seconds since its last heartbeat, as this replica last read the leases"
        " (several offices; null otherwise)"
    )
    offices: list[str] = Field(description="the ids of the offices it runs")


@router.get("/replicas", response_model=list[ReplicaOut])
async def list_replicas(request: Request) -> list[ReplicaOut]:
    """Which replica runs which office, and each replica's health (operator only)."""
    offices: Offices = request.app.state.offices
    offices.authenticate(
        office_of(request.scope), request.headers.get("authorization")
    ).require_operator()
    if offices.leases is None:
        return []
    views = await asyncio.to_thread(offices.replicas)  # reads the shared leases
    return [ReplicaOut(**dataclasses.asdict(view)) for view in views]
