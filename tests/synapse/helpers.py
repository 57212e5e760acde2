"""Small waits and reads shared by the Synapse tests."""

from __future__ import annotations

import asyncio
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from assistantx.adapters.messenger.matrix import MatrixClient, MatrixConfig, SqliteEventStore
from assistantx.core.ports.messenger import InboundMessage
from helpers.eventually import eventually

WAIT_S = 20.0


async def next_message(
    inbox: asyncio.Queue[InboundMessage], timeout_s: float = WAIT_S
) -> InboundMessage:
    return await asyncio.wait_for(inbox.get(), timeout_s)


async def wait_joined(client: MatrixClient, room_id: str, user_id: str) -> None:
    async def joined() -> bool:
        return user_id in await client.joined_members(room_id)

    await eventually(joined, what=f"{user_id} to join {room_id}", timeout_s=WAIT_S, interval_s=0.1)


async def room_messages(client: MatrixClient, room_id: str) -> list[dict[str, Any]]:
    """The room's m.room.message events, oldest first."""
    page = await client.room_messages(room_id, from_token=None, direction="b", limit=100)
    events = [e for e in page.get("chunk", []) if e.get("type") == "m.room.message"]
    return list(reversed(events))


async def wait_room_messages(
    client: MatrixClient, room_id: str, count: int
) -> list[dict[str, Any]]:
    return await eventually(
        lambda: room_messages(client, room_id),
        until=lambda events: len(events) >= count,
        what=f"{count} messages in {room_id}",
        timeout_s=WAIT_S,
        interval_s=0.1,
    )


async def join_when_invited(client: MatrixClient, room_id: str) -> None:
    async def joined() -> bool:
        await client.join(room_id)
        return True

    await eventually(
        joined,
        what=f"an invitation to {room_id}",
        timeout_s=WAIT_S,
        interval_s=0.1,
        ignore=(Exception,),
    )


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
