"""An instruction's event stream always ends with its ``instruction_ended`` event, also for an
instruction that ended with no such event journaled (cancelled while it waited to start) and
for one cancelled twice in quick succession (the second cancel cut the loop's own end short,
so the instruction was journaled as ended before its end event). Real HTTP, a real server."""

from __future__ import annotations

import asyncio
import json
from pathlib import Path
from typing import Any

import httpx

from assistantx.core.events import TraceEvent
from service.inprocess import serving_runtime

BRING = {"requester": "lee", "text": "Please bring me a stapler."}


async def _events(api: httpx.AsyncClient, iid: str) -> list[tuple[str, dict[str, Any]]]:
    """(event, data) for each event of the stream, until the server ends it."""
    out: list[tuple[str, dict[str, Any]]] = []
    kind = ""
    async with asyncio.timeout(30):
        async with api.stream("GET", f"/v1/instructions/{iid}/events") as response:
            assert response.status_code == 200
            async for line in response.aiter_lines():
                if line.startswith("event: "):
                    kind = line[7:]
                elif line.startswith("data: "):
                    out.append((kind, json.loads(line[6:])))
    return out


async def test_an_instruction_cancelled_before_it_started_ends_its_stream_with_its_end(
    tmp_path: Path,
) -> None:
    async with serving_runtime(tmp_path / "data") as (api, runtime):
        await runtime.admission.stop()  # admitted from now on, none starts: they wait
        iid = (await api.post("/v1/instructions", json=BRING)).json()["id"]
        assert (await api.post(f"/v1/instructions/{iid}/cancel")).json()["cancelled"]
        assert (await api.get(f"/v1/instructions/{iid}")).json()["status"] == "cancelled"
        events = await _events(api, iid)
    assert [kind for kind, _ in events] == ["instruction_ended"]
    data = events[0][1]
    assert data["instruction_id"] == iid
    assert data["data"] == {"outcome": "failed", "summary": "The instruction was cancelled."}


async def test_a_double_cancel_still_journals_the_end_before_the_instruction_ends(
    tmp_path: Path,
) -> None:
    """Streams opened at every event after the cancels each end with ``instruction_ended``."""
    settings: dict[str, Any] = {"robot": "sim", "speedup": 100, "sim_handover_delay_s": 300.0}
    async with serving_runtime(tmp_path / "data", **settings) as (api, runtime):
        asked = asyncio.Event()

        async def on_event(event: TraceEvent) -> None:
            if event.kind == "action_result":
                asked.set()

        runtime.assistant.subscribe(on_event)
        iid = (await api.post("/v1/instructions", json=BRING)).json()["id"]
        await asyncio.wait_for(asked.wait(), 30)
        for _ in range(2):  # the second while the first one's end is being told
            assert (await api.post(f"/v1/instructions/{iid}/cancel")).is_success
        while (await api.get(f"/v1/instructions/{iid}")).json()["status"] in ("queued", "running"):
            pass  # a stream opened at once, as the status turns final
        events = await _events(api, iid)
        ended = [data for kind, data in events if kind == "instruction_ended"]
        assert len(ended) == 1 and events[-1][0] == "instruction_ended"
        assert ended[0]["data"]["summary"].startswith("The instruction was cancelled.")
        journaled = runtime.journal.events(iid, after_seq=0, limit=1000)
        assert [r.event.kind for r in journaled].count("instruction_ended") == 1
