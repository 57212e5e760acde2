"""Requests first (service.turns): instructions move one at a time, in the order they came,
one per turn of the loop, and not at all while a request is being answered, except once per
hold; a waiter that is cancelled leaves the line; the middleware counts a request until its
answer's headers are sent, also when the app fails."""

from __future__ import annotations

import asyncio

import pytest
from starlette.types import Message, Receive, Scope, Send

from assistantx.service.turns import RequestsFirst, Turns, turns_of

FOREVER_S = 3600.0  # a hold that never ends within a test


async def _turns_of_loop(n: int) -> None:
    for _ in range(n):
        await asyncio.sleep(0)


async def test_instructions_move_in_order_one_per_turn_of_the_loop() -> None:
    loop = asyncio.get_running_loop()
    turns = Turns(loop, hold_max_s=FOREVER_S)
    happened: list[str] = []

    async def instruction(name: str) -> None:
        await turns.take()
        happened.append(name)
        # Runs at the loop's next turn: before the next instruction, when only one moves a turn.
        loop.call_soon(happened.append, f"turn after {name}")

    await asyncio.gather(*(instruction(n) for n in ("a", "b", "c")))
    await _turns_of_loop(2)
    assert happened == ["a", "turn after a", "b", "turn after b", "c", "turn after c"]


async def test_the_line_stands_while_a_request_is_answered() -> None:
    turns = Turns(asyncio.get_running_loop(), hold_max_s=FOREVER_S)
    turns.request_started()
    waiting = asyncio.create_task(turns.take())
    await _turns_of_loop(50)
    assert not waiting.done() and turns.waiting == 1
    turns.request_answered()
    await asyncio.wait_for(waiting, 5)
    assert turns.waiting == 0 and turns.requests == 0


async def test_a_steady_stream_of_requests_still_lets_instructions_move() -> None:
    turns = Turns(asyncio.get_running_loop(), hold_max_s=0.0)
    turns.request_started()  # never answered in this test
    await asyncio.wait_for(asyncio.gather(turns.take(), turns.take()), 5)
    assert turns.requests == 1


async def test_requests_answered_after_a_hold_ended_let_the_rest_move() -> None:
    turns = Turns(asyncio.get_running_loop(), hold_max_s=0.01)
    turns.request_started()
    first = asyncio.create_task(turns.take())
    await asyncio.wait_for(first, 5)  # the hold ended: one moved, with the request in flight
    turns.request_answered()  # nobody in line now
    await asyncio.wait_for(turns.take(), 5)
    assert turns.waiting == 0 and turns.requests == 0


async def test_a_cancelled_waiter_leaves_the_line() -> None:
    turns = Turns(asyncio.get_running_loop(), hold_max_s=FOREVER_S)
    turns.request_started()
    first = asyncio.create_task(turns.take())
    second = asyncio.create_task(turns.take())
    await _turns_of_loop(5)
    first.cancel()
    await _turns_of_loop(5)
    assert turns.waiting == 1
    turns.request_answered()
    await asyncio.wait_for(second, 5)
    assert first.cancelled()


def _app(seen: list[int], *, fail: bool = False) -> RequestsFirst:
    async def app(scope: Scope, receive: Receive, send: Send) -> None:
        seen.append(turns_of().requests)  # inside: counted
        if fail:
            raise RuntimeError("the app failed before answering")
        await send({"type": "http.response.start", "status": 200, "headers": []})
        seen.append(turns_of().requests)  # headers sent: no longer counted
        await send({"type": "http.response.body", "body": b"streamed on", "more_body": True})

    return RequestsFirst(app)


async def _call(app: RequestsFirst) -> None:
    async def receive() -> Message:
        return {"type": "http.request", "body": b"", "more_body": False}

    async def send(message: Message) -> None:
        pass

    await app({"type": "http", "method": "GET", "path": "/"}, receive, send)


async def test_a_request_counts_until_its_answer_starts() -> None:
    seen: list[int] = []
    await _call(_app(seen))
    assert seen == [1, 0]
    assert turns_of().requests == 0


async def test_a_request_whose_app_fails_stops_counting() -> None:
    seen: list[int] = []
    with pytest.raises(RuntimeError):
        await _call(_app(seen, fail=True))
    assert seen == [1]
    assert turns_of().requests == 0
