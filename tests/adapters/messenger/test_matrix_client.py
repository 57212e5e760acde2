"""The client's retries against a scripted homeserver double on a real uvicorn server."""

from __future__ import annotations

import time

import pytest
from fastapi import FastAPI, Request
from fastapi.responses import JSONResponse

from assistantx.adapters.messenger.matrix import MatrixClient, MatrixError, RetryPolicy
from assistantx.adapters.messenger.matrix.client import parse_mxc
from helpers.servers import serve_asgi


def scripted_homeserver(answers: list[tuple[int, dict[str, object]]], seen: list[str]) -> FastAPI:
    """Answers each request with the next scripted (status, body); records the paths."""
    app = FastAPI()

    @app.api_route("/{path:path}", methods=["GET", "PUT", "POST"])
    async def answer(path: str, request: Request) -> JSONResponse:
        seen.append(f"{request.method} /{path} {request.headers.get('authorization')}")
        status, body = answers.pop(0)
        return JSONResponse(body, status_code=status)

    return app


async def test_send_retries_429_and_5xx_with_the_same_transaction_id() -> None:
    seen: list[str] = []
    answers = [
        (429, {"errcode": "M_LIMIT_EXCEEDED", "retry_after_ms": 300}),
        (502, {"errcode": "M_UNKNOWN"}),
        (200, {"event_id": "$sent"}),
    ]
    async with serve_asgi(scripted_homeserver(answers, seen)) as url:
        async with MatrixClient(url, "tok", retry=RetryPolicy(base_delay_s=0.01)) as client:
            started = time.monotonic()
            event_id = await client.send_event(
                "!r:o", "m.room.message", {"body": "x"}, txn_id="ax1"
            )
            elapsed = time.monotonic() - started
    assert event_id == "$sent"
    assert len(seen) == 3 and len(set(seen)) == 1  # one URL, one txn id, thrice
    assert seen[0] == "PUT /_matrix/client/v3/rooms/!r:o/send/m.room.message/ax1 Bearer tok"
    assert elapsed >= 0.3  # honoured retry_after_ms


async def test_client_errors_are_not_retried_and_keep_the_errcode() -> None:
    seen: list[str] = []
    answers = [(403, {"errcode": "M_FORBIDDEN", "error": "not in room"})]
    async with serve_asgi(scripted_homeserver(answers, seen)) as url:
        async with MatrixClient(url, "tok") as client:
            with pytest.raises(MatrixError, match="not in room") as caught:
                await client.join("!r:o")
    assert (caught.value.status, caught.value.errcode, len(seen)) == (403, "M_FORBIDDEN", 1)


async def test_retries_are_bounded() -> None:
    seen: list[str] = []
    answers = [(500, {})] * 3
    async with serve_asgi(scripted_homeserver(answers, seen)) as url:
        async with MatrixClient(
            url, "tok", retry=RetryPolicy(max_retries=2, base_delay_s=0.01)
        ) as client:
            with pytest.raises(MatrixError) as caught:
                await client.whoami()
    assert caught.value.status == 500 and len(seen) == 3


def test_parse_mxc() -> None:
    assert parse_mxc("mxc://office.test/AbC") == ("office.test", "AbC")
    for bad in ("http://x/y", "mxc://office.test", "mxc:///id", "mxc://a/b/c"):
        with pytest.raises(MatrixError):
            parse_mxc(bad)
