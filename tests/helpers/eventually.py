"""Wait until a condition holds, with a deadline and a failure that says what was awaited.

For the few things a test cannot await directly (a counter inside a client, a server's
``started`` flag, a state read over HTTP). Where a real event exists (a task, a queue, an
instruction-end hook, an SSE event), a test waits on that instead.

The condition is called until it returns something truthy (or, given ``until``, something
``until`` accepts), which ``eventually`` returns; an exception it raises ends the wait at once,
except the types named in ``ignore`` (for example a connection refused while a server starts),
which count as "not yet".
"""

from __future__ import annotations

import asyncio
import inspect
import time
from collections.abc import Awaitable, Callable
from typing import Any, TypeVar

T = TypeVar("T")

_NOTHING_YET = object()


class _Poll:
    """One wait's bookkeeping: its deadline, the last value seen, and the failure."""

    def __init__(self, what: str, timeout_s: float) -> None:
        self.what, self.timeout_s = what, timeout_s
        self.deadline = time.monotonic() + timeout_s
        self.last: object = _NOTHING_YET

    def expire(self) -> None:
        """Raise the timeout, naming what was awaited and the last value seen."""
        if time.monotonic() < self.deadline:
            return
        shown = "nothing yet" if self.last is _NOTHING_YET else repr(self.last)
        if len(shown) > 400:
            shown = shown[:400] + "..."
        raise AssertionError(
            f"timed out after {self.timeout_s:g} s waiting for {self.what} (last: {shown})"
        )


async def eventually(
    condition: Callable[[], T | Awaitable[T]],
    *,
    what: str,
    timeout_s: float = 30.0,
    interval_s: float = 0.02,
    ignore: tuple[type[BaseException], ...] = (),
    until: Callable[[T], object] = bool,
) -> T:
    """The first value of ``condition()`` (sync or async) that ``until`` accepts."""
    poll = _Poll(what, timeout_s)
    while True:
        try:
            value = condition()
            poll.last = value = await value if inspect.isawaitable(value) else value
            if until(value):  # type: ignore[arg-type]
                return value  # type: ignore[return-value]
        except ignore as exc:
            poll.last = exc
        poll.expire()
        await asyncio.sleep(interval_s)


def eventually_sync(
    condition: Callable[[], T],
    *,
    what: str,
    timeout_s: float = 30.0,
    interval_s: float = 0.05,
    ignore: tuple[type[BaseException], ...] = (),
    until: Callable[[T], object] = bool,
) -> T:
    """The blocking twin of :func:`eventually`, for tests that drive subprocesses or a browser."""
    poll = _Poll(what, timeout_s)
    while True:
        try:
            poll.last = value = condition()
            if until(value):
                return value
        except ignore as exc:
            poll.last = exc
        poll.expire()
        time.sleep(interval_s)


async def assert_quiet(queue: asyncio.Queue[Any], seconds: float, *, what: str) -> None:
    """Nothing more arrives on ``queue`` within ``seconds`` (no duplicate, no stray event).

    A check that something does *not* happen can only wait a while; it waits on the queue
    itself, so an extra item fails the test the moment it arrives."""
    try:
        extra = await asyncio.wait_for(queue.get(), seconds)
    except TimeoutError:
        return
    raise AssertionError(f"unexpected {what}: {extra!r}")
