"""``MatrixMessenger``: the office's ``Messenger`` on a Matrix homeserver.

Inbound, by mode: ``push`` (the homeserver pushes to ``appservice_router()``, which the service
mounts), ``pull`` (a /sync poller on an ordinary bot account) or ``both`` (each message still
reaches the inbox once: both paths deduplicate on the event id in the shared ``EventStore``).

Outbound: text to a person's DM room (recorded in the store, checked to be private before
anything is sent; else found through the bot's ``m.direct`` account data, or created) or to a
group's room; images and files are uploaded to the media repository, or forwarded by their
``mxc://`` URI without a copy (a file a person sent is found by its office item, ``file:lee``).
Each part of a message gets a random transaction id recorded in the store under its
``OutboundMessage.idempotency_key``: a retry of the same message reuses it (and is answered
from the store once sent), while a new message is never taken for a repeat of an old one, also
after a restart. The sender is the application service's bot in ``push``/``both`` modes and
the pull account in ``pull`` mode. Once ``closing`` is set (the service is shutting down),
nothing more is sent: an instruction cut short resumes after the restart instead of telling
its requester it failed.

In ``both`` mode the pull account is kept in every room the bot talks in (it is invited to
the DM rooms the bot creates or joins, and joins the group rooms), so either path alone
receives everything: the poller is a real fallback while pushes fail, not a half view.

A person sees at once that the bot took their message: a read receipt, the bot typing in
their DM until it sends there, and ``instruction_started`` writes "On it: ..." to the requester.
The bot stays out of end-to-end encrypted rooms (it cannot encrypt): it leaves an encrypted
DM it is invited to and says so in the person's unencrypted DM (see ``rooms``).

Consumers call ``acknowledge(message)`` when done with an inbound message; messages accepted
but never acknowledged are put on the inbox again by the next ``start()``.
"""

from __future__ import annotations

import hashlib
import json
import logging
import struct
import uuid
from collections.abc import Awaitable, Callable, Mapping
from datetime import UTC, datetime
from typing import Any, Protocol

import httpx
from fastapi import APIRouter

from assistantx.adapters.messenger.matrix.appservice import (
    create_appservice_router,
    create_discarding_router,
)
from assistantx.adapters.messenger.matrix.client import (
    JSON,
    MatrixClient,
    MatrixError,
    matrix_policy,
    retrying_http,
)
from assistantx.adapters.messenger.matrix.config import MatrixConfig
from assistantx.adapters.messenger.matrix.ingest import EventIngestor
from assistantx.adapters.messenger.matrix.normalize import (
    ENCRYPTED_ROOM_TEXT,
    PLATFORM,
    STRANGER_TEXT,
    AutoReply,
    EventNormalizer,
)
from assistantx.adapters.messenger.matrix.rooms import RoomDirectory
from assistantx.adapters.messenger.matrix.store import EventStore
from assistantx.adapters.messenger.matrix.sync import SyncPoller
from assistantx.core.errors import MessengerError, UnreachableContactError
from assistantx.core.isolation import SkippedEvents
from assistantx.core.ports.messenger import (
    Attachment,
    ChatRef,
    InboundMessage,
    Messenger,
    OutboundMessage,
    SentMessage,
    persons_file,
)

logger = logging.getLogger(__name__)

_PNG_MAGIC = b"\x89PNG\r\n\x1a\n"

ACK_TEXT = "On it: {request}"
"""Sent to the requester as soon as an instruction starts."""
ACK_REQUEST_CHARS = 120
TYPING_MS = 20_000
"""How long the bot shows itself typing after a person's DM, unless it answers sooner."""


def transaction_id(idempotency_key: str, part: int) -> str:
    """Stable per (key, part); only for keys unique for ever (an answered event's id)."""
    digest = hashlib.sha256(f"{idempotency_key}\x00{part}".encode()).hexdigest()
    return f"ax{digest[:40]}"


def png_size(data: bytes) -> tuple[int, int] | None:
    """(width, height) from a PNG's IHDR chunk, or None for anything else."""
    if len(data) < 24 or not data.startswith(_PNG_MAGIC) or data[12:16] != b"IHDR":
        return None
    width, height = struct.unpack(">II", data[16:24])
    return int(width), int(height)


