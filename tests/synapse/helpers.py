"""Small waits and reads shared by the Synapse tests."""

from __future__ import annotations

import asyncio
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from assistantx.adapters.messenger.matrix import (
    EventStore,
    MatrixClient,
    MatrixConfig,
    MatrixMessenger,
    SqliteEventStore,
)
from assistantx.core.ports.messenger import InboundMessage
from helpers.eventually import eventually
from synapse.gateway import AppserviceGateway
from synapse.homeserver import Account

WAIT_S = 20.0


@dataclass(frozen=True)
class Colleague:
    """A person of the office on Matrix: their account and their own client (closed after the
    test)."""

    account: Account
    client: MatrixClient


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


def pull_config(
    config: MatrixConfig, account: Account, mode: str, sync_timeout_s: float = 1.0, **update: Any
) -> MatrixConfig:
    """``config`` in mode ``pull`` or ``both``, polling as ``account``."""
    return derive(
        config,
        mode=mode,
        pull_user_id=account.user_id,
        pull_access_token=account.access_token,
        sync_timeout_s=sync_timeout_s,
        **update,
    )


def bridge(
    config: MatrixConfig,
    store: EventStore,
    inbox: asyncio.Queue[InboundMessage],
    gateway: AppserviceGateway | None = None,
) -> MatrixMessenger:
    """A messenger (not started) on ``store`` delivering to ``inbox``; with ``gateway``, the
    homeserver's pushes go to it."""
    messenger = MatrixMessenger(config, store)
    messenger.connect_inbox(inbox)
    if gateway is not None:
        gateway.mount(messenger.appservice_router())
    return messenger


async def dm_with(person: MatrixClient, user_id: str) -> str:
    """A direct chat ``person`` opens with ``user_id``; returns once they joined."""
    room = await person.create_room(invite=[user_id], is_direct=True)
    await wait_joined(person, room, user_id)
    return room


async def say(person: MatrixClient, room: str, text: str) -> str:
    """``person`` writes ``text`` (also its transaction id: one text, one message)."""
    return await person.send_event(
        room, "m.room.message", {"msgtype": "m.text", "body": text}, txn_id=text
    )


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
