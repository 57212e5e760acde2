"""Messages nobody asked for are kept for a look, the latest ones only (issue 26: memory flat
over 10,000 instructions)."""

from __future__ import annotations

from datetime import UTC, datetime

from assistantx.core.office import load_office
from assistantx.core.ports.messenger import ChatRef, InboundMessage
from assistantx.runtime.assistant import UNMATCHED_KEPT
from assistantx.sim.office import SimOffice
from helpers.office import sim_assistant
from helpers.scripted_reasoner import ScriptedReasoner


def chatter(n: int) -> InboundMessage:
    """A word in a group, to nobody in particular."""
    return InboundMessage(
        platform="test",
        event_id=f"group-{n}",
        chat=ChatRef(kind="group", id="office_work"),
        sender="lee",
        text=f"lunch at {n}?",
        time=datetime(2025, 1, 1, tzinfo=UTC),
    )


async def test_unmatched_messages_are_kept_up_to_a_bound() -> None:
    sim = SimOffice(load_office())
    assistant = sim_assistant(sim, lambda: ScriptedReasoner([]))
    total = 5 * UNMATCHED_KEPT
    for n in range(total):
        assert await assistant.handle_inbound(chatter(n)) is None
        assert len(assistant.unmatched) <= 2 * UNMATCHED_KEPT
    kept = [m.event_id for m in assistant.unmatched]
    assert len(kept) >= UNMATCHED_KEPT
    assert kept == [f"group-{n}" for n in range(total - len(kept), total)]  # the latest, in order


async def test_a_few_unmatched_messages_are_all_kept() -> None:
    sim = SimOffice(load_office())
    assistant = sim_assistant(sim, lambda: ScriptedReasoner([]))
    for n in range(3):
        await assistant.handle_inbound(chatter(n))
    assert [m.event_id for m in assistant.unmatched] == ["group-0", "group-1", "group-2"]
