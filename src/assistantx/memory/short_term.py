"""Short-term memory of one instruction: dialogue, embodied state and the trace."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Literal

from pydantic import BaseModel, Field

from assistantx.core.dialogue import DialogueTurn
from assistantx.core.trace import Trace

CodeState = Literal["issued", "scanned", "used", "revoked"]
# What the lock reported of codes (code id → "scanned"/"used"), possibly ahead of an
# instruction that has not looked at the locker since: ``Locker.code_states``.
LockReports = Mapping[str, Literal["scanned", "used"]]


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
        """The instruction's own view of the code."""
        if self.used:
            return "used"
        if self.scanned:
            return "scanned"
        return "revoked" if self.revoked else "issued"

    def current_state(self, reported: LockReports | None = None) -> CodeState:
        """The instruction's view brought up to date by what the lock reported since (a scan
        shows at once, not only when the instruction next looks at the locker)."""
        if self.state != "issued" or reported is None:
            return self.state
        return reported.get(self.code_id, "issued")

    def unused(self, reported: LockReports | None = None) -> bool:
        """The one rule for "this code is still unused": it was sent and still opens the
        locker, i.e. neither scanned, used nor revoked. A scanned code is spent at the lock
        (a second scan is refused as a replay), so its holder no longer holds a usable code;
        an unused one must not be sent again and is what is revoked when it lost its purpose.
        ``reported``: the lock's reports, for callers that can see the lock."""
        return self.current_state(reported) == "issued"


class EmbodiedState(BaseModel):
    robot_place: str | None = None
    locker_contents: list[str] = Field(default_factory=list)
    door: Literal["open", "closed"] = "closed"
    codes: list[IssuedCode] = Field(default_factory=list)

    def unused_code(
        self, person: str, item: str, purpose: str, reported: LockReports | None = None
    ) -> IssuedCode | None:
        """The unused code ``person`` already holds for ``purpose`` on ``item``, if any."""
        for code in self.codes:
            if (code.person, code.item, code.purpose) == (person, item, purpose):
                if code.unused(reported):
                    return code
        return None


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

    @classmethod
    def begin(
        cls,
        instruction_id: str,
        requester: str,
        text: str,
        *,
        reasoner: str,
        started_at: float,
        trace_text: str | None = None,
    ) -> ShortTermMemory:
        """The memory of an instruction that starts now, with its empty trace (whose text is
        ``trace_text`` where the trace names the work otherwise than the request does)."""
        trace = Trace(
            instruction_id=instruction_id,
            requester=requester,
            text=text if trace_text is None else trace_text,
            reasoner=reasoner,
            started_at=started_at,
        )
        return cls(instruction_id=instruction_id, requester=requester, text=text, trace=trace)

    def replies_to(self, question_id: str) -> list[DialogueTurn]:
        return [t for t in self.dialogue if t.direction == "in" and t.in_reply_to == question_id]

    def requester_answers(self) -> list[str]:
        """The requester's first answer to each clarifying question asked of them, in order."""
        answers: list[str] = []
        for turn in self.dialogue:
            if turn.direction == "out" and turn.question_id and turn.person == self.requester:
                replies = [
                    t.text for t in self.replies_to(turn.question_id) if t.person == self.requester
                ]
                if replies:
                    answers.append(replies[0])
        return answers
