"""Synapse redelivers what the assistant did not acknowledge; nothing is lost or doubled.

Synapse retries a failed transaction after 2 s, then 4 s, 8 s... (``_Recoverer`` in
synapse/appservice/scheduler.py), so one injected failure costs about 2 s here.
"""

from __future__ import annotations

import asyncio
import time
from collections.abc import Sequence
from pathlib import Path

import pytest

from assistantx.adapters.messenger.matrix import (
    MatrixConfig,
    MatrixMessenger,
    SqliteEventStore,
)
from assistantx.core.errors import MessengerError
from assistantx.core.ports.messenger import InboundMessage
from helpers.eventually import assert_quiet, eventually
from synapse.gateway import AppserviceGateway
from synapse.helpers import Colleague, bridge, dm_with, next_message, say

pytestmark = [pytest.mark.synapse, pytest.mark.asyncio(loop_scope="session")]


class FailsOnceStore(SqliteEventStore):
    """The real store, except the first write holding a message fails (a disk hiccup)."""

    def __init__(self, path: Path) -> None:
        super().__init__(path)
        self.failures_left = 1
        self.failed_at: float | None = None

    async def accept(
        self, messages: Sequence[InboundMessage], **kwargs: str | None
    ) -> list[InboundMessage]:
        if messages and self.failures_left:
            self.failures_left -= 1
            self.failed_at = time.monotonic()
            raise MessengerError("injected: the event store is unavailable")
        return await super().accept(messages, **kwargs)  # type: ignore[arg-type]


async def test_a_failed_transaction_is_retried_and_handled_once(
    lee: Colleague,
    lee_config: MatrixConfig,
    gateway_mounts: AppserviceGateway,
    inbox: asyncio.Queue[InboundMessage],
    tmp_path: Path,
) -> None:
    store = FailsOnceStore(tmp_path / "e.db")
    messenger = bridge(lee_config, store, inbox, gateway_mounts)
    async with messenger:
        room = await dm_with(lee.client, lee_config.bot_user_id)
        event_id = await say(lee.client, room, "bring the signed form")
        message = await next_message(inbox)
        assert store.failures_left == 0 and store.failed_at is not None
        assert message.event_id == event_id
        # It came from Synapse's retry, after the backoff, not from the first attempt.
        assert time.monotonic() - store.failed_at >= 1.0
        await assert_quiet(inbox, 1.0, what="extra inbound message")
    await store.close()


async def test_restart_between_transactions_loses_nothing(
    lee: Colleague,
    lee_config: MatrixConfig,
    gateway_mounts: AppserviceGateway,
    inbox: asyncio.Queue[InboundMessage],
    tmp_path: Path,
) -> None:
    config, person = lee_config, lee.client
    db = tmp_path / "events.db"
    first = bridge(config, SqliteEventStore(db), inbox, gateway_mounts)
    async with first:
        room = await dm_with(person, config.bot_user_id)
        one = await say(person, room, "first")
        got_one = await next_message(inbox)
        assert got_one.event_id == one
        await first.acknowledge(got_one)
        # A second message is accepted (stored, queued) but the app dies before handling it.
        two = await say(person, room, "second")
        assert (await next_message(inbox)).event_id == two
    await first.store.close()

    gateway_mounts.go_down()  # the service is restarting: Synapse gets 503 and backs off
    refused = gateway_mounts.refused
    three = await say(person, room, "third")
    await eventually(
        lambda: gateway_mounts.refused > refused, what="Synapse's push of the third message"
    )

    second = MatrixMessenger(config, SqliteEventStore(db))
    fresh_inbox: asyncio.Queue[InboundMessage] = asyncio.Queue()
    second.connect_inbox(fresh_inbox)
    async with second:
        gateway_mounts.mount(second.appservice_router())
        replayed = await next_message(fresh_inbox)  # accepted before the restart, unhandled
        assert replayed.event_id == two
        redelivered = await next_message(fresh_inbox)  # Synapse's retry after the 503
        assert redelivered.event_id == three
        await assert_quiet(fresh_inbox, 1.0, what="extra inbound message")
    await second.store.close()
