"""A cancelled instruction reads as cancelled where people look: its trace says so (the usage
report counts it under ``cancelled``, and no survey follows), and the codes it had sent read
as revoked, also one the lock no longer knew."""

from __future__ import annotations

import asyncio
from typing import Any

import pytest

from assistantx.agents.symbolic import build_factory
from assistantx.core.events import TraceEvent
from assistantx.core.office import Office, load_office
from assistantx.feedback.impact import summarise
from assistantx.sim.lock.local import LocalLocker
from assistantx.sim.office import SimOffice
from helpers.office import sim_assistant, started


@pytest.fixture(scope="module")
def office() -> Office:
    return load_office()


async def test_a_cancel_after_a_code_went_out(office: Office) -> None:
    sim = SimOffice(office, handover_delay_s=3600)  # the lender takes an hour to come
    assistant = sim_assistant(sim, build_factory(office, None))
    sent: asyncio.Future[str] = asyncio.get_running_loop().create_future()

    async def sink(event: TraceEvent) -> None:
        result: dict[str, Any] = event.data.get("result") or {}
        if event.kind == "action_result" and result.get("action", {}).get("type") == "send_qr":
            if not sent.done():
                sent.set_result(str(result["data"]["code_id"]))

    assistant.subscribe(sink)
    async with started(sim, assistant):
        stm = await assistant.submit("lee", "Please bring me a stapler.")
        code_id = await sent
        # The lock forgets the code (as an in-process lock does when it restarts).
        assert isinstance(sim.locker, LocalLocker)
        sim.locker.controller.revoke(code_id)
        assert assistant.cancel(stm.instruction_id)
        with pytest.raises(asyncio.CancelledError):
            await assistant.wait(stm.instruction_id)
    ended = assistant.get(stm.instruction_id)
    assert ended is not None
    assert ended.trace.cancelled and ended.trace.outcome == "failed"
    assert summarise(office, ended.trace, ended_at=0.0).outcome == "cancelled"
    assert [c.state for c in ended.embodied.codes] == ["revoked"]
