"""Slack Events API contract: signed, forged, stale, replayed and oversized requests, over a
real uvicorn server."""

from __future__ import annotations

import asyncio
import json
import time
from typing import Any

import httpx
import pytest
from pydantic import SecretStr

from assistantx.adapters.messenger.matrix import SqliteEventStore
from assistantx.adapters.messenger.webhooks import (
    SlackSignatureError,
    create_slack_router,
    slack_signature,
    verify_slack_request,
)
from assistantx.core.ports.messenger import InboundMessage
from messenger.conftest import ServeRouters

SECRET = "8f742231b10e8888abcd99yyyzzz85a5"
PATH = "/webhooks/slack/events"


def signed_headers(body: bytes, *, secret: str = SECRET, at: float | None = None) -> dict[str, str]:
    timestamp = str(int(time.time() if at is None else at))
    return {
        "X-Slack-Request-Timestamp": timestamp,
        "X-Slack-Signature": slack_signature(secret, timestamp, body),
        "Content-Type": "application/json",
    }


def message_envelope(event_id: str = "Ev01", text: str = "where is my parcel?") -> dict[str, Any]:
    return {
        "type": "event_callback",
        "event_id": event_id,
        "event_time": 1700000000,
        "event": {
            "type": "message",
            "user": "U0LEE",
            "channel": "D0DM",
            "channel_type": "im",
            "text": text,
            "ts": "1700000000.000200",
        },
    }


@pytest.fixture
def router(store: SqliteEventStore, inbox: asyncio.Queue[InboundMessage]) -> Any:
    return create_slack_router(
        signing_secret=SecretStr(SECRET),
        store=store,
        inbox=inbox,
        people={"U0LEE": "lee", "U0ZHANG": "zhang"},
        channels={"C0PRINT": "printing"},
        max_body_bytes=4096,
    )


def test_verify_matches_slacks_documented_example() -> None:
    # The worked example of Slack's "Verifying requests from Slack" guide.
    body = (
        b"token=xyzz0WbapA4vBCDEFasx0q6G&team_id=T1DC2JH3J&team_domain=testteamnow&"
        b"channel_id=G8PSS9T3V&channel_name=foobar&user_id=U2CERLKJA&user_name=roadrunner&"
        b"command=%2Fwebhook-collect&text=&response_url=https%3A%2F%2Fhooks.slack.com%2F"
        b"commands%2FT1DC2JH3J%2F397700885554%2F96rGlfmibIGlgcZRskXaIFfN&"
        b"trigger_id=398738663015.47445629121.803a0bc887a14d10d2c447fce8b6703c"
    )
    signature = "v0=a2114d57b48eac39b9ad189dd8316235a7b4a8d21a10bd27519666489c69b503"
    verify_slack_request(
        SECRET, timestamp="1531420618", signature=signature, body=body, now_s=1531420618
    )
    with pytest.raises(SlackSignatureError, match="off"):
        verify_slack_request(
            SECRET, timestamp="1531420618", signature=signature, body=body, now_s=1531420919
        )
    with pytest.raises(SlackSignatureError, match="mismatch"):
        verify_slack_request(
            SECRET, timestamp="1531420618", signature=signature, body=body + b"x", now_s=1531420618
        )


async def test_signed_message_is_queued_once_even_when_slack_retries(
    serve_routers: ServeRouters, router: Any, inbox: asyncio.Queue[InboundMessage]
) -> None:
    body = json.dumps(message_envelope()).encode()
    async with serve_routers(router) as url, httpx.AsyncClient(base_url=url) as client:
        first = await client.post(PATH, content=body, headers=signed_headers(body))
        retry = await client.post(
            PATH, content=body, headers={**signed_headers(body), "X-Slack-Retry-Num": "1"}
        )
    assert (first.status_code, retry.status_code) == (200, 200)
    assert inbox.qsize() == 1
    message = inbox.get_nowait()
    assert (message.platform, message.event_id, str(message.chat), message.sender) == (
        "slack",
        "Ev01",
        "dm:lee",
        "lee",
    )
    assert message.text == "where is my parcel?"
    assert message.time.timestamp() == pytest.approx(1700000000.0002)


