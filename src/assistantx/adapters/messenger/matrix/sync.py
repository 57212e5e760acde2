"""The /sync long-poll loop of an ordinary bot account (an application service's own user
cannot /sync).

Each round: GET ``/sync?since=...&timeout=...``, join the rooms it was invited to, fill the
gap of every ``limited`` timeline from ``/rooms/{id}/messages`` (back to an event already
seen), hand all events to the ingestor, which stores the new messages and ``next_batch`` in
one write. So the position advances only after the events are safe, and a crash repeats at
most one round, which the event-id dedup absorbs.

On its very first run (no stored position) the poller takes the position without replaying the
account's history as new messages, but still joins pending invites. Likewise a room it has
just joined shows its earlier history: everything before the account's own join is old news
and is dropped, never taken for a new request. Errors back off
exponentially; the first failure and the recovery are logged, not every attempt.

One room whose data breaks the round (anything but the homeserver failing) is logged, counted
and skipped, and each event in the ingestor on its own, so no event stops the poller.
"""

from __future__ import annotations

import asyncio
import json
import logging
import random
from collections.abc import Coroutine, Mapping
from typing import Any

from assistantx.adapters.messenger.matrix.client import JSON, MatrixClient, MatrixError
from assistantx.adapters.messenger.matrix.ingest import EventIngestor, RoomEvent
from assistantx.adapters.messenger.matrix.normalize import PLATFORM
from assistantx.core.backoff import Backoff
from assistantx.core.lifecycle import Component

logger = logging.getLogger(__name__)


def _sync_filter(timeline_limit: int) -> str:
    return json.dumps(
        {
            "presence": {"not_types": ["*"]},
            "account_data": {"not_types": ["*"]},
            "room": {
                "timeline": {
                    "types": ["m.room.message", "m.room.encrypted", "m.reaction", "m.room.member"],
                    "limit": timeline_limit,
                },
                "state": {"lazy_load_members": True},
                "ephemeral": {"not_types": ["*"]},
                "account_data": {"not_types": ["*"]},
            },
        },
        separators=(",", ":"),
    )


