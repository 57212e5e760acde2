"""The application-service router's contract over a real uvicorn server (no homeserver):
authentication, transaction dedup, malformed and oversized bodies."""

from __future__ import annotations

import asyncio
from typing import Any

import httpx
import pytest
from pydantic import SecretStr

from adapters.messenger.conftest import ServeRouters
from assistantx.adapters.messenger.matrix import (
    EventIngestor,
    EventNormalizer,
    MatrixConfig,
    SqliteEventStore,
    create_appservice_router,
)
from assistantx.core.ports.messenger import InboundMessage

HS_TOKEN = "hs-secret-token"
CONFIG = MatrixConfig(
    homeserver_url="http://127.0.0.1:9",
    server_name="office.test",
    as_token=SecretStr("as"),
    hs_token=SecretStr(HS_TOKEN),
    people={"lee": "@lee:office.test"},
)
AUTH = {"Authorization": f"Bearer {HS_TOKEN}"}


def text_event(event_id: str, body: str, sender: str = "@lee:office.test") -> dict[str, Any]:
    return {
        "type": "m.room.message",
        "event_id": event_id,
        "room_id": "!dm:office.test",
        "sender": sender,
        "origin_server_ts": 1700000000123,
        "content": {"msgtype": "m.text", "body": body},
    }


@pytest.fixture
def router(store: SqliteEventStore, inbox: asyncio.Queue[InboundMessage]) -> Any:
    ingestor = EventIngestor(store, EventNormalizer(CONFIG, {}), inbox.put)
    return create_appservice_router(hs_token=SecretStr(HS_TOKEN), ingestor=ingestor)


async def test_transactions_are_acknowledged_and_deduplicated(
    serve_routers: ServeRouters,
    router: Any,
    inbox: asyncio.Queue[InboundMessage],
    store: SqliteEventStore,
) -> None:
    txn = {
        "events": [
            text_event("$a", "one"),
            text_event("$b", "two"),
            text_event("$c", "mine", sender="@assistant:office.test"),
        ]
    }
    async with serve_routers(router) as url, httpx.AsyncClient(base_url=url) as client:
        first = await client.put("/_matrix/app/v1/transactions/1", json=txn, headers=AUTH)
        repeat = await client.put("/_matrix/app/v1/transactions/1", json=txn, headers=AUTH)
        # Another transaction carrying an already accepted event (e.g. seen by /sync) adds nothing.
        overlap = await client.put(
            "/_matrix/app/v1/transactions/2",
            json={"events": [text_event("$b", "two"), text_event("$d", "three")]},
            headers=AUTH,
        )
    assert [r.status_code for r in (first, repeat, overlap)] == [200, 200, 200]
    assert first.json() == {}
    got = [inbox.get_nowait() for _ in range(inbox.qsize())]
    assert [(m.event_id, m.text) for m in got] == [("$a", "one"), ("$b", "two"), ("$d", "three")]
    assert await store.transaction_seen("1") and await store.transaction_seen("2")
    assert got[0].time.timestamp() == pytest.approx(1700000000.123)


async def test_legacy_query_token_is_accepted(
    serve_routers: ServeRouters, router: Any, inbox: asyncio.Queue[InboundMessage]
) -> None:
    async with serve_routers(router) as url, httpx.AsyncClient(base_url=url) as client:
        response = await client.put(
            "/_matrix/app/v1/transactions/9",
            params={"access_token": HS_TOKEN},
            json={"events": [text_event("$q", "legacy")]},
        )
    assert response.status_code == 200
    assert inbox.get_nowait().text == "legacy"


@pytest.mark.parametrize(
    ("headers", "params", "status", "errcode"),
    [
        ({}, {}, 401, "M_UNAUTHORIZED"),
        ({"Authorization": "Bearer wrong"}, {}, 403, "M_FORBIDDEN"),
        ({"Authorization": "Basic " + HS_TOKEN}, {}, 403, "M_FORBIDDEN"),
        ({}, {"access_token": "wrong"}, 403, "M_FORBIDDEN"),
    ],
)
async def test_missing_or_forged_tokens_are_refused(
    serve_routers: ServeRouters,
    router: Any,
    inbox: asyncio.Queue[InboundMessage],
    store: SqliteEventStore,
    headers: dict[str, str],
    params: dict[str, str],
    status: int,
    errcode: str,
) -> None:
    async with serve_routers(router) as url, httpx.AsyncClient(base_url=url) as client:
        push = await client.put(
            "/_matrix/app/v1/transactions/5",
            json={"events": [text_event("$x", "forged")]},
            headers=headers,
            params=params,
        )
        ping = await client.post("/_matrix/app/v1/ping", json={}, headers=headers, params=params)
    assert (push.status_code, push.json()["errcode"]) == (status, errcode)
    assert ping.status_code == status
    assert inbox.empty()
    assert not await store.transaction_seen("5")


async def test_ping_user_and_room_queries(serve_routers: ServeRouters, router: Any) -> None:
    async with serve_routers(router) as url, httpx.AsyncClient(base_url=url) as client:
        ping = await client.post("/_matrix/app/v1/ping", json={"transaction_id": "p"}, headers=AUTH)
        user = await client.get("/_matrix/app/v1/users/@x:office.test", headers=AUTH)
        room = await client.get("/_matrix/app/v1/rooms/%23x:office.test", headers=AUTH)
    assert (ping.status_code, ping.json()) == (200, {})
    assert (user.status_code, user.json()["errcode"]) == (404, "M_NOT_FOUND")
    assert room.status_code == 404


