"""The messengers start and stop cleanly, twice in a row, and again after a stop."""

from __future__ import annotations

import asyncio
from pathlib import Path

import pytest
from pydantic import SecretStr

from assistantx.adapters.messenger.builtin import BuiltinMessenger
from assistantx.adapters.messenger.matrix import MatrixConfig, MatrixMessenger, SqliteEventStore
from assistantx.core.clock import SimClock
from assistantx.core.ports.messenger import ChatRef, InboundMessage, OutboundMessage
from assistantx.store.journal import Journal
from helpers.eventually import eventually


async def test_builtin_messenger_starts_and_stops_twice(tmp_path: Path) -> None:
    journal = Journal.open(tmp_path / "journal.db")
    messenger = BuiltinMessenger(journal, SimClock())
    try:
        for n in range(2):
            await messenger.start()
            await messenger.start()
            sent = await messenger.send(
                OutboundMessage(chat=ChatRef(kind="dm", id="lee"), text=f"{n}")
            )
            assert sent.platform == "builtin"
            await messenger.stop()
            await messenger.stop()
            assert not messenger.started
    finally:
        journal.close()


async def test_matrix_messenger_tracks_its_poller_and_stops_twice(
    tmp_path: Path, caplog: pytest.LogCaptureFixture
) -> None:
    """Pull mode against a homeserver that is not there: the poller keeps retrying in its
    task until the messenger stops, which ends it."""
    config = MatrixConfig(
        homeserver_url="http://127.0.0.1:9",
        server_name="office.test",
        as_token=SecretStr("as"),
        hs_token=SecretStr("hs"),
        mode="pull",
        pull_user_id="@sync:office.test",
        pull_access_token=SecretStr("pull"),
        people={"lee": "@lee:office.test"},
        max_retries=0,
    )
    store = SqliteEventStore(tmp_path / "events.db")
    messenger = MatrixMessenger(config, store)
    messenger.connect_inbox(asyncio.Queue[InboundMessage]())
    try:
        for round_ in range(2):
            await messenger.start()
            await messenger.start()
            poller = messenger.poller
            assert poller is not None and poller.started
            polling = poller.tasks
            assert len(polling) == 1
            # The first /sync fails (nothing listens there): it backs off, still running.
            await eventually(
                lambda: [r for r in caplog.records if "/sync failed" in r.getMessage()],
                until=lambda failed, seen=round_: len(failed) > seen,
                what="the poller's first failed /sync",
            )
            assert not any(task.done() for task in polling)
            await messenger.stop()
            await messenger.stop()
            assert all(task.done() for task in polling) and not poller.started
            assert messenger.poller is None and not messenger.started
    finally:
        await store.close()
