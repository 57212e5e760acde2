"""A client that leaves an event stream while events still flow leaves no traceback behind
(issue 24): FastAPI's keep-alive inserter raised ``BrokenResourceError`` (in an exception
group) through the whole app into uvicorn's log once the stream's reader was gone."""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Any

import httpx
import pytest

from assistantx.core.settings import Settings
from assistantx.service.app import create_app
from assistantx.service.server import service_server
from helpers.eventually import eventually
from helpers.servers import free_port, running
from service.server import OPERATOR

OP = {"Authorization": f"Bearer {OPERATOR}"}


async def test_a_client_leaving_a_flowing_stream_logs_no_traceback(
    tmp_path: Path, caplog: pytest.LogCaptureFixture, request: pytest.FixtureRequest
) -> None:
    settings = Settings(  # type: ignore[arg-type]
        data_dir=tmp_path / "data",
        operator_token=OPERATOR,
        speedup=200,
        people="simulated",
        robot_localize=False,
    )
    app = create_app(settings)
    port = free_port()
    server = service_server(app, "127.0.0.1", port, log_level="warning")
    # uvicorn's loggers do not propagate to the root, where caplog listens: listen there too.
    uvicorn_log = logging.getLogger("uvicorn")
    uvicorn_log.addHandler(caplog.handler)
    request.addfinalizer(lambda: uvicorn_log.removeHandler(caplog.handler))
    base = f"http://127.0.0.1:{port}"
    async with running(server), httpx.AsyncClient(base_url=base, headers=OP) as api:
        body = {"requester": "lee", "text": "Bring me a stapler"}
        created = await api.post("/v1/instructions", json=body)
        assert created.status_code == 202, created.text

        async def ended() -> dict[str, Any]:
            found: dict[str, Any] = (await api.get(created.headers["location"])).json()
            return found

        await eventually(
            ended,
            until=lambda r: r["status"] not in ("queued", "running"),
            what="the instruction to end",
            timeout_s=60,
        )
        with caplog.at_level(logging.DEBUG):
            for _ in range(5):
                # The replay holds dozens of events: the client reads one line and leaves
                # while the server still has events to send.
                async with api.stream("GET", "/v1/events?replay=1000") as response:
                    assert response.status_code == 200
                    async for _line in response.aiter_lines():
                        break

                await eventually(
                    lambda: not server.server_state.tasks,
                    what="the stream's request to end",
                    timeout_s=10,
                )
        assert (await api.get("/healthz")).json() == {"status": "ok"}
    tracebacks = [
        r.getMessage() for r in caplog.records if r.exc_info is not None or r.levelno >= 40
    ]
    assert tracebacks == []