def content_digest(room_id: str, content: Mapping[str, Any]) -> str:
    """What makes two sends the same message: room and content, not the upload's new URL."""
    stable = {k: v for k, v in content.items() if k not in ("url", "info")}
    text = json.dumps([room_id, stable], sort_keys=True, ensure_ascii=False)
    return hashlib.sha256(text.encode()).hexdigest()


Relay = Callable[[OutboundMessage], Awaitable[None]]


class Transcript(Protocol):
    """Where every message in and out is also written (the service's journal)."""

    def record_outbound(self, message: OutboundMessage, sender: str, now: float) -> Any: ...

    def record_inbound(self, message: InboundMessage) -> Any: ...


class MatrixMessenger(Messenger):
    platform = PLATFORM

    def __init__(
        self,
        config: MatrixConfig,
        store: EventStore,
        *,
        http: httpx.AsyncClient | None = None,
        transcript: Transcript | None = None,
    ) -> None:
        super().__init__()
        self.config = config
        self.store = store
        self.transcript = transcript
        self._external_http = http
        self._http: httpx.AsyncClient | None = None
        self._as_client: MatrixClient | None = None
        self._pull_client: MatrixClient | None = None
        self._poller: SyncPoller | None = None
        self.normalizer = EventNormalizer(config, {})
        self.normalizer.rooms.strict = True  # only recorded DMs and configured groups count
        self.directory = RoomDirectory(config, store, self.normalizer.rooms)
        # Inbound events that raised, by path (on /metrics).
        paths = ["matrix_push"] * config.push_enabled + ["matrix_sync"] * config.pull_enabled
        self.skipped_events = SkippedEvents(*paths)
        self.ingestor = EventIngestor(
            store,
            self.normalizer,
            self._deliver_or_fail,
            on_invite=self._on_invite,
            on_accepted=self._remember_media,
            prepare=self._prepare,
            after_prepare=self.directory.flush,
            on_delivered=self._seen_by_bot,
            on_auto_reply=self._auto_reply,
            skipped=self.skipped_events,
        )
        self.closing = False  # set on shutdown: nothing more goes out
        self._typing: set[str] = set()  # rooms where the bot shows itself typing
        self._relays: list[Relay] = []

    # -- lifecycle ----------------------------------------------------------------------

    async def _start(self) -> None:
        config = self.config
        retry = matrix_policy(max_retries=config.max_retries)
        self._http = self._external_http or retrying_http(retry, config.request_timeout_s)
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
        self.closing = False
        await self.directory.load()
        await self._resolve_groups()
        await self._bring_pull_account_along()
        for message in await self.store.unhandled():
            if message.platform == PLATFORM:
                await self._deliver_or_fail(message)
        if self._pull_client is not None:
            self._poller = SyncPoller(
                self._pull_client,
                self.ingestor,
                sync_key=f"matrix:{config.pull_user_id}",
                timeout_s=config.sync_timeout_s,
                own_user_id=config.pull_user_id,
            )
            await self._poller.start()

    async def _stop(self) -> None:
        try:
            if self._poller is not None:
                poller, self._poller = self._poller, None
                await poller.stop()
        finally:  # the client's connections to the homeserver close whatever the poller did
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

    def leftover_push_router(self) -> APIRouter:
        """For ``pull`` mode: pushes of a registration left from ``push`` mode are acknowledged
        and dropped (the poller receives everything), so the homeserver does not retry them
        for ever against a 405."""
        return create_discarding_router(hs_token=self.config.hs_token)

    def relay_to(self, relay: Relay) -> None:
        """Also hand every sent message to ``relay`` (the dashboard notes QR codes so the
        operator can scan them at the locker, whatever the messenger)."""
        self._relays.append(relay)

    async def acknowledge(self, message: InboundMessage) -> None:
        """The consumer is done with ``message``; it will not be replayed on restart."""
        await self.store.mark_handled(message.platform, message.event_id)

    async def instruction_ended(self, instruction_id: str) -> None:
        """The instruction is over: a later one reusing its id never has a send deduplicated
        against its messages."""
        await self.store.close_instruction(instruction_id)

    # -- inbound plumbing ---------------------------------------------------------------

    async def _deliver_or_fail(self, message: InboundMessage) -> None:
        if self._inbox is None:
            # Stored already; failing here makes the push answer 500 and the poller retry.
            raise MessengerError("no inbox connected; call connect_inbox() before start()")
        if self.transcript is not None:
            self.transcript.record_inbound(message)
        await self._deliver(message)

    async def _prepare(self, room_id: str, event: Mapping[str, Any]) -> None:
        if self.started:  # not started: nothing to learn rooms from (the push fails later)
            await self.directory.observe(self._sender(), room_id, event)

    async def _remember_media(self, room_id: str, message: InboundMessage) -> None:
        for attachment in message.attachments:
            if attachment.item and attachment.ref:
                await self.store.remember_media(
                    attachment.item, attachment.ref, attachment.name, attachment.mime
                )

    async def _seen_by_bot(self, room_id: str, message: InboundMessage) -> None:
        """What a person sees at once: their message read, and in a DM the bot typing until
        it answers (or for ``TYPING_MS``). Sent by a task of the messenger's own, so the push
        is acknowledged without waiting for it, and ``stop`` ends it before the HTTP client
        closes."""
        if self.closing or not self.started:
            return
        self.create_task(self._signal_seen(room_id, message), name=f"seen:{message.event_id}")

    async def _signal_seen(self, room_id: str, message: InboundMessage) -> None:
        client = self._sender()
        try:
            await client.read_receipt(room_id, message.event_id)
            if message.chat.kind == "dm" and message.text.strip():
                self._typing.add(room_id)
                await client.typing(self._sender_id(), room_id, typing=True, timeout_ms=TYPING_MS)
        except MatrixError as exc:
            logger.info("could not show %s as read: %s", message.event_id, exc)

    async def _stop_typing(self, client: MatrixClient, room_id: str) -> None:
        if room_id not in self._typing:
            return
        self._typing.discard(room_id)
        try:
            await client.typing(self._sender_id(), room_id, typing=False, timeout_ms=0)
        except MatrixError as exc:
            logger.debug("could not stop typing in %s: %s", room_id, exc)

    async def instruction_started(self, instruction_id: str, requester: str, text: str) -> None:
        """Tell the requester at once that their request is being worked on: on Matrix they
        otherwise see nothing until the instruction's first message, which can take a while.
        Sent once per instruction (a resumed one is answered from the store)."""
        if self.closing or requester not in self.config.people:
            return
        request = " ".join(text.split())
        if len(request) > ACK_REQUEST_CHARS:
            request = request[: ACK_REQUEST_CHARS - 1].rstrip() + "…"
        message = OutboundMessage(
            chat=ChatRef(kind="dm", id=requester),
            text=ACK_TEXT.format(request=request),
            instruction_id=instruction_id,
            idempotency_key=f"on-it:{instruction_id}",
        )
        try:
            await self.send(message)
        except MessengerError as exc:
            logger.warning("could not acknowledge %s to its requester: %s", instruction_id, exc)

    async def _auto_reply(self, reply: AutoReply) -> None:
        if self.closing:
            return
        content = {"msgtype": "m.notice", "body": reply.text}
        # Keyed by the answered event, whose id is unique for ever: one answer per event.
        txn = transaction_id(f"auto:{reply.event_id}", 0)
        await self._sender().send_event(reply.room_id, "m.room.message", content, txn_id=txn)
        person = self.normalizer.rooms.dms.get(reply.room_id)
        group = self.normalizer.rooms.groups.get(reply.room_id)
        if self.transcript is not None and (person or group):
            chat = (
                ChatRef(kind="dm", id=person) if person else ChatRef(kind="group", id=group or "")
            )
            self.transcript.record_outbound(
                OutboundMessage(chat=chat, text=reply.text),
                "assistant",
                datetime.now(UTC).timestamp(),
            )

    async def _on_invite(self, room_id: str, user_id: str, event: Mapping[str, Any]) -> None:
        if user_id == self.config.bot_user_id and self.config.push_enabled:
            client = self._sender()
        elif user_id == self.config.pull_user_id and self._pull_client is not None:
            client = self._pull_client
        else:
            return
        inviter = event.get("sender")
        content = event.get("content")
        is_direct = isinstance(content, dict) and content.get("is_direct") is True
        person = self.config.person_of(inviter) if isinstance(inviter, str) else None
        own = isinstance(inviter, str) and self.normalizer.is_own(inviter)
        group = await self.directory.group_of(client, room_id)
        if person is None and group is None and not own:
            await self._turn_away(client, room_id, user_id, inviter)
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
        if person is not None and group is None and is_direct:
            if await self.directory.is_encrypted(client, room_id):
                await self._stay_out_of_encrypted(client, room_id, person)
                return
            await self.directory.set_dm(person, room_id)
        if user_id == self.config.bot_user_id:
            await self._invite_pull_account(room_id)

    async def _stay_out_of_encrypted(self, client: MatrixClient, room_id: str, person: str) -> None:
        """A person opened an encrypted DM: the bot cannot read or write it, so it leaves and
        says so in their unencrypted DM (found or created by ``dm_room``)."""
        logger.warning(
            "%s invited the bot to an end-to-end encrypted DM (%s); it left and asks for an "
            "unencrypted one",
            person,
            room_id,
        )
        await client.leave(room_id)
        if self.closing:
            return
        dm = await self.dm_room(person)
        content = {"msgtype": "m.notice", "body": ENCRYPTED_ROOM_TEXT}
        txn = transaction_id(f"encrypted:{room_id}", 0)
        await self._sender().send_event(dm, "m.room.message", content, txn_id=txn)

    async def _turn_away(
        self, client: MatrixClient, room_id: str, user_id: str, inviter: object
    ) -> None:
        """Someone outside the office: say so once (as the sending account), then leave."""
        logger.info("declining the invite of %s to %s: not of the office", inviter, room_id)
        try:
            if user_id == self._sender_id() and not self.closing:
                await client.join(room_id)
                txn = transaction_id(f"decline:{room_id}", 0)
                content = {"msgtype": "m.notice", "body": STRANGER_TEXT}
                await client.send_event(room_id, "m.room.message", content, txn_id=txn)
            await client.leave(room_id)
        except MatrixError as exc:
            logger.warning("could not decline the invite to %s: %s", room_id, exc)

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

    async def _bring_pull_account_along(self) -> None:
        """``both`` mode after ``push``: DM rooms made earlier get the pull account too."""
        if self.config.mode != "both":
            return
        for room_id in list(self.normalizer.rooms.dms):
            try:
                await self._invite_pull_account(room_id)
            except MatrixError as exc:
                logger.warning("could not bring the pull account into %s: %s", room_id, exc)

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
        client = self._sender()
        room_id = await self.directory.resolve_group(client, group)
        joined = set(await client.joined_rooms())
        if room_id not in joined:
            await client.join(room_id)
        await self._pull_account_into_group(room_id)
        return room_id

    async def _pull_account_into_group(self, room_id: str) -> None:
        """``both`` mode: the pull account is in every group room the bot is in (else an
        answer there is lost while pushes fail). It joins a public room itself; into another
        the bot invites it, and its poller joins on the invite."""
        if self.config.mode != "both" or self._pull_client is None:
            return
        if room_id in set(await self._pull_client.joined_rooms()):
            return
        try:
            await self._pull_client.join(room_id)
        except MatrixError as exc:
            if exc.status is None or exc.status >= 500:
                raise
            logger.info("pull account cannot join %s by itself (%s); inviting it", room_id, exc)
            await self._invite_pull_account(room_id)

    async def dm_room(self, person: str) -> str:
        """The room to write to ``person`` in: recorded and still private, recorded in
        m.direct and private, or new."""
        user_id = self.config.people.get(person)
        if user_id is None:
            raise UnreachableContactError(
                f"{person} cannot be reached on Matrix: no Matrix account is configured for "
                "them; reach them another way or ask someone else"
            )
        client = self._sender()
        known = self.directory.dm_of(person)
        if known is not None and await self.directory.is_private(client, known, user_id):
            return known
        direct = await client.get_account_data(self._sender_id(), "m.direct") or {}
        joined = set(await client.joined_rooms())
        for room_id in reversed(direct.get(user_id, [])):
            if room_id in joined and await self.directory.is_private(client, room_id, user_id):
                await self.directory.set_dm(person, str(room_id))
                return str(room_id)
        invite = [user_id]
        if self.config.mode == "both" and self.config.pull_user_id is not None:
            invite.append(self.config.pull_user_id)
        room_id = await client.create_room(
            invite=invite, is_direct=True, preset="trusted_private_chat"
        )
        direct.setdefault(user_id, []).append(room_id)
        await client.set_account_data(self._sender_id(), "m.direct", direct)
        await self.directory.set_dm(person, room_id)
        logger.info("created DM room %s for %s", room_id, person)
        return room_id

    async def _room_for(self, chat: ChatRef) -> str:
        return await (self.dm_room(chat.id) if chat.kind == "dm" else self._group_room(chat.id))

    # -- outbound -----------------------------------------------------------------------

    async def send(self, message: OutboundMessage) -> SentMessage:
        if not self.started:
            raise MessengerError("the Matrix messenger is not started")
        if self.closing:
            raise MessengerError("the service is shutting down; the message was not sent")
        if not message.text and not message.attachments:
            raise MessengerError("an outbound message needs text or an attachment")
        client = self._sender()
        room_id = await self._room_for(message.chat)
        # Resolve everything first: a missing file must not leave half a message behind.
        contents: list[tuple[JSON, Attachment | None]] = []
        if message.text:
            contents.append(({"msgtype": "m.text", "body": message.text}, None))
        for attachment in message.attachments:
            contents.append((await self._describe(attachment), attachment))
        key = message.idempotency_key or uuid.uuid4().hex
        event_ids: list[str] = []
        for part, (content, original) in enumerate(contents):
            record = await self.store.outbound_part(
                key,
                part,
                content_digest(room_id, content),
                room_id=room_id,
                instruction_id=message.instruction_id,
            )
            if record.event_id is not None:
                event_ids.append(record.event_id)  # sent before a restart: not again
                continue
            if original is not None and original.data is not None:
                content = await self._upload(client, content, original.data)
            event_id = await client.send_event(
                room_id, "m.room.message", content, txn_id=record.txn_id
            )
            await self.store.part_sent(record.txn_id, event_id, message.question_id)
            if message.question_id:
                self.normalizer.rooms.questions[event_id] = message.question_id
            event_ids.append(event_id)
        await self._stop_typing(client, room_id)
        if self.transcript is not None:
            self.transcript.record_outbound(message, "assistant", datetime.now(UTC).timestamp())
        for relay in self._relays:
            try:
                await relay(message)
            except Exception:
                logger.exception("relay of a sent message failed")
        logger.debug("sent %d events to %s (%s)", len(event_ids), message.chat, room_id)
        return SentMessage(
            platform=PLATFORM,
            message_id=event_ids[0],
            chat=message.chat,
            time=datetime.now(UTC),
        )

    async def _media(self, item: str) -> tuple[str, str, str] | None:
        """The media a person sent for ``item``: remembered under the item, or, for the
        office's name of their file (``script:lee``), under the one it came in as
        (``file:lee``: this adapter does not know the office's name for files)."""
        found = await self.store.media(item)
        owner = item.partition(":")[2]
        if found is None and owner and item != persons_file(owner):
            found = await self.store.media(persons_file(owner))
        return found

    async def _describe(self, attachment: Attachment) -> JSON:
        """The event content of an attachment (its URL filled in by ``_upload`` for data)."""
        mime, name = attachment.mime, attachment.name
        info: dict[str, Any] = {}
        url: str | None = None
        if attachment.data is not None:
            if mime == "application/octet-stream" and attachment.data.startswith(_PNG_MAGIC):
                mime = "image/png"
        elif attachment.ref is not None and attachment.ref.startswith("mxc://"):
            url = attachment.ref  # forward: the media stays where it is, no copy
        elif attachment.item is not None and (found := await self._media(attachment.item)):
            url, name, mime = found  # the person's own file name, not the office's item id
        else:
            owner = (attachment.item or "").partition(":")[2] or "anyone"
            raise MessengerError(
                f"I have no copy of {attachment.item or attachment.name}: {owner} has not sent "
                "it to me on Matrix; ask them to send it first"
            )
        info["mimetype"] = mime
        content: JSON = {
            "msgtype": "m.image" if attachment.kind == "image" else "m.file",
            "body": name,
            "filename": name,
            "info": info,
        }
        if url is not None:
            content["url"] = url
        return content

    async def _upload(self, client: MatrixClient, content: JSON, data: bytes) -> JSON:
        info = dict(content["info"])
        url = await client.upload(data, content_type=info["mimetype"], filename=content["body"])
        info["size"] = len(data)
        size = png_size(data)
        if size is not None:
            info["w"], info["h"] = size
        return {**content, "url": url, "info": info}

    async def download(self, attachment: Attachment) -> bytes:
        """The bytes of a received attachment (by its ``mxc://`` reference)."""
        if attachment.ref is None:
            raise MessengerError(f"attachment {attachment.name!r} has no media reference")
        return await self._sender().download(attachment.ref)
