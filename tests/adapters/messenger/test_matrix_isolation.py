"""One bad event never stops the Matrix bridge (issue 24): on the push path, the /sync path and
in the room bookkeeping, the event that raises is logged with its id, counted and skipped, and
the batch around it is acknowledged."""

from __future__ import annotations

import asyncio
import json
import logging
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import httpx
import pytest
from fastapi import FastAPI
from pydantic import SecretStr

from adapters.messenger.conftest import ServeRouters
from adapters.messenger.test_matrix_appservice import AUTH, CONFIG, HS_TOKEN, text_event
from assistantx.adapters.messenger.matrix import (
    EventIngestor,
    EventNormalizer,
    MatrixClient,
    SqliteEventStore,
    SyncPoller,
    create_appservice_router,
)
from assistantx.adapters.messenger.matrix.rooms import RoomDirectory
from assistantx.core.errors import MessengerError
from assistantx.core.ports.messenger import InboundMessage
from helpers.servers import serve_asgi

BOT = CONFIG.bot_user_id
POISON_BODY = '"\\ud800 lone surrogate"'  # valid JSON, not valid Unicode


def poison_event(event_id: str) -> str:
    """A text event (as JSON text) whose body JSON allows and UTF-8 cannot hold."""
    fine = json.dumps(text_event(event_id, "PLACEHOLDER"))
    return fine.replace('"PLACEHOLDER"', POISON_BODY)


def invite(event_id: str, room_id: str) -> dict[str, Any]:
    return {
        "type": "m.room.member",
        "event_id": event_id,
        "room_id": room_id,
        "sender": "@lee:office.test",
        "state_key": BOT,
        "content": {"membership": "invite"},
    }


def drained(inbox: asyncio.Queue[InboundMessage]) -> list[str]:
    return [inbox.get_nowait().event_id for _ in range(inbox.qsize())]


async def test_a_poison_event_is_skipped_and_its_transaction_acknowledged(
    serve_routers: ServeRouters,
    store: SqliteEventStore,
    inbox: asyncio.Queue[InboundMessage],
    caplog: pytest.LogCaptureFixture,
) -> None:
    async def on_invite(room_id: str, user: str, event: Mapping[str, Any]) -> None:
        raise MessengerError(f"the homeserver refused to join {room_id}")

    ingestor = EventIngestor(store, EventNormalizer(CONFIG, {}), inbox.put, on_invite=on_invite)
    router = create_appservice_router(hs_token=SecretStr(HS_TOKEN), ingestor=ingestor)
    events = [
        json.dumps(text_event("$before", "one")),
        poison_event("$poison"),
        json.dumps(invite("$invite", "!elsewhere:office.test")),
        json.dumps(text_event("$after", "two")),
    ]
    body = ('{"events": [' + ", ".join(events) + "]}").encode()
    headers = {**AUTH, "Content-Type": "application/json"}
    async with serve_routers(router) as url, httpx.AsyncClient(base_url=url) as client:
        with caplog.at_level(logging.ERROR):
            first = await client.put(
                "/_matrix/app/v1/transactions/p1", content=body, headers=headers
            )
        again = await client.put("/_matrix/app/v1/transactions/p1", content=body, headers=headers)
    assert (first.status_code, first.json()) == (200, {})
    assert (again.status_code, again.json()) == (200, {})
    assert drained(inbox) == ["$before", "$after"]
    assert await store.transaction_seen("p1")
    assert ingestor.skipped.by_path == {"matrix_push": 2}
    logged = sorted(r.getMessage() for r in caplog.records if "skipped inbound" in r.getMessage())
    assert len(logged) == 2
    assert "$invite" in logged[0] and "refused to join" in logged[0]
    assert "$poison" in logged[1] and "MalformedEventError" in logged[1]