async def test_channel_message_maps_to_its_group(
    serve_routers: ServeRouters, router: Any, inbox: asyncio.Queue[InboundMessage]
) -> None:
    envelope = message_envelope("Ev02", "I can sign it")
    envelope["event"].update(user="U0ZHANG", channel="C0PRINT", channel_type="channel")
    body = json.dumps(envelope).encode()
    async with serve_routers(router) as url, httpx.AsyncClient(base_url=url) as client:
        assert (
            await client.post(PATH, content=body, headers=signed_headers(body))
        ).status_code == 200
    message = inbox.get_nowait()
    assert (str(message.chat), message.sender) == ("group:printing", "zhang")


@pytest.mark.parametrize(
    "tamper",
    ["forged-signature", "wrong-secret", "stale", "missing-headers", "body-changed"],
)
async def test_unauthenticated_requests_are_refused_and_queue_nothing(
    serve_routers: ServeRouters, router: Any, inbox: asyncio.Queue[InboundMessage], tamper: str
) -> None:
    body = json.dumps(message_envelope()).encode()
    headers = signed_headers(body)
    sent = body
    if tamper == "forged-signature":
        headers["X-Slack-Signature"] = "v0=" + "0" * 64
    elif tamper == "wrong-secret":
        headers = signed_headers(body, secret="not-the-secret")
    elif tamper == "stale":
        headers = signed_headers(body, at=time.time() - 301)
    elif tamper == "missing-headers":
        headers = {"Content-Type": "application/json"}
    else:
        sent = body.replace(b"parcel", b"wallet")
    async with serve_routers(router) as url, httpx.AsyncClient(base_url=url) as client:
        response = await client.post(PATH, content=sent, headers=headers)
    assert response.status_code == 401
    assert inbox.empty()


async def test_url_verification_needs_a_signature_and_echoes_the_challenge(
    serve_routers: ServeRouters, router: Any
) -> None:
    body = json.dumps({"type": "url_verification", "challenge": "3eZbrw1aB"}).encode()
    async with serve_routers(router) as url, httpx.AsyncClient(base_url=url) as client:
        ok = await client.post(PATH, content=body, headers=signed_headers(body))
        forged = await client.post(PATH, content=body, headers={"X-Slack-Signature": "v0=00"})
    assert ok.json() == {"challenge": "3eZbrw1aB"}
    assert forged.status_code == 401


async def test_oversized_and_malformed_bodies(
    serve_routers: ServeRouters, router: Any, inbox: asyncio.Queue[InboundMessage]
) -> None:
    big = json.dumps(message_envelope(text="x" * 5000)).encode()
    junk = b"{not json"
    async with serve_routers(router) as url, httpx.AsyncClient(base_url=url) as client:
        too_big = await client.post(PATH, content=big, headers=signed_headers(big))
        malformed = await client.post(PATH, content=junk, headers=signed_headers(junk))
    assert too_big.status_code == 413
    assert malformed.status_code == 400
    assert inbox.empty()


async def test_bot_messages_and_strangers_are_acknowledged_but_dropped(
    serve_routers: ServeRouters, router: Any, inbox: asyncio.Queue[InboundMessage]
) -> None:
    from_bot = message_envelope("Ev10")
    from_bot["event"]["bot_id"] = "B0ASSISTANT"
    stranger = message_envelope("Ev11")
    stranger["event"]["user"] = "U0NOBODY"
    async with serve_routers(router) as url, httpx.AsyncClient(base_url=url) as client:
        for envelope in (from_bot, stranger):
            body = json.dumps(envelope).encode()
            assert (
                await client.post(PATH, content=body, headers=signed_headers(body))
            ).status_code == 200
    assert inbox.empty()


MALFORMED_EVENTS: list[tuple[str, Any]] = [
    ("event", "not an object"),
    ("event_id", 42),
    ("files", 5),
    ("ts", [1]),
    ("ts", "soon"),
    ("ts", "1e300"),
]


@pytest.mark.parametrize(("field", "value"), MALFORMED_EVENTS)
async def test_signed_but_malformed_events_get_400_and_queue_nothing(
    serve_routers: ServeRouters,
    router: Any,
    inbox: asyncio.Queue[InboundMessage],
    field: str,
    value: Any,
) -> None:
    envelope = message_envelope()
    if field in ("event", "event_id"):
        envelope[field] = value
    else:
        envelope["event"][field] = value
    body = json.dumps(envelope).encode()
    async with serve_routers(router) as url, httpx.AsyncClient(base_url=url) as client:
        response = await client.post(PATH, content=body, headers=signed_headers(body))
    assert response.status_code == 400, response.text
    assert response.json()["error"]
    assert inbox.empty()
