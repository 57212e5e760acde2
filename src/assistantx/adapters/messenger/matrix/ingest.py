"""The one path from Matrix events to the inbox, shared by the push router and the poller.

For a batch of events (one pushed transaction, or one /sync response) it

1. joins the rooms the assistant was invited to (idempotent, so a retried batch is harmless),
   and lets the messenger learn what it needs about the rooms (``prepare``);
2. normalizes the messages and, in ONE atomic store write, records those never seen before
   together with the transaction id or the poller's next position;
3. only then puts the new messages on the inbox, in the order the homeserver gave them, and
   sends the short answers the bot gives by itself (each event answered once, for ever).

Because step 2 happens before step 3 and before the caller acknowledges, a crash loses
nothing (the store replays what was never handled), and a redelivered batch adds nothing.

Steps 1 and 2 are per event: one event that raises is skipped alone (``core.isolation``).
"""

from __future__ import annotations

import asyncio
import logging
from collections.abc import Awaitable, Callable, Mapping, Sequence
from typing import Any

from assistantx.adapters.messenger.matrix.normalize import PLATFORM, AutoReply, EventNormalizer
from assistantx.adapters.messenger.matrix.store import EventStore
from assistantx.core.errors import MessengerClosedError
from assistantx.core.isolation import SkippedEvents
from assistantx.core.ports.messenger import InboundMessage

logger = logging.getLogger(__name__)

RoomEvent = tuple[str, Mapping[str, Any]]
"""An event and the room it belongs to (/sync timelines leave ``room_id`` out of events)."""

Deliver = Callable[[InboundMessage], Awaitable[None]]
InviteHandler = Callable[[str, str, Mapping[str, Any]], Awaitable[None]]
"""(room id, invited user id, the invite event) → join or decline; only for the bot's users."""
AcceptedHook = Callable[[str, InboundMessage], Awaitable[None]]
PrepareHook = Callable[[str, Mapping[str, Any]], Awaitable[None]]
"""What the messenger learns from one event about its rooms before the batch is normalized."""
ReplyHook = Callable[[AutoReply], Awaitable[None]]
DeliveredHook = Callable[[str, InboundMessage], Awaitable[None]]
"""(room id, message) once a new message is in the inbox: read receipt and the like."""


def invited_user(event: Mapping[str, Any]) -> str | None:
    """The invited user if ``event`` is an invite, else None."""
    content = event.get("content")
    if event.get("type") != "m.room.member" or not isinstance(content, dict):
        return None
    state_key = event.get("state_key")
    if content.get("membership") != "invite" or not isinstance(state_key, str):
        return None
    return state_key


class EventIngestor:
    """Normalizes, deduplicates durably, then delivers. Batches are taken in one at a time.

    Each event is handled on its own: an event whose invite handling, room bookkeeping or
    normalization raises is logged with its id, counted in ``skipped`` and left out, and the
    batch goes on (its transaction is acknowledged, the poller advances). Only what is no
    event's fault fails the whole batch: the store's write and the hand-over to the inbox."""

    def __init__(
        self,
        store: EventStore,
        normalizer: EventNormalizer,
        deliver: Deliver,
        *,
        on_invite: InviteHandler | None = None,
        on_accepted: AcceptedHook | None = None,
        prepare: PrepareHook | None = None,
        after_prepare: Callable[[], Awaitable[None]] | None = None,
        on_auto_reply: ReplyHook | None = None,
        on_delivered: DeliveredHook | None = None,
        skipped: SkippedEvents | None = None,
    ) -> None:
        self.store = store
        self._normalizer = normalizer
        self._deliver = deliver
        self._on_invite = on_invite
        self._on_accepted = on_accepted
        self._prepare = prepare
        self._after_prepare = after_prepare
        self._on_auto_reply = on_auto_reply
        self._on_delivered = on_delivered
        self.skipped = skipped or SkippedEvents()
        # One batch at a time keeps the inbox in homeserver order across push and pull.
        self._lock = asyncio.Lock()

    async def ingest(
        self,
        events: Sequence[RoomEvent],
        *,
        txn_id: str | None = None,
        sync_key: str | None = None,
        sync_token: str | None = None,
    ) -> list[InboundMessage]:
        """Take in one batch; returns the messages that were new and are now in the inbox."""
        path = "matrix_push" if txn_id is not None else "matrix_sync"
        async with self._lock:
            healthy: list[RoomEvent] = []
            for room_id, event in events:
                try:
                    await self._take_invite(room_id, event)
                    if self._prepare is not None:
                        await self._prepare(room_id, event)
                except MessengerClosedError:
                    raise  # stopping mid-batch: the whole batch comes again, nothing skipped
                except Exception as exc:
                    self.skipped.skip(path, _event_id(event), "room bookkeeping", exc)
                    continue
                healthy.append((room_id, event))
            if self._after_prepare is not None:
                await self._after_prepare()
            messages: list[InboundMessage] = []
            replies: list[AutoReply] = []
            rooms: dict[str, str] = {}
            for room_id, event in healthy:
                try:
                    items = self._normalizer.interpret(room_id, event)
                except Exception as exc:
                    self.skipped.skip(path, _event_id(event), "normalizing", exc)
                    continue
                for item in items:
                    if isinstance(item, AutoReply):
                        replies.append(item)
                    else:
                        messages.append(item)
                        rooms[item.event_id] = room_id
            if replies and self._on_auto_reply is not None:
                # Claimed before sending: a redelivered event is never answered twice.
                claimed = set(await self.store.claim(PLATFORM, [r.event_id for r in replies]))
                for reply in replies:
                    if reply.event_id in claimed:
                        await self._send_reply(reply)
            fresh = await self.store.accept(
                messages, txn_id=txn_id, sync_key=sync_key, sync_token=sync_token
            )
            for message in fresh:
                if self._on_accepted is not None:
                    try:
                        await self._on_accepted(rooms[message.event_id], message)
                    except Exception:
                        # Bookkeeping only (e.g. remembering a DM room); the message is safe.
                        logger.exception("after-accept hook failed for %s", message.event_id)
                logger.debug(
                    "inbound %s in %s from %s", message.event_id, message.chat, message.sender
                )
                await self._deliver(message)
                if self._on_delivered is not None:
                    await self._courtesy(self._on_delivered(rooms[message.event_id], message))
            if len(messages) > len(fresh):
                logger.debug("skipped %d already seen events", len(messages) - len(fresh))
            return fresh

    async def _take_invite(self, room_id: str, event: Mapping[str, Any]) -> None:
        user = invited_user(event)
        if user is not None and self._normalizer.is_own(user) and self._on_invite:
            await self._on_invite(room_id, user, event)

    async def _send_reply(self, reply: AutoReply) -> None:
        assert self._on_auto_reply is not None
        try:
            await self._on_auto_reply(reply)
        except Exception:
            # A courtesy answer: losing it must not make the homeserver redeliver the batch.
            logger.exception("could not answer %s in %s", reply.event_id, reply.room_id)

    async def _courtesy(self, work: Awaitable[None]) -> None:
        try:
            await work
        except Exception:
            logger.exception("a courtesy to the sender of an inbound message failed")


def _event_id(event: object) -> object:
    return event.get("event_id") if isinstance(event, Mapping) else None
