"""Instruction ids are unique for ever: a restarted service on the same data folder never hands
out an id its journal holds, so every owner keeps reading and cancelling their own."""

from __future__ import annotations

from pathlib import Path

import httpx

from helpers.eventually import eventually
from service.inprocess import running_service
from service.server import LEE, ZHANG

AS_LEE = {"Authorization": f"Bearer {LEE}"}
AS_ZHANG = {"Authorization": f"Bearer {ZHANG}"}
REQUEST = "please bring me a stapler"


async def _dm_instruction(client: httpx.AsyncClient, headers: dict[str, str]) -> str:
    """Send a request by direct message; the id of the instruction it started."""
    before = {
        i["id"] for i in (await client.get("/v1/instructions", headers=headers)).json()["items"]
    }
    r = await client.post("/v1/messages", json={"text": REQUEST}, headers=headers)
    assert r.status_code == 202, r.text

    async def new() -> list[str]:
        items = (await client.get("/v1/instructions", headers=headers)).json()["items"]
        return [str(i["id"]) for i in items if i["id"] not in before]

    [iid] = await eventually(new, what="an instruction started by the direct message")
    return iid


async def test_ids_of_dm_instructions_are_not_reused_after_a_restart(tmp_path: Path) -> None:
    data_dir = tmp_path / "data"
    async with running_service(data_dir) as api:
        lees = await _dm_instruction(api, AS_LEE)
    async with running_service(data_dir) as api:
        zhangs = await _dm_instruction(api, AS_ZHANG)
        assert zhangs != lees
        mine = await api.get(f"/v1/instructions/{lees}", headers=AS_LEE)
        assert mine.status_code == 200 and mine.json()["requester"] == "lee"
        assert mine.json()["text"] == REQUEST
        assert (await api.get(f"/v1/instructions/{lees}", headers=AS_ZHANG)).status_code == 404
        his = await api.get(f"/v1/instructions/{zhangs}", headers=AS_ZHANG)
        assert his.status_code == 200 and his.json()["requester"] == "zhang"
        assert (await api.get(f"/v1/instructions/{zhangs}", headers=AS_LEE)).status_code == 404
        assert (
            await api.post(f"/v1/instructions/{lees}/cancel", headers=AS_LEE)
        ).status_code == 200
        assert (
            await api.post(f"/v1/instructions/{zhangs}/cancel", headers=AS_ZHANG)
        ).status_code == 200
        assert (
            await api.post(f"/v1/instructions/{lees}/cancel", headers=AS_ZHANG)
        ).status_code == 404
