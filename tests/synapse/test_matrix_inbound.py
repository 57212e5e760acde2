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
    OfferCountingStore,
    bridge,
    derive,
    dm_with,
    next_message,
    pull_config,
    say,
    wait_joined,
)
from synapse.homeserver import Account, SynapseHomeserver

pytestmark = [pytest.mark.synapse, pytest.mark.asyncio(loop_scope="session")]


async def test_push_dm_arrives_normalized_once(
    base_config: MatrixConfig,
    gateway_mounts: AppserviceGateway,
    new_account: Callable[[str], Account],
    inbox: asyncio.Queue[InboundMessage],
    tmp_path: Path,
) -> None:
    lee = new_account("lee")
    config = derive(base_config, people={"lee": lee.user_id})
    messenger = bridge(config, SqliteEventStore(tmp_path / "events.db"), inbox, gateway_mounts)
    async with messenger, MatrixClient(config.homeserver_url, lee.access_token) as person:
        room = await dm_with(person, config.bot_user_id)  # auto-joined on the pushed invite
        event_id = await say(person, room, "Please fetch my printout")
        message = await next_message(inbox)
        assert message.platform == "matrix"
        assert message.event_id == event_id
        assert str(message.chat) == "dm:lee"
        assert message.sender == "lee"
        assert message.text == "Please fetch my printout"
        assert message.time.tzinfo is not None
        await assert_quiet(inbox, 1.0, what="extra inbound message")


async def test_pull_dm_arrives_once_and_position_is_kept(
    base_config: MatrixConfig,
    new_account: Callable[[str], Account],
    inbox: asyncio.Queue[InboundMessage],
    tmp_path: Path,
) -> None:
    lee, bot = new_account("lee"), new_account("syncbot")
    config = pull_config(base_config, bot, "pull", 2.0, people={"lee": lee.user_id})
    store = SqliteEventStore(tmp_path / "events.db")
    messenger = bridge(config, store, inbox)
    async with messenger, MatrixClient(config.homeserver_url, lee.access_token) as person:
        assert messenger.poller is not None
        await asyncio.wait_for(messenger.poller.ready.wait(), 20)
        room = await dm_with(person, bot.user_id)  # the poller joined on the invite
        event_id = await say(person, room, "hello by sync")
        message = await next_message(inbox)
        assert (message.event_id, str(message.chat), message.text) == (
            event_id,
            "dm:lee",
            "hello by sync",
        )
        await assert_quiet(inbox, 1.0, what="extra inbound message")
    assert await store.sync_token(f"matrix:{bot.user_id}") is not None


async def test_both_modes_each_message_handled_once(
    base_config: MatrixConfig,
    gateway_mounts: AppserviceGateway,
    new_account: Callable[[str], Account],
    inbox: asyncio.Queue[InboundMessage],
    tmp_path: Path,
) -> None:
    lee, bot = new_account("lee"), new_account("syncbot")
    config = pull_config(base_config, bot, "both", people={"lee": lee.user_id})
    store = OfferCountingStore(tmp_path / "events.db")
    messenger = bridge(config, store, inbox, gateway_mounts)
    async with messenger, MatrixClient(config.homeserver_url, lee.access_token) as person:
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


async def test_pull_fills_a_limited_timeline_gap(
    homeserver: SynapseHomeserver,
    base_config: MatrixConfig,
    new_account: Callable[[str], Account],
    inbox: asyncio.Queue[InboundMessage],
    tmp_path: Path,
) -> None:
    lee, bot = new_account("lee"), new_account("syncbot")
    config = derive(base_config, people={"lee": lee.user_id})
    store = SqliteEventStore(tmp_path / "events.db")
    ingestor = EventIngestor(store, EventNormalizer(config, {}), inbox.put)
    async with (
        MatrixClient(homeserver.url, bot.access_token) as bot_client,
        MatrixClient(homeserver.url, lee.access_token) as person,
    ):
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
    inbox: asyncio.Queue[InboundMessage],
    tmp_path: Path,
) -> None:
    messenger = MatrixMessenger(base_config, SqliteEventStore(tmp_path / "events.db"))
    gateway_mounts.mount(messenger.appservice_router())
    async with MatrixClient(homeserver.url, base_config.as_token.get_secret_value()) as client:
        response = await client.request(
            "POST",
            f"/_matrix/client/v1/appservice/{base_config.appservice_id}/ping",
            json={"transaction_id": "ping-1"},
        )
    assert "duration_ms" in response.json()
