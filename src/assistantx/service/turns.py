"""Requests first: running instructions take turns on the event loop, one piece at a time,
and wait while requests are being answered.

Each instruction's trace event is a point where it can wait (``Turns.take``): between two
events it runs on the loop without a pause (its reasoner's reading and planning, a message to a
colleague, the world's snapshot). A journal group commit wakes every instruction it held at
once, and a request that came in meanwhile waited behind all of them (200 instructions woken
together held a GET for hundreds of milliseconds). Here a woken instruction goes back to the
end of the line at its next event, the line moves one instruction per turn of the loop (so
the loop polls its sockets between any two of them), and while a request is in flight (from
its arrival until its answer's headers are sent: a stream counts until it starts) the line
does not move at all, except once every ``HOLD_MAX_S``, so that a steady stream of requests
slows the instructions and never stops them.

One line per event loop (``turns_of``): every office of a process shares the loop, so they
share its line; ``RequestsFirst`` counts the requests of the whole app.
"""

from __future__ import annotations

import asyncio
import weakref
from collections import deque

from starlette.types import ASGIApp, Message, Receive, Scope, Send

HOLD_MAX_S = 0.02  # while requests are in flight, one instruction moves at least this often


class Turns:
    """The line of instructions waiting for their turn on one event loop."""

    def __init__(self, loop: asyncio.AbstractEventLoop, *, hold_max_s: float = HOLD_MAX_S):
        self._loop = loop
        self._hold_max_s = hold_max_s
        self._line: deque[asyncio.Future[None]] = deque()
        self._requests = 0  # in flight, not answered yet
        self._last_move = float("-inf")
        self._mover: asyncio.Handle | None = None  # the next move, scheduled
        self._mover_waits = False  # ... on a timer, for the hold to end

    @property
    def waiting(self) -> int:
        return sum(not turn.done() for turn in self._line)

    @property
    def requests(self) -> int:
        return self._requests

    async def take(self) -> None:
        """Wait for this instruction's turn."""
        turn: asyncio.Future[None] = self._loop.create_future()
        if not self._line:  # the hold counts from the moment someone waits
            self._last_move = max(self._last_move, self._loop.time())
        self._line.append(turn)
        self._schedule()
        await turn

    async def take_after(self, _event: object) -> None:
        """``take`` as a trace event's sink (``Assistant.subscribe``)."""
        await self.take()

    def request_started(self) -> None:
        self._requests += 1

    def request_answered(self) -> None:
        self._requests -= 1
        if self._requests == 0 and self._mover is not None and self._mover_waits:
            self._mover.cancel()  # no need to wait for the hold to end
            self._mover = None
            self._schedule()

    def _held_for_s(self) -> float:
        """How long the line must still wait for the requests in flight (0: it may move)."""
        if not self._requests:
            return 0.0
        return max(0.0, self._last_move + self._hold_max_s - self._loop.time())

    def _schedule(self) -> None:
        if self._mover is not None or not self._line:
            return
        held_s = self._held_for_s()
        self._mover_waits = held_s > 0
        if self._mover_waits:
            self._mover = self._loop.call_later(held_s, self._move)
        else:
            self._mover = self._loop.call_soon(self._move)

    def _move(self) -> None:
        """Let the first instruction in line go on; the next one goes at a later turn."""
        self._mover, self._mover_waits = None, False
        if self._held_for_s() == 0:
            while self._line:
                turn = self._line.popleft()
                if not turn.done():  # a cancelled waiter has left the line
                    turn.set_result(None)
                    self._last_move = self._loop.time()
                    break
        self._schedule()


_TURNS: weakref.WeakKeyDictionary[asyncio.AbstractEventLoop, Turns] = weakref.WeakKeyDictionary()


def turns_of(loop: asyncio.AbstractEventLoop | None = None) -> Turns:
    """The line of ``loop`` (the running loop when None)."""
    loop = loop or asyncio.get_running_loop()
    turns = _TURNS.get(loop)
    if turns is None:
        turns = _TURNS[loop] = Turns(loop)
    return turns


class RequestsFirst:
    """Counts every HTTP request from its arrival until its answer's headers are sent (or its
    app call ends without them), so that instructions wait meanwhile (``Turns``)."""

    def __init__(self, app: ASGIApp) -> None:
        self.app = app

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        turns = turns_of()
        turns.request_started()
        answered = False

        async def answering(message: Message) -> None:
            nonlocal answered
            if message["type"] == "http.response.start" and not answered:
                answered = True
                turns.request_answered()
            await send(message)

        try:
            await self.app(scope, receive, answering)
        finally:
            if not answered:
                answered = True
                turns.request_answered()
