"""Matrix events → ``InboundMessage``: sender user → person, room → chat, content → text and
attachments, ``origin_server_ts`` → time.

A room listed among the office's groups is that group's chat; any other room is a DM with the
sender. Only ``m.room.message`` events from people count: the assistant's own messages, edits,
encrypted media and state events are dropped here (with a reason at DEBUG).
"""

from __future__ import annotations

import logging
from collections.abc import Mapping
from datetime import UTC, datetime
from typing import Any

from assistantx.adapters.messenger.base import Attachment, ChatRef, InboundMessage
from assistantx.adapters.messenger.matrix.config import MatrixConfig

logger = logging.getLogger(__name__)

PLATFORM = "matrix"
_TEXT_TYPES = frozenset({"m.text", "m.notice", "m.emote"})
_MEDIA_KINDS = {"m.image": "image", "m.file": "file"}


class EventNormalizer:
    """Knows the office's people and group rooms; turns one event into one message or None."""

    def __init__(self, config: MatrixConfig, group_rooms: Mapping[str, str]) -> None:
        self._config = config
        self._group_rooms = dict(group_rooms)  # room id → group id
        self._own = config.own_user_ids()

    def set_group_rooms(self, group_rooms: Mapping[str, str]) -> None:
        self._group_rooms = dict(group_rooms)

    def is_own(self, user_id: str) -> bool:
        return user_id in self._own

    def normalize(self, room_id: str, event: Mapping[str, Any]) -> InboundMessage | None:
        event_id = event.get("event_id")
        sender = event.get("sender")
        content = event.get("content")
        if event.get("type") != "m.room.message" or not isinstance(event_id, str):
            return None
        if not isinstance(sender, str) or sender in self._own:
            return None
        if not isinstance(content, dict) or "msgtype" not in content:
            logger.debug("dropping %s: redacted or malformed", event_id)
            return None
        relation = content.get("m.relates_to")
        if isinstance(relation, dict) and relation.get("rel_type") == "m.replace":
            logger.debug("dropping %s: an edit of an earlier message", event_id)
            return None
        person = self._config.person_of(sender)
        if person is None:
            if not self._config.accept_unknown_senders:
                logger.info("dropping %s from %s: not a person of the office", event_id, sender)
                return None
            person = sender
        parsed = _text_and_attachments(event_id, content)
        if parsed is None:
            return None
        text, attachments = parsed
        sent = _event_time(event)
        if sent is None:
            # Skipped, not failed: a failing transaction would be pushed again for ever.
            logger.warning("dropping %s: origin_server_ts is out of range", event_id)
            return None
        group = self._group_rooms.get(room_id)
        chat = ChatRef(kind="group", id=group) if group else ChatRef(kind="dm", id=person)
        return InboundMessage(
            platform=PLATFORM,
            event_id=event_id,
            chat=chat,
            sender=person,
            text=text,
            attachments=attachments,
            time=sent,
        )


def _text_and_attachments(
    event_id: str, content: Mapping[str, Any]
) -> tuple[str, list[Attachment]] | None:
    msgtype = content.get("msgtype")
    body = content.get("body")
    body = body if isinstance(body, str) else ""
    if msgtype in _TEXT_TYPES:
        return body, []
    kind = _MEDIA_KINDS.get(str(msgtype))
    if kind is None:
        logger.debug("dropping %s: msgtype %r is not supported", event_id, msgtype)
        return None
    url = content.get("url")
    if not isinstance(url, str) or not url.startswith("mxc://"):
        # End-to-end encrypted media carries "file" instead of "url"; we cannot decrypt it.
        logger.warning("dropping %s: %s without a plain mxc:// url", event_id, msgtype)
        return None
    info = content.get("info")
    mime = info.get("mimetype") if isinstance(info, dict) else None
    filename = content.get("filename")
    # Since Matrix 1.10 a "filename" next to a different "body" makes the body a caption.
    if isinstance(filename, str) and filename and filename != body:
        name, caption = filename, body
    else:
        name, caption = body or "attachment", ""
    attachment = Attachment(
        kind="image" if kind == "image" else "file",
        name=name,
        mime=mime if isinstance(mime, str) and mime else "application/octet-stream",
        ref=url,
    )
    return caption, [attachment]


def _event_time(event: Mapping[str, Any]) -> datetime | None:
    """When the event was sent (now when the server left it out); None when out of range."""
    ts = event.get("origin_server_ts")
    if not isinstance(ts, int | float):
        return datetime.now(UTC)
    try:
        return datetime.fromtimestamp(ts / 1000, tz=UTC)
    except (OverflowError, OSError, ValueError):
        return None
