"""Inbound Telegram Bot API webhook.

Telegram sends the secret given to ``setWebhook`` in ``X-Telegram-Bot-Api-Secret-Token``; it is
compared in constant time before the body is read. The body is capped (413). Each update is
stored under its ``update_id`` (Telegram repeats an update until it gets a 2xx; the store drops
the repeat) and queued. Updates are taken in one at a time; Telegram sends them in
``update_id`` order when the webhook is set with ``max_connections=1`` (recommended), and an
update older than the newest one seen is still delivered but logged as out of order.

Telegram user ids map to person ids, chat ids to group ids; a private chat is a DM with the
author. Photos and documents become attachments referenced as ``telegram:<file_id>``.
"""

from __future__ import annotations

import asyncio
import hmac
import json
import logging
from collections.abc import Mapping
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

PLATFORM = "telegram"
SECRET_HEADER = "x-telegram-bot-api-secret-token"
DEFAULT_MAX_BODY_BYTES = 1024 * 1024


def verify_telegram_secret(expected: str, presented: str | None) -> bool:
    """Whether the request carries the webhook's secret token (constant-time compare)."""
    if presented is None:
        return False
    return hmac.compare_digest(expected.encode(), presented.encode())


def _attachments(message: Mapping[str, Any]) -> list[Attachment]:
    found: list[Attachment] = []
    photos = message.get("photo")
    if isinstance(photos, list) and photos:
        if not all(isinstance(p, dict) and isinstance(p.get("file_size", 0), int) for p in photos):
            raise MalformedBodyError("'photo' is not a list of PhotoSize objects")
        largest = max(photos, key=lambda p: int(p.get("file_size", 0) or 0))
        found.append(
            Attachment(
                kind="image",
                name="photo.jpg",
                mime="image/jpeg",
                ref=f"telegram:{largest.get('file_id')}",
            )
        )
    document = message.get("document")
    if isinstance(document, dict):
        found.append(
            Attachment(
                kind="file",
                name=str(document.get("file_name") or "document"),
                mime=str(document.get("mime_type") or "application/octet-stream"),
                ref=f"telegram:{document.get('file_id')}",
            )
        )
    return found


def normalize_telegram_update(
    update: Mapping[str, Any], people: Mapping[str, str], groups: Mapping[str, str]
) -> InboundMessage | None:
    """A ``message`` update → a message, or None for other updates and strangers;
    MalformedBodyError when a field is not of the type the Bot API documents."""
    message = update.get("message")
    if message is None:
        return None
    if not isinstance(message, dict):
        raise MalformedBodyError("'message' is not a Message object")
    author = message.get("from") or {}
    chat = message.get("chat") or {}
    if not isinstance(author, dict) or not isinstance(chat, dict):
        raise MalformedBodyError("'from' and 'chat' of a message are objects")
    if author.get("is_bot"):
        return None
    person = people.get(str(author.get("id")))
    if person is None:
        logger.info(
            "dropping update %s: author is not a person of the office", update.get("update_id")
        )
        return None
    if chat.get("type") == "private":
        ref = ChatRef(kind="dm", id=person)
    elif str(chat.get("id")) in groups:
        ref = ChatRef(kind="group", id=groups[str(chat.get("id"))])
    else:
        logger.info(
            "dropping update %s: chat %s is not an office group",
            update.get("update_id"),
            chat.get("id"),
        )
        return None
    sent = message.get("date")
    return InboundMessage(
        platform=PLATFORM,
        event_id=str(update["update_id"]),
        chat=ref,
        sender=person,
        text=str(message.get("text") or message.get("caption") or ""),
        attachments=_attachments(message),
        time=timestamp_utc(sent) if isinstance(sent, int) else datetime.now(UTC),
    )


def create_telegram_router(
    *,
    secret_token: SecretStr,
    store: EventStore,
    inbox: asyncio.Queue[InboundMessage],
    people: Mapping[str, str],
    groups: Mapping[str, str] | None = None,
    path: str = "/webhooks/telegram",
    max_body_bytes: int = DEFAULT_MAX_BODY_BYTES,
) -> APIRouter:
    """The webhook endpoint; ``people`` maps Telegram user ids, ``groups`` chat ids."""
    router = APIRouter(tags=["telegram"])
    group_chats = dict(groups or {})
    lock = asyncio.Lock()
    newest: list[int] = []  # the highest update_id taken in, once there is one

    @router.post(path)
    async def telegram_update(request: Request) -> JSONResponse:
        if not verify_telegram_secret(
            secret_token.get_secret_value(), request.headers.get(SECRET_HEADER)
        ):
            logger.warning("refused a Telegram request from %s: bad secret", request.client)
            return JSONResponse({"error": "invalid secret token"}, status_code=401)
        try:
            body = await read_capped_body(request, max_body_bytes)
        except BodyTooLargeError as exc:
            return JSONResponse({"error": str(exc)}, status_code=413)
        try:
            update = json.loads(body)
        except ValueError:
            update = None
        if not isinstance(update, dict) or not isinstance(update.get("update_id"), int):
            return JSONResponse({"error": "an update is a JSON object with update_id"}, 400)
        update_id: int = update["update_id"]
        async with lock:
            if newest and update_id < newest[0]:
                logger.warning("Telegram update %d arrived after %d", update_id, newest[0])
            try:
                message = normalize_telegram_update(update, people, group_chats)
            except MalformedBodyError as exc:
                return JSONResponse({"error": str(exc)}, status_code=400)
            if message is not None:
                try:
                    await accept_and_enqueue(store, inbox, message)
                except Exception:
                    logger.exception("Telegram update %d not accepted", update_id)
                    return JSONResponse({"error": "not accepted; retry"}, status_code=500)
            if not newest or update_id > newest[0]:
                newest[:] = [update_id]
        return JSONResponse({})

    return router
