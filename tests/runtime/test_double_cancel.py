"""A second cancel while the first one's end is being told (the requester's message slow to
go out) does not let the instruction count as ended before its ``instruction_ended`` event:
the service journals an instruction as ended in its end hooks, and an event stream opened
between the two ended without the event."""

from __future__ import annotations

import asyncio

import pytest

from assistantx.agents.symbolic import build_factory
from assistantx.core.events import TraceEvent
from assistantx.core.office import Office, load_office
from assistantx.core.ports.messenger import OutboundMessage, SentMessage
from assistantx.memory.short_term import ShortTermMemory
from assistantx.sim.office import SimMessenger, SimOffice
from helpers.office import sim_assistant, started


class SlowToTellTheEnd(SimMessenger):
    """The simulated messenger, holding the final message until ``release`` is set."""

    def __init__(self, sim: SimOffice) -> None:
        super().__init__(sim)
        self.holding = asyncio.Event()
        self.release = asyncio.Event()

    async def send(self, message: OutboundMessage) -> SentMessage:
        if message.text.startswith("[failed]"):
            self.holding.set()
            await self.release.wait()
        return await super().send(message)


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


async def test_a_second_cancel_does_not_end_the_instruction_before_its_end_event(
    office: Office,
) -> None:
    sim = SimOffice(office, handover_delay_s=3600)
    messenger = SlowToTellTheEnd(sim)
    sim.messenger = messenger
    assistant = sim_assistant(sim, build_factory(office, None))
    order: list[str] = []
    began = asyncio.Event()

    async def sink(event: TraceEvent) -> None:
        order.append(event.kind)
        if event.kind == "action_result":
            began.set()

    async def on_end(stm: ShortTermMemory) -> None:
        order.append("end hooks")

    assistant.subscribe(sink)
    assistant.on_instruction_end(on_end)
    async with started(sim, assistant):
        stm = await assistant.submit("lee", "Please bring me a stapler.")
        await began.wait()
        assert assistant.cancel(stm.instruction_id)
        await messenger.holding.wait()  # the first cancel's end is being told
        assert assistant.cancel(stm.instruction_id)  # and a second one comes
        messenger.release.set()
        with pytest.raises(asyncio.CancelledError):
            await assistant.wait(stm.instruction_id)
    assert order[-2:] == ["instruction_ended", "end hooks"]
    assert order.count("instruction_ended") == 1
