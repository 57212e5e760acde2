"""Small waits and reads shared by the Synapse tests."""

from __future__ import annotations

import asyncio
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from assistantx.adapters.messenger.matrix import MatrixClient, MatrixConfig, SqliteEventStore
from assistantx.core.ports.messenger import InboundMessage

WAIT_S = 20.0


async def next_message(
    inbox: asyncio.Queue[InboundMessage], timeout_s: float = WAIT_S
) -> InboundMessage:
    return await asyncio.wait_for(inbox.get(), timeout_s)


async def assert_quiet(inbox: asyncio.Queue[InboundMessage], seconds: float) -> None:
    """Nothing more arrives within ``seconds`` (no duplicate deliveries)."""
    try:
        extra = await asyncio.wait_for(inbox.get(), seconds)
    except TimeoutError:
        return
    raise AssertionError(f"unexpected extra inbound message: {extra!r}")


async def wait_joined(client: MatrixClient, room_id: str, user_id: str) -> None:
    deadline = time.monotonic() + WAIT_S
    while time.monotonic() < deadline:
        if user_id in await client.joined_members(room_id):
            return
        await asyncio.sleep(0.1)
    raise AssertionError(f"{user_id} did not join {room_id} in {WAIT_S}s")


async def room_messages(client: MatrixClient, room_id: str) -> list[dict[str, Any]]:
    """The room's m.room.message events, oldest first."""
    page = await client.room_messages(room_id, from_token=None, direction="b", limit=100)
    events = [e for e in page.get("chunk", []) if e.get("type") == "m.room.message"]
    return list(reversed(events))


async def wait_room_messages(
    client: MatrixClient, room_id: str, count: int
) -> list[dict[str, Any]]:
    deadline = time.monotonic() + WAIT_S
    while time.monotonic() < deadline:
        events = await room_messages(client, room_id)
        if len(events) >= count:
            return events
        await asyncio.sleep(0.1)
    raise AssertionError(f"fewer than {count} messages in {room_id} after {WAIT_S}s")


async def join_when_invited(client: MatrixClient, room_id: str) -> None:
    deadline = time.monotonic() + WAIT_S
    while True:
        try:
            await client.join(room_id)
            return
        except Exception:
            if time.monotonic() > deadline:
                raise
            await asyncio.sleep(0.1)


def derive(config: MatrixConfig, **update: Any) -> MatrixConfig:
    """A validated copy with ``update`` applied (``model_copy`` would skip validation)."""
    return MatrixConfig.model_validate({**config.model_dump(), **update})


class OfferCountingStore(SqliteEventStore):
    """The real store, also counting how often each event was offered (by any path)."""

    def __init__(self, path: Path) -> None:
        super().__init__(path)
        self.offered: dict[str, int] = {}
        self._changed = asyncio.Condition()

    async def wait_offered(self, event_ids: list[str], times: int) -> None:
        async with self._changed:
            await self._changed.wait_for(
                lambda: all(self.offered.get(e, 0) >= times for e in event_ids)
            )

    async def accept(
        self, messages: Sequence[InboundMessage], **kwargs: str | None
    ) -> list[InboundMessage]:
        for message in messages:
            self.offered[message.event_id] = self.offered.get(message.event_id, 0) + 1
        async with self._changed:
            self._changed.notify_all()
        return await super().accept(messages, **kwargs)  # type: ignore[arg-type]