class SyncPoller(Component):
    """Polls one account in a tracked task while started; ``ready`` is set after round one."""

    def __init__(
        self,
        client: MatrixClient,
        ingestor: EventIngestor,
        *,
        sync_key: str,
        timeout_s: float = 30.0,
        max_backfill_pages: int = 5,
        timeline_limit: int = 50,
        backoff_max_s: float = 60.0,
        own_user_id: str | None = None,
        rng: random.Random | None = None,
    ) -> None:
        super().__init__()
        self._client = client
        self._ingestor = ingestor
        self._sync_key = sync_key
        self._timeout_ms = int(timeout_s * 1000)
        self._max_backfill_pages = max_backfill_pages
        self._filter = _sync_filter(timeline_limit)
        self._backoff = Backoff(initial_s=1.0, max_s=backoff_max_s)
        self._rng = rng or random.Random()
        self._own_user_id = own_user_id
        self.ready = asyncio.Event()

    async def _start(self) -> None:
        self.create_task(self._run(), name=f"matrix-sync:{self._sync_key}")

    async def _run(self) -> None:
        failures = 0
        while True:
            try:
                await self.sync_once()
            except asyncio.CancelledError:
                raise
            except Exception as exc:
                if failures == 0:
                    logger.warning("Matrix /sync failed (%s); retrying with backoff", exc)
                await asyncio.sleep(self._backoff.delay_s(failures, self._rng))
                failures += 1
                continue
            if failures:
                logger.info("Matrix /sync recovered after %d failed attempts", failures)
                failures = 0
            self.ready.set()

    async def sync_once(self) -> None:
        """One round: sync, join invites, backfill gaps, ingest, advance."""
        since = await self._ingestor.store.sync_token(self._sync_key)
        first_run = since is None
        response = await self._client.sync(
            since=since,
            timeout_ms=0 if first_run else self._timeout_ms,
            filter_json=self._filter,
        )
        next_batch = response.get("next_batch")
        if not isinstance(next_batch, str):
            raise MatrixError("/sync answer has no next_batch")
        rooms = response.get("rooms")
        rooms = rooms if isinstance(rooms, dict) else {}
        events: list[RoomEvent] = []
        for room_id, room in _entries(rooms.get("invite")):
            events.extend(await self._isolated(room_id, self._invites(room_id, room)))
        if not first_run:
            for room_id, room in _entries(rooms.get("join")):
                events.extend(await self._isolated(room_id, self._timeline(room_id, room)))
        await self._ingestor.ingest(events, sync_key=self._sync_key, sync_token=next_batch)

    async def _isolated(
        self, room_id: str, work: Coroutine[Any, Any, list[RoomEvent]]
    ) -> list[RoomEvent]:
        """One room's events; a room whose data breaks the poller is skipped, not retried
        for ever. The homeserver failing (``MatrixError``) fails the round: it is retried."""
        try:
            return await work
        except MatrixError:
            raise
        except Exception as exc:
            self._ingestor.skipped.skip("matrix_sync", f"room {room_id}", "reading /sync", exc)
            return []

    async def _invites(self, room_id: str, room: Mapping[str, Any]) -> list[RoomEvent]:
        """The invite's state events, so the ingestor's invite handling joins the room."""
        return [
            (room_id, event)
            for event in room.get("invite_state", {}).get("events", [])
            if isinstance(event, dict) and event.get("type") == "m.room.member"
        ]

    async def _timeline(self, room_id: str, room: Mapping[str, Any]) -> list[RoomEvent]:
        timeline = room.get("timeline", {})
        events: list[JSON] = list(timeline.get("events", []))
        joined_at = self._own_join(events)
        if joined_at is not None:
            return [(room_id, event) for event in events[joined_at + 1 :]]
        prev_batch = timeline.get("prev_batch")
        if timeline.get("limited") and isinstance(prev_batch, str):
            events = await self._backfill(room_id, prev_batch) + events
        return [(room_id, event) for event in events]

    def _own_join(self, events: list[JSON]) -> int | None:
        """The index of this account's (last) join event among ``events``, if there."""
        found: int | None = None
        for index, event in enumerate(events):
            content = event.get("content")
            if (
                event.get("type") == "m.room.member"
                and event.get("state_key") == self._own_user_id
                and isinstance(content, dict)
                and content.get("membership") == "join"
                and _previous_membership(event) != "join"  # not a mere profile change
            ):
                found = index
        return found

    async def _backfill(self, room_id: str, from_token: str) -> list[JSON]:
        """Older events of a gap, oldest first, back to the first one already seen."""
        gathered: list[JSON] = []
        token: str | None = from_token
        for _ in range(self._max_backfill_pages):
            if token is None:
                break
            page = await self._client.room_messages(room_id, from_token=token)
            chunk: list[JSON] = page.get("chunk", [])
            reached_known = False
            for event in chunk:  # newest first
                if self._own_join([event]) is not None:
                    reached_known = True  # before the join is history, not news
                    break
                event_id = event.get("event_id")
                if isinstance(event_id, str) and await self._ingestor.store.event_seen(
                    PLATFORM, event_id
                ):
                    reached_known = True
                    break
                gathered.append(event)
            end = page.get("end")
            if reached_known or not chunk or not isinstance(end, str):
                break
            token = end
        else:
            logger.warning(
                "gap in %s larger than %d pages; older events skipped",
                room_id,
                self._max_backfill_pages,
            )
        gathered.reverse()
        logger.debug("back-filled %d events in %s", len(gathered), room_id)
        return gathered


def _entries(rooms: object) -> list[tuple[str, Any]]:
    """The (room id, room) pairs of one section of a /sync answer (nothing if malformed)."""
    if not isinstance(rooms, dict):
        return []
    return [(str(room_id), room) for room_id, room in rooms.items()]


def _previous_membership(event: JSON) -> str | None:
    unsigned = event.get("unsigned")
    prev = unsigned.get("prev_content") if isinstance(unsigned, dict) else None
    value = prev.get("membership") if isinstance(prev, dict) else None
    return value if isinstance(value, str) else None
