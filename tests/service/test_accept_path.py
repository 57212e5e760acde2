"""The accept path: a POST is answered 202 only once its instruction's insert is committed
(the journal's writer held, no answer comes and nothing is visible; let go, the answer comes
and a reader of the file sees the instruction)."""

from __future__ import annotations

import asyncio
import threading
from pathlib import Path
from typing import Any

from service.inprocess import serving_runtime

HELD_S = 0.5  # how long the test keeps the writer held: no answer may come meanwhile


async def test_a_post_is_answered_after_its_insert_is_committed(tmp_path: Path) -> None:
    async with serving_runtime(tmp_path / "data") as (client, runtime):
        let_go = threading.Event()
        holding = threading.Event()

        def hold(_db: Any) -> None:  # runs on the writer's thread: later groups wait
            holding.set()
            let_go.wait(30)

        held = runtime.journal.writer.submit(hold, now=True)
        assert await asyncio.to_thread(holding.wait, 30)
        before = {r.id for r in runtime.journal.instructions(limit=200)}
        post = asyncio.create_task(
            client.post(
                "/v1/instructions", json={"requester": "lee", "text": "Please bring me a stapler."}
            )
        )
        try:
            await asyncio.sleep(HELD_S)
            assert not post.done()  # no answer while the insert waits for its commit
            assert {r.id for r in runtime.journal.instructions(limit=200)} == before
        finally:
            let_go.set()
        r = await asyncio.wait_for(post, 30)
        held.result(30)
        assert r.status_code == 202, r.text
        record = runtime.journal.instruction(r.json()["id"])
        assert record is not None and record.text == "Please bring me a stapler."
