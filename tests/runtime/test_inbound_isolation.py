"""The Assistant's one inbox consumer skips a message whose handling raises, counts it, and
handles the next one (issue 24: per-event isolation on every inbound path)."""

from __future__ import annotations

from datetime import UTC, datetime

from assistantx.core.office import load_office
from assistantx.core.ports.messenger import ChatRef, InboundMessage
from assistantx.sim.office import SimOffice
from helpers.office import sim_assistant, started
from helpers.scripted_reasoner import ScriptedReasoner


def dm(event_id: str, text: str) -> InboundMessage:
    return InboundMessage(
        platform="test",
        event_id=event_id,
        chat=ChatRef(kind="dm", id="lee"),
        sender="lee",
        text=text,
        time=datetime(2025, 1, 1, tzinfo=UTC),
    )


async def test_a_message_that_breaks_its_handler_is_skipped_and_counted() -> None:
    seen: list[str] = []

    def is_request(text: str, sender: str, *, strict: bool) -> bool:
        seen.append(text)
        if text == "poison":
            raise ValueError("a recognizer bug")
        return False  # "hello" asks for nothing: answered in words

    sim = SimOffice(load_office())
    assistant = sim_assistant(sim, lambda: ScriptedReasoner([]), is_request=is_request)
    async with started(sim, assistant):
        await assistant.inbox.put(dm("$poison", "poison"))
        await assistant.inbox.put(dm("$hello", "hello"))
    # stop() let the consumer take everything queued before its sentinel
    assert seen == ["poison", "hello"]
    assert assistant.skipped.by_path == {"dispatch": 1}
    [answer] = [m for m in sim.messenger.sent if m.chat == ChatRef(kind="dm", id="lee")]
    assert answer.text.startswith("I did not find a request in your message")
