"""One person cannot flood the office: beyond ``instructions_per_minute`` a REST submission
gets a one-line 429, and a direct message that asks for something gets one answer in words
and starts nothing; other people are not affected."""

from __future__ import annotations

from pathlib import Path

import httpx

from helpers.eventually import eventually
from service.inprocess import serving_runtime
from service.server import LEE

AS_LEE = {"Authorization": f"Bearer {LEE}"}
SETTINGS = {"robot": "sim", "instructions_per_minute": 3}


async def _count(api: httpx.AsyncClient, requester: str) -> int:
    items = (await api.get("/v1/instructions?limit=100")).json()["items"]
    return sum(1 for i in items if i["requester"] == requester)


async def test_rest_submissions_beyond_the_bound_get_a_clear_429(tmp_path: Path) -> None:
    async with serving_runtime(tmp_path / "data", **SETTINGS) as (api, _):
        body = {"requester": "lee", "text": "Please bring me a stapler."}
        codes = [
            (await api.post("/v1/instructions", json=body, headers=AS_LEE)).status_code
            for _ in range(5)
        ]
        assert codes == [202, 202, 202, 429, 429]
        refused = await api.post("/v1/instructions", json=body, headers=AS_LEE)
        assert refused.json()["error"] == "too_many_requests"
        message = refused.json()["message"]
        assert "\n" not in message and "at most 3 a minute" in message
        assert message.startswith("Too many requests from Lee Ming")
        other = {"requester": "zhang", "text": "Please bring me a stapler."}
        assert (await api.post("/v1/instructions", json=other)).status_code == 202
        assert await _count(api, "lee") == 3


async def test_direct_messages_beyond_the_bound_are_answered_once(tmp_path: Path) -> None:
    async with serving_runtime(tmp_path / "data", **SETTINGS) as (api, _):
        for n in range(6):
            r = await api.post(
                "/v1/messages", json={"sender": "hu", "text": f"Please bring me a stapler ({n})."}
            )
            assert r.status_code == 202
        # Handled in order: once this chatter is answered, every request before it was.
        await api.post("/v1/messages", json={"sender": "hu", "text": "ok thanks"})

        async def last_answered() -> bool:
            chat = (await api.get("/v1/chats/dm/hu")).json()
            return any("did not find a request" in m["text"] for m in chat)

        await eventually(last_answered, what="the answer to the chatter")

        async def refusals() -> list[str]:
            chat = (await api.get("/v1/chats/dm/hu")).json()
            return [m["text"] for m in chat if m["text"].startswith("Too many requests")]

        assert len(await refusals()) == 1
        assert await _count(api, "hu") == 3
