"""The give-back errand survives a restart: cancel while the lender's stapler is in the locker,
stop the service (SIGTERM: in process; kill -9: a real server process) while the robot waits
at the lender's desk, start it again, and the lender still gets the stapler back, told in
words at each attempt with a fresh code (the one cut short was withdrawn)."""

from __future__ import annotations

import asyncio
from pathlib import Path
from typing import Any

import httpx
import pytest

from assistantx.core.events import TraceEvent
from helpers.eventually import eventually, eventually_sync
from helpers.instructions import ended
from service.inprocess import serving_runtime
from service.server import LEE, OPERATOR, free_port, serve, sse

# People come to the locker 0.1 s of wall time after the robot stands at their desk; in process,
# once Wang's stapler is in the locker he is made to take a day over it (the simulated people's
# delay, read when the robot stands at his desk again), so the stop always comes while the
# robot waits at his desk, not when a 3 s window happened to be long enough.
SETTINGS: dict[str, Any] = {"robot": "sim", "speedup": 100, "sim_handover_delay_s": 10.0}
A_DAY_S = 86_400.0
# The real server process (kill -9): each hand-over takes 3 s of wall time, long enough to
# kill it during the return.
ENV = {
    "ASSISTANTX_ROBOT": "sim",
    "ASSISTANTX_SPEEDUP": "100",
    "ASSISTANTX_SIM_HANDOVER_DELAY_S": "300",
}
BRING = {"requester": "lee", "text": "Please bring me a stapler."}
TOLD = "is in the robot's locker"
AUTH_OP = {"Authorization": f"Bearer {OPERATOR}"}


def _texts(messages: list[dict[str, Any]]) -> list[str]:
    return [str(m["text"]) for m in messages if m["direction"] == "out"]


def _codes(messages: list[dict[str, Any]]) -> int:
    return sum(1 for m in messages if m["direction"] == "out" and m["attachments"])


async def test_a_give_back_cut_short_by_a_stop_resumes_on_start(tmp_path: Path) -> None:
    data = tmp_path / "data"
    async with serving_runtime(data, **SETTINGS) as (api, runtime):
        deposited = asyncio.Event()

        async def sink(event: TraceEvent) -> None:
            result: dict[str, Any] = event.data.get("result") or {}
            action = result.get("action") or {}
            if action.get("type") == "wait_in_place" and result.get("ok"):
                runtime.sim.handover_delay_s = A_DAY_S  # Wang does not come before the stop
                deposited.set()

        runtime.assistant.subscribe(sink)
        iid = (await api.post("/v1/instructions", json=BRING)).json()["id"]
        await asyncio.wait_for(deposited.wait(), 60)
        assert (await api.post(f"/v1/instructions/{iid}/cancel")).json()["cancelled"]
        assert (await ended(api, iid))["status"] == "cancelled"

        async def wang() -> list[dict[str, Any]]:
            return list((await api.get("/v1/chats/dm/wang")).json())

        await eventually(
            lambda: _codes_after_told(wang), what="Wang to be told and sent a code", timeout_s=60
        )
        assert runtime.sim.world.holder["stapler:wang"] == "locker"  # he has not come yet
    # Stopped while the robot waits at Wang's desk; started again on the same data.
    async with serving_runtime(data, **SETTINGS) as (api, runtime):
        await eventually(
            lambda: runtime.sim.world.holder["stapler:wang"] == "wang",
            what="Wang to have his stapler back after the restart",
            timeout_s=60,
        )
        messages = list((await api.get("/v1/chats/dm/wang")).json())
        assert sum(TOLD in t for t in _texts(messages)) == 2  # once per attempt
        assert _codes(messages) == 3  # the deposit code, and one collect code per attempt


async def _codes_after_told(messages: Any) -> bool:
    texts = await messages()
    told = [n for n, m in enumerate(texts) if m["direction"] == "out" and TOLD in m["text"]]
    return bool(told) and any(m["attachments"] for m in texts[told[0] :])


@pytest.mark.slow
def test_a_give_back_cut_short_by_kill_9_resumes_on_start(tmp_path: Path) -> None:
    port = free_port()
    server = serve(tmp_path / "data", port, **ENV)
    try:
        with httpx.Client(base_url=server.url, timeout=10) as client:
            r = client.post("/v1/instructions", json=BRING, headers=AUTH_OP)
            iid = r.json()["id"]
            for _, kind, data in sse(client, f"/v1/instructions/{iid}/events", LEE):
                result: dict[str, Any] = data["data"].get("result", {})  # type: ignore[union-attr]
                action = result.get("action") or {}
                if kind == "action_result" and action["type"] == "wait_in_place" and result["ok"]:
                    break  # Wang's stapler is in the locker
            assert client.post(f"/v1/instructions/{iid}/cancel", headers=AUTH_OP).is_success
            list(sse(client, f"/v1/instructions/{iid}/events", LEE))  # ends once it ended

            def wang() -> list[dict[str, Any]]:
                return list(client.get("/v1/chats/dm/wang", headers=AUTH_OP).json())

            def told_and_sent_a_code() -> bool:
                texts = wang()
                told = [
                    n for n, m in enumerate(texts) if m["direction"] == "out" and TOLD in m["text"]
                ]
                return bool(told) and any(m["attachments"] for m in texts[told[0] :])

            eventually_sync(
                told_and_sent_a_code, what="Wang to be told and sent a code", timeout_s=60
            )
    finally:
        server.kill()

    server = serve(tmp_path / "data", port, **ENV)
    try:
        with httpx.Client(base_url=server.url, timeout=10) as client:

            def errand_over() -> bool:
                # The robot free again, after the resumed attempt sent its code.
                return client.get("/v1/robot", headers=AUTH_OP).json()["holder"] is None and (
                    _codes(list(client.get("/v1/chats/dm/wang", headers=AUTH_OP).json())) == 3
                )

            eventually_sync(errand_over, what="the resumed give-back to end", timeout_s=60)
            messages = list(client.get("/v1/chats/dm/wang", headers=AUTH_OP).json())
            assert sum(TOLD in t for t in _texts(messages)) == 2  # once per attempt
            lee = _texts(list(client.get("/v1/chats/dm/lee", headers=AUTH_OP).json()))
            assert sum("bringing Wang Fang's stapler back to Wang Fang" in t for t in lee) == 1
    finally:
        server.stop()
    # The world the service journaled when the errand was over: Wang holds his stapler.
    asyncio.run(_holder_after_restart(tmp_path / "data", "stapler:wang", "wang"))


async def _holder_after_restart(data: Path, item: str, holder: str) -> None:
    async with serving_runtime(data, **SETTINGS) as (_, runtime):
        assert runtime.sim.world.holder[item] == holder
