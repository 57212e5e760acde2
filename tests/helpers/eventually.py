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


def _timed_out(what: str, timeout_s: float, last: object) -> AssertionError:
    shown = "nothing yet" if last is _NOTHING_YET else repr(last)
    if len(shown) > 400:
        shown = shown[:400] + "..."
    return AssertionError(f"timed out after {timeout_s:g} s waiting for {what} (last: {shown})")


async def eventually(
    condition: Callable[[], T | Awaitable[T]],
    *,
    what: str,
    timeout_s: float = 30.0,
    interval_s: float = 0.02,
    ignore: tuple[type[BaseException], ...] = (),
    until: Callable[[T], object] = bool,
) -> T:
    """The first truthy value of ``condition()`` (sync or async) within ``timeout_s``."""
    deadline = time.monotonic() + timeout_s
    last: object = _NOTHING_YET
    while True:
        try:
            value = condition()
            if inspect.isawaitable(value):
                value = await value
        except ignore as exc:
            last = exc
        else:
            if until(value):  # type: ignore[arg-type]
                return value  # type: ignore[return-value]
            last = value
        if time.monotonic() >= deadline:
            raise _timed_out(what, timeout_s, last)
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
    deadline = time.monotonic() + timeout_s
    last: object = _NOTHING_YET
    while True:
        try:
            value = condition()
        except ignore as exc:
            last = exc
        else:
            if until(value):
                return value
            last = value
        if time.monotonic() >= deadline:
            raise _timed_out(what, timeout_s, last)
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
