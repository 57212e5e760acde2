"""What a person's Matrix client received from others, handed out to the test one at a time.

``expect`` hands out each received message once (oldest first among those that match), so a
test reads a conversation the way a person does: wait for the next message of a kind, then act.
The person's sync loop (whichever client library it uses) ``add``s what arrives.
"""

from __future__ import annotations

import asyncio
import contextlib
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from assistantx.adapters.messenger.matrix.adapter import ACK_TEXT
from synapse.helpers import WAIT_S


@dataclass(frozen=True)
class Seen:
    """One event from someone else, as the person's client received it."""

    room_id: str
    event_id: str
    sender: str
    content: dict[str, Any]
    type: str = "m.room.message"

    @property
    def msgtype(self) -> str:
        return str(self.content.get("msgtype", ""))

    @property
    def body(self) -> str:
        return str(self.content.get("body", ""))


def is_acknowledgement(message: Seen) -> bool:
    return message.body.startswith(ACK_TEXT.format(request=""))


class Inbox:
    def __init__(self, name: str) -> None:
        self.name = name
        self.seen: list[Seen] = []  # every event from others, in arrival order
        self._taken: set[str] = set()
        self._changed = asyncio.Condition()
        self._task: asyncio.Task[None] | None = None  # the client's sync loop

    async def stop_syncing(self) -> None:
        task, self._task = self._task, None
        if task is not None:
            task.cancel()
            with contextlib.suppress(asyncio.CancelledError):
                await task

    def visible(self, message: Seen) -> bool:
        """Whether ``messages`` and ``expect`` show it (a subclass may set some aside). The
        bot's "On it: ..." as an instruction starts is read apart (``acknowledgements``)."""
        return message.type == "m.room.message" and not is_acknowledgement(message)

    def acknowledgements(self) -> list[Seen]:
        return [m for m in self.seen if m.type == "m.room.message" and is_acknowledgement(m)]

    async def add(self, fresh: list[Seen]) -> None:
        if fresh:
            async with self._changed:
                self.seen.extend(fresh)
                self._changed.notify_all()

    def messages(self, predicate: Callable[[Seen], bool] = lambda m: True) -> list[Seen]:
        return [m for m in self.seen if self.visible(m) and predicate(m)]

    async def expect(
        self,
        *,
        sender: str | None = None,
        room: str | None = None,
        not_room: str | None = None,
        msgtype: str | None = None,
        timeout_s: float = WAIT_S,
    ) -> Seen:
        """The oldest message not yet taken that matches; waits for it if need be."""

        def matches(m: Seen) -> bool:
            return (
                m.event_id not in self._taken
                and self.visible(m)
                and (sender is None or m.sender == sender)
                and (room is None or m.room_id == room)
                and (not_room is None or m.room_id != not_room)
                and (msgtype is None or m.msgtype == msgtype)
            )

        try:
            async with asyncio.timeout(timeout_s), self._changed:
                await self._changed.wait_for(lambda: any(matches(m) for m in self.seen))
        except TimeoutError:
            seen = [(m.room_id, m.sender, m.msgtype, m.body) for m in self.messages()]
            raise AssertionError(
                f"{self.name} got no message from {sender} in {room} ({msgtype}) within "
                f"{timeout_s}s; received: {seen}"
            ) from None
        found = next(m for m in self.seen if matches(m))
        self._taken.add(found.event_id)
        return found
