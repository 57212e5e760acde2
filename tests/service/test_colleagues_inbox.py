"""What simulated colleagues write is journaled by a task, in order, without the event loop
waiting on the journal's commit; what is still queued at stop is journaled before it ends."""

from __future__ import annotations

import asyncio
from datetime import UTC, datetime
from pathlib import Path

from assistantx.adapters.messenger.builtin import BuiltinMessenger
from assistantx.core.clock import WallClock
from assistantx.core.ports.messenger import ChatRef, InboundMessage
from assistantx.service.colleagues import InboxRelay
from assistantx.store.journal import Journal


def _from_wang(n: int) -> InboundMessage:
    return InboundMessage(
        platform="sim",
        event_id=f"sim-{n}",
        chat=ChatRef(kind="dm", id="wang"),
        sender="wang",
        text=f"message {n}",
        time=datetime.now(tz=UTC),
    )


async def test_messages_put_without_waiting_are_journaled_in_order_by_stop(
    tmp_path: Path,
) -> None:
    journal = Journal.open(tmp_path / "journal.sqlite3")
    messenger = BuiltinMessenger(journal, WallClock())
    assistant_inbox: asyncio.Queue[InboundMessage] = asyncio.Queue()
    messenger.connect_inbox(assistant_inbox)
    try:
        async with InboxRelay(messenger) as relay:
            for n in range(5):
                relay.put_nowait(_from_wang(n))  # what the simulator calls: it returns at once
            assert journal.messages() == []  # nothing committed while the loop has not run
        # Leaving the context handed on everything queued.
        assert [m.text for m in journal.messages()] == [f"message {n}" for n in range(5)]
        assert [assistant_inbox.get_nowait().text for _ in range(5)] == [
            f"message {n}" for n in range(5)
        ]
    finally:
        journal.close()


async def test_a_duplicate_is_skipped_and_the_relay_keeps_going(tmp_path: Path) -> None:
    journal = Journal.open(tmp_path / "journal.sqlite3")
    messenger = BuiltinMessenger(journal, WallClock())
    try:
        async with InboxRelay(messenger) as relay:
            relay.put_nowait(_from_wang(1))
            relay.put_nowait(_from_wang(1))  # the same event id again
            relay.put_nowait(_from_wang(2))
        assert [m.text for m in journal.messages()] == ["message 1", "message 2"]
    finally:
        journal.close()
