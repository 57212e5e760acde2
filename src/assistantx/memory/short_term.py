"""Short-term memory of one instruction: dialogue, embodied state and the trace."""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, Field

from assistantx.core.dialogue import DialogueTurn
from assistantx.core.trace import Trace

CodeState = Literal["issued", "scanned", "used", "revoked"]


class IssuedCode(BaseModel):
    """A one-time code this instruction sent. ``scanned``: the lock accepted it (the door
    opened); ``used``: the door closed after it; ``revoked``: withdrawn at the lock (the
    hand-over timed out, or the instruction ended first)."""

    code_id: str
    person: str
    item: str
    purpose: str
    used: bool = False
    scanned: bool = False
    revoked: bool = False

    @property
    def state(self) -> CodeState:
        if self.used:
            return "used"
        if self.scanned:
            return "scanned"
        return "revoked" if self.revoked else "issued"

    @property
    def live(self) -> bool:
        """Still opens the locker (sent, neither scanned nor revoked)."""
        return not (self.used or self.scanned or self.revoked)


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
