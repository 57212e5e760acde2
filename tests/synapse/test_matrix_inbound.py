"""A person writes to the assistant on a real Synapse: push, pull, and both at once."""

from __future__ import annotations

import asyncio
from collections.abc import Callable
from pathlib import Path

import pytest

from assistantx.adapters.messenger.matrix import (
    EventIngestor,
    EventNormalizer,
    MatrixClient,
    MatrixConfig,
    MatrixMessenger,
    SqliteEventStore,
    SyncPoller,
)
from assistantx.core.ports.messenger import InboundMessage
from helpers.eventually import assert_quiet
from synapse.gateway import AppserviceGateway
from synapse.helpers import (
    Colleague,
    OfferCountingStore,
    bridge,
    dm_with,
    next_message,
    pull_config,
    say,
    wait_joined,
)
from synapse.homeserver import Account, SynapseHomeserver

pytestmark = [pytest.mark.synapse, pytest.mark.asyncio(loop_scope="session")]


async def test_push_dm_arrives_normalized_once(
    lee: Colleague,
    lee_config: MatrixConfig,
    pushed: MatrixMessenger,
    inbox: asyncio.Queue[InboundMessage],
) -> None:
    async with pushed:
        room = await dm_with(lee.client, lee_config.bot_user_id)  # joined on the pushed invite
        event_id = await say(lee.client, room, "Please fetch my printout")
        message = await next_message(inbox)
        assert message.platform == "matrix"
        assert message.event_id == event_id
        assert str(message.chat) == "dm:lee"
        assert message.sender == "lee"
        assert message.text == "Please fetch my printout"
        assert message.time.tzinfo is not None
        await assert_quiet(inbox, 1.0, what="extra inbound message")


async def test_pull_dm_arrives_once_and_position_is_kept(
    lee: Colleague,
    lee_config: MatrixConfig,
    new_account: Callable[[str], Account],
    event_store: SqliteEventStore,
    inbox: asyncio.Queue[InboundMessage],
) -> None:
    bot = new_account("syncbot")
    messenger = bridge(pull_config(lee_config, bot, "pull", 2.0), event_store, inbox)
    async with messenger:
        assert messenger.poller is not None
        await asyncio.wait_for(messenger.poller.ready.wait(), 20)
        room = await dm_with(lee.client, bot.user_id)  # the poller joined on the invite
        event_id = await say(lee.client, room, "hello by sync")
        message = await next_message(inbox)
        assert (message.event_id, str(message.chat), message.text) == (
            event_id,
            "dm:lee",
            "hello by sync",
        )
        await assert_quiet(inbox, 1.0, what="extra inbound message")
    assert await event_store.sync_token(f"matrix:{bot.user_id}") is not None


async def test_both_modes_each_message_handled_once(
    lee: Colleague,
    lee_config: MatrixConfig,
    gateway_mounts: AppserviceGateway,
    new_account: Callable[[str], Account],
    inbox: asyncio.Queue[InboundMessage],
    tmp_path: Path,
) -> None:
    bot = new_account("syncbot")
    config = pull_config(lee_config, bot, "both")
    store = OfferCountingStore(tmp_path / "events.db")
    messenger = bridge(config, store, inbox, gateway_mounts)
    person = lee.client
    async with messenger:
        assert messenger.poller is not None
        await asyncio.wait_for(messenger.poller.ready.wait(), 20)
        room = await person.create_room(invite=[config.bot_user_id, bot.user_id])
        await wait_joined(person, room, config.bot_user_id)
        await wait_joined(person, room, bot.user_id)
        sent = [await say(person, room, f"m{i}") for i in range(3)]
        received = [await next_message(inbox) for _ in sent]
        assert sorted(m.event_id for m in received) == sorted(sent)
        # Wait until BOTH paths have offered every message, then nothing more may arrive.
        async with asyncio.timeout(20):
            await store.wait_offered(sent, times=2)
        await assert_quiet(inbox, 0.5, what="extra inbound message")
    await store.close()


async def test_pull_fills_a_limited_timeline_gap(
    homeserver: SynapseHomeserver,
    lee: Colleague,
    lee_config: MatrixConfig,
    new_account: Callable[[str], Account],
    event_store: SqliteEventStore,
    inbox: asyncio.Queue[InboundMessage],
) -> None:
    bot = new_account("syncbot")
    ingestor = EventIngestor(event_store, EventNormalizer(lee_config, {}), inbox.put)
    person = lee.client
    async with MatrixClient(homeserver.url, bot.access_token) as bot_client:
        room = await person.create_room(invite=[bot.user_id])
        await bot_client.join(room)
        poller = SyncPoller(bot_client, ingestor, sync_key="gap", timeout_s=0.5, timeline_limit=2)
        await poller.sync_once()  # first run: takes the position, replays nothing
        bodies = [f"while away {i}" for i in range(7)]
        for body in bodies:
            await say(person, room, body)
        await poller.sync_once()  # a timeline of 2, limited: the other 5 come from /messages
        got = [inbox.get_nowait().text for _ in range(inbox.qsize())]
        assert got == bodies


async def test_homeserver_ping_reaches_the_router(
    homeserver: SynapseHomeserver,
    base_config: MatrixConfig,
    gateway_mounts: AppserviceGateway,
    event_store: SqliteEventStore,
) -> None:
    messenger = MatrixMessenger(base_config, event_store)
    gateway_mounts.mount(messenger.appservice_router())
    async with MatrixClient(homeserver.url, base_config.as_token.get_secret_value()) as client:
        response = await client.request(
            "POST",
            f"/_matrix/client/v1/appservice/{base_config.appservice_id}/ping",
            json={"transaction_id": "ping-1"},
        )
    assert "duration_ms" in response.json()
