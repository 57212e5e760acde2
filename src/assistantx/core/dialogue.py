"""A turn of dialogue between the assistant and a person or group chat."""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, Field

from assistantx.core.ports.messenger import ChatRef


class DialogueTurn(BaseModel):
    time: float
    direction: Literal["out", "in"]
    chat: ChatRef
    person: str = Field(description="the author (in) or the recipient person/group id (out)")
    text: str
    question_id: str | None = Field(default=None, description="out: the question asked")
    in_reply_to: str | None = Field(default=None, description="in: the question it answers")
    files: list[str] = Field(default_factory=list, description="item ids of attached files")
    event_id: str | None = None
