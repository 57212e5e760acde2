"""Fan-out of journaled trace events to live listeners (the SSE streams).

Each listener has a bounded queue; a listener that falls that far behind is dropped (its
stream ends and the client reconnects with Last-Event-ID, replaying from the journal), so a
slow client never holds memory or slows the loop.
"""

from __future__ import annotations

import asyncio
import logging
from dataclasses import dataclass

from assistantx.store.journal import EventRecord

logger = logging.getLogger(__name__)


@dataclass(eq=False)
class Listener:
    queue: asyncio.Queue[EventRecord | None]
    instruction_id: str | None
    dropped: bool = False


class EventHub:
    def __init__(self, max_backlog: int = 1000) -> None:
        self._listeners: set[Listener] = set()
        self._max_backlog = max_backlog
        self.closed = False

    def subscribe(self, instruction_id: str | None = None) -> Listener:
        listener = Listener(asyncio.Queue(self._max_backlog), instruction_id)
        if self.closed:  # shutting down: the stream replays what is journaled, then ends
            listener.queue.put_nowait(None)
            listener.dropped = True
            return listener
        self._listeners.add(listener)
        return listener

    def unsubscribe(self, listener: Listener) -> None:
        self._listeners.discard(listener)

    def publish(self, record: EventRecord) -> None:
        for listener in list(self._listeners):
            if listener.instruction_id not in (None, record.event.instruction_id):
                continue
            try:
                listener.queue.put_nowait(record)
            except asyncio.QueueFull:
                logger.info("dropping a slow event listener")
                self._drop(listener)

    def close(self) -> None:
        """End every stream, and any opened from now on (shutdown); idempotent."""
        self.closed = True
        for listener in list(self._listeners):
            self._drop(listener)

    def _drop(self, listener: Listener) -> None:
        listener.dropped = True
        self._listeners.discard(listener)
        while listener.queue.full():  # make room for the end marker
            listener.queue.get_nowait()
        listener.queue.put_nowait(None)

    def __len__(self) -> int:
        return len(self._listeners)
