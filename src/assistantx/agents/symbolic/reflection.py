"""Reflection: what each action was expected to do, what was observed, and what memory learns.

Verdict Y when every action did what it was for (a question got its answer, the robot arrived,
the person used the locker); N with the reason otherwise. The memory updates follow from the
observations: an answer means the person is here (and, for a lend question, whether they own
the item); a wait that timed out means whoever did not answer is away; a hand-over moves the
item; a person who never came is away.
"""

from __future__ import annotations

from assistantx.agents.symbolic.answers import stance
from assistantx.agents.symbolic.evidence import Evidence, Question
from assistantx.agents.symbolic.roles import Role, Roles
from assistantx.core import task_kinds
from assistantx.core.actions import (
    Action,
    ForwardFile,
    Inform,
    Inquire,
    Move,
    SendQR,
    Stop,
    Wait,
    WaitInPlace,
)
from assistantx.core.trace import ActionResult, Observation, Reflection
from assistantx.memory.graph import LOCKER
from assistantx.memory.updates import (
    AvailabilityUpdate,
    ItemLocationUpdate,
    MemoryUpdate,
    OwnershipUpdate,
)


def expectation(action: Action) -> str:
    match action:
        case Inquire():
            return f"the question reaches {action.contact}"
        case Wait():
            return "an answer arrives"
        case Inform():
            return f"{action.contact} is told"
        case ForwardFile():
            return f"the file reaches {action.target}"
        case SendQR():
            return f"{action.contact} gets a code to {action.purpose} {action.item}"
        case Move():
            return f"the robot arrives at {action.place}"
        case WaitInPlace():
            return f"{action.person} comes and uses the locker"
        case Stop():
            return "the requester is told the outcome"
    return "it works"  # pragma: no cover


class Reflector:
    def __init__(self, roles: Roles) -> None:
        self.roles = roles

    def reflect(
        self,
        roles: list[Role],
        before: Evidence,
        after: Evidence,
        results: list[ActionResult],
        observed: Observation,
    ) -> Reflection:
        updates: list[MemoryUpdate] = []
        problems: list[str] = []
        for result in results:
            if result.refused:
                problems.append(f"{result.action.type} was refused ({result.observation})")
            elif not result.ok and not isinstance(result.action, Wait):
                problems.append(f"expected {expectation(result.action)}, but {result.observation}")
        updates += self._answers(roles, after, observed)
        timed_out = [r for r in results if isinstance(r.action, Wait) and r.data.get("timed_out")]
        for wait in timed_out:
            for q in after.questions:
                silent = not q.group and q.contact != after.requester and q.time <= wait.started_at
                if silent and not after.answers(q) and q not in _expired_before(before, q):
                    updates.append(
                        AvailabilityUpdate(
                            person=q.contact,
                            available=False,
                            evidence=f"no answer within {wait.action.timeout_s:.0f} s",  # type: ignore[union-attr]
                        )
                    )
                    problems.append(f"{q.contact} did not answer")
                elif q.group and not after.answers(q) and q.time <= wait.started_at:
                    problems.append(f"nobody in {q.contact} answered")
        for result in results:
            if isinstance(result.action, WaitInPlace):
                updates += self._handover(result, after)
                if not result.ok:
                    if after.interrupted_handover(result.action.person):
                        problems.append("the wait at the locker was cut short by a message")
        verdict = "N" if problems else "Y"
        reason = (
            "; ".join(problems)
            if problems
            else "; ".join(expectation(r.action) for r in results) or "nothing to check"
        )
        return Reflection(verdict=verdict, reason=reason[:2000], updates=_dedupe(updates)[:20])

    def _role_of(self, roles: list[Role], q: Question) -> Role | None:
        for role in roles:
            if q.group and q.text == self.roles.group_question(role):
                return role
            if not q.group and q.text == self.roles.question(role, q.contact):
                return role
        return None

    def _answers(
        self, roles: list[Role], ev: Evidence, observed: Observation
    ) -> list[MemoryUpdate]:
        out: list[MemoryUpdate] = []
        by_id = {q.question_id: q for q in ev.questions}
        for turn in observed.messages:
            q = by_id.get(turn.in_reply_to or "")
            if q is None or turn.person == ev.requester:
                continue
            said = stance(turn.text)
            quote = turn.text[:200]
            if said == "unclear":
                continue
            out.append(
                AvailabilityUpdate(
                    person=turn.person, available=True, evidence=f"answered: {quote}"
                )
            )
            role = self._role_of(roles, q)
            if role is None:
                continue
            owned = role.item_type if role.asks_ownership else None
            if task_kinds.needs_tool(role.kind):  # a yes means they own the tool (the seal)
                owned = task_kinds.tool_type(role.kind, self.roles.office)
            if owned is None:
                continue
            if not q.group:
                out.append(
                    OwnershipUpdate(
                        person=turn.person,
                        item_type=owned,
                        owns=said == "yes",
                        evidence=f"answered: {quote}",
                    )
                )
            elif said == "yes":
                out.append(
                    OwnershipUpdate(
                        person=turn.person,
                        item_type=owned,
                        owns=True,
                        evidence=f"offered in the group chat: {quote}",
                    )
                )
        return out

    def _handover(self, result: ActionResult, ev: Evidence) -> list[MemoryUpdate]:
        action = result.action
        assert isinstance(action, WaitInPlace)
        person = action.person
        if result.ok:
            out: list[MemoryUpdate] = [
                AvailabilityUpdate(person=person, available=True, evidence="came to the robot")
            ]
            for code in ev.codes:
                if code.person != person or not code.used:
                    continue
                where = {"deposit": LOCKER, "produce": LOCKER, "collect": person}.get(code.purpose)
                if where is not None:
                    out.append(
                        ItemLocationUpdate(
                            item=code.item,
                            holder=where,
                            evidence=f"{person} used a {code.purpose} code",
                        )
                    )
                product = self.roles.office.made_from(code.item.partition(":")[0])
                if code.purpose == "copy" and product is not None:
                    owner = code.item.split(":", 1)[1]
                    out.append(
                        ItemLocationUpdate(
                            item=f"{product}:{owner}",
                            holder=LOCKER,
                            evidence=f"{person} made a copy",
                        )
                    )
            return out
        attempt = next((h for h in reversed(ev.handovers) if h.person == person), None)
        if attempt is None or attempt.interrupted or attempt.complaint:
            return []
        return [
            AvailabilityUpdate(
                person=person,
                available=False,
                evidence=f"did not come to the robot within {action.timeout_s:.0f} s",
            )
        ]


def _expired_before(before: Evidence, q: Question) -> list[Question]:
    """Questions that had already expired before this step (their silence is old news)."""
    return [x for x in before.questions if x.question_id == q.question_id and before.expired(x)]


def _dedupe(updates: list[MemoryUpdate]) -> list[MemoryUpdate]:
    seen: set[str] = set()
    out: list[MemoryUpdate] = []
    for u in updates:
        key = u.model_dump_json(exclude={"evidence"})
        if key not in seen:
            seen.add(key)
            out.append(u)
    return out
