"""QR payloads are credentials: they never reach the journal, not even inside the simulated
world's snapshot, while simulated colleagues hold them (real uvicorn server, real journal)."""

from __future__ import annotations

import json
import stat
from pathlib import Path

from assistantx.core.events import TraceEvent
from assistantx.core.ports.messenger import OutboundMessage
from assistantx.core.settings import Settings
from assistantx.service.app import create_app
from helpers.instructions import ended
from helpers.servers import serving_app
from service.server import OPERATOR


async def test_held_codes_are_journaled_without_their_payloads(tmp_path: Path) -> None:
    data_dir = tmp_path / "data"
    settings = Settings(
        data_dir=data_dir, operator_token=OPERATOR, speedup=200, robot_localize=False
    )
    app = create_app(settings)
    runtime = app.state.runtime
    payloads: list[str] = []
    snapshots: list[str] = []  # the simulated world as journaled while people held codes

    async def note(message: OutboundMessage) -> None:
        payloads.extend(a.qr_payload for a in message.attachments if a.qr_payload)

    async def look(event: TraceEvent) -> None:
        if event.kind == "action_result" and runtime.sim.codes:
            snapshots.append(json.dumps(runtime.journal.state("sim_world")))

    async with serving_app(app, headers={"Authorization": f"Bearer {OPERATOR}"}) as client:
        runtime.messenger.relay_to(note)  # the lifespan made the messenger
        runtime.assistant.subscribe(look)
        created = await client.post(
            "/v1/instructions", json={"requester": "lee", "text": "bring me a stapler"}
        )
        body = await ended(client, created.json()["id"])
        assert body["status"] == "done", body

    assert len(payloads) == 2  # the lender's code and the requester's
    assert snapshots  # people held codes while the world was journaled
    for snapshot in snapshots:
        assert not [p for p in payloads if p in snapshot]
        assert '"ref"' in snapshot  # each held code is named by a digest instead
    journal_bytes = b"".join(p.read_bytes() for p in data_dir.glob("journal.sqlite3*"))
    assert not [p for p in payloads if p.encode() in journal_bytes]
    phones = data_dir / "sim-codes.json"  # where the simulated people keep them instead
    assert stat.S_IMODE(phones.stat().st_mode) == 0o600
    book = data_dir / "locker-codes.json"  # the dashboard's code book, kept across restarts
    assert stat.S_IMODE(book.stat().st_mode) == 0o600
    assert sorted(json.loads(book.read_text())) == sorted(payloads)
