"""Late or stray direct messages start nothing: a colleague writing back after the instruction
that contacted them ended, or a reply to an ended instruction's question, is acknowledged in
words; a message that asks for nothing too. A request still starts an instruction."""

from __future__ import annotations

from pathlib import Path

import httpx

from helpers.eventually import eventually
from helpers.instructions import ended as instruction_ended
from service.inprocess import running_service
from service.server import LEE, OPERATOR

OP = {"Authorization": f"Bearer {OPERATOR}"}
AS_LEE = {"Authorization": f"Bearer {LEE}"}


async def _ids(api: httpx.AsyncClient) -> list[str]:
    items = (await api.get("/v1/instructions", headers=OP)).json()["items"]
    return [str(i["id"]) for i in items]


async def _dm(api: httpx.AsyncClient, sender: str, text: str, **extra: str) -> None:
    body = {"text": text, "sender": sender, **extra}
    r = await api.post("/v1/messages", json=body, headers=OP)
    assert r.status_code == 202, r.text


async def _last_out(api: httpx.AsyncClient, person: str, after: int) -> list[str]:
    """The assistant's messages in ``person``'s DM after sequence number ``after``."""

    async def out() -> list[str]:
        chat = (await api.get(f"/v1/chats/dm/{person}?after={after}", headers=OP)).json()
        return [str(m["text"]) for m in chat if m["direction"] == "out"]

    return await eventually(out, what=f"the assistant's answer to {person}", timeout_s=5)


async def _seq(api: httpx.AsyncClient, person: str) -> int:
    chat = (await api.get(f"/v1/chats/dm/{person}", headers=OP)).json()
    return max((int(m["seq"]) for m in chat), default=0)


async def test_late_replies_and_chatter_are_acknowledged_not_executed(tmp_path: Path) -> None:
    # speed-up 200 (the tests' default is 50): the errand only has to end before the late
    # messages come
    async with running_service(tmp_path / "data", speedup=200) as api:
        r = await api.post(
            "/v1/instructions",
            json={"requester": "lee", "text": "Please bring me a stapler."},
            headers=AS_LEE,
        )
        iid = r.json()["id"]
        ended = await instruction_ended(api, iid, OP)
        assert ended["status"] == "done"
        wang = (await api.get("/v1/chats/dm/wang", headers=OP)).json()
        [question] = [m["question_id"] for m in wang if m["question_id"]]

        # Wang, contacted by the ended instruction, writes back late.
        seq = await _seq(api, "wang")
        await _dm(api, "wang", "I came to the robot, but: I don't have a stapler")
        [ack] = await _last_out(api, "wang", seq)
        assert "already ended" in ack and "ins-" not in ack
        # A reply to the ended instruction's question.
        seq = await _seq(api, "wang")
        await _dm(api, "wang", "Yes, I have a stapler.", in_reply_to=question)
        [ack] = await _last_out(api, "wang", seq)
        assert "already ended" in ack
        # Someone the assistant never contacted, asking for nothing.
        seq = await _seq(api, "zhang")
        await _dm(api, "zhang", "ok thanks")
        [ack] = await _last_out(api, "zhang", seq)
        assert "did not find a request" in ack

        # Requests still start instructions, also from the colleague contacted before. The
        # inbox is handled in order, so had the chatter above started anything, it would be
        # listed before these two: exactly three instructions, these two the newest.
        await _dm(api, "wang", "Please bring me a coffee.")
        await _dm(api, "zhang", "Bring me a stapler")
        await eventually(
            lambda: _ids(api), until=lambda ids: len(ids) >= 3, what="two more instructions"
        )
        assert len(await _ids(api)) == 3
        started = (await api.get("/v1/instructions", headers=OP)).json()["items"]
        assert sorted((i["requester"], i["text"]) for i in started[:2]) == [
            ("wang", "Please bring me a coffee."),
            ("zhang", "Bring me a stapler"),
        ]
