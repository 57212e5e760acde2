"""Inbound Slack Events API webhook.

Every request is authenticated on its raw body before anything parses it: Slack signs
``v0:{X-Slack-Request-Timestamp}:{body}`` with HMAC-SHA256 under the app's signing secret and
sends ``v0=<hex>`` in ``X-Slack-Signature``; a timestamp more than 300 s away from our clock
is refused as a replay. The body is capped (413). ``url_verification`` is answered with its
challenge. A message event is normalized, stored under its ``event_id`` (Slack retries a
delivery it thinks failed; the store drops the repeat) and queued; the answer is immediate,
the agents handle the inbox asynchronously.

Slack user ids map to person ids, and channel ids to group ids; DMs (``channel_type: im``)
become a DM with the author. Bot messages and edits/deletions (subtypes) are acknowledged and
dropped.
"""

from __future__ import annotations

import asyncio
import hashlib
import hmac
import json
import logging
import time
from collections.abc import Callable, Mapping
from datetime import UTC, datetime
from typing import Any

from fastapi import APIRouter, Request
from fastapi.responses import JSONResponse
from pydantic import SecretStr

from assistantx.adapters.messenger.matrix.store import EventStore
from assistantx.adapters.messenger.webhooks._accept import accept_and_enqueue
from assistantx.adapters.messenger.webhooks.body import (
    BodyTooLargeError,
    MalformedBodyError,
    read_capped_body,
    timestamp_utc,
)
from assistantx.core.ports.messenger import Attachment, ChatRef, InboundMessage

logger = logging.getLogger(__name__)

PLATFORM = "slack"
SIGNATURE_VERSION = "v0"
DEFAULT_TOLERANCE_S = 300.0
DEFAULT_MAX_BODY_BYTES = 1024 * 1024
_ACCEPTED_SUBTYPES = frozenset({None, "file_share"})


class SlackSignatureError(Exception):
    """The request is not provably from Slack (missing, stale or wrong signature)."""


def slack_signature(signing_secret: str, timestamp: str, body: bytes) -> str:
    """The ``X-Slack-Signature`` value Slack computes for this request."""
    base = f"{SIGNATURE_VERSION}:{timestamp}:".encode() + body
    digest = hmac.new(signing_secret.encode(), base, hashlib.sha256).hexdigest()
    return f"{SIGNATURE_VERSION}={digest}"


def verify_slack_request(
    signing_secret: str,
    *,
    timestamp: str | None,
    signature: str | None,
    body: bytes,
    now_s: float,
    tolerance_s: float = DEFAULT_TOLERANCE_S,
) -> None:
    """Raise ``SlackSignatureError`` unless the signature is right and the timestamp fresh."""
    if not timestamp or not signature:
        raise SlackSignatureError("missing X-Slack-Request-Timestamp or X-Slack-Signature")
    try:
        sent_at = int(timestamp)
    except ValueError as exc:
        raise SlackSignatureError("X-Slack-Request-Timestamp is not an integer") from exc
    if abs(now_s - sent_at) > tolerance_s:
        raise SlackSignatureError(f"timestamp {sent_at} is more than {tolerance_s:.0f}s off")
    expected = slack_signature(signing_secret, timestamp, body)
    if not hmac.compare_digest(expected.encode(), signature.encode()):
        raise SlackSignatureError("signature mismatch")


def normalize_slack_event(
    envelope: Mapping[str, Any], people: Mapping[str, str], channels: Mapping[str, str]
) -> InboundMessage | None:
    """An ``event_callback`` envelope → a message, or None for anything we do not handle;
    MalformedBodyError when a field is not of the type Slack documents."""
    event = envelope.get("event")
    event_id = envelope.get("event_id")
    if not isinstance(event, dict) or not isinstance(event_id, str):
        raise MalformedBodyError("an event_callback has an 'event' object and an 'event_id'")
    if event.get("type") != "message" or event.get("subtype") not in _ACCEPTED_SUBTYPES:
        return None
    if event.get("bot_id"):
        return None  # our own (or another bot's) message
    person = people.get(str(event.get("user")))
    if person is None:
        logger.info("dropping Slack event %s: author is not a person of the office", event_id)
        return None
    channel = str(event.get("channel"))
    if event.get("channel_type") == "im":
        chat = ChatRef(kind="dm", id=person)
    elif channel in channels:
        chat = ChatRef(kind="group", id=channels[channel])
    else:
        logger.info("dropping Slack event %s: channel %s is not an office group", event_id, channel)
        return None
    files = event.get("files", [])
    if not isinstance(files, list):
        raise MalformedBodyError("'files' is not a list")
    attachments = [
        Attachment(
            kind="image" if str(f.get("mimetype", "")).startswith("image/") else "file",
            name=str(f.get("name") or f.get("id")),
            mime=str(f.get("mimetype") or "application/octet-stream"),
            ref=f.get("url_private"),
        )
        for f in files
        if isinstance(f, dict)
    ]
    ts = event.get("ts")
    if ts is None:
        sent = datetime.now(UTC)
    else:
        try:
            seconds = float(ts)
        except (TypeError, ValueError) as exc:
            raise MalformedBodyError(f"'ts' {ts!r} is not a Slack timestamp") from exc
        sent = timestamp_utc(seconds)
    return InboundMessage(
        platform=PLATFORM,
        event_id=event_id,
        chat=chat,
        sender=person,
        text=str(event.get("text") or ""),
        attachments=attachments,
        time=sent,
    )


def create_slack_router(
    *,
    signing_secret: SecretStr,
    store: EventStore,
    inbox: asyncio.Queue[InboundMessage],
    people: Mapping[str, str],
    channels: Mapping[str, str] | None = None,
    path: str = "/webhooks/slack/events",
    max_body_bytes: int = DEFAULT_MAX_BODY_BYTES,
    clock: Callable[[], float] = time.time,
) -> APIRouter:
    """The Events API endpoint; ``people`` maps Slack user ids, ``channels`` channel ids."""
    router = APIRouter(tags=["slack"])
    groups = dict(channels or {})

    @router.post(path)
    async def slack_events(request: Request) -> JSONResponse:
        try:
            body = await read_capped_body(request, max_body_bytes)
        except BodyTooLargeError as exc:
            return JSONResponse({"error": str(exc)}, status_code=413)
        try:
            verify_slack_request(
                signing_secret.get_secret_value(),
                timestamp=request.headers.get("x-slack-request-timestamp"),
                signature=request.headers.get("x-slack-signature"),
                body=body,
                now_s=clock(),
            )
        except SlackSignatureError as exc:
            logger.warning("refused a Slack request from %s: %s", request.client, exc)
            return JSONResponse({"error": "invalid signature"}, status_code=401)
        try:
            envelope = json.loads(body)
        except ValueError:
            envelope = None
        if not isinstance(envelope, dict):
            return JSONResponse({"error": "body is not a JSON object"}, status_code=400)
        kind = envelope.get("type")
        if kind == "url_verification":
            return JSONResponse({"challenge": str(envelope.get("challenge", ""))})
        if kind == "event_callback":
            try:
                message = normalize_slack_event(envelope, people, groups)
            except MalformedBodyError as exc:
                return JSONResponse({"error": str(exc)}, status_code=400)
            if message is not None:
                try:
                    new = await accept_and_enqueue(store, inbox, message)
                except Exception:
                    logger.exception("Slack event %s not accepted", message.event_id)
                    return JSONResponse({"error": "not accepted; retry"}, status_code=500)
                if not new:
                    logger.debug("Slack event %s already accepted", message.event_id)
        return JSONResponse({})

    return router
