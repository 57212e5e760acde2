"""Nobody is left without their things: cancel an instruction while the lender's stapler is in
the robot's locker, and the robot brings it back to the lender, who is told why in words; the
requester's last message says so too."""

from __future__ import annotations

import asyncio
from collections.abc import Callable
from pathlib import Path
from typing import Any

from assistantx.core.events import TraceEvent
from assistantx.service.runtime import ServiceRuntime
from helpers.eventually import eventually
from helpers.instructions import ended
from service.inprocess import serving_runtime

# People come to the locker 0.04 s of wall time after the robot stands at their desk (10
# simulated seconds at a speed-up of 250). The cancel must come before Lee's hand-over: the
# moment Wang's deposit is seen, Lee steps away (the simulated world's availability), so she
# never comes for the stapler, however long the cancel takes (before, each hand-over took
# 1.2 s of wall time, a window the cancel happened to fit in, and the test waited out two).
SETTINGS: dict[str, Any] = {"robot": "sim", "speedup": 250, "sim_handover_delay_s": 10.0}


def deposited_by(
    runtime: ServiceRuntime, person: str, then: Callable[[], None]
) -> asyncio.Future[None]:
    """Done when ``person`` has put their item in the locker; ``then`` runs at that moment."""
    done: asyncio.Future[None] = asyncio.get_running_loop().create_future()

    async def sink(event: TraceEvent) -> None:
        result: dict[str, Any] = event.data.get("result") or {}
        action = result.get("action") or {}
        if event.kind == "action_result" and action.get("type") == "wait_in_place":
            if action["person"] == person and result["ok"] and not done.done():
                then()
                done.set_result(None)

    runtime.assistant.subscribe(sink)
    return done


async def test_a_cancel_with_the_lenders_stapler_aboard_gives_it_back(tmp_path: Path) -> None:
    async with serving_runtime(tmp_path / "data", **SETTINGS) as (api, runtime):
        deposited = deposited_by(
            runtime, "wang", lambda: runtime.sim.world.set_available("lee", False)
        )
        r = await api.post(
            "/v1/instructions", json={"requester": "lee", "text": "Please bring me a stapler."}
        )
        iid = r.json()["id"]
        await asyncio.wait_for(deposited, 60)
        assert runtime.sim.world.holder["stapler:wang"] == "locker"
        assert (await api.post(f"/v1/instructions/{iid}/cancel")).json()["cancelled"]
        final = await ended(api, iid)
        assert final["status"] == "cancelled"

        await eventually(
            lambda: runtime.sim.world.holder["stapler:wang"] == "wang",
            what="Wang to have his stapler back",
            timeout_s=60,
        )
        lee = [m["text"] for m in (await api.get("/v1/chats/dm/lee")).json()]
        last = next(t for t in reversed(lee) if t.startswith("[failed]"))
        assert "cancelled" in last
        assert "bringing Wang Fang's stapler back to Wang Fang" in last
        wang = [m["text"] for m in (await api.get("/v1/chats/dm/wang")).json()]
        told = [t for t in wang if "is in the robot's locker" in t]
        assert told == [
            "Your stapler is in the robot's locker, and Lee Ming's request it was for was "
            "cancelled. The robot is at your desk to give it back: scan the code I am sending "
            "you to take it out."
        ]
        assert not any("ins-" in t or "stapler:" in t for t in wang + lee)
        assert (await api.get("/v1/locker")).json()["contents"] == []
