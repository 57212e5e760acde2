"""Matrix events → ``InboundMessage`` (or a short answer the bot gives by itself).

Sender user → person, room → chat, content → text and attachments, ``origin_server_ts`` → time.

A room is a chat only when the bot knows what it is: a configured group's room, or the DM room
recorded for the sender. Messages in any other room (a "Lunch Club" someone invited the bot
to) are not for the assistant, so a request or answer written there never makes that room
anybody's DM, and nothing private is ever sent there.

What people expect of a Matrix bot (as maubot and the mautrix bridges do it):

- the bot's own messages and ``m.notice`` (other bots) are ignored, never answered;
- a rich reply's fallback quote is stripped; a reply to a question is that question's answer;
- a 👍/👎 reaction to a question is a "yes"/"no" answer; another reaction to the bot's message
  is acknowledged;
- an edit is answered with what the bot does about it (it keeps the original request);
- an encrypted message, a stranger's direct message and an over-long text each get a short
  answer in plain words instead of silence;
- a file is delivered as the sender's file, ``file:lee`` (``ports.messenger.persons_file``:
  the runtime reads it as the office's own name for it, ``script:lee``).

``interpret`` takes any JSON value as an event. What is not a message for the bot (wrong
types, missing fields, unknown kinds) gives no item; the one error it raises is
``MalformedEventError``, for an event whose text cannot be stored or sent on (a lone UTF-16
surrogate, which JSON allows and UTF-8 does not). The ingestor skips such an event alone.
"""

from __future__ import annotations

import logging
import re
from collections.abc import Mapping
from dataclasses import dataclass
from datetime import UTC, datetime
from typing import Any

from assistantx.adapters.messenger.matrix.config import MatrixConfig
from assistantx.core.errors import MessengerError
from assistantx.core.ports.messenger import Attachment, ChatRef, InboundMessage, persons_file

logger = logging.getLogger(__name__)

PLATFORM = "matrix"
MAX_TEXT_CHARS = 4000
"""As on REST (``POST /v1/instructions`` and ``/v1/messages`` take at most 4000 characters)."""

_TEXT_TYPES = frozenset({"m.text", "m.emote"})
_MEDIA_KINDS = {"m.image": "image", "m.file": "file"}
_YES = frozenset({"👍", "👍️", "✅", "✔️", "🆗"})
_NO = frozenset({"👎", "👎️", "❌", "✖️"})
_SKIN_TONES = re.compile("[\U0001f3fb-\U0001f3ff]")

ENCRYPTED_TEXT = (
    "I can't read encrypted messages here — please message me in an unencrypted DM "
    "(turn encryption off when you start the chat)."
)
ENCRYPTED_ROOM_TEXT = (
    "I can't take part in encrypted chats, so I left the one you invited me to. Please write "
    "to me here instead."
)
STRANGER_TEXT = (
    "Hello! I'm the assistant of this office and I only serve its people, so I can't help "
    "you here. Please ask someone from the office."
)
EDIT_TEXT = (
    "I saw your edit, but I keep working on your original message. If you want something "
    "else, send it as a new message."
)
TOO_LONG_TEXT = (
    "Your message is {length:,} characters long; I take at most {limit:,}. Please send a "
    "shorter one."
)
REACTION_TEXT = "Thanks for the {key}! If it answers my question, please reply in words."
FILE_TEXT = "I have your file {name}. If it goes with a request, tell me what to do with it."


class MalformedEventError(MessengerError):
    """An event whose text is not valid Unicode: it can be neither stored nor answered."""


@dataclass(frozen=True)
class AutoReply:
    """A short answer the bot sends by itself to ``room_id`` about event ``event_id``."""

    room_id: str
    event_id: str
    text: str


Normalized = InboundMessage | AutoReply


@dataclass
class Rooms:
    """What the bot knows about rooms and its own sent events (filled by the messenger)."""

    groups: dict[str, str]  # room id → group id
    dms: dict[str, str]  # room id → person id
    questions: dict[str, str]  # sent event id → question id ("" for a sent plain message)
    # False for a normalizer used on its own (tests, tools): any other room is the sender's DM.
    # The messenger, which records DM rooms, sets it True.
    strict: bool = False


