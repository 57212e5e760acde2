"""The waiting helper: returns the first truthy value, and fails naming what it waited for."""

from __future__ import annotations

import pytest

from helpers.eventually import eventually, eventually_sync


async def test_returns_the_first_truthy_value_of_a_sync_or_async_condition() -> None:
    calls: list[int] = []

    def third() -> list[int]:
        calls.append(len(calls))
        return calls if len(calls) >= 3 else []

    async def fifth() -> str:
        calls.append(len(calls))
        return "five" if len(calls) >= 5 else ""

    assert await eventually(third, what="three calls", interval_s=0) == [0, 1, 2]
    assert await eventually(fifth, what="five calls", interval_s=0) == "five"
    assert eventually_sync(lambda: len(calls) or None, what="calls", interval_s=0) == 5


async def test_a_timeout_names_what_was_awaited_and_the_last_value() -> None:
    with pytest.raises(AssertionError, match=r"waiting for lee's messages \(last: \[\]\)"):
        await eventually(list, what="lee's messages", timeout_s=0.05)
    with pytest.raises(AssertionError, match=r"waiting for a server \(last: ConnectionRefused"):
        eventually_sync(_refused, what="a server", timeout_s=0.05, ignore=(OSError,))


async def test_an_error_that_is_not_ignored_ends_the_wait_at_once() -> None:
    with pytest.raises(ConnectionRefusedError):
        await eventually(_refused, what="a server", timeout_s=60)


def _refused() -> bool:
    raise ConnectionRefusedError("nobody listens")


async def test_until_accepts_a_falsy_value_the_caller_waits_for() -> None:
    polls = iter([[1, 2], [1], []])
    assert (
        await eventually(lambda: next(polls), until=lambda v: v == [], what="an empty list") == []
    )
