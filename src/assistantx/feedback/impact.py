"""What one ended instruction did, in the figures the usage report counts.

``summarise`` reads the trace once: the kind of task, its outcome, how long it took, how many
times it asked a group chat for help, and the walking it saved. The record is stored with the
instruction (``FeedbackStore``) so the report never re-reads traces.
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, Field

from assistantx.core.actions import ForwardFile, Inform, Inquire, Move, SendQR, WaitInPlace
from assistantx.core.office import Office
from assistantx.core.task_schema import RecordKind
from assistantx.core.trace import Trace
from assistantx.feedback.walking import DistanceFn, WalkingEstimate, estimate_walking

# The report's kinds are the task schema's coarse record kinds (what the robot did), not its
# task kinds: one name each, so the two are never mistaken for each other.
RecordOutcome = Literal["done", "failed", "unachievable", "cancelled"]
OUTCOMES: tuple[RecordOutcome, ...] = ("done", "failed", "unachievable", "cancelled")


class InstructionRecord(BaseModel):
    instruction_id: str
    requester: str
    text: str
    kind: RecordKind = Field(
        description="delivery: the robot drove or handed something over; file: a file was "
        "forwarded; message: only messages, at least one to someone besides the requester; "
        "none: it reached nobody but the requester (e.g. 'asdf qwerty', a decline)"
    )
    outcome: RecordOutcome
    started_at: float
    ended_at: float
    steps: int
    actions: int
    group_requests: int = Field(description="questions put to group chats")
    walking: WalkingEstimate

    @property
    def duration_s(self) -> float:
        return max(0.0, self.ended_at - self.started_at)


def task_kind(trace: Trace) -> RecordKind:
    tried = [r.action for r in trace.actions() if not r.refused]
    if any(isinstance(a, Move | SendQR | WaitInPlace) for a in tried):
        return "delivery"
    if any(isinstance(a, ForwardFile) for a in tried):
        return "file"
    # A message task told or asked someone; answering only the requester (what happens to
    # "asdf qwerty" or a declined request) did nothing for anyone else.
    if any(isinstance(a, Inform | Inquire) and a.contact != trace.requester for a in tried):
        return "message"
    return "none"


def group_requests(office: Office, trace: Trace) -> int:
    groups = {g.id for g in office.groups}
    return sum(
        1
        for r in trace.actions()
        if isinstance(r.action, Inquire) and not r.refused and r.action.contact in groups
    )


def summarise(
    office: Office, trace: Trace, ended_at: float, distance: DistanceFn | None = None
) -> InstructionRecord:
    """The record of an ended instruction (``ended_at`` when the trace has no end time)."""
    end = trace.ended_at if trace.ended_at is not None else ended_at
    return InstructionRecord(
        instruction_id=trace.instruction_id,
        requester=trace.requester,
        text=trace.text,
        kind=task_kind(trace),
        outcome="cancelled" if trace.cancelled else trace.outcome or "cancelled",
        started_at=trace.started_at,
        ended_at=end,
        steps=len(trace.steps),
        actions=sum(1 for r in trace.actions() if not r.refused),
        group_requests=group_requests(office, trace),
        walking=estimate_walking(office, trace, distance),
    )