async def test_the_bot_or_a_stranger_leaving_a_room_changes_no_dm(tmp_path: Path) -> None:
    """The bot leaves a stranger's room, a stranger leaves a group: no DM is affected (this
    raised KeyError and the transaction was retried for ever). Lee leaving his DM forgets it."""
    store = SqliteEventStore(tmp_path / "events.db")
    normalizer = EventNormalizer(CONFIG, {})
    directory = RoomDirectory(CONFIG, store, normalizer.rooms)
    await directory.set_dm("lee", "!lee-dm:office.test")
    # Member events need no homeserver: the client is never called for them.
    client = MatrixClient("http://127.0.0.1:9", "unused")

    def leave(user: str, room: str) -> dict[str, Any]:
        return {
            "type": "m.room.member",
            "event_id": f"$leave-{user}-{room}",
            "sender": user,
            "state_key": user,
            "content": {"membership": "leave"},
        }

    try:
        await directory.observe(client, "!stranger:office.test", leave(BOT, "s"))
        await directory.observe(client, "!group:office.test", leave("@eve:else.where", "g"))
        await directory.flush()
        assert directory.dm_of("lee") == "!lee-dm:office.test"
        await directory.observe(client, "!lee-dm:office.test", leave("@lee:office.test", "d"))
        await directory.flush()
        assert directory.dm_of("lee") is None
        assert await store.dm_rooms() == {}
    finally:
        await client.aclose()
        await store.close()


async def test_a_poison_event_or_room_in_sync_is_skipped_and_the_poller_advances(
    store: SqliteEventStore, inbox: asyncio.Queue[InboundMessage]
) -> None:
    """/sync answers a room that is not an object and a poison event between two good ones:
    the good ones are delivered and the position advances (before, the round failed and was
    retried for ever)."""
    answer = (
        '{"next_batch": "s2", "rooms": {"join": {"!broken:office.test": 7, '
        '"!dm:office.test": {"timeline": {"events": ['
        + ", ".join(
            [
                json.dumps(text_event("$before", "one")),
                poison_event("$poison"),
                json.dumps(text_event("$after", "two")),
            ]
        )
        + "]}}}}}"
    )
    homeserver = FastAPI()

    @homeserver.get("/_matrix/client/v3/sync")
    async def sync() -> Any:
        from fastapi.responses import Response

        return Response(answer, media_type="application/json")

    ingestor = EventIngestor(store, EventNormalizer(CONFIG, {}), inbox.put)
    await store.accept([], sync_key="pull", sync_token="s1")  # not the first run
    async with serve_asgi(homeserver) as url, MatrixClient(url, "tok") as client:
        poller = SyncPoller(client, ingestor, sync_key="pull", own_user_id="@sync:office.test")
        await poller.sync_once()
    assert drained(inbox) == ["$before", "$after"]
    assert await store.sync_token("pull") == "s2"
    assert ingestor.skipped.by_path == {"matrix_sync": 2}


async def test_a_transaction_met_by_a_closed_homeserver_connection_is_taken_again_not_skipped(
    serve_routers: ServeRouters,
    store: SqliteEventStore,
    inbox: asyncio.Queue[InboundMessage],
) -> None:
    """Stopping mid-batch (the Matrix client already closed under the room bookkeeping) is no
    event's fault: the transaction is refused, so the homeserver brings it again, and its
    events are handled then (a stop lost a DM's bookkeeping for good before)."""
    closing = MatrixClient("http://127.0.0.1:9", "token")
    await closing.aclose()
    joins: list[str] = []

    async def on_invite(room_id: str, user: str, event: Mapping[str, Any]) -> None:
        if not joins:
            joins.append("stopped")
            await closing.request("POST", f"/_matrix/client/v3/join/{room_id}")
        joins.append(room_id)

    ingestor = EventIngestor(store, EventNormalizer(CONFIG, {}), inbox.put, on_invite=on_invite)
    router = create_appservice_router(hs_token=SecretStr(HS_TOKEN), ingestor=ingestor)
    events = [json.dumps(invite("$invite", "!dm:office.test")), json.dumps(text_event("$hi", "hi"))]
    body = ('{"events": [' + ", ".join(events) + "]}").encode()
    headers = {**AUTH, "Content-Type": "application/json"}
    async with serve_routers(router) as url, httpx.AsyncClient(base_url=url) as client:
        first = await client.put("/_matrix/app/v1/transactions/t1", content=body, headers=headers)
        assert first.status_code == 500
        assert not await store.transaction_seen("t1")
        again = await client.put("/_matrix/app/v1/transactions/t1", content=body, headers=headers)
    assert again.status_code == 200
    assert joins == ["stopped", "!dm:office.test"]
    assert ingestor.skipped.total == 0
    assert drained(inbox) == ["$hi"]
