"""Store first, then enqueue: the common tail of every inbound webhook."""

from __future__ import annotations

import asyncio

from assistantx.adapters.messenger.matrix.store import EventStore
from assistantx.core.ports.messenger import InboundMessage


async def accept_and_enqueue(
    store: EventStore, inbox: asyncio.Queue[InboundMessage], message: InboundMessage
) -> bool:
    """Durably record ``message`` unless already seen, then queue it; True if it was new."""
    fresh = await store.accept([message])
    for new in fresh:
        inbox.put_nowait(new)  # an unbounded queue: answering fast matters more than pacing
    return bool(fresh)
