"""Backoff delays, Retry-After parsing, and the one retrying transport against a real server."""

from __future__ import annotations

import asyncio
import time
from email.utils import formatdate
from typing import Any

import httpx
import pytest
from fastapi import FastAPI
from fastapi.responses import JSONResponse

from assistantx.core.http_retry import (
    TRIES,
    RetryingTransport,
    RetryPolicy,
    Try,
    is_retryable_status,
    parse_retry_after,
)
from helpers.servers import refusing_port, serve_asgi

NOW = 1_750_000_000.0


@pytest.mark.parametrize(
    ("value", "expected"),
    [
        ("3", 3.0),
        (" 0.25 ", 0.25),
        ("-5", 0.0),
        (None, None),
        ("", None),
        ("soon", None),
        ("nan", None),
        (formatdate(NOW + 30, usegmt=True), 30.0),
        (formatdate(NOW - 30, usegmt=True), 0.0),
    ],
)
def test_parse_retry_after(value: str | None, expected: float | None) -> None:
    assert parse_retry_after(value, now=NOW) == expected


def test_backoff_grows_exponentially_with_full_jitter() -> None:
    policy = RetryPolicy(base_delay_s=1.0, max_delay_s=8.0, seed=1)
    for index, ceiling in enumerate([1.0, 2.0, 4.0, 8.0, 8.0, 8.0]):
        delay = policy.delay_s(index)
        assert 0.0 <= delay <= ceiling


def test_backoff_is_reproducible_from_the_seed() -> None:
    first = [RetryPolicy(seed=5).delay_s(i) for i in range(4)]
    again = [RetryPolicy(seed=5).delay_s(i) for i in range(4)]
    other = [RetryPolicy(seed=6).delay_s(i) for i in range(4)]
    assert first == again
    assert first != other


def test_retry_after_replaces_backoff_up_to_the_cap() -> None:
    policy = RetryPolicy(base_delay_s=1.0, retry_after_cap_s=10.0)
    assert policy.delay_s(3, retry_after_s=2.5) == 2.5
    assert policy.delay_s(0, retry_after_s=600.0) == 10.0


def test_invalid_policy_rejected() -> None:
    with pytest.raises(ValueError, match="max_retries"):
        RetryPolicy(max_retries=-1)
    with pytest.raises(ValueError, match="delays"):
        RetryPolicy(base_delay_s=-1)


@pytest.mark.parametrize(
    ("status", "retry"),
    [
        (429, True),
        (500, True),
        (503, True),
        (408, True),
        (400, False),
        (401, False),
        (404, False),
        (422, False),
    ],
)
def test_retryable_statuses(status: int, retry: bool) -> None:
    assert is_retryable_status(status) is retry


# -- the transport, against a real local server ---------------------------------------------


def answering(answers: list[tuple[int, dict[str, str]]], seen: list[float]) -> FastAPI:
    """Answers each request with the next scripted (status, headers); records when."""
    app = FastAPI()

    @app.post("/call")
    async def call() -> JSONResponse:
        seen.append(time.monotonic())
        status, headers = answers.pop(0)
        return JSONResponse({"status": status}, status_code=status, headers=headers)

    return app


def fast(max_retries: int = 4, **options: Any) -> RetryPolicy:
    return RetryPolicy(max_retries=max_retries, base_delay_s=0.001, max_delay_s=0.002, **options)


async def test_429_and_503_are_retried_honouring_retry_after() -> None:
    seen: list[float] = []
    answers = [(429, {"Retry-After": "0.4"}), (503, {}), (200, {})]
    tries: list[Try] = []
    async with (
        serve_asgi(answering(answers, seen)) as url,
        httpx.AsyncClient(transport=RetryingTransport(fast())) as client,
    ):
        response = await client.post(f"{url}/call", json={"x": 1}, extensions={TRIES: tries})
    assert response.status_code == 200 and response.json() == {"status": 200}
    assert [(t.outcome, t.status) for t in tries] == [
        ("answered", 429),
        ("answered", 503),
        ("answered", 200),
    ]
    assert seen[1] - seen[0] >= 0.4  # the server's wait, not the 2 ms backoff
    assert seen[2] - seen[1] < 0.4


async def test_the_last_answer_comes_back_when_retries_run_out_and_4xx_is_final() -> None:
    seen: list[float] = []
    answers = [(503, {}), (503, {}), (404, {})]
    async with (
        serve_asgi(answering(answers, seen)) as url,
        httpx.AsyncClient(transport=RetryingTransport(fast(max_retries=1))) as client,
    ):
        assert (await client.post(f"{url}/call")).status_code == 503
        assert len(seen) == 2
        assert (await client.post(f"{url}/call")).status_code == 404  # not retried
    assert len(seen) == 3


async def test_a_refused_connection_is_retried_and_every_try_recorded() -> None:
    tries: list[Try] = []
    with refusing_port() as port:
        async with httpx.AsyncClient(transport=RetryingTransport(fast(max_retries=2))) as client:
            with pytest.raises(httpx.ConnectError):
                await client.post(f"http://127.0.0.1:{port}/call", extensions={TRIES: tries})
    assert [t.outcome for t in tries] == ["refused"] * 3
    assert not any(t.reached_server for t in tries)


async def test_timeouts_are_retried_only_when_the_policy_says_so() -> None:
    release = asyncio.Event()
    seen: list[float] = []
    app = FastAPI()

    @app.post("/call")
    async def slow() -> JSONResponse:
        seen.append(time.monotonic())
        await release.wait()
        return JSONResponse({})

    async with serve_asgi(app) as url:
        for retry_timeouts, expected in ((False, 1), (True, 3)):
            seen.clear()
            tries: list[Try] = []
            policy = fast(max_retries=2, retry_timeouts=retry_timeouts)
            async with httpx.AsyncClient(
                transport=RetryingTransport(policy), timeout=httpx.Timeout(0.2)
            ) as client:
                with pytest.raises(httpx.ReadTimeout):
                    await client.post(f"{url}/call", extensions={TRIES: tries})
            assert [t.outcome for t in tries] == ["timed_out"] * expected
        release.set()


async def test_closing_lets_a_request_in_flight_finish_before_the_pool_closes() -> None:
    """Shutdown closed the pool under a request another task had just started: the request
    failed and its socket was left to the garbage collector (an unclosed-socket warning in
    whichever test ran next)."""
    arrived = asyncio.Event()
    release = asyncio.Event()
    app = FastAPI()

    @app.post("/call")
    async def held() -> JSONResponse:
        arrived.set()
        await release.wait()
        return JSONResponse({"done": True})

    transport = RetryingTransport(fast())
    async with serve_asgi(app) as url:
        client = httpx.AsyncClient(transport=transport)
        tries: list[Try] = []
        request = asyncio.create_task(client.post(f"{url}/call", extensions={TRIES: tries}))
        try:
            await arrived.wait()
            closing = asyncio.create_task(client.aclose())
            await asyncio.sleep(0)  # let the close begin while the request is held
        finally:
            release.set()
        response = await request
        await closing
    assert response.status_code == 200 and response.json() == {"done": True}
    # one try: the close did not break it (it was retried on a connection nobody closed)
    assert [t.outcome for t in tries] == ["answered"]
    assert transport.in_flight == 0
    with pytest.raises(RuntimeError, match="closed"):
        await client.post(f"{url}/call")