class EventNormalizer:
    """Knows the office's people and rooms; turns one event into messages and answers."""

    def __init__(self, config: MatrixConfig, group_rooms: Mapping[str, str]) -> None:
        self._config = config
        self.rooms = Rooms(groups=dict(group_rooms), dms={}, questions={})
        self._own = config.own_user_ids()

    def set_group_rooms(self, group_rooms: Mapping[str, str]) -> None:
        self.rooms.groups = dict(group_rooms)

    def is_own(self, user_id: str) -> bool:
        return user_id in self._own

    def chat_of(self, room_id: str, person: str) -> ChatRef | None:
        """The chat ``room_id`` is for a message from ``person``; None: not the bot's business."""
        group = self.rooms.groups.get(room_id)
        if group is not None:
            return ChatRef(kind="group", id=group)
        if self.rooms.dms.get(room_id) == person or (
            not self.rooms.strict and room_id not in self.rooms.dms
        ):
            return ChatRef(kind="dm", id=person)
        return None

    def normalize(self, room_id: str, event: Mapping[str, Any]) -> InboundMessage | None:
        """The message in ``event`` for the inbox, if any (answers the bot gives are dropped)."""
        for item in self.interpret(room_id, event):
            if isinstance(item, InboundMessage):
                return item
        return None

    def interpret(self, room_id: str, event: Mapping[str, Any]) -> list[Normalized]:
        """The messages and answers ``event`` gives; ``MalformedEventError`` when its text
        cannot be represented (see the module's docstring)."""
        if not isinstance(event, Mapping):
            return []
        items = self._interpret(room_id, event)
        for item in items:
            _check_unicode(item)
        return items

    def _interpret(self, room_id: str, event: Mapping[str, Any]) -> list[Normalized]:
        event_id = event.get("event_id")
        sender = event.get("sender")
        content = event.get("content")
        kind = event.get("type")
        if not isinstance(event_id, str) or not isinstance(sender, str) or sender in self._own:
            return []
        if not isinstance(content, dict):
            return []
        person = self._config.person_of(sender)
        if person is None and self._config.accept_unknown_senders:
            person = sender
        if kind == "m.room.encrypted":
            return [AutoReply(room_id, event_id, ENCRYPTED_TEXT)]
        if kind == "m.reaction":
            return self._reaction(room_id, event_id, person, content, event)
        if kind != "m.room.message" or "msgtype" not in content:
            return []
        if content.get("msgtype") == "m.notice":
            logger.debug("ignoring %s: a notice (from a bot)", event_id)
            return []
        if person is None:
            if room_id in self.rooms.groups:
                logger.info("ignoring %s from %s: not a person of the office", event_id, sender)
                return []
            return [AutoReply(room_id, event_id, STRANGER_TEXT)]
        relation = content.get("m.relates_to")
        relation = relation if isinstance(relation, dict) else {}
        chat = self.chat_of(room_id, person)
        if chat is None:
            logger.info("ignoring %s: %s is neither a configured group nor a DM", event_id, room_id)
            return []
        if relation.get("rel_type") == "m.replace":
            return [AutoReply(room_id, event_id, EDIT_TEXT)]
        parsed = _text_and_attachments(event_id, person, content)
        if parsed is None:
            return []
        text, attachments = parsed
        reply_to = relation.get("m.in_reply_to")
        in_reply_to: str | None = None
        if isinstance(reply_to, dict) and isinstance(reply_to.get("event_id"), str):
            text = strip_reply_fallback(text)
            in_reply_to = self.rooms.questions.get(reply_to["event_id"]) or None
        if len(text) > MAX_TEXT_CHARS:
            reply = TOO_LONG_TEXT.format(length=len(text), limit=MAX_TEXT_CHARS)
            return [AutoReply(room_id, event_id, reply)]
        sent = _event_time(event)
        if sent is None:
            # Skipped, not failed: a failing transaction would be pushed again for ever.
            logger.warning("dropping %s: origin_server_ts is out of range", event_id)
            return []
        message = InboundMessage(
            platform=PLATFORM,
            event_id=event_id,
            chat=chat,
            sender=person,
            text=text,
            attachments=attachments,
            time=sent,
            in_reply_to=in_reply_to,
        )
        if attachments and not text and chat.kind == "dm":
            # Clients send a file and its request separately: keep the file, say so.
            note = AutoReply(
                room_id, f"{event_id}:file", FILE_TEXT.format(name=attachments[0].name)
            )
            return [message, note]
        return [message]

    def _reaction(
        self,
        room_id: str,
        event_id: str,
        person: str | None,
        content: Mapping[str, Any],
        event: Mapping[str, Any],
    ) -> list[Normalized]:
        relation = content.get("m.relates_to")
        if person is None or not isinstance(relation, dict):
            return []
        target, key = relation.get("event_id"), relation.get("key")
        if not isinstance(target, str) or not isinstance(key, str):
            return []
        question = self.rooms.questions.get(target)
        if question is None:
            return []  # a reaction to someone else's message is not for the bot
        chat = self.chat_of(room_id, person)
        plain = _SKIN_TONES.sub("", key).strip()
        answer = "Yes" if plain in _YES else "No" if plain in _NO else None
        if not question or answer is None or chat is None:
            return [AutoReply(room_id, event_id, REACTION_TEXT.format(key=key))]
        sent = _event_time(event)
        if sent is None:
            return []
        return [
            InboundMessage(
                platform=PLATFORM,
                event_id=event_id,
                chat=chat,
                sender=person,
                text=answer,
                time=sent,
                in_reply_to=question,
            )
        ]


def _check_unicode(item: Normalized) -> None:
    if isinstance(item, AutoReply):
        texts = [item.room_id, item.event_id, item.text]
    else:
        texts = [item.event_id, item.sender, item.chat.id, item.text, item.in_reply_to or ""]
        for attachment in item.attachments:
            texts += [attachment.name, attachment.mime, attachment.ref or "", attachment.item or ""]
    for text in texts:
        try:
            text.encode("utf-8")
        except UnicodeEncodeError as exc:
            raise MalformedEventError(
                f"event {item.event_id.encode('utf-8', 'backslashreplace').decode()} holds "
                "text that is not valid Unicode"
            ) from exc


def strip_reply_fallback(body: str) -> str:
    """Drop the ``> <@user> quoted`` lines a rich reply starts with (Matrix spec 11.19.2)."""
    lines = body.split("\n")
    n = 0
    while n < len(lines) and lines[n].startswith(">"):
        n += 1
    if n and n < len(lines) and lines[n] == "":
        n += 1
    return "\n".join(lines[n:]) if n else body


def _text_and_attachments(
    event_id: str, person: str, content: Mapping[str, Any]
) -> tuple[str, list[Attachment]] | None:
    msgtype = content.get("msgtype")
    if not isinstance(msgtype, str):  # a list or an object is not hashable: no type at all
        msgtype = None
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
        # The office's name for files is not known here: the port's neutral one, which the
        # runtime reads as the sender's file in the office's own type (see forward_file).
        item=persons_file(person) if kind == "file" else None,
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
