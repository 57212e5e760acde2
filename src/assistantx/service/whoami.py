"""``GET /v1/me``: who the presented token is, so a client (the dashboard's "As" box) can act
as that person by default instead of guessing, and knows when to ask (the operator)."""

from __future__ import annotations

from fastapi import APIRouter
from pydantic import BaseModel, Field

from assistantx.service.deps import Caller, Runtime

router = APIRouter(prefix="/v1", tags=["auth"])


class Me(BaseModel):
    person: str | None = Field(description="the token's person id; null for the operator")
    name: str | None = Field(description="that person's display name")
    operator: bool = Field(description="true when the token has operator rights")


@router.get("/me", response_model=Me)
async def whoami(runtime: Runtime, caller: Caller) -> Me:
    if caller.person is None:
        return Me(person=None, name=None, operator=True)
    name = runtime.assistant.office.person(caller.person).name
    return Me(person=caller.person, name=name, operator=False)