async def test_malformed_and_oversized_transactions_are_not_acknowledged(
    serve_routers: ServeRouters,
    router: Any,
    inbox: asyncio.Queue[InboundMessage],
    store: SqliteEventStore,
) -> None:
    async with serve_routers(router) as url, httpx.AsyncClient(base_url=url) as client:
        junk = await client.put("/_matrix/app/v1/transactions/6", content=b"[1,", headers=AUTH)
        big = await client.put(
            "/_matrix/app/v1/transactions/7",
            json={"events": [text_event("$big", "x" * 5000)]},
            headers=AUTH,
        )
    assert (junk.status_code, junk.json()["errcode"]) == (400, "M_NOT_JSON")
    assert (big.status_code, big.json()["errcode"]) == (413, "M_TOO_LARGE")
    assert inbox.empty()
    assert not await store.transaction_seen("7")


async def test_an_event_with_an_absurd_timestamp_is_skipped_not_a_500(
    serve_routers: ServeRouters,
    router: Any,
    inbox: asyncio.Queue[InboundMessage],
    store: SqliteEventStore,
) -> None:
    absurd = text_event("$absurd", "from the far future")
    absurd["origin_server_ts"] = 10**22
    txn = {"events": [absurd, text_event("$fine", "hello")]}
    async with serve_routers(router) as url, httpx.AsyncClient(base_url=url) as client:
        response = await client.put("/_matrix/app/v1/transactions/40", json=txn, headers=AUTH)
    assert (response.status_code, response.json()) == (200, {})
    assert [m.event_id for m in [inbox.get_nowait() for _ in range(inbox.qsize())]] == ["$fine"]
    assert await store.transaction_seen("40")


async def test_matrix_transactions_have_their_own_size_limit_in_the_service(
    store: SqliteEventStore, inbox: asyncio.Queue[InboundMessage]
) -> None:
    """The service caps bodies at 64 KiB, but not the homeserver's pushes: they get Matrix's
    limit and a Matrix error body, which the homeserver understands."""
    from fastapi import FastAPI

    from assistantx.service.app import PATH_BODY_LIMITS
    from assistantx.service.body_limit import BodyLimit
    from helpers.servers import serve_asgi

    ingestor = EventIngestor(store, EventNormalizer(CONFIG, {}), inbox.put)
    app = FastAPI()
    app.include_router(create_appservice_router(hs_token=SecretStr(HS_TOKEN), ingestor=ingestor))

    @app.post("/v1/echo")
    async def echo() -> dict[str, str]:
        return {}

    app.add_middleware(BodyLimit, max_bytes=64 * 1024, paths=PATH_BODY_LIMITS)
    events = [text_event(f"$e{n}", "x" * 1000) for n in range(100)]  # ~120 KiB
    huge = b'{"events": [' + b" " * (17 * 1024 * 1024) + b"]}"
    async with serve_asgi(app) as url, httpx.AsyncClient(base_url=url, timeout=30) as client:
        big = await client.put(
            "/_matrix/app/v1/transactions/50", json={"events": events}, headers=AUTH
        )
        too_big = await client.put("/_matrix/app/v1/transactions/51", content=huge, headers=AUTH)
        other = await client.post("/v1/echo", content=b"x" * (65 * 1024))
    assert (big.status_code, big.json()) == (200, {})
    assert inbox.qsize() == 100
    assert (too_big.status_code, too_big.json()["errcode"]) == (413, "M_TOO_LARGE")
    assert other.status_code == 413 and other.json()["error"] == "payload_too_large"


async def test_a_streamed_push_over_the_limit_gets_a_matrix_413(
    serve_routers: ServeRouters,
    router: Any,
    inbox: asyncio.Queue[InboundMessage],
    store: SqliteEventStore,
) -> None:
    """Without a Content-Length (chunked) the body limit counts what arrives."""

    async def chunks() -> Any:
        yield b'{"events": ['
        for _ in range(10):
            yield b" " * 1000
        yield b"]}"

    async with serve_routers(router) as url, httpx.AsyncClient(base_url=url) as client:
        big = await client.put("/_matrix/app/v1/transactions/8", content=chunks(), headers=AUTH)
    assert (big.status_code, big.json()["errcode"]) == (413, "M_TOO_LARGE")
    assert "4096" in big.json()["error"]
    assert not await store.transaction_seen("8")


async def test_a_push_nested_too_deep_is_acknowledged_and_blocks_nothing(
    serve_routers: ServeRouters,
    store: SqliteEventStore,
    inbox: asyncio.Queue[InboundMessage],
) -> None:
    """1500 levels of nesting (a RecursionError in the parser) once answered a plain-text 500
    that the homeserver retried for ever; it is acknowledged in JSON and counted, and the next
    transaction is taken in."""
    ingestor = EventIngestor(store, EventNormalizer(CONFIG, {}), inbox.put)
    router = create_appservice_router(hs_token=SecretStr(HS_TOKEN), ingestor=ingestor)
    deep = b'{"events": [' + b"[" * 1500 + b"]" * 1500 + b"]}"
    async with serve_routers(router) as url, httpx.AsyncClient(base_url=url) as client:
        pushed = await client.put("/_matrix/app/v1/transactions/deep", content=deep, headers=AUTH)
        after = await client.put(
            "/_matrix/app/v1/transactions/next",
            json={"events": [text_event("$next", "still here")]},
            headers=AUTH,
        )
    assert (pushed.status_code, pushed.json()) == (200, {})
    assert (after.status_code, after.json()) == (200, {})
    assert inbox.get_nowait().event_id == "$next"
    assert ingestor.skipped.by_path == {"matrix_push": 1}
