"""Short-term memory of one instruction: dialogue, embodied state and the trace."""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, Field

from assistantx.dialogue import DialogueTurn
from assistantx.trace import Trace


class IssuedCode(BaseModel):
    code_id: str
    person: str
    item: str
    purpose: str
    used: bool = False


class EmbodiedState(BaseModel):
    robot_place: str | None = None
    locker_contents: list[str] = Field(default_factory=list)
    door: Literal["open", "closed"] = "closed"
    codes: list[IssuedCode] = Field(default_factory=list)


class ShortTermMemory(BaseModel):
    instruction_id: str
    requester: str
    text: str
    dialogue: list[DialogueTurn] = Field(default_factory=list)
    embodied: EmbodiedState = Field(default_factory=EmbodiedState)
    files_received: dict[str, list[str]] = Field(
        default_factory=dict, description="person id → file item ids received from them"
    )
    trace: Trace

    def replies_to(self, question_id: str) -> list[DialogueTurn]:
        return [t for t in self.dialogue if t.direction == "in" and t.in_reply_to == question_id]
