"""The one path from Matrix events to the inbox, shared by the push router and the poller.

For a batch of events (one pushed transaction, or one /sync response) it

1. joins the rooms the assistant was invited to (idempotent, so a retried batch is harmless);
2. normalizes the messages and, in ONE atomic store write, records those never seen before
   together with the transaction id or the poller's next position;
3. only then puts the new messages on the inbox, in the order the homeserver gave them.

Because step 2 happens before step 3 and before the caller acknowledges, a crash loses
nothing (the store replays what was never handled), and a redelivered batch adds nothing.
"""

from __future__ import annotations

import asyncio
import logging
from collections.abc import Awaitable, Callable, Mapping, Sequence
from typing import Any

from assistantx.adapters.messenger.base import InboundMessage
from assistantx.adapters.messenger.matrix.normalize import EventNormalizer
from assistantx.adapters.messenger.matrix.store import EventStore

logger = logging.getLogger(__name__)

RoomEvent = tuple[str, Mapping[str, Any]]
"""An event and the room it belongs to (/sync timelines leave ``room_id`` out of events)."""

Deliver = Callable[[InboundMessage], Awaitable[None]]
InviteHandler = Callable[[str, str], Awaitable[None]]
"""(room id, invited user id) → join; called only for the assistant's own users."""
AcceptedHook = Callable[[str, InboundMessage], Awaitable[None]]


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
    """Normalizes, deduplicates durably, then delivers. Batches are taken in one at a time."""

    def __init__(
        self,
        store: EventStore,
        normalizer: EventNormalizer,
        deliver: Deliver,
        *,
        on_invite: InviteHandler | None = None,
        on_accepted: AcceptedHook | None = None,
    ) -> None:
        self.store = store
        self._normalizer = normalizer
        self._deliver = deliver
        self._on_invite = on_invite
        self._on_accepted = on_accepted
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
        async with self._lock:
            for room_id, event in events:
                user = invited_user(event)
                if user is not None and self._normalizer.is_own(user) and self._on_invite:
                    await self._on_invite(room_id, user)
            messages: list[InboundMessage] = []
            rooms: dict[str, str] = {}
            for room_id, event in events:
                message = self._normalizer.normalize(room_id, event)
                if message is not None:
                    messages.append(message)
                    rooms[message.event_id] = room_id
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
            if len(messages) > len(fresh):
                logger.debug("skipped %d already seen events", len(messages) - len(fresh))
            return fresh
