"""Telegram webhook contract over a real uvicorn server: secret token, dedup, order, caps."""

from __future__ import annotations

import asyncio
import json
from typing import Any

import httpx
import pytest
from pydantic import SecretStr

from assistantx.adapters.messenger.matrix import SqliteEventStore
from assistantx.adapters.messenger.webhooks import create_telegram_router, verify_telegram_secret
from assistantx.core.ports.messenger import InboundMessage
from messenger.conftest import ServeRouters

SECRET = "s3cr3t-Token_for-webhook"
PATH = "/webhooks/telegram"
HEADERS = {"X-Telegram-Bot-Api-Secret-Token": SECRET}


def update(
    update_id: int, text: str, *, user: int = 1001, chat: dict[str, Any] | None = None
) -> dict[str, Any]:
    return {
        "update_id": update_id,
        "message": {
            "message_id": update_id * 10,
            "from": {"id": user, "is_bot": False, "first_name": "Lee"},
            "chat": chat or {"id": user, "type": "private"},
            "date": 1700000000 + update_id,
            "text": text,
        },
    }


@pytest.fixture
def router(store: SqliteEventStore, inbox: asyncio.Queue[InboundMessage]) -> Any:
    return create_telegram_router(
        secret_token=SecretStr(SECRET),
        store=store,
        inbox=inbox,
        people={"1001": "lee", "1002": "zhang"},
        groups={"-100555": "printing"},
        max_body_bytes=2048,
    )


def test_secret_comparison() -> None:
    assert verify_telegram_secret(SECRET, SECRET)
    assert not verify_telegram_secret(SECRET, SECRET[:-1])
    assert not verify_telegram_secret(SECRET, None)


async def test_updates_are_queued_in_order_and_repeats_dropped(
    serve_routers: ServeRouters, router: Any, inbox: asyncio.Queue[InboundMessage]
) -> None:
    async with serve_routers(router) as url, httpx.AsyncClient(base_url=url) as client:
        for update_id, text in [(7, "one"), (8, "two"), (7, "one"), (9, "three"), (8, "two")]:
            response = await client.post(PATH, json=update(update_id, text), headers=HEADERS)
            assert response.status_code == 200
    got = [inbox.get_nowait() for _ in range(inbox.qsize())]
    assert [(m.event_id, m.text) for m in got] == [("7", "one"), ("8", "two"), ("9", "three")]
    assert {(m.platform, str(m.chat), m.sender) for m in got} == {("telegram", "dm:lee", "lee")}
    assert got[0].time.timestamp() == 1700000007


async def test_group_chat_document_becomes_a_file_attachment(
    serve_routers: ServeRouters, router: Any, inbox: asyncio.Queue[InboundMessage]
) -> None:
    payload = update(20, "", user=1002, chat={"id": -100555, "type": "supergroup"})
    payload["message"].pop("text")
    payload["message"]["caption"] = "the signed form"
    payload["message"]["document"] = {
        "file_id": "BQACAgI",
        "file_name": "form.pdf",
        "mime_type": "application/pdf",
    }
    async with serve_routers(router) as url, httpx.AsyncClient(base_url=url) as client:
        assert (await client.post(PATH, json=payload, headers=HEADERS)).status_code == 200
    message = inbox.get_nowait()
    assert (str(message.chat), message.sender, message.text) == (
        "group:printing",
        "zhang",
        "the signed form",
    )
    assert [(a.kind, a.name, a.mime, a.ref) for a in message.attachments] == [
        ("file", "form.pdf", "application/pdf", "telegram:BQACAgI")
    ]


@pytest.mark.parametrize("headers", [{}, {"X-Telegram-Bot-Api-Secret-Token": "guess"}])
async def test_missing_or_wrong_secret_is_refused(
    serve_routers: ServeRouters,
    router: Any,
    inbox: asyncio.Queue[InboundMessage],
    headers: dict[str, str],
) -> None:
    async with serve_routers(router) as url, httpx.AsyncClient(base_url=url) as client:
        response = await client.post(PATH, json=update(1, "let me in"), headers=headers)
    assert response.status_code == 401
    assert inbox.empty()


async def test_oversized_and_malformed_updates(
    serve_routers: ServeRouters, router: Any, inbox: asyncio.Queue[InboundMessage]
) -> None:
    async with serve_routers(router) as url, httpx.AsyncClient(base_url=url) as client:
        too_big = await client.post(PATH, json=update(2, "x" * 4000), headers=HEADERS)
        no_id = await client.post(PATH, content=json.dumps({"message": {}}), headers=HEADERS)
        junk = await client.post(PATH, content=b"\xff\xfe", headers=HEADERS)
    assert (too_big.status_code, no_id.status_code, junk.status_code) == (413, 400, 400)
    assert inbox.empty()


MALFORMED_MESSAGES: list[tuple[str, Any]] = [
    ("message", "not an object"),
    ("from", 5),
    ("chat", "private"),
    ("photo", [1, 2]),
    ("photo", [{"file_id": "x", "file_size": "big"}]),
    ("date", 10**20),
]


@pytest.mark.parametrize(("field", "value"), MALFORMED_MESSAGES)
async def test_authenticated_but_malformed_updates_get_400_and_queue_nothing(
    serve_routers: ServeRouters,
    router: Any,
    inbox: asyncio.Queue[InboundMessage],
    field: str,
    value: Any,
) -> None:
    payload = update(30, "hello")
    if field == "message":
        payload["message"] = value
    else:
        payload["message"][field] = value
    async with serve_routers(router) as url, httpx.AsyncClient(base_url=url) as client:
        response = await client.post(PATH, json=payload, headers=HEADERS)
    assert response.status_code == 400, response.text
    assert response.json()["error"]
    assert inbox.empty()
