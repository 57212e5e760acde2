"""A person the messenger cannot reach at all (no account on it) is, for this instruction,
unavailable: memory learns it once and the assistant turns to someone else, instead of asking
the same person again until the instruction breaks off (seen on Matrix with Wang, who has no
Matrix account, while Zhang had)."""

from __future__ import annotations

import pytest

from assistantx.agents.registry import reasoner_factory
from assistantx.core.errors import UnreachableContactError
from assistantx.core.office import Office, load_office
from assistantx.core.ports.messenger import OutboundMessage, SentMessage
from assistantx.core.settings import Settings
from assistantx.memory.short_term import ShortTermMemory
from assistantx.runtime.failures import failure_summary
from assistantx.sim.office import SimMessenger, SimOffice
from helpers.office import run_one, sim_assistant


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


class NoAccountFor(SimMessenger):
    """The simulated office's messenger, where some people have no account (a real bridge
    raises this when a person has no Matrix user configured)."""

    def __init__(self, office_sim: SimOffice, without: set[str]) -> None:
        super().__init__(office_sim)
        self.without = without
        self.refused: list[str] = []

    async def send(self, message: OutboundMessage) -> SentMessage:
        if message.chat.kind == "dm" and message.chat.id in self.without:
            self.refused.append(message.chat.id)
            raise UnreachableContactError(f"{message.chat.id} cannot be reached on this messenger")
        return await super().send(message)


async def _fetch_stapler(office: Office, without: set[str]) -> tuple[ShortTermMemory, list[str]]:
    sim = SimOffice(office)
    messenger = NoAccountFor(sim, without)
    sim.messenger = messenger
    assistant = sim_assistant(
        sim, reasoner_factory("symbolic", office, Settings()), reasoner_name="symbolic"
    )
    stm = await run_one(sim, assistant, "lee", "bring me a stapler")
    return stm, messenger.refused


async def test_an_unreachable_owner_is_asked_once_then_someone_else(office: Office) -> None:
    first_owner = "wang"  # the first known stapler owner the embedded planner asks
    stm, refused = await _fetch_stapler(office, {first_owner})
    assert refused == [first_owner]  # tried once, never again
    assert stm.trace.outcome == "done", stm.trace.summary
    applied = [a.update for step in stm.trace.steps for a in step.applied]
    assert any(
        getattr(u, "person", None) == first_owner and getattr(u, "available", None) is False
        for u in applied
    )
    lenders = {t.person for t in stm.dialogue if t.direction == "in"}
    assert first_owner not in lenders and lenders  # someone else lent it


def test_a_repeated_failure_is_told_with_names_not_action_names(office: Office) -> None:
    from assistantx.core.actions import Inquire
    from assistantx.core.trace import ActionResult, Trace

    trace = Trace(instruction_id="ins-x", requester="lee", text="t", reasoner="x", started_at=0.0)
    stm = ShortTermMemory(instruction_id="ins-x", requester="lee", text="t", trace=trace)
    result = ActionResult(
        action=Inquire(contact="wang", question="Could you lend your stapler?"),
        ok=False,
        observation="failed: the messenger is down",
        error="MessengerError",
        started_at=0.0,
        ended_at=0.0,
    )
    told = failure_summary(office, stm, SimOffice(office).robot, result)
    assert told.startswith(f"I could not ask {office.person('wang').name}, twice")
    assert "inquire" not in told and "wang," not in told


def test_a_closed_door_is_told_in_words_with_what_happens_next(office: Office) -> None:
    from assistantx.core.actions import Move
    from assistantx.core.trace import ActionResult, Trace

    trace = Trace(instruction_id="ins-d", requester="lee", text="t", reasoner="x", started_at=0.0)
    stm = ShortTermMemory(instruction_id="ins-d", requester="lee", text="t", trace=trace)
    result = ActionResult(
        action=Move(place="meeting_room"),
        ok=False,
        observation="failed: the way is blocked: the doorway at (35.4, 9.5) ... is shut",
        error="DoorClosedError",
        started_at=0.0,
        ended_at=0.0,
    )
    told = failure_summary(office, stm, SimOffice(office).robot, result)
    room = next(loc.name for loc in office.locations if loc.id == "meeting_room")
    assert told.startswith(f"I could not get to {room}, twice for the same reason (a door on")
    assert f"The door on the way to {room} is closed" in told
    assert "once the door is open, send me the request again" in told
    assert "35.4" not in told and "meeting_room" not in told
