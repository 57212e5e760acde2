"""``MatrixMessenger``: the office's ``Messenger`` on a Matrix homeserver.

Inbound, by mode: ``push`` (the homeserver pushes to ``appservice_router()``, which the service
mounts), ``pull`` (a /sync poller on an ordinary bot account) or ``both`` (each message still
reaches the inbox once: both paths deduplicate on the event id in the shared ``EventStore``).

Outbound: text to a person's DM room (found through the bot's ``m.direct`` account data, or
created and recorded there) or to a group's room; images and files are uploaded to the media
repository, or forwarded by their ``mxc://`` URI without a copy. Each part of a message is sent
with a transaction id derived from ``OutboundMessage.idempotency_key``, so a retried send never
posts twice. The sender is the application service's bot in ``push``/``both`` modes and the
pull account in ``pull`` mode.

In ``both`` mode the pull account is kept in every room the bot talks in (it is invited to
the DM rooms the bot creates or joins, and joins the group rooms), so either path alone
receives everything: the poller is a real fallback while pushes fail, not a half view.

Consumers call ``acknowledge(message)`` when done with an inbound message; messages accepted
but never acknowledged are put on the inbox again by the next ``start()``.
"""

from __future__ import annotations

import hashlib
import logging
import struct
import uuid
from datetime import UTC, datetime
from typing import Any

import httpx
from fastapi import APIRouter

from assistantx.adapters.messenger.base import (
    Attachment,
    ChatRef,
    InboundMessage,
    Messenger,
    OutboundMessage,
    SentMessage,
)
from assistantx.adapters.messenger.matrix.appservice import create_appservice_router
from assistantx.adapters.messenger.matrix.client import JSON, MatrixClient, MatrixError, RetryPolicy
from assistantx.adapters.messenger.matrix.config import MatrixConfig
from assistantx.adapters.messenger.matrix.ingest import EventIngestor
from assistantx.adapters.messenger.matrix.normalize import PLATFORM, EventNormalizer
from assistantx.adapters.messenger.matrix.store import EventStore
from assistantx.adapters.messenger.matrix.sync import SyncPoller
from assistantx.errors import MessengerError

logger = logging.getLogger(__name__)

_PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def transaction_id(idempotency_key: str, part: int) -> str:
    """Stable per (logical message, part): the homeserver drops a repeated id."""
    digest = hashlib.sha256(f"{idempotency_key}\x00{part}".encode()).hexdigest()
    return f"ax{digest[:40]}"


def png_size(data: bytes) -> tuple[int, int] | None:
    """(width, height) from a PNG's IHDR chunk, or None for anything else."""
    if len(data) < 24 or not data.startswith(_PNG_MAGIC) or data[12:16] != b"IHDR":
        return None
    width, height = struct.unpack(">II", data[16:24])
    return int(width), int(height)


