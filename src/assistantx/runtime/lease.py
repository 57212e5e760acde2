"""The robot and its locker are one shared body: leased to one instruction at a time.

An instruction takes the lease when it first needs the body (a move, a QR code, a hand-over)
and keeps it until it ends, so two instructions never interleave their moves or mix up the
locker's contents. Waiting instructions queue in arrival order and can see the queue.
"""

from __future__ import annotations

import asyncio
from collections import deque
from collections.abc import Callable


class BodyLease:
    """The one robot's lease (``runtime.fleet.FleetLease``: one per robot of a fleet)."""

    def __init__(self) -> None:
        self._holder: str | None = None
        self._waiting: deque[tuple[str, asyncio.Future[None]]] = deque()

    @property
    def holder(self) -> str | None:
        return self._holder

    def queue(self) -> list[str]:
        """The holder first, then the waiting instructions in order."""
        head = [self._holder] if self._holder else []
        return head + [iid for iid, _ in self._waiting]

    def holds(self, instruction_id: str) -> bool:
        return self._holder == instruction_id

    async def acquire(
        self,
        instruction_id: str,
        on_wait: Callable[[list[str]], None] | None = None,
        toward: str | None = None,
    ) -> None:
        """``toward``: where the instruction drives first; one robot goes wherever it must
        (a fleet's lease picks the robot by it)."""
        del toward
        if self._holder == instruction_id:
            return
        if self._holder is None and not self._waiting:
            self._holder = instruction_id
            return
        future: asyncio.Future[None] = asyncio.get_running_loop().create_future()
        self._waiting.append((instruction_id, future))
        if on_wait is not None:
            on_wait(self.queue())
        try:
            await future
        except asyncio.CancelledError:
            self._waiting = deque((i, f) for i, f in self._waiting if f is not future)
            if self._holder == instruction_id:
                self.release(instruction_id)
            raise

    def release(self, instruction_id: str) -> None:
        if self._holder != instruction_id:
            self._waiting = deque((i, f) for i, f in self._waiting if i != instruction_id)
            return
        self._holder = None
        while self._waiting:
            next_id, future = self._waiting.popleft()
            if not future.done():
                self._holder = next_id
                future.set_result(None)
                return
