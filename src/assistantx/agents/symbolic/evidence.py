"""What happened so far in one instruction, read back from its short-term memory.

Everything the planner and the decision need (who was asked what, who answered how, which
waits timed out, who was told, which codes were used, which hand-overs failed) is derived
from the dialogue, the embodied state and the trace, never kept aside. A resumed instruction
therefore continues where it stopped.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from assistantx.agents.symbolic.answers import Stance, stance
from assistantx.core.actions import ForwardFile, Inform, Inquire, Wait, WaitInPlace
from assistantx.core.dialogue import DialogueTurn
from assistantx.core.office import Office
from assistantx.memory.short_term import IssuedCode, ShortTermMemory

# A wait_in_place that ended this much before its timeout was cut short by a message.
_INTERRUPTED_MARGIN_S = 1.0


@dataclass(frozen=True)
class Question:
    question_id: str
    contact: str  # person or group id
    group: bool
    text: str
    time: float


@dataclass(frozen=True)
class HandoverAttempt:
    person: str
    place: str | None
    ok: bool
    interrupted: bool  # ended early by someone else's message, not by the person
    started_at: float
    ended_at: float
    complaint: str | None  # what the person wrote instead of coming


@dataclass
class Evidence:
    requester: str
    robot_place: str | None
    instruction_id: str = ""  # whose evidence: memory's changes by others are told apart
    locker: list[str] = field(default_factory=list)  # item ids in the robot's locker now
    questions: list[Question] = field(default_factory=list)
    replies: dict[str, list[DialogueTurn]] = field(default_factory=dict)  # question id → turns
    timeouts: list[float] = field(default_factory=list)  # start times of timed-out waits
    told: set[str] = field(default_factory=set)  # people sent a non-QR message
    codes: list[IssuedCode] = field(default_factory=list)
    files_received: dict[str, list[str]] = field(default_factory=dict)
    forwarded: set[tuple[str, str, str]] = field(default_factory=set)  # source, target, file
    handovers: list[HandoverAttempt] = field(default_factory=list)
    inbound: list[DialogueTurn] = field(default_factory=list)
    outbound: list[DialogueTurn] = field(default_factory=list)
    # what the requester stated in the request (the frame's hints): person → their words
    said_away: dict[str, str] = field(default_factory=dict)
    # (person, item type) → the condition the requester stated ("broken")
    said_unusable: dict[tuple[str, str], str] = field(default_factory=dict)

    # -- questions -----------------------------------------------------------------------
    def asked(self, contact: str, text: str) -> Question | None:
        """The question with exactly this text sent to ``contact`` (the latest)."""
        found = [q for q in self.questions if q.contact == contact and q.text == text]
        return found[-1] if found else None

    def answers(self, question: Question) -> list[DialogueTurn]:
        return self.replies.get(question.question_id, [])

    def stance_of(self, question: Question, person: str) -> Stance | None:
        """The latest answer of ``person`` to ``question`` (None: no answer yet)."""
        mine = [t for t in self.answers(question) if t.person == person]
        return stance(mine[-1].text) if mine else None

    def expired(self, question: Question) -> bool:
        """A wait after the question timed out: whoever did not answer by then is silent."""
        return any(t >= question.time for t in self.timeouts)

    def pending(self, question: Question) -> bool:
        return not self.answers(question) and not self.expired(question)

    # -- hand-overs ----------------------------------------------------------------------
    def used(self, item: str, purpose: str) -> bool:
        return any(c.used and c.item == item and c.purpose == purpose for c in self.codes)

    def holds_code(self, person: str, item: str, purpose: str) -> bool:
        return any(
            (c.person, c.item, c.purpose) == (person, item, purpose) and c.unused()
            for c in self.codes
        )

    def failed_handover(self, person: str) -> HandoverAttempt | None:
        """The person's last hand-over attempt, when it failed for a reason of theirs."""
        mine = [h for h in self.handovers if h.person == person]
        if not mine or mine[-1].ok or mine[-1].interrupted:
            return None
        return mine[-1]

    def interrupted_handover(self, person: str) -> bool:
        mine = [h for h in self.handovers if h.person == person]
        return bool(mine) and mine[-1].interrupted


def gather(stm: ShortTermMemory, office: Office) -> Evidence:
    ev = Evidence(
        requester=stm.requester,
        instruction_id=stm.instruction_id,
        robot_place=stm.embodied.robot_place,
        locker=list(stm.embodied.locker_contents),
        codes=list(stm.embodied.codes),
        files_received={k: list(v) for k, v in stm.files_received.items()},
    )
    ev.told.add(stm.requester)
    groups = {g.id: g.members for g in office.groups}
    for turn in stm.dialogue:
        if turn.direction == "out":
            ev.outbound.append(turn)
        if turn.direction == "out" and turn.question_id:
            ev.questions.append(
                Question(
                    turn.question_id, turn.person, turn.chat.kind == "group", turn.text, turn.time
                )
            )
        elif turn.direction == "in":
            ev.inbound.append(turn)
            if turn.in_reply_to:
                ev.replies.setdefault(turn.in_reply_to, []).append(turn)
    for result in stm.trace.actions():
        action = result.action
        if result.refused:
            continue
        if isinstance(action, Inform | Inquire) and result.ok:
            ev.told.update(groups.get(action.contact, (action.contact,)))
        elif isinstance(action, ForwardFile) and result.ok:
            ev.told.update(groups.get(action.target, (action.target,)))
            ev.forwarded.add(
                (action.source, action.target, action.file or office.file_of(action.source))
            )
        elif isinstance(action, Wait) and result.data.get("timed_out"):
            ev.timeouts.append(result.started_at)
        elif isinstance(action, WaitInPlace):
            ev.handovers.append(
                _attempt(stm, action, result.ok, result.started_at, result.ended_at, result.data)
            )
    return ev


def _attempt(
    stm: ShortTermMemory,
    action: WaitInPlace,
    ok: bool,
    started: float,
    ended: float,
    data: dict[str, object],
) -> HandoverAttempt:
    complaint = next(
        (
            t.text
            for t in stm.dialogue
            if t.direction == "in" and t.person == action.person and started <= t.time <= ended
        ),
        None,
    )
    events = data.get("events") or []
    # The executor says when the wait ran out. The timestamps are wall time and the timeout
    # is in simulated seconds: at a speed-up (50 in the service's simulation) a full wait of
    # 300 s lasts 6 s of them, which read as "cut short" kept the person bound and sent a
    # new code after each wait. Results journaled before the flag keep the old reading.
    full_wait = bool(data.get("timed_out")) or (
        ended - started >= action.timeout_s - _INTERRUPTED_MARGIN_S
    )
    interrupted = not ok and complaint is None and not full_wait and not events
    return HandoverAttempt(
        person=action.person,
        place=None,
        ok=ok,
        interrupted=interrupted,
        started_at=started,
        ended_at=ended,
        complaint=complaint,
    )