class MatrixMessenger(Messenger):
    platform = PLATFORM

    def __init__(
        self,
        config: MatrixConfig,
        store: EventStore,
        *,
        http: httpx.AsyncClient | None = None,
    ) -> None:
        super().__init__()
        self.config = config
        self.store = store
        self._external_http = http
        self._http: httpx.AsyncClient | None = None
        self._as_client: MatrixClient | None = None
        self._pull_client: MatrixClient | None = None
        self._poller: SyncPoller | None = None
        self._group_rooms: dict[str, str] = {}  # group id → room id
        self._dm_rooms: dict[str, str] = {}  # person id → room id
        self.normalizer = EventNormalizer(config, {})
        self.ingestor = EventIngestor(
            store,
            self.normalizer,
            self._deliver_or_fail,
            on_invite=self._join_invited,
            on_accepted=self._remember_room,
        )
        self._started = False

    # -- lifecycle ----------------------------------------------------------------------

    async def start(self) -> None:
        if self._started:
            return
        config = self.config
        retry = RetryPolicy(max_retries=config.max_retries)
        self._http = self._external_http or httpx.AsyncClient(timeout=config.request_timeout_s)
        self._as_client = MatrixClient(
            config.homeserver_url,
            config.as_token.get_secret_value(),
            retry=retry,
            http=self._http,
        )
        if config.pull_enabled:
            assert config.pull_access_token is not None  # checked by MatrixConfig
            self._pull_client = MatrixClient(
                config.homeserver_url,
                config.pull_access_token.get_secret_value(),
                retry=retry,
                http=self._http,
            )
        self._started = True
        try:
            await self._resolve_groups()
            for message in await self.store.unhandled():
                if message.platform == PLATFORM:
                    await self._deliver_or_fail(message)
            if self._pull_client is not None:
                self._poller = SyncPoller(
                    self._pull_client,
                    self.ingestor,
                    sync_key=f"matrix:{config.pull_user_id}",
                    timeout_s=config.sync_timeout_s,
                )
                await self._poller.start()
        except BaseException:
            await self.stop()
            raise

    async def stop(self) -> None:
        if not self._started:
            return
        self._started = False
        if self._poller is not None:
            await self._poller.stop()
            self._poller = None
        if self._http is not None and self._external_http is None:
            await self._http.aclose()
        self._http = None
        self._as_client = self._pull_client = None

    @property
    def poller(self) -> SyncPoller | None:
        return self._poller

    def appservice_router(self) -> APIRouter:
        """The push endpoints for the service to mount (modes ``push`` and ``both``)."""
        if not self.config.push_enabled:
            raise MessengerError(f"mode {self.config.mode!r} receives no pushes")
        return create_appservice_router(hs_token=self.config.hs_token, ingestor=self.ingestor)

    async def acknowledge(self, message: InboundMessage) -> None:
        """The consumer is done with ``message``; it will not be replayed on restart."""
        await self.store.mark_handled(message.platform, message.event_id)

    # -- inbound plumbing ---------------------------------------------------------------

    async def _deliver_or_fail(self, message: InboundMessage) -> None:
        if self._inbox is None:
            # Stored already; failing here makes the push answer 500 and the poller retry.
            raise MessengerError("no inbox connected; call connect_inbox() before start()")
        await self._deliver(message)

    async def _join_invited(self, room_id: str, user_id: str) -> None:
        if user_id == self.config.bot_user_id and self.config.push_enabled:
            client = self._sender()
        elif user_id == self.config.pull_user_id and self._pull_client is not None:
            client = self._pull_client
        else:
            return
        try:
            await client.join(room_id)
        except MatrixError as exc:
            if exc.status is not None and 400 <= exc.status < 500:
                # The invite was withdrawn or the room is gone: nothing to retry.
                logger.warning("cannot join %s as %s: %s", room_id, user_id, exc)
                return
            raise
        logger.info("joined %s as %s", room_id, user_id)
        if user_id == self.config.bot_user_id:
            await self._invite_pull_account(room_id)

    async def _invite_pull_account(self, room_id: str) -> None:
        """In ``both`` mode, bring the pull account into a room the bot is in (its poller
        joins on the invite)."""
        if self.config.mode != "both" or self.config.pull_user_id is None:
            return
        try:
            await self._sender().invite(room_id, self.config.pull_user_id)
        except MatrixError as exc:
            if exc.status is not None and 400 <= exc.status < 500:
                # Typically "already in the room" (a person invited both accounts).
                logger.debug("pull account not invited to %s: %s", room_id, exc)
                return
            raise

    async def _remember_room(self, room_id: str, message: InboundMessage) -> None:
        if message.chat.kind == "dm":
            # Answer a person in the room they wrote in.
            self._dm_rooms[message.chat.id] = room_id

    # -- rooms --------------------------------------------------------------------------

    def _sender(self) -> MatrixClient:
        client = self._as_client if self.config.push_enabled else self._pull_client
        if client is None:
            raise MessengerError("the Matrix messenger is not started")
        return client

    def _sender_id(self) -> str:
        if self.config.push_enabled:
            return self.config.bot_user_id
        assert self.config.pull_user_id is not None
        return self.config.pull_user_id

    async def _resolve_groups(self) -> None:
        for group in self.config.groups:
            try:
                await self._group_room(group)
            except MatrixError as exc:
                logger.warning("group %s is not reachable yet: %s", group, exc)

    async def _group_room(self, group: str) -> str:
        room_id = self._group_rooms.get(group)
        if room_id is not None:
            return room_id
        target = self.config.groups.get(group)
        if target is None:
            raise MessengerError(f"group {group!r} has no Matrix room in the configuration")
        client = self._sender()
        room_id = await client.resolve_alias(target) if target.startswith("#") else target
        await client.join(room_id)
        if self.config.mode == "both" and self._pull_client is not None:
            await self._pull_client.join(room_id)
        self._group_rooms[group] = room_id
        self.normalizer.set_group_rooms({room: g for g, room in self._group_rooms.items()})
        return room_id

    async def dm_room(self, person: str) -> str:
        """The room to write to ``person`` in: known, recorded in m.direct, or new."""
        user_id = self.config.people.get(person)
        if user_id is None:
            raise MessengerError(f"person {person!r} has no Matrix account in the configuration")
        client = self._sender()
        joined = set(await client.joined_rooms())
        known = self._dm_rooms.get(person)
        if known is not None and known in joined:
            return known
        direct = await client.get_account_data(self._sender_id(), "m.direct") or {}
        for room_id in reversed(direct.get(user_id, [])):
            if room_id in joined:
                self._dm_rooms[person] = room_id
                return str(room_id)
        invite = [user_id]
        if self.config.mode == "both" and self.config.pull_user_id is not None:
            invite.append(self.config.pull_user_id)
        room_id = await client.create_room(
            invite=invite, is_direct=True, preset="trusted_private_chat"
        )
        direct.setdefault(user_id, []).append(room_id)
        await client.set_account_data(self._sender_id(), "m.direct", direct)
        self._dm_rooms[person] = room_id
        logger.info("created DM room %s for %s", room_id, person)
        return room_id

    async def _room_for(self, chat: ChatRef) -> str:
        return await (self.dm_room(chat.id) if chat.kind == "dm" else self._group_room(chat.id))

    # -- outbound -----------------------------------------------------------------------

    async def send(self, message: OutboundMessage) -> SentMessage:
        if not self._started:
            raise MessengerError("the Matrix messenger is not started")
        if not message.text and not message.attachments:
            raise MessengerError("an outbound message needs text or an attachment")
        client = self._sender()
        room_id = await self._room_for(message.chat)
        # Upload first: a failed upload must not leave half a message behind.
        contents: list[JSON] = []
        if message.text:
            contents.append({"msgtype": "m.text", "body": message.text})
        for attachment in message.attachments:
            contents.append(await self._attachment_content(client, attachment))
        key = message.idempotency_key or uuid.uuid4().hex
        event_ids = [
            await client.send_event(
                room_id, "m.room.message", content, txn_id=transaction_id(key, part)
            )
            for part, content in enumerate(contents)
        ]
        logger.debug("sent %d events to %s (%s)", len(event_ids), message.chat, room_id)
        return SentMessage(
            platform=PLATFORM,
            message_id=event_ids[0],
            chat=message.chat,
            time=datetime.now(UTC),
        )

    async def _attachment_content(self, client: MatrixClient, attachment: Attachment) -> JSON:
        mime = attachment.mime
        info: dict[str, Any] = {}
        if attachment.data is not None:
            data = attachment.data
            if mime == "application/octet-stream" and data.startswith(_PNG_MAGIC):
                mime = "image/png"
            url = await client.upload(data, content_type=mime, filename=attachment.name)
            info["size"] = len(data)
            size = png_size(data)
            if size is not None:
                info["w"], info["h"] = size
        elif attachment.ref is not None and attachment.ref.startswith("mxc://"):
            url = attachment.ref  # forward: the media stays where it is, no copy
        else:
            raise MessengerError(
                f"attachment {attachment.name!r} has neither data nor an mxc:// reference"
            )
        info["mimetype"] = mime
        return {
            "msgtype": "m.image" if attachment.kind == "image" else "m.file",
            "body": attachment.name,
            "filename": attachment.name,
            "url": url,
            "info": info,
        }

    async def download(self, attachment: Attachment) -> bytes:
        """The bytes of a received attachment (by its ``mxc://`` reference)."""
        if attachment.ref is None:
            raise MessengerError(f"attachment {attachment.name!r} has no media reference")
        return await self._sender().download(attachment.ref)
