"""``GET /v1/offices``: the offices a token may use, which replica runs each, and its health."""

from __future__ import annotations

from fastapi import APIRouter, Request
from pydantic import BaseModel, Field

from assistantx.service.offices.directory import Offices

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
