"""The simulated world is journaled only when it changed, and the journal always ends up
holding the world as it is (real uvicorn server, real journal)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from assistantx.core.settings import Settings
from assistantx.service import colleagues
from assistantx.service.app import create_app
from helpers.instructions import ended
from helpers.servers import serving_app
from service.server import OPERATOR


def _as_journaled(world: dict[str, Any]) -> Any:
    return json.loads(json.dumps(world))


async def test_the_journaled_world_is_the_world_after_a_hand_over(tmp_path: Path) -> None:
    # Speed-up 200 (the tests' usual 50 took 4 s of wall time): only the world after the
    # instruction's end is looked at, nothing in between.
    settings = Settings(
        data_dir=tmp_path / "data", operator_token=OPERATOR, speedup=200, robot_localize=False
    )
    app = create_app(settings)
    runtime = app.state.runtime
    headers = {"Authorization": f"Bearer {OPERATOR}"}
    async with serving_app(app, headers=headers) as client:
        before = _as_journaled(colleagues.snapshot(runtime.sim))
        created = await client.post(
            "/v1/instructions", json={"requester": "lee", "text": "bring me a stapler"}
        )
        body = await ended(client, created.json()["id"])
        assert body["status"] == "done", body
        now = _as_journaled(colleagues.snapshot(runtime.sim))
        assert now != before  # the stapler changed hands
        journaled = runtime.journal.state(colleagues.SIM_STATE)
        assert journaled is not None
        # The last checkpoint (the instruction's end) holds the world after the hand-over;
        # the codes and who was told are dropped by the end hook that runs after it.
        for part in ("holder", "received", "messages_to", "robot"):
            assert journaled[part] == now[part], part
